/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "ZonalGravityForce.H"
#include "inputChecks.H"
#include "keywordChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ZonalGravityForce<CloudType>::ZonalGravityForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    g_(owner.g().value()),
    zeroGravity_(mesh.nCells(), false)
{
    inputChecks::rejectUnknown(this->coeffs(), {"zeroGravityZone"});
    const word zoneName
    (
        inputChecks::getChoice
        (
            this->coeffs(), "zeroGravityZone", mesh.cellZones().names()
        )
    );
    const label zonei = mesh.cellZones().findZoneID(zoneName);

    for (const label celli : mesh.cellZones()[zonei])
    {
        zeroGravity_[celli] = true;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::forceSuSp Foam::ZonalGravityForce<CloudType>::calcNonCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    forceSuSp value(Zero);

    if (!zeroGravity_[p.cell()])
    {
        value.Su() = mass*g_*(1 - td.rhoc()/p.rho());
    }

    return value;
}


// ************************************************************************* //
