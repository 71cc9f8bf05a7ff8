/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "randomStreams.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::label Foam::randomStreams::seed
(
    const label randomSeed,
    const offset stream,
    const label proc
)
{
    return randomSeed*spacing + stream + proc;
}


Foam::label Foam::randomStreams::seed
(
    const label randomSeed,
    const offset stream
)
{
    return seed(randomSeed, stream, Pstream::myProcNo());
}


// ************************************************************************* //
