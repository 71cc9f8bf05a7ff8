/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "collisionSubSteps.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "restartState.H"
#include "cellFields.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::collisionSubSteps::keyword("collisionSubSteps");


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionSubSteps::collisionSubSteps
(
    const dictionary& props,
    const label nCells,
    const bool cartesian,
    const bool boundable
)
:
    active_(props.found(keyword)),
    perSubStep_(1),
    maxSubSteps_(64),
    subStepped_(0),
    largest_(0),
    capped_(0),
    wanted_(0),
    tried_(0),
    accepted_(0)
{
    if (!active_)
    {
        return;
    }

    using namespace inputChecks;

    if (!props.isDict(keyword))
    {
        outOfRange
        (
            props, keyword, valueText(props, keyword),
            "a dictionary { collisionsPerSubStep <Lambda>; maxSubSteps"
            " <k>; }"
        );
    }
    const dictionary& dict =
        knownSubDict(props, keyword, {"collisionsPerSubStep", "maxSubSteps"});
    perSubStep_ =
        getIntervalOrDefault
        (
            dict, "collisionsPerSubStep", interval::open(0, VGREAT), 1
        );
    maxSubSteps_ = getLabelOrDefault(dict, "maxSubSteps", 64, 1, 100000);

    if (!cartesian)
    {
        outOfRange
        (
            props, "tracking", "barycentric",
            "cartesian (the default) with " + keyword
        );
    }
    if (!boundable)
    {
        outOfRange
        (
            props, "BinaryCollisionModel",
            valueText(props, "BinaryCollisionModel"),
            "with " + keyword + ", a model of the variable hard sphere's"
            " cross-section: VariableHardSphere,"
            " LarsenBorgnakkeVariableHardSphere, VariableSoftSphere,"
            " LarsenBorgnakkeVariableSoftSphere"
        );
    }

    last_.setSize(nCells, 0);
    collisions_.setSize(nCells, 0);
    simulators_.setSize(nCells, 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::collisionSubSteps::subSteps(const label celli, const label n)
{
    const scalar Lambda = 2*last_[celli]/n;
    const scalar wanted = std::ceil(Lambda/perSubStep_);
    if (wanted <= 1)
    {
        return 1;
    }
    if (wanted > maxSubSteps_)
    {
        capped_ += 1;
        wanted_ = max(wanted_, label(min(wanted, scalar(labelMax))));
        largest_ = maxSubSteps_;
        subStepped_ += 1;
        return maxSubSteps_;
    }

    const label k = label(wanted);
    largest_ = max(largest_, k);
    subStepped_ += 1;
    return k;
}


void Foam::collisionSubSteps::record
(
    const label celli,
    const label n,
    const label tried,
    const label collided
)
{
    estimate(celli, n, collided);
    tried_ += tried;
    accepted_ += collided;
}


void Foam::collisionSubSteps::estimate
(
    const label celli,
    const label n,
    const scalar collisions
)
{
    last_[celli] = collisions;
    collisions_[celli] += collisions;
    simulators_[celli] += n;
}


void Foam::collisionSubSteps::put(dictionary& state) const
{
    if (active_)
    {
        restartState::put(state, "cellCollisions", last_);
    }
}


void Foam::collisionSubSteps::get(const dictionary& state)
{
    if (active_)
    {
        restartState::get(state, "cellCollisions", last_.size(), last_);
    }
}


void Foam::collisionSubSteps::write(const fvMesh& mesh)
{
    if (!active_)
    {
        return;
    }

    reduce(subStepped_, sumOp<scalar>());
    reduce(largest_, maxOp<label>());
    reduce(capped_, sumOp<scalar>());
    reduce(wanted_, maxOp<label>());
    reduce(tried_, sumOp<scalar>());
    reduce(accepted_, sumOp<scalar>());

    Info<< "Gas collision sub-steps since the last write: " << subStepped_
        << " cell-steps in more than one (largest " << largest_
        << "), capped " << capped_ << "; acceptance of the bound "
        << (tried_ > 0 ? accepted_/tried_ : 0) << endl;

    if (capped_ > 0)
    {
        WarningInFunction
            << capped_ << " cell-steps wanted more than maxSubSteps "
            << maxSubSteps_ << " collision sub-steps (up to " << wanted_
            << "): their collisions are right in number, each sub-step's"
            << " bound is looser; raise maxSubSteps in " << keyword
            << " or shorten deltaT" << endl;
    }

    scalarField Lambda(collisions_.size(), 0);
    forAll(Lambda, celli)
    {
        if (simulators_[celli] > 0)
        {
            Lambda[celli] = 2*collisions_[celli]/simulators_[celli];
        }
    }
    writeCellField(mesh, "gas", "collisionNumber", dimless, Lambda);

    collisions_ = 0;
    simulators_ = 0;
    subStepped_ = 0;
    largest_ = 0;
    capped_ = 0;
    wanted_ = 0;
    tried_ = 0;
    accepted_ = 0;
}


// ************************************************************************* //
