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

    forAll(cellOccupancy(), celli)
    {
        const DynamicList<gasParcel*>& members = cellOccupancy()[celli];
        const label n = members.size();
        if (n < 2)
        {
            continue;
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
            const DynamicList<label>& octant = octants[octantOf[i]];
            const label nOctant = octant.size();

            label j = i;
            while (j == i)
            {
                j = nOctant > 1
                  ? octant[rnd.position<label>(0, nOctant - 1)]
                  : rnd.position<label>(0, n - 1);
            }

            gasParcel& p = *members[i];
            gasParcel& q = *members[j];

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
