/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    Registers the interphase coupling models (doc/physics.md#coupling) for
    each grain cloud kind (basicSolidCloud, demSolidCloud), with gasCloud
    as the gas.

\*---------------------------------------------------------------------------*/

#include "basicSolidCloud.H"
#include "demSolidCloud.H"
#include "gasCloud.H"

#include "InterphaseCouplingModel.H"
#include "NoInterphaseCoupling.H"
#include "OneWayCoupling.H"
#include "LothCoupling.H"
#include "AdaptiveCoupling.H"
#include "TwoWayDirectCoupling.H"
#include "TwoWayIndirectCoupling.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeInterphaseCouplingModel(basicSolidCloud);

makeInterphaseCouplingModelType(NoInterphaseCoupling, basicSolidCloud);
makeInterphaseCouplingModelType(OneWayCoupling, basicSolidCloud);
makeInterphaseCouplingModelType(LothCoupling, basicSolidCloud);
makeInterphaseCouplingModelType(AdaptiveCoupling, basicSolidCloud);
makeInterphaseCouplingModelType(TwoWayDirectCoupling, basicSolidCloud);
makeInterphaseCouplingModelType(TwoWayIndirectCoupling, basicSolidCloud);

makeInterphaseCouplingModel(demSolidCloud);

makeInterphaseCouplingModelType(NoInterphaseCoupling, demSolidCloud);
makeInterphaseCouplingModelType(OneWayCoupling, demSolidCloud);
makeInterphaseCouplingModelType(LothCoupling, demSolidCloud);
makeInterphaseCouplingModelType(AdaptiveCoupling, demSolidCloud);
makeInterphaseCouplingModelType(TwoWayDirectCoupling, demSolidCloud);
makeInterphaseCouplingModelType(TwoWayIndirectCoupling, demSolidCloud);


// ************************************************************************* //
