/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasCellAverage.H"
#include "restartState.H"
#include "vhsCrossSection.H"
#include "physicoChemicalConstants.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasCellAverage::gasCellAverage
(
    const gasCloud& gas,
    const label window
)
:
    mesh_(gas.mesh()),
    window_(window),
    count_(gas.constProps().size()),
    mass_(mesh_.nCells(), Zero),
    momentum_(mesh_.nCells(), Zero),
    twiceKinetic_(mesh_.nCells(), Zero),
    vibration_(gas.vibration()),
    m_(gas.constProps().size()),
    d_(m_.size()),
    omega_(m_.size()),
    zeta_(m_.size()),
    muRef_(m_.size()),
    Tref_
    (
        gas.binaryCollision().coeffDict().getOrDefault<scalar>("Tref", 273)
    ),
    Wg_(gas.nParticle())
{
    slot_.setSize(m_.size() + 1, Zero);
    forAll(m_, typei)
    {
        slot_[typei + 1] =
            slot_[typei] + vibration_.modeTheta(typei).size();
    }
    levels_.setSize(slot_.last());
    for (scalarField& l : levels_)
    {
        l.setSize(mesh_.nCells(), Zero);
    }

    forAll(m_, typei)
    {
        const auto& props = gas.constProps()[typei];
        count_[typei].setSize(mesh_.nCells(), Zero);
        m_[typei] = props.mass();
        d_[typei] = props.d();
        omega_[typei] = props.omega();
        zeta_[typei] = props.internalDegreesOfFreedom();
        muRef_[typei] =
            vhsCrossSection::referenceViscosity
            (
                m_[typei], d_[typei], omega_[typei], Tref_
            );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasCellAverage::sample(const gasCloud& gas)
{
    const scalar w = window_.next();
    const scalar keep = 1 - w;

    const auto& occupancy = gas.cellOccupancy();
    const axisymmetricMode& axisymmetric = gas.axisymmetric();
    const bool weighted = axisymmetric.weighted();

    forAll(occupancy, celli)
    {
        scalar M = 0;
        vector P = Zero;
        scalar E = 0;
        for (auto& c : count_)
        {
            c[celli] *= keep;
        }
        for (auto& l : levels_)
        {
            l[celli] *= keep;
        }
        for (const gasParcel* p : occupancy[celli])
        {
            // Radial weight factor: simulators per nParticle molecules
            const scalar f =
                weighted ? axisymmetric.weightAt(gas.position(*p)) : 1;
            const label typei = p->typeId();
            const scalar mi = f*m_[typei];
            count_[typei][celli] += w*f;
            M += mi;
            P += mi*p->U();
            E += mi*magSqr(p->U());

            const labelList& levels = p->vibLevels();
            const labelList& mode = vibration_.mode(typei);
            forAll(levels, k)
            {
                levels_[slot_[typei] + mode[k]][celli] += w*f*levels[k];
            }
        }
        mass_[celli] = keep*mass_[celli] + w*M;
        momentum_[celli] = keep*momentum_[celli] + w*P;
        twiceKinetic_[celli] = keep*twiceKinetic_[celli] + w*E;
    }
}


void Foam::gasCellAverage::add(const gasCellAverage& step)
{
    const scalar w = window_.next();
    const scalar keep = 1 - w;

    forAll(count_, typei)
    {
        count_[typei] = keep*count_[typei] + w*step.count_[typei];
    }
    forAll(levels_, i)
    {
        levels_[i] = keep*levels_[i] + w*step.levels_[i];
    }
    mass_ = keep*mass_ + w*step.mass_;
    momentum_ = keep*momentum_ + w*step.momentum_;
    twiceKinetic_ = keep*twiceKinetic_ + w*step.twiceKinetic_;
}


void Foam::gasCellAverage::reset()
{
    window_.reset();
    for (auto& c : count_)
    {
        c = Zero;
    }
    for (auto& l : levels_)
    {
        l = Zero;
    }
    mass_ = Zero;
    momentum_ = Zero;
    twiceKinetic_ = Zero;
}


void Foam::gasCellAverage::writeState(dictionary& state) const
{
    state.add("samples", window_.nSamples());
    forAll(count_, typei)
    {
        restartState::put(state, "count" + Foam::name(typei), count_[typei]);
    }
    restartState::put(state, "mass", mass_);
    restartState::put(state, "momentum", momentum_);
    restartState::put(state, "twiceKinetic", twiceKinetic_);
    forAll(levels_, i)
    {
        restartState::put(state, "levels" + Foam::name(i), levels_[i]);
    }
}


bool Foam::gasCellAverage::readState(const dictionary& state)
{
    const label nCells = mass_.size();
    List<scalarField> count(count_.size());
    List<scalarField> levels(levels_.size());
    scalarField mass, twiceKinetic;
    vectorField momentum;

    bool ok = state.found("samples");
    forAll(count, typei)
    {
        ok = ok && restartState::get
        (
            state, "count" + Foam::name(typei), nCells, count[typei]
        );
    }
    ok = ok
     && restartState::get(state, "mass", nCells, mass)
     && restartState::get(state, "momentum", nCells, momentum)
     && restartState::get(state, "twiceKinetic", nCells, twiceKinetic);
    forAll(levels, i)
    {
        ok = ok && restartState::get
        (
            state, "levels" + Foam::name(i), nCells, levels[i]
        );
    }
    if (!ok)
    {
        return false;
    }

    window_.restore(state.get<label>("samples"));
    count_.transfer(count);
    mass_.transfer(mass);
    momentum_.transfer(momentum);
    twiceKinetic_.transfer(twiceKinetic);
    levels_.transfer(levels);
    return true;
}


Foam::scalar Foam::gasCellAverage::nSimulators(const label celli) const
{
    scalar N = 0;
    for (const auto& c : count_)
    {
        N += c[celli];
    }
    return N;
}


Foam::scalar Foam::gasCellAverage::n(const label celli) const
{
    return Wg_*nSimulators(celli)/mesh_.V()[celli];
}


Foam::scalar Foam::gasCellAverage::rho(const label celli) const
{
    return Wg_*mass_[celli]/mesh_.V()[celli];
}


Foam::vector Foam::gasCellAverage::U(const label celli) const
{
    const scalar M = mass_[celli];
    return M > 0 ? momentum_[celli]/M : vector::zero;
}


Foam::scalar Foam::gasCellAverage::T(const label celli) const
{
    const scalar M = mass_[celli];
    const scalar N = nSimulators(celli);
    if (!(M > 0 && N > 0))
    {
        return 0;
    }
    return
        max(twiceKinetic_[celli] - magSqr(momentum_[celli])/M, 0)
       /(3*constant::physicoChemical::k.value()*N);
}


Foam::scalar Foam::gasCellAverage::mu(const label celli) const
{
    const scalar N = nSimulators(celli);
    const scalar Tc = T(celli);
    if (!(N > 0 && Tc > 0))
    {
        return 0;
    }
    scalar sum = 0;
    forAll(count_, typei)
    {
        sum += count_[typei][celli]*muRef_[typei]*pow(Tc/Tref_, omega_[typei]);
    }
    return sum/N;
}


Foam::scalar Foam::gasCellAverage::gamma(const label celli) const
{
    const scalar N = nSimulators(celli);
    scalar zeta = 0;
    if (N > 0)
    {
        forAll(count_, typei)
        {
            zeta += count_[typei][celli]*zeta_[typei];
        }
        zeta /= N;
    }
    return (5 + zeta)/(3 + zeta);
}


Foam::scalar Foam::gasCellAverage::R(const label celli) const
{
    const scalar M = mass_[celli];
    return
        M > 0
      ? constant::physicoChemical::k.value()*nSimulators(celli)/M
      : 0;
}


Foam::scalar Foam::gasCellAverage::lambda(const label celli) const
{
    using constant::mathematical::pi;

    const scalar N = nSimulators(celli);
    const scalar Tc = T(celli);
    if (!(N > 0 && Tc > 0))
    {
        return 0;
    }

    // sum_s x_s d_s^2 (Tref/T)^(omega_s - 1/2)
    scalar sigma = 0;
    forAll(count_, typei)
    {
        sigma +=
            count_[typei][celli]*sqr(d_[typei])
           *pow(Tref_/Tc, omega_[typei] - 0.5);
    }
    sigma /= N;

    return 1/(sqrt(2.0)*pi*n(celli)*sigma);
}


Foam::tmp<Foam::scalarField> Foam::gasCellAverage::lambda() const
{
    auto tl = tmp<scalarField>::New(mesh_.nCells());
    scalarField& l = tl.ref();
    forAll(l, celli)
    {
        l[celli] = lambda(celli);
    }
    return tl;
}


void Foam::gasCellAverage::vibrationalSums
(
    const label celli,
    const label typei,
    scalar& zeta,
    scalar& zetaT
) const
{
    zeta = 0;
    zetaT = 0;
    forAll(m_, s)
    {
        const scalar N = count_[s][celli];
        if ((typei >= 0 && s != typei) || !(N > 0))
        {
            continue;
        }
        forAll(vibration_.modeTheta(s), m)
        {
            // zeta T of a mode is 2 a theta
            const scalar theta = vibration_.modeTheta(s)[m];
            const scalar a = levels_[slot_[s] + m][celli]/N;
            zeta +=
                N
               *vibrationalModes::modeDof
                (
                    theta, vibration_.degeneracy(s)[m], a
                );
            zetaT += N*2*a*theta;
        }
    }
}


Foam::scalar Foam::gasCellAverage::vibrationalDof(const label celli) const
{
    scalar zeta, zetaT;
    vibrationalSums(celli, -1, zeta, zetaT);
    return zeta;
}


Foam::scalar Foam::gasCellAverage::vibrationalEnergy(const label celli) const
{
    scalar sum = 0;
    forAll(m_, typei)
    {
        forAll(vibration_.modeTheta(typei), m)
        {
            sum +=
                vibration_.modeTheta(typei)[m]
               *levels_[slot_[typei] + m][celli];
        }
    }
    return constant::physicoChemical::k.value()*sum;
}


Foam::tmp<Foam::scalarField> Foam::gasCellAverage::vibrationalT
(
    const label typei
) const
{
    auto tT = tmp<scalarField>::New(mesh_.nCells(), Zero);
    scalarField& T = tT.ref();
    forAll(T, celli)
    {
        scalar zeta, zetaT;
        vibrationalSums(celli, typei, zeta, zetaT);
        T[celli] = zeta > 0 ? zetaT/zeta : 0;
    }
    return tT;
}


// ************************************************************************* //
