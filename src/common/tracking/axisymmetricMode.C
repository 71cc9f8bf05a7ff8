/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "axisymmetricMode.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::axisymmetricMode::axisymmetricMode
(
    const dictionary& dict,
    const polyMesh& mesh,
    const word& phase
)
:
    active_(inputChecks::getBoolOrDefault(dict, "axisymmetric", false)),
    radialExtent_(GREAT),
    maxWeight_(1),
    angle_(0)
{
    using namespace inputChecks;

    if (!active_)
    {
        for (const word key : {"radialExtent", "maxRadialWeight"})
        {
            if (dict.found(key))
            {
                badValue
                (
                    dict, key, dict.lookup(key).toString().c_str(),
                    "only with 'axisymmetric true;'"
                );
            }
        }
        if (wedgeMesh(mesh))
        {
            // v1912 stops a simulator at its first wedge hit and moves
            // parcels in the wedge's planes only
            badValue
            (
                dict, "axisymmetric", "false",
                "true on a wedge mesh (the " + phase + " moves through the"
                " wedge's sides only in the axisymmetric mode)"
            );
        }
        return;
    }

    radialExtent_ = getPositive(dict, "radialExtent");
    maxWeight_ = getAtLeast(dict, "maxRadialWeight", 1, 1);

    // The mesh: a wedge about the x axis, y radial, reaching the axis
    const auto notWedge = [&dict](const std::string& why)
    {
        badValue
        (
            dict, "axisymmetric", "true",
            "only on a wedge mesh about the x axis, y radial, of at most "
          + std::to_string(label(maxWedgeAngle)) + " degrees, reaching the"
            " axis; this mesh: " + why
        );
    };

    label nWedges = 0;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wedgePolyPatch>(pp))
        {
            ++nWedges;
        }
    }
    if (!nWedges)
    {
        notWedge("no wedge patch");
    }

    const pointField& pts = mesh.points();
    const scalar span = mag(mesh.bounds().span());
    const scalar tol = 1e-9*span;

    scalar minY = GREAT;
    scalar minR = GREAT;
    scalar maxR = 0;
    scalar maxHalfAngle = 0;
    for (const point& p : pts)
    {
        minY = min(minY, p.y());
        const scalar r = radius(p);
        minR = min(minR, r);
        maxR = max(maxR, r);
        if (r > tol)
        {
            maxHalfAngle = max(maxHalfAngle, atan2(mag(p.z()), p.y()));
        }
    }
    reduce(minY, minOp<scalar>());
    reduce(minR, minOp<scalar>());
    reduce(maxR, maxOp<scalar>());
    reduce(maxHalfAngle, maxOp<scalar>());

    angle_ = 2*maxHalfAngle;
    const scalar angle = radToDeg(angle_);

    if (minY < -tol)
    {
        notWedge("points at y < 0 (y must be the radial direction)");
    }
    if (angle > maxWedgeAngle*(1 + 1e-6))
    {
        notWedge("wedge angle " + std::to_string(angle) + " degrees");
    }
    if (minR > tol)
    {
        notWedge
        (
            "nearest point " + std::to_string(minR) + " m from the x axis"
        );
    }

    Info<< "Axisymmetric " << phase << ": wedge of " << angle << " degrees about the x"
        << " axis, radius " << maxR << " m; radial weight factor 1 + ("
        << maxWeight_ << " - 1) r/" << radialExtent_ << endl;

    if (maxR > radialExtent_*(1 + 1e-6))
    {
        WarningInFunction
            << "radialExtent " << radialExtent_ << " m is less than the"
            << " mesh's radius " << maxR << " m: weights there exceed "
            << "maxRadialWeight " << maxWeight_ << endl;
    }
}


// ************************************************************************* //
