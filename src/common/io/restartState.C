/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "restartState.H"
#include "Time.H"
#include "cloud.H"
#include "polyMesh.H"

#include <cstring>
#include <limits>
#include <random>
#include <type_traits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Random's members, in its order, so that its state can be copied out and
// in through its bytes (Random has no accessor for it)
struct randomLayout
{
    label seed;
    Rand48 generator;
    std::uniform_real_distribution<scalar> uniform01;
    bool hasGaussSample;
    scalar gaussSample;
};

static_assert
(
    std::is_trivially_copyable<Random>::value
 && std::is_trivially_copyable<randomLayout>::value
 && sizeof(randomLayout) == sizeof(Random)
 && sizeof(Rand48) == sizeof(uint64_t),
    "Random's layout differs from the one restartState stores"
);


IOobject stateIO
(
    const objectRegistry& db,
    const word& cloudName,
    const word& owner,
    const IOobject::readOption r
)
{
    return IOobject
    (
        owner + "State",
        db.time().timeName(),
        "uniform"/cloud::prefix/cloudName,
        db,
        r,
        IOobject::NO_WRITE,
        false
    );
}


// Who wrote a state: the processor, the number of processors and, when db
// is a mesh, its number of cells and the sum of its cell centres (a case
// decomposed anew gives each processor other cells)
dictionary writer(const objectRegistry& db)
{
    dictionary dict;
    dict.add("processor", Pstream::myProcNo());
    dict.add("nProcessors", Pstream::nProcs());
    const polyMesh* meshPtr = dynamic_cast<const polyMesh*>(&db);
    if (meshPtr)
    {
        dict.add("nCells", meshPtr->nCells());
        restartState::put(dict, "cellCentreSum", sum(meshPtr->cellCentres()));
    }
    return dict;
}


// Does the writer recorded in a state describe this processor's mesh?
// (a state without the record, written before it existed, is taken)
bool sameWriter(const dictionary& recorded, const dictionary& now)
{
    if
    (
        recorded.get<label>("processor") != now.get<label>("processor")
     || recorded.get<label>("nProcessors") != now.get<label>("nProcessors")
     || recorded.getOrDefault<label>("nCells", -1)
     != now.getOrDefault<label>("nCells", -1)
    )
    {
        return false;
    }
    if (now.found("cellCentreSum"))
    {
        const vector a(recorded.get<vector>("cellCentreSum"));
        const vector b(now.get<vector>("cellCentreSum"));
        return mag(a - b) <= 1e-10*max(mag(b), VSMALL);
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::dictionary Foam::restartState::read
(
    const objectRegistry& db,
    const word& cloudName,
    const word& owner
)
{
    const localIOdictionary dict
    (
        stateIO(db, cloudName, owner, IOobject::READ_IF_PRESENT)
    );
    if (dict.empty())
    {
        return dict;
    }

    // A state copied in from another processor (decomposePar links or
    // copies the case's uniform/, which reconstructPar took from
    // processor0) would give every processor the same random streams
    const dictionary* recorded = dict.findDict("writtenBy");
    if (recorded && !sameWriter(*recorded, writer(db)))
    {
        WarningInFunction
            << "Restart state " << dict.objectPath()
            << " was written by processor "
            << recorded->get<label>("processor") << " of "
            << recorded->get<label>("nProcessors")
            << " on another decomposition (case decomposed anew, or"
            << " reconstructed): " << owner << " starts afresh" << endl;
        return dictionary();
    }

    Info<< "    restart state of " << owner << " read from "
        << dict.objectPath() << endl;
    return dict;
}


void Foam::restartState::write
(
    const objectRegistry& db,
    const word& cloudName,
    const word& owner,
    const dictionary& state,
    const bool shared
)
{
    localIOdictionary dict(stateIO(db, cloudName, owner, IOobject::NO_READ));
    dict.merge(state);
    if (!shared)
    {
        dict.add("writtenBy", writer(db), true);
    }
    const Time& time = db.time();

    // Every scalar with the digits that read back to the same double
    const unsigned precision =
        IOstream::defaultPrecision(std::numeric_limits<scalar>::max_digits10);
    dict.regIOobject::writeObject
    (
        time.writeFormat(),
        IOstream::currentVersion,
        time.writeCompression(),
        true
    );
    IOstream::defaultPrecision(precision);
}


void Foam::restartState::put
(
    dictionary& state,
    const word& key,
    const Random& rnd
)
{
    randomLayout r;
    std::memcpy(static_cast<void*>(&r), &rnd, sizeof(Random));
    uint64_t x;
    std::memcpy(&x, &r.generator, sizeof(x));

    char hex[24];
    std::snprintf(hex, sizeof(hex), "x%012llx", static_cast<unsigned long long>(x));

    dictionary dict;
    dict.add("seed", r.seed);
    dict.add("generator", word(hex));
    dict.add("hasGaussSample", r.hasGaussSample);
    put(dict, "gaussSample", r.hasGaussSample ? r.gaussSample : 0);
    state.add(key, dict, true);
}


bool Foam::restartState::get
(
    const dictionary& state,
    const word& key,
    Random& rnd
)
{
    const dictionary* dictPtr = state.findDict(key);
    if (!dictPtr)
    {
        return false;
    }
    const dictionary& dict = *dictPtr;

    randomLayout r;
    std::memcpy(static_cast<void*>(&r), &rnd, sizeof(Random));

    const word hex(dict.get<word>("generator"));
    const uint64_t x = std::strtoull(hex.c_str() + 1, nullptr, 16);
    std::memcpy(static_cast<void*>(&r.generator), &x, sizeof(x));
    r.seed = dict.get<label>("seed");
    r.hasGaussSample = dict.get<bool>("hasGaussSample");
    r.gaussSample = dict.get<scalar>("gaussSample");

    std::memcpy(static_cast<void*>(&rnd), &r, sizeof(Random));
    return true;
}


// ************************************************************************* //
