/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "AdaptiveCoupling.H"
#include "gasCloud.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "cellFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::AdaptiveCoupling<CloudType>::AdaptiveCoupling
(
    const dictionary& dict,
    CloudType& owner
)
:
    LothCoupling<CloudType>(dict, owner, typeName),
    KnSwitch_(10),
    sums_(),
    nFreeMolecular_(owner.mesh().nCells(), Zero),
    nLoth_(owner.mesh().nCells(), Zero)
{
    const dictionary& coeffs = dict.optionalSubDict(typeName + "Coeffs");
    if (dict.isDict(typeName + "Coeffs"))
    {
        inputChecks::rejectUnknown
        (
            coeffs, {"KnSwitch", "lift", "averagingSteps"}
        );
    }
    if (coeffs.found("KnSwitch"))
    {
        KnSwitch_ = inputChecks::getPositive(coeffs, "KnSwitch");
    }
    Info<< "    adaptive: free-molecular where Kn_p >= " << KnSwitch_
        << ", Loth below" << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::AdaptiveCoupling<CloudType>::writeFractions()
{
    const scalar nFm = gSum(nFreeMolecular_);
    const scalar nL = gSum(nLoth_);
    const scalar n = max(nFm + nL, 1);

    Info<< "adaptive: parcel-steps since last write: " << nFm + nL
        << ", free-molecular " << 100*nFm/n << " %, Loth "
        << 100*nL/n << " %" << endl;

    const scalarField total(max(nFreeMolecular_ + nLoth_, scalar(1)));
    const fvMesh& mesh = this->owner().mesh();
    const word& cloud = this->owner().name();
    writeCellField
    (
        mesh, cloud, "freeMolecularFraction", dimless,
        scalarField(nFreeMolecular_/total)
    );
    writeCellField
    (
        mesh, cloud, "LothFraction", dimless, scalarField(nLoth_/total)
    );

    nFreeMolecular_ = Zero;
    nLoth_ = Zero;
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::AdaptiveCoupling<CloudType>::parcelForcesAndHeat(gasCloud* gasPtr)
{
    gasCloud& gas = *gasPtr;
    if (!sums_.valid())
    {
        sums_.reset(new freeMolecularSums(gas));
    }
    this->updateGas(&gas);

    CloudType& cloud = this->owner();
    const scalar dt = cloud.db().time().deltaTValue();
    const scalarField& V = cloud.mesh().V();
    const scalar Wg = gas.nParticle();
    const auto& occupancy = gas.cellOccupancy();
    const gasCellAverage& average = this->average();

    typename LothCoupling<CloudType>::gasState g;
    vector dP;
    scalar dE;
    label gathered = -1;
    for (parcelType* pPtr : freeMolecularSums::byCell(cloud))
    {
        parcelType& p = *pPtr;
        const label celli = p.cell();
        const scalar lambda = average.lambda(celli);
        if (!(lambda > 0))
        {
            continue;
        }

        if (lambda >= KnSwitch_*p.d())
        {
            nFreeMolecular_[celli] += 1;
            const auto& inCell = occupancy[celli];
            if (!inCell.empty())
            {
                if (celli != gathered)
                {
                    sums_->gather(inCell);
                    gathered = celli;
                }
                sums_->apply(p, Wg, V[celli], dt, dP, dE);
                this->addExchange(celli, dP, dE);
            }
        }
        else
        {
            nLoth_[celli] += 1;
            if (this->cellGas(celli, g))
            {
                this->relax(p, g, dt);
            }
        }
    }

    if (cloud.db().time().writeTime())
    {
        writeFractions();
    }
}


// ************************************************************************* //
