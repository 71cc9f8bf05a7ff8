/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "coordinateTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::coordinateTable::coordinateNames
(
    {"x", "y", "z", "r"}
);


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::coordinateTable::badRow
(
    const label i,
    const string& what,
    const string& valid
) const
{
    inputChecks::badValue
    (
        dict_, keyword_,
        (where_ + Foam::name(i) + ": " + what).c_str(),
        valid.c_str()
    );
}


Foam::label Foam::coordinateTable::upper(const scalar s) const
{
    label i = 1;
    while (rows_[i][0] < s)
    {
        ++i;
    }
    return i;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coordinateTable::coordinateTable
(
    const dictionary& dict,
    const labelList& nColumns,
    const string& columnsText
)
:
    dict_(dict),
    coordinate_(0),
    origin_(inputChecks::getVectorOrDefault(dict, "origin", Zero)),
    axis_(Zero),
    clamp_(false),
    keyword_("table"),
    where_("row ")
{
    using namespace inputChecks;

    coordinate_ =
        coordinateNames.find(getChoice(dict, "coordinate", coordinateNames));
    if (coordinate_ == 3)
    {
        const vector a(getVector(dict, "axis"));
        if (!(mag(a) > VSMALL))
        {
            badValue(dict, "axis", a, "a vector of non-zero length");
        }
        axis_ = a/mag(a);
    }

    clamp_ =
    (
        getChoiceOrDefault(dict, "outOfBounds", "error", {"error", "clamp"})
     == "clamp"
    );

    // The rows, inline or from a file
    if (dict.found("table") || !dict.found("file"))
    {
        dict.readEntry("table", rows_);
    }
    else
    {
        keyword_ = "file";
        fileName name(getName(dict, "file", "a readable file", false));
        name.expand();
        IFstream is(name);
        if (!is.good())
        {
            badValue(dict, keyword_, name, "a readable file");
        }
        is >> rows_;
        where_ = name + ", row ";
    }

    if (rows_.size() < 2)
    {
        badValue
        (
            dict, keyword_,
            (Foam::name(rows_.size()) + " rows").c_str(),
            "at least 2 rows"
        );
    }
    const label nCol = rows_[0].size();
    forAll(rows_, i)
    {
        if (rows_[i].size() != nCol || !nColumns.found(nCol))
        {
            badRow
            (
                i, Foam::name(rows_[i].size()) + " columns",
                columnsText + " columns, the same in every row"
            );
        }
        for (const scalar v : rows_[i])
        {
            if (!std::isfinite(v))
            {
                badRow(i, "not finite", "finite numbers");
            }
        }
        if (i && !(rows_[i][0] > rows_[i-1][0]))
        {
            badRow
            (
                i,
                "position " + Foam::name(rows_[i][0]) + " after "
              + Foam::name(rows_[i-1][0]),
                "positions (first column) strictly increasing"
            );
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coordinateTable::checkPositive
(
    const label col,
    const word& name
) const
{
    forAll(rows_, i)
    {
        if (!(rows_[i][col] > 0))
        {
            badRow
            (
                i, name + " = " + Foam::name(rows_[i][col]),
                name + " in (0, inf)"
            );
        }
    }
}


void Foam::coordinateTable::checkNonNegative
(
    const label col,
    const word& name
) const
{
    forAll(rows_, i)
    {
        if (!(rows_[i][col] >= 0))
        {
            badRow
            (
                i, name + " = " + Foam::name(rows_[i][col]),
                name + " in [0, inf)"
            );
        }
    }
}


Foam::scalar Foam::coordinateTable::value
(
    const scalar s,
    const label col
) const
{
    if (s <= sMin())
    {
        return rows_.first()[col];
    }
    if (s >= sMax())
    {
        return rows_.last()[col];
    }
    const label i = upper(s);
    const scalarList& lo = rows_[i-1];
    const scalarList& hi = rows_[i];
    const scalar w = (s - lo[0])/(hi[0] - lo[0]);
    return (1 - w)*lo[col] + w*hi[col];
}


Foam::scalar Foam::coordinateTable::slope
(
    const scalar s,
    const label col
) const
{
    if (!(s > sMin() && s < sMax()))
    {
        return 0;
    }
    const label i = upper(s);
    return
        (rows_[i][col] - rows_[i-1][col])
       /(rows_[i][0] - rows_[i-1][0]);
}


Foam::vector Foam::coordinateTable::direction(const point& x) const
{
    if (coordinate_ < 3)
    {
        vector e(Zero);
        e[coordinate_] = 1;
        return e;
    }
    const vector d(x - origin_);
    const vector radial(d - (d & axis_)*axis_);
    const scalar r = mag(radial);
    return r > 0 ? radial/r : vector::zero;
}


Foam::string Foam::coordinateTable::describe() const
{
    return
        Foam::name(rows_.size()) + " rows in "
      + coordinateNames[coordinate_] + " from " + Foam::name(sMin())
      + " to " + Foam::name(sMax())
      + (clamp_ ? ", clamped outside" : ", error outside");
}


// ************************************************************************* //
