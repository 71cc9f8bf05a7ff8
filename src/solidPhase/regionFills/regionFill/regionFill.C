/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

\*---------------------------------------------------------------------------*/

#include "regionFill.H"
#include "mortonLocate.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "mathematicalConstants.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(regionFill, 0);
    defineRunTimeSelectionTable(regionFill, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::regionFill::regionFill
(
    const dictionary& dict,
    const cloudSetup& setup,
    const wordList& keywords,
    const bool hasAxisymmetricForm
)
:
    dict_(checked(dict, keywords)),
    mesh_(setup.mesh),
    constProps_(setup.constProps),
    axisymmetric_(setup.axisymmetric),
    rnd_(setup.rnd),
    d_(readDiameter(dict, setup.mesh)),
    U0_(inputChecks::getVector(dict, "U0")),
    sigmaU_(inputChecks::getNonNegativeOrDefault(dict, "sigmaU", 0)),
    T0_(inputChecks::getPositiveOrDefault(dict, "T0", constProps_.T0())),
    vParticle_(pi*pow3(d_)/6),
    V_(0),
    meanWeight_(1)
{
    if (axisymmetric_.active() && !hasAxisymmetricForm)
    {
        inputChecks::badValue
        (
            dict, "type", dict.lookup("type").toString().c_str(),
            "box (x and radius ranges) with axisymmetric true"
        );
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::regionFill::readDiameter
(
    const dictionary& dict,
    const polyMesh& mesh
)
{
    // The whole mesh's diagonal (on every processor alike)
    const scalar diagonal = mag(boundBox(mesh.points(), true).span());

    return inputChecks::getOpen
    (
        dict, "d", 0, diagonal,
        "the mesh's diagonal = " + Foam::name(diagonal) + " m"
    );
}


Foam::point Foam::regionFill::uniform(const point& lo, const vector& span)
{
    return point(lo + cmptMultiply(rnd_.sample01<vector>(), span));
}


void Foam::regionFill::count
(
    const scalar alphaMax,
    const word& alphaMaxWhat,
    label& nParcels,
    scalar& W
) const
{
    using namespace inputChecks;

    const bool hasAlpha = dict_.found("alpha0");
    const bool hasW = dict_.found("nParticle");
    const bool hasN = dict_.found("nParcels");

    if (hasAlpha + hasW + hasN != 2)
    {
        badValue
        (
            dict_, "alpha0",
            hasAlpha ? "given" : "absent",
            "exactly two of alpha0, nParticle, nParcels"
        );
    }

    // (Each of the three is optional, any two given: read as optional, so
    // that the keyword record does not list them as required)
    if (hasN)
    {
        nParcels = label(getPositiveOrDefault(dict_, "nParcels", 1));
    }

    scalar alpha0 = 0;
    if (hasAlpha)
    {
        alpha0 = getIntervalOrDefault
        (
            dict_, "alpha0", interval::open(0, alphaMax, alphaMaxWhat), 0
        );
    }

    if (hasW)
    {
        W = getPositiveOrDefault(dict_, "nParticle", 1);
    }

    if (!hasN)
    {
        nParcels =
            label(std::round(alpha0*V_/(vParticle_*W*meanWeight_)));
    }
    else if (!hasW)
    {
        W = alpha0*V_/(vParticle_*nParcels*meanWeight_);
    }
}


Foam::labelList Foam::regionFill::locate(const pointField& xs) const
{
    return mortonLocate(mesh_).cells(xs);
}


const Foam::dictionary& Foam::regionFill::checked
(
    const dictionary& dict,
    const wordList& keywords
)
{
    wordList valid
    ({
        "type", "d", "U0", "sigmaU", "T0", "alpha0", "nParticle", "nParcels"
    });
    valid.append(keywords);
    inputChecks::rejectUnknown(dict, valid);

    return dict;
}


Foam::word Foam::regionFill::placedBy() const
{
    return "type";
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::regionFill::alphaLimit
(
    const dictionary& cloudProps,
    word& what
)
{
    const dictionary& models = cloudProps.subDict("subModels");
    // A packing model with a particle stress packs to its alphaPacked;
    // a cloud without (none, or DEM's without an MPPIC layer) to 1
    // (the name is checked, with its choices, by the cloud's checkInput)
    const word packing(models.getOrDefault<word>("packingModel", "none"));
    const word coeffs(packing + "Coeffs");

    if
    (
        !models.isDict(coeffs)
     || !models.subDict(coeffs).isDict("particleStressModel")
    )
    {
        what = "1 (no packing model)";
        return 1;
    }

    const scalar alphaPacked =
        models.subDict(coeffs).subDict("particleStressModel")
       .get<scalar>("alphaPacked");
    what = "alphaPacked = " + Foam::name(alphaPacked);
    return alphaPacked;
}


Foam::regionFill::drawing Foam::regionFill::drawAll
(
    const scalar alphaMax,
    const word& alphaMaxWhat
)
{
    label nParcels = 0;
    drawing parcels;
    count(alphaMax, alphaMaxWhat, nParcels, parcels.W);

    // Draw: the same sequence on every processor (each parcel's point,
    // then its velocity), whichever processor keeps the parcel
    parcels.xs.setSize(nParcels);
    parcels.Us.setSize(sigmaU_ > 0 ? nParcels : 0);
    for (label i = 0; i < nParcels; ++i)
    {
        parcels.xs[i] = draw(i);

        // Drawn for every parcel, kept or not, so that every processor
        // follows the same sequence
        if (sigmaU_ > 0)
        {
            parcels.Us[i] = U0_ + sigmaU_*rnd_.GaussNormal<vector>();
        }
    }
    parcels.cells = locate(parcels.xs);

    return parcels;
}


Foam::label Foam::regionFill::placed
(
    const drawing& parcels,
    const label nHere,
    const scalar realHere
) const
{
    const label nParcels = parcels.xs.size();
    const label nPlaced = returnReduce(nHere, sumOp<label>());
    if (nPlaced != nParcels)
    {
        inputChecks::badValue
        (
            dict_, placedBy(),
            name(nParcels - nPlaced) + " of " + name(nParcels)
          + " positions outside the mesh",
            "a region inside the mesh"
        );
    }

    Info<< "    " << dict_.dictName() << ": " << nParcels << " parcels of "
        << parcels.W << " particles";
    if (axisymmetric_.weighted())
    {
        Info<< " on the axis (mean radial weight factor " << meanWeight_
            << ")";
    }
    Info<< ", d = " << d_ << " m";
    if (sigmaU_ > 0)
    {
        Info<< ", sigmaU = " << sigmaU_ << " m/s";
    }
    if (V_ > 0)
    {
        Info<< ", alpha0 = "
            << returnReduce(realHere, sumOp<scalar>())*vParticle_/V_
            << " over " << V_ << " m^3";
    }
    Info<< nl;

    return nPlaced;
}


// ************************************************************************* //
