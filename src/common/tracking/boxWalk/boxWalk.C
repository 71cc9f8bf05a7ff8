/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "boxWalk.H"
#include "boundBox.H"
#include "tetIndices.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(boxWalk, 0);
}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::boxWalk::findSides(const label celli)
{
    const cell& faceIs = mesh_.cells()[celli];
    if (faceIs.size() != 6)
    {
        return false;
    }

    const pointField& points = mesh_.points();
    const boundBox box(points, mesh_.cellPoints()[celli], false);
    const scalar tol = 1e-9*box.mag();

    FixedList<label, 6>& sides = sides_[celli];
    FixedList<scalar, 6>& planes = planes_[celli];

    for (const label facei : faceIs)
    {
        const face& f = mesh_.faces()[facei];
        if (f.size() != 4 || mesh_.tetBasePtIs()[facei] < 0)
        {
            return false;
        }

        for (label a = 0; a < 3; ++a)
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
                    // Two faces on one side: not a box
                    if (sides[2*a + end] >= 0)
                    {
                        return false;
                    }
                    sides[2*a + end] = facei;
                    planes[2*a + end] = plane;
                }
            }
        }
    }

    for (label side = 0; side < 6; ++side)
    {
        if (sides[side] < 0)
        {
            return false;
        }
    }

    // The corners of every tet's triangle (a box's face points are all
    // corners)
    for (label side = 0; side < 6; ++side)
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
                label k = 0;
                for (label a = 0; a < 3; ++a)
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
                corners_[celli][3*(2*side + tetPti - 1) + i] = k;
            }
        }
    }

    return true;
}


inline Foam::label Foam::boxWalk::sideAhead
(
    const FixedList<scalar, 6>& planes,
    const point& origin,
    const vector& direction,
    scalar& distance,
    scalar& speed
)
{
    // The smallest distance/speed, compared as products
    label side = -1;
    distance = 1;
    speed = 0;
    for (label a = 0; a < 3; ++a)
    {
        if (direction[a] != 0)
        {
            const bool up = direction[a] > 0;
            const scalar da =
                max
                (
                    up ? planes[2*a + 1] - origin[a] : origin[a] - planes[2*a],
                    scalar(0)
                );
            const scalar sa = mag(direction[a]);
            if (da*speed < distance*sa || side < 0)
            {
                distance = da;
                speed = sa;
                side = 2*a + up;
            }
        }
    }
    return side;
}


inline void Foam::boxWalk::triangle
(
    const label celli,
    const label side,
    const label tetPti,
    point& base,
    point& vertex1,
    point& vertex2
) const
{
    const label first = 3*(2*side + tetPti - 1);
    const FixedList<unsigned char, 36>& k = corners_[celli];
    base = corner(celli, k[first]);
    vertex1 = corner(celli, k[first + 1]);
    vertex2 = corner(celli, k[first + 2]);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::boxWalk::boxWalk(const polyMesh& mesh)
:
    MeshObject<polyMesh, GeometricMeshObject, boxWalk>(mesh),
    sides_(mesh.nCells()),
    planes_(mesh.nCells()),
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

bool Foam::boxWalk::selected(const dictionary& dict, const bool axisymmetric)
{
    return
        inputChecks::getChoiceOrDefault
        (
            dict, "tracking", axisymmetric ? "barycentric" : "cartesian",
            axisymmetric
          ? wordList({"barycentric"})
          : wordList({"cartesian", "barycentric"})
        )
     == "cartesian";
}


Foam::scalar Foam::boxWalk::walk
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

    // Each cell entered is left at a larger t, so no cell is met twice
    label c = celli;
    scalar tIn = 0;
    for (label n = 0; n < mesh_.nCells(); ++n)
    {
        scalar distance, speed;
        const label side = sideAhead(planes_[c], x0, s, distance, speed);

        if (side < 0 || distance >= speed)
        {
            celli = c;
            return 1;
        }
        const scalar tOut = max(distance/speed, tIn);

        const label facei = sides_[c][side];
        label next = -1;
        if (mesh_.isInternalFace(facei))
        {
            next = owner[facei] == c ? neighbour[facei] : owner[facei];
        }

        if (next < 0 || !walkable(next))
        {
            if (c == celli)
            {
                return 0;
            }
            celli = c;
            return 0.5*(tIn + tOut);
        }

        c = next;
        tIn = tOut;
    }

    return 0;
}


Foam::point Foam::boxWalk::position(const particle& p) const
{
    const label celli = p.cell();
    if (!walkable(celli))
    {
        return p.position();
    }

    const label side = tetSide(p, celli);
    if (side < 0)
    {
        return p.position();
    }

    point base, vertex1, vertex2;
    triangle(celli, side, p.tetPt(), base, vertex1, vertex2);
    const barycentric& y = p.coordinates();

    return
        y.a()*mesh_.cellCentres()[celli] + y.b()*base + y.c()*vertex1
      + y.d()*vertex2;
}


bool Foam::boxWalk::moveInTet
(
    particle& p,
    const label celli,
    const label side,
    const vector& s
) const
{
    const point& centre = mesh_.cellCentres()[celli];
    point base, vertex1, vertex2;
    triangle(celli, side, p.tetPt(), base, vertex1, vertex2);

    // x - centre = Y (base - centre) + y2 (v1 - base) + y3 (v2 - base),
    // Y = y1 + y2 + y3: along the side's axis a only Y counts (the
    // triangle lies in the side's plane), in its plane's axes u, w a 2 x 2
    // solve with the triangle's edges
    const label a = side/2;
    const label u = (a + 1) % 3;
    const label w = (a + 2) % 3;
    const scalar dY = s[a]/(base[a] - centre[a]);
    const scalar ru = s[u] - dY*(base[u] - centre[u]);
    const scalar rw = s[w] - dY*(base[w] - centre[w]);
    const scalar e1u = vertex1[u] - base[u], e1w = vertex1[w] - base[w];
    const scalar e2u = vertex2[u] - base[u], e2w = vertex2[w] - base[w];
    const scalar det = e1u*e2w - e2u*e1w;
    const scalar dy2 = (ru*e2w - e2u*rw)/det;
    const scalar dy3 = (e1u*rw - ru*e1w)/det;

    const barycentric& y = p.coordinates();
    const barycentric moved
    (
        y.a() - dY, y.b() + dY - dy2 - dy3, y.c() + dy2, y.d() + dy3
    );
    if (min(min(moved.a(), moved.b()), min(moved.c(), moved.d())) < 0)
    {
        return false;
    }

    // (see placeOnSide)
    const_cast<barycentric&>(p.coordinates()) = moved;
    p.face() = -1;
    return true;
}


bool Foam::boxWalk::placeOnSide
(
    particle& p,
    const label celli,
    const label side,
    const vector& d,
    const scalar along
) const
{
    const point& centre = mesh_.cellCentres()[celli];

    // Barycentric coordinates to round-off: a point on a tet's face may
    // come out a few ulps outside it
    const scalar tol = 1e-9;

    // The point x = centre + d is the fraction along of the way from the
    // centre to q = centre + d/along on the side's plane: its weights of
    // the triangle's corners are along times q's, found in the plane's
    // two axes u, w
    const label u = (side/2 + 1) % 3;
    const label w = (side/2 + 2) % 3;

    for (label tetPti = 1; tetPti < 3; ++tetPti)
    {
        point base, vertex1, vertex2;
        triangle(celli, side, tetPti, base, vertex1, vertex2);

        const scalar e1u = vertex1[u] - base[u], e1w = vertex1[w] - base[w];
        const scalar e2u = vertex2[u] - base[u], e2w = vertex2[w] - base[w];
        const scalar cu = centre[u] - base[u], cw = centre[w] - base[w];
        const scalar det = e1u*e2w - e2u*e1w;
        const scalar y2 =
            (along*(cu*e2w - e2u*cw) + (d[u]*e2w - e2u*d[w]))/det;
        const scalar y3 =
            (along*(e1u*cw - cu*e1w) + (e1u*d[w] - d[u]*e1w))/det;
        const scalar y1 = along - y2 - y3;
        // On the side itself the centre's weight is zero exactly, as
        // upstream's tracking leaves a particle on a face
        const scalar y0 = along == 1 ? 0 : 1 - along;

        if (min(min(y0, y1), min(y2, y3)) >= -tol)
        {
            barycentric b
            (
                y0, max(y1, scalar(0)), max(y2, scalar(0)), max(y3, scalar(0))
            );
            b /= b.a() + b.b() + b.c() + b.d();

            p.cell() = celli;
            p.tetFace() = sides_[celli][side];
            p.tetPt() = tetPti;

            // particle offers its coordinates read-only, having no setter
            // other than a tracking search (relocate) from the cell centre;
            // the particle itself is not const
            const_cast<barycentric&>(p.coordinates()) = b;
            return true;
        }
    }

    return false;
}


bool Foam::boxWalk::place
(
    particle& p,
    const point& x,
    const label celli
) const
{
    const point& centre = mesh_.cellCentres()[celli];
    const vector d(x - centre);

    // The side the ray from the centre through x leaves by: its tets
    // (centre, face triangle) hold x, the fraction speed/distance of the
    // way to its plane
    scalar distance, speed;
    label side = sideAhead(planes_[celli], centre, d, distance, speed);
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


bool Foam::boxWalk::trackToFace
(
    particle& p,
    const vector& displacement,
    const scalar fraction,
    scalar& left
) const
{
    const label celli = p.cell();
    if (!walkable(celli))
    {
        return false;
    }
    const label tetSidei = tetSide(p, celli);
    if (tetSidei < 0)
    {
        return false;
    }

    // Most pieces of a path end in the tet they start in
    if (moveInTet(p, celli, tetSidei, displacement))
    {
        p.stepFraction() += fraction;
        left = 0;
        return true;
    }

    const point x0(position(p));
    scalar distance, speed;
    const label side =
        sideAhead(planes_[celli], x0, displacement, distance, speed);

    // The path ends in the cell (or does not move)
    if (side < 0 || distance >= speed)
    {
        if (!place(p, x0 + displacement, celli))
        {
            return false;
        }
        p.stepFraction() += fraction;
        left = 0;
        return true;
    }

    // Onto the side's face, at the point the path meets its plane
    // (placeOnSide reads the two coordinates in the side's plane only)
    const scalar t = distance/speed;
    if
    (
        !placeOnSide
        (
            p, celli, side, x0 + t*displacement - mesh_.cellCentres()[celli], 1
        )
    )
    {
        return false;
    }
    p.face() = sides_[celli][side];
    p.stepFraction() += t*fraction;
    left = 1 - t;
    return true;
}


// ************************************************************************* //
