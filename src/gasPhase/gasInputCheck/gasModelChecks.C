/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasModelChecks.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::HashTable<Foam::gasModelChecks::checker>& Foam::gasModelChecks::checkers()
{
    // (built at the first registration, whatever the order of the static
    // objects of the registration files)
    static HashTable<checker> table;
    return table;
}


Foam::wordHashSet& Foam::gasModelChecks::vibrating()
{
    static wordHashSet names;
    return names;
}


Foam::gasModelChecks::add::add(const word& typeName, checker check)
{
    checkers().set(typeName, check);
}


Foam::gasModelChecks::addVibrating::addVibrating(const word& typeName)
{
    vibrating().insert(typeName);
}


void Foam::gasModelChecks::check
(
    const word& typeName,
    const dictionary& dict,
    const wordList& species
)
{
    const auto iter = checkers().cfind(typeName);
    if (iter.found())
    {
        (*iter.val())(dict, species);
    }
}


bool Foam::gasModelChecks::exchangesVibration(const word& typeName)
{
    return vibrating().found(typeName);
}


Foam::wordList Foam::gasModelChecks::vibratingModels()
{
    return vibrating().sortedToc();
}


// ************************************************************************* //
