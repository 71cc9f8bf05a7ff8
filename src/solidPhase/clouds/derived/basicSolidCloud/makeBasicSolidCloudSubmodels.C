/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    Registers, for basicSolidCloud, upstream's kinematic and MPPIC submodels (as
    MPPICFoam's cloud has them) and our own: the zonalGravity force, the
    NTCHardSphere stochastic collision model, the twoSided packing model,
    the restartableStochastic isotropy model and the erosionPlanes cloud
    function.

\*---------------------------------------------------------------------------*/

#include "basicSolidCloud.H"

#include "makeParcelCloudFunctionObjects.H"

// Kinematic
#include "makeParcelForces.H"
#include "makeParcelDispersionModels.H"
#include "makeParcelInjectionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeParcelSurfaceFilmModels.H"

// MPPIC
#include "makeMPPICParcelDampingModels.H"
#include "makeMPPICParcelIsotropyModels.H"
#include "makeMPPICParcelPackingModels.H"

// Ours
#include "ZonalGravityForce.H"
#include "ErosionPlanes.H"
#include "NTCHardSphere.H"
#include "TwoSided.H"
#include "RestartableStochastic.H"
#include "solidModelChecks.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(basicSolidCloud);

makeParcelForces(basicSolidCloud);
makeParcelDispersionModels(basicSolidCloud);
makeParcelInjectionModels(basicSolidCloud);
makeParcelPatchInteractionModels(basicSolidCloud);
makeParcelStochasticCollisionModels(basicSolidCloud);
makeParcelSurfaceFilmModels(basicSolidCloud);

makeMPPICParcelDampingModels(basicSolidCloud);
makeMPPICParcelIsotropyModels(basicSolidCloud);
makeMPPICParcelPackingModels(basicSolidCloud);

makeParticleForceModelType(ZonalGravityForce, basicSolidCloud);
makeCloudFunctionObjectType(ErosionPlanes, basicSolidCloud);
makeStochasticCollisionModelType(NTCHardSphere, basicSolidCloud);
makePackingModelType(TwoSided, basicSolidCloud);
makeIsotropyModelType(RestartableStochastic, basicSolidCloud);

// The checkers (solidModelChecks) of our models that read keywords
static const Foam::solidModelChecks::add addNTCHardSphereCheck
(
    Foam::NTCHardSphere<kinematicCloudType>::typeName_(),
    Foam::NTCHardSphere<kinematicCloudType>::check
);

static const Foam::solidModelChecks::add addTwoSidedCheck
(
    Foam::PackingModels::TwoSided<MPPICCloudType>::typeName_(),
    Foam::PackingModels::TwoSided<MPPICCloudType>::check
);

static const Foam::solidModelChecks::add addRestartableStochasticCheck
(
    Foam::IsotropyModels::RestartableStochastic<MPPICCloudType>::typeName_(),
    Foam::IsotropyModels::RestartableStochastic<MPPICCloudType>::check
);


// ************************************************************************* //
