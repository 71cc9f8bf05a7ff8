/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "phaseBalancedDecomp.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "CompactListList.H"
#include "inputChecks.H"

#include <metis.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(phaseBalancedDecomp, 0);
    addToRunTimeSelectionTable
    (
        decompositionMethod,
        phaseBalancedDecomp,
        dictionary
    );
    addToRunTimeSelectionTable
    (
        decompositionMethod,
        phaseBalancedDecomp,
        dictionaryRegion
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::phaseBalancedDecomp::partition
(
    const labelUList& xadj,
    const labelUList& adjncy,
    const List<scalarField>& weights
) const
{
    const label nCells = xadj.size() - 1;

    // The fields with a non-zero total, each scaled to integers summing to
    // about 1e7
    DynamicList<label> used;
    forAll(weights, k)
    {
        if (sum(weights[k]) > 0)
        {
            used.append(k);
        }
    }
    idx_t ncon = max(used.size(), 1);
    List<idx_t> vwgt(nCells*ncon, 1);
    forAll(used, c)
    {
        const scalarField& w = weights[used[c]];
        const scalar unit = sum(w)/1e7;
        for (label celli = 0; celli < nCells; ++celli)
        {
            vwgt[celli*ncon + c] = idx_t(w[celli]/unit + 0.5);
        }
    }

    List<idx_t> xadjM(xadj.size());
    List<idx_t> adjncyM(adjncy.size());
    forAll(xadj, i)
    {
        xadjM[i] = xadj[i];
    }
    forAll(adjncy, i)
    {
        adjncyM[i] = adjncy[i];
    }

    idx_t nVertices = nCells;
    idx_t nParts = nDomains_;
    List<real_t> ubvec(ncon, real_t(imbalance_));
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    idx_t cut = 0;
    List<idx_t> part(nCells, 0);

    if (nParts > 1)
    {
        const int status = METIS_PartGraphRecursive
        (
            &nVertices, &ncon, xadjM.data(), adjncyM.data(), vwgt.data(),
            nullptr, nullptr, &nParts, nullptr, ubvec.data(), options, &cut,
            part.data()
        );
        if (status != METIS_OK)
        {
            FatalErrorInFunction
                << "METIS_PartGraphRecursive failed (status " << status
                << ") on " << nCells << " cells, " << ncon
                << " constraints, " << nParts << " parts"
                << exit(FatalError);
        }
    }

    labelList decomp(nCells);
    forAll(decomp, celli)
    {
        decomp[celli] = part[celli];
    }

    // What each processor gets of each field
    forAll(used, c)
    {
        scalarField share(nDomains_, Zero);
        const scalarField& w = weights[used[c]];
        forAll(decomp, celli)
        {
            share[decomp[celli]] += w[celli];
        }
        Info<< "phaseBalanced: " << weightFields_[used[c]]
            << " per processor max/mean = "
            << max(share)/max(average(share), VSMALL) << endl;
    }

    return decomp;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::phaseBalancedDecomp::phaseBalancedDecomp(const dictionary& decompDict)
:
    phaseBalancedDecomp(decompDict, word::null)
{}


Foam::phaseBalancedDecomp::phaseBalancedDecomp
(
    const dictionary& decompDict,
    const word& regionName
)
:
    decompositionMethod(decompDict, regionName),
    weightFields_(),
    imbalance_(1.03)
{
    const dictionary& coeffs =
        findCoeffsDict(typeName + "Coeffs", selectionType::NULL_DICT);
    weightFields_ = coeffs.getOrDefault<wordList>
    (
        "weightFields",
        wordList
        ({
            "cellCostGasSimulators",
            "cellCostGasCollisions",
            "cellCostCoupling",
            "cellCostGrains"
        })
    );
    if (weightFields_.empty())
    {
        inputChecks::badValue
        (
            coeffs, "weightFields", "()",
            "a list of one or more volScalarField names"
        );
    }
    imbalance_ = inputChecks::getIntervalOrDefault
    (
        coeffs, "imbalance", inputChecks::interval::open(1, VGREAT), 1.03
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::phaseBalancedDecomp::decompose
(
    const polyMesh& mesh,
    const pointField&,
    const scalarField&
) const
{
    List<scalarField> weights(weightFields_.size());
    forAll(weightFields_, k)
    {
        const volScalarField field
        (
            IOobject
            (
                weightFields_[k],
                mesh.time().timeName(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            ),
            dynamic_cast<const fvMesh&>(mesh)
        );
        weights[k] = field.primitiveField();
        if (min(weights[k]) < 0)
        {
            FatalErrorInFunction
                << "Weight field " << field.objectPath()
                << " has negative values (smallest " << min(weights[k])
                << "): a cost cannot be negative" << exit(FatalError);
        }
    }

    CompactListList<label> cellCells;
    calcCellCells
    (
        mesh, identity(mesh.nCells()), mesh.nCells(), false, cellCells
    );

    return partition(cellCells.offsets(), cellCells.m(), weights);
}


Foam::labelList Foam::phaseBalancedDecomp::decompose
(
    const labelListList&,
    const pointField&,
    const scalarField&
) const
{
    FatalErrorInFunction
        << "phaseBalanced decomposes a mesh with its weight fields "
        << weightFields_ << " only" << exit(FatalError);
    return labelList();
}


// ************************************************************************* //
