/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
\*---------------------------------------------------------------------------*/

#include "OneWayCoupling.H"
#include "gasCloud.H"
#include "physicoChemicalConstants.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::OneWayCoupling<CloudType>::OneWayCoupling
(
    const dictionary& dict,
    CloudType& owner
)
:
    InterphaseCouplingModel<CloudType>(dict, owner, typeName)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::OneWayCoupling<CloudType>::parcelForcesAndHeat(gasCloud& gas)
{
    using constant::mathematical::pi;
    const scalar k = constant::physicoChemical::k.value();
    const scalar sqrtPiBy3 = sqrt(pi)/3;

    CloudType& cloud = this->owner();
    const scalar dt = cloud.db().time().deltaTValue();
    const scalarField& V = cloud.mesh().V();
    const scalar Wg = gas.nParticle();
    const auto& occupancy = gas.cellOccupancy();

    // Per species: mass and the thermal factor (2 + zeta/2) k
    const auto& props = gas.constProps();
    const label nSpecies = props.size();
    scalarList mass(nSpecies);
    scalarList energyFactor(nSpecies);
    forAll(props, typei)
    {
        mass[typei] = props[typei].mass();
        energyFactor[typei] =
            (2 + 0.5*props[typei].internalDegreesOfFreedom())*k;
    }

    // Per parcel, per species: the diffuse re-emission speed term and the
    // energy a re-emitted molecule carries away (both depend on T_p)
    scalarList reemitSpeed(nSpecies);
    scalarList reemitEnergy(nSpecies);

    for (parcelType& p : cloud)
    {
        const label celli = p.cell();
        const auto& inCell = occupancy[celli];
        if (inCell.empty())
        {
            continue;
        }

        const scalar Tp = p.T();
        const scalar eps = p.specularFraction();
        const scalar alpha = p.thermalAccommodation();
        const scalar diffuse = (1 - eps)*alpha;
        const scalar incident = 1 + 4.0/9.0*(1 - eps)*(1 - alpha);

        forAll(props, typei)
        {
            reemitSpeed[typei] =
                diffuse*sqrtPiBy3*sqrt(2*k*Tp/mass[typei]);
            reemitEnergy[typei] = energyFactor[typei]*Tp;
        }

        const vector& Up = p.U();
        vector F(Zero);
        scalar Q = 0;
        for (const gasParcel* g : inCell)
        {
            const label typei = g->typeId();
            const scalar m = mass[typei];
            const vector w(g->U() - Up);
            const scalar magW = mag(w);

            F += (m*(incident*magW + reemitSpeed[typei]))*w;
            Q += magW*(0.5*m*sqr(magW) + g->Ei() - reemitEnergy[typei]);
        }

        const scalar scale = Wg*pi*sqr(0.5*p.d())/V[celli];
        F *= scale;
        Q *= scale*diffuse;

        const scalar mp = p.mass();
        p.U() += (dt/mp)*F;
        p.T() += (dt/(mp*p.Cp()))*Q;

        const scalar W = p.nParticle();
        this->addExchange(celli, (W*dt)*F, W*dt*Q);
    }
}


// ************************************************************************* //
