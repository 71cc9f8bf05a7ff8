/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

\*---------------------------------------------------------------------------*/

#include "cylinderFill.H"
#include "inputChecks.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makeRegionFill(cylinderFill);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::regionFills::cylinderFill::cylinderFill
(
    const dictionary& dict,
    const cloudSetup& setup
)
:
    regionFill(dict, setup, {"p1", "p2", "radius"}),
    p1_(inputChecks::getVector(dict, "p1"))
{
    const point p2(inputChecks::getVector(dict, "p2"));
    R_ = inputChecks::getPositive(dict, "radius");
    axis_ = p2 - p1_;
    const scalar L = mag(axis_);
    if (!(L > 0))
    {
        inputChecks::badValue(dict, "p2", p2, "a point other than p1");
    }
    const vector a(axis_/L);

    // Any unit vector normal to the axis: a crossed with the coordinate
    // direction it is least aligned with
    const direction least = findMin(cmptMag(a));
    vector ex(Zero);
    ex[least] = 1;
    e1_ = normalised(a ^ ex);
    e2_ = a ^ e1_;
    V_ = pi*sqr(R_)*L;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::point Foam::regionFills::cylinderFill::draw(const label)
{
    const scalar r = R_*sqrt(rnd_.sample01<scalar>());
    const scalar theta = 2*pi*rnd_.sample01<scalar>();
    const scalar h = rnd_.sample01<scalar>();
    return point(p1_ + h*axis_ + r*(cos(theta)*e1_ + sin(theta)*e2_));
}


// ************************************************************************* //
