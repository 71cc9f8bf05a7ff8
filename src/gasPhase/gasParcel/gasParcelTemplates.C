/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasParcel.H"
#include "wallPolyPatch.H"
#include "meshTools.H"

// * * * * * * * * * * * * * * * * Tracking  * * * * * * * * * * * * * * * * //

template<class TrackCloudType>
void Foam::gasParcel::enter(TrackCloudType& cloud, trackingData& td)
{
    if (entered_)
    {
        if (td.randomEntry())
        {
            this->stepFraction() =
                cloud.rndGen().template sample01<scalar>();
        }
        entered_ = false;

        if (td.vibrating())
        {
            td.drawInflowLevels(*this);
        }
    }
}


template<class TrackCloudType>
bool Foam::gasParcel::move
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    // Known again only where the Cartesian move ends the step
    octant_ = noOctant;

    if (td.axisymmetric())
    {
        return moveAxisymmetric(cloud, td, trackTime);
    }

    enter(cloud, td);

    // Upstream's ballistic move, or the Cartesian move (boxWalk) wherever
    // the path lies in box cells, handing each crossing of a boundary face
    // (and each cell that is not a box) to upstream's tracking
    bool keep = true;
    if (td.boxes())
    {
        td.switchProcessor = false;
        td.keepParticle = true;

        const polyMesh& mesh = cloud.pMesh();

        // Upstream's path over the rest of the step (reduced-dimension
        // constraint and drift off the mid-plane included)
        auto path = [&](const scalar f)
        {
            vector Utracking(U_);
            meshTools::constrainDirection(mesh, mesh.solutionD(), Utracking);
            return f*trackTime*Utracking - this->deviationFromMeshCentre();
        };

        while
        (
            td.keepParticle && !td.switchProcessor
         && this->stepFraction() < 1
        )
        {
            const scalar f = 1 - this->stepFraction();
            if (walk(td, path(f), f) < 1)
            {
                const scalar rest = 1 - this->stepFraction();
                this->trackToAndHitFace(path(rest), rest, cloud, td);
            }
        }
        keep = td.keepParticle;
    }
    else
    {
        keep = DSMCParcel<particle>::move(cloud, td, trackTime);
    }

    if (!keep)
    {
        td.countRemoved(this->onBoundaryFace() ? this->patch() : -1);
        return false;
    }

    return true;
}


template<class TrackCloudType>
bool Foam::gasParcel::moveAxisymmetric
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    td.switchProcessor = false;
    td.keepParticle = true;

    // Already at the end of the step (a later sweep of a parallel move)
    if (this->stepFraction() >= 1)
    {
        return true;
    }

    // Where it is (kept up to date by each piece of the move)
    point here = td.position(*this);
    const scalar w0 = entered_ ? 1 : td.weightAt(here);

    // Just inserted: by default it entered at a uniformly random time
    // within the step (upstream moves it over the whole step, which leaves
    // the layer next to a free-stream boundary short of the last half
    // step's inflow)
    enter(cloud, td);

    // Pieces in a row that ended on a boundary face without moving (by
    // less than stallFraction of the rest of the step): a simulator
    // reflected at a wall and at once back at it.  A diffuse wall re-emits
    // it, as at a true second hit an instant later; after a stall (a
    // specular wall grazed, or a fast azimuthal motion along the outer
    // wall, whose chord leads out through it whichever the sign of v_r,
    // both of which would reflect it there for ever) it slides along the
    // wall (axisymmetricMode::offWall).  In a corner of two specular walls
    // the slide along one stalls at the other, and the two would take
    // turns for ever: after maxStalls stalls in a row it stays where it
    // is for the rest of the step
    static constexpr scalar stallFraction = 1e-9;
    static constexpr label maxStalls = 4;
    label nStalled = 0;

    while (td.keepParticle && !td.switchProcessor && this->stepFraction() < 1)
    {
        scalar f = 1 - this->stepFraction();

        // The Cartesian move through the cells that are rectangles in the
        // plane, as far as they go; upstream's tracking of the chord from
        // where it stops
        if (td.wedges() && !nStalled)
        {
            if (walkWedge(td, f*trackTime*U_, f, here) == 1)
            {
                break;
            }
            f = 1 - this->stepFraction();
        }

        // Straight 3-D path over the rest of the step from the simulator's
        // image in the plane z = 0 (it is off the plane only when just
        // placed), and the chord in that plane to where the path ends
        const point start(here.x(), here.y(), 0);
        const vector path = f*trackTime*U_;
        vector chord(axisymmetricMode::chord(here, path));
        if (nStalled)
        {
            chord = axisymmetricMode::offWall(*this, chord);
        }

        this->trackToFace(chord, f);
        nStalled =
            this->stepFraction() - (1 - f) <= stallFraction*f
         && this->onBoundaryFace()
          ? nStalled + 1 : 0;

        const scalar done = (this->stepFraction() - (1 - f))/f;
        axisymmetricMode::turn(U_, start + done*path);

        this->hitFace(chord, cloud, td);
        here = td.position(*this);

        if (nStalled == maxStalls)
        {
            this->stepFraction() = 1;
        }
    }

    if (!td.keepParticle)
    {
        td.countRemoved(this->onBoundaryFace() ? this->patch() : -1);
        return false;
    }

    td.keepParticle =
        td.weighMove(*this, w0, td.weightAt(here), !td.switchProcessor);

    return td.keepParticle;
}


template<class TrackCloudType>
void Foam::gasParcel::hitWallPatch(TrackCloudType& cloud, trackingData& td)
{
    const label patchi = this->patch();
    const wallPolyPatch& wpp =
        refCast<const wallPolyPatch>(this->mesh().boundaryMesh()[patchi]);
    const label facei = wpp.whichFace(this->face());

    const vector& Sf = wpp.faceAreas()[facei];
    const scalar area = mag(Sf);
    const vector nHat = Sf/area;

    const auto& props = cloud.constProps(typeId_);
    const scalar m = props.mass();
    const scalar iDof = props.internalDegreesOfFreedom();

    // Radial weight factor of the simulator where it hits (1 unless
    // axisymmetric)
    const scalar rwf = td.weightAt(this->position());

    // Flux-weighted sample of this simulator onto the wall face: a simulator
    // crossing a face of area A at normal speed |U.n| stands for a number
    // density 1/(|U.n| A) per unit time
    auto sampleOnWall = [&]()
    {
        const scalar Un = U_ & nHat;
        const scalar w = rwf/max(mag(Un)*area, VSMALL);

        cloud.rhoNBF()[patchi][facei] += w;
        cloud.rhoMBF()[patchi][facei] += m*w;
        cloud.linearKEBF()[patchi][facei] += 0.5*m*magSqr(U_)*w;
        cloud.internalEBF()[patchi][facei] += Ei_*w;
        cloud.iDofBF()[patchi][facei] += iDof*w;
        cloud.momentumBF()[patchi][facei] += m*(U_ - Un*nHat)*w;
    };

    sampleOnWall();

    // Vibrational energy (zero without modes)
    auto vibrational = [&]()
    {
        return td.vibrating() ? td.vibrationalEnergy(*this) : 0;
    };

    const scalar energyIn = 0.5*m*magSqr(U_) + Ei_ + vibrational();
    const vector momentumIn = m*U_;
    const vector specular = U_ - 2*(U_ & nHat)*nHat;

    cloud.wallInteraction().correct(*this);

    // A diffuse reflection accommodates the vibration to the wall
    if (td.vibrating() && magSqr(U_ - specular) > SMALL*magSqr(specular))
    {
        td.drawWallLevels(*this, patchi, facei);
    }

    sampleOnWall();

    // Energy and momentum given to the wall per unit time and area
    const scalar dtArea = cloud.pMesh().time().deltaTValue()*area;

    cloud.qBF()[patchi][facei] +=
        rwf*cloud.nParticle()
       *(energyIn - (0.5*m*magSqr(U_) + Ei_ + vibrational()))/dtArea;
    cloud.fDBF()[patchi][facei] +=
        rwf*cloud.nParticle()*(momentumIn - m*U_)/dtArea;
}


template<class TrackCloudType>
void Foam::gasParcel::hitWedgePatch(TrackCloudType& cloud, trackingData& td)
{
    if (td.axisymmetric())
    {
        this->hitSymmetryPatch(cloud, td);
    }
    else
    {
        particle::hitWedgePatch(cloud, td);
    }
}


// ************************************************************************* //
