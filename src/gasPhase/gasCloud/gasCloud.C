/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "cellExtent.H"
#include "gasCellAverage.H"
#include "randomStreams.H"
#include "restartState.H"
#include "sortByCell.H"
#include "BinaryCollisionModel.H"
#include "InflowBoundaryModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(gasCloud, 0);
}

constexpr Foam::scalar Foam::gasCloud::fastShareLimit;
constexpr Foam::label Foam::gasCloud::sortInterval_;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::gasCloud::seedFromCase()
{
    // Without the keyword the stream is upstream's, untouched
    label seed = 0;
    if (particleProperties().readIfPresent("randomSeed", seed))
    {
        rndGen().reset(randomStreams::seed(seed, randomStreams::gas));

        Info<< "Gas random seed " << seed << " (+ processor number)" << endl;
    }
}


void Foam::gasCloud::readState()
{
    const dictionary state(restartState::read(mesh(), name(), typeName));
    restartState::get(state, "random", rndGen());

    scalarList remainder;
    if
    (
        restartState::get
        (
            state, "collisionSelectionRemainder", mesh().nCells(), remainder
        )
    )
    {
        collisionSelectionRemainder() = remainder;
    }
    subSteps_.get(state);
    bgk_.get(state);
}


void Foam::gasCloud::evolveCartesian()
{
    gasParcel::trackingData td(*this);

    // Every few steps: simulators cross a fraction of a cell per step, so
    // the order decays slowly, and the sort costs as much as a third of a
    // step (measured on freeSpacePeriodic: 14 % of the run when sorted at
    // every step)
    if (mesh().time().timeIndex() % sortInterval_ == 0)
    {
        Foam::sortByCell(*this);
    }

    // The sampled fields' patch values sum this step's wall hits
    // (gasParcel::hitWallPatch), their cell values are set by
    // sampleWeighted
    fields_.reset();

    inflowBoundary().inflow();

    Cloud<gasParcel>::move(*this, td, mesh().time().deltaTValue());

    buildOccupancy();

    collide();

    sampleWeighted();
}


void Foam::gasCloud::buildOccupancy()
{
    for (auto& members : occupancy_)
    {
        members.clear();
    }
    for (gasParcel& p : *this)
    {
        occupancy_[p.cell()].append(&p);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasCloud::gasCloud(const word& cloudName, const fvMesh& mesh)
:
    gasCloudInputCheck(cloudName, mesh),
    DSMCCloud<gasParcel>(cloudName, mesh, true),
    vibration_(readVibration()),
    account_("Simulators", mesh.boundaryMesh(), this->size()),
    randomEntryTime_
    (
        particleProperties().getOrDefault<bool>
        (
            "randomEntryTime",
            axisymmetric_.active()
        )
    ),
    boxes_(nullptr),
    wedges_(nullptr),
    vhs_(new vhsCrossSection(*this)),
    subSteps_
    (
        particleProperties(),
        mesh.nCells(),
        cartesianTracking(particleProperties()),
        vhs_->bounded()
    ),
    bgk_
    (
        particleProperties(),
        mesh.nCells(),
        cartesianTracking(particleProperties())
    ),
    writeState_(true),
    majorant_(sigmaTcRMax()),
    remainder_(collisionSelectionRemainder()),
    rnd_(rndGen()),
    fields_(*this),
    extents_(smallestCellExtents(mesh)),
    atCollisionsIndex_(-1)
{
    if (cartesianTracking(particleProperties()))
    {
        label nWalkable = 0;
        if (axisymmetric_.active())
        {
            wedges_ = &wedgeWalk::New(mesh);
            nWalkable = wedges_->nWalkable();
        }
        else
        {
            boxes_ = &boxWalk::New(mesh);
            nWalkable = boxes_->nWalkable();
        }
        occupancy_.setSize(mesh.nCells());
        buildOccupancy();
        Info<< "Gas tracking: Cartesian through "
            << returnReduce(nWalkable, sumOp<label>())
            << " of " << returnReduce(mesh.nCells(), sumOp<label>())
            << " cells, barycentric elsewhere" << nl << endl;
    }

    bgk_.setGas(*this);
    seedFromCase();
    readState();
    account_.read(mesh, cloudName, mesh.boundaryMesh());
    setWeighting();
    drawMissingLevels();
}


Foam::gasCloud::gasCloud
(
    const word& cloudName,
    const fvMesh& mesh,
    const IOdictionary& initialiseDict
)
:
    gasCloudInputCheck(cloudName, mesh, initialiseDict),
    DSMCCloud<gasParcel>(cloudName, mesh, emptied(initialiseDict)),
    vibration_(readVibration()),
    account_("Simulators", mesh.boundaryMesh(), 0),
    randomEntryTime_(false),    // the fill moves nothing
    boxes_(nullptr),
    wedges_(nullptr),
    vhs_(nullptr),              // (upstream's fill builds no models)
    subSteps_
    (
        particleProperties(),
        mesh.nCells(),
        cartesianTracking(particleProperties()),
        true                    // (the solver checks the model)
    ),
    bgk_
    (
        particleProperties(),
        mesh.nCells(),
        cartesianTracking(particleProperties())
    ),
    writeState_(false),
    majorant_(sigmaTcRMax()),
    remainder_(collisionSelectionRemainder()),
    rnd_(rndGen()),
    fields_(*this),
    extents_(smallestCellExtents(mesh)),
    atCollisionsIndex_(-1)
{
    setWeighting();
    fill(initialiseDict);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::gasCloud::~gasCloud()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasCloud::arrive(const label celli)
{
    // The k-th arrival adds (RWF_c - 1) k of upstream's per-pair
    // candidates: over N arrivals (RWF_c - 1) N (N - 1)/2 of them
    const label k = nArrived_[celli]++;

    // (the bound majorants of collisionSubSteps weigh the cell's
    // candidates by its RWF themselves)
    if (k && !subSteps_.active())
    {
        collisionSelectionRemainder()[celli] +=
            (cellWeight_[celli] - 1)*k*nParticle()
           *sigmaTcRMax()[celli]*mesh().time().deltaTValue()
           /mesh().cellVolumes()[celli];
    }
}


bool Foam::gasCloud::weighMove
(
    gasParcel& p,
    const scalar w0,
    const scalar w1,
    const bool complete
)
{
    if (!axisymmetric_.weighted())
    {
        return true;
    }

    const label nCopies = axisymmetricMode::copies(w0, w1, rndGen());

    // Clones appended to the cloud being moved: the move loop reaches a
    // clone (or not, if appended while the last member moves) with the
    // step already done, so its move does nothing, and it is in the cell
    // for this step's collisions.  (A clone made at a processor boundary
    // is moved on from there like its parent.)
    const bool kept = axisymmetricMode::keepCopies
    (
        *this, p, nCopies, account_,
        [&](const gasParcel& clone)
        {
            if (complete)
            {
                arrive(clone.cell());
            }
        }
    );
    if (!kept)
    {
        return false;
    }

    if (complete)
    {
        arrive(p.cell());
    }

    return true;
}


Foam::scalar Foam::gasCloud::collisionTemperature(const label celli)
{
    const label index = mesh().time().timeIndex();
    if (atCollisionsIndex_ != index)
    {
        if (!atCollisions_.valid())
        {
            atCollisions_.reset(new gasCellAverage(*this, 1));
        }
        atCollisions_->sample(*this);
        atCollisionsIndex_ = index;
    }
    return atCollisions_->T(celli);
}


void Foam::gasCloud::drawInflowLevels(gasParcel& p)
{
    if (p.vibLevels().size() == vibration_.nOscillators(p.typeId()))
    {
        return;     // drawn by the inflow model itself (PatchInflow)
    }

    if (inflowT_.empty())
    {
        // FreeStream's patches: every plain patch
        inflowT_.setSize(mesh().nCells(), Zero);
        scalarField nFaces(mesh().nCells(), Zero);
        forAll(mesh().boundaryMesh(), patchi)
        {
            const polyPatch& patch = mesh().boundaryMesh()[patchi];
            if (!isType<polyPatch>(patch))
            {
                continue;
            }
            const scalarField& T = boundaryT().boundaryField()[patchi];
            forAll(patch, facei)
            {
                const label celli = patch.faceCells()[facei];
                inflowT_[celli] += T[facei];
                nFaces[celli] += 1;
            }
        }
        forAll(inflowT_, celli)
        {
            if (nFaces[celli] > 0)
            {
                inflowT_[celli] /= nFaces[celli];
            }
        }
    }

    vibration_.draw
    (
        p.typeId(), inflowT_[p.cell()], rndGen(), p.vibLevels()
    );
}


Foam::tmp<Foam::scalarField> Foam::gasCloud::collisionCandidates() const
{
    tmp<scalarField> tcandidates(new scalarField(mesh().nCells(), Zero));
    if (!binaryCollision().active())
    {
        return tcandidates;
    }

    scalarField& candidates = tcandidates.ref();
    const scalarField& majorant = majorant_.primitiveField();
    const scalar dt = mesh().time().deltaTValue();
    const scalarField& V = mesh().cellVolumes();
    forAll(candidates, celli)
    {
        const scalar n = cellOccupancy()[celli].size();
        const scalar rwf = cellWeight_.size() ? cellWeight_[celli] : 1;
        candidates[celli] =
            0.5*n*max(n - 1, 0)*nParticle()*rwf*majorant[celli]*dt
           /V[celli];
    }
    return tcandidates;
}


void Foam::gasCloud::evolve()
{
    const label nBefore = this->size();

    if (axisymmetric_.weighted())
    {
        nArrived_ = 0;
    }

    // Upstream's collisions draw each cell's candidates from its
    // majorant and raise it for the next step when a candidate exceeds it
    // (the bound majorants of collisionSubSteps count their own excess)
    const scalarField drawnMax
    (
        subSteps_.active() ? scalarField() : sigmaTcRMax().primitiveField()
    );

    if (boxes_ || wedges_)
    {
        evolveCartesian();
    }
    else
    {
        DSMCCloud<gasParcel>::evolve();
    }

    forAll(drawnMax, celli)
    {
        const scalar raised = sigmaTcRMax()[celli];
        if (raised > drawnMax[celli])
        {
            majorantExcess_.n += 1;
            majorantExcess_.largest =
                max(majorantExcess_.largest, raised/drawnMax[celli]);
        }
    }

    if (axisymmetric_.weighted() && !boxes_ && !wedges_)
    {
        sampleWeighted();
    }

    sampleCells();

    if (vibration_.active())
    {
        addVibrationToFields();
    }

    // Inflow is not reported by upstream's model: it is the balance
    account_.closeStep(nBefore, this->size());
}


const Foam::gasCellAverage& Foam::gasCloud::cellState() const
{
    return now_();
}


const Foam::gasCellAverage& Foam::gasCloud::sinceWrite() const
{
    if (!sinceWrite_.valid())
    {
        FatalErrorInFunction
            << "the gas has not been sampled yet: its average since the"
            << " last write exists after the first step" << exit(FatalError);
    }
    return sinceWrite_();
}


void Foam::gasCloud::writeFields() const
{
    DSMCCloud<gasParcel>::writeFields();
    if (!writeState_)
    {
        return;
    }

    dictionary state;
    restartState::put(state, "random", rnd_);
    restartState::put(state, "collisionSelectionRemainder", remainder_);
    subSteps_.put(state);
    bgk_.put(state);
    restartState::write(mesh(), name(), typeName, state);
    account_.write(mesh(), name(), mesh().boundaryMesh());
}


// ************************************************************************* //
