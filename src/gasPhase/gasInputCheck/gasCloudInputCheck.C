/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasCloudInputCheck.H"
#include "gasModelChecks.H"
#include "gasParcel.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "vibrationalModes.H"
#include "DSMCCloud.H"
#include "BinaryCollisionModel.H"
#include "WallInteractionModel.H"
#include "InflowBoundaryModel.H"

// * * * * * * * * * * * * * Static Member Functions  * * * * * * * * * * * //

void Foam::gasCloudInputCheck::checkVibration(const dictionary& props)
{
    using namespace inputChecks;

    const word& modesKeyword = vibrationalModes::modesKeyword;
    const word& relaxationKeyword = vibrationalModes::relaxationKeyword;
    if (!props.found(modesKeyword))
    {
        if (props.found(relaxationKeyword))
        {
            outOfRange
            (
                props, relaxationKeyword, valueText(props, relaxationKeyword),
                "an entry only beside " + modesKeyword
            );
        }
        return;
    }
    if (!props.isDict(modesKeyword))
    {
        outOfRange
        (
            props, modesKeyword, valueText(props, modesKeyword),
            "a dictionary { <mode> { temperature <theta K>; degeneracy"
            " <count>; } ... }"
        );
    }

    const dictionary& modes = props.subDict(modesKeyword);
    if (modes.empty())
    {
        outOfRange(props, modesKeyword, "{}", "one or more modes");
    }
    for (const word& mode : modes.toc())
    {
        if (!modes.isDict(mode))
        {
            outOfRange
            (
                modes, mode, valueText(modes, mode),
                "a dictionary { temperature <theta K>; degeneracy <count>; }"
            );
        }
        const dictionary& d = modes.subDict(mode);
        rejectUnknown(d, {"temperature", "degeneracy"});
        getPositive(d, "temperature");
        getLabelOrDefault(d, "degeneracy", 1, 1, 10);
    }
    getInterval(props, relaxationKeyword, interval::atLeast(1));
}


bool Foam::gasCloudInputCheck::cartesianTracking(const dictionary& dict)
{
    return
        inputChecks::getChoiceOrDefault
        (
            dict, "tracking", "cartesian", {"cartesian", "barycentric"}
        )
     == "cartesian";
}


Foam::wordList Foam::gasCloudInputCheck::checkProperties
(
    const dictionary& dict
)
{
    using namespace inputChecks;

    getPositive(dict, "nEquivalentParticles");
    getLabelOrDefault(dict, "randomSeed", 0, 0, 2000);
    getBoolOrDefault(dict, "randomEntryTime", false);
    cartesianTracking(dict);

    const wordList species(dict.get<wordList>("typeIdList"));
    if (species.empty())
    {
        outOfRange(dict, "typeIdList", species, "a list of one or more species");
    }

    const dictionary& molecules = dict.subDict("moleculeProperties");
    for (const word& name : species)
    {
        const dictionary& props = molecules.subDict(name);
        rejectUnknown
        (
            props,
            {
                "mass", "diameter", "internalDegreesOfFreedom", "omega",
                vibrationalModes::modesKeyword,
                vibrationalModes::relaxationKeyword
            }
        );
        getPositive(props, "mass");
        getPositive(props, "diameter");
        getClosed(props, "internalDegreesOfFreedom", 0, 10);
        getClosed(props, "omega", 0.5, 1.0);
        checkVibration(props);
    }

    // The three models: a name from upstream's selection table, then the
    // keywords of upstream's models (ours check theirs when built)
    typedef DSMCCloud<gasParcel> cloudType;
    const word collision
    (
        modelName<BinaryCollisionModel<cloudType>>(dict, "BinaryCollisionModel")
    );
    for
    (
        const word& model
      : {
            collision,
            modelName<WallInteractionModel<cloudType>>
            (
                dict, "WallInteractionModel"
            ),
            modelName<InflowBoundaryModel<cloudType>>
            (
                dict, "InflowBoundaryModel"
            )
        }
    )
    {
        gasModelChecks::call(model, dict, species);
    }

    // Vibrational modes need a collision model that exchanges them
    for (const word& name : species)
    {
        if
        (
            !gasModelChecks::exchangesVibration(collision)
         && molecules.subDict(name).found(vibrationalModes::modesKeyword)
        )
        {
            FatalIOErrorInFunction(dict)
                << "BinaryCollisionModel " << collision << " in "
                << dict.name() << ": species " << name << " has "
                << vibrationalModes::modesKeyword << ", which "
                << collision << " does not exchange; valid choices with "
                << "vibrational modes: "
                << gasModelChecks::vibratingModels()
                << exit(FatalIOError);
        }
    }

    // The top level's plain entries: upstream's and ours (axisymmetricMode,
    // randomSeed, randomEntryTime); the dictionaries there are upstream's,
    // required where a selected model reads them
    rejectMisspelt
    (
        dict,
        {
            "nEquivalentParticles", "typeIdList", "BinaryCollisionModel",
            "WallInteractionModel", "InflowBoundaryModel", "randomSeed",
            "randomEntryTime", "axisymmetric", "radialExtent",
            "maxRadialWeight", "tracking"
        },
        false
    );

    return species;
}


void Foam::gasCloudInputCheck::checkInitialise
(
    const dictionary& dict,
    const wordList& species
)
{
    using namespace inputChecks;

    rejectMisspelt
    (
        dict, {"numberDensities", "temperature", "velocity", "randomSeed"}
    );
    getLabelOrDefault(dict, "randomSeed", 0, 0, 2000);
    getPositive(dict, "temperature");
    getVector(dict, "velocity");

    const dictionary& densities = dict.subDict("numberDensities");
    if (densities.empty())
    {
        outOfRange(dict, "numberDensities", "{}", "one entry per species");
    }
    for (const word& name : densities.toc())
    {
        if (!species.found(name))
        {
            notOneOf(densities, "numberDensities", name, species);
        }
        getNonNegativeOrDefault(densities, name, 0);
    }
}


const Foam::dictionary& Foam::gasCloudInputCheck::checked
(
    const dictionary& dict
)
{
    checkProperties(dict);
    return dict;
}


const Foam::dictionary& Foam::gasCloudInputCheck::checked
(
    const dictionary& dict,
    const dictionary& initialiseDict
)
{
    checkInitialise(initialiseDict, checkProperties(dict));
    return dict;
}


Foam::gasCloudInputCheck::gasCloudInputCheck
(
    const word& cloudName,
    const fvMesh& mesh
)
:
    axisymmetric_
    (
        checked(inputChecks::readCloudProperties(cloudName, mesh)),
        mesh,
        "gas"
    )
{}


Foam::gasCloudInputCheck::gasCloudInputCheck
(
    const word& cloudName,
    const fvMesh& mesh,
    const dictionary& initialiseDict
)
:
    axisymmetric_
    (
        checked
        (
            inputChecks::readCloudProperties(cloudName, mesh),
            initialiseDict
        ),
        mesh,
        "gas"
    )
{}


// ************************************************************************* //
