/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "TwoWayCoupling.H"
#include "gasCloud.H"
#include "cellTimer.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "randomStreams.H"
#include "restartState.H"
#include "ntcSelection.H"
#include "normalTo.H"
#include "mathematicalConstants.H"
#include "physicoChemicalConstants.H"

// * * * * * * * * * * * * * * * Local helpers  * * * * * * * * * * * * * * //

namespace Foam
{
namespace TwoWayCouplingTools
{

//- The coefficients dictionary <type>Coeffs of subModels (null when not
//  given), after checking its keywords against valid
inline const dictionary& checkedCoeffs
(
    const dictionary& subModels,
    const word& type,
    const wordList& valid
)
{
    const word name(type + "Coeffs");
    if (!subModels.isDict(name))
    {
        return dictionary::null;
    }

    const dictionary& coeffs = subModels.subDict(name);
    inputChecks::rejectUnknown(coeffs, valid);
    return coeffs;
}


//- valid and the keywords every two-way model reads
inline wordList withCommon(const wordList& valid)
{
    wordList all(valid);
    all.append("randomSeed");
    all.append("maxCollisionsPerStep");
    return all;
}

} // End namespace TwoWayCouplingTools
} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::TwoWayCoupling<CloudType>::sigmaCrBound
(
    const UList<gasParcel*>& inCell,
    const UList<partner>& partners
)
{
    // |c_j - v_k| <= |c_j| + |v_k|
    scalar cMax = 0;
    for (const gasParcel* g : inCell)
    {
        cMax = max(cMax, mag(g->U()));
    }

    scalar vMax = 0;
    scalar WSigmaMax = 0;
    for (const partner& s : partners)
    {
        vMax = max(vMax, mag(s.U));
        WSigmaMax = max(WSigmaMax, s.W*s.sigma);
    }

    return WSigmaMax*(cMax + vMax);
}


template<class CloudType>
Foam::scalar Foam::TwoWayCoupling<CloudType>::equilibriumEi
(
    const scalar zeta,
    const scalar T
)
{
    // Gamma(zeta/2) k T: a sum of zeta/2 unit exponentials, and Z^2/2 for
    // an odd half
    const label nFull = label(zeta + 0.5)/2;
    scalar e = 0;
    for (label i = 0; i < nFull; ++i)
    {
        e -= log(1 - rnd_.sample01<scalar>());
    }
    if (label(zeta + 0.5) % 2)
    {
        e += 0.5*sqr(rnd_.GaussNormal<scalar>());
    }
    return e*constant::physicoChemical::k.value()*T;
}


template<class CloudType>
Foam::scalar Foam::TwoWayCoupling<CloudType>::vibrationalEnergy
(
    const gasParcel& g
) const
{
    return
        gasVibration_->active()
      ? gasVibration_->energy(g.typeId(), g.vibLevels())
      : 0;
}


template<class CloudType>
void Foam::TwoWayCoupling<CloudType>::reemit(gasParcel& g, const partner& s)
{
    using constant::mathematical::twoPi;

    const vector w(g.U() - s.U);
    const scalar magW = mag(w);
    if (magW < VSMALL)
    {
        return;
    }

    // Outward normal at a point uniform over the cross-section hit
    const vector wHat(w/magW);
    const vector e1(normalTo(wHat));
    const vector e2(wHat ^ e1);
    const scalar sinSqr = rnd_.sample01<scalar>();
    const scalar phi = twoPi*rnd_.sample01<scalar>();
    const vector n
    (
        -sqrt(1 - sinSqr)*wHat
      + sqrt(sinSqr)*(cos(phi)*e1 + sin(phi)*e2)
    );

    const scalar branch = rnd_.sample01<scalar>();
    if (branch < s.eps)
    {
        g.U() = s.U + w - 2*(w & n)*n;
        return;
    }

    const vector t1(normalTo(n));
    const vector t2(n ^ t1);
    const scalar psi = twoPi*rnd_.sample01<scalar>();

    if (branch < s.eps + (1 - s.eps)*s.alpha)
    {
        // Accommodated: flux-weighted half-range Maxwellian at T_p
        const label typei = g.typeId();
        const scalar kT = constant::physicoChemical::k.value()*s.T;
        const scalar m = mass_[typei];
        const scalar un = sqrt(-2*kT/m*log(1 - rnd_.sample01<scalar>()));
        const scalar ut = sqrt(kT/m);
        g.U() =
            s.U + un*n
          + ut*(rnd_.GaussNormal<scalar>()*t1 + rnd_.GaussNormal<scalar>()*t2);
        g.Ei() = equilibriumEi(zeta_[typei], s.T);
        if (gasVibration_->active())
        {
            gasVibration_->draw(typei, s.T, rnd_, g.vibLevels());
        }
    }
    else
    {
        // Not accommodated: cosine-law direction, incident speed
        const scalar sinSqrOut = rnd_.sample01<scalar>();
        g.U() =
            s.U
          + magW
           *(
                sqrt(1 - sinSqrOut)*n
              + sqrt(sinSqrOut)*(cos(psi)*t1 + sin(psi)*t2)
            );
    }
}


template<class CloudType>
void Foam::TwoWayCoupling<CloudType>::startStep(const gasCloud& gas)
{
    if (mass_.empty())
    {
        const auto& props = gas.constProps();
        mass_.setSize(props.size());
        zeta_.setSize(props.size());
        forAll(props, typei)
        {
            mass_[typei] = props[typei].mass();
            zeta_[typei] = props[typei].internalDegreesOfFreedom();
        }
    }

    Wg_ = gas.nParticle();
    gasAxisymmetric_ = &gas.axisymmetric();
    gasVibration_ = &gas.vibration();
    gained_ = gasGain();
    counts_ = stepCounts();
    subCycled_ = false;
}


template<class CloudType>
Foam::label Foam::TwoWayCoupling<CloudType>::collideCell
(
    const label celli,
    const UList<gasParcel*>& inCell,
    const UList<partner>& partners,
    const scalar dt
)
{
    const label Ng = inCell.size();
    const label Ns = partners.size();

    scalar& sigmaCrMax = sigmaCrMax_[celli];
    if (sigmaCrMax <= 0)
    {
        sigmaCrMax = sigmaCrBound(inCell, partners);
    }

    const scalar drawnMax = sigmaCrMax;
    const label nCandidates = ntcSelection::candidates
    (
        scalar(Ng)*Ns*drawnMax*dt/this->owner().mesh().V()[celli],
        remainder_[celli]
    );
    counts_.candidates += nCandidates;

    label nAccepted = 0;
    for (label i = 0; i < nCandidates; ++i)
    {
        gasParcel& g = *inCell[rnd_.position<label>(0, Ng - 1)];
        const partner& s = partners[rnd_.position<label>(0, Ns - 1)];

        const scalar WSigmaCr = s.W*s.sigma*mag(g.U() - s.U);
        if
        (
            ntcSelection::accept
            (
                WSigmaCr, drawnMax, sigmaCrMax, rnd_, counts_.over
            )
        )
        {
            const vector c0(g.U());
            const scalar Ei0 = g.Ei() + vibrationalEnergy(g);
            reemit(g, s);
            ++nAccepted;

            // What the gas gained (all W_g RWF(r) real molecules)
            const scalar Wg = Wg_*gasAxisymmetric_->weightAt(g.position());
            const scalar m = mass_[g.typeId()];
            const vector dP(Wg*m*(g.U() - c0));
            const scalar dE =
                Wg
               *(
                    0.5*m*(magSqr(g.U()) - magSqr(c0))
                  + g.Ei() + vibrationalEnergy(g) - Ei0
                );
            gained_.momentum += dP;
            gained_.energy += dE;
            gained_.momentumSqr += cmptSqr(dP);
            gained_.energySqr += sqr(dE);
        }
    }

    counts_.collisions += nAccepted;
    return nAccepted;
}


template<class CloudType>
Foam::label Foam::TwoWayCoupling<CloudType>::subSteps
(
    const label celli,
    const UList<gasParcel*>& inCell,
    const UList<partner>& partners,
    const scalar dt
) const
{
    scalar rateMax = 0;
    for (const gasParcel* g : inCell)
    {
        scalar rate = 0;
        for (const partner& s : partners)
        {
            rate += s.W*s.sigma*mag(g->U() - s.U);
        }
        rateMax = max(rateMax, rate);
    }

    // Beyond a million sub-steps (or an overflowing rate) the grains'
    // size and weight are outside what the coupling can resolve: stop
    // rather than convert an unbounded count
    const scalar x = rateMax*dt/this->owner().mesh().V()[celli];
    const scalar n = std::ceil(x/maxCollisionsPerStep_);
    if (!(n <= maxSubSteps_))
    {
        FatalIOErrorInFunction(this->dict())
            << "interphaseCoupling " << this->modelType() << ": cell "
            << celli << " needs " << n << " sub-steps (more than "
            << maxSubSteps_ << ") to keep maxCollisionsPerStep "
            << maxCollisionsPerStep_ << " per gas simulator: the grains'"
            << " cross-section times weight (W pi d^2/4) is too large for"
            << " the cell and time step"
            << nl << "    valid: grain diameters and parcel weights whose"
            << " collision rate needs at most " << maxSubSteps_
            << " sub-steps" << exit(FatalIOError);
    }
    return max(label(1), label(n));
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
typename Foam::TwoWayCoupling<CloudType>::partner
Foam::TwoWayCoupling<CloudType>::partnerOf(const parcelType& p)
{
    partner s;
    s.W = p.nParticle();
    s.sigma = constant::mathematical::pi*sqr(0.5*p.d());
    s.U = p.U();
    s.T = p.T();
    s.eps = p.specularFraction();
    s.alpha = p.thermalAccommodation();
    return s;
}


template<class CloudType>
void Foam::TwoWayCoupling<CloudType>::actOnCell
(
    const label celli,
    const UList<parcelType*>& parcels,
    const UList<gasParcel*>& inCell,
    const scalar Wg,
    const scalar dt
)
{
    const auto& partners = partners_[celli];
    const label n =
        partners.empty() ? 1 : subSteps(celli, inCell, partners, dt);

    if (n == 1)
    {
        OneWayCoupling<CloudType>::actOnCell(celli, parcels, inCell, Wg, dt);
        return;
    }

    // Grains and gas of this cell in turn, n times over dt/n (the
    // simulators stay in the cell: gathered once, then refreshed)
    label nAccepted = 0;
    for (label i = 0; i < n; ++i)
    {
        if (i == 0)
        {
            this->sums().gather(inCell);
        }
        else
        {
            this->sums().refresh(inCell);
        }
        this->applyGathered(celli, parcels, Wg, dt/n);
        nAccepted += collideCell(celli, inCell, partners, dt/n);
    }

    subCycled_[celli] = true;
    ++counts_.subCycledCells;
    counts_.subStepsMax = max(counts_.subStepsMax, n);
    counts_.probabilityMax =
        max(counts_.probabilityMax, scalar(nAccepted)/inCell.size());
}


template<class CloudType>
void Foam::TwoWayCoupling<CloudType>::parcelForcesAndHeat(gasCloud* gas)
{
    startStep(*gas);

    for (auto& list : partners_)
    {
        list.clear();
    }
    collectPartners();

    OneWayCoupling<CloudType>::parcelForcesAndHeat(gas);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::TwoWayCoupling<CloudType>::TwoWayCoupling
(
    const dictionary& dict,
    CloudType& owner,
    const word& type,
    const wordList& valid
)
:
    OneWayCoupling<CloudType>(dict, owner, type),
    rnd_
    (
        randomStreams::seed
        (
            inputChecks::getLabelOrDefault
            (
                TwoWayCouplingTools::checkedCoeffs
                (
                    dict, type, TwoWayCouplingTools::withCommon(valid)
                ),
                "randomSeed", 0, 0, 2000
            ),
            randomStreams::coupling
        )
    ),
    sigmaCrMax_(owner.mesh().nCells(), Zero),
    remainder_(owner.mesh().nCells(), Zero),
    maxCollisionsPerStep_
    (
        inputChecks::getPositiveOrDefault
        (
            TwoWayCouplingTools::checkedCoeffs
            (
                dict, type, TwoWayCouplingTools::withCommon(valid)
            ),
            "maxCollisionsPerStep", 0.1
        )
    ),
    subCycled_(owner.mesh().nCells(), false),
    counts_(),
    nCollisionsTotal_(0),
    Wg_(0),
    gasAxisymmetric_(nullptr),
    gasVibration_(nullptr),
    gained_(),
    mass_(),
    zeta_(),
    partners_(owner.mesh().nCells())
{
    const label nCells = owner.mesh().nCells();
    const dictionary state
    (
        restartState::read(owner.mesh(), owner.name(), stateName())
    );
    restartState::get(state, "random", rnd_);
    restartState::get(state, "sigmaCrMax", nCells, sigmaCrMax_);
    restartState::get(state, "remainder", nCells, remainder_);
    state.readIfPresent("nCollisionsTotal", nCollisionsTotal_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::TwoWayCoupling<CloudType>::coupleGas(gasCloud& gas)
{
    const scalar dt = this->owner().db().time().deltaTValue();
    const auto& occupancy = gas.cellOccupancy();
    cellTimer timer(this->owner().mesh());

    forAll(partners_, celli)
    {
        const auto& partners = partners_[celli];
        const auto& inCell = occupancy[celli];
        if (partners.empty() || inCell.empty() || subCycled_[celli])
        {
            continue;
        }

        timer.start();
        const label nAccepted = collideCell(celli, inCell, partners, dt);
        timer.stop(celli);
        counts_.probabilityMax =
            max(counts_.probabilityMax, scalar(nAccepted)/inCell.size());
    }
    nCollisionsTotal_ += counts_.collisions;

    stepCounts all(counts_);
    scalar total = nCollisionsTotal_;
    reduce(all.candidates, sumOp<label>());
    reduce(all.collisions, sumOp<label>());
    reduce(total, sumOp<scalar>());
    reduce(all.probabilityMax, maxOp<scalar>());
    reduce(all.subCycledCells, sumOp<label>());
    reduce(all.subStepsMax, maxOp<label>());
    all.over.reduce();

    reduce(gained_.momentum, sumOp<vector>());
    reduce(gained_.energy, sumOp<scalar>());
    reduce(gained_.momentumSqr, sumOp<vector>());
    reduce(gained_.energySqr, sumOp<scalar>());

    Info<< "    Gas-grain candidates, collisions, since start,"
        << " largest probability = " << all.candidates << ' '
        << all.collisions << ' ' << total << ' ' << all.probabilityMax << nl
        << "    Gas-grain sub-cycled cells, largest sub-steps = "
        << all.subCycledCells << ' ' << all.subStepsMax << nl
        << "    Gas-grain candidates with acceptance probability above 1,"
        << " largest = " << all.over.n << ' ' << all.over.largest << nl
        << "    Gas gain from grains: momentum, energy, sums of squares = "
        << gained_.momentum << ' ' << gained_.energy << ' '
        << gained_.momentumSqr << ' ' << gained_.energySqr << nl;

    if (this->owner().db().time().writeTime())
    {
        dictionary state;
        restartState::put(state, "random", rnd_);
        restartState::put(state, "sigmaCrMax", sigmaCrMax_);
        restartState::put(state, "remainder", remainder_);
        restartState::put(state, "nCollisionsTotal", nCollisionsTotal_);
        writeState(state);
        restartState::write
        (
            this->owner().mesh(), this->owner().name(), stateName(), state
        );
    }
}


// ************************************************************************* //
