/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasCarrierFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Header of the field name.gas
Foam::IOobject carrierHeader
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const bool write
)
{
    using namespace Foam;

    return IOobject
    (
        name + ".gas",
        mesh.time().timeName(),
        mesh,
        IOobject::NO_READ,
        write ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasCarrierFields::gasCarrierFields(const fvMesh& mesh, const bool write)
:
    rho
    (
        carrierHeader(mesh, "rho", write), mesh,
        dimensionedScalar(dimDensity, Zero)
    ),
    U
    (
        carrierHeader(mesh, "U", write), mesh,
        dimensionedVector(dimVelocity, Zero)
    ),
    mu
    (
        carrierHeader(mesh, "mu", write), mesh,
        dimensionedScalar(dimDynamicViscosity, Zero)
    ),
    T
    (
        carrierHeader(mesh, "T", write), mesh,
        dimensionedScalar(dimTemperature, Zero)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasCarrierFields::update(const gasCellAverage& now)
{
    forAll(rho, celli)
    {
        rho[celli] = now.rho(celli);
        U[celli] = now.U(celli);
        T[celli] = now.T(celli);
        mu[celli] = now.mu(celli);
    }

    rho.correctBoundaryConditions();
    U.correctBoundaryConditions();
    T.correctBoundaryConditions();
    mu.correctBoundaryConditions();
}


void Foam::gasCarrierFields::update(const gasCloud& gas)
{
    gasCellAverage now(gas, 1);
    now.sample(gas);
    update(now);
}


// ************************************************************************* //
