/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasParcel.H"
#include "gasCloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

constexpr unsigned char Foam::gasParcel::noOctant;

namespace Foam
{
    defineTypeNameAndDebug(gasParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<gasParcel>, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasParcel::trackingData::trackingData(DSMCCloud<gasParcel>& cloud)
:
    particle::trackingData(cloud),
    nEscaped_(owner(cloud).account().escapedStep()),
    nLost_(owner(cloud).account().lostStep()),
    nCrossed_(owner(cloud).account().crossedStep()),
    owner_(owner(cloud)),
    axisymmetric_
    (
        owner_.axisymmetric().active() ? &owner_.axisymmetric() : nullptr
    ),
    randomEntry_(owner_.randomEntryTime()),
    vibrating_(owner_.vibration().active()),
    boxes_(owner_.boxes()),
    wedges_(owner_.wedges())
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::gasCloud& Foam::gasParcel::trackingData::owner
(
    DSMCCloud<gasParcel>& cloud
)
{
    gasCloud* gc = dynamic_cast<gasCloud*>(&cloud);

    if (!gc)
    {
        FatalErrorInFunction
            << "gasParcel tracked by a cloud that is not a gasCloud"
            << abort(FatalError);
    }

    return *gc;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::gasParcel::walk
(
    const trackingData& td,
    const vector& s,
    const scalar f
)
{
    const point x0(td.boxes()->position(*this));
    label celli = this->cell();
    const scalar t = td.boxes()->walk(x0, s, celli);

    if (t > 0 && td.boxes()->place(*this, x0 + t*s, celli))
    {
        if (t < 1)
        {
            this->stepFraction() += t*f;
        }
        else
        {
            this->stepFraction() = 1;
            const vector r(x0 + s - this->mesh().cellCentres()[celli]);
            octant_ = pos0(r.x()) + 2*pos0(r.y()) + 4*pos0(r.z());
        }
        return t;
    }

    return 0;
}


Foam::scalar Foam::gasParcel::walkWedge
(
    const trackingData& td,
    const vector& path,
    const scalar f,
    point& here
)
{
    const point start(here.x(), here.y(), 0);
    label celli = this->cell();
    const scalar t = td.wedges()->walk(start, path, celli);
    if (t == 0)
    {
        return 0;
    }

    const point end(start + t*path);
    const point inPlane(end.x(), axisymmetricMode::radius(end), 0);
    if (!td.wedges()->place(*this, inPlane, celli))
    {
        return 0;
    }
    here = inPlane;

    if (t < 1)
    {
        this->stepFraction() += t*f;
    }
    else
    {
        // The quadrant of its cell in the plane (the collisions' sub-cell)
        this->stepFraction() = 1;
        const point& centre = this->mesh().cellCentres()[celli];
        octant_ =
            pos0(inPlane.x() - centre.x()) + 2*pos0(inPlane.y() - centre.y());
    }
    axisymmetricMode::turn(U_, end);
    return t;
}


Foam::scalar Foam::gasParcel::trackingData::vibrationalEnergy
(
    const gasParcel& p
) const
{
    return owner_.vibration().energy(p.typeId(), p.vibLevels());
}


void Foam::gasParcel::trackingData::drawInflowLevels(gasParcel& p)
{
    owner_.drawInflowLevels(p);
}


void Foam::gasParcel::trackingData::drawWallLevels
(
    gasParcel& p,
    const label patchi,
    const label facei
)
{
    owner_.vibration().draw
    (
        p.typeId(),
        owner_.boundaryT().boundaryField()[patchi][facei],
        owner_.rndGen(),
        p.vibLevels()
    );
}


bool Foam::gasParcel::trackingData::weighMove
(
    gasParcel& p,
    const scalar w0,
    const scalar w1,
    const bool complete
)
{
    return owner_.weighMove(p, w0, w1, complete);
}


// ************************************************************************* //
