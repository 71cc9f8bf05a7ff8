/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "regionFill.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
Foam::label Foam::regionFill::fill
(
    Cloud<ParcelType>& cloud,
    const scalar alphaMax,
    const word& alphaMaxWhat
)
{
    const drawing parcels(drawAll(alphaMax, alphaMaxWhat));

    // Place, in the order drawn: each parcel where it lies
    label nHere = 0;
    scalar realHere = 0;
    forAll(parcels.xs, i)
    {
        const point& x = parcels.xs[i];
        const label celli = parcels.cells[i];
        if (celli < 0)
        {
            continue;       // Another processor's, or outside the mesh
        }

        ParcelType* p = new ParcelType(mesh_, x, celli);
        p->typeId() = constProps_.parcelTypeId();
        p->nParticle() = parcels.W*axisymmetric_.weightAt(x);
        realHere += p->nParticle();
        p->d() = d_;
        p->dTarget() = d_;
        p->rho() = constProps_.rho0();
        p->U() = parcels.Us.size() ? parcels.Us[i] : U0_;
        p->setMaterial(constProps_);
        p->T() = T0_;
        cloud.addParticle(p);
        ++nHere;
    }

    return placed(parcels, nHere, realHere);
}


// ************************************************************************* //
