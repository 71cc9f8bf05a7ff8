/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "LothCoupling.H"
#include "restartState.H"
#include "gasCloud.H"
#include "dragLaws.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "mathematicalConstants.H"
#include "fvcCurl.H"
#include "extrapolatedCalculatedFvPatchFields.H"

// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::LothCoupling<CloudType>::readCoeffs
(
    const dictionary& dict,
    const bool forceDsmc
)
{
    fromDsmc_ = true;
    if (!forceDsmc)
    {
        inputChecks::rejectUnknown
        (
            dict, {"gas", "lift", "averagingSteps", "prescribed"}
        );
        fromDsmc_ =
        (
            inputChecks::getChoice(dict, "gas", {"dsmc", "prescribed"})
         == "dsmc"
        );
    }

    lift_ = inputChecks::getBoolOrDefault(dict, "lift", false);
    if (lift_)
    {
        Info<< "    Loth: shear lift on" << endl;
    }

    if (fromDsmc_)
    {
        averagingSteps_ =
            inputChecks::getLabelOrDefault
            (
                dict, "averagingSteps", 200, 1, labelMax
            );
        Info<< "    Loth: gas from the DSMC cells, averaged over "
            << averagingSteps_ << " steps" << endl;
    }
    else
    {
        prescribed_.reset(new prescribedGas(dict.subDict("prescribed")));
    }
}


template<class CloudType>
void Foam::LothCoupling<CloudType>::updateVorticity()
{
    const fvMesh& mesh = this->owner().mesh();

    volVectorField Ug
    (
        IOobject("LothGasU", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        extrapolatedCalculatedFvPatchVectorField::typeName
    );
    gasState g;
    forAll(Ug, celli)
    {
        if (cellGas(celli, g))
        {
            Ug[celli] = g.U;
        }
    }
    Ug.correctBoundaryConditions();

    curlU_ = fvc::curl(Ug)().primitiveField();
}


template<class CloudType>
void Foam::LothCoupling<CloudType>::updateGas(gasCloud* gas)
{
    if (fromDsmc_)
    {
        if (!average_.valid())
        {
            average_.reset(new gasCellAverage(*gas, averagingSteps_));
            average_->readState(restart_);
            restart_.clear();
        }
        average_->add(this->gasNow());

        if (this->owner().db().time().writeTime())
        {
            dictionary state;
            average_->writeState(state);
            restartState::write
            (
                this->owner().mesh(), this->owner().name(), stateName, state
            );
        }
    }
    if (fromDsmc_ && lift_)
    {
        updateVorticity();
    }
}


template<class CloudType>
bool Foam::LothCoupling<CloudType>::cellGas
(
    const label celli,
    gasState& g
) const
{
    if (!fromDsmc_)
    {
        g = prescribed_->at(this->owner().mesh().C()[celli]);
        return true;
    }

    const gasCellAverage& a = average_();
    g.T = a.T(celli);
    g.mu = a.mu(celli);
    if (!(g.T > 0 && g.mu > 0))
    {
        return false;
    }
    g.rho = a.rho(celli);
    g.U = a.U(celli);
    g.gamma = a.gamma(celli);
    g.R = a.R(celli);
    g.Pr = 4*g.gamma/(9*g.gamma - 5);
    g.curlU = lift_ ? curlU_[celli] : vector::zero;
    return true;
}


template<class CloudType>
void Foam::LothCoupling<CloudType>::relax
(
    parcelType& p,
    const gasState& g,
    const scalar dt
)
{
    using constant::mathematical::pi;

    const scalar d = p.d();
    const scalar mp = p.mass();
    const vector U0(p.U());
    const scalar T0 = p.T();

    const vector v0(g.U - U0);
    const scalar magV0 = mag(v0);
    const scalar Re = g.rho*magV0*d/g.mu;
    const scalar sqrtRT = sqrt(g.R*g.T);

    // Drag: exact relaxation with C_D frozen over the step (expm1: a
    // heavy grain's change below the round-off of U still counts)
    vector dU(Zero);
    if (Re > 0)
    {
        const scalar Ma = magV0/(sqrt(g.gamma)*sqrtRT);
        const scalar Cd = dragLaws::lothCd(Re, Ma, g.gamma, T0/g.T);
        const scalar beta = Cd*(pi*sqr(d)/8)*g.rho*magV0/mp;
        dU = -expm1(-beta*dt)*v0;
    }

    // Shear lift, explicit
    const vector liftDir(v0 ^ g.curlU);
    if (lift_ && Re > 0 && mag(liftDir) > 0)
    {
        const scalar omegaStar = mag(g.curlU)*d/magV0;
        const scalar Cl = dragLaws::lothCl(Re, omegaStar);
        dU +=
            (Cl*(pi*sqr(d)/8)*g.rho*sqr(magV0)*dt/mp)
           *liftDir/mag(liftDir);
    }

    // Heat: Nu = Nu_c/(1 + Nu_c/Nu_fm) with Kn = lambda/d (dragLaws)
    const scalar Kn = g.mu/(g.rho*d)*sqrt(pi/2)/sqrtRT;
    const scalar NuC = dragLaws::nusseltContinuum(Re, g.Pr);
    const scalar NuFm =
        dragLaws::nusseltFreeMolecular(Kn, g.Pr, g.gamma, p.thermalAccommodation());
    const scalar Nu = NuC/(1 + NuC/NuFm);
    const scalar kappa = g.mu*g.gamma*g.R/((g.gamma - 1)*g.Pr);
    const scalar rate = Nu*pi*d*kappa/(mp*p.Cp());
    const scalar dT = -expm1(-rate*dt)*(g.T - T0);

    p.U() = U0 + dU;
    p.T() = T0 + dT;

    const scalar W = p.nParticle();
    this->addExchange(p.cell(), (W*mp)*dU, W*mp*p.Cp()*dT);
}


template<class CloudType>
void Foam::LothCoupling<CloudType>::parcelForcesAndHeat(gasCloud* gas)
{
    CloudType& cloud = this->owner();
    const scalar dt = cloud.db().time().deltaTValue();

    updateGas(gas);

    gasState g;
    for (parcelType& p : cloud)
    {
        if (planes_ && !planes_->gasActs(p.position()))
        {
            continue;
        }
        if (!fromDsmc_)
        {
            // At the parcel's position (a table varies within a cell)
            g = prescribed_->at(p.position());
            relax(p, g, dt);
        }
        else if (cellGas(p.cell(), g))
        {
            relax(p, g, dt);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::LothCoupling<CloudType>::LothCoupling
(
    const dictionary& dict,
    CloudType& owner,
    const word& type,
    const bool forceDsmc
)
:
    InterphaseCouplingModel<CloudType>(dict, owner, type),
    fromDsmc_(true),
    averagingSteps_(1),
    prescribed_(nullptr),
    average_(),
    lift_(false),
    curlU_(),
    planes_(nullptr),
    restart_(restartState::read(owner.mesh(), owner.name(), stateName))
{
    planes_ = gasShelter::find(owner.functions());

    readCoeffs
    (
        forceDsmc
      ? dict.optionalSubDict(type + "Coeffs")
      : dict.subDict(type + "Coeffs"),
        forceDsmc
    );
}


template<class CloudType>
Foam::LothCoupling<CloudType>::LothCoupling
(
    const dictionary& dict,
    CloudType& owner
)
:
    LothCoupling<CloudType>(dict, owner, typeName, false)
{}


template<class CloudType>
Foam::LothCoupling<CloudType>::LothCoupling
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    LothCoupling<CloudType>(dict, owner, type, true)
{}


// ************************************************************************* //
