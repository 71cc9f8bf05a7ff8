/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "rarefiedMultiphaseSystem.H"
#include "axisymmetricMode.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Whether constant/<name> holds a dictionary
bool present(const Foam::fvMesh& mesh, const Foam::word& name)
{
    using namespace Foam;

    return
        IOobject(name, mesh.time().constant(), mesh)
       .typeHeaderOk<IOdictionary>(true);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rarefiedMultiphaseSystem::checkPhases
(
    const fvMesh& mesh,
    const word& cloudName
) const
{
    if
    (
        gas_.valid() && grains_.valid()
     && gas_->axisymmetric().active() != grains_->axisymmetric().active()
    )
    {
        inputChecks::badValue
        (
            grains_->properties(), "axisymmetric",
            grains_->axisymmetric().active() ? "true" : "false",
            word(gas_->axisymmetric().active() ? "true" : "false")
          + ", as axisymmetric in " + gas_->particleProperties().name()
        );
    }

    if (!gas_.valid() && !grains_.valid())
    {
        FatalErrorInFunction
            << "Nothing to solve: no phase dictionary in "
            << mesh.time().constant() << " (expected dsmcProperties and/or "
            << cloudName << "Properties)" << exit(FatalError);
    }
}


void Foam::rarefiedMultiphaseSystem::readStepControls(const Time& runTime)
{
    const dictionary& controls = runTime.controlDict();

    // Upstream's keyword: Time has read it, and stopped on a bad value
    adjustTimeStep_ = controls.getOrDefault<bool>("adjustTimeStep", false);
    maxTransit_ =
        inputChecks::getIntervalOrDefault
        (
            controls, "maxTransit", inputChecks::interval::above(0, 1), 1
        );
    maxDeltaT_ =
        inputChecks::getPositiveOrDefault
        (
            controls, "maxDeltaT", controls.get<scalar>("deltaT")
        );

    if (adjustTimeStep_ && !gas_.valid())
    {
        inputChecks::badValue
        (
            controls, "adjustTimeStep", "yes",
            "no (the step follows the gas's cell transit, and there is no"
            " constant/dsmcProperties)"
        );
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rarefiedMultiphaseSystem::rarefiedMultiphaseSystem
(
    const fvMesh& mesh,
    const word& cloudName
)
:
    balance_(mesh),
    adjustTimeStep_(false),
    maxTransit_(1),
    maxDeltaT_(0),
    transit_(0),
    shortest_(GREAT),
    longest_(0),
    transitMax_(0)
{
    if (present(mesh, "dsmcProperties"))
    {
        Info<< "Constructing gas phase (constant/dsmcProperties)" << endl;
        gas_.reset(new gasCloud("dsmc", mesh));
    }
    else
    {
        Info<< "No constant/dsmcProperties: no gas phase (vacuum)" << endl;
    }

    if (present(mesh, cloudName + "Properties"))
    {
        Info<< "Constructing solid phase (constant/" << cloudName
            << "Properties)" << endl;

        carrier_.reset(new gasCarrierFields(mesh, gas_.valid()));
        if (gas_.valid())
        {
            carrier_->update(gas_());
        }

        g_.reset
        (
            new uniformDimensionedVectorField
            (
                IOobject
                (
                    "g",
                    mesh.time().constant(),
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE
                )
            )
        );

        grains_ =
            grainPhase::New(cloudName, mesh, carrier_(), g_(), gas_.valid());
    }
    else
    {
        Info<< "No constant/" << cloudName << "Properties: no solid phase"
            << endl;
    }

    checkPhases(mesh, cloudName);
    readStepControls(mesh.time());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rarefiedMultiphaseSystem::adjustDeltaT(Time& runTime)
{
    if (!adjustTimeStep_)
    {
        return;
    }

    // From the state alone (no growth limit from the last step): a restart
    // finds the same step (but for round-off in the time's sum)
    const scalar rate = gas_->largestTransitRate();
    scalar dt = rate*maxDeltaT_ > maxTransit_ ? maxTransit_/rate : maxDeltaT_;

    // Steps of equal length to the next write time: as many as needed for
    // none to be longer (Time's own spreading may lengthen them by half),
    // but for the time's round-off (a relative 1e-9)
    const dictionary& controls = runTime.controlDict();
    if
    (
        controls.getOrDefault<word>("writeControl", "timeStep")
     == "adjustableRunTime"
    )
    {
        const scalar interval = controls.get<scalar>("writeInterval");
        const scalar sinceStart =
            runTime.value() - runTime.startTime().value();
        const label written = label(sinceStart/interval + 1e-6);
        const scalar toWrite = (written + 1)*interval - sinceStart;
        dt = toWrite/(label(toWrite/dt*(1 - 1e-9)) + 1);
    }
    runTime.setDeltaT(dt, false);
    transit_ = rate*dt;
}


void Foam::rarefiedMultiphaseSystem::evolve()
{
    if (adjustTimeStep_)
    {
        const Time& runTime = gas_->mesh().time();
        const scalar dt = runTime.deltaTValue();
        Info<< "deltaT = " << dt << " s, largest cell transit " << transit_
            << " (maxTransit " << maxTransit_ << ")" << endl;

        shortest_ = min(shortest_, dt);
        longest_ = max(longest_, dt);
        transitMax_ = max(transitMax_, transit_);
        if (runTime.writeTime())
        {
            Info<< "Gas step since the last write (adjustTimeStep): deltaT"
                << " from " << shortest_ << " to " << longest_ << " s,"
                << " largest cell transit of a step " << transitMax_
                << " (maxTransit " << maxTransit_ << ")" << endl;
            shortest_ = GREAT;
            longest_ = 0;
            transitMax_ = 0;
        }
    }

    // Steps 1-3: gas inflow, move, collisions
    if (gas_.valid())
    {
        balance_.begin(loadBalance::gas);
        gas_->evolve();

        // The counts per cell only where the cost per cell is measured
        labelList simulators;
        scalarField candidates;
        if (balance_.perCell())
        {
            const auto& occupancy = gas_->cellOccupancy();
            simulators.setSize(occupancy.size());
            forAll(occupancy, celli)
            {
                simulators[celli] = occupancy[celli].size();
            }
            candidates = gas_->collisionCandidates();
        }
        balance_.endGas(simulators, candidates);
    }

    if (grains_.valid())
    {
        // Step 4: the gas on the parcels, then the solid step
        balance_.begin(loadBalance::coupling);
        grains_->sortByCell();
        grains_->coupleParcels(gas_.get());
        labelList parcels;
        if (balance_.perCell())
        {
            parcels = grains_->parcelsPerCell();
        }
        balance_.end(loadBalance::coupling, parcels);

        balance_.begin(loadBalance::grains);
        if (gas_.valid())
        {
            // With gas the coupling exists and has sampled it
            carrier_->update(grains_->gasNow());
        }
        grains_->evolve();
        if (balance_.perCell())
        {
            parcels = grains_->parcelsPerCell();
        }
        balance_.end(loadBalance::grains, parcels);

        // Step 5: the gas side of two-way models
        if (gas_.valid())
        {
            balance_.begin(loadBalance::coupling);
            grains_->coupleGas(gas_());
            balance_.end(loadBalance::coupling, parcels);
        }
    }

    balance_.endStep();
}


void Foam::rarefiedMultiphaseSystem::info() const
{
    if (gas_.valid())
    {
        gas_->info();
    }
}


// ************************************************************************* //
