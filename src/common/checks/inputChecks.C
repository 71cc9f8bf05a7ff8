/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "inputChecks.H"
#include "OStringStream.H"
#include "Switch.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * * The record  * * * * * * * * * * * * * * * //

namespace Foam
{
namespace inputChecks
{
namespace
{

struct recordRow
{
    string dictName;
    word keyword;
    word kind;
    string valid;
    bool required;
};

bool recording = false;

DynamicList<recordRow>& rows()
{
    static DynamicList<recordRow> list;
    return list;
}

HashSet<string>& seen()
{
    static HashSet<string> set;
    return set;
}


//- The value of an entry as its text (tokens separated by spaces)
std::string entryText(const entry& e)
{
    if (e.isDict())
    {
        return "a dictionary";
    }

    OStringStream os;
    const ITstream& is = e.stream();
    forAll(is, i)
    {
        if (i)
        {
            os << ' ';
        }
        os << is[i];
    }
    return os.str();
}


//- The entry of keyword in dict (not its parents, no pattern), nullptr
//  when missing; a missing required keyword stops, naming valid
const entry* findChecked
(
    const dictionary& dict,
    const word& keyword,
    const word& kind,
    const std::string& valid,
    const bool required
)
{
    keywordRecord::add(dict, keyword, kind, valid, required);

    const entry* e = dict.findEntry(keyword, keyType::LITERAL);

    if (!e && required)
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword '" << keyword << "' in " << dict.name()
            << nl << "    value: missing"
            << nl << "    valid: " << valid.c_str()
            << exit(FatalIOError);
    }
    if (e && e->isDict())
    {
        badValue(dict, keyword, "a dictionary", valid.c_str());
    }

    return e;
}


//- The single token of a primitive entry, or stop: the form is not kind
const token& singleToken
(
    const dictionary& dict,
    const entry& e,
    const std::string& valid,
    const bool wanted
)
{
    const ITstream& is = e.stream();
    if (is.size() != 1 || !wanted)
    {
        badValue(dict, e.keyword(), entryText(e).c_str(), valid.c_str());
    }
    return is[0];
}


//- Read keyword as a word of choices, or as any name when what (its
//  description) is given
word getWordChecked
(
    const dictionary& dict,
    const word& keyword,
    const wordList& choices,
    const std::string& what,
    const bool required,
    const word& deflt
)
{
    const bool anyName = !what.empty();

    OStringStream valid;
    if (anyName)
    {
        valid << what.c_str();
    }
    else
    {
        valid << "one of";
        for (const word& c : choices)
        {
            valid << ' ' << c;
        }
    }

    const entry* e = findChecked
    (
        dict, keyword, anyName ? "name" : "word", valid.str(),
        required
    );

    if (!e)
    {
        return deflt;
    }

    // A name may be quoted (a file name with / or <constant>)
    const ITstream& is = e->stream();
    const bool form =
        is.size() == 1
     && (is[0].isWord() || (anyName && is[0].isString()));
    const token& t = singleToken(dict, *e, valid.str(), form);
    const word value
    (
        t.isWord() ? t.wordToken() : word(t.stringToken(), false)
    );

    if (!anyName && !choices.found(value))
    {
        badValue(dict, keyword, value, valid.str().c_str());
    }

    return value;
}


//- Read keyword as a vector (x y z) of finite components
bool getVectorChecked
(
    const dictionary& dict,
    const word& keyword,
    const bool required,
    vector& value
)
{
    const std::string valid("a vector (x y z) of finite numbers");
    const entry* e = findChecked(dict, keyword, "vector", valid, required);

    if (!e)
    {
        return false;
    }

    const ITstream& is = e->stream();
    bool good =
        is.size() == 5
     && is[0].isPunctuation() && is[0].pToken() == token::BEGIN_LIST
     && is[4].isPunctuation() && is[4].pToken() == token::END_LIST;

    for (label i = 1; good && i < 4; ++i)
    {
        good = is[i].isNumber() && std::isfinite(is[i].number());
        if (good)
        {
            value[i - 1] = is[i].number();
        }
    }

    if (!good)
    {
        badValue(dict, keyword, entryText(*e).c_str(), valid.c_str());
    }

    return true;
}

} // End anonymous namespace
} // End namespace inputChecks
} // End namespace Foam


std::string Foam::inputChecks::valueText
(
    const dictionary& dict,
    const word& keyword
)
{
    const entry* e = dict.findEntry(keyword, keyType::LITERAL);
    return e ? entryText(*e) : std::string("missing");
}



void Foam::inputChecks::keywordRecord::addOption(const std::string& usage)
{
    argList::addBoolOption("listKeywords", usage);
}


void Foam::inputChecks::keywordRecord::start(const argList& args)
{
    recording = args.found("listKeywords");
}


bool Foam::inputChecks::keywordRecord::active()
{
    return recording;
}


void Foam::inputChecks::keywordRecord::add
(
    const dictionary& dict,
    const word& keyword,
    const word& kind,
    const std::string& valid,
    const bool required
)
{
    // (a dictionary without a name: an optional one absent, read as empty)
    if
    (
        recording && !dict.name().empty()
     && seen().insert(dict.name() + '\t' + keyword)
    )
    {
        rows().append({dict.name(), keyword, kind, valid, required});
    }
}


void Foam::inputChecks::keywordRecord::print(const fileName& casePath)
{
    const std::string prefix(casePath + '/');

    for (const recordRow& r : rows())
    {
        std::string name(r.dictName);
        if (name.compare(0, prefix.size(), prefix) == 0)
        {
            name.erase(0, prefix.size());
        }

        Info<< "checkedKeyword\t" << name.c_str() << '\t'
            << r.keyword.c_str() << '\t' << r.kind.c_str() << '\t'
            << (r.required ? "required" : "optional") << '\t'
            << r.valid.c_str() << nl;
    }
    Info<< "checkedKeywords " << rows().size() << endl;
}


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

bool Foam::inputChecks::interval::contains(const scalar value) const
{
    return
        std::isfinite(value)
     && (openMin ? value > min : value >= min)
     && (openMax ? value < max : value <= max);
}


std::string Foam::inputChecks::interval::text() const
{
    const auto end = [](const scalar x) -> std::string
    {
        if (x >= VGREAT)
        {
            return "inf";
        }
        if (x <= -VGREAT)
        {
            return "-inf";
        }
        return Foam::name(x);
    };

    return std::string(openMin ? "(" : "[") + end(min) + ", "
      + (maxText.empty() ? end(max) : maxText) + (openMax ? ")" : "]");
}


namespace Foam
{
namespace inputChecks
{
namespace
{

//- getInterval and getIntervalOrDefault
scalar readInterval
(
    const dictionary& dict,
    const word& keyword,
    const interval& valid,
    const bool required,
    const scalar deflt
)
{
    const std::string text(valid.text());
    const entry* e = findChecked(dict, keyword, "scalar", text, required);

    if (!e)
    {
        return deflt;
    }

    const ITstream& is = e->stream();
    const token& t =
        singleToken(dict, *e, text, is.size() == 1 && is[0].isNumber());
    const scalar value = t.number();

    if (!valid.contains(value))
    {
        outOfRange(dict, keyword, value, text);
    }

    return value;
}

} // End anonymous namespace
} // End namespace inputChecks
} // End namespace Foam


Foam::scalar Foam::inputChecks::getInterval
(
    const dictionary& dict,
    const word& keyword,
    const interval& valid
)
{
    return readInterval(dict, keyword, valid, true, 0);
}


Foam::scalar Foam::inputChecks::getIntervalOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const interval& valid,
    const scalar deflt
)
{
    return readInterval(dict, keyword, valid, false, deflt);
}


void Foam::inputChecks::notOneOf
(
    const dictionary& dict,
    const word& keyword,
    const word& value,
    const wordList& choices
)
{
    badValue(dict, keyword, value, choices);
}


Foam::scalar Foam::inputChecks::getPositive
(
    const dictionary& dict,
    const word& keyword
)
{
    return getInterval(dict, keyword, interval::open(0, VGREAT));
}


Foam::scalar Foam::inputChecks::getPositiveOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt
)
{
    return getIntervalOrDefault
    (
        dict, keyword, interval::open(0, VGREAT), deflt
    );
}


Foam::scalar Foam::inputChecks::getNonNegative
(
    const dictionary& dict,
    const word& keyword
)
{
    return getInterval(dict, keyword, interval::atLeast(0));
}


Foam::scalar Foam::inputChecks::getNonNegativeOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt
)
{
    return getIntervalOrDefault(dict, keyword, interval::atLeast(0), deflt);
}


Foam::scalar Foam::inputChecks::getClosed
(
    const dictionary& dict,
    const word& keyword,
    const scalar min,
    const scalar max
)
{
    return getInterval(dict, keyword, interval::closed(min, max));
}


Foam::scalar Foam::inputChecks::getClosedOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt,
    const scalar min,
    const scalar max
)
{
    return getIntervalOrDefault
    (
        dict, keyword, interval::closed(min, max), deflt
    );
}


Foam::scalar Foam::inputChecks::getOpen
(
    const dictionary& dict,
    const word& keyword,
    const scalar min,
    const scalar max,
    const std::string& maxText
)
{
    return getInterval(dict, keyword, interval::open(min, max, maxText));
}


Foam::scalar Foam::inputChecks::getAtLeast
(
    const dictionary& dict,
    const word& keyword,
    const scalar min,
    const scalar deflt
)
{
    return getIntervalOrDefault(dict, keyword, interval::atLeast(min), deflt);
}


Foam::label Foam::inputChecks::getLabelOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const label deflt,
    const label min,
    const label max
)
{
    const std::string valid
    (
        "an integer in [" + Foam::name(min) + ", " + Foam::name(max) + "]"
    );
    const entry* e = findChecked(dict, keyword, "label", valid, false);

    if (!e)
    {
        return deflt;
    }

    const ITstream& is = e->stream();
    const label value =
        singleToken(dict, *e, valid, is.size() == 1 && is[0].isLabel())
       .labelToken();

    if (value < min || value > max)
    {
        outOfRange(dict, keyword, value, valid);
    }

    return value;
}


bool Foam::inputChecks::getBoolOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const bool deflt
)
{
    const std::string valid("true or false (also yes/no, on/off)");
    const entry* e = findChecked(dict, keyword, "bool", valid, false);

    if (!e)
    {
        return deflt;
    }

    const ITstream& is = e->stream();
    const bool form = is.size() == 1 && (is[0].isWord() || is[0].isBool());
    const token& t = singleToken(dict, *e, valid, form);

    if (t.isBool())
    {
        return t.boolToken();
    }

    const Switch value(t.wordToken(), true);
    if (!value.valid())
    {
        badValue(dict, keyword, t.wordToken(), valid.c_str());
    }

    return bool(value);
}


Foam::word Foam::inputChecks::getChoice
(
    const dictionary& dict,
    const word& keyword,
    const wordList& choices
)
{
    return getWordChecked(dict, keyword, choices, "", true, word::null);
}


Foam::word Foam::inputChecks::getChoiceOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const word& deflt,
    const wordList& choices
)
{
    return getWordChecked(dict, keyword, choices, "", false, deflt);
}


Foam::word Foam::inputChecks::getName
(
    const dictionary& dict,
    const word& keyword,
    const std::string& what,
    const bool required
)
{
    return getWordChecked
    (
        dict, keyword, wordList(), what, required, word::null
    );
}


Foam::vector Foam::inputChecks::getVector
(
    const dictionary& dict,
    const word& keyword
)
{
    vector value(Zero);
    getVectorChecked(dict, keyword, true, value);
    return value;
}


Foam::vector Foam::inputChecks::getVectorOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const vector& deflt
)
{
    vector value(deflt);
    getVectorChecked(dict, keyword, false, value);
    return value;
}


Foam::IOdictionary Foam::inputChecks::readCloudProperties
(
    const word& cloudName,
    const objectRegistry& db
)
{
    return IOdictionary
    (
        IOobject
        (
            cloudName + "Properties",
            db.time().constant(),
            db,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
}


// ************************************************************************* //
