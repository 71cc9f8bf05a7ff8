/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
\*---------------------------------------------------------------------------*/

#include "OneWayCoupling.H"
#include "gasCloud.H"

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
void Foam::OneWayCoupling<CloudType>::parcelForcesAndHeat(gasCloud* gasPtr)
{
    gasCloud& gas = *gasPtr;
    if (!sums_.valid())
    {
        sums_.reset(new freeMolecularSums(gas));
    }

    CloudType& cloud = this->owner();
    const scalar dt = cloud.db().time().deltaTValue();
    const scalarField& V = cloud.mesh().V();
    const scalar Wg = gas.nParticle();
    const auto& occupancy = gas.cellOccupancy();

    vector dP;
    scalar dE;
    label gathered = -1;
    for (parcelType* pPtr : freeMolecularSums::byCell(cloud))
    {
        parcelType& p = *pPtr;
        const label celli = p.cell();
        const auto& inCell = occupancy[celli];
        if (inCell.empty())
        {
            continue;
        }
        if (celli != gathered)
        {
            sums_->gather(inCell);
            gathered = celli;
        }

        sums_->apply(p, Wg, V[celli], dt, dP, dE);
        this->addExchange(celli, dP, dE);
    }
}


// ************************************************************************* //
