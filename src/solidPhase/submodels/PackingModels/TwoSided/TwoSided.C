/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "TwoSided.H"
#include "keywordChecks.H"
#include "inputChecks.H"
#include "solidModelChecks.H"
#include "cellFields.H"
#include "wallPolyPatch.H"
#include "syncTools.H"
#include "restartState.H"
#include "cloudAverages.H"
#include "polyMeshTetDecomposition.H"
#include "globalMeshData.H"

// * * * * * * * * * * * * * * * Input checks  * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::TwoSided<CloudType>::coeffs::coeffs
(
    const dictionary& subModels
)
:
    dict
    (
        inputChecks::knownSubDict
        (
            subModels, typeName + "Coeffs",
            {
                "particleStressModel", "e", "alphaMin", "relief", "smoothing",
                "packedCells", "predictMean"
            }
        )
    ),
    e(inputChecks::getClosed(dict, "e", 0, 1)),
    alphaMin
    (
        inputChecks::getIntervalOrDefault
        (
            dict, "alphaMin", inputChecks::interval::open(0, 1), 1e-4
        )
    ),
    relief(inputChecks::getClosedOrDefault(dict, "relief", 0, 0, 1)),
    smoothing(inputChecks::getClosedOrDefault(dict, "smoothing", 0, 0, 1)),
    packedCells(inputChecks::getBoolOrDefault(dict, "packedCells", false)),
    predictMean(inputChecks::getBoolOrDefault(dict, "predictMean", false))
{}


template<class CloudType>
void Foam::PackingModels::TwoSided<CloudType>::check
(
    const dictionary& subModels,
    const dictionary& cloudProperties
)
{
    solidChecks::particleStress
    (
        subModels.subDict(typeName + "Coeffs"), cloudProperties
    );
    coeffs{subModels};      // (read and checked, then dropped)
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::TwoSided<CloudType>::findNeighbours()
{
    const fvMesh& mesh = this->owner().mesh();
    const vectorField& C = mesh.cellCentres();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();

    // Best alignment found so far, per cell and direction
    FixedList<scalarField, vector::nComponents> bestBelow, bestAbove;
    const scalar least = aligned;
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        below_[i] = identity(mesh.nCells());
        above_[i] = identity(mesh.nCells());
        bestBelow[i].setSize(mesh.nCells(), -least);
        bestAbove[i].setSize(mesh.nCells(), least);
    }

    // Offset d from cell c to what lies across one of its faces
    auto consider = [&](const label c, const vector& d, const label across)
    {
        const vector dHat = d/max(mag(d), VSMALL);
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            if (dHat[i] < bestBelow[i][c])
            {
                bestBelow[i][c] = dHat[i];
                below_[i][c] = across;
            }
            if (dHat[i] > bestAbove[i][c])
            {
                bestAbove[i][c] = dHat[i];
                above_[i][c] = across;
            }
        }
    };

    forAll(own, facei)
    {
        consider(own[facei], C[nei[facei]] - C[own[facei]], nei[facei]);
        consider(nei[facei], C[own[facei]] - C[nei[facei]], own[facei]);
    }

    // Walls are at rest; across coupled patches (processor, cyclic) lies
    // the cell whose mean comes from swapBoundaryCellList; open
    // boundaries leave the cell its own mean
    pointField nbrC;
    syncTools::swapBoundaryCellPositions(mesh, C, nbrC);
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        const bool isWall = isA<wallPolyPatch>(pp);
        if (!isWall && !pp.coupled())
        {
            continue;
        }
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const label c = own[facei];
            if (isWall)
            {
                consider(c, mesh.faceCentres()[facei] - C[c], wall);
            }
            else
            {
                const label bFacei = facei - mesh.nInternalFaces();
                consider(c, nbrC[bFacei] - C[c], coupled(bFacei));
            }
        }
    }
}


template<class CloudType>
void Foam::PackingModels::TwoSided<CloudType>::smoothStressGradient()
{
    const fvMesh& mesh = this->owner().mesh();
    tauGradCell_.setSize(mesh.nCells());
    tauGradPoint_.setSize(mesh.nPoints());
    tauGradCell_ = Zero;
    tauGradPoint_ = Zero;
    scalarField volumeCell(mesh.nCells(), 0);
    scalarField volumePoint(mesh.nPoints(), 0);

    // grad(tau) is taken at each tetrahedron's centroid (constant within
    // it for dual averaging)
    const barycentric centroid(0.25, 0.25, 0.25, 0.25);
    for (label celli = 0; celli < mesh.nCells(); ++celli)
    {
        for
        (
            const tetIndices& tetIs
          : polyMeshTetDecomposition::cellTetIndices(mesh, celli)
        )
        {
            const scalar v = tetIs.tet(mesh).mag();
            const vector vGrad =
                v*stressAverage_->interpolateGrad(centroid, tetIs);
            tauGradCell_[celli] += vGrad;
            volumeCell[celli] += v;
            for (const label pointi : tetIs.faceTriIs(mesh))
            {
                tauGradPoint_[pointi] += vGrad;
                volumePoint[pointi] += v;
            }
        }
    }

    // Points on processor and cyclic patches: the tetrahedra of both sides
    mesh.globalData().syncPointData
    (
        tauGradPoint_, plusEqOp<vector>(), mapDistribute::transform()
    );
    mesh.globalData().syncPointData
    (
        volumePoint, plusEqOp<scalar>(), mapDistribute::transform()
    );
    tauGradCell_ /= volumeCell;
    tauGradPoint_ /= volumePoint;
}


template<class CloudType>
void Foam::PackingModels::TwoSided<CloudType>::predictMean()
{
    const fvMesh& mesh = this->owner().mesh();
    if (!started_)
    {
        uMean_ = uAverage_;
    }
    else if (!predict_)
    {
        uMean_ = &uStart_();
    }
    else
    {
        // u_m = u_s + (1 - h) f and h, per node and component
        AveragingMethod<vector>& u = uPredicted_();
        const AveragingMethod<vector>& after = *uAverage_;
        const AveragingMethod<vector>& uStart = uStart_();
        const AveragingMethod<vector>& c = correction_();
        AveragingMethod<vector>& h = held_();
        forAll(u, i)
        {
            forAll(u[i], j)
            {
                for (direction d = 0; d < vector::nComponents; ++d)
                {
                    const scalar f = after[i][j][d] - uStart[i][j][d];
                    h[i][j][d] = held(c[i][j][d], f);
                    u[i][j][d] = uStart[i][j][d] + (1 - h[i][j][d])*f;
                }
            }
        }
        uMean_ = &u;
    }
    uCell_ = uMean_->primitiveField();
    uNbr_.setSize(mesh.nBoundaryFaces());
    syncTools::swapBoundaryCellList(mesh, uCell_, uNbr_);

    // h of the cells (the sides of velocityCorrection)
    if (predict_)
    {
        heldCell_ =
            started_
          ? held_->primitiveField()
          : tmp<vectorField>::New(mesh.nCells(), vector::one);
        heldNbr_.setSize(mesh.nBoundaryFaces());
        syncTools::swapBoundaryCellList(mesh, heldCell_, heldNbr_);
    }
}


template<class CloudType>
Foam::vector Foam::PackingModels::TwoSided<CloudType>::stressGradient
(
    const barycentric& coordinates,
    const tetIndices& tetIs
) const
{
    const vector tetGrad =
        stressAverage_->interpolateGrad(coordinates, tetIs);
    if (smoothing_ == 0)
    {
        return tetGrad;
    }

    // The continuous gradient: linear in the tetrahedron between the
    // values at its cell centre and its three points
    const triFace tri(tetIs.faceTriIs(this->owner().mesh()));
    const vector smoothGrad =
        coordinates[0]*tauGradCell_[tetIs.cell()]
      + coordinates[1]*tauGradPoint_[tri[0]]
      + coordinates[2]*tauGradPoint_[tri[1]]
      + coordinates[3]*tauGradPoint_[tri[2]];

    return (1 - smoothing_)*tetGrad + smoothing_*smoothGrad;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PackingModels::TwoSided<CloudType>::TwoSided
(
    const dictionary& dict,
    CloudType& owner
)
:
    TwoSided(dict, owner, coeffs(dict))
{}


template<class CloudType>
Foam::PackingModels::TwoSided<CloudType>::TwoSided
(
    const dictionary& dict,
    CloudType& owner,
    const coeffs& c
)
:
    PackingModel<CloudType>(dict, owner, typeName),
    e_(c.e),
    alphaMin_(c.alphaMin),
    relief_(c.relief),
    smoothing_(c.smoothing),
    packedCells_(c.packedCells),
    predict_(c.predictMean),
    cellLength_(cbrt(owner.mesh().V().field())),
    volumeAverage_(nullptr),
    massAverage_(nullptr),
    uAverage_(nullptr),
    stressAverage_(nullptr),
    uStart_(nullptr),
    correction_(nullptr),
    held_(nullptr),
    uPredicted_(nullptr),
    uMean_(nullptr),
    uEnd_(nullptr),
    uCell_(),
    uNbr_(),
    started_(false),
    restart_(restartState::read(owner.mesh(), owner.name(), typeName))
{
    findNeighbours();
}


template<class CloudType>
Foam::PackingModels::TwoSided<CloudType>::TwoSided
(
    const TwoSided<CloudType>& cm
)
:
    PackingModel<CloudType>(cm),
    e_(cm.e_),
    alphaMin_(cm.alphaMin_),
    relief_(cm.relief_),
    smoothing_(cm.smoothing_),
    packedCells_(cm.packedCells_),
    predict_(cm.predict_),
    cellLength_(cm.cellLength_),
    volumeAverage_(nullptr),
    massAverage_(nullptr),
    uAverage_(nullptr),
    stressAverage_(nullptr),
    uStart_(nullptr),
    correction_(nullptr),
    held_(nullptr),
    uPredicted_(nullptr),
    uMean_(nullptr),
    uEnd_(nullptr),
    tauGradCell_(),
    tauGradPoint_(),
    below_(cm.below_),
    above_(cm.above_),
    uCell_(),
    uNbr_(),
    started_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PackingModels::TwoSided<CloudType>::cacheFields(const bool store)
{
    PackingModel<CloudType>::cacheFields(store);

    const fvMesh& mesh = this->owner().mesh();
    const word& cloudName = this->owner().name();

    if (store)
    {
        const CloudType& cloud = this->owner();
        volumeAverage_ = &cloudAverages::find<scalar>(cloud, "volumeAverage");
        massAverage_ = &cloudAverages::find<scalar>(cloud, "massAverage");
        uAverage_ = &cloudAverages::find<vector>(cloud, "uAverage");

        stressAverage_ = cloudAverages::make<scalar>(cloud, "stressAverage");
        stressAverage_() =
            this->particleStressModel_->tau
            (
                *volumeAverage_,
                cloudAverages::find<scalar>(cloud, "rhoAverage"),
                cloudAverages::find<scalar>(cloud, "uSqrAverage")
            )();
        if (smoothing_ > 0)
        {
            smoothStressGradient();
        }

        if (!uStart_.valid())
        {
            uStart_ =
                cloudAverages::make<vector>(cloud, "twoSidedStartVelocity");
            uEnd_ = cloudAverages::make<vector>(cloud, "twoSidedEndVelocity");
            if (predict_)
            {
                uPredicted_ =
                    cloudAverages::make<vector>(cloud, "twoSidedMeanVelocity");
                correction_ =
                    cloudAverages::make<vector>(cloud, "twoSidedCorrection");
                held_ = cloudAverages::make<vector>(cloud, "twoSidedHeld");
            }

            // u_s (and c) of a restart: every part of the averages (dual:
            // the cells' and the points')
            started_ = restart_.size();
            auto read = [&](const word& name, AveragingMethod<vector>& u)
            {
                forAll(u, i)
                {
                    List<vector> values;
                    const word key(name + Foam::name(i));
                    if (restartState::get(restart_, key, u[i].size(), values))
                    {
                        u[i] = values;
                    }
                    else
                    {
                        started_ = false;
                    }
                }
            };
            read("uMean", uStart_());
            if (predict_)
            {
                read("correction", correction_());
            }
            restart_.clear();
        }
        uEnd_() = Zero;
        predictMean();
        if (packedCells_)
        {
            alphaCell_ = volumeAverage_->primitiveField();
            alphaNbr_.setSize(mesh.nBoundaryFaces());
            syncTools::swapBoundaryCellList(mesh, alphaCell_, alphaNbr_);
        }

        if (mesh.time().writeTime())
        {
            writeCellField
            (
                mesh, cloudName, "alphaAverage", dimless,
                volumeAverage_->primitiveField()()
            );
        }
    }
    else
    {
        // The corrected velocities' mean (and the mean correction): u_s
        // (and c) of the next step
        uEnd_->average(*massAverage_);
        if (predict_)
        {
            AveragingMethod<vector>& c = correction_();
            forAll(c, i)
            {
                c[i] = uEnd_()[i] - (*uAverage_)[i];
            }
        }
        uStart_() = uEnd_();
        started_ = true;

        if (mesh.time().writeTime())
        {
            dictionary state;
            const AveragingMethod<vector>& u = uStart_();
            forAll(u, i)
            {
                restartState::put(state, "uMean" + Foam::name(i), u[i]);
                if (predict_)
                {
                    restartState::put
                    (
                        state, "correction" + Foam::name(i), correction_()[i]
                    );
                }
            }
            restartState::write(mesh, cloudName, typeName, state);
        }

        volumeAverage_ = nullptr;
        massAverage_ = nullptr;
        uAverage_ = nullptr;
        stressAverage_.clear();
    }
}


template<class CloudType>
Foam::vector Foam::PackingModels::TwoSided<CloudType>::velocityCorrection
(
    typename CloudType::parcelType& p,
    const scalar deltaT
) const
{
    const tetIndices tetIs(p.currentTetIndices());

    const scalar alpha =
        max(volumeAverage_->interpolate(p.coordinates(), tetIs), alphaMin_);
    const vector tauGrad = stressGradient(p.coordinates(), tetIs);
    const vector uMean = uMean_->interpolate(p.coordinates(), tetIs);

    // Stress correction (Snider's eq. 38 without drag; above alphaPacked
    // the stress counts as infinitely stiff: the limits alone apply) and
    // the slip reflected about the mean (eqs. 39-41)
    const scalar alphaPacked = this->particleStressModel_->alphaPacked();
    const vector dU = -deltaT*tauGrad/(p.rho()*alpha);
    const vector reflected = (1 + e_)*(uMean - p.U());

    // packedCells: the cell's averaged alpha counts as well as the
    // parcel's
    const scalar alphaPack =
        packedCells_ ? max(alpha, alphaCell_[p.cell()]) : alpha;
    const bool stiff = alphaPack >= alphaPacked;

    // Over-packed: the speed that takes the share relief of the cell's
    // excess out in one step
    const scalar uRelief =
        alphaPack > alphaPacked
      ? relief_*(1 - alphaPacked/alphaPack)*cellLength_[p.cell()]/deltaT
      : 0;

    vector uCorr(Zero);
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        // Pushed away from the stressed side, at most to the velocity of
        // the neighbour there (clamped at its rest: it may stop the
        // parcel, never drive it) plus the relief, or by the reflected
        // slip
        const bool up = tauGrad[i] <= 0;
        const label n = (up ? below_ : above_)[i][p.cell()];
        const scalar uSide = onSide(n, uCell_, vector::zero, uNbr_)[i];

        // packedCells: a packed cell on the stressed side stops the
        // parcel as if it were packed itself, and at rest
        const bool packedSide =
            packedCells_
         && onSide(n, alphaCell_, scalar(0), alphaNbr_) >= alphaPacked;
        const bool stiffSide = stiff || packedSide;
        const scalar rest =
            predict_ && !packedSide
          ? (1 - onSide(n, heldCell_, vector::one, heldNbr_)[i])*uMean[i]
          : 0;

        if (up)
        {
            const scalar stopped = min(uSide, rest) + uRelief - p.U()[i];
            const scalar limit = max(reflected[i], stopped);
            uCorr[i] =
                max(scalar(0), stiffSide ? limit : min(dU[i], limit));
        }
        else
        {
            const scalar stopped = max(uSide, rest) - uRelief - p.U()[i];
            const scalar limit = min(reflected[i], stopped);
            uCorr[i] =
                min(scalar(0), stiffSide ? limit : max(dU[i], limit));
        }
    }

    uEnd_->add
    (
        p.coordinates(),
        tetIs,
        p.nParticle()*p.mass()*(p.U() + uCorr)
    );

    return uCorr;
}


// ************************************************************************* //
