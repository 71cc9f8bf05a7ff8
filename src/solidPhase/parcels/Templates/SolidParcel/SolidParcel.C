/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "SolidParcel.H"
#include "processorPolyPatch.H"
#include "wallPolyPatch.H"
#include "MPPICParcel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class ParcelType>
const Foam::boxWalk* Foam::SolidParcel<ParcelType>::boxes_ = nullptr;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::SolidParcel<ParcelType>::constantProperties::constantProperties()
:
    ParcelType::constantProperties(),
    T0_(this->dict_, 0.0),
    Cp0_(this->dict_, 0.0),
    specularFraction_(this->dict_, 0.0),
    thermalAccommodation_(this->dict_, 0.0)
{}


template<class ParcelType>
Foam::SolidParcel<ParcelType>::constantProperties::constantProperties
(
    const constantProperties& cp
)
:
    ParcelType::constantProperties(cp),
    T0_(cp.T0_),
    Cp0_(cp.Cp0_),
    specularFraction_(cp.specularFraction_),
    thermalAccommodation_(cp.thermalAccommodation_)
{}


template<class ParcelType>
Foam::SolidParcel<ParcelType>::constantProperties::constantProperties
(
    const dictionary& parentDict
)
:
    ParcelType::constantProperties(parentDict),
    T0_(this->dict_, "T0"),
    Cp0_(this->dict_, "Cp0"),
    specularFraction_(this->dict_, "specularFraction"),
    thermalAccommodation_(this->dict_, "thermalAccommodation")
{}


// * * * * * * * * * * * * * * * Layer specifics * * * * * * * * * * * * * //

namespace Foam
{
namespace solidParcelLayers
{

//- Velocity corrections of the layer below on a wedge: none but MPPIC's
template<class ParcelType>
struct wedgeCorrection
{
    template<class Parcel, class TrackingData>
    static void drop(Parcel&, const TrackingData&)
    {}
};

//- MPPIC's damping and packing corrections lose their z part (see
//  SolidParcel.H, axisymmetric mode)
template<class ParcelType>
struct wedgeCorrection<MPPICParcel<ParcelType>>
{
    template<class Parcel, class TrackingData>
    static void drop(Parcel& p, const TrackingData& td)
    {
        if
        (
            td.part() == TrackingData::tpDampingNoTrack
         || td.part() == TrackingData::tpPackingNoTrack
        )
        {
            p.UCorrect().z() = 0;
        }
    }
};


//- A step's move: upstream's, but for MPPIC's correction passes (below)
template<class ParcelType>
struct stepMove
{
    template<class Parcel, class TrackCloudType, class TrackingData>
    static bool move
    (
        Parcel& p,
        TrackCloudType& cloud,
        TrackingData& td,
        const scalar trackTime
    )
    {
        return p.ParcelType::move(cloud, td, trackTime);
    }
};

//- The correction pass of MPPIC's damping and packing moves the parcel
//  by its correction UCorrect over the rest of the step, with its own
//  velocity kept and the correction added for the fraction moved, as
//  MPPICParcel does; the move is SolidParcel::moveAlong, in one piece to
//  the next face, not upstream's move in maxCo pieces with each piece's
//  forces (which are off during the corrections); on a 3-D or wedge mesh
template<class ParcelType>
struct stepMove<MPPICParcel<ParcelType>>
{
    template<class Parcel, class TrackCloudType, class TrackingData>
    static bool move
    (
        Parcel& p,
        TrackCloudType& cloud,
        TrackingData& td,
        const scalar trackTime
    )
    {
        // Upstream's move keeps a reduced-D (empty) mesh's parcels on its
        // centre plane; a wedge's corrections have already lost their
        // normal part
        if
        (
            td.part() != TrackingData::tpCorrectTrack
         || (p.mesh().nGeometricD() < 3 && !p.onWedge())
        )
        {
            return p.MPPICParcel<ParcelType>::move(cloud, td, trackTime);
        }

        const vector U(p.U());
        const scalar f = p.stepFraction();

        p.U() = (1 - f)*p.UCorrect();
        const bool keep = p.moveAlong(cloud, td, trackTime);
        p.U() = U + (p.stepFraction() - f)*p.UCorrect();

        return keep;
    }
};

} // End namespace solidParcelLayers
} // End namespace Foam


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
bool Foam::SolidParcel<ParcelType>::hitPatch
(
    TrackCloudType& cloud,
    typename ParcelType::trackingData& td
)
{
    const bool handled = ParcelType::hitPatch(cloud, td);

    // Processor patches hand the parcel on; any other patch that ends its
    // life (escape, or a stick/none model deleting it) counts as its exit
    if (!td.keepParticle && !td.switchProcessor)
    {
        ++cloud.account().escapedStep()[this->patch()];
    }

    return handled;
}


template<class ParcelType>
template<class TrackCloudType>
bool Foam::SolidParcel<ParcelType>::move
(
    TrackCloudType& cloud,
    typename ParcelType::trackingData& td,
    const scalar trackTime
)
{
    if (!onWedge())
    {
        // The cloud's Cartesian tracking while this parcel moves
        boxes_ = cloud.boxes();
        const bool keep =
        (
            cloud.trackingDisplacement()
          ? moveAlong(cloud, td, trackTime)
          : moveStep(cloud, td, trackTime)
        );
        boxes_ = nullptr;
        return keep;
    }

    if (cloud.trackingDisplacement())
    {
        return moveAlong(cloud, td, trackTime);
    }

    // The start point for the radial re-weighting (position() costs a
    // tet's geometry: only here, not on every Cartesian move)
    const point start = this->position();

    bool keep = moveStep(cloud, td, trackTime);

    solidParcelLayers::wedgeCorrection<ParcelType>::drop(*this, td);

    if (keep)
    {
        keep = cloud.weighMove(*this, start);
        td.keepParticle = keep;
    }

    return keep;
}


template<class ParcelType>
template<class TrackCloudType>
bool Foam::SolidParcel<ParcelType>::moveStep
(
    TrackCloudType& cloud,
    typename ParcelType::trackingData& td,
    const scalar trackTime
)
{
    return solidParcelLayers::stepMove<ParcelType>::move
    (
        *this, cloud, td, trackTime
    );
}


template<class ParcelType>
template<class TrackCloudType>
bool Foam::SolidParcel<ParcelType>::moveAlong
(
    TrackCloudType& cloud,
    typename ParcelType::trackingData& td,
    const scalar trackTime
)
{
    td.keepParticle = true;
    td.switchProcessor = false;

    // The start of each piece only for cloud functions that ask for it
    const bool functions = cloud.functions().size() > 0;

    while (td.keepParticle && !td.switchProcessor && this->stepFraction() < 1)
    {
        // Over the whole step at the present velocity (a wall's rebound
        // turns it)
        const vector s(trackTime*this->U());
        const point start(functions ? this->position() : point::zero);
        const scalar f = 1 - this->stepFraction();

        if (this->active())
        {
            this->trackToFace(f*s, f);
        }
        else
        {
            // Stuck (upstream's stick interaction): the time passes
            this->stepFraction() = 1;
        }

        if
        (
            cloud.trackingDisplacement()
         && this->onBoundaryFace()
         && isA<wallPolyPatch>(this->mesh().boundaryMesh()[this->patch()])
        )
        {
            const polyPatch& pp = this->mesh().boundaryMesh()[this->patch()];
            FatalErrorInFunction
                << "The centre of a grain (d = " << this->d() << " m) reached"
                << " wall patch " << pp.name() << " at " << this->position()
                << ": its contact with the wall failed (stiffness kn too low"
                << " for the load, or the grain too fast for the sub-step)"
                << exit(FatalError);
        }

        if (functions)
        {
            if (this->active() && this->onFace())
            {
                cloud.functions().postFace(*this, td.keepParticle);
            }
            cloud.functions().postMove
            (
                *this, (this->stepFraction() - 1 + f)*trackTime, start,
                td.keepParticle
            );
        }

        if (!this->active() || !this->onFace() || !td.keepParticle)
        {
            continue;
        }

        // An internal face: the next cell; a boundary face: its patch
        this->hitFace(s, cloud, td);
    }

    return td.keepParticle;
}


template<class ParcelType>
Foam::scalar Foam::SolidParcel<ParcelType>::trackToFace
(
    const vector& displacement,
    const scalar fraction
)
{
    if (!onWedge())
    {
        scalar left;
        if (boxes_ && boxes_->trackToFace(*this, displacement, fraction, left))
        {
            return left;
        }
        return ParcelType::trackToFace(displacement, fraction);
    }

    // Along the chord in the plane z = 0 to the radius where the straight
    // 3-D path from the parcel's image there ends, turning the velocity
    // by the angle of the 3-D point reached
    const point here = this->position();
    const scalar left = ParcelType::trackToFace
    (
        axisymmetricMode::offWall
        (
            *this, axisymmetricMode::chord(here, displacement)
        ),
        fraction
    );

    axisymmetricMode::turn
    (
        this->U(),
        point(here.x(), here.y(), 0) + (1 - left)*displacement
    );

    return left;
}


template<class ParcelType>
template<class TrackCloudType>
void Foam::SolidParcel<ParcelType>::hitWedgePatch
(
    TrackCloudType& cloud,
    typename ParcelType::trackingData& td
)
{
    if (onWedge())
    {
        this->hitSymmetryPatch(cloud, td);
    }
    else
    {
        ParcelType::hitWedgePatch(cloud, td);
    }
}


// * * * * * * * * * * * * * * * * * * IO  * * * * * * * * * * * * * * * * * //

#include "SolidParcelIO.C"

// ************************************************************************* //
