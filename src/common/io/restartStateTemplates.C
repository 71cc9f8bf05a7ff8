/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

template<class Type>
void Foam::restartState::put
(
    dictionary& state,
    const word& key,
    const Type& value
)
{
    const unsigned precision =
        IOstream::defaultPrecision(std::numeric_limits<scalar>::max_digits10);
    state.add(key, value, true);
    IOstream::defaultPrecision(precision);
}


template<class Type>
bool Foam::restartState::get
(
    const dictionary& state,
    const word& key,
    const label size,
    List<Type>& values
)
{
    if (!state.found(key))
    {
        return false;
    }

    List<Type> read(state.get<List<Type>>(key));
    if (read.size() != size)
    {
        WarningInFunction
            << state.name() << ": " << key << " has " << read.size()
            << " entries where the mesh needs " << size
            << " (decomposed anew?); it starts afresh" << endl;
        return false;
    }

    values.transfer(read);
    return true;
}


// ************************************************************************* //
