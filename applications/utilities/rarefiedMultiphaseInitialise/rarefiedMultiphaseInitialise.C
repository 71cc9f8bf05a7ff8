/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Application
    rarefiedMultiphaseInitialise

Group
    grpPreProcessingUtilities

Description
    Fills a case with its initial phases for rarefiedMultiphaseFoam.

    Gas: from system/dsmcInitialiseDict (numberDensities per species,
    temperature, velocity), as dsmcInitialise does, with the species of
    constant/dsmcProperties; a dsmcFoam case initialises unchanged.  The
    dictionaries are checked first: a bad value stops with a FatalIOError
    naming file, keyword and valid range.

    Solid grains: from system/<cloud>InitialiseDict (cloud name from
    -cloud, default grains), see solidInitialise.H.  Each phase is filled
    only when its dictionary exists.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gasCloud.H"
#include "solidInitialise.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Initialise the gas (system/dsmcInitialiseDict) and the solid grains"
        " (system/<cloud>InitialiseDict) of a rarefiedMultiphaseFoam case"
    );
    argList::addOption
    (
        "cloud",
        "name",
        "Solid cloud name (default grains)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createNamedMesh.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    IOstream::defaultPrecision(15);

    const word solidCloudName(args.getOrDefault<word>("cloud", "grains"));
    const bool solids = initialiseSolids(mesh, solidCloudName);

    IOobject initialiseHeader
    (
        "dsmcInitialiseDict",
        runTime.system(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );

    if (initialiseHeader.typeHeaderOk<IOdictionary>(true))
    {
        Info<< "Initialising gas for Time = " << runTime.timeName() << nl
            << endl;

        const IOdictionary initialiseDict(initialiseHeader);
        gasCloud gas("dsmc", mesh, initialiseDict);

        Info<< nl << "Gas simulators added: "
            << returnReduce(gas.size(), sumOp<label>()) << nl << endl;

        if (!mesh.write())
        {
            FatalErrorInFunction
                << "Failed writing the initial gas" << exit(FatalError);
        }
    }
    else if (!solids)
    {
        FatalErrorInFunction
            << "No phase to initialise: neither " << runTime.system()
            << "/dsmcInitialiseDict nor " << runTime.system() << "/"
            << solidCloudName << "InitialiseDict found" << exit(FatalError);
    }

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
