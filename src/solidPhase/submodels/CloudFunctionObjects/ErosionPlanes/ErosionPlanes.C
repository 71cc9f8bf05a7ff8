/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "ErosionPlanes.H"
#include "CollidingParcel.H"
#include "inputChecks.H"
#include "ListOps.H"

// * * * * * * * * * * * * * * * * Local Helpers * * * * * * * * * * * * * * //

namespace Foam
{
namespace erosionPlanesDetail
{

//- Grain-grain contacts of a DEM grain (its pair records)
template<class ParcelType>
label pairContacts(const CollidingParcel<ParcelType>* p)
{
    return p->collisionRecords().pairRecords().size();
}

//- Grains without resolved contacts
inline label pairContacts(const void*)
{
    return -1;
}

//- Whether the grains' contacts are resolved (a DEM cloud)
template<class ParcelType>
constexpr bool resolvesContacts(const CollidingParcel<ParcelType>*)
{
    return true;
}

constexpr bool resolvesContacts(const void*)
{
    return false;
}


//- Every processor's values, in processor order, on every processor
inline List<scalar> allOf(const List<scalar>& local)
{
    List<List<scalar>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = local;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    return ListListOps::combine<List<scalar>>(all, accessOp<List<scalar>>());
}

} // End namespace erosionPlanesDetail
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::ErosionPlanes<CloudType>::setGeometry()
{
    const vector g(this->owner().g().value());
    up_ = mag(g) > VSMALL ? -g/mag(g) : vector(0, 1, 0);

    const fvMesh& mesh = this->owner().mesh();
    const scalarField h(mesh.points() & up_);
    floor_ = returnReduce(min(h), minOp<scalar>());
    top_ = returnReduce(max(h), maxOp<scalar>());
    area_ = gSum(mesh.V())/(top_ - floor_);
}


template<class CloudType>
Foam::scalar Foam::ErosionPlanes<CloudType>::topOf(List<scalar> heights) const
{
    heights = erosionPlanesDetail::allOf(heights);
    if (heights.size() < topGrains_)
    {
        return -GREAT;
    }
    Foam::sort(heights);
    scalar sum = 0;
    for (label i = heights.size() - topGrains_; i < heights.size(); ++i)
    {
        sum += heights[i];
    }
    return sum/topGrains_ + d_/2;
}


template<class CloudType>
void Foam::ErosionPlanes<CloudType>::start()
{
    const CloudType& cloud = this->owner();

    d_ = 0;
    DynamicList<scalar> heights;
    for (const parcelType& p : cloud)
    {
        d_ = max(d_, p.d());
        heights.append(p.position() & up_);
    }
    reduce(d_, maxOp<scalar>());

    const dictionary& dict = this->coeffDict();
    bedTop0_ = topOf(heights);
    if (bedTop0_ == -GREAT)
    {
        inputChecks::outOfRange
        (
            dict, "topGrains", topGrains_,
            "[1, " + name(returnReduce(cloud.size(), sumOp<label>()))
          + "] (the grains present at startTime)"
        );
    }

    label inside = 0;
    for (const scalar h : heights)
    {
        inside += (h > floor_ + 2*d_ && h < bedTop0_ - 2*d_);
    }
    reduce(inside, sumOp<label>());
    packing0_ =
        inside*constant::mathematical::pi*pow3(d_)/6
       /max(area_*(bedTop0_ - floor_ - 4*d_), VSMALL);
    nGrains0_ = returnReduce(cloud.size(), sumOp<label>());
    drop_ = 0;
    started_ = true;

    if (anchoring() <= floor_)
    {
        inputChecks::outOfRange
        (
            dict, "anchoringDepth", anchoringDepth_,
            "[0, " + name((bedTop0_ - floor_)/d_) + ") grain diameters (the"
            " anchoring plane below the floor; bed top " + name(bedTop0_)
          + " m)"
        );
    }
    if (erosion() >= top_)
    {
        inputChecks::outOfRange
        (
            dict, "erosionHeight", erosionHeight_,
            "[0, " + name((top_ - bedTop0_)/d_) + ") grain diameters (the"
            " erosion plane above the domain; bed top " + name(bedTop0_)
          + " m)"
        );
    }

    Info<< "    erosionPlanes: bed top " << bedTop0_ << " m, packing "
        << packing0_ << ", " << nGrains0_ << " grains; anchoring plane "
        << anchoring() << " m, erosion plane " << erosion() << " m" << endl;
}


template<class CloudType>
void Foam::ErosionPlanes<CloudType>::store()
{
    this->setModelProperty("started", started_);
    this->setModelProperty("d", d_);
    this->setModelProperty("bedTop0", bedTop0_);
    this->setModelProperty("packing0", packing0_);
    this->setModelProperty("nGrains0", nGrains0_);
    this->setModelProperty("drop", drop_);
    this->setModelProperty("above", above_.toc());
    if (collisionless_ && !airborne_)
    {
        this->setModelProperty("reached", reached_.toc());
    }
}


template<class CloudType>
void Foam::ErosionPlanes<CloudType>::write()
{
    store();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ErosionPlanes<CloudType>::ErosionPlanes
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    startTime_(inputChecks::getNonNegative(this->coeffDict(), "startTime")),
    anchoringDepth_
    (
        inputChecks::getNonNegative(this->coeffDict(), "anchoringDepth")
    ),
    erosionHeight_
    (
        inputChecks::getNonNegative(this->coeffDict(), "erosionHeight")
    ),
    topGrains_
    (
        inputChecks::getLabelOrDefault
        (
            this->coeffDict(), "topGrains", 20, 1, labelMax
        )
    ),
    collisionless_
    (
        inputChecks::getBoolOrDefault
        (
            this->coeffDict(), "collisionless", false
        )
    ),
    airborne_
    (
        inputChecks::getChoiceOrDefault
        (
            this->coeffDict(), "collisionlessRule", "reached",
            {"reached", "airborne"}
        ) == "airborne"
    ),
    up_(Zero),
    floor_(0),
    top_(0),
    area_(0),
    started_(this->template getModelProperty<bool>("started", false)),
    d_(this->template getModelProperty<scalar>("d")),
    bedTop0_(this->template getModelProperty<scalar>("bedTop0")),
    packing0_(this->template getModelProperty<scalar>("packing0")),
    nGrains0_(this->template getModelProperty<label>("nGrains0")),
    drop_(this->template getModelProperty<scalar>("drop")),
    above_(),
    reached_(),
    belowFloor_(false),
    contactSteps_(0),
    contactFractions_(0),
    csv_()
{
    List<labelPair> grains;
    this->getModelProperty("above", grains);
    above_.insert(grains);
    grains.clear();
    this->getModelProperty("reached", grains);
    reached_.insert(grains);
    setGeometry();

    inputChecks::rejectUnknown
    (
        this->coeffDict(),
        {
            "type", "startTime", "anchoringDepth", "erosionHeight",
            "topGrains", "collisionless", "collisionlessRule"
        }
    );

    const word contacts
    (
        owner.subModelProperties().template getOrDefault<word>
        (
            "collisionModel", "none"
        )
    );
    if (collisionless_ && !contactModels::found(contacts))
    {
        inputChecks::badValue
        (
            this->coeffDict(), "collisionless", "true",
            "false with collisionModel " + contacts + " (only "
          + contactModels::list() + " honours it)"
        );
    }

    if (Pstream::master())
    {
        const Time& time = owner.db().time();
        const fileName dir(this->outputDir()/time.timeName());
        mkDir(dir);
        csv_.reset(new OFstream(dir/"erosionPlanes.csv"));
        csv_()
            << "time,erosionNumber,above,up,down,colliding,"
            << "fractionalCollisions,bedTop,anchoring,erosion,grains,"
            << "contactSteps,contactStepCollisions" << nl;
        csv_().precision(10);
    }
}


template<class CloudType>
Foam::ErosionPlanes<CloudType>::ErosionPlanes
(
    const ErosionPlanes<CloudType>& ep
)
:
    CloudFunctionObject<CloudType>(ep),
    startTime_(ep.startTime_),
    anchoringDepth_(ep.anchoringDepth_),
    erosionHeight_(ep.erosionHeight_),
    topGrains_(ep.topGrains_),
    collisionless_(ep.collisionless_),
    airborne_(ep.airborne_),
    up_(ep.up_),
    floor_(ep.floor_),
    top_(ep.top_),
    area_(ep.area_),
    started_(ep.started_),
    d_(ep.d_),
    bedTop0_(ep.bedTop0_),
    packing0_(ep.packing0_),
    nGrains0_(ep.nGrains0_),
    drop_(ep.drop_),
    above_(ep.above_),
    reached_(ep.reached_),
    belowFloor_(ep.belowFloor_),
    contactSteps_(ep.contactSteps_),
    contactFractions_(ep.contactFractions_),
    csv_()
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::ErosionPlanes<CloudType>::contactStep
(
    const UList<point>& x,
    const UList<bool>& touching
)
{
    if (!started_)
    {
        return;
    }
    const scalar hE = erosion();
    label above = 0;
    label colliding = 0;
    forAll(x, i)
    {
        if ((x[i] & up_) > hE)
        {
            ++above;
            colliding += touching[i];
        }
    }
    ++contactSteps_;
    contactFractions_ += above > 0 ? scalar(colliding)/above : 0;
}


template<class CloudType>
void Foam::ErosionPlanes<CloudType>::postEvolve()
{
    const CloudType& cloud = this->owner();
    const Time& time = cloud.db().time();

    if (!started_)
    {
        if (time.value() < startTime_ - 0.5*time.deltaTValue())
        {
            CloudFunctionObject<CloudType>::postEvolve();
            return;
        }
        start();
    }

    const scalar hE = erosion();

    HashSet<labelPair, labelPair::Hash<>> aboveNow;
    DynamicList<scalar> below;
    label nUp = 0;
    label nDown = 0;
    label colliding = 0;
    const bool resolved = erosionPlanesDetail::resolvesContacts
    (
        static_cast<const parcelType*>(nullptr)
    );
    for (const parcelType& p : cloud)
    {
        const scalar h = p.position() & up_;
        const labelPair id(p.origProc(), p.origId());
        if (h > hE)
        {
            aboveNow.insert(id);
            nUp += !above_.found(id);
            colliding += (erosionPlanesDetail::pairContacts(&p) > 0);
        }
        else
        {
            nDown += above_.found(id);
            below.append(h);
        }
    }

    label nAbove = aboveNow.size();
    label nGrains = cloud.size();
    reduce(nAbove, sumOp<label>());
    reduce(nUp, sumOp<label>());
    reduce(nDown, sumOp<label>());
    reduce(colliding, sumOp<label>());
    reduce(nGrains, sumOp<label>());

    // Grains gone left through an open patch, above the plane
    const label erosionNumber = nAbove + nGrains0_ - nGrains;

    const scalar bedTop = max(topOf(below), floor_);

    if (!resolved)
    {
        colliding = -1;
    }
    const scalar fraction =
        colliding < 0 ? -1 : nAbove > 0 ? scalar(colliding)/nAbove : 0;

    drop_ = max
    (
        drop_,
        erosionNumber*constant::mathematical::pi*pow3(d_)/6
       /(packing0_*area_)
    );

    if (!belowFloor_ && anchoring() <= floor_)
    {
        belowFloor_ = true;
        WarningInFunction
            << "erosionPlanes: at t = " << time.value() << " s the anchoring"
            << " plane (" << anchoring() << " m) is below the floor ("
            << floor_ << " m): the bed is eroded to the floor, the gas acts"
            << " on every grain from now on" << endl;
    }

    if (csv_.valid())
    {
        csv_()
            << time.value() << ',' << erosionNumber << ',' << nAbove << ','
            << nUp << ',' << nDown << ',' << colliding << ',' << fraction
            << ',' << bedTop << ',' << anchoring() << ',' << erosion()
            << ',' << nGrains << ',' << contactSteps_ << ','
            << (contactSteps_ > 0 ? contactFractions_/contactSteps_ : -1)
            << nl;
    }
    contactSteps_ = 0;
    contactFractions_ = 0;

    above_.transfer(aboveNow);

    if (collisionless_ && !airborne_)
    {
        for (const parcelType& p : cloud)
        {
            if (gasActs(p.position()))
            {
                reached_.insert(labelPair(p.origProc(), p.origId()));
            }
        }
    }

    CloudFunctionObject<CloudType>::postEvolve();
}


// ************************************************************************* //
