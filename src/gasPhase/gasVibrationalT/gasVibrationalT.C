/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasVibrationalT.H"
#include "gasCloud.H"
#include "gasCellAverage.H"
#include "cellFields.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(gasVibrationalT, 0);
    addToRunTimeSelectionTable(functionObject, gasVibrationalT, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::gasVibrationalT::gasVibrationalT
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    cloudName_("dsmc"),
    told_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::gasVibrationalT::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    cloudName_ = dict.getOrDefault<word>("cloud", "dsmc");
    return true;
}


bool Foam::functionObjects::gasVibrationalT::execute()
{
    return true;
}


bool Foam::functionObjects::gasVibrationalT::write()
{
    const gasCloud& gas = mesh_.lookupObject<gasCloud>(cloudName_);

    if (!gas.vibration().active())
    {
        if (!told_)
        {
            Info<< type() << ' ' << name() << ": the gas has no vibrational"
                << " modes, nothing to write" << endl;
            told_ = true;
        }
        return true;
    }

    const gasCellAverage& average = gas.sinceWrite();

    writeCellField
    (
        mesh_, "gas", "vibrationalT", dimTemperature,
        average.vibrationalT(-1)()
    );
    forAll(gas.typeIdList(), typei)
    {
        if (gas.vibration().nOscillators(typei))
        {
            writeCellField
            (
                mesh_, gas.typeIdList()[typei], "vibrationalT",
                dimTemperature, average.vibrationalT(typei)()
            );
        }
    }

    return true;
}


// ************************************************************************* //
