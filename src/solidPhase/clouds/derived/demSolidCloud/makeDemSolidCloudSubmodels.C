/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    Registers the submodels selectable for the DEM grain cloud: upstream's
    kinematic and collision models (those of icoUncoupledKinematicParcelFoam's
    colliding cloud) and our own: the zonalGravity force, the NTCHardSphere
    stochastic collision model, the linear spring-dashpot pair and wall
    contacts, the cartesianContacts collision model and the erosionPlanes
    cloud function.

\*---------------------------------------------------------------------------*/

#include "demSolidCloud.H"

#include "makeParcelCloudFunctionObjects.H"

// Kinematic
#include "makeParcelForces.H"
#include "makeParcelDispersionModels.H"
#include "makeParcelInjectionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeParcelSurfaceFilmModels.H"

// Colliding
#include "NoCollision.H"
#include "PairCollision.H"
#include "PairSpringSliderDashpot.H"
#include "WallSpringSliderDashpot.H"
#include "WallLocalSpringSliderDashpot.H"

// Ours
#include "ZonalGravityForce.H"
#include "ErosionPlanes.H"
#include "NTCHardSphere.H"
#include "PairLinearSpringDashpot.H"
#include "WallLinearSpringDashpot.H"
#include "CartesianContacts.H"
#include "pairCollisionCheck.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(demSolidCloud);

makeParcelForces(demSolidCloud);
makeParcelDispersionModels(demSolidCloud);
makeParcelInjectionModels(demSolidCloud);
makeParcelPatchInteractionModels(demSolidCloud);
makeParcelStochasticCollisionModels(demSolidCloud);
makeParcelSurfaceFilmModels(demSolidCloud);

// As upstream's makeParcelCollisionModels, whose pair and wall tables are
// those of the cloud named, here the colliding layer below ours
makeCollisionModel(demSolidCloud);
makeCollisionModelType(NoCollision, demSolidCloud);
makeCollisionModelType(PairCollision, demSolidCloud);

makePairModel(demCollidingCloud);
makePairModelType(PairSpringSliderDashpot, demCollidingCloud);
makeWallModel(demCollidingCloud);
makeWallModelType(WallSpringSliderDashpot, demCollidingCloud);
makeWallModelType(WallLocalSpringSliderDashpot, demCollidingCloud);

makeParticleForceModelType(ZonalGravityForce, demSolidCloud);
makeCloudFunctionObjectType(ErosionPlanes, demSolidCloud);
makeStochasticCollisionModelType(NTCHardSphere, demSolidCloud);
makePairModelType(PairLinearSpringDashpot, demCollidingCloud);
makeWallModelType(WallLinearSpringDashpot, demCollidingCloud);
makeCollisionModelType(CartesianContacts, demSolidCloud);

// cartesianContacts leaves out the contacts erosionPlanes turns off
// The checkers (solidModelChecks) of upstream's pair collisions and of our
// models that read keywords
static const Foam::solidModelChecks::add addPairCollisionCheck
(
    Foam::PairCollision<Foam::demCollidingCloud>::typeName_(),
    Foam::solidChecks::pairCollision<Foam::demCollidingCloud>
);

static const Foam::solidModelChecks::add addPairLinearSpringDashpotCheck
(
    Foam::PairLinearSpringDashpot<Foam::demCollidingCloud>::typeName_(),
    Foam::solidChecks::linearContactModel
    <
        Foam::PairLinearSpringDashpot<Foam::demCollidingCloud>
    >
);

static const Foam::solidModelChecks::add addWallLinearSpringDashpotCheck
(
    Foam::WallLinearSpringDashpot<Foam::demCollidingCloud>::typeName_(),
    Foam::solidChecks::linearContactModel
    <
        Foam::WallLinearSpringDashpot<Foam::demCollidingCloud>
    >
);

static const Foam::solidModelChecks::add addNTCHardSphereCheck
(
    Foam::NTCHardSphere<kinematicCloudType>::typeName_(),
    Foam::NTCHardSphere<kinematicCloudType>::check
);

static const Foam::contactModels::add addContactsCartesianContacts
(
    Foam::CartesianContacts<Foam::demCollidingCloud>::typeName_()
);


// ************************************************************************* //
