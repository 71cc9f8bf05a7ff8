/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "CoupledGrainCloud.H"
#include "gasCarrierFields.H"
#include "sortByCell.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::CoupledGrainCloud<CloudType>::CoupledGrainCloud
(
    const word& cloudName,
    const gasCarrierFields& carrier,
    const dimensionedVector& g,
    const bool gasPresent
)
:
    cloud_(cloudName, carrier.rho, carrier.U, carrier.mu, g)
{
    const dictionary& subModels = cloud_.subModelProperties();

    if
    (
        gasPresent
     || subModels.found(InterphaseCouplingModel<CloudType>::typeName)
    )
    {
        coupling_ = InterphaseCouplingModel<CloudType>::New(subModels, cloud_);
        coupling_->checkForces(subModels);
        coupling_->checkGas(subModels, gasPresent);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
const Foam::dictionary&
Foam::CoupledGrainCloud<CloudType>::properties() const
{
    return cloud_.particleProperties();
}


template<class CloudType>
const Foam::axisymmetricMode&
Foam::CoupledGrainCloud<CloudType>::axisymmetric() const
{
    return cloud_.axisymmetric();
}


template<class CloudType>
void Foam::CoupledGrainCloud<CloudType>::coupleParcels(gasCloud* gas)
{
    if (coupling_.valid())
    {
        coupling_->coupleParcels(gas);
    }
}


template<class CloudType>
void Foam::CoupledGrainCloud<CloudType>::sortByCell()
{
    if ((cloud_.mesh().time().timeIndex() - 1) % sortInterval == 0)
    {
        Foam::sortByCell(cloud_);
    }
}


template<class CloudType>
const Foam::gasCellAverage&
Foam::CoupledGrainCloud<CloudType>::gasNow() const
{
    return coupling_->gasNow();
}


template<class CloudType>
void Foam::CoupledGrainCloud<CloudType>::evolve()
{
    cloud_.evolve();
}


template<class CloudType>
void Foam::CoupledGrainCloud<CloudType>::coupleGas(gasCloud& gas)
{
    if (coupling_.valid())
    {
        coupling_->coupleGas(gas);
    }
}


template<class CloudType>
Foam::labelList Foam::CoupledGrainCloud<CloudType>::parcelsPerCell() const
{
    labelList n(cloud_.mesh().nCells(), Zero);
    for (const auto& p : cloud_)
    {
        ++n[p.cell()];
    }
    return n;
}


// ************************************************************************* //
