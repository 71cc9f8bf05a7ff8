/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "grainPhase.H"
#include "IOdictionary.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::grainPhase> Foam::grainPhase::New
(
    const word& cloudName,
    const fvMesh& mesh,
    const gasCarrierFields& carrier,
    const dimensionedVector& g,
    const bool gasPresent
)
{
    // Read unregistered: the cloud registers the same dictionary itself
    const IOdictionary dict
    (
        IOobject
        (
            cloudName + "Properties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    const word kind
    (
        inputChecks::modelNameOrDefault<grainPhase>
        (
            dict, "cloudType", "basicSolidCloud"
        )
    );

    Info<< "Selecting grain cloud " << kind << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(kind);

    return cstrIter()(cloudName, carrier, g, gasPresent);
}


void Foam::grainPhase::fill
(
    const word& cloudName,
    const fvMesh& mesh,
    const IOdictionary& initDict
)
{
    const IOdictionary cloudProps
    (
        inputChecks::readCloudProperties(cloudName, mesh)
    );
    const word kind
    (
        inputChecks::modelNameOrDefault<grainPhase>
        (
            cloudProps, "cloudType", "basicSolidCloud"
        )
    );

    (**fills::find(kind))(cloudName, mesh, cloudProps, initDict);
}


// ************************************************************************* //
