/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "restartState.H"
#include "Time.H"
#include "cloud.H"

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
    if (dict.size())
    {
        Info<< "    restart state of " << owner << " read from "
            << dict.objectPath() << endl;
    }
    return dict;
}


void Foam::restartState::write
(
    const objectRegistry& db,
    const word& cloudName,
    const word& owner,
    const dictionary& state
)
{
    localIOdictionary dict(stateIO(db, cloudName, owner, IOobject::NO_READ));
    dict.merge(state);
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
