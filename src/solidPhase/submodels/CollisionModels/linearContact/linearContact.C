/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "linearContact.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "mathematicalConstants.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearContact::linearContact(const dictionary& coeffs)
:
    dict_(coeffs),
    kn_(inputChecks::getPositive(coeffs, "kn")),
    kt_(inputChecks::getPositive(coeffs, "kt")),
    e_
    (
        inputChecks::getInterval
        (
            coeffs, "e", inputChecks::interval::above(0, 1)
        )
    ),
    mu_(inputChecks::getNonNegative(coeffs, "mu")),
    tangentialDamping_
    (
        inputChecks::getNonNegativeOrDefault(coeffs, "tangentialDamping", 0.5)
    ),
    dampingFactor_(0)
{
    inputChecks::rejectUnknown
    (
        coeffs, {"kn", "kt", "e", "mu", "tangentialDamping"}
    );

    const scalar lnE = std::log(e_);
    dampingFactor_ =
        2*mag(lnE)/std::sqrt(sqr(constant::mathematical::pi) + sqr(lnE));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::linearContact::etaN(const scalar mEff) const
{
    return dampingFactor_*std::sqrt(mEff*kn_);
}


Foam::scalar Foam::linearContact::contactTime(const scalar mEff) const
{
    const scalar eta = etaN(mEff);
    return
        constant::mathematical::pi
       /std::sqrt(kn_/mEff - sqr(eta/(2*mEff)));
}


void Foam::linearContact::checkTimeStep
(
    const Time& time,
    const scalar mEffMin
) const
{
    const scalar tc = contactTime(mEffMin);
    const scalar dt = time.deltaTValue();

    if (dt > tc/5)
    {
        inputChecks::outOfRange
        (
            time.controlDict(), "deltaT", dt,
            "(0, t_c/5 = " + name(tc/5) + "] s, t_c = " + name(tc)
          + " s the contact time of kn = " + name(kn_) + ", e = "
          + name(e_) + " in " + dict_.name() + " for the lightest contact"
            " (t_c/50 recommended)"
        );
    }

    if (dt > tc/20 && !warned_)
    {
        WarningInFunction
            << "deltaT = " << dt << " s is more than t_c/20 = " << tc/20
            << " s (contact time t_c = " << tc << " s of " << dict_.name()
            << "): contacts are resolved in fewer than 20 steps;"
            << " t_c/50 is recommended" << endl;
        warned_ = true;
    }
}


void Foam::linearContact::reportOverlap
(
    const Time& time,
    const word& who
) const
{
    if (!time.writeTime())
    {
        return;
    }

    reduce(overlapMax_, maxOp<scalar>());

    Info<< "    " << who << ": largest overlap since the last write "
        << overlapMax_ << " of the radius" << endl;

    if (overlapMax_ > overlapLimit)
    {
        WarningInFunction
            << who << ": a contact of " << dict_.name() << " overlapped by "
            << overlapMax_ << " of the radius (above " << overlapLimit
            << "): the springs are too soft for the impacts (kn = " << kn_
            << " N/m; the overlap falls as 1/sqrt(kn))" << endl;
    }

    overlapMax_ = 0;
}


Foam::linearContact::forces Foam::linearContact::contact
(
    const scalar overlap,
    const scalar radius,
    const vector& n,
    const vector& v,
    const scalar mEff,
    const scalar deltaT,
    vector& spring
) const
{
    overlapMax_ = max(overlapMax_, overlap/radius);

    const scalar eta = etaN(mEff);
    const scalar vn = v & n;
    const vector vt = v - vn*n;

    // The dashpot at the velocity the force leaves the contact with at
    // the end of the step: upstream's leapfrog hands the models the
    // half-step velocity v_h, and v = v_h + (dt/2) F/m_eff
    forces f;
    f.normal =
        (kn_*overlap - eta*vn)/(1 + eta*deltaT/(2*mEff))*n;

    // The spring turns with the contact: keep its tangential part only
    spring -= (spring & n)*n;
    spring += vt*deltaT;

    const scalar etaT = tangentialDamping_*eta;
    f.tangential = -kt_*spring - etaT*vt;

    const scalar limit = mu_*mag(f.normal);
    const scalar Ft = mag(f.tangential);
    if (Ft > limit)
    {
        f.tangential *= limit/Ft;
        spring = -(f.tangential + etaT*vt)/kt_;
    }

    return f;
}


// ************************************************************************* //
