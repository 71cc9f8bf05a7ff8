/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "SolidParcel.H"
#include "processorPolyPatch.H"
#include "wallPolyPatch.H"
#include "MPPICParcel.H"

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


//- A step's move: upstream's, or with Cartesian tracking trackMove in
//  place of KinematicParcel::move (the tracking part of the colliding
//  layer, or the kinematic layer's whole move)
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
        if (td.boxes() && td.part() == TrackingData::tpLinearTrack)
        {
            return p.trackMove(cloud, td, trackTime, true);
        }
        return p.ParcelType::move(cloud, td, trackTime);
    }
};

//- MPPIC's layer.  The correction pass of the damping and packing moves
//  the parcel by its correction UCorrect over the rest of the step, with
//  its own velocity kept and the correction added for the fraction
//  moved, as MPPICParcel does; on a 3-D or wedge mesh the move is
//  SolidParcel::trackMove without forces, in one piece to the next face,
//  not upstream's move in maxCo pieces with each piece's forces (which
//  are off during the corrections).  With Cartesian tracking trackMove
//  with forces stands for KinematicParcel::move in the tracking pass and
//  in a reduced-D mesh's correction pass (which keeps the parcel's age,
//  as upstream's).
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
        const bool along =
            p.mesh().nGeometricD() == 3 || p.onWedge();

        if (td.part() == TrackingData::tpLinearTrack && td.boxes())
        {
            return p.trackMove(cloud, td, trackTime, true);
        }
        if
        (
            td.part() != TrackingData::tpCorrectTrack
         || (!along && !td.boxes())
        )
        {
            return p.MPPICParcel<ParcelType>::move(cloud, td, trackTime);
        }

        const vector U(p.U());
        const scalar f = p.stepFraction();
        const scalar age = p.age();

        p.U() = (1 - f)*p.UCorrect();
        const bool keep = p.trackMove(cloud, td, trackTime, !along);
        p.U() = U + (p.stepFraction() - f)*p.UCorrect();
        if (!along)
        {
            p.age() = age;
        }

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
    trackingData& td,
    const scalar trackTime
)
{
    if (td.alongDisplacement())
    {
        return trackMove(cloud, td, trackTime, false);
    }
    if (!onWedge())
    {
        return moveStep(cloud, td, trackTime);
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
    trackingData& td,
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
bool Foam::SolidParcel<ParcelType>::trackMove
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime,
    const bool forces
)
{
    td.keepParticle = true;
    td.switchProcessor = false;

    const cloudSolution& solution = cloud.solution();
    const scalarField& lengths = cloud.cellLengthScale();
    const scalar maxCo = solution.maxCo();

    // The start of each piece only for cloud functions that ask for it
    const bool functions = cloud.functions().size() > 0;

    while (td.keepParticle && !td.switchProcessor && this->stepFraction() < 1)
    {
        // The rest of the step at the present velocity (a wall's rebound
        // turns it)
        const point start(functions ? walkedPosition(td) : point::zero);
        const scalar f0 = this->stepFraction();
        const vector s(trackTime*this->U());
        scalar f = 1 - f0;

        // With forces at most maxCo of the step and of the cell's length
        // scale; on a reduced-D mesh back to its centre plane
        vector d(Zero);
        if (forces)
        {
            const scalar l = lengths[this->cell()];
            d = this->deviationFromMeshCentre();
            f = min(f, maxCo);
            f = min(f, maxCo*l/max(SMALL*l, mag(s)));
        }

        if (this->active())
        {
            trackPiece(td, f*s - d, f);
        }
        else
        {
            // Stuck (upstream's stick interaction): the time passes
            this->stepFraction() = forces ? f0 + f : 1;
        }

        if
        (
            td.alongDisplacement()
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

        // The forces and heat over the time tracked (none over a vanishing
        // piece)
        const scalar dt = (this->stepFraction() - f0)*trackTime;
        if (forces)
        {
            if (dt > ROOTVSMALL)
            {
                this->setCellValues(cloud, td);
                this->calcDispersion(cloud, td, dt);
                if (solution.cellValueSourceCorrection())
                {
                    this->cellValueSourceCorrection(cloud, td, dt);
                }
                this->calc(cloud, td, dt);
            }
            this->age() += dt;
        }

        if (functions)
        {
            if (this->active() && this->onFace())
            {
                cloud.functions().postFace(*this, td.keepParticle);
            }
            cloud.functions().postMove(*this, dt, start, td.keepParticle);
        }

        // An internal face: the next cell; a boundary face: its patch
        if (this->active() && this->onFace() && td.keepParticle)
        {
            this->hitFace(s, cloud, td);
        }
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
