/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    Registers our averaging methods in upstream's AveragingMethod<scalar>
    and AveragingMethod<vector> selection tables (keyword averagingMethod
    of a cloud's solution dictionary): cachedDual.

\*---------------------------------------------------------------------------*/

#include "CachedDual.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

#define makeOurAveragingMethod(Model, Type)                                    \
                                                                               \
    defineNamedTemplateTypeNameAndDebug                                        \
    (                                                                          \
        Foam::AveragingMethods::Model<Foam::Type>,                             \
        0                                                                      \
    );                                                                         \
                                                                               \
    Foam::AveragingMethod<Foam::Type>::                                        \
    adddictionaryConstructorToTable                                            \
    <                                                                          \
        Foam::AveragingMethods::Model<Foam::Type>                              \
    > add##Model##Type##ConstructorToTable_;

makeOurAveragingMethod(CachedDual, scalar);
makeOurAveragingMethod(CachedDual, vector);


// ************************************************************************* //
