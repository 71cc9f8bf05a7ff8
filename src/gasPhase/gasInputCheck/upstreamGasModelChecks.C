/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    The checkers of upstream's gas models that read keywords (gasModelChecks):
    VariableHardSphere and LarsenBorgnakkeVariableHardSphere (Tref, and the
    relaxation collision number of the second), MixedDiffuseSpecular
    (diffuseFraction), FreeStream (numberDensities per species).  Upstream's
    other models read none.

\*---------------------------------------------------------------------------*/

#include "gasModelChecks.H"
#include "inputChecks.H"
#include "keywordChecks.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace
{

using namespace inputChecks;

void checkVariableHardSphere(const dictionary& dict, const wordList&)
{
    const dictionary& coeffs =
        knownSubDict(dict, "VariableHardSphereCoeffs", {"Tref"});
    getPositive(coeffs, "Tref");
}


void checkLarsenBorgnakkeVariableHardSphere
(
    const dictionary& dict,
    const wordList&
)
{
    const dictionary& coeffs = knownSubDict
    (
        dict, "LarsenBorgnakkeVariableHardSphereCoeffs",
        {"Tref", "relaxationCollisionNumber"}
    );
    getPositive(coeffs, "Tref");
    getInterval(coeffs, "relaxationCollisionNumber", interval::atLeast(1));
}


void checkMixedDiffuseSpecular(const dictionary& dict, const wordList&)
{
    const dictionary& coeffs =
        knownSubDict(dict, "MixedDiffuseSpecularCoeffs", {"diffuseFraction"});
    getClosed(coeffs, "diffuseFraction", 0, 1);
}


void checkFreeStream(const dictionary& dict, const wordList& species)
{
    const dictionary& coeffs =
        knownSubDict(dict, "FreeStreamCoeffs", {"numberDensities"});
    const dictionary& densities = coeffs.subDict("numberDensities");
    for (const word& name : densities.toc())
    {
        if (!species.found(name))
        {
            notOneOf(densities, "numberDensities", name, species);
        }
        getNonNegativeOrDefault(densities, name, 0);
    }
}


const gasModelChecks::add addVariableHardSphere
(
    "VariableHardSphere", checkVariableHardSphere
);

const gasModelChecks::add addLarsenBorgnakkeVariableHardSphere
(
    "LarsenBorgnakkeVariableHardSphere",
    checkLarsenBorgnakkeVariableHardSphere
);

const gasModelChecks::add addMixedDiffuseSpecular
(
    "MixedDiffuseSpecular", checkMixedDiffuseSpecular
);

const gasModelChecks::add addFreeStream("FreeStream", checkFreeStream);

} // End anonymous namespace
} // End namespace Foam


// ************************************************************************* //
