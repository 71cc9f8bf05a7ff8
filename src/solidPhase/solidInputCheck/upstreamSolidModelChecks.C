/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    The checkers of upstream's grain models that read keywords
    (solidModelChecks): the explicit and implicit packing models (their
    particle stress model), HarrisCrighton's particle stress (pSolid, beta,
    eps), the relaxation damping model and the stochastic isotropy model
    (their time scale model; and the averaging the second can take), the
    localInteraction and standardWallInteraction patch interactions (each
    wall's e and mu).  The DEM cloud's pairCollision is registered with
    the cloud (pairCollisionCheck.H).

\*---------------------------------------------------------------------------*/

#include "solidModelChecks.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace
{

using namespace inputChecks;

//- The coefficients of model typeName in the subModels dictionary
inline const dictionary& coeffs(const dictionary& models, const word& type)
{
    return models.subDict(type + "Coeffs");
}


void checkExplicit(const dictionary& models, const dictionary& props)
{
    solidChecks::particleStress(coeffs(models, "explicit"), props);
}


void checkImplicit(const dictionary& models, const dictionary& props)
{
    solidChecks::particleStress(coeffs(models, "implicit"), props);
}


void checkHarrisCrighton(const dictionary& dict, const dictionary&)
{
    getPositive(dict, "pSolid");
    getNonNegative(dict, "beta");
    getPositive(dict, "eps");
}


void checkRelaxation(const dictionary& models, const dictionary&)
{
    solidChecks::timeScale(coeffs(models, "relaxation"));
}


void checkStochastic(const dictionary& models, const dictionary& props)
{
    solidChecks::timeScale(coeffs(models, "stochastic"));
    solidChecks::isotropyAveraging(props, "stochastic");
}


void checkLocalInteraction(const dictionary& models, const dictionary&)
{
    const dictionary& dict = coeffs(models, "localInteraction");
    const PtrList<entry> patches(dict.lookup("patches"));
    for (const entry& e : patches)
    {
        if (e.isDict())
        {
            // Named after the file, for the message
            dictionary patchDict(e.dict());
            patchDict.name() = dict.name() + ".patches." + e.keyword();
            solidChecks::rebound(patchDict);
        }
    }
}


void checkStandardWallInteraction(const dictionary& models, const dictionary&)
{
    solidChecks::rebound(coeffs(models, "standardWallInteraction"));
}


const solidModelChecks::add addExplicit("explicit", checkExplicit);
const solidModelChecks::add addImplicit("implicit", checkImplicit);
const solidModelChecks::add addHarrisCrighton
(
    "HarrisCrighton", checkHarrisCrighton
);
const solidModelChecks::add addRelaxation("relaxation", checkRelaxation);
const solidModelChecks::add addStochastic("stochastic", checkStochastic);
const solidModelChecks::add addLocalInteraction
(
    "localInteraction", checkLocalInteraction
);
const solidModelChecks::add addStandardWallInteraction
(
    "standardWallInteraction", checkStandardWallInteraction
);

// Upstream's uniform body force, and its averaging with gradients
const bodyForces::add addGravity("gravity");
const signedAveragings::add addMoment("moment");

} // End anonymous namespace
} // End namespace Foam


// ************************************************************************* //
