/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "InterphaseCouplingModel.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * * Selector * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<Foam::InterphaseCouplingModel<CloudType>>
Foam::InterphaseCouplingModel<CloudType>::New
(
    const dictionary& dict,
    CloudType& owner
)
{
    const word modelType
    (
        inputChecks::modelName<InterphaseCouplingModel<CloudType>>
        (
            dict, typeName
        )
    );

    Info<< "Selecting interphase coupling model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    return autoPtr<InterphaseCouplingModel<CloudType>>
    (
        cstrIter()(dict, owner)
    );
}


// ************************************************************************* //
