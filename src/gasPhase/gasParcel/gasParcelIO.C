/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasParcel.H"
#include "IOField.H"
#include "Cloud.H"

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
}


// ************************************************************************* //
