/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "WallLinearSpringDashpot.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::WallLinearSpringDashpot<CloudType>::WallLinearSpringDashpot
(
    const dictionary& dict,
    CloudType& cloud
)
:
    WallModel<CloudType>(dict, cloud, typeName),
    contact_(this->coeffDict())
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::WallLinearSpringDashpot<CloudType>::evaluateSite
(
    typename CloudType::parcelType& p,
    const point& site
) const
{
    const scalar R = pREff(p);
    const vector r = p.position() - site;
    const scalar rMag = mag(r);
    const scalar overlap = R - rMag;

    if (overlap <= 0)
    {
        return;
    }

    const vector n = r/(rMag + VSMALL);
    // Walls at rest: the site data upstream passes (the carrier gas's
    // velocity there) is not a motion of the wall
    const vector v = p.U() + (p.omega() ^ (-R*n));

    vector& spring =
        p.collisionRecords().matchWallRecord(-r, R).collisionData();

    const linearContact::forces f = contact_.contact
    (
        overlap, R, n, v, p.mass(),
        this->owner().db().time().deltaTValue(), spring
    );

    p.f() += f.normal + f.tangential;
    p.torque() += (-R*n) ^ f.tangential;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::WallLinearSpringDashpot<CloudType>::nSubCycles() const
{
    contact_.checkTimeStep(this->owner(), 1);
    contact_.reportOverlap(this->owner().db().time(), this->type());

    return 1;
}


template<class CloudType>
void Foam::WallLinearSpringDashpot<CloudType>::evaluateWall
(
    typename CloudType::parcelType& p,
    const List<point>& flatSitePoints,
    const List<WallSiteData<vector>>& flatSiteData,
    const List<point>& sharpSitePoints,
    const List<WallSiteData<vector>>& sharpSiteData
) const
{
    forAll(flatSitePoints, i)
    {
        evaluateSite(p, flatSitePoints[i]);
    }
    forAll(sharpSitePoints, i)
    {
        evaluateSite(p, sharpSitePoints[i]);
    }
}


// ************************************************************************* //
