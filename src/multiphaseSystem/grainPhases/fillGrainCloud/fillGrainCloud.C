/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "fillGrainCloud.H"
#include "basicSolidParcel.H"
#include "axisymmetricMode.H"
#include "regionFill.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "randomStreams.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

template<class CloudType>
void Foam::fillGrainCloud
(
    const word& cloudName,
    const fvMesh& mesh,
    const IOdictionary& cloudProps,
    const IOdictionary& initDict
)
{
    typedef typename CloudType::parcelType parcelType;

    CloudType::checkInput(cloudName, mesh);

    const basicSolidParcel::constantProperties constProps(cloudProps);
    const axisymmetricMode axisymmetric(cloudProps, mesh, cloudName);

    word alphaMaxWhat;
    const scalar alphaMax = regionFill::alphaLimit(cloudProps, alphaMaxWhat);

    inputChecks::rejectMisspelt(initDict, {"randomSeed", "regions"});
    const label seed =
        inputChecks::getLabelOrDefault(initDict, "randomSeed", 0, 0, 2000);
    // The same stream on every processor (no processor number)
    Random rnd(randomStreams::seed(seed, randomStreams::grainFill, 0));

    Info<< "Initialising solid cloud " << cloudName << " (seed " << seed
        << ")" << nl;

    Cloud<parcelType> cloud(mesh, cloudName, IDLList<parcelType>());

    const regionFill::cloudSetup setup{mesh, constProps, axisymmetric, rnd};

    label nTotal = 0;
    const dictionary& regions = initDict.subDict("regions");
    for (const entry& e : regions)
    {
        if (!e.isDict())
        {
            inputChecks::badValue
            (
                regions, e.keyword(), "not a dictionary",
                "a dictionary per region"
            );
        }
        nTotal += regionFill::New(e.dict(), setup)->fill
        (
            cloud, alphaMax, alphaMaxWhat
        );
    }

    Info<< "Solid parcels added: " << nTotal << nl << endl;

    if (!inputChecks::keywordRecord::active() && !cloud.write())
    {
        FatalErrorInFunction
            << "Failed writing cloud " << cloudName << exit(FatalError);
    }
}


// ************************************************************************* //
