/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam

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

    // keyword path and bad value (written as the message prints it); the
    // message must name the keyword, the value and the valid range
    const List<Tuple2<word, string>> badProperties
    ({
        {"nEquivalentParticles", "-1e+12"},
        {"nEquivalentParticles", "0"},
        {"randomSeed", "-3"},
        {"randomSeed", "5000"},
        {"moleculeProperties/N2/mass", "-4.65e-26"},
        {"moleculeProperties/N2/diameter", "0"},
        {"moleculeProperties/Ar/omega", "1.3"},
        {"moleculeProperties/Ar/internalDegreesOfFreedom", "-1"},
        {"MixedDiffuseSpecularCoeffs/diffuseFraction", "1.5"},
        {"LarsenBorgnakkeVariableHardSphereCoeffs/Tref", "-273"},
        {"LarsenBorgnakkeVariableHardSphereCoeffs/relaxationCollisionNumber", "0.5"},
        {"FreeStreamCoeffs/numberDensities/N2", "-1e+20"},
    });

    for (const auto& bad : badProperties)
    {
        const word key = bad.first().substr(bad.first().rfind('/') + 1);
        expectError
        (
            "dsmcProperties " + bad.first() + " = " + bad.second(),
            changed(props, bad.first(), bad.second()),
            init,
            {key, word(bad.second()), "valid"}
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
            {model, "NoSuchModel", "Valid"}
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

    const List<Tuple2<word, string>> badInitialise
    ({
        {"temperature", "-300"},
        {"temperature", "0"},
        {"numberDensities/N2", "-1e+20"},
        {"randomSeed", "2001"},
    });

    for (const auto& bad : badInitialise)
    {
        const word key = bad.first().substr(bad.first().rfind('/') + 1);
        expectError
        (
            "dsmcInitialiseDict " + bad.first() + " = " + bad.second(),
            props,
            changed(init, bad.first(), bad.second()),
            {key, word(bad.second()), "valid"}
        );
    }

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
