/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "solidModelChecks.H"
#include "inputChecks.H"
#include "ParticleStressModel.H"
#include "TimeScaleModel.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace Foam
{
    defineNameRegistry(solidModelChecksTag, solidModelChecker);
    defineNameRegistry(bodyForcesTag, bool);
    defineNameRegistry(signedAveragingsTag, bool);
}


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::solidChecks::particleStress
(
    const dictionary& coeffs,
    const dictionary& cloudProperties
)
{
    const dictionary& dict = coeffs.subDict("particleStressModel");
    const word type
    (
        inputChecks::modelName<ParticleStressModel>(dict, "type")
    );

    inputChecks::getOpen(dict, "alphaPacked", 0, 1);

    solidModelChecks::call(type, dict, cloudProperties);
}


void Foam::solidChecks::timeScale(const dictionary& coeffs)
{
    using namespace inputChecks;

    const dictionary& dict = coeffs.subDict("timeScaleModel");
    modelName<TimeScaleModel>(dict, "type");

    getOpen(dict, "alphaPacked", 0, 1);
    getClosed(dict, "e", 0, 1);
}


void Foam::solidChecks::isotropyAveraging
(
    const dictionary& cloudProperties,
    const word& isotropy
)
{
    // The stochastic isotropy models take exp(-dt/tau) of every component
    // of the averages, the moment method's gradients too: a negative
    // gradient overflows (found by validation/badKeywords' fuzz)
    // (its name is checked, with its choices, by SolidCloud::checkInput)
    const dictionary& solution = cloudProperties.subDict("solution");
    const word averaging(solution.get<word>("averagingMethod"));
    if (signedAveragings::found(averaging))
    {
        inputChecks::badValue
        (
            solution, "averagingMethod", averaging,
            "basic, dual or cachedDual with isotropyModel " + isotropy
        );
    }
}


void Foam::solidChecks::rebound(const dictionary& dict)
{
    inputChecks::getClosedOrDefault(dict, "e", 0, 0, 1);
    inputChecks::getClosedOrDefault(dict, "mu", 0, 0, 1);
}


// ************************************************************************* //
