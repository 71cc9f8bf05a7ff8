/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

\*---------------------------------------------------------------------------*/

#include "positionsFileFill.H"
#include "inputChecks.H"
#include "vectorIOField.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makeRegionFill(positionsFileFill);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::regionFills::positionsFileFill::positionsFileFill
(
    const dictionary& dict,
    const cloudSetup& setup
)
:
    regionFill(dict, setup, {"file"}),
    positions_
    (
        vectorIOField
        (
            IOobject
            (
                inputChecks::getName
                (
                    dict, "file", "a file of points in constant/"
                ),
                setup.mesh.time().constant(),
                setup.mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        )
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::regionFills::positionsFileFill::count
(
    const scalar,
    const word&,
    label& nParcels,
    scalar& W
) const
{
    nParcels = positions_.size();
    W = inputChecks::getPositive(dict_, "nParticle");
}


Foam::point Foam::regionFills::positionsFileFill::draw(const label i)
{
    return positions_[i];
}


Foam::word Foam::regionFills::positionsFileFill::placedBy() const
{
    return "file";
}


// ************************************************************************* //
