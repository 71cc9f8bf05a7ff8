/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "CachedDual.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
const Foam::AveragingMethods::Dual<Type>&
Foam::AveragingMethods::CachedDual<Type>::prototype
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word name(typeName + ':' + word(pTraits<Type>::typeName));

    // Dual volumes of a mesh that has moved are stale: build them anew
    if (mesh.changing())
    {
        static_cast<const objectRegistry&>(mesh).checkOut(name);
    }

    const Dual<Type>* ptr = mesh.cfindObject<Dual<Type>>(name);
    if (!ptr)
    {
        Dual<Type>* built = new Dual<Type>
        (
            IOobject
            (
                name,
                mesh.time().constant(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                true
            ),
            dict,
            mesh
        );
        built->store();
        ptr = built;
    }

    return *ptr;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Type>
Foam::AveragingMethods::CachedDual<Type>::CachedDual
(
    const IOobject& io,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    Dual<Type>(prototype(dict, mesh))
{
    // The copy has the prototype's name and is not registered: take the
    // name, instance and registration asked for (the MPPIC submodels find
    // the averages by name)
    this->registerObject() = io.registerObject();
    regIOobject::operator=(io);
}


// ************************************************************************* //
