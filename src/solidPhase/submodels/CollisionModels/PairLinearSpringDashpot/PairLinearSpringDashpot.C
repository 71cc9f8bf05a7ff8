/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "PairLinearSpringDashpot.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PairLinearSpringDashpot<CloudType>::PairLinearSpringDashpot
(
    const dictionary& dict,
    CloudType& cloud
)
:
    PairModel<CloudType>(dict, cloud, typeName),
    contact_(this->coeffDict())
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
const Foam::point& Foam::PairLinearSpringDashpot<CloudType>::positionOf
(
    const typename CloudType::parcelType& p
) const
{
    // The grains (real and referred) are built anew each step: a new
    // time index (a step, or a sub-cycle of one) empties the cache
    const label index = this->owner().db().time().timeIndex();
    if (index != cachedIndex_)
    {
        positions_.clear();
        cachedIndex_ = index;
    }

    auto found = positions_.find(&p);
    if (found == positions_.end())
    {
        found = positions_.emplace(&p, p.position()).first;
    }
    return found->second;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::PairLinearSpringDashpot<CloudType>::nSubCycles() const
{
    // The lightest contact: two of the lightest grains
    contact_.checkTimeStep(this->owner(), 0.5);
    contact_.reportOverlap(this->owner().db().time(), this->type());

    return 1;
}


template<class CloudType>
void Foam::PairLinearSpringDashpot<CloudType>::evaluatePair
(
    typename CloudType::parcelType& pA,
    typename CloudType::parcelType& pB
) const
{
    const vector r = positionOf(pA) - positionOf(pB);
    const scalar RA = pA.d()/2;
    const scalar RB = pB.d()/2;
    const scalar rMag = mag(r);
    const scalar overlap = RA + RB - rMag;

    if (overlap <= 0)
    {
        return;
    }

    const vector n = r/(rMag + VSMALL);
    const vector v =
        pA.U() - pB.U() - ((RA*pA.omega() + RB*pB.omega()) ^ n);
    const scalar mA = pA.mass();
    const scalar mB = pB.mass();

    vector& springA =
        pA.collisionRecords().matchPairRecord
        (
            pB.origProc(), pB.origId()
        ).collisionData();
    vector& springB =
        pB.collisionRecords().matchPairRecord
        (
            pA.origProc(), pA.origId()
        ).collisionData();

    const linearContact::forces f = contact_.contact
    (
        overlap, min(RA, RB), n, v, mA*mB/(mA + mB),
        this->owner().db().time().deltaTValue(), springA
    );
    springB = -springA;

    const vector F = f.normal + f.tangential;
    pA.f() += F;
    pB.f() -= F;
    pA.torque() += (-RA*n) ^ f.tangential;
    pB.torque() += (RB*n) ^ (-f.tangential);
}


// ************************************************************************* //
