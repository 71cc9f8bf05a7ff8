/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
\*---------------------------------------------------------------------------*/

#include "gasParcel.H"
#include "wallPolyPatch.H"

// * * * * * * * * * * * * * * * * Tracking  * * * * * * * * * * * * * * * * //

template<class TrackCloudType>
bool Foam::gasParcel::move
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    // Upstream's ballistic move (reduced-dimension constraint included)
    const bool keep = DSMCParcel<particle>::move(cloud, td, trackTime);

    if (!keep)
    {
        td.countRemoved(this->onBoundaryFace() ? this->patch() : -1);
        return false;
    }

    afterMove();

    return true;
}


template<class TrackCloudType>
void Foam::gasParcel::hitWallPatch(TrackCloudType& cloud, trackingData&)
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

    // Flux-weighted sample of this simulator onto the wall face: a simulator
    // crossing a face of area A at normal speed |U.n| stands for a number
    // density 1/(|U.n| A) per unit time
    auto sampleOnWall = [&]()
    {
        const scalar Un = U_ & nHat;
        const scalar w = 1/max(mag(Un)*area, VSMALL);

        cloud.rhoNBF()[patchi][facei] += w;
        cloud.rhoMBF()[patchi][facei] += m*w;
        cloud.linearKEBF()[patchi][facei] += 0.5*m*magSqr(U_)*w;
        cloud.internalEBF()[patchi][facei] += Ei_*w;
        cloud.iDofBF()[patchi][facei] += iDof*w;
        cloud.momentumBF()[patchi][facei] += m*(U_ - Un*nHat)*w;
    };

    sampleOnWall();

    const scalar energyIn = 0.5*m*magSqr(U_) + Ei_;
    const vector momentumIn = m*U_;

    cloud.wallInteraction().correct(*this);

    sampleOnWall();

    // Energy and momentum given to the wall per unit time and area
    const scalar dtArea = cloud.pMesh().time().deltaTValue()*area;

    cloud.qBF()[patchi][facei] +=
        cloud.nParticle()*(energyIn - (0.5*m*magSqr(U_) + Ei_))/dtArea;
    cloud.fDBF()[patchi][facei] +=
        cloud.nParticle()*(momentumIn - m*U_)/dtArea;
}


// ************************************************************************* //
