/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "keywordChecks.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::label Foam::inputChecks::editDistance
(
    const std::string& a,
    const std::string& b
)
{
    labelList previous(label(b.size()) + 1);
    labelList current(label(b.size()) + 1);
    forAll(previous, j)
    {
        previous[j] = j;
    }
    for (size_t i = 1; i <= a.size(); ++i)
    {
        current[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
        {
            current[j] = min
            (
                min(previous[j] + 1, current[j - 1] + 1),
                previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)
            );
        }
        previous.transfer(current);
        current.setSize(label(b.size()) + 1);
    }
    return previous[b.size()];
}


Foam::word Foam::inputChecks::closeTo
(
    const word& keyword,
    const wordList& valid
)
{
    for (const word& v : valid)
    {
        if (keyword == v)
        {
            return word::null;
        }
    }
    for (const word& v : valid)
    {
        const bool sameLetters = keyword.size() == v.size()
         && std::equal
            (
                keyword.begin(), keyword.end(), v.begin(),
                [](char a, char b) { return tolower(a) == tolower(b); }
            );
        if (sameLetters || (v.size() >= 5 && editDistance(keyword, v) <= 2))
        {
            return v;
        }
    }
    return word::null;
}


void Foam::inputChecks::rejectUnknown
(
    const dictionary& dict,
    const wordList& valid
)
{
    for (const entry& e : dict)
    {
        if (!valid.found(e.keyword()))
        {
            const word meant(closeTo(e.keyword(), valid));
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "' in "
                << dict.name();
            if (!meant.empty())
            {
                FatalIOError<< "  (did you mean '" << meant << "'?)";
            }
            FatalIOError
                << nl << "    valid keywords: " << valid
                << exit(FatalIOError);
        }
    }
}


const Foam::dictionary& Foam::inputChecks::knownSubDict
(
    const dictionary& dict,
    const word& name,
    const wordList& valid
)
{
    const dictionary& sub = dict.subDict(name);
    rejectUnknown(sub, valid);
    return sub;
}


void Foam::inputChecks::rejectMisspelt
(
    const dictionary& dict,
    const wordList& valid,
    const bool subDictionaries
)
{
    for (const entry& e : dict)
    {
        if (!subDictionaries && e.isDict())
        {
            continue;
        }
        const word meant(closeTo(e.keyword(), valid));
        if (!meant.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "' in "
                << dict.name() << "  (did you mean '" << meant << "'?)"
                << nl << "    valid keywords: " << valid
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
