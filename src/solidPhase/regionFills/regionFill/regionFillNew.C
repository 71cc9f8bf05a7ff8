/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

\*---------------------------------------------------------------------------*/

#include "regionFill.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::regionFill> Foam::regionFill::New
(
    const dictionary& dict,
    const cloudSetup& setup
)
{
    const word fillType(dict.get<word>("type"));

    Info<< "    Selecting region fill " << fillType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(fillType);

    if (!cstrIter.found())
    {
        inputChecks::notOneOf
        (
            dict, "type", fillType,
            dictionaryConstructorTablePtr_->sortedToc()
        );
    }

    return cstrIter()(dict, setup);
}


// ************************************************************************* //
