/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Application
    Test-gasInputChecks

Description
    Unit test of the gas phase's input checks (gasCloudInputCheck): a valid
    dsmcProperties / dsmcInitialiseDict pair passes; each bad value raises a
    FatalIOError whose message names the keyword, the bad value and the
    valid range or choices.  Exits non-zero on any failure.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IStringStream.H"
#include "gasCloud.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

const char* const validProperties =
    "nEquivalentParticles 1e12;"
    "randomSeed 7;"
    "WallInteractionModel MixedDiffuseSpecular;"
    "MixedDiffuseSpecularCoeffs { diffuseFraction 0.8; }"
    "BinaryCollisionModel LarsenBorgnakkeVariableHardSphere;"
    "LarsenBorgnakkeVariableHardSphereCoeffs"
    "{ Tref 273; relaxationCollisionNumber 5; }"
    "InflowBoundaryModel FreeStream;"
    "FreeStreamCoeffs { numberDensities { N2 1e20; Ar 2e19; } }"
    "typeIdList (N2 Ar);"
    "moleculeProperties"
    "{"
    "    N2 { mass 46.5e-27; diameter 4.17e-10;"
    "         internalDegreesOfFreedom 2; omega 0.74; }"
    "    Ar { mass 66.3e-27; diameter 4.17e-10;"
    "         internalDegreesOfFreedom 0; omega 0.81; }"
    "}";

const char* const validInitialise =
    "numberDensities { N2 1e20; Ar 0; }"
    "temperature 300;"
    "velocity (100 0 0);";


dictionary parse(const char* text)
{
    IStringStream is(text);
    return dictionary(is);
}


label nFailed = 0;
label nPassed = 0;

void report(const bool ok, const string& what)
{
    Info<< (ok ? "PASS " : "FAIL ") << what.c_str() << nl;
    (ok ? nPassed : nFailed)++;
}


//- Run the checks on (properties, initialise); return the error message,
//  empty when no error was raised
string messageOf(const dictionary& props, const dictionary& init)
{
    try
    {
        gasCloudInputCheck::checkInitialise
        (
            init,
            gasCloudInputCheck::checkProperties(props)
        );
    }
    catch (const Foam::IOerror& err)
    {
        return err.message() + " " + err.ioFileName();
    }
    catch (const Foam::error& err)
    {
        return err.message();
    }
    return string();
}


//- Set keyword (a "/"-separated path) of a copy of base to value
dictionary changed(const dictionary& base, const string& path, const string& value)
{
    dictionary dict(base);
    dictionary* target = &dict;

    const wordList parts(fileName(path).components());
    for (label i = 0; i < parts.size() - 1; ++i)
    {
        target = &target->subDict(parts[i]);
    }

    IStringStream is(parts.last() + " " + value + ";");
    target->set(entry::New(is).ptr());
    return dict;
}


//- Expect an error whose message contains every one of words
void expectError
(
    const string& what,
    const dictionary& props,
    const dictionary& init,
    const wordList& words
)
{
    const string msg = messageOf(props, init);
    bool ok = !msg.empty();
    for (const word& w : words)
    {
        if (msg.find(w) == string::npos)
        {
            Info<< "    message lacks '" << w << "'" << nl;
            ok = false;
        }
    }
    if (!ok)
    {
        Info<< "    message was: " << msg.c_str() << nl;
    }
    report(ok, what);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noParallel();
    argList args(argc, argv);

    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const dictionary props(parse(validProperties));
    const dictionary init(parse(validInitialise));

    {
        const string msg = messageOf(props, init);
        report(msg.empty(), "valid dictionaries pass" + (msg.empty() ? "" : ": " + msg));
    }

    // Dictionary (true: dsmcProperties, false: dsmcInitialiseDict), keyword
    // path and bad value (written as the message prints it); the message
    // must name the keyword, the value and the valid range
    struct badValue { bool inProperties; word path; string value; };
    const List<badValue> badValues
    ({
        {true, "nEquivalentParticles", "-1e+12"},
        {true, "nEquivalentParticles", "0"},
        {true, "randomSeed", "-3"},
        {true, "randomSeed", "5000"},
        {true, "moleculeProperties/N2/mass", "-4.65e-26"},
        {true, "moleculeProperties/N2/diameter", "0"},
        {true, "moleculeProperties/Ar/omega", "1.3"},
        {true, "moleculeProperties/Ar/internalDegreesOfFreedom", "-1"},
        {true, "MixedDiffuseSpecularCoeffs/diffuseFraction", "1.5"},
        {true, "LarsenBorgnakkeVariableHardSphereCoeffs/Tref", "-273"},
        {true, "LarsenBorgnakkeVariableHardSphereCoeffs/relaxationCollisionNumber", "0.5"},
        {true, "FreeStreamCoeffs/numberDensities/N2", "-1e+20"},
        {false, "temperature", "-300"},
        {false, "temperature", "0"},
        {false, "numberDensities/N2", "-1e+20"},
        {false, "randomSeed", "2001"},
    });

    for (const badValue& bad : badValues)
    {
        const word key = bad.path.substr(bad.path.rfind('/') + 1);
        expectError
        (
            (bad.inProperties ? "dsmcProperties " : "dsmcInitialiseDict ")
          + bad.path + " = " + bad.value,
            bad.inProperties ? changed(props, bad.path, bad.value) : props,
            bad.inProperties ? init : changed(init, bad.path, bad.value),
            {key, word(bad.value), "valid"}
        );
    }

    for
    (
        const word& model
      : {"BinaryCollisionModel", "WallInteractionModel", "InflowBoundaryModel"}
    )
    {
        expectError
        (
            "dsmcProperties unknown " + model,
            changed(props, model, "NoSuchModel"),
            init,
            {model, "NoSuchModel", "valid: one of"}
        );
    }

    expectError
    (
        "dsmcProperties FreeStream species not in typeIdList",
        changed(props, "FreeStreamCoeffs/numberDensities/Xe", "1e19"),
        init,
        {"Xe", "N2", "Ar"}
    );

    expectError
    (
        "dsmcProperties species without moleculeProperties",
        changed(props, "typeIdList", "(N2 Ar He)"),
        init,
        {"He"}
    );

    expectError
    (
        "dsmcInitialiseDict species not in typeIdList",
        props,
        changed(init, "numberDensities/O2", "1e20"),
        {"O2", "valid", "N2"}
    );

    Info<< nl << nPassed << " passed, " << nFailed << " failed" << nl;

    // argList's destructor ends every run with exit code 0: report failure
    // through FatalError, which exits with 1
    if (nFailed)
    {
        FatalError.dontThrowExceptions();
        FatalErrorInFunction
            << nFailed << " checks failed" << exit(FatalError);
    }

    return 0;
}


// ************************************************************************* //
