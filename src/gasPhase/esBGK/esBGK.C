/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "esBGK.H"
#include "vhsCrossSection.H"
#include <cmath>
#include "inputChecks.H"
#include "keywordChecks.H"
#include "restartState.H"
#include "cellFields.H"
#include "vibrationalModes.H"
#include "BinaryCollisionModel.H"
#include "physicoChemicalConstants.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::esBGK::keyword("esBGK");
constexpr Foam::scalar Foam::esBGK::Pr;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::esBGK::collisionTime(const scalar n, const scalar T) const
{
    const scalar k = constant::physicoChemical::k.value();
    return
        1
       /(
            4*n*d_*d_*Foam::sqrt(constant::mathematical::pi*k*Tref_/m_)
           *Foam::pow(T/Tref_, 1 - omega_)
        );
}


Foam::scalar Foam::esBGK::viscosity(const scalar T) const
{
    return
        vhsCrossSection::referenceViscosity(m_, d_, omega_, Tref_)
       *Foam::pow(T/Tref_, omega_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::esBGK::esBGK
(
    const dictionary& props,
    const label nCells,
    const bool cartesian
)
:
    active_(props.found(keyword)),
    above_(0),
    below_(0),
    m_(0),
    zeta_(0),
    d_(0),
    omega_(0),
    Tref_(0),
    Z_(0),
    steps_(0),
    switches_(0)
{
    if (!active_)
    {
        return;
    }

    using namespace inputChecks;

    if (!props.isDict(keyword))
    {
        outOfRange
        (
            props, keyword, valueText(props, keyword),
            "a dictionary { switchAbove <Lambda>; switchBelow <Lambda>; }"
        );
    }
    const dictionary& dict =
        knownSubDict(props, keyword, {"switchAbove", "switchBelow"});
    above_ = getPositive(dict, "switchAbove");
    below_ =
        getInterval
        (
            dict, "switchBelow",
            interval::open(0, above_, "switchAbove = " + Foam::name(above_))
        );

    if (!cartesian)
    {
        outOfRange
        (
            props, "tracking", "barycentric",
            "cartesian (the default) with " + keyword
        );
    }

    bgk_.setSize(nCells, 0);
    bgkSteps_.setSize(nCells, 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::esBGK::setGas(const DSMCCloud<gasParcel>& cloud)
{
    if (!active_)
    {
        return;
    }

    using namespace inputChecks;

    const dictionary& props = cloud.particleProperties();
    const wordList species(props.get<wordList>("typeIdList"));
    if (species.size() != 1)
    {
        outOfRange
        (
            props, "typeIdList", species,
            "one species with " + keyword + " (its mixtures are not"
            " modelled)"
        );
    }
    const dictionary& molecule =
        props.subDict("moleculeProperties").subDict(species[0]);
    if (molecule.found(vibrationalModes::modesKeyword))
    {
        outOfRange
        (
            molecule, vibrationalModes::modesKeyword,
            valueText(molecule, vibrationalModes::modesKeyword),
            "none with " + keyword + " (it relaxes translation and"
            " rotation only)"
        );
    }

    const dictionary& coeffs = cloud.binaryCollision().coeffDict();
    if (!coeffs.found("Tref"))
    {
        outOfRange
        (
            props, "BinaryCollisionModel",
            valueText(props, "BinaryCollisionModel"),
            "with " + keyword + ", a model of the variable hard sphere's"
            " cross-section: VariableHardSphere,"
            " LarsenBorgnakkeVariableHardSphere, VariableSoftSphere,"
            " LarsenBorgnakkeVariableSoftSphere"
        );
    }

    const auto& P = cloud.constProps(0);
    m_ = P.mass();
    zeta_ = P.internalDegreesOfFreedom();
    d_ = P.d();
    omega_ = P.omega();
    Tref_ = coeffs.get<scalar>("Tref");
    Z_ = coeffs.getOrDefault<scalar>("relaxationCollisionNumber", 0);
}


bool Foam::esBGK::collide
(
    const label celli,
    const UList<gasParcel*>& members,
    const scalar n,
    const scalar dt,
    Random& rnd,
    scalar& Lambda
)
{
    const scalar k = constant::physicoChemical::k.value();
    const label N = members.size();

    // The cell's moments: mean velocity, temperature tensor [K]
    vector u(Zero);
    for (const gasParcel* p : members)
    {
        u += p->U();
    }
    u /= N;
    symmTensor S(Zero);
    scalar Erot = 0;
    for (const gasParcel* p : members)
    {
        S += sqr(p->U() - u);
        Erot += p->Ei();
    }
    const symmTensor Theta(m_/k*S/N);
    const scalar T = tr(Theta)/3;

    Lambda = T > 0 ? dt/collisionTime(n, T) : 0;

    const bool was = bgk_[celli] > 0.5;
    const bool bgk = was ? Lambda >= below_ : Lambda > above_;
    if (bgk != was)
    {
        switches_ += 1;
        bgk_[celli] = bgk;
    }
    if (!bgk)
    {
        return false;
    }
    bgkSteps_[celli] += 1;
    if (N < 3 || T <= 0)
    {
        return true;
    }

    // Translation: the target's covariance, exact anisotropic decay
    const scalar x = Pr*n*k*T/viscosity(T)*dt;
    const scalar P = -std::expm1(-x);
    const scalar b = 1 + std::expm1(-x/Pr)/P;
    const symmTensor A((1 - b)*T*symmTensor::I + b*Theta);

    // Its Cholesky factor (a degenerate tensor falls back to isotropy)
    scalar L00 = Foam::sqrt(max(A.xx(), 0));
    scalar L10 = 0, L20 = 0, L11 = 0, L21 = 0, L22 = 0;
    if (L00 > 0)
    {
        L10 = A.xy()/L00;
        L20 = A.xz()/L00;
        L11 = Foam::sqrt(max(A.yy() - sqr(L10), 0));
        if (L11 > 0)
        {
            L21 = (A.yz() - L20*L10)/L11;
            L22 = Foam::sqrt(max(A.zz() - sqr(L20) - sqr(L21), 0));
        }
    }
    if (!(L00 > 0 && L11 > 0 && L22 > 0))
    {
        L00 = L11 = L22 = Foam::sqrt(T);
        L10 = L20 = L21 = 0;
    }

    DynamicList<gasParcel*> relaxed(N);
    for (gasParcel* p : members)
    {
        if (rnd.sample01<scalar>() < P)
        {
            relaxed.append(p);
        }
    }
    const label nR = relaxed.size();

    // Rotation: redraws at T_eq, whose energy the cell's translation
    // gives or takes
    DynamicList<scalar> oldEi;
    DynamicList<gasParcel*> turned;
    scalar dE = 0;
    if (zeta_ > 0 && Z_ > 0)
    {
        const scalar Trot = 2*Erot/(N*zeta_*k);
        const scalar Teq = (3*T + zeta_*Trot)/(3 + zeta_);
        const scalar Zc = Z_*(1 + zeta_/(5 - 2*omega_));
        const scalar Prot =
            -std::expm1(-(1 + zeta_/3.0)*dt/(Zc*collisionTime(n, T)));
        for (gasParcel* p : members)
        {
            if (rnd.sample01<scalar>() < Prot)
            {
                scalar chi2 = 0;
                for (label i = 0; i < zeta_; ++i)
                {
                    chi2 += sqr(rnd.GaussNormal<scalar>());
                }
                turned.append(p);
                oldEi.append(p->Ei());
                const scalar Ei = 0.5*chi2*k*Teq;
                dE += Ei - p->Ei();
                p->Ei() = Ei;
            }
        }
    }
    if (nR == 0 && turned.empty())
    {
        return true;
    }

    // The relaxed simulators draw about the cell's mean (A in kelvin)
    const scalar kByM = Foam::sqrt(k/m_);
    for (gasParcel* p : relaxed)
    {
        const scalar z0 = rnd.GaussNormal<scalar>();
        const scalar z1 = rnd.GaussNormal<scalar>();
        const scalar z2 = rnd.GaussNormal<scalar>();
        p->U() =
            u
          + kByM
           *vector(L00*z0, L10*z0 + L11*z1, L20*z0 + L21*z1 + L22*z2);
    }

    // The cell's momentum and energy restored by a shift and a scale of
    // all its simulators about their mean (restoring them within the
    // relaxed set would keep in each relaxed simulator its share of the
    // set's old mean velocity: too slow a relaxation when few relax)
    vector uNew(Zero);
    for (const gasParcel* p : members)
    {
        uNew += p->U();
    }
    uNew /= N;
    scalar Enew = 0;
    for (const gasParcel* p : members)
    {
        Enew += 0.5*m_*magSqr(p->U() - uNew);
    }
    const scalar E = 0.5*m_*tr(S);
    scalar target = E - dE;
    if (target <= 0)
    {
        // (too little translational energy in the cell to pay for the
        // rotation: the rotation waits)
        forAll(turned, i)
        {
            turned[i]->Ei() = oldEi[i];
        }
        target = E;
    }
    const scalar scale = Enew > 0 ? Foam::sqrt(target/Enew) : 0;
    for (gasParcel* p : members)
    {
        p->U() = u + scale*(p->U() - uNew);
    }

    return true;
}


void Foam::esBGK::put(dictionary& state) const
{
    if (active_)
    {
        restartState::put(state, "bgkCells", bgk_);
    }
}


void Foam::esBGK::get(const dictionary& state)
{
    if (active_)
    {
        restartState::get(state, "bgkCells", bgk_.size(), bgk_);
    }
}


void Foam::esBGK::write(const fvMesh& mesh)
{
    if (!active_)
    {
        return;
    }

    label nBGK = 0;
    for (const scalar b : bgk_)
    {
        nBGK += (b > 0.5);
    }
    const label nCells = returnReduce(bgk_.size(), sumOp<label>());
    reduce(nBGK, sumOp<label>());
    reduce(switches_, sumOp<scalar>());
    const scalar steps = max(steps_, 1);

    Info<< "Gas ES-BGK since the last write: " << nBGK << " of " << nCells
        << " cells in BGK at the last step; " << switches_
        << " switches between DSMC and BGK" << endl;

    writeCellField(mesh, "gas", keyword, dimless, scalarField(bgkSteps_/steps));

    bgkSteps_ = 0;
    steps_ = 0;
    switches_ = 0;
}


// ************************************************************************* //
