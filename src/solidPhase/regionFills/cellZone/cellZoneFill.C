/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

\*---------------------------------------------------------------------------*/

#include "cellZoneFill.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makeRegionFill(cellZoneFill);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::regionFills::cellZoneFill::cellZoneFill
(
    const dictionary& dict,
    const cloudSetup& setup
)
:
    regionFill(dict, setup, {"zone"}),
    inZone_(mesh_.nCells(), false)
{
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(dict)
            << "cellZone regions are filled in serial: run "
            << "rarefiedMultiphaseInitialise before decomposePar"
            << exit(FatalIOError);
    }
    const word zoneName
    (
        inputChecks::getChoice(dict, "zone", mesh_.cellZones().names())
    );
    const label zonei = mesh_.cellZones().findZoneID(zoneName);
    boundBox bb;
    for (const label celli : mesh_.cellZones()[zonei])
    {
        inZone_[celli] = true;
        V_ += mesh_.V()[celli];
        bb.add(mesh_.points(), mesh_.cellPoints()[celli]);
    }
    if (!(V_ > 0))
    {
        inputChecks::badValue
        (
            dict, "zone", zoneName, "a cellZone with cells"
        );
    }
    lo_ = bb.min();
    span_ = bb.span();
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::point Foam::regionFills::cellZoneFill::draw(const label)
{
    point x;
    label celli;
    do
    {
        x = uniform(lo_, span_);
        celli = mesh_.findCell(x);
    } while (celli < 0 || !inZone_[celli]);

    cells_.append(celli);
    return x;
}


Foam::labelList Foam::regionFills::cellZoneFill::locate
(
    const pointField&
) const
{
    return cells_;
}


// ************************************************************************* //
