/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

\*---------------------------------------------------------------------------*/

#include "mortonLocate.H"
#include "meshSearch.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mortonLocate::mortonLocate(const polyMesh& mesh)
:
    mesh_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

uint64_t Foam::mortonLocate::key(const point& x, const boundBox& bb)
{
    // Spread the low 21 bits of v to every third bit
    const auto spread = [](uint64_t v)
    {
        v &= 0x1fffff;
        v = (v | v << 32) & 0x1f00000000ffff;
        v = (v | v << 16) & 0x1f0000ff0000ff;
        v = (v | v << 8) & 0x100f00f00f00f00f;
        v = (v | v << 4) & 0x10c30c30c30c30c3;
        v = (v | v << 2) & 0x1249249249249249;
        return v;
    };

    const uint64_t nBins = uint64_t(1) << 21;
    uint64_t k = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const scalar span = bb.span()[d];
        const scalar f = span > 0 ? (x[d] - bb.min()[d])/span : 0;
        const uint64_t bin =
            min(uint64_t(max(f, scalar(0))*nBins), nBins - 1);
        k |= spread(bin) << d;
    }
    return k;
}


Foam::labelList Foam::mortonLocate::cells(const pointField& points) const
{
    labelList cells(points.size(), -1);
    if (points.empty())
    {
        return cells;
    }

    // Builds the tet decomposition (parallel: on every processor at once)
    const meshSearch search(mesh_);
    const boundBox localBb(mesh_.points(), false);

    const boundBox bb(points, false);
    List<uint64_t> keys(points.size());
    forAll(points, i)
    {
        keys[i] = key(points[i], bb);
    }
    labelList order(identity(points.size()));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [&keys](const label a, const label b) { return keys[a] < keys[b]; }
    );

    label seed = -1;
    bool started = false;
    for (const label i : order)
    {
        const point& x = points[i];
        label celli = -1;
        if (localBb.contains(x))
        {
            if (!started)
            {
                seed = mesh_.findNearestCell(x);
                started = true;
            }
            if (seed >= 0)
            {
                celli = search.findCell(x, seed, false);
            }
            if (celli < 0)
            {
                celli = mesh_.findCell(x);
            }
        }
        cells[i] = celli;
        seed = celli;
    }

    return cells;
}


// ************************************************************************* //
