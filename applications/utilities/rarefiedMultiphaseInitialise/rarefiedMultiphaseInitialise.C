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
    -cloud, default grains): randomSeed and one region fill per entry of
    regions, filled in turn from one random stream (see regionFill and
    src/solidPhase/regionFills).  Each phase is filled only when its
    dictionary exists.

    With loadBalance { cellCost yes; } in system/controlDict it also writes
    the field cellCost, uniform (nothing measured yet), for decomposePar's
    weightField (loadBalance, doc/physics.md#load-balance).

    Errors raised (FatalIOError, file/keyword/value/valid range): those of
    the fills; randomSeed outside [0, 2000]; an entry of regions that is
    not a dictionary.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gasCloud.H"
#include "grainPhase.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "randomStreams.H"
#include "loadBalance.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Fill the solid cloud of the case, if its initialisation dictionary
// exists, with parcels of the kind its cloudType names
static bool initialiseSolids(const fvMesh& mesh, const word& cloudName)
{
    IOobject header
    (
        cloudName + "InitialiseDict",
        mesh.time().system(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );

    if (!header.typeHeaderOk<IOdictionary>(true))
    {
        return false;
    }

    grainPhase::fill(cloudName, mesh, IOdictionary(header));

    return true;
}


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
    inputChecks::keywordRecord::addOption
    (
        "Read and check the set-up as for initialising, print every keyword"
        " checked (dictionary, kind, valid range or choices), write nothing"
    );

    #include "setRootCase.H"
    inputChecks::keywordRecord::start(args);
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

        if (!inputChecks::keywordRecord::active() && !mesh.write())
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

    if (inputChecks::keywordRecord::active())
    {
        inputChecks::keywordRecord::print(runTime.path());
    }
    else
    {
        loadBalance::writeInitial(mesh);
    }

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
