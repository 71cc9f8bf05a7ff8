/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    Registers the grain cloud kinds selectable by cloudType (grainPhase)
    and their initial fills.

\*---------------------------------------------------------------------------*/

#include "CoupledGrainCloud.H"
#include "fillGrainCloud.H"
#include "basicSolidCloud.H"
#include "demSolidCloud.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeGrainPhase(basicSolidCloud);
makeGrainPhase(demSolidCloud);


// ************************************************************************* //
