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
    const word fillType(inputChecks::modelName<regionFill>(dict, "type"));

    Info<< "    Selecting region fill " << fillType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(fillType);

    return cstrIter()(dict, setup);
}


// ************************************************************************* //
