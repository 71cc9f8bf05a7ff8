/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "VariableSoftSphere.H"
#include "physicoChemicalConstants.H"
#include "mathematicalConstants.H"
#include "normalTo.H"
#include "inputChecks.H"
#include "keywordChecks.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::VariableSoftSphere<CloudType>::readInverseZ
(
    const bool exchange
) const
{
    const dictionary& coeffs = this->coeffDict();
    wordList valid({"Tref", "alpha", "alphaPairs"});
    scalar inverseZ = 0;
    if (exchange)
    {
        valid.append("relaxationCollisionNumber");
        inverseZ =
            1
           /inputChecks::getInterval
            (
                coeffs, "relaxationCollisionNumber",
                inputChecks::interval::atLeast(1)
            );
    }
    inputChecks::rejectUnknown(coeffs, valid);
    return inverseZ;
}


template<class CloudType>
Foam::scalarSquareMatrix
Foam::VariableSoftSphere<CloudType>::readAlpha() const
{
    // The scattering exponents: every species, the pairs optional, from 1
    // (isotropic, VHS) to 2
    using namespace inputChecks;

    const wordList& species = this->owner().typeIdList();
    const dictionary& perSpecies = this->coeffDict().subDict("alpha");
    for (const word& name : perSpecies.toc())
    {
        if (!species.found(name))
        {
            notOneOf(perSpecies, "alpha", name, species);
        }
    }

    scalarList own(species.size());
    forAll(species, p)
    {
        own[p] = getClosed(perSpecies, species[p], 1, 2);
    }

    scalarSquareMatrix alpha(species.size());
    forAll(species, p)
    {
        forAll(species, q)
        {
            alpha(p, q) = 0.5*(own[p] + own[q]);
        }
    }

    const dictionary pairs(this->coeffDict().subOrEmptyDict("alphaPairs"));
    for (const word& p : pairs.toc())
    {
        if (!species.found(p) || !pairs.isDict(p))
        {
            notOneOf(pairs, "alphaPairs", p, species);
        }
        const dictionary& partners = pairs.subDict(p);
        for (const word& q : partners.toc())
        {
            if (!species.found(q))
            {
                notOneOf(partners, p, q, species);
            }
            const label i = species.find(p);
            const label j = species.find(q);
            alpha(i, j) = alpha(j, i) = getClosed(partners, q, 1, 2);
        }
    }
    return alpha;
}


template<class CloudType>
Foam::scalar Foam::VariableSoftSphere<CloudType>::internalFraction
(
    const scalar zeta,
    const scalar omega
)
{
    // x^(a - 1) (1 - x)^(b - 1): a beta distribution
    Random& rnd = this->owner().rndGen();
    const scalar a = 0.5*zeta;
    const scalar b = 2.5 - omega;

    if (mag(a - 1) < SMALL)
    {
        // Its distribution function is 1 - (1 - x)^b: inverted
        return 1 - pow(rnd.sample01<scalar>(), 1/b);
    }

    // Johnk's method: X = U^(1/a), Y = V^(1/b) conditioned on X + Y <= 1
    // gives X/(X + Y) the beta distribution
    while (true)
    {
        const scalar x = pow(rnd.sample01<scalar>(), 1/a);
        const scalar y = pow(rnd.sample01<scalar>(), 1/b);
        if (x + y <= 1 && x + y > 0)
        {
            return x/(x + y);
        }
    }
}


template<class CloudType>
void Foam::VariableSoftSphere<CloudType>::vibrate
(
    typename CloudType::parcelType& pp,
    const label s,
    const label q,
    const scalar omega,
    scalar& translational
)
{
    const vibrationalModes& modes = gas_->vibration();
    const scalarList& theta = modes.theta(s);
    if (theta.empty())
    {
        return;
    }

    Random& rnd = this->owner().rndGen();
    const scalar T = gas_->collisionTemperature(pp.cell());
    const scalar a = 1.5 - omega;
    labelList& levels = pp.vibLevels();

    forAll(theta, k)
    {
        if (modes.selection(s, q, theta[k], T) <= rnd.sample01<scalar>())
        {
            continue;
        }

        // Level j in 0 .. E_c/(k theta) with probability proportional to
        // (1 - j k theta/E_c)^(3/2 - omega): uniform j, accepted by that
        // ratio (its largest value, at j = 0, is 1)
        const scalar e = constant::physicoChemical::k.value()*theta[k];
        const scalar Ec = translational + levels[k]*e;
        if (!(Ec > 0))
        {
            continue;
        }
        const label jMax = label(Ec/e);
        label j = 0;
        do
        {
            j = min(label(rnd.sample01<scalar>()*(jMax + 1)), jMax);
        }
        while (pow(1 - j*e/Ec, a) < rnd.sample01<scalar>());

        levels[k] = j;
        translational = Ec - j*e;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::VariableSoftSphere<CloudType>::VariableSoftSphere
(
    const dictionary& dict,
    CloudType& cloud,
    const word& type,
    const bool exchange
)
:
    BinaryCollisionModel<CloudType>(dict, cloud, type),
    inverseZ_(readInverseZ(exchange)),
    Tref_(inputChecks::getPositive(this->coeffDict(), "Tref")),
    alpha_(readAlpha()),
    gas_(nullptr)
{}


template<class CloudType>
Foam::VariableSoftSphere<CloudType>::VariableSoftSphere
(
    const dictionary& dict,
    CloudType& cloud
)
:
    VariableSoftSphere(dict, cloud, typeName, false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::VariableSoftSphere<CloudType>::sigmaTcR
(
    const typename CloudType::parcelType& pP,
    const typename CloudType::parcelType& pQ
) const
{
    const CloudType& cloud = this->owner();
    const auto& P = cloud.constProps(pP.typeId());
    const auto& Q = cloud.constProps(pQ.typeId());

    const scalar cR = mag(pP.U() - pQ.U());
    if (cR < VSMALL)
    {
        return 0;
    }

    const scalar d = 0.5*(P.d() + Q.d());
    const scalar omega = 0.5*(P.omega() + Q.omega());
    const scalar mR = P.mass()*Q.mass()/(P.mass() + Q.mass());

    const scalar sigmaT =
        constant::mathematical::pi*d*d
       *pow
        (
            2*constant::physicoChemical::k.value()*Tref_/(mR*cR*cR),
            omega - 0.5
        )
       /exp(lgamma(2.5 - omega));

    return sigmaT*cR;
}


template<class CloudType>
void Foam::VariableSoftSphere<CloudType>::collide
(
    typename CloudType::parcelType& pP,
    typename CloudType::parcelType& pQ
)
{
    CloudType& cloud = this->owner();
    Random& rnd = cloud.rndGen();

    const label p = pP.typeId();
    const label q = pQ.typeId();
    const auto& P = cloud.constProps(p);
    const auto& Q = cloud.constProps(q);

    const scalar mP = P.mass();
    const scalar mQ = Q.mass();
    const scalar mR = mP*mQ/(mP + mQ);
    const scalar omega = 0.5*(P.omega() + Q.omega());

    vector& UP = pP.U();
    vector& UQ = pQ.U();
    const vector Ucm = (mP*UP + mQ*UQ)/(mP + mQ);
    const vector cR0 = UP - UQ;

    // Larsen-Borgnakke: each molecule with internal energy, in turn
    scalar translational = 0.5*mR*magSqr(cR0);
    auto exchange = [&](typename CloudType::parcelType& pp, const label zeta)
    {
        if (zeta > 0 && inverseZ_ > rnd.sample01<scalar>())
        {
            const scalar E = translational + pp.Ei();
            pp.Ei() = internalFraction(zeta, omega)*E;
            translational = E - pp.Ei();
        }
    };
    if (inverseZ_ > 0)
    {
        if (!gas_)
        {
            gas_ = &dynamic_cast<gasCloud&>(cloud);
        }
        // (vibrate draws nothing for a species without modes)
        vibrate(pP, p, q, omega, translational);
        exchange(pP, P.internalDegreesOfFreedom());
        vibrate(pQ, q, p, omega, translational);
        exchange(pQ, Q.internalDegreesOfFreedom());
    }
    const scalar cR = sqrt(2*translational/mR);

    // Unit vectors: g along the pre-collision relative velocity (any
    // direction when it is zero), e1 and e2 across it
    const scalar cR0mag = mag(cR0);
    vector g(1, 0, 0);
    if (cR0mag > VSMALL)
    {
        g = cR0/cR0mag;
    }
    const vector e1 = normalTo(g);
    const vector e2 = g ^ e1;

    // Deflection: cos chi = 2 R^(1/alpha) - 1, azimuth uniform
    const scalar cosChi = 2*pow(rnd.sample01<scalar>(), 1/alpha_(p, q)) - 1;
    const scalar sinChi = sqrt(max(scalar(0), 1 - cosChi*cosChi));
    const scalar eps = constant::mathematical::twoPi*rnd.sample01<scalar>();

    const vector cRnew =
        cR*(cosChi*g + sinChi*(cos(eps)*e1 + sin(eps)*e2));

    UP = Ucm + cRnew*mQ/(mP + mQ);
    UQ = Ucm - cRnew*mP/(mP + mQ);
}


// ************************************************************************* //
