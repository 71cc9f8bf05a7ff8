/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasParcel.H"
#include "IOField.H"
#include "PtrList.H"
#include "Cloud.H"
#include "DSMCCloud.H"
#include "vibrationalModes.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{
    //- Oscillators per species of the cloud c (a DSMCCloud<gasParcel>)
    Foam::labelList oscillators(const Foam::Cloud<Foam::gasParcel>& c)
    {
        const auto& dc =
            dynamic_cast<const Foam::DSMCCloud<Foam::gasParcel>&>(c);
        return Foam::vibrationalModes::oscillators
        (
            dc.particleProperties().subDict("moleculeProperties"),
            dc.typeIdList()
        );
    }

    //- Name of the field of oscillator k
    Foam::word levelName(const Foam::label k)
    {
        return "vibLevel" + Foam::name(k);
    }
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasParcel::readFields(Cloud<gasParcel>& c)
{
    const bool valid = c.size();

    particle::readFields(c);

    IOField<vector> U(c.fieldIOobject("U", IOobject::MUST_READ), valid);
    IOField<scalar> Ei(c.fieldIOobject("Ei", IOobject::MUST_READ), valid);
    IOField<label> typeId
    (
        c.fieldIOobject("typeId", IOobject::MUST_READ),
        valid
    );
    c.checkFieldIOobject(c, U);
    c.checkFieldIOobject(c, Ei);
    c.checkFieldIOobject(c, typeId);

    label i = 0;
    for (gasParcel& p : c)
    {
        p.U_ = U[i];
        p.Ei_ = Ei[i];
        p.typeId_ = typeId[i];
        ++i;
    }

    // Vibrational levels: if a file is absent (a case started without
    // modes, or given more since) every level is left empty, to be drawn
    // by gasCloud
    const labelList nOsc(oscillators(c));
    const label nMax = nOsc.size() ? max(nOsc) : 0;
    if (!nMax)
    {
        return;
    }
    PtrList<IOField<label>> levels(nMax);
    for (label k = 0; k < nMax; ++k)
    {
        IOobject io(c.fieldIOobject(levelName(k), IOobject::MUST_READ));
        if (!valid || !io.typeHeaderOk<IOField<label>>(true))
        {
            return;
        }
        levels.set(k, new IOField<label>(io));
        c.checkFieldIOobject(c, levels[k]);
    }

    i = 0;
    for (gasParcel& p : c)
    {
        p.vibLevels_.setSize(nOsc[p.typeId_]);
        forAll(p.vibLevels_, k)
        {
            p.vibLevels_[k] = levels[k][i];
        }
        ++i;
    }
}


void Foam::gasParcel::writeFields(const Cloud<gasParcel>& c)
{
    particle::writeFields(c);

    const label n = c.size();

    IOField<vector> U(c.fieldIOobject("U", IOobject::NO_READ), n);
    IOField<scalar> Ei(c.fieldIOobject("Ei", IOobject::NO_READ), n);
    IOField<label> typeId(c.fieldIOobject("typeId", IOobject::NO_READ), n);

    label i = 0;
    for (const gasParcel& p : c)
    {
        U[i] = p.U();
        Ei[i] = p.Ei();
        typeId[i] = p.typeId();
        ++i;
    }

    U.write(n > 0);
    Ei.write(n > 0);
    typeId.write(n > 0);

    const labelList nOsc(oscillators(c));
    const label nMax = nOsc.size() ? max(nOsc) : 0;
    for (label k = 0; k < nMax; ++k)
    {
        IOField<label> level
        (
            c.fieldIOobject(levelName(k), IOobject::NO_READ), n
        );
        label i = 0;
        for (const gasParcel& p : c)
        {
            level[i++] = k < p.vibLevels_.size() ? p.vibLevels_[k] : 0;
        }
        level.write(n > 0);
    }
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const gasParcel& p)
{
    os  << static_cast<const DSMCParcel<particle>&>(p);
    if (os.format() == IOstream::ASCII)
    {
        os  << token::SPACE;
    }
    os  << p.vibLevels_;

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
