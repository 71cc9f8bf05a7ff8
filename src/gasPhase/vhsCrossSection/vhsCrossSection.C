/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "vhsCrossSection.H"
#include "physicoChemicalConstants.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineNameRegistry(vhsModelsTag, bool);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::scalar Foam::vhsCrossSection::referenceViscosity
(
    const scalar m,
    const scalar d,
    const scalar omega,
    const scalar Tref
)
{
    const scalar k = constant::physicoChemical::k.value();
    return
        15*Foam::sqrt(m*k*Tref/constant::mathematical::pi)
       /(2*(5 - 2*omega)*(7 - 2*omega)*sqr(d));
}


Foam::vhsCrossSection::vhsCrossSection(const DSMCCloud<gasParcel>& cloud)
:
    nSpecies_(cloud.constProps().size()),
    upstream_(false)
{
    const auto& model = cloud.binaryCollision();
    const bool* upstream = vhsModels::find(model.type());
    if (!upstream)
    {
        return;
    }
    upstream_ = *upstream;

    const scalar Tref = model.coeffDict().getScalar("Tref");
    const scalar k = constant::physicoChemical::k.value();

    A_.setSize(nSpecies_*nSpecies_);
    exponent_.setSize(nSpecies_*nSpecies_);
    for (label p = 0; p < nSpecies_; ++p)
    {
        for (label q = 0; q < nSpecies_; ++q)
        {
            const auto& P = cloud.constProps(p);
            const auto& Q = cloud.constProps(q);
            const scalar d = 0.5*(P.d() + Q.d());
            const scalar omega = 0.5*(P.omega() + Q.omega());
            const scalar mR = P.mass()*Q.mass()/(P.mass() + Q.mass());

            A_[p*nSpecies_ + q] =
                constant::mathematical::pi*d*d
               *Foam::pow(2*k*Tref/mR, omega - 0.5)
               /Foam::exp(Foam::lgamma(2.5 - omega));
            exponent_[p*nSpecies_ + q] = 1 - omega;
        }
    }
}


// ************************************************************************* //
