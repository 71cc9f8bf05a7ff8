/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "grainPhase.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(grainPhase, 0);
    defineRunTimeSelectionTable(grainPhase, dictionary);
    constexpr label grainPhase::sortInterval;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::HashTable<Foam::grainPhase::fillFunction>& Foam::grainPhase::fillTable()
{
    // (built at the first registration, whatever the order of the static
    // objects)
    static HashTable<fillFunction> table;
    return table;
}


Foam::grainPhase::addFill::addFill(const word& kind, fillFunction fillKind)
{
    fillTable().set(kind, fillKind);
}


// ************************************************************************* //
