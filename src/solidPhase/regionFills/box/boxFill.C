/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

\*---------------------------------------------------------------------------*/

#include "boxFill.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makeRegionFill(boxFill);


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::regionFills::boxFill::meanRadialWeight() const
{
    // int r dr / int r/RWF dr
    const scalar r0 = lo_.y();
    const scalar r1 = hi_.y();
    const label nSteps = 10000;
    const scalar dr = (r1 - r0)/nSteps;
    scalar thinned = 0;
    for (label i = 0; i < nSteps; ++i)
    {
        const scalar r = r0 + (i + 0.5)*dr;
        thinned += r/axisymmetric_.weight(r)*dr;
    }
    return 0.5*(sqr(r1) - sqr(r0))/thinned;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::regionFills::boxFill::boxFill
(
    const dictionary& dict,
    const cloudSetup& setup
)
:
    regionFill(dict, setup, {"min", "max"}, true),
    lo_(inputChecks::getVector(dict, "min")),
    hi_(inputChecks::getVector(dict, "max")),
    span_(hi_ - lo_),
    w0_(1)
{
    if (axisymmetric_.active())
    {
        // A box in (x, r) only
        if (!(hi_.x() > lo_.x() && hi_.y() > lo_.y() && lo_.y() >= 0))
        {
            inputChecks::badValue
            (
                dict, "max", hi_,
                "x and radius (y) > min " + name(lo_) + ", min radius >= 0"
            );
        }
        V_ = 0.5*axisymmetric_.angle()*(sqr(hi_.y()) - sqr(lo_.y()))
            *(hi_.x() - lo_.x());
        meanWeight_ = meanRadialWeight();
        w0_ = axisymmetric_.weight(lo_.y());
    }
    else
    {
        if (!(cmptMin(span_) > 0))
        {
            inputChecks::badValue
            (
                dict, "max", hi_, "every component > min " + name(lo_)
            );
        }
        V_ = cmptProduct(span_);
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::point Foam::regionFills::boxFill::draw(const label)
{
    if (!axisymmetric_.active())
    {
        return uniform(lo_, span_);
    }

    // Radius with density r, thinned to r/RWF(r)
    const scalar r0 = lo_.y();
    const scalar r1 = hi_.y();
    scalar r;
    do
    {
        r = sqrt(sqr(r0) + rnd_.sample01<scalar>()*(sqr(r1) - sqr(r0)));
    } while (rnd_.sample01<scalar>()*axisymmetric_.weight(r) > w0_);

    return point(lo_.x() + rnd_.sample01<scalar>()*(hi_.x() - lo_.x()), r, 0);
}


// ************************************************************************* //
