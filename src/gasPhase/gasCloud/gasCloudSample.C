/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    gasCloud: the sampled fields (radially weighted), the cell state of the
    step and its average since the last write, and what is written from
    it at a write time.

\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "gasCellAverage.H"
#include "cellFields.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace Foam
{
namespace
{

//- The registered field that field is, writable
template<class FieldType>
FieldType& registered(const FieldType& field)
{
    return field.db().template lookupObjectRef<FieldType>(field.name());
}

} // End anonymous namespace
} // End namespace Foam


Foam::gasCloud::sampledFields::sampledFields
(
    const DSMCCloud<gasParcel>& cloud
)
:
    q(registered(cloud.q())),
    fD(registered(cloud.fD())),
    rhoN(registered(cloud.rhoN())),
    rhoM(registered(cloud.rhoM())),
    dsmcRhoN(registered(cloud.dsmcRhoN())),
    linearKE(registered(cloud.linearKE())),
    internalE(registered(cloud.internalE())),
    iDof(registered(cloud.iDof())),
    momentum(registered(cloud.momentum()))
{}


void Foam::gasCloud::sampledFields::reset()
{
    auto value = [](const volScalarField& field, const scalar v)
    {
        return dimensionedScalar("0", field.dimensions(), v);
    };
    q = value(q, Zero);
    fD = dimensionedVector("0", fD.dimensions(), Zero);
    rhoN = value(rhoN, VSMALL);
    rhoM = value(rhoM, VSMALL);
    dsmcRhoN = value(dsmcRhoN, Zero);
    linearKE = value(linearKE, Zero);
    internalE = value(internalE, Zero);
    iDof = value(iDof, VSMALL);
    momentum = dimensionedVector("0", momentum.dimensions(), Zero);
}


void Foam::gasCloud::sampleWeighted()
{
    // This cloud's sums replace upstream's unweighted ones
    volScalarField& rhoN = fields_.rhoN;
    volScalarField& rhoM = fields_.rhoM;
    volScalarField& dsmcRhoN = fields_.dsmcRhoN;
    volScalarField& linearKE = fields_.linearKE;
    volScalarField& internalE = fields_.internalE;
    volScalarField& iDof = fields_.iDof;
    volVectorField& momentum = fields_.momentum;

    // Upstream's starting values (VSMALL keeps divisions by rhoN finite);
    // the boundary values are the wall samples of this step's move
    rhoN.primitiveFieldRef() = VSMALL;
    rhoM.primitiveFieldRef() = VSMALL;
    dsmcRhoN.primitiveFieldRef() = Zero;
    linearKE.primitiveFieldRef() = Zero;
    internalE.primitiveFieldRef() = Zero;
    iDof.primitiveFieldRef() = VSMALL;
    momentum.primitiveFieldRef() = Zero;

    for (const gasParcel& p : *this)
    {
        const label celli = p.cell();
        const auto& props = constProps(p.typeId());
        const scalar w =
            axisymmetric_.weighted() ? axisymmetric_.weightAt(position(p)) : 1;
        const scalar m = props.mass();

        rhoN[celli] += w;
        rhoM[celli] += w*m;
        dsmcRhoN[celli] += 1;
        linearKE[celli] += w*0.5*m*magSqr(p.U());
        internalE[celli] += w*p.Ei();
        iDof[celli] += w*props.internalDegreesOfFreedom();
        momentum[celli] += w*m*p.U();
    }

    // Simulators per unit volume (already VSMALL-started) to real densities
    const scalarField scale(nParticle()/mesh().cellVolumes());

    rhoN.primitiveFieldRef() *= scale;
    rhoM.primitiveFieldRef() *= scale;
    linearKE.primitiveFieldRef() *= scale;
    internalE.primitiveFieldRef() *= scale;
    iDof.primitiveFieldRef() *= scale;
    momentum.primitiveFieldRef() *= scale;

    rhoN.correctBoundaryConditions();
    rhoM.correctBoundaryConditions();
    dsmcRhoN.correctBoundaryConditions();
    linearKE.correctBoundaryConditions();
    internalE.correctBoundaryConditions();
    iDof.correctBoundaryConditions();
    momentum.correctBoundaryConditions();
}


void Foam::gasCloud::addVibrationToFields()
{
    volScalarField& internalE = fields_.internalE;
    volScalarField& iDof = fields_.iDof;

    const scalarField& V = mesh().cellVolumes();
    forAll(V, celli)
    {
        const scalar scale = nParticle()/V[celli];
        internalE[celli] += scale*now_->vibrationalEnergy(celli);
        iDof[celli] += scale*now_->vibrationalDof(celli);
    }

    internalE.correctBoundaryConditions();
    iDof.correctBoundaryConditions();
}


void Foam::gasCloud::sampleCells()
{
    if (!now_.valid())
    {
        now_.reset(new gasCellAverage(*this, 1));
        sinceWrite_.reset(new gasCellAverage(*this, 0));
    }

    now_->sample(*this);
    if (resetSinceWrite_)
    {
        sinceWrite_->reset();
        resetSinceWrite_ = false;
    }
    sinceWrite_->add(now_());

    if (mesh().time().writeTime())
    {
        lambda_ = sinceWrite_->lambda();
        writeCellField(mesh(), "gas", "lambda", dimLength, lambda_);
        reportStepCriteria(sinceWrite_());
        reportMajorantExcess();
        subSteps_.write(mesh());
        bgk_.write(mesh());

        // (kept until the next step's sample, for the function objects
        // that write its means: gasVibrationalT)
        resetSinceWrite_ = true;
    }
}


// ************************************************************************* //
