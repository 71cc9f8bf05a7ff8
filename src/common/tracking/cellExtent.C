/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "cellExtent.H"
#include "boundBox.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::smallestCellExtents(const polyMesh& mesh)
{
    const pointField& points = mesh.points();
    const Vector<label>& geometric = mesh.geometricD();

    tmp<scalarField> th(new scalarField(mesh.nCells(), GREAT));
    scalarField& h = th.ref();
    forAll(h, celli)
    {
        const boundBox box(points, mesh.cellPoints()[celli], false);
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (geometric[d] == 1)
            {
                h[celli] = min(h[celli], box.span()[d]);
            }
        }
    }
    return th;
}


// ************************************************************************* //
