/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "loadBalance.H"
#include "cellTimer.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "profilingPstream.H"
#include "Pair.H"

#include <ctime>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// system/controlDict's loadBalance (empty when absent), checked
dictionary settings(const fvMesh& mesh)
{
    const dictionary dict
    (
        mesh.time().controlDict().subOrEmptyDict("loadBalance")
    );
    inputChecks::rejectUnknown
    (
        dict, {"cellCost", "maxImbalance", "candidateCost", "measure"}
    );
    return dict;
}


// Whether the cost is the counted work (measure work) instead of CPU time
bool countsWork(const fvMesh& mesh)
{
    return
        inputChecks::getChoiceOrDefault
        (
            settings(mesh), "measure", "cpuTime", {"cpuTime", "work"}
        ) == "work";
}


// The cost fields' unit: seconds of CPU time, or counted work (in
// simulator moves) without a unit
dimensionSet costDimensions(const bool work)
{
    return work ? dimless : dimTime;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::loadBalance::cpuSeconds()
{
    return scalar(std::clock())/CLOCKS_PER_SEC;
}


Foam::scalar Foam::loadBalance::communication()
{
    scalar sum = 0;
    for (const scalar t : profilingPstream::times())
    {
        sum += t;
    }
    return sum;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::loadBalance::loadBalance(const fvMesh& mesh)
:
    mesh_(mesh),
    maxImbalance_
    (
        inputChecks::getIntervalOrDefault
        (
            settings(mesh), "maxImbalance",
            inputChecks::interval::open(1, VGREAT), VGREAT
        )
    ),
    candidateCost_
    (
        inputChecks::getIntervalOrDefault
        (
            settings(mesh), "candidateCost", inputChecks::interval::atLeast(0),
            0.2
        )
    ),
    countWork_(countsWork(mesh)),
    cost_(),
    resetCost_(false),
    computed_(Zero),
    communicated_(0),
    carried_(Zero),
    cpuStart_(0),
    commStart_(0),
    costStart_(0),
    stop_(false)
{
    if (inputChecks::getBoolOrDefault(settings(mesh), "cellCost", false))
    {
        cost_.setSize(names().size());
        forAll(cost_, i)
        {
            cost_.set
            (
                i,
                new volScalarField
                (
                    IOobject
                    (
                        names()[i],
                        mesh.time().timeName(),
                        mesh,
                        IOobject::NO_READ,
                        IOobject::AUTO_WRITE
                    ),
                    mesh,
                    dimensionedScalar(costDimensions(countWork_), Zero)
                )
            );
        }
    }

    if (Pstream::parRun() && !countWork_)
    {
        profilingPstream::enable();
    }
}


// * * * * * * * * * * * * * * Static Member Functions  * * * * * * * * * * //

const Foam::wordList& Foam::loadBalance::names()
{
    static const wordList fields
    ({
        "cellCostGasSimulators",
        "cellCostGasCollisions",
        cellTimer::fieldName,
        "cellCostGrains",
        "cellCost"
    });
    return fields;
}


void Foam::loadBalance::writeInitial(const fvMesh& mesh)
{
    if (!inputChecks::getBoolOrDefault(settings(mesh), "cellCost", false))
    {
        return;
    }

    for (const word& name : names())
    {
        IOobject io
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
        if (!io.typeHeaderOk<volScalarField>(false))
        {
            volScalarField
            (
                io,
                mesh,
                dimensionedScalar
                (
                    "uniform", costDimensions(countsWork(mesh)), 1.0
                )
            ).write();
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::loadBalance::begin(const phase which)
{
    if (resetCost_)
    {
        forAll(cost_, i)
        {
            cost_[i].primitiveFieldRef() = Zero;
        }
        resetCost_ = false;
    }

    cpuStart_ = cpuSeconds();
    commStart_ = communication();
    costStart_ =
        which == coupling && cost_.size()
      ? sum(cost_[couplingCells].primitiveField())
      : 0;
}


Foam::scalar Foam::loadBalance::spent
(
    const phase which,
    const scalar timed,
    const scalar work
)
{
    if (countWork_)
    {
        computed_[which] += work;
        return work;
    }

    const scalar comm = communication() - commStart_;
    const scalar spent = cpuSeconds() - cpuStart_ - comm;
    computed_[which] += spent;
    communicated_ += comm;

    // The communication time is counted in 10 ms ticks, so a step's share
    // can come out negative: it is carried to the next step instead
    const scalar rest = spent - timed + carried_[which];
    carried_[which] = min(rest, 0);
    return max(rest, 0);
}


template<class Type>
void Foam::loadBalance::spread
(
    scalarField& cost,
    const scalar time,
    const UList<Type>& weights,
    const scalar total
)
{
    if (total > 0)
    {
        forAll(cost, celli)
        {
            cost[celli] += time*weights[celli]/total;
        }
    }
    else if (cost.size())
    {
        cost += time/cost.size();
    }
}


void Foam::loadBalance::endGas
(
    const labelUList& simulators,
    const scalarField& candidates
)
{
    const scalarField C(candidateCost_*candidates);
    const scalar total = sum(simulators) + sum(C);
    const scalar rest = spent(gas, 0, total);
    if (cost_.empty() || rest <= 0)
    {
        return;
    }

    spread(cost_[gasSimulators].primitiveFieldRef(), rest, simulators, total);
    if (total > 0)
    {
        spread(cost_[gasCollisions].primitiveFieldRef(), rest, C, total);
    }
}


void Foam::loadBalance::end(const phase which, const labelUList& parcels)
{
    const label fieldi = which == coupling ? couplingCells : grainParcels;
    const scalar timed =
        which == coupling && cost_.size()
      ? sum(cost_[fieldi].primitiveField()) - costStart_
      : 0;
    const scalar total = sum(parcels);
    const scalar rest = spent(which, timed, total);
    if (cost_.empty() || rest <= 0)
    {
        return;
    }

    spread(cost_[fieldi].primitiveFieldRef(), rest, parcels, total);
}


void Foam::loadBalance::endStep()
{
    const Time& runTime = mesh_.time();
    if (!runTime.writeTime())
    {
        return;
    }

    if (Pstream::parRun())
    {
        // Largest and mean over the processors
        const auto overProcessors = [](const scalar x)
        {
            return Pair<scalar>
            (
                returnReduce(x, maxOp<scalar>()),
                returnReduce(x, sumOp<scalar>())/Pstream::nProcs()
            );
        };
        const auto ratio = [](const Pair<scalar>& s)
        {
            return s.second() > 0 ? s.first()/s.second() : 1;
        };

        const Pair<scalar> allPhases
        (
            overProcessors
            (
                computed_[gas] + computed_[coupling] + computed_[grains]
            )
        );
        const Pair<scalar> gasTimes(overProcessors(computed_[gas]));
        const Pair<scalar> couplingTimes
        (
            overProcessors(computed_[coupling])
        );
        const Pair<scalar> grainTimes(overProcessors(computed_[grains]));
        const Pair<scalar> commTimes(overProcessors(communicated_));
        const scalar imbalance = ratio(allPhases);

        if (countWork_)
        {
            Info<< "Load balance since the last write: counted work per"
                << " processor max/mean = " << imbalance << " (max "
                << allPhases.first() << ", mean " << allPhases.second()
                << " simulator moves; gas " << ratio(gasTimes)
                << ", coupling " << ratio(couplingTimes) << ", grains "
                << ratio(grainTimes) << ")" << endl;
        }
        else
        {
            Info<< "Load balance since the last write: compute time per"
                << " processor max/mean = " << imbalance << " (max "
                << allPhases.first() << " s, mean " << allPhases.second()
                << " s; gas "
                << ratio(gasTimes) << ", coupling " << ratio(couplingTimes)
                << ", grains " << ratio(grainTimes)
                << "); communication and waiting max " << commTimes.first()
                << " s, mean " << commTimes.second() << " s" << endl;
        }

        stop_ =
            imbalance > maxImbalance_
         && runTime.value()
          < runTime.endTime().value() - 0.5*runTime.deltaTValue();
        if (stop_)
        {
            Info<< "Stopping at t = " << runTime.timeName()
                << " to re-balance: max/mean " << imbalance
                << " > maxImbalance " << maxImbalance_ << " ("
                << runTime.controlDict().name() << "). Continue with"
                << " reconstructPar -newTimes; decomposePar -latestTime"
                << " -force (weighted by cellCost, or method"
                << " phaseBalanced); the solver again." << nl << endl;
        }
    }
    computed_ = Zero;
    communicated_ = 0;

    if (cost_.size())
    {
        // The total, raised to 1 % of the mean cell where below
        scalarField& total = cost_[all].primitiveFieldRef();
        total = Zero;
        for (label fieldi = 0; fieldi < all; ++fieldi)
        {
            total += cost_[fieldi].primitiveField();
        }
        const scalar floor =
            0.01*returnReduce(sum(total), sumOp<scalar>())
           /max(returnReduce(total.size(), sumOp<label>()), 1);
        total = max(total, max(floor, VSMALL));
        resetCost_ = true;
    }
}


// ************************************************************************* //
