/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "grainPhase.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(grainPhase, 0);
    defineRunTimeSelectionTable(grainPhase, dictionary);
    constexpr label grainPhase::sortInterval;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace Foam
{
    defineNameRegistry(grainPhase::fillsTag, grainPhase::fillFunction);
}


// ************************************************************************* //
