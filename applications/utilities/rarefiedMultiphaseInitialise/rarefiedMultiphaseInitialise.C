/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam

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

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gasCloud.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Initialise the gas (system/dsmcInitialiseDict) of a"
        " rarefiedMultiphaseFoam case"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createNamedMesh.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    IOobject initialiseHeader
    (
        "dsmcInitialiseDict",
        runTime.system(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );

    if (!initialiseHeader.typeHeaderOk<IOdictionary>(true))
    {
        FatalErrorInFunction
            << "No phase to initialise: " << runTime.system()
            << "/dsmcInitialiseDict not found" << exit(FatalError);
    }

    Info<< "Initialising gas for Time = " << runTime.timeName() << nl << endl;

    const IOdictionary initialiseDict(initialiseHeader);
    gasCloud gas("dsmc", mesh, initialiseDict);

    Info<< nl << "Gas simulators added: "
        << returnReduce(gas.size(), sumOp<label>()) << nl << endl;

    IOstream::defaultPrecision(15);

    if (!mesh.write())
    {
        FatalErrorInFunction
            << "Failed writing the initial phases" << exit(FatalError);
    }

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
