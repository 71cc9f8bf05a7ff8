/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "wedgeWalk.H"
#include "boundBox.H"
#include "tetIndices.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(wedgeWalk, 0);
}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::wedgeWalk::findSides(const label celli)
{
    const cell& faceIs = mesh_.cells()[celli];
    if (faceIs.size() != 6)
    {
        return false;
    }

    const pointField& points = mesh_.points();
    const boundBox box(points, mesh_.cellPoints()[celli], false);
    const scalar tol = 1e-9*box.mag();

    // Off the axis, centred on the meridional plane
    if (box.min().y() <= tol || mag(mesh_.cellCentres()[celli].z()) > tol)
    {
        return false;
    }

    FixedList<label, 4>& sides = sides_[celli];
    FixedList<scalar, 4>& planes = planes_[celli];
    label nAbove = 0;
    label nBelow = 0;

    for (const label facei : faceIs)
    {
        const face& f = mesh_.faces()[facei];
        if (f.size() != 4 || mesh_.tetBasePtIs()[facei] < 0)
        {
            return false;
        }

        bool onSide = false;
        for (label a = 0; a < 2; ++a)
        {
            for (label end = 0; end < 2; ++end)
            {
                const scalar plane = end ? box.max()[a] : box.min()[a];
                bool onPlane = true;
                for (const label pointi : f)
                {
                    onPlane = onPlane && mag(points[pointi][a] - plane) <= tol;
                }
                if (onPlane)
                {
                    // Two faces on one side, or one face on two: not a
                    // rectangle
                    if (sides[2*a + end] >= 0 || onSide)
                    {
                        return false;
                    }
                    sides[2*a + end] = facei;
                    planes[2*a + end] = plane;
                    onSide = true;
                }
            }
        }

        // Else one of the wedge's sides, wholly on one side of z = 0
        if (!onSide)
        {
            bool above = true;
            bool below = true;
            for (const label pointi : f)
            {
                above = above && points[pointi].z() >= -tol;
                below = below && points[pointi].z() <= tol;
            }
            if (above == below)
            {
                return false;
            }
            nAbove += above;
            nBelow += below;
        }
    }

    if (nAbove != 1 || nBelow != 1)
    {
        return false;
    }
    for (label side = 0; side < 4; ++side)
    {
        if (sides[side] < 0)
        {
            return false;
        }
    }

    // The corners of every side's tets (a rectangle's face points are all
    // corners)
    for (label side = 0; side < 4; ++side)
    {
        for (label tetPti = 1; tetPti < 3; ++tetPti)
        {
            const triFace tri
            (
                tetIndices(celli, sides[side], tetPti).faceTriIs(mesh_)
            );
            forAll(tri, i)
            {
                const point& pt = points[tri[i]];
                label k = pt.z() > 0 ? 4 : 0;
                for (label a = 0; a < 2; ++a)
                {
                    if (mag(pt[a] - planes[2*a + 1]) <= tol)
                    {
                        k |= 1 << a;
                    }
                    else if (mag(pt[a] - planes[2*a]) > tol)
                    {
                        return false;
                    }
                }
                points_[celli][k] = pt;
                corners_[celli][3*(2*side + tetPti - 1) + i] = k;
            }
        }
    }

    return true;
}


bool Foam::wedgeWalk::placeOnSide
(
    particle& p,
    const label celli,
    const label side,
    const vector& d,
    const scalar along
) const
{
    const point& centre = mesh_.cellCentres()[celli];

    // Barycentric coordinates to round-off (as boxWalk)
    const scalar tol = 1e-9;

    // The side's face lies in a plane normal to axis side/2: the point
    // x = centre + d is the fraction along of the way from the centre to
    // where the ray meets it, and its weights of a triangle's corners are
    // along times that point's, found in the plane's two other axes
    const label u = (side/2 + 1) % 3;
    const label w = (side/2 + 2) % 3;

    for (label tetPti = 1; tetPti < 3; ++tetPti)
    {
        const point* base;
        const point* vertex1;
        const point* vertex2;
        triangle(celli, side, tetPti, base, vertex1, vertex2);

        const scalar e1u = (*vertex1)[u] - (*base)[u];
        const scalar e1w = (*vertex1)[w] - (*base)[w];
        const scalar e2u = (*vertex2)[u] - (*base)[u];
        const scalar e2w = (*vertex2)[w] - (*base)[w];
        const scalar cu = centre[u] - (*base)[u];
        const scalar cw = centre[w] - (*base)[w];
        const scalar det = e1u*e2w - e2u*e1w;
        const scalar y2 =
            (along*(cu*e2w - e2u*cw) + (d[u]*e2w - e2u*d[w]))/det;
        const scalar y3 =
            (along*(e1u*cw - cu*e1w) + (e1u*d[w] - d[u]*e1w))/det;
        const scalar y1 = along - y2 - y3;
        const scalar y0 = 1 - along;

        if (min(min(y0, y1), min(y2, y3)) >= -tol)
        {
            barycentric b
            (
                max(y0, scalar(0)), max(y1, scalar(0)), max(y2, scalar(0)),
                max(y3, scalar(0))
            );
            b /= b.a() + b.b() + b.c() + b.d();

            p.cell() = celli;
            p.tetFace() = sides_[celli][side];
            p.tetPt() = tetPti;

            // particle offers its coordinates read-only (see boxWalk)
            const_cast<barycentric&>(p.coordinates()) = b;
            return true;
        }
    }

    return false;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wedgeWalk::wedgeWalk(const polyMesh& mesh)
:
    MeshObject<polyMesh, GeometricMeshObject, wedgeWalk>(mesh),
    sides_(mesh.nCells()),
    planes_(mesh.nCells()),
    points_(mesh.nCells()),
    corners_(mesh.nCells()),
    nWalkable_(0)
{
    forAll(sides_, celli)
    {
        sides_[celli] = -1;
        if (findSides(celli))
        {
            ++nWalkable_;
        }
        else
        {
            sides_[celli] = -1;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::wedgeWalk::walk
(
    const point& x0,
    const vector& s,
    label& celli
) const
{
    if (!walkable(celli))
    {
        return 0;
    }

    const labelUList& owner = mesh_.faceOwner();
    const labelUList& neighbour = mesh_.faceNeighbour();

    // r(t)^2 = a t^2 + 2 b t + c
    const scalar a = sqr(s.y()) + sqr(s.z());
    const scalar b = x0.y()*s.y();
    const scalar c = sqr(x0.y());

    // Each cell entered is left at a larger t, so the walk ends
    label cur = celli;
    scalar tIn = 0;
    for (label n = 0; n < mesh_.nCells(); ++n)
    {
        const FixedList<scalar, 4>& planes = planes_[cur];

        // The first side met after tIn; none before the path's end
        scalar tOut = 1;
        label side = -1;

        if (s.x() != 0)
        {
            const label up = s.x() > 0;
            const scalar t = (planes[up] - x0.x())/s.x();
            if (t < tOut)
            {
                tOut = t;
                side = up;
            }
        }

        if (a > 0)
        {
            // Out through r1 at the larger root (the forms without
            // cancellation)
            const scalar R2 = sqr(planes[3]);
            const scalar d = Foam::sqrt(max(sqr(b) + a*(R2 - c), scalar(0)));
            const scalar t = b > 0 ? (R2 - c)/(b + d) : (d - b)/a;
            if (t < tOut)
            {
                tOut = t;
                side = 3;
            }

            // In through r0 at the smaller root, while r still decreases
            // (t < -b/a)
            if (b < -tIn*a)
            {
                const scalar r02 = sqr(planes[2]);
                const scalar d2 = sqr(b) + a*(r02 - c);
                if (d2 >= 0)
                {
                    const scalar t0 = (c - r02)/(Foam::sqrt(d2) - b);
                    if (t0 < tOut)
                    {
                        tOut = t0;
                        side = 2;
                    }
                }
            }
        }

        if (side < 0)
        {
            celli = cur;
            return 1;
        }
        tOut = max(tOut, tIn);

        const label facei = sides_[cur][side];
        label next = -1;
        if (mesh_.isInternalFace(facei))
        {
            next = owner[facei] == cur ? neighbour[facei] : owner[facei];
        }

        if (next < 0 || !walkable(next))
        {
            if (cur == celli)
            {
                return 0;
            }
            celli = cur;
            return 0.5*(tIn + tOut);
        }

        cur = next;
        tIn = tOut;
    }

    return 0;
}


Foam::point Foam::wedgeWalk::position(const particle& p) const
{
    const label celli = p.cell();
    if (!walkable(celli))
    {
        return p.position();
    }

    const FixedList<label, 4>& sides = sides_[celli];
    label side = 0;
    while (side < 4 && sides[side] != p.tetFace())
    {
        ++side;
    }
    if (side == 4)
    {
        // In a tet of a wedge side
        return p.position();
    }

    const point* base;
    const point* vertex1;
    const point* vertex2;
    triangle(celli, side, p.tetPt(), base, vertex1, vertex2);
    const barycentric& y = p.coordinates();

    return
        y.a()*mesh_.cellCentres()[celli] + y.b()*(*base) + y.c()*(*vertex1)
      + y.d()*(*vertex2);
}


bool Foam::wedgeWalk::place
(
    particle& p,
    const point& x,
    const label celli
) const
{
    const point& centre = mesh_.cellCentres()[celli];
    const vector d(x - centre);
    const FixedList<scalar, 4>& planes = planes_[celli];

    // The side the ray from the centre through x leaves the rectangle by
    // (the smallest distance/speed, compared as products): its tets
    // (centre, face triangle) hold x, the fraction speed/distance of the
    // way to its plane
    label side = -1;
    scalar distance = 1;
    scalar speed = 0;
    for (label a = 0; a < 2; ++a)
    {
        if (d[a] != 0)
        {
            const bool up = d[a] > 0;
            const scalar da =
                max
                (
                    up ? planes[2*a + 1] - centre[a] : centre[a] - planes[2*a],
                    scalar(0)
                );
            const scalar sa = mag(d[a]);
            if (side < 0 || da*speed < distance*sa)
            {
                distance = da;
                speed = sa;
                side = 2*a + up;
            }
        }
    }
    if (side < 0 || distance == 0)
    {
        // x at the centre (to the last bit): any tet holds it
        side = 0;
        speed = 0;
        distance = 1;
    }

    if (!placeOnSide(p, celli, side, d, speed/distance))
    {
        return false;
    }
    p.face() = -1;
    return true;
}


// ************************************************************************* //
