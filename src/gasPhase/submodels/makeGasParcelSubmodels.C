/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    Registers upstream's DSMC submodels (binary collision, wall interaction,
    inflow boundary) and ours (VariableSoftSphere and its Larsen-Borgnakke
    form, PatchInflow) in the selection tables of
    DSMCCloud<gasParcel>.

\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "gasModelChecks.H"
#include "vhsCrossSection.H"

#include "NoBinaryCollision.H"
#include "VariableHardSphere.H"
#include "LarsenBorgnakkeVariableHardSphere.H"
#include "VariableSoftSphere.H"

#include "MaxwellianThermal.H"
#include "SpecularReflection.H"
#include "MixedDiffuseSpecular.H"

#include "NoInflow.H"
#include "FreeStream.H"
#include "PatchInflow.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    typedef DSMCCloud<gasParcel> gasCloudBase;

    makeBinaryCollisionModel(gasCloudBase);
    makeBinaryCollisionModelType(NoBinaryCollision, gasCloudBase);
    makeBinaryCollisionModelType(VariableHardSphere, gasCloudBase);
    makeBinaryCollisionModelType
    (
        LarsenBorgnakkeVariableHardSphere,
        gasCloudBase
    );
    makeBinaryCollisionModelType(VariableSoftSphere, gasCloudBase);
    makeBinaryCollisionModelType
    (
        LarsenBorgnakkeVariableSoftSphere,
        gasCloudBase
    );

    // The models with the variable-hard-sphere law (vhsCrossSection):
    // upstream's, whose rate its table evaluates, and ours
    static const vhsModels::add addVHS
    (
        VariableHardSphere<gasCloudBase>::typeName_(), true
    );
    static const vhsModels::add addLBVHS
    (
        LarsenBorgnakkeVariableHardSphere<gasCloudBase>::typeName_(), true
    );
    static const vhsModels::add addVSS
    (
        VariableSoftSphere<gasCloudBase>::typeName_(), false
    );
    static const vhsModels::add addLBVSS
    (
        LarsenBorgnakkeVariableSoftSphere<gasCloudBase>::typeName_(), false
    );

    // The collision model that exchanges vibrational energy
    static const gasModelChecks::addVibrating addVibratingLBVSS
    (
        LarsenBorgnakkeVariableSoftSphere<gasCloudBase>::typeName_()
    );

    makeWallInteractionModel(gasCloudBase);
    makeWallInteractionModelType(MaxwellianThermal, gasCloudBase);
    makeWallInteractionModelType(SpecularReflection, gasCloudBase);
    makeWallInteractionModelType(MixedDiffuseSpecular, gasCloudBase);

    makeInflowBoundaryModel(gasCloudBase);
    makeInflowBoundaryModelType(NoInflow, gasCloudBase);
    makeInflowBoundaryModelType(FreeStream, gasCloudBase);
    makeInflowBoundaryModelType(PatchInflow, gasCloudBase);
}


// ************************************************************************* //
