/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "movingWindow.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::movingWindow::movingWindow(const label window)
:
    window_(window),
    nSamples_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::movingWindow::next()
{
    ++nSamples_;
    return 1.0/scalar(window_ > 0 ? min(nSamples_, window_) : nSamples_);
}


// ************************************************************************* //
