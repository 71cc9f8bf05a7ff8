/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Application
    rarefiedMultiphaseFoam

Group
    grpDiscreteMethodsSolvers

Description
    Transient solver for rarefied gas flows (DSMC) carrying solid grains
    (Lagrangian parcels).  The phases, their coupling and the order of a
    step belong to rarefiedMultiphaseSystem (doc/physics.md#step): a
    dsmcFoam case runs unchanged, grains run alone in vacuum, or both
    together.  The grain cloud is constant/<cloud>Properties (-cloud,
    default grains).  After each step a progress line gives the simulated
    time, the wall time used and an estimate of the wall time left.  With
    adjustTimeStep (system/controlDict) each step's length follows the
    gas's cell transit (rarefiedMultiphaseSystem).  A
    time directory whose write did not finish (a killed run, a full disk)
    is set aside at the restart (writeGuard; doc/physics.md#restart).  A
    parallel run logs its load balance at every write, and may write the
    cost per cell and stop to re-balance (loadBalance;
    doc/physics.md#load-balance).  Memory the solver frees stays with it for the
    next step (heapReuse).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "rarefiedMultiphaseSystem.H"
#include "progressReport.H"
#include "writeGuard.H"
#include "inputChecks.H"
#include "heapReuse.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    // Each step's mesh-sized fields reuse the last step's memory
    heapReuse();

    argList::addNote
    (
        "Transient solver for rarefied gas (DSMC) and solid grain flows"
    );

    #define NO_CONTROL
    #include "postProcess.H"

    argList::addOption
    (
        "cloud",
        "name",
        "Solid cloud name (default grains): constant/<name>Properties"
    );

    inputChecks::keywordRecord::addOption
    (
        "Read and check the case's set-up, print every keyword checked"
        " (dictionary, kind, valid range or choices) and stop"
    );

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    inputChecks::keywordRecord::start(args);
    writeGuard::skipIncomplete(args);
    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"

    if (inputChecks::keywordRecord::active())
    {
        inputChecks::keywordRecord::print(runTime.path());
        return 0;
    }

    progressReport progress(runTime);

    Info<< "\nStarting time loop\n" << endl;

    // With adjustTimeStep the step is set before the end time is tested
    phases.adjustDeltaT(runTime);
    while (runTime.run())
    {
        ++runTime;

        writeGuard::begin(runTime);
        Info<< "Time = " << runTime.timeName() << nl << endl;

        phases.evolve();
        phases.info();

        writeGuard::end(runTime, runTime.write());

        progress.report();

        if (phases.stopToRebalance())
        {
            break;
        }

        phases.adjustDeltaT(runTime);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
