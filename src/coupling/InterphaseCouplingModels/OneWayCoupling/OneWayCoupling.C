/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "OneWayCoupling.H"
#include "gasCloud.H"
#include "cellTimer.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::OneWayCoupling<CloudType>::OneWayCoupling
(
    const dictionary& dict,
    CloudType& owner
)
:
    OneWayCoupling<CloudType>(dict, owner, typeName)
{}


template<class CloudType>
Foam::OneWayCoupling<CloudType>::OneWayCoupling
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    InterphaseCouplingModel<CloudType>(dict, owner, type),
    sums_()
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::OneWayCoupling<CloudType>::applyGathered
(
    const label celli,
    const UList<parcelType*>& parcels,
    const scalar Wg,
    const scalar dt
)
{
    const scalar V = this->owner().mesh().V()[celli];

    vector dP;
    scalar dE;
    for (parcelType* pPtr : parcels)
    {
        sums_->apply(*pPtr, Wg, V, dt, dP, dE);
        this->addExchange(celli, dP, dE);
    }
}


template<class CloudType>
void Foam::OneWayCoupling<CloudType>::actOnCell
(
    const label celli,
    const UList<parcelType*>& parcels,
    const UList<gasParcel*>& inCell,
    const scalar Wg,
    const scalar dt
)
{
    sums_->gather(inCell);
    applyGathered(celli, parcels, Wg, dt);
}


template<class CloudType>
void Foam::OneWayCoupling<CloudType>::parcelForcesAndHeat(gasCloud* gasPtr)
{
    gasCloud& gas = *gasPtr;
    if (!sums_.valid())
    {
        sums_.reset(new freeMolecularSums(gas));
    }

    CloudType& cloud = this->owner();
    const scalar dt = cloud.db().time().deltaTValue();
    const scalar Wg = gas.nParticle();
    const auto& occupancy = gas.cellOccupancy();

    // The parcels cell by cell: each cell's run [start, end) of the list
    const auto parcels = freeMolecularSums::byCell(cloud);
    cellTimer timer(cloud.mesh());
    for (label start = 0, end = 0; start < parcels.size(); start = end)
    {
        const label celli = parcels[start]->cell();
        while (end < parcels.size() && parcels[end]->cell() == celli)
        {
            ++end;
        }

        const auto& inCell = occupancy[celli];
        if (!inCell.empty())
        {
            timer.start();
            actOnCell
            (
                celli,
                SubList<parcelType*>(parcels, end - start, start),
                inCell,
                Wg,
                dt
            );
            timer.stop(celli);
        }
    }
}


// ************************************************************************* //
