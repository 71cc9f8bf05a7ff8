/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "prescribedGas.H"
#include "inputChecks.H"
#include "keywordChecks.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::prescribedGas::readConstants(const dictionary& dict)
{
    state& g = uniform_;
    if (!muColumn_)
    {
        g.mu = inputChecks::getPositive(dict, "mu");
    }
    // 5/3 as written with 6 digits (1.66667) is accepted
    g.gamma = inputChecks::getInterval
    (
        dict, "gamma",
        inputChecks::interval::above(1, 5.0/3.0*(1 + 1e-5), "5/3")
    );
    g.R = inputChecks::getPositive(dict, "R");
    g.Pr = inputChecks::getPositiveOrDefault
    (
        dict, "Pr", 4*g.gamma/(9*g.gamma - 5)
    );
}


void Foam::prescribedGas::readTable(const dictionary& dict)
{
    table_.reset
    (
        new coordinateTable
        (
            dict, labelList({6, 7}),
            "6 (s rho Ux Uy Uz T) or 7 (s rho Ux Uy Uz T mu)"
        )
    );
    const coordinateTable& t = table_();
    muColumn_ = (t.nColumns() == 7);
    t.checkPositive(1, "rho");
    t.checkPositive(5, "T");
    if (muColumn_)
    {
        t.checkPositive(6, "mu");
    }

    readConstants(dict);

    Info<< "    prescribed gas: table of " << t.describe().c_str()
        << (muColumn_ ? " (mu a column)" : "")
        << "; gamma " << uniform_.gamma << " R " << uniform_.R
        << " Pr " << uniform_.Pr << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prescribedGas::prescribedGas(const dictionary& dict)
:
    dictName_(dict.name()),
    uniform_(),
    tabulated_(dict.found("table") || dict.found("file")),
    muColumn_(false),
    table_()
{
    wordList valid({"rho", "U", "T", "mu", "gamma", "R", "Pr"});
    valid.append(coordinateTable::keywords());
    inputChecks::rejectUnknown(dict, valid);

    if (tabulated_)
    {
        readTable(dict);
        return;
    }

    state& g = uniform_;
    g.rho = inputChecks::getPositive(dict, "rho");
    g.U = inputChecks::getVector(dict, "U");
    g.T = inputChecks::getPositive(dict, "T");
    readConstants(dict);
    Info<< "    prescribed gas: uniform, rho " << g.rho
        << " U " << g.U << " T " << g.T << " mu " << g.mu
        << " gamma " << g.gamma << " R " << g.R << " Pr " << g.Pr
        << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::prescribedGas::state Foam::prescribedGas::at(const point& x) const
{
    if (!tabulated_)
    {
        return uniform_;
    }

    const coordinateTable& t = table_();
    const scalar s = t.coordinate(x);
    if (!t.clamp() && !t.inRange(s))
    {
        FatalErrorInFunction
            << "Point " << x << " is outside the prescribed gas table of "
            << dictName_ << nl
            << "    coordinate: " << s << nl
            << "    table range: [" << t.sMin() << ", " << t.sMax() << "]"
            << nl << "    Extend the table or set outOfBounds clamp."
            << exit(FatalError);
    }

    state g(uniform_);
    g.rho = t.value(s, 1);
    g.U = t.vectorValue(s, 2);
    g.T = t.value(s, 5);
    if (muColumn_)
    {
        g.mu = t.value(s, 6);
    }
    // curl U = grad s x dU/ds
    g.curlU =
        t.direction(x)
      ^ vector(t.slope(s, 2), t.slope(s, 3), t.slope(s, 4));
    return g;
}


// ************************************************************************* //
