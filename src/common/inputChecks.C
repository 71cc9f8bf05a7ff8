/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "inputChecks.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::inputChecks::notOneOf
(
    const dictionary& dict,
    const word& keyword,
    const word& value,
    const wordList& choices
)
{
    badValue(dict, keyword, value, choices);
}


void Foam::inputChecks::checkClosed
(
    const dictionary& dict,
    const word& keyword,
    const scalar value,
    const scalar min,
    const scalar max
)
{
    if (!(value >= min && value <= max))
    {
        outOfRange
        (
            dict, keyword, value,
            "[" + Foam::name(min) + ", " + Foam::name(max) + "]"
        );
    }
}


Foam::scalar Foam::inputChecks::getPositive
(
    const dictionary& dict,
    const word& keyword
)
{
    const scalar value = dict.get<scalar>(keyword);

    if (!(value > 0 && std::isfinite(value)))
    {
        outOfRange(dict, keyword, value, "(0, inf)");
    }

    return value;
}


Foam::scalar Foam::inputChecks::getPositiveOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt
)
{
    const scalar value = dict.getOrDefault<scalar>(keyword, deflt);

    if (!(value > 0 && std::isfinite(value)))
    {
        outOfRange(dict, keyword, value, "(0, inf)");
    }

    return value;
}


Foam::scalar Foam::inputChecks::getNonNegative
(
    const dictionary& dict,
    const word& keyword
)
{
    const scalar value = dict.get<scalar>(keyword);

    if (!(value >= 0 && std::isfinite(value)))
    {
        outOfRange(dict, keyword, value, "[0, inf)");
    }

    return value;
}


Foam::scalar Foam::inputChecks::getClosed
(
    const dictionary& dict,
    const word& keyword,
    const scalar min,
    const scalar max
)
{
    const scalar value = dict.get<scalar>(keyword);
    checkClosed(dict, keyword, value, min, max);
    return value;
}


Foam::label Foam::inputChecks::getLabelOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const label deflt,
    const label min,
    const label max
)
{
    const label value = dict.getOrDefault<label>(keyword, deflt);

    if (value < min || value > max)
    {
        outOfRange
        (
            dict, keyword, value,
            "[" + Foam::name(min) + ", " + Foam::name(max) + "]"
        );
    }

    return value;
}


Foam::IOdictionary Foam::inputChecks::readCloudProperties
(
    const word& cloudName,
    const objectRegistry& db
)
{
    return IOdictionary
    (
        IOobject
        (
            cloudName + "Properties",
            db.time().constant(),
            db,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
}


// ************************************************************************* //
