/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "particleAccount.H"
#include "restartState.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

namespace
{
    //- Owner name of the totals in the restart state
    const Foam::word accountOwner("particleAccount");
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleAccount::particleAccount
(
    const word& noun,
    const polyBoundaryMesh& patches,
    const label nPresentLocal
)
:
    noun_(noun),
    escapedStep_(patches.size(), Zero),
    escapedTotal_(patches.size(), Zero),
    present_(returnReduce(nPresentLocal, sumOp<label>()))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleAccount::closeStep
(
    const label nBeforeLocal,
    const label nNowLocal,
    const label nInLocal
)
{
    const label nPatches = escapedStep_.size();
    scalarField counts(nPatches + 7);
    forAll(escapedStep_, patchi)
    {
        counts[patchi] = escapedStep_[patchi];
    }
    counts[nPatches] = lostStep_;
    counts[nPatches + 1] = nNowLocal;
    counts[nPatches + 2] = nBeforeLocal;
    counts[nPatches + 3] = nInLocal;
    counts[nPatches + 4] = clonedStep_;
    counts[nPatches + 5] = deletedStep_;
    counts[nPatches + 6] = crossedStep_;

    Pstream::listCombineGather(counts, plusEqOp<scalar>());
    Pstream::listCombineScatter(counts);

    const SubField<scalar> escaped(counts, nPatches);
    const scalar now = counts[nPatches + 1];
    const scalar before = counts[nPatches + 2];

    lostLast_ = counts[nPatches];
    outLast_ = sum(escaped);
    clonedLast_ = counts[nPatches + 4];
    deletedLast_ = counts[nPatches + 5];
    crossedLast_ = counts[nPatches + 6];

    // What the weighting added (clones) less what it removed
    const scalar reweighted = clonedLast_ - deletedLast_;

    if (nInLocal < 0)
    {
        inLast_ = now - before + outLast_ + lostLast_ - reweighted;
    }
    else
    {
        inLast_ = counts[nPatches + 3];
        lostLast_ = before + inLast_ + reweighted - outLast_ - now;
    }

    present_ = now;
    escapedTotal_ += escaped;
    lostTotal_ += lostLast_;
    inTotal_ += inLast_;
    clonedTotal_ += clonedLast_;
    deletedTotal_ += deletedLast_;
    crossedTotal_ += crossedLast_;

    escapedStep_ = Zero;
    lostStep_ = 0;
    clonedStep_ = 0;
    deletedStep_ = 0;
    crossedStep_ = 0;
}


void Foam::particleAccount::info(const polyBoundaryMesh& patches) const
{
    // Labels padded to upstream's column of '='
    const auto label = [this](const char* what)
    {
        const std::string text("    " + noun_ + what);
        return text + std::string(max(1, 36 - int(text.size())), ' ');
    };

    Info<< label(" present").c_str() << "= " << present_ << nl
        << label(" in / out this step").c_str() << "= "
        << inLast_ << " / " << outLast_ + lostLast_ << nl
        << label(" in / out since start").c_str() << "= "
        << inTotal_ << " / " << sum(escapedTotal_) + lostTotal_
        << nl;

    if (weighted_)
    {
        Info<< label(" cloned / deleted this step").c_str() << "= "
            << clonedLast_ << " / " << deletedLast_ << nl
            << label(" cloned / deleted since start").c_str() << "= "
            << clonedTotal_ << " / " << deletedTotal_ << nl;
    }

    if (Pstream::parRun())
    {
        Info<< label(" crossed processors this step").c_str() << "= "
            << crossedLast_ << nl
            << label(" crossed processors since start").c_str() << "= "
            << crossedTotal_ << nl;
    }

    forAll(escapedTotal_, patchi)
    {
        if (escapedTotal_[patchi] > 0)
        {
            Info<< "        out through " << patches[patchi].name()
                << " = " << escapedTotal_[patchi] << nl;
        }
    }

    if (lostTotal_ != 0)
    {
        Info<< "        lost away from patches = " << lostTotal_ << nl;
    }

    Info<< endl;
}


void Foam::particleAccount::write
(
    const objectRegistry& db,
    const word& cloudName,
    const polyBoundaryMesh& patches
) const
{
    dictionary escaped;
    forAll(escapedTotal_, patchi)
    {
        if (escapedTotal_[patchi] != 0)
        {
            restartState::put
            (
                escaped, patches[patchi].name(), escapedTotal_[patchi]
            );
        }
    }

    dictionary state;
    restartState::put(state, "in", inTotal_);
    restartState::put(state, "lost", lostTotal_);
    restartState::put(state, "cloned", clonedTotal_);
    restartState::put(state, "deleted", deletedTotal_);
    restartState::put(state, "crossed", crossedTotal_);
    state.add("escaped", escaped);
    restartState::write(db, cloudName, accountOwner, state, true);
}


void Foam::particleAccount::read
(
    const objectRegistry& db,
    const word& cloudName,
    const polyBoundaryMesh& patches
)
{
    const dictionary state(restartState::read(db, cloudName, accountOwner));
    if (state.empty())
    {
        return;
    }

    inTotal_ = state.get<scalar>("in");
    lostTotal_ = state.get<scalar>("lost");
    clonedTotal_ = state.get<scalar>("cloned");
    deletedTotal_ = state.get<scalar>("deleted");
    crossedTotal_ = state.get<scalar>("crossed");
    const dictionary& escaped = state.subDict("escaped");
    forAll(escapedTotal_, patchi)
    {
        escapedTotal_[patchi] =
            escaped.getOrDefault<scalar>(patches[patchi].name(), 0);
    }
}


// ************************************************************************* //
