/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasMeanFields.H"
#include "volFields.H"
#include "wallPolyPatch.H"
#include "constants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(gasMeanFields, 0);
    addToRunTimeSelectionTable(functionObject, gasMeanFields, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The gas state of one cell or face from its batch means (see the class
//  description); all zero where no simulator was counted
struct gasState
{
    vector U = Zero;
    scalar translationalT = 0;
    scalar internalT = 0;
    scalar overallT = 0;
    scalar p = 0;

    gasState
    (
        const scalar n,
        const scalar rho,
        const vector& momentum,
        const scalar linearKE,
        const scalar internalE,
        const scalar iDof
    )
    {
        if (n <= 0 || rho <= 0)
        {
            return;
        }
        const scalar k = constant::physicoChemical::k.value();
        U = momentum/rho;
        const scalar thermalKE = linearKE - 0.5*rho*magSqr(U);
        translationalT = 2*thermalKE/(3*k*n);
        internalT = iDof > 0 ? 2*internalE/(k*iDof) : 0;
        overallT = 2*(thermalKE + internalE)/(k*(3*n + iDof));
        p = n*k*translationalT;
    }
};


//- A field of the time's registry to be written, calculated patches
template<class Type>
tmp<GeometricField<Type, fvPatchField, volMesh>> newField
(
    const fvMesh& mesh,
    const word& name,
    const dimensionSet& dims
)
{
    return tmp<GeometricField<Type, fvPatchField, volMesh>>::New
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensioned<Type>(dims, Zero)
    );
}

//- The fields of gasState from the means, element by element (the cells,
//  or one patch's faces)
void fillGasState
(
    vectorField& U,
    scalarField& translationalT,
    scalarField& internalT,
    scalarField& overallT,
    scalarField& p,
    const scalarField& n,
    const scalarField& rho,
    const vectorField& momentum,
    const scalarField& linearKE,
    const scalarField& internalE,
    const scalarField& iDof
)
{
    forAll(n, i)
    {
        const gasState s
        (
            n[i], rho[i], momentum[i], linearKE[i], internalE[i], iDof[i]
        );
        U[i] = s.U;
        translationalT[i] = s.translationalT;
        internalT[i] = s.internalT;
        overallT[i] = s.overallT;
        p[i] = s.p;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::gasMeanFields::gasMeanFields
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::gasMeanFields::execute()
{
    return true;
}


bool Foam::functionObjects::gasMeanFields::write()
{
    const auto& n = lookupObject<volScalarField>("rhoNMean");
    const auto& rho = lookupObject<volScalarField>("rhoMMean");
    const auto& momentum = lookupObject<volVectorField>("momentumMean");
    const auto& linearKE = lookupObject<volScalarField>("linearKEMean");
    const auto& internalE = lookupObject<volScalarField>("internalEMean");
    const auto& iDof = lookupObject<volScalarField>("iDofMean");
    const auto& fD = lookupObject<volVectorField>("fDMean");
    const auto& simulators = lookupObject<volScalarField>("dsmcRhoNMean");

    const dimensionSet dimT(dimTemperature);
    auto tU = newField<vector>(mesh_, "UMean", dimVelocity);
    auto tTt = newField<scalar>(mesh_, "translationalT", dimT);
    auto tTi = newField<scalar>(mesh_, "internalT", dimT);
    auto tTo = newField<scalar>(mesh_, "overallT", dimT);
    auto tp = newField<scalar>(mesh_, "p", dimPressure);
    volVectorField& U = tU.ref();
    volScalarField& Tt = tTt.ref();
    volScalarField& Ti = tTi.ref();
    volScalarField& To = tTo.ref();
    volScalarField& p = tp.ref();

    fillGasState
    (
        U.primitiveFieldRef(), Tt.primitiveFieldRef(),
        Ti.primitiveFieldRef(), To.primitiveFieldRef(),
        p.primitiveFieldRef(),
        n.primitiveField(), rho.primitiveField(),
        momentum.primitiveField(), linearKE.primitiveField(),
        internalE.primitiveField(), iDof.primitiveField()
    );

    forAll(mesh_.boundaryMesh(), patchi)
    {
        fillGasState
        (
            U.boundaryFieldRef()[patchi], Tt.boundaryFieldRef()[patchi],
            Ti.boundaryFieldRef()[patchi], To.boundaryFieldRef()[patchi],
            p.boundaryFieldRef()[patchi],
            n.boundaryField()[patchi], rho.boundaryField()[patchi],
            momentum.boundaryField()[patchi],
            linearKE.boundaryField()[patchi],
            internalE.boundaryField()[patchi], iDof.boundaryField()[patchi]
        );

        // A wall's pressure is the normal momentum flux the gas put on it
        if (isA<wallPolyPatch>(mesh_.boundaryMesh()[patchi]))
        {
            p.boundaryFieldRef()[patchi] =
                fD.boundaryField()[patchi] & mesh_.boundary()[patchi].nf();
        }
    }

    // Cells no simulator visited (the sums of rhoN and rhoM start from a
    // tiny value, that of dsmcRhoN from zero): the formulas gave them zero
    label unvisited = 0;
    for (const scalar visits : simulators.primitiveField())
    {
        unvisited += (visits <= 0);
    }
    reduce(unvisited, sumOp<label>());

    Log << type() << " " << name() << " write:" << nl
        << "    cells without gas in the batch (fields zero) : "
        << unvisited << " of " << returnReduce(mesh_.nCells(), sumOp<label>())
        << nl
        << "    max mag(UMean), translationalT, overallT, p : "
        << gMax(mag(U.primitiveField())()) << " " << gMax(Tt.primitiveField())
        << " " << gMax(To.primitiveField()) << " " << gMax(p.primitiveField())
        << endl;

    U.write();
    Tt.write();
    Ti.write();
    To.write();
    p.write();

    return true;
}


// ************************************************************************* //
