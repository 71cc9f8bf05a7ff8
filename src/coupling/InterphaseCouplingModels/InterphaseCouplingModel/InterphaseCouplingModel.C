/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "InterphaseCouplingModel.H"
#include "cellFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::InterphaseCouplingModel<CloudType>::InterphaseCouplingModel
(
    CloudType& owner
)
:
    CloudSubModelBase<CloudType>(owner),
    momentum_(),
    energy_(),
    interval_(0),
    gas_(nullptr)
{}


template<class CloudType>
Foam::InterphaseCouplingModel<CloudType>::InterphaseCouplingModel
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    CloudSubModelBase<CloudType>
    (
        word::null,
        owner,
        dict.optionalSubDict(type + "Coeffs"),
        typeName,
        type
    ),
    momentum_(owner.mesh().nCells(), Zero),
    energy_(owner.mesh().nCells(), Zero),
    interval_(0),
    gas_(nullptr)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::InterphaseCouplingModel<CloudType>::writeExchange()
{
    const fvMesh& mesh = this->owner().mesh();

    // Per volume and per time since the last write
    const scalarField perVolTime
    (
        1/(mesh.V().field()*max(interval_, VSMALL))
    );

    const word& cloud = this->owner().name();
    writeCellField
    (
        mesh, cloud, "couplingForce", dimForce/dimVolume,
        vectorField(momentum_*perVolTime)
    );
    writeCellField
    (
        mesh, cloud, "couplingHeat", dimPower/dimVolume,
        scalarField(energy_*perVolTime)
    );

    momentum_ = Zero;
    energy_ = Zero;
    interval_ = 0;
}


template<class CloudType>
void Foam::InterphaseCouplingModel<CloudType>::writeKnudsen
(
    const scalarField& lambda
) const
{
    const fvMesh& mesh = this->owner().mesh();

    // Smallest parcel diameter per cell
    scalarField dMin(mesh.nCells(), GREAT);
    for (const auto& p : this->owner())
    {
        dMin[p.cell()] = min(dMin[p.cell()], p.d());
    }

    scalarField Knp(mesh.nCells(), Zero);
    forAll(Knp, celli)
    {
        if (dMin[celli] < GREAT && dMin[celli] > 0)
        {
            Knp[celli] = lambda[celli]/dMin[celli];
        }
    }

    writeCellField(mesh, this->owner().name(), "Knp", dimless, Knp);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::InterphaseCouplingModel<CloudType>::checkGas
(
    const dictionary& dict,
    const bool gasPresent
) const
{
    if (needsGas() && !gasPresent)
    {
        FatalIOErrorInFunction(dict)
            << "interphaseCoupling " << this->modelType()
            << " in " << dict.name() << " needs a gas phase"
            << " (constant/dsmcProperties), and the case has none"
            << nl << "    valid without gas: none, or Loth with"
            << " gas prescribed in LothCoeffs"
            << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::InterphaseCouplingModel<CloudType>::checkForces
(
    const dictionary& dict
) const
{
    // Upstream's drag forces (sphereDrag, ErgunWenYuDrag, ...) act on the
    // carrier fields, which this model also acts through: both would push
    // the grains with the same gas
    if (!active() || !dict.isDict("particleForces"))
    {
        return;
    }

    const dictionary& forces = dict.subDict("particleForces");
    for (const entry& e : forces)
    {
        const word& force = e.keyword();
        if (force.ends_with("Drag"))
        {
            FatalIOErrorInFunction(forces)
                << "particleForces lists " << force
                << " while interphaseCoupling is " << this->modelType()
                << ": the gas would drag the grains twice.  Remove "
                << force << " (the coupling model gives the drag) or set"
                << " interphaseCoupling none" << exit(FatalIOError);
        }
    }
}


template<class CloudType>
void Foam::InterphaseCouplingModel<CloudType>::coupleParcels(gasCloud* gas)
{
    const bool writing = this->owner().db().time().writeTime();

    gas_ = gas;

    if (active())
    {
        parcelForcesAndHeat(gas);
        interval_ += this->owner().db().time().deltaTValue();

        if (writing)
        {
            writeExchange();
        }
    }

    if (writing && gas)
    {
        writeKnudsen(gas->meanFreePath());
    }
}


// * * * * * * * * * * * * * * * * * Selector * * * * * * * * * * * * * * * //

#include "InterphaseCouplingModelNew.C"

// ************************************************************************* //
