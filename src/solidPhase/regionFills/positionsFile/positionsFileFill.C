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


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The points file named by keyword file, which must exist in constant/
Foam::IOobject positionsFile
(
    const Foam::dictionary& dict,
    const Foam::regionFill::cloudSetup& setup
)
{
    using namespace Foam;
    const word name
    (
        inputChecks::getName(dict, "file", "a file of points in constant/")
    );
    IOobject io
    (
        name,
        setup.mesh.time().constant(),
        setup.mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<vectorIOField>(false))
    {
        inputChecks::badValue
        (
            dict, "file", name,
            "a file of points in constant/ (no file " + name + " there)"
        );
    }
    return io;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::regionFills::positionsFileFill::positionsFileFill
(
    const dictionary& dict,
    const cloudSetup& setup
)
:
    regionFill(dict, setup, {"file"}),
    positions_(vectorIOField(positionsFile(dict, setup)))
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
