/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam

Description
    Registers, for solidCloud, upstream's kinematic and MPPIC submodels (as
    MPPICFoam's cloud has them) and our own: the zonalGravity force and the
    NTCHardSphere stochastic collision model.

\*---------------------------------------------------------------------------*/

#include "solidCloud.H"

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
#include "NTCHardSphere.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(solidCloud);

makeParcelForces(solidCloud);
makeParcelDispersionModels(solidCloud);
makeParcelInjectionModels(solidCloud);
makeParcelPatchInteractionModels(solidCloud);
makeParcelStochasticCollisionModels(solidCloud);
makeParcelSurfaceFilmModels(solidCloud);

makeMPPICParcelDampingModels(solidCloud);
makeMPPICParcelIsotropyModels(solidCloud);
makeMPPICParcelPackingModels(solidCloud);

makeParticleForceModelType(ZonalGravityForce, solidCloud);
makeStochasticCollisionModelType(NTCHardSphere, solidCloud);


// ************************************************************************* //
