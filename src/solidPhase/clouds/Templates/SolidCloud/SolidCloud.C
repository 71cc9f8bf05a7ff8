/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "SolidCloud.H"
#include "cellExtent.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "solidModelChecks.H"
#include "randomStreams.H"
#include "restartState.H"
#include "cellFields.H"
#include "PackingModel.H"
#include "DampingModel.H"
#include "IsotropyModel.H"
#include "PatchInteractionModel.H"
#include "StochasticCollisionModel.H"
#include "AveragingMethod.H"
#include "MPPICCloud.H"
#include "CollidingCloud.H"
#include "CollisionModel.H"
#include "subSteppedCollision.H"

// * * * * * * * * * * * * * * * Input checks  * * * * * * * * * * * * * * * //

namespace Foam
{
namespace solidCloudChecks
{

using namespace inputChecks;

//- The model of family Model that keyword of models selects: its name
//  among the family's choices, then its checker (solidModelChecks), if it
//  has one
template<class Model>
void checkSelected
(
    const dictionary& models,
    const word& keyword,
    const dictionary& props
)
{
    solidModelChecks::call(modelName<Model>(models, keyword), models, props);
}


//- The models of the MPPIC layer
template<class CloudType>
void checkLayer(const dictionary& props, const MPPICCloud<CloudType>*)
{
    typedef MPPICCloud<CloudType> mppicType;

    modelName<AveragingMethod<scalar>>
    (
        props.subDict("solution"), "averagingMethod"
    );

    const dictionary& models = props.subDict("subModels");
    checkSelected<PackingModel<mppicType>>(models, "packingModel", props);
    checkSelected<DampingModel<mppicType>>(models, "dampingModel", props);
    checkSelected<IsotropyModel<mppicType>>(models, "isotropyModel", props);
}


//- The models of the colliding (DEM) layer; 3-D only
template<class CloudType>
void checkLayer(const dictionary& props, const CollidingCloud<CloudType>*)
{
    typedef CollidingCloud<CloudType> collidingType;

    if (getBoolOrDefault(props, "axisymmetric", false))
    {
        badValue
        (
            props, "axisymmetric", "true",
            "false (DEM grains are resolved in 3-D)"
        );
    }

    checkSelected<CollisionModel<collidingType>>
    (
        props.subDict("subModels"), "collisionModel", props
    );
}

} // End namespace solidCloudChecks
} // End namespace Foam


template<class CloudType>
const Foam::word& Foam::SolidCloud<CloudType>::checkInput
(
    const word& cloudName,
    const fvMesh& mesh
)
{
    using namespace solidCloudChecks;

    typedef typename CloudType::kinematicCloudType kinematicType;

    const IOdictionary props(readCloudProperties(cloudName, mesh));

    const dictionary& constProps = props.subDict("constantProperties");
    getPositive(constProps, "rho0");
    getPositive(constProps, "T0");
    getPositive(constProps, "Cp0");
    getClosed(constProps, "specularFraction", 0, 1);
    getClosed(constProps, "thermalAccommodation", 0, 1);

    boxWalk::selected
    (
        props, getBoolOrDefault(props, "axisymmetric", false)
    );

    const dictionary& models = props.subDict("subModels");

    // The layer below ours: MPPIC or colliding
    checkLayer(props, static_cast<const CloudType*>(nullptr));

    checkSelected<StochasticCollisionModel<kinematicType>>
    (
        models, "stochasticCollisionModel", props
    );

    checkSelected<PatchInteractionModel<kinematicType>>
    (
        models, "patchInteractionModel", props
    );

    // Misspellings where upstream's readers and ours share a dictionary
    // (upstream takes further keywords there: only near-misses stop)
    rejectMisspelt
    (
        props,
        {
            "solution", "constantProperties", "subModels", "cloudFunctions",
            "axisymmetric", "radialExtent", "maxRadialWeight", "cloudType",
            "randomSeed", "reportInterval", "tracking"
        }
    );
    rejectMisspelt
    (
        constProps,
        {
            "rho0", "T0", "Cp0", "specularFraction", "thermalAccommodation",
            "parcelTypeId", "rhoMin", "minParcelMass", "youngsModulus",
            "poissonsRatio", "alphaMax"
        }
    );
    rejectMisspelt
    (
        models,
        {
            "particleForces", "injectionModels", "dispersionModel",
            "patchInteractionModel", "stochasticCollisionModel",
            "surfaceFilmModel", "packingModel", "dampingModel",
            "isotropyModel", "interphaseCoupling", "collisionModel"
        },
        false
    );

    return cloudName;
}


// * * * * * * * * * * * * * * * Layer reports * * * * * * * * * * * * * * //

namespace Foam
{
namespace solidCloudLayers
{

//- The MPPIC layer adds nothing to the step's report
template<class CloudType>
void info(const MPPICCloud<CloudType>&)
{}


//- The colliding layer's contacts at the end of the step (a contact's
//  record lives while the grains overlap; a grain-grain contact is
//  recorded by both grains, across processors too)
template<class CloudType>
void info(const CollidingCloud<CloudType>& cloud)
{
    label grains = 0;
    label pairRecords = 0;
    label walls = 0;
    for (const auto& p : cloud)
    {
        const label nPair = p.collisionRecords().pairRecords().size();
        const label nWall = p.collisionRecords().wallRecords().size();
        pairRecords += nPair;
        walls += nWall;
        grains += (nPair + nWall > 0);
    }
    reduce(grains, sumOp<label>());
    reduce(pairRecords, sumOp<label>());
    reduce(walls, sumOp<label>());

    Info<< "    Grains in contact               = " << grains << nl
        << "    Grain-grain contacts            = " << pairRecords/2 << nl
        << "    Grain-wall contacts             = " << walls << nl;
}


//- The MPPIC layer moves as upstream's
template<class CloudType, class TrackCloudType>
bool ownMotion
(
    MPPICCloud<CloudType>&,
    TrackCloudType&,
    typename TrackCloudType::parcelType::trackingData&
)
{
    return false;
}


//- The colliding layer moves as upstream's, but with a sub-stepped
//  collision model (cartesianContacts), whose step it is
template<class CloudType, class TrackCloudType>
bool ownMotion
(
    CollidingCloud<CloudType>& layer,
    TrackCloudType& cloud,
    typename TrackCloudType::parcelType::trackingData& td
)
{
    auto* stepped =
        dynamic_cast<subSteppedCollision<TrackCloudType>*>(&layer.collision());
    if (!stepped)
    {
        return false;
    }

    stepped->advance(cloud, td);
    return true;
}

} // End namespace solidCloudLayers
} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::SolidCloud<CloudType>::nInjected() const
{
    label n = 0;
    for (const auto& injector : this->injectors())
    {
        n += injector.parcelsAddedTotal();
    }
    return n;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SolidCloud<CloudType>::SolidCloud
(
    const word& cloudName,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& mu,
    const dimensionedVector& g,
    bool readFields
)
:
    CloudType(checkInput(cloudName, rho.mesh()), rho, U, mu, g, readFields),
    account_("Parcels", rho.mesh().boundaryMesh(), this->size()),
    axisymmetric_(this->particleProperties(), rho.mesh(), cloudName),
    rnd_
    (
        randomStreams::seed
        (
            inputChecks::getLabelOrDefault
            (
                this->particleProperties(), "randomSeed", 0, 0, 2000
            ),
            randomStreams::grainWeighting
        )
    ),
    reportInterval_
    (
        inputChecks::getLabelOrDefault
        (
            this->particleProperties(), "reportInterval", 1, 1, labelMax
        )
    ),
    boxes_(nullptr)
{
    const dictionary& dict = this->particleProperties();
    const polyMesh& mesh = rho.mesh();

    const dictionary& injection =
        dict.subDict("subModels").subDict("injectionModels");
    if (axisymmetric_.active() && injection.size())
    {
        inputChecks::badValue
        (
            injection, "injectionModels", injection.toc(),
            "none with axisymmetric true (fill the cloud with"
            " rarefiedMultiphaseInitialise)"
        );
    }

    if (axisymmetric_.weighted())
    {
        account_.countWeighting();
    }

    if (boxWalk::selected(dict, axisymmetric_.active()))
    {
        boxes_ = &boxWalk::New(mesh);
        Info<< "Grain tracking (" << cloudName << "): Cartesian through "
            << returnReduce(boxes_->nWalkable(), sumOp<label>())
            << " of " << returnReduce(mesh.nCells(), sumOp<label>())
            << " cells, barycentric elsewhere" << nl << endl;
    }

    // The cloud's own stream (the isotropy models' draws), seeded from
    // randomSeed as every stream of the project, not from the processor
    // number alone (KinematicCloud's seed)
    this->rndGen().reset
    (
        randomStreams::seed
        (
            inputChecks::getLabelOrDefault(dict, "randomSeed", 0, 0, 2000),
            randomStreams::grainCloud
        )
    );

    const dictionary state(restartState::read(mesh, cloudName, "solidCloud"));
    restartState::get(state, "random", this->rndGen());
    restartState::get(state, "weighting", rnd_);
    account_.read(mesh, cloudName, mesh.boundaryMesh());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
bool Foam::SolidCloud<CloudType>::weighMove
(
    parcelType& p,
    const point& start
)
{
    if (!axisymmetric_.weighted())
    {
        return true;
    }

    const scalar w0 = axisymmetric_.weightAt(start);
    const scalar w1 = axisymmetric_.weightAt(p.position());

    // The parcel now carries the weight of where it is; RWF(r0)/RWF(r1)
    // copies of it on average keep the real grains of the one that moved
    p.nParticle() *= w1/w0;
    // Clones are appended to the cloud being moved with the step done, so
    // the move loop leaves them where they are
    return axisymmetricMode::keepCopies
    (
        *this, p, axisymmetricMode::copies(w0, w1, rnd_), account_,
        [](const parcelType&) {}
    );
}


template<class CloudType>
void Foam::SolidCloud<CloudType>::setParcelThermoProperties
(
    parcelType& parcel,
    const scalar lagrangianDt
)
{
    CloudType::setParcelThermoProperties(parcel, lagrangianDt);
    parcel.setMaterial(this->constProps());
}


template<class CloudType>
void Foam::SolidCloud<CloudType>::evolve()
{
    if (!this->solution().canEvolve())
    {
        return;
    }

    nBefore_ = this->size();
    nInjectedBefore_ = nInjected();

    // As upstream's MPPIC and colliding evolve, but tracking with this cloud so that the
    // parcels reach the account and the material properties
    typename parcelType::trackingData td(*this);
    this->solve(*this, td);
}


template<class CloudType>
template<class TrackCloudType>
void Foam::SolidCloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    if (!solidCloudLayers::ownMotion(*this, cloud, td))
    {
        CloudType::motion(cloud, td);
    }

    // Upstream's injection counters are already summed over processors
    const label nIn =
        Pstream::master() ? nInjected() - nInjectedBefore_ : 0;

    account_.closeStep(nBefore_, this->size(), nIn);

    // The step criterion: the travel of each parcel over its cell
    if (cellExtent_.size() != this->mesh().nCells())
    {
        cellExtent_ = smallestCellExtents(this->mesh());
    }
    const scalar dt = this->db().time().deltaTValue();
    for (const parcelType& p : *this)
    {
        const scalar travel = mag(p.U())*dt/cellExtent_[p.cell()];
        travelMax_ = max(travelMax_, travel);
        nTravelAbove_ += (travel > 1);
    }
}


template<class CloudType>
void Foam::SolidCloud<CloudType>::info()
{
    const Time& time = this->db().time();
    if (time.timeIndex() % reportInterval_ && !time.writeTime())
    {
        return;
    }

    CloudType::info();
    solidCloudLayers::info(*this);
    account_.info(this->mesh().boundaryMesh());

    if (time.writeTime())
    {
        reduce(travelMax_, maxOp<scalar>());
        reduce(nTravelAbove_, sumOp<scalar>());
        Info<< "    Grain step criterion since the last write: travel"
            << " |U| deltaT/h largest " << travelMax_ << " ("
            << nTravelAbove_ << " parcel-steps above 1)" << endl;
        if (nTravelAbove_ > 0)
        {
            WarningInFunction
                << "deltaT " << time.deltaTValue() << " s is too long for"
                << " the grains of " << this->name() << ": parcels crossed"
                << " up to " << travelMax_ << " times their cell in a step ("
                << nTravelAbove_ << " parcel-steps): shorten deltaT in"
                << " system/controlDict" << endl;
        }
        travelMax_ = 0;
        nTravelAbove_ = 0;
    }
}


template<class CloudType>
void Foam::SolidCloud<CloudType>::writeFields() const
{
    CloudType::writeFields();

    const label nCells = this->mesh().nCells();
    scalarField nParcels(nCells, Zero);
    scalarField mass(nCells, Zero);
    vectorField momentum(nCells, Zero);
    scalarField heat(nCells, Zero);

    for (const parcelType& p : *this)
    {
        const label celli = p.cell();
        const scalar m = p.nParticle()*p.mass();
        nParcels[celli] += 1;
        mass[celli] += m;
        momentum[celli] += m*p.U();
        heat[celli] += m*p.T();
    }

    const scalarField massOrOne(max(mass, VSMALL));

    const fvMesh& mesh = this->mesh();
    const word& cloud = this->name();
    writeCellField(mesh, cloud, "alpha", dimless, this->theta()().primitiveField());
    writeCellField(mesh, cloud, "nParcels", dimless, nParcels);
    writeCellField(mesh, cloud, "U", dimVelocity, vectorField(momentum/massOrOne));
    writeCellField(mesh, cloud, "T", dimTemperature, scalarField(heat/massOrOne));

    dictionary state;
    restartState::put(state, "random", this->rndGen());
    restartState::put(state, "weighting", rnd_);
    restartState::write(mesh, cloud, "solidCloud", state);
    account_.write(mesh, cloud, mesh.boundaryMesh());
}


// ************************************************************************* //
