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
    InterphaseCouplingModel<CloudType>(dict, owner, typeName),
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

    // The parcels grouped by cell (stable: in cloud order within a cell),
    // so that each cell's simulators are gathered once for all its parcels
    DynamicList<parcelType*> parcels(cloud.size());
    DynamicList<label> cells(cloud.size());
    for (parcelType& p : cloud)
    {
        parcels.append(&p);
        cells.append(p.cell());
    }
    labelList order;
    sortedOrder(cells, order);

    vector dP;
    scalar dE;
    label gathered = -1;
    for (const label i : order)
    {
        parcelType& p = *parcels[i];
        const label celli = cells[i];
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
