/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    gasCloud: the NTC collisions of the Cartesian move.

\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "BinaryCollisionModel.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::gasCloud::pick
(
    const label n,
    const label i,
    const DynamicList<label>& octant
)
{
    Random& rnd = rndGen();
    const label nOctant = octant.size();

    label j = i;
    while (j == i)
    {
        j = nOctant > 1
          ? octant[rnd.position<label>(0, nOctant - 1)]
          : rnd.position<label>(0, n - 1);
    }
    return j;
}


Foam::label Foam::gasCloud::collideBounded
(
    const label celli,
    const List<DynamicList<label>>& octants,
    const UList<label>& octantOf,
    label& nTried
)
{
    const DynamicList<gasParcel*>& members = cellOccupancy()[celli];
    const label n = members.size();
    Random& rnd = rndGen();
    scalar& remainder = collisionSelectionRemainder()[celli];
    const scalar w =
        axisymmetric_.weighted() ? cellWeight_[celli] : scalar(1);

    const label k = subSteps_.subSteps(celli, n);

    // The bound is exact for the pair of the two fastest simulators about
    // the mean (two simulators: always); its power and that of sigmaTcR
    // round apart by an ulp or two
    constexpr scalar roundUp = 1 + 1e-12;

    // Candidates per unit majorant in a sub-step
    const scalar rate =
        0.5*n*(n - 1)*nParticle()*w*mesh().time().deltaTValue()
       /(k*mesh().cellVolumes()[celli]);

    label tried = 0;
    label collided = 0;
    scalar bound = 0;
    ntcSelection::excess over;     // (none unless the bound is wrong)
    for (label s = 0; s < k; ++s)
    {
        // The two largest speeds about the mean velocity bound every
        // relative speed in the cell
        vector mean(Zero);
        for (const gasParcel* p : members)
        {
            mean += p->U();
        }
        mean /= n;

        scalar d1 = 0;
        scalar d2 = 0;
        auto spread = [&](const gasParcel& p)
        {
            const scalar d = mag(p.U() - mean);
            if (d > d1)
            {
                d2 = d1;
                d1 = d;
            }
            else if (d > d2)
            {
                d2 = d;
            }
        };
        for (const gasParcel* p : members)
        {
            spread(*p);
        }
        bound = roundUp*vhs_->largest(sqr(d1 + d2));

        // Candidates as time at the bound's rate: a raised bound scales
        // what is left of the sub-step
        scalar budget = rate*bound + remainder;
        while (budget >= 1)
        {
            budget -= 1;
            ++tried;

            const label i = rnd.position<label>(0, n - 1);
            const label j = pick(n, i, octants[octantOf[i]]);
            gasParcel& p = *members[i];
            gasParcel& q = *members[j];

            scalar drawn = bound;
            if
            (
                ntcSelection::accept
                (
                    vhs_->sigmaTcR(p, q), drawn, bound, rnd, over
                )
            )
            {
                binaryCollision().collide(p, q);
                ++collided;

                const scalar before = d1 + d2;
                spread(p);
                spread(q);
                if (d1 + d2 > before)
                {
                    const scalar raised =
                        roundUp*vhs_->largest(sqr(d1 + d2));
                    budget *= raised/bound;
                    bound = raised;
                }
            }
        }
        remainder = budget;
    }

    if (over.n > 0)
    {
        majorantExcess_.n += 1;
        majorantExcess_.largest = max(majorantExcess_.largest, over.largest);
    }
    sigmaTcRMax()[celli] = bound;
    subSteps_.record(celli, n, tried, collided);
    nTried += tried;
    return collided;
}


void Foam::gasCloud::collide()
{
    if (!binaryCollision().active())
    {
        return;
    }

    const scalar dt = mesh().time().deltaTValue();
    const scalarField& V = mesh().cellVolumes();
    const vectorField& centres = mesh().cellCentres();
    scalarField& majorant = sigmaTcRMax().primitiveFieldRef();
    scalarField& remainder = collisionSelectionRemainder();
    Random& rnd = rndGen();

    // Counted by evolve from the majorants before and after
    ntcSelection::excess uncounted;

    List<DynamicList<label>> octants(8);
    DynamicList<label> octantOf;
    label nTried = 0;
    label nCollided = 0;

    if (bgk_.active())
    {
        bgk_.newStep();
    }

    forAll(cellOccupancy(), celli)
    {
        const DynamicList<gasParcel*>& members = cellOccupancy()[celli];
        const label n = members.size();
        if (n < 2)
        {
            if (subSteps_.active())
            {
                subSteps_.record(celli, n, 0, 0);
            }
            continue;
        }

        if (bgk_.active())
        {
            const scalar w =
                axisymmetric_.weighted() ? cellWeight_[celli] : scalar(1);
            scalar Lambda = 0;
            if
            (
                bgk_.collide
                (
                    celli, members, n*nParticle()*w/V[celli], dt, rnd,
                    Lambda
                )
            )
            {
                if (subSteps_.active())
                {
                    subSteps_.estimate(celli, n, 0.5*Lambda*n);
                }
                continue;
            }
        }

        for (auto& octant : octants)
        {
            octant.clear();
        }
        octantOf.resize(n);
        forAll(members, i)
        {
            label k = members[i]->octant();
            if (k == gasParcel::noOctant)
            {
                // (in the axisymmetric mode the quadrant in the plane)
                const vector r(position(*members[i]) - centres[celli]);
                k = pos0(r.x()) + 2*pos0(r.y())
                  + (wedges_ ? 0 : 4*pos0(r.z()));
            }
            octants[k].append(i);
            octantOf[i] = k;
        }

        if (subSteps_.active())
        {
            nCollided += collideBounded(celli, octants, octantOf, nTried);
            continue;
        }

        const scalar drawnMax = majorant[celli];
        const label nCandidates = ntcSelection::candidates
        (
            0.5*n*(n - 1)*nParticle()*drawnMax*dt/V[celli],
            remainder[celli]
        );
        nTried += nCandidates;

        for (label c = 0; c < nCandidates; ++c)
        {
            const label i = rnd.position<label>(0, n - 1);
            gasParcel& p = *members[i];
            gasParcel& q = *members[pick(n, i, octants[octantOf[i]])];

            if
            (
                ntcSelection::accept
                (
                    vhs_->active()
                  ? vhs_->sigmaTcR(p, q)
                  : binaryCollision().sigmaTcR(p, q),
                    drawnMax, majorant[celli], rnd, uncounted
                )
            )
            {
                binaryCollision().collide(p, q);
                ++nCollided;
            }
        }
    }

    sigmaTcRMax().correctBoundaryConditions();

    // Upstream's log lines
    reduce(nTried, sumOp<label>());
    reduce(nCollided, sumOp<label>());
    if (nTried)
    {
        Info<< "    Collisions                      = " << nCollided << nl
            << "    Acceptance rate                 = "
            << scalar(nCollided)/nTried << nl << endl;
    }
    else
    {
        Info<< "    No collisions" << endl;
    }
}


// ************************************************************************* //
