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
    (Lagrangian parcels).  Each phase exists only when its dictionary does:
    constant/dsmcProperties for the gas, constant/<cloud>Properties for the
    grains (cloud name from -cloud, default grains; gravity from
    constant/g).  A dsmcFoam case runs unchanged and, without a randomSeed
    keyword, reproduces dsmcFoam byte for byte.  Without gas (vacuum) the
    grains run alone and no gas work is done.

    One step of length deltaT (doc/physics.md section 1), and where each part lives:

      1. gas inflow               gasCloud::evolve (InflowBoundaryModel)
      2. gas move                 gasCloud::evolve; in the axisymmetric
                                  mode (axisymmetricMode) gasParcel moves
                                  each simulator in 3-D, rotates it back
                                  into the meridional plane, and
                                  gasCloud::weighMove deletes or clones it
                                  by the radial weight
      3. gas-gas collisions       gasCloud::evolve (NTC, BinaryCollisionModel),
                                  then the instantaneous gas fields are
                                  sampled (upstream's order: what steps 4-5
                                  change is sampled in the next step)
      4. solid evolve             the interphase coupling model's
                                  coupleParcels samples the molecules now
                                  in each cell (the one pass over the gas
                                  for steps 4-5: gasNow) and applies the
                                  gas's force and heat to the parcels
                                  (doc/physics.md section 4, keyword
                                  interphaseCoupling); the carrier fields
                                  (gasCarrierFields) are copied from that
                                  sample; then basicSolidCloud::evolve:
                                  injection, forces, MPPIC / stochastic
                                  collisions, parcel move with walls
      5. two-way gas update       the coupling model's coupleGas:
                                  molecules that collided with grains
                                  take their post-collision states
                                  (twoWayDirect, twoWayIndirect; nothing
                                  for the other models)
      6. sampling and writing     function objects (fieldAverage, dsmcFields)
                                  and runTime.write()

    The progress line after each step gives the simulated time, the wall
    time used and an estimate of the wall time left.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gasCloud.H"
#include "basicSolidCloud.H"
#include "InterphaseCouplingModel.H"
#include "gasCarrierFields.H"
#include "progressReport.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
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

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"

    progressReport progress(runTime);

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.loop())
    {
        Info<< "Time = " << runTime.timeName() << nl << endl;

        // Steps 1-3: gas inflow, move, collisions
        if (gas.valid())
        {
            gas->evolve();
        }

        // Step 4: solid phase
        if (solids.valid())
        {
            if (coupling.valid())
            {
                coupling->coupleParcels(gas.get());  // null without gas
            }
            if (gas.valid())
            {
                // Both phases: the coupling exists and sampled the gas
                carrier->update(coupling->gasNow());
            }
            solids->evolve();           // prints its own info()
        }

        // Step 5, two-way models: the gas side of the coupling
        if (coupling.valid() && gas.valid())
        {
            coupling->coupleGas(gas());
        }

        if (gas.valid())
        {
            gas->info();
        }

        // Step 6
        runTime.write();

        progress.report();
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
