/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "PatchInflow.H"
#include "gasCloud.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "coordinateTable.H"
#include "restartState.H"
#include "polyMeshTetDecomposition.H"
#include "physicoChemicalConstants.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
typename Foam::PatchInflow<CloudType>::inflowPatch
Foam::PatchInflow<CloudType>::readPatch
(
    const dictionary& dict,
    const word& name
) const
{
    using namespace inputChecks;

    const CloudType& cloud = this->owner();
    const polyBoundaryMesh& bm = cloud.mesh().boundaryMesh();

    // Inflow patches: the plain patches of the mesh
    wordList plain;
    forAll(bm, patchi)
    {
        if (isType<polyPatch>(bm[patchi]))
        {
            plain.append(bm[patchi].name());
        }
    }

    inflowPatch ip;
    ip.patchi = bm.findPatchID(name);
    if (ip.patchi < 0 || !isType<polyPatch>(bm[ip.patchi]))
    {
        notOneOf(this->coeffDict(), "patch", name, plain);
    }
    ip.inserted = 0;

    wordList valid({"composition", "n", "T", "U"});
    valid.append(coordinateTable::keywords());
    rejectUnknown(dict, valid);

    // Composition
    const dictionary& comp = dict.subDict("composition");
    const wordList& species = cloud.typeIdList();
    scalar sum = 0;
    for (const word& s : comp.toc())
    {
        const label typeId = species.find(s);
        if (typeId < 0)
        {
            notOneOf(comp, "composition", s, species);
        }
        ip.typeIds.append(typeId);
        ip.fractions.append(getNonNegativeOrDefault(comp, s, 0));
        sum += ip.fractions.last();
    }
    if (ip.typeIds.empty() || mag(sum - 1) > 1e-6)
    {
        outOfRange(comp, "composition", sum, "number fractions summing to 1");
    }

    // State at each face centre
    const label nFaces = bm[ip.patchi].size();
    if (dict.found("table") || dict.found("file"))
    {
        readProfile(dict, ip);
    }
    else
    {
        ip.n = scalarField(nFaces, getNonNegative(dict, "n"));
        ip.T = scalarField(nFaces, getPositive(dict, "T"));
        ip.U = vectorField(nFaces, getVector(dict, "U"));
    }

    ip.carry = List<scalarField>(ip.typeIds.size(), scalarField(nFaces, Zero));

    return ip;
}


template<class CloudType>
void Foam::PatchInflow<CloudType>::readProfile
(
    const dictionary& dict,
    inflowPatch& ip
) const
{
    const coordinateTable table
    (
        dict, labelList({6}), "6 (s n T Ux Uy Uz)"
    );
    table.checkNonNegative(1, "n");
    table.checkPositive(2, "T");

    const polyPatch& pp = this->owner().mesh().boundaryMesh()[ip.patchi];
    ip.n.setSize(pp.size());
    ip.T.setSize(pp.size());
    ip.U.setSize(pp.size());

    forAll(pp, facei)
    {
        const scalar s = table.coordinate(pp.faceCentres()[facei]);
        if (!table.clamp() && !table.inRange(s))
        {
            inputChecks::outOfRange
            (
                dict, "table", s,
                "the coordinate of a face centre of patch " + pp.name()
              + "; the rows cover [" + Foam::name(table.sMin()) + ", "
              + Foam::name(table.sMax()) + "] (or set outOfBounds clamp)"
            );
        }
        ip.n[facei] = table.value(s, 1);
        ip.T[facei] = table.value(s, 2);
        ip.U[facei] = table.vectorValue(s, 3);
    }

    Info<< "    PatchInflow: " << pp.name() << ", table of "
        << table.describe().c_str() << endl;
}


template<class CloudType>
Foam::scalar Foam::PatchInflow<CloudType>::sampleNormalSpeed
(
    const scalar q
)
{
    Random& rnd = this->owner().rndGen();

    // Support of the proposal: the density u exp(-(u - q)^2) is below
    // exp(-25) of its peak outside it (for q < -2.5 it falls as
    // exp(-2 u |q|), hence the upper end 15/|q|)
    const scalar lo = max(q - 5, 0);
    const scalar hi = q >= -2.5 ? max(q, 0) + 5 : 15/(-q);

    const scalar uPeak = 0.5*(q + sqrt(sqr(q) + 2));
    const scalar logPeak = log(uPeak) - sqr(uPeak - q);

    while (true)
    {
        const scalar u = lo + (hi - lo)*rnd.sample01<scalar>();
        if
        (
            u > 0
         && log(rnd.sample01<scalar>()) < log(u) - sqr(u - q) - logPeak
        )
        {
            return u;
        }
    }
}


template<class CloudType>
Foam::label Foam::PatchInflow<CloudType>::insertOnFace
(
    inflowPatch& ip,
    const label facei
)
{
    using constant::mathematical::pi;
    const scalar k = constant::physicoChemical::k.value();

    CloudType& cloud = this->owner();
    const polyMesh& mesh = cloud.mesh();
    Random& rnd = cloud.rndGen();
    const scalar dt = mesh.time().deltaTValue();

    const polyPatch& pp = mesh.boundaryMesh()[ip.patchi];
    const label meshFacei = pp.start() + facei;
    const label celli = mesh.faceOwner()[meshFacei];
    const vector& Sf = pp.faceAreas()[facei];
    const scalar A = mag(Sf);
    const vector nIn(-Sf/A);

    const scalar n = ip.n[facei];
    const scalar T = ip.T[facei];
    const vibrationalModes& vibration =
        dynamic_cast<const gasCloud&>(cloud).vibration();
    const vector& U = ip.U[facei];

    // How many of each species this step
    labelList nInsert(ip.typeIds.size(), Zero);
    forAll(ip.typeIds, si)
    {
        const scalar m = cloud.constProps(ip.typeIds[si]).mass();
        const scalar cmp = sqrt(2*k*T/m);
        const scalar q = (U & nIn)/cmp;
        const scalar flux =
            cmp*(exp(-sqr(q)) + sqrt(pi)*q*(1 + erf(q)))/(2*sqrt(pi));

        scalar& carry = ip.carry[si][facei];
        carry += ip.fractions[si]*n*A*dt*flux/cloud.nParticle();
        label whole = label(carry);
        if (rnd.sample01<scalar>() < carry - whole)
        {
            ++whole;
        }
        carry -= whole;
        nInsert[si] = whole;
    }
    if (sum(nInsert) == 0)
    {
        return 0;
    }

    // Triangles of the face (as the tracking decomposes it), by area
    const List<tetIndices> tris
    (
        polyMeshTetDecomposition::faceTetIndices(mesh, meshFacei, celli)
    );
    scalarList cumArea(tris.size());
    scalar total = 0;
    forAll(tris, ti)
    {
        total += tris[ti].faceTri(mesh).mag();
        cumArea[ti] = total;
    }

    // Tangent basis: n x (the Cartesian axis least along n)
    vector e(Zero);
    e[findMin(cmptMag(nIn))] = 1;
    const vector t1((nIn ^ e)/mag(nIn ^ e));
    const vector t2(nIn ^ t1);
    const vector Ut(U - (U & nIn)*nIn);

    forAll(ip.typeIds, si)
    {
        const label typeId = ip.typeIds[si];
        const auto& props = cloud.constProps(typeId);
        const scalar m = props.mass();
        const scalar cmp = sqrt(2*k*T/m);
        const scalar q = (U & nIn)/cmp;
        const scalar sigma = sqrt(k*T/m);

        for (label i = 0; i < nInsert[si]; ++i)
        {
            const scalar pick = total*rnd.sample01<scalar>();
            label ti = 0;
            while (ti < tris.size() - 1 && cumArea[ti] < pick)
            {
                ++ti;
            }
            const point p(tris[ti].faceTri(mesh).randomPoint(rnd));

            const vector c
            (
                Ut
              + sigma
               *(
                    rnd.GaussNormal<scalar>()*t1
                  + rnd.GaussNormal<scalar>()*t2
                )
              + sampleNormalSpeed(q)*cmp*nIn
            );

            const scalar Ei =
                cloud.equipartitionInternalEnergy
                (
                    T, props.internalDegreesOfFreedom()
                );

            cloud.addNewParcel(p, celli, c, Ei, typeId);
            if (vibration.active())
            {
                vibration.draw(typeId, T, rnd, cloud.last()->vibLevels());
            }
        }
    }

    return sum(nInsert);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PatchInflow<CloudType>::PatchInflow
(
    const dictionary& dict,
    CloudType& cloud
)
:
    InflowBoundaryModel<CloudType>(dict, cloud, typeName),
    patches_()
{
    // Every entry of the coefficients is a patch's subdictionary
    const dictionary& coeffs = this->coeffDict();
    wordList patchNames;
    for (const entry& e : coeffs)
    {
        if (e.isDict())
        {
            patchNames.append(e.keyword());
        }
    }
    inputChecks::rejectUnknown(coeffs, patchNames);

    for (const word& name : coeffs.toc())
    {
        if (coeffs.isDict(name))
        {
            patches_.append(readPatch(coeffs.subDict(name), name));
        }
    }
    if (patches_.empty())
    {
        inputChecks::outOfRange
        (
            coeffs, "patches", "none",
            "at least one patch subdictionary"
        );
    }

    // The carried fractions of a restart
    const dictionary state
    (
        restartState::read(cloud.mesh(), cloud.name(), typeName)
    );
    const polyBoundaryMesh& bm = cloud.mesh().boundaryMesh();
    for (inflowPatch& ip : patches_)
    {
        const dictionary* dictPtr = state.findDict(bm[ip.patchi].name());
        if (!dictPtr)
        {
            continue;
        }
        forAll(ip.carry, si)
        {
            restartState::get
            (
                *dictPtr, "carry" + Foam::name(si), ip.carry[si].size(),
                ip.carry[si]
            );
        }
        dictPtr->readIfPresent("inserted", ip.inserted);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PatchInflow<CloudType>::inflow()
{
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();

    for (inflowPatch& ip : patches_)
    {
        label step = 0;
        forAll(ip.n, facei)
        {
            step += insertOnFace(ip, facei);
        }
        reduce(step, sumOp<label>());
        ip.inserted += step;

        Info<< "    Simulators inserted through " << bm[ip.patchi].name()
            << " = " << step << " / " << ip.inserted << endl;
    }

    if (this->owner().mesh().time().writeTime())
    {
        dictionary state;
        for (const inflowPatch& ip : patches_)
        {
            dictionary patch;
            forAll(ip.carry, si)
            {
                restartState::put(patch, "carry" + Foam::name(si), ip.carry[si]);
            }
            patch.add("inserted", ip.inserted);
            state.add(bm[ip.patchi].name(), patch);
        }
        restartState::write
        (
            this->owner().mesh(), this->owner().name(), typeName, state
        );
    }
}


// ************************************************************************* //
