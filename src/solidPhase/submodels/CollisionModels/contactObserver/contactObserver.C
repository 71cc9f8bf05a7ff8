/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "contactObserver.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordHashSet& Foam::contactModels::names()
{
    // (built at the first registration, whatever the order of the static
    // objects)
    static wordHashSet set;
    return set;
}


Foam::contactModels::add::add(const word& typeName)
{
    names().insert(typeName);
}


bool Foam::contactModels::honoursContactsOff(const word& typeName)
{
    return names().found(typeName);
}


Foam::wordList Foam::contactModels::honouring()
{
    return names().sortedToc();
}


// ************************************************************************* //
