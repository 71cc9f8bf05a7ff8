/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "SolidParcel.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * Static Member Data  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::string Foam::SolidParcel<ParcelType>::propertyList_ =
    Foam::SolidParcel<ParcelType>::propertyList();


template<class ParcelType>
const std::size_t Foam::SolidParcel<ParcelType>::sizeofFields
(
    SolidParcel<ParcelType>::nFields*sizeof(scalar)
);


namespace Foam
{
namespace solidParcelFields
{
    //- Names of the per-parcel fields this layer adds, in storage order
    static const char* const names[] =
    {
        "T", "Cp", "specularFraction", "thermalAccommodation"
    };
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::SolidParcel<ParcelType>::SolidParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    fields_{0, 0, 0, 0}
{
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            for (scalar& value : fields_)
            {
                is  >> value;
            }
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            // Non-native scalar size
            is.beginRawRead();
            readRawScalar(is, fields_, nFields);
            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(fields_), sizeofFields);
        }
    }

    is.check(FUNCTION_NAME);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class CloudType>
void Foam::SolidParcel<ParcelType>::readFields(CloudType& c)
{
    const bool valid = c.size();

    ParcelType::readFields(c);

    for (label fieldi = 0; fieldi < nFields; ++fieldi)
    {
        IOField<scalar> values
        (
            c.fieldIOobject(solidParcelFields::names[fieldi], IOobject::MUST_READ),
            valid
        );
        c.checkFieldIOobject(c, values);

        label i = 0;
        for (SolidParcel<ParcelType>& p : c)
        {
            p.fields_[fieldi] = values[i++];
        }
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::SolidParcel<ParcelType>::writeFields(const CloudType& c)
{
    ParcelType::writeFields(c);

    const label np = c.size();

    for (label fieldi = 0; fieldi < nFields; ++fieldi)
    {
        IOField<scalar> values
        (
            c.fieldIOobject(solidParcelFields::names[fieldi], IOobject::NO_READ),
            np
        );

        label i = 0;
        for (const SolidParcel<ParcelType>& p : c)
        {
            values[i++] = p.fields_[fieldi];
        }

        values.write(np > 0);
    }
}


template<class ParcelType>
void Foam::SolidParcel<ParcelType>::writeProperties
(
    Ostream& os,
    const wordRes& filters,
    const word& delim,
    const bool namesOnly
) const
{
    ParcelType::writeProperties(os, filters, delim, namesOnly);

    for (label fieldi = 0; fieldi < nFields; ++fieldi)
    {
        ParcelType::writeProperty
        (
            os, solidParcelFields::names[fieldi], fields_[fieldi],
            namesOnly, delim, filters
        );
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::SolidParcel<ParcelType>::readObjects
(
    CloudType& c,
    const objectRegistry& obr
)
{
    ParcelType::readObjects(c, obr);

    if (!c.size()) return;

    for (label fieldi = 0; fieldi < nFields; ++fieldi)
    {
        const auto& values =
            cloud::lookupIOField<scalar>(solidParcelFields::names[fieldi], obr);

        label i = 0;
        for (SolidParcel<ParcelType>& p : c)
        {
            p.fields_[fieldi] = values[i++];
        }
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::SolidParcel<ParcelType>::writeObjects
(
    const CloudType& c,
    objectRegistry& obr
)
{
    ParcelType::writeObjects(c, obr);

    const label np = c.size();

    for (label fieldi = 0; fieldi < nFields; ++fieldi)
    {
        auto& values = cloud::createIOField<scalar>
        (
            solidParcelFields::names[fieldi], np, obr
        );

        label i = 0;
        for (const SolidParcel<ParcelType>& p : c)
        {
            values[i++] = p.fields_[fieldi];
        }
    }
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const SolidParcel<ParcelType>& p
)
{
    if (os.format() == IOstream::ASCII)
    {
        os  << static_cast<const ParcelType&>(p)
            << token::SPACE << p.T()
            << token::SPACE << p.Cp()
            << token::SPACE << p.specularFraction()
            << token::SPACE << p.thermalAccommodation();
    }
    else
    {
        os  << static_cast<const ParcelType&>(p);
        os.write
        (
            reinterpret_cast<const char*>(p.fields_),
            SolidParcel<ParcelType>::sizeofFields
        );
    }

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
