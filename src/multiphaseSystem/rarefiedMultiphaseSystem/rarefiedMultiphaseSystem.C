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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rarefiedMultiphaseSystem::rarefiedMultiphaseSystem
(
    const fvMesh& mesh,
    const word& cloudName
)
:
    balance_(mesh)
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
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rarefiedMultiphaseSystem::evolve()
{
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
