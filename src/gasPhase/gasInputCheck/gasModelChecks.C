/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasModelChecks.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace Foam
{
    defineNameRegistry(gasModelChecksTag, gasModelChecker);
    defineNameRegistry(vibratingGasModelsTag, bool);
}


void Foam::gasModelChecks::check
(
    const word& typeName,
    const dictionary& dict,
    const wordList& species
)
{
    const gasModelChecker* checker = find(typeName);
    if (checker)
    {
        (*checker)(dict, species);
    }
}


// ************************************************************************* //
