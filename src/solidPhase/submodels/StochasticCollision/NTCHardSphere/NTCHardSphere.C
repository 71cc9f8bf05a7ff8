/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "NTCHardSphere.H"
#include "keywordChecks.H"
#include "inputChecks.H"
#include "randomStreams.H"
#include "restartState.H"
#include "ntcSelection.H"
#include "parcelsByCell.H"
#include "volFields.H"
#include "cellFields.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Input checks  * * * * * * * * * * * * * * * //

namespace Foam
{
namespace NTCHardSphereChecks
{

//- Read an optional volume fraction threshold and check 0 < value <= 1
inline scalar getFraction
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt
)
{
    return inputChecks::getIntervalOrDefault
    (
        dict, keyword, inputChecks::interval::above(0, 1), deflt
    );
}

} // End namespace NTCHardSphereChecks
} // End namespace Foam


template<class CloudType>
Foam::NTCHardSphere<CloudType>::coeffs::coeffs(const dictionary& subModels)
:
    dict
    (
        inputChecks::knownSubDict
        (
            subModels, typeName + "Coeffs",
            {"e", "alphaValid", "alphaSwitch", "randomSeed"}
        )
    ),
    e(inputChecks::getClosed(dict, "e", 0, 1)),
    alphaValid(NTCHardSphereChecks::getFraction(dict, "alphaValid", 0.1)),
    alphaSwitch
    (
        // (no default: absent, NTC runs wherever the grains are)
        dict.found("alphaSwitch")
      ? NTCHardSphereChecks::getFraction(dict, "alphaSwitch", 1)
      : GREAT
    ),
    randomSeed(inputChecks::getLabelOrDefault(dict, "randomSeed", 0, 0, 2000))
{}


template<class CloudType>
void Foam::NTCHardSphere<CloudType>::check
(
    const dictionary& subModels,
    const dictionary&
)
{
    coeffs{subModels};      // (read and checked, then dropped)
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::word Foam::NTCHardSphere<CloudType>::fieldName(const word& name) const
{
    return name + "." + this->owner().name();
}


template<class CloudType>
Foam::scalar Foam::NTCHardSphere<CloudType>::sigmaCrBound
(
    const DynamicList<parcelType*>& parcels
)
{
    // |v_p - v_q| <= |v_p - <v>| + |v_q - <v>| <= 2 max|v - <v>| and
    // pi (R_p + R_q)^2 <= pi d_max^2
    vector mean(Zero);
    scalar dMax = 0;
    for (const parcelType* p : parcels)
    {
        mean += p->U();
        dMax = max(dMax, p->d());
    }
    mean /= parcels.size();

    scalar devMax = 0;
    for (const parcelType* p : parcels)
    {
        devMax = max(devMax, mag(p->U() - mean));
    }

    return constant::mathematical::pi*sqr(dMax)*2*devMax;
}


template<class CloudType>
Foam::label Foam::NTCHardSphere<CloudType>::collideCell
(
    const label celli,
    const DynamicList<parcelType*>& parcels,
    const scalar dt,
    label& nAccepted
)
{
    using constant::mathematical::pi;
    using constant::mathematical::twoPi;

    const label N = parcels.size();

    // Never below the bound of this step's pairs: a majorant set while
    // the cell's grains moved together would otherwise stay too small to
    // draw the candidates that raise it
    scalar& sigmaCrMax = sigmaCrMax_[celli];
    sigmaCrMax = max(sigmaCrMax, sigmaCrBound(parcels));
    const scalar drawnMax = sigmaCrMax;

    scalar WMax = 0;
    for (const parcelType* p : parcels)
    {
        WMax = max(WMax, p->nParticle());
    }

    const label nPairs = ntcSelection::candidates
    (
        WMax*N*(N - 1)*sigmaCrMax*dt/(2*this->owner().mesh().V()[celli]),
        remainder_[celli]
    );

    for (label pairi = 0; pairi < nPairs; ++pairi)
    {
        // Two distinct parcels, uniformly
        const label i = rnd_.position<label>(0, N - 1);
        label j = rnd_.position<label>(0, N - 2);
        if (j >= i)
        {
            ++j;
        }
        parcelType& p = *parcels[i];
        parcelType& q = *parcels[j];

        const scalar cr = mag(p.U() - q.U());
        const scalar sigmaCr = pi*sqr(0.5*(p.d() + q.d()))*cr;

        if
        (
            !ntcSelection::accept(sigmaCr, drawnMax, sigmaCrMax, rnd_, over_)
        )
        {
            continue;
        }

        ++nAccepted;

        const scalar mp = p.mass();
        const scalar mq = q.mass();
        const scalar M = mp + mq;
        const vector Um((mp*p.U() + mq*q.U())/M);

        // Isotropic unit vector
        const scalar cosTheta = 2*rnd_.sample01<scalar>() - 1;
        const scalar sinTheta = sqrt(max(1 - sqr(cosTheta), scalar(0)));
        const scalar phi = twoPi*rnd_.sample01<scalar>();
        const vector n(sinTheta*cos(phi), sinTheta*sin(phi), cosTheta);

        // |v_p - v_m| = m_q c_r/M, |v_q - v_m| = m_p c_r/M
        const scalar crPost = e_*cr;

        // Energy lost per real pair, split by mass
        const scalar dEbyM = (1 - sqr(e_))*0.5*(mp*mq/M)*sqr(cr)/M;

        // Unequal weights: each parcel takes the collision with the
        // probability that its particles meet the other's (see Description)
        const scalar Wp = p.nParticle();
        const scalar Wq = q.nParticle();
        const bool updateP =
            Wq >= WMax || rnd_.sample01<scalar>()*WMax < Wq;
        const bool updateQ =
            Wp >= WMax || rnd_.sample01<scalar>()*WMax < Wp;

        if (updateP)
        {
            p.U() = Um + (crPost*mq/M)*n;
            p.T() += dEbyM/p.Cp();
        }
        if (updateQ)
        {
            q.U() = Um - (crPost*mp/M)*n;
            q.T() += dEbyM/q.Cp();
        }
    }

    return nPairs;
}


template<class CloudType>
void Foam::NTCHardSphere<CloudType>::writeFields(const scalarField& alpha)
{
    const fvMesh& mesh = this->owner().mesh();

    const word& cloud = this->owner().name();
    writeCellField(mesh, cloud, "sigmaCrMax", dimVolume/dimTime, sigmaCrMax_);
    writeCellField(mesh, cloud, "nCandidates", dimless, nCandidates_);
    writeCellField(mesh, cloud, "nCollisions", dimless, nCollisions_);

    // Step guards since the previous write
    scalar perStepMax = 0;
    label nCellsAbove = 0;
    forAll(nParcelSteps_, celli)
    {
        if (nCollisions_[celli] >= 10)
        {
            const scalar perStep = 2*nCollisions_[celli]/nParcelSteps_[celli];
            perStepMax = max(perStepMax, perStep);
            nCellsAbove += (perStep > 1);
        }
    }
    reduce(perStepMax, maxOp<scalar>());
    reduce(nCellsAbove, sumOp<label>());
    over_.reduce();

    Info<< "    " << typeName << ": collisions per parcel per step since"
        << " the last write largest " << perStepMax << " (" << nCellsAbove
        << " cells above 1); candidates with acceptance probability above"
        << " 1 " << over_.n << " (largest " << over_.largest << ")" << nl;

    if (nCellsAbove || over_.n > 0)
    {
        WarningInFunction
            << "deltaT " << mesh.time().deltaTValue() << " s is too long for"
            << " the grain collisions in " << nCellsAbove << " cells (up to "
            << perStepMax << " collisions per parcel per step), and "
            << over_.n << " candidates had an acceptance probability above"
            << " 1 (up to " << over_.largest << "): shorten deltaT in"
            << " system/controlDict" << endl;
    }

    nCandidates_ = 0;
    nCollisions_ = 0;
    nParcelSteps_ = 0;
    over_ = ntcSelection::excess();

    dictionary state;
    restartState::put(state, "random", rnd_);
    restartState::put(state, "remainder", remainder_);
    restartState::write(mesh, cloud, typeName, state);

    // Validity of binary collisions
    label nAbove = 0;
    label nAboveColliding = 0;
    forAll(alpha, celli)
    {
        if (alpha[celli] > alphaValid_)
        {
            ++nAbove;
            if (alpha[celli] < alphaSwitch_)
            {
                ++nAboveColliding;
            }
        }
    }
    reduce(nAbove, sumOp<label>());
    reduce(nAboveColliding, sumOp<label>());

    Info<< "    " << typeName << ": " << nAbove << " of "
        << returnReduce(alpha.size(), sumOp<label>())
        << " cells above alphaValid = " << alphaValid_
        << " (binary collisions not valid there), " << nAboveColliding
        << " of them colliding" << nl;
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::NTCHardSphere<CloudType>::collide
(
    typename parcelType::trackingData&,
    const scalar dt
)
{
    const fvMesh& mesh = this->owner().mesh();
    const scalarField& V = mesh.V();
    const label nCells = mesh.nCells();

    if (sigmaCrMax_.size() != nCells)
    {
        sigmaCrMax_.setSize(nCells, Zero);
        remainder_.setSize(nCells, Zero);
        nCandidates_.setSize(nCells, Zero);
        nCollisions_.setSize(nCells, Zero);
        nParcelSteps_.setSize(nCells, Zero);
    }

    // The parcels of each cell and the cell's solid volume fraction
    const List<DynamicList<parcelType*>> cellParcels
    (
        parcelsByCell(this->owner())
    );
    scalarField alpha(nCells, Zero);
    forAll(cellParcels, celli)
    {
        for (const parcelType* p : cellParcels[celli])
        {
            alpha[celli] += p->nParticle()*p->volume();
        }
    }
    alpha /= V;

    label nCand = 0;
    label nAccepted = 0;
    label nColliding = 0;
    label nDense = 0;

    forAll(cellParcels, celli)
    {
        const DynamicList<parcelType*>& parcels = cellParcels[celli];

        if (alpha[celli] >= alphaSwitch_)
        {
            nDense += parcels.size();
            continue;
        }

        nColliding += parcels.size();

        if (parcels.size() < 2)
        {
            continue;
        }

        label accepted = 0;
        const label cand = collideCell(celli, parcels, dt, accepted);
        nCandidates_[celli] += cand;
        nCollisions_[celli] += accepted;
        nParcelSteps_[celli] += parcels.size();
        nCand += cand;
        nAccepted += accepted;
    }

    reduce(nCand, sumOp<label>());
    reduce(nAccepted, sumOp<label>());

    Info<< "    NTC candidate pairs             = " << nCand << nl
        << "    NTC collisions                  = " << nAccepted << nl;

    if (alphaSwitch_ < GREAT)
    {
        reduce(nColliding, sumOp<label>());
        reduce(nDense, sumOp<label>());
        const scalar n = max(nColliding + nDense, 1);
        Info<< "    Parcel fraction NTC / MPPIC only = "
            << nColliding/n << " / " << nDense/n << nl;
    }

    if (mesh.time().writeTime())
    {
        writeFields(alpha);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::NTCHardSphere<CloudType>::NTCHardSphere
(
    const dictionary& dict,
    CloudType& owner
)
:
    NTCHardSphere(dict, owner, coeffs(dict))
{}


template<class CloudType>
Foam::NTCHardSphere<CloudType>::NTCHardSphere
(
    const dictionary& dict,
    CloudType& owner,
    const coeffs& c
)
:
    StochasticCollisionModel<CloudType>(dict, owner, typeName),
    e_(c.e),
    alphaValid_(c.alphaValid),
    alphaSwitch_(c.alphaSwitch),
    rnd_(randomStreams::seed(c.randomSeed, randomStreams::grainCollisions)),
    sigmaCrMax_(owner.mesh().nCells(), Zero),
    remainder_(owner.mesh().nCells(), Zero),
    nCandidates_(owner.mesh().nCells(), Zero),
    nCollisions_(owner.mesh().nCells(), Zero),
    nParcelSteps_(owner.mesh().nCells(), Zero),
    over_()
{
    // (sigma c_r)_max of a restart
    const fvMesh& mesh = owner.mesh();
    IOobject io
    (
        fieldName("sigmaCrMax"),
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (io.typeHeaderOk<volScalarField>(true))
    {
        sigmaCrMax_ = volScalarField(io, mesh).primitiveField();
        Info<< "    " << typeName << ": read " << io.name() << nl;
    }
    const dictionary state
    (
        restartState::read(mesh, owner.name(), typeName)
    );
    restartState::get(state, "random", rnd_);
    restartState::get(state, "remainder", mesh.nCells(), remainder_);

    Info<< "    " << typeName << ": e = " << e_ << ", alphaValid = "
        << alphaValid_;
    if (alphaSwitch_ < GREAT)
    {
        Info<< ", hybrid: NTC below alphaSwitch = " << alphaSwitch_
            << ", MPPIC only above";
    }
    Info<< nl;
}


template<class CloudType>
Foam::NTCHardSphere<CloudType>::NTCHardSphere
(
    const NTCHardSphere<CloudType>& cm
)
:
    StochasticCollisionModel<CloudType>(cm),
    e_(cm.e_),
    alphaValid_(cm.alphaValid_),
    alphaSwitch_(cm.alphaSwitch_),
    rnd_(cm.rnd_),
    sigmaCrMax_(cm.sigmaCrMax_),
    remainder_(cm.remainder_),
    nCandidates_(cm.nCandidates_),
    nCollisions_(cm.nCollisions_),
    nParcelSteps_(cm.nParcelSteps_),
    over_(cm.over_)
{}


// ************************************************************************* //
