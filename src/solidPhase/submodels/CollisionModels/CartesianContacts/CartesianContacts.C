/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "CartesianContacts.H"
#include "inputChecks.H"
#include "solidModelChecks.H"
#include "cyclicPolyPatch.H"
#include "wallPolyPatch.H"
#include "processorPolyPatch.H"

#include <cmath>
#include <cstdint>
#include <unordered_map>

// * * * * * * * * * * * * * * * * Local Helpers * * * * * * * * * * * * * * //

namespace Foam
{
namespace cartesianContactsDetail
{

//- A grain's lasting name (its origin processor and number)
inline std::int64_t grainKey(const label origProc, const label origId)
{
    return (std::int64_t(origProc) << 32) | std::int64_t(origId);
}

//- A pair's key in a list of N grains, i < j
inline std::int64_t pairKey(const label i, const label j, const label n)
{
    return std::int64_t(i)*n + j;
}

} // End namespace cartesianContactsDetail
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::CartesianContacts<CloudType>::readGeometry()
{
    // The keyword that selected this model
    const dictionary& models = this->dict();

    const polyBoundaryMesh& pbm = this->owner().mesh().boundaryMesh();
    const boundBox& bb = this->owner().mesh().bounds();
    const scalar tol = 1e-9*mag(bb.span());

    if (Pstream::parRun())
    {
        inputChecks::badValue
        (
            models, "collisionModel", this->type(),
            "pairCollision in a decomposed run (cartesianContacts builds no"
            " contacts across processor patches)"
        );
    }

    period_ = Zero;
    DynamicList<wallPlane> walls;

    for (const polyPatch& pp : pbm)
    {
        if (isA<cyclicPolyPatch>(pp))
        {
            const cyclicPolyPatch& cpp = refCast<const cyclicPolyPatch>(pp);
            const vectorField& sep = cpp.separation();
            const vector s(sep.size() == 1 ? sep[0] : vector::zero);
            direction axis = 0;
            for (direction a = 1; a < vector::nComponents; ++a)
            {
                if (mag(s[a]) > mag(s[axis]))
                {
                    axis = a;
                }
            }

            if
            (
                !cpp.separated() || sep.size() != 1
             || mag(s) < SMALL || mag(mag(s) - mag(s[axis])) > tol
            )
            {
                inputChecks::badValue
                (
                    models, "collisionModel", this->type(),
                    "pairCollision for cyclic patch " + pp.name()
                  + " (cartesianContacts needs cyclics that are"
                    " translations along x, y or z)"
                );
            }
            period_[axis] = mag(s);
        }
        else if (isA<wallPolyPatch>(pp) && pp.size())
        {
            const vectorField n(pp.faceNormals());
            const vectorField& c = pp.faceCentres();
            bool plane = true;
            forAll(pp, facei)
            {
                plane = plane
                    && mag(n[facei] - n[0]) < 1e-8
                    && mag((c[facei] - c[0]) & n[0]) < tol;
            }
            if (!plane)
            {
                inputChecks::badValue
                (
                    models, "collisionModel", this->type(),
                    "pairCollision for wall patch " + pp.name()
                  + " (cartesianContacts needs plane walls)"
                );
            }
            // Face normals point out of the domain
            walls.append(wallPlane{c[0], -n[0]});
        }
    }

    walls_.transfer(walls);
}


template<class CloudType>
void Foam::CartesianContacts<CloudType>::gather(CloudType& cloud)
{
    using namespace cartesianContactsDetail;

    parcels_.clear();
    x_.clear();
    v_.clear();
    L_.clear();
    f_.clear();
    tau_.clear();
    m_.clear();
    R_.clear();
    I_.clear();
    off_.clear();
    touching_.clear();
    dMax_ = 0;
    mMin_ = GREAT;

    // Berger's box: erosionPlanes says which grains are out
    // (collisionless) and counts the colliding grains per sub-step
    planes_ = contactObserver<parcelType>::find(cloud.functions());

    for (parcelType& p : cloud)
    {
        parcels_.append(&p);
        x_.append(p.position());
        v_.append(p.U());
        L_.append(p.angularMomentum());
        f_.append(p.f());
        tau_.append(p.torque());
        m_.append(p.mass());
        R_.append(p.d()/2);
        I_.append(p.momentOfInertia());
        off_.append(planes_ && planes_->contactsOff(p));
        dMax_ = max(dMax_, p.d());
        mMin_ = min(mMin_, p.mass());
    }

    const label n = parcels_.size();
    const label nWalls = walls_.size();
    touching_.setSize(n);

    std::unordered_map<std::int64_t, label> index(2*n);
    forAll(parcels_, i)
    {
        index[grainKey(parcels_[i]->origProc(), parcels_[i]->origId())] = i;
    }

    // The springs of the contacts the last step ended with
    pairs_.clear();
    wallSprings_.setSize(n*nWalls);
    wallSprings_ = vector::zero;

    forAll(parcels_, i)
    {
        const auto& records = parcels_[i]->collisionRecords();
        for (const auto& r : records.pairRecords())
        {
            auto found = index.find
            (
                grainKey(r.origProcOfOther(), r.origIdOfOther())
            );
            if (found != index.end() && found->second > i)
            {
                pairs_.append
                (
                    pairEntry{i, found->second, Zero, r.collisionData()}
                );
            }
        }
        for (const auto& r : records.wallRecords())
        {
            const vector dir(r.pRel()/(mag(r.pRel()) + VSMALL));
            forAll(walls_, w)
            {
                if ((dir & walls_[w].normal) < -0.99)
                {
                    wallSprings_[i*nWalls + w] = r.collisionData();
                }
            }
        }
    }
}


template<class CloudType>
void Foam::CartesianContacts<CloudType>::buildPairs()
{
    using namespace cartesianContactsDetail;

    const label n = x_.size();

    // The springs in contact carry over
    std::unordered_map<std::int64_t, vector> springs(2*pairs_.size() + 1);
    for (const pairEntry& e : pairs_)
    {
        if (magSqr(e.spring) > 0)
        {
            springs[pairKey(e.i, e.j, n)] = e.spring;
        }
    }
    pairs_.clear();
    xBuilt_ = x_;

    if (n < 2)
    {
        return;
    }

    const scalar reach = skin_*dMax_;
    const scalar cutoff = dMax_ + reach;

    const boundBox& bb = this->owner().mesh().bounds();
    const vector span(bb.span());
    labelVector nBins;
    vector width;
    for (direction a = 0; a < vector::nComponents; ++a)
    {
        nBins[a] = max(label(1), label(span[a]/cutoff));
        width[a] = span[a]/nBins[a];
        if (period_[a] > 0 && nBins[a] < 3)
        {
            FatalErrorInFunction
                << "cartesianContacts: the periodic length " << span[a]
                << " m along " << vector::componentNames[a]
                << " holds fewer than 3 bins of the contact reach "
                << cutoff << " m (d_max (1 + neighbourSkin)); use"
                << " pairCollision for this box"
                << exit(FatalError);
        }
    }

    auto binOf = [&](const point& x, const direction a)
    {
        label c = label(std::floor((x[a] - bb.min()[a])/width[a]));
        if (period_[a] > 0)
        {
            c %= nBins[a];
            return c < 0 ? c + nBins[a] : c;
        }
        return min(max(c, label(0)), nBins[a] - 1);
    };

    // Linked lists of the grains in each bin
    const label nTotal = nBins.x()*nBins.y()*nBins.z();
    labelList head(nTotal, -1);
    labelList next(n, -1);
    labelList binX(n), binY(n), binZ(n);
    for (label i = n - 1; i >= 0; --i)
    {
        binX[i] = binOf(x_[i], 0);
        binY[i] = binOf(x_[i], 1);
        binZ[i] = binOf(x_[i], 2);
        const label b = (binZ[i]*nBins.y() + binY[i])*nBins.x() + binX[i];
        next[i] = head[b];
        head[b] = i;
    }

    auto wrap = [&](label c, const direction a)
    {
        if (period_[a] > 0)
        {
            return (c + nBins[a]) % nBins[a];
        }
        return (c < 0 || c >= nBins[a]) ? label(-1) : c;
    };

    for (label i = 0; i < n; ++i)
    {
        for (label dz = -1; dz <= 1; ++dz)
        {
            const label cz = wrap(binZ[i] + dz, 2);
            if (cz < 0 || (nBins.z() == 1 && dz != 0)) continue;
            for (label dy = -1; dy <= 1; ++dy)
            {
                const label cy = wrap(binY[i] + dy, 1);
                if (cy < 0 || (nBins.y() == 1 && dy != 0)) continue;
                for (label dx = -1; dx <= 1; ++dx)
                {
                    const label cx = wrap(binX[i] + dx, 0);
                    if (cx < 0 || (nBins.x() == 1 && dx != 0)) continue;

                    const label b = (cz*nBins.y() + cy)*nBins.x() + cx;
                    for (label j = head[b]; j >= 0; j = next[j])
                    {
                        if (j <= i || (off_[i] && off_[j])) continue;

                        const vector d(x_[i] - x_[j]);
                        vector r(d);
                        for (direction a = 0; a < 3; ++a)
                        {
                            if (period_[a] > 0)
                            {
                                r[a] -= period_[a]*std::round(r[a]/period_[a]);
                            }
                        }
                        if (magSqr(r) < sqr(R_[i] + R_[j] + reach))
                        {
                            auto found = springs.find(pairKey(i, j, n));
                            pairs_.append
                            (
                                pairEntry
                                {
                                    i, j, d - r,
                                    found == springs.end()
                                  ? vector::zero : found->second
                                }
                            );
                        }
                    }
                }
            }
        }
    }
}


template<class CloudType>
void Foam::CartesianContacts<CloudType>::contactForces(const scalar dt)
{
    f_ = vector::zero;
    tau_ = vector::zero;
    touching_ = false;

    for (pairEntry& e : pairs_)
    {
        const label i = e.i;
        const label j = e.j;
        const vector r(x_[i] - x_[j] - e.shift);
        const scalar Rsum = R_[i] + R_[j];
        const scalar r2 = magSqr(r);

        if (r2 >= sqr(Rsum))
        {
            // Apart: the contact and its spring end
            e.spring = Zero;
            continue;
        }

        touching_[i] = true;
        touching_[j] = true;

        const scalar rMag = std::sqrt(r2);
        const vector n(r/(rMag + VSMALL));
        const vector omegaI(L_[i]/I_[i]);
        const vector omegaJ(L_[j]/I_[j]);
        const vector v
        (
            v_[i] - v_[j] - ((R_[i]*omegaI + R_[j]*omegaJ) ^ n)
        );

        const linearContact::forces fc = grainGrain_.contact
        (
            Rsum - rMag, min(R_[i], R_[j]), n, v,
            m_[i]*m_[j]/(m_[i] + m_[j]), dt, e.spring
        );

        const vector F(fc.normal + fc.tangential);
        f_[i] += F;
        f_[j] -= F;
        tau_[i] += (-R_[i]*n) ^ fc.tangential;
        tau_[j] += (R_[j]*n) ^ (-fc.tangential);
    }

    const label nWalls = walls_.size();
    forAll(x_, i)
    {
        forAll(walls_, w)
        {
            const wallPlane& wp = walls_[w];
            const scalar dist = (x_[i] - wp.origin) & wp.normal;
            vector& spring = wallSprings_[i*nWalls + w];

            if (dist >= R_[i])
            {
                spring = Zero;
                continue;
            }

            const vector& n = wp.normal;
            const vector v(v_[i] + ((L_[i]/I_[i]) ^ (-R_[i]*n)));

            const linearContact::forces fc = grainWall_.contact
            (
                R_[i] - dist, R_[i], n, v, m_[i], dt, spring
            );

            f_[i] += fc.normal + fc.tangential;
            tau_[i] += (-R_[i]*n) ^ fc.tangential;
        }
    }
}


template<class CloudType>
void Foam::CartesianContacts<CloudType>::scatterSprings()
{
    const label nWalls = walls_.size();

    for (const pairEntry& e : pairs_)
    {
        if (magSqr(x_[e.i] - x_[e.j] - e.shift) < sqr(R_[e.i] + R_[e.j]))
        {
            parcelType& pI = *parcels_[e.i];
            parcelType& pJ = *parcels_[e.j];
            pI.collisionRecords().matchPairRecord
            (
                pJ.origProc(), pJ.origId()
            ).collisionData() = e.spring;
            pJ.collisionRecords().matchPairRecord
            (
                pI.origProc(), pI.origId()
            ).collisionData() = -e.spring;
        }
    }

    forAll(parcels_, i)
    {
        forAll(walls_, w)
        {
            const scalar dist = (x_[i] - walls_[w].origin) & walls_[w].normal;
            if (dist < R_[i])
            {
                parcels_[i]->collisionRecords().matchWallRecord
                (
                    -dist*walls_[w].normal, R_[i]
                ).collisionData() = wallSprings_[i*nWalls + w];
            }
        }

        // Records not matched above (contacts that ended) go
        parcels_[i]->collisionRecords().update();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::CartesianContacts<CloudType>::CartesianContacts
(
    const dictionary& dict,
    CloudType& owner
)
:
    CollisionModel<CloudType>(dict, owner, typeName),
    grainGrain_(this->coeffDict().subDict("grainGrain")),
    grainWall_(this->coeffDict().subDict("grainWall")),
    stepsPerContact_
    (
        inputChecks::getAtLeast(this->coeffDict(), "stepsPerContact", 5, 50)
    ),
    skin_
    (
        inputChecks::getIntervalOrDefault
        (
            this->coeffDict(), "neighbourSkin",
            inputChecks::interval::above(0, 1), 0.2
        )
    ),
    gravity_(false),
    period_(Zero),
    walls_(),
    nSubSteps_(0),
    dMax_(0),
    mMin_(GREAT),
    planes_(nullptr)
{
    const dictionary& coeffs = this->coeffDict();

    inputChecks::rejectUnknown
    (
        coeffs,
        {"grainGrain", "grainWall", "stepsPerContact", "neighbourSkin"}
    );
    if (stepsPerContact_ < 20)
    {
        WarningInFunction
            << "stepsPerContact = " << stepsPerContact_ << " in "
            << coeffs.name() << ": contacts are resolved in fewer than 20"
            << " sub-steps; 50 is recommended" << endl;
    }

    const dictionary& forces = owner.forces().dict();
    for (const word& force : forces.toc())
    {
        if (!bodyForces::found(force))
        {
            inputChecks::badValue
            (
                forces, force, force,
                bodyForces::list(", ")
              + " only with cartesianContacts (the gas acts through"
                " interphaseCoupling)"
            );
        }
        gravity_ = true;
    }

    readGeometry();
}


template<class CloudType>
Foam::CartesianContacts<CloudType>::CartesianContacts
(
    const CartesianContacts<CloudType>& cm
)
:
    CollisionModel<CloudType>(cm),
    grainGrain_(cm.grainGrain_),
    grainWall_(cm.grainWall_),
    stepsPerContact_(cm.stepsPerContact_),
    skin_(cm.skin_),
    gravity_(cm.gravity_),
    period_(cm.period_),
    walls_(cm.walls_),
    nSubSteps_(cm.nSubSteps_),
    dMax_(cm.dMax_),
    mMin_(cm.mMin_),
    planes_(nullptr)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::CartesianContacts<CloudType>::collide()
{
    FatalErrorInFunction
        << "cartesianContacts moves the grains itself (SolidCloud::motion);"
        << " it is not a collide() of upstream's colliding cloud"
        << abort(FatalError);
}


template<class CloudType>
void Foam::CartesianContacts<CloudType>::advance
(
    SolidCloud<CloudType>& cloud,
    typename parcelType::trackingData& td
)
{
    const scalar deltaT = cloud.db().time().deltaTValue();

    gather(cloud);
    const label n = parcels_.size();

    // Sub-steps from the lightest contact (a pair of the lightest grains,
    // or the lightest grain on a wall)
    if (n > 0)
    {
        const scalar tc = min
        (
            grainGrain_.contactTime(mMin_/2),
            walls_.size() ? grainWall_.contactTime(mMin_) : GREAT
        );
        // (a case step of exactly k contact steps is k sub-steps)
        const label nSub =
            label(std::ceil((1 - 1e-9)*stepsPerContact_*deltaT/tc));
        if (nSub != nSubSteps_)
        {
            Info<< "    cartesianContacts: " << nSub << " sub-steps of "
                << deltaT/nSub << " s (t_c = " << tc << " s)" << endl;
        }
        nSubSteps_ = max(nSub, label(1));
    }

    const scalar dt = deltaT/max(nSubSteps_, label(1));
    const vector g(gravity_ ? cloud.g().value() : vector::zero);

    const scalar moveLimit2 = sqr(skin_*dMax_/2);

    const List<point> x0(x_);
    buildPairs();

    for (label k = 0; n > 0 && k < nSubSteps_; ++k)
    {
        bool rebuild = false;
        for (label i = 0; i < n; ++i)
        {
            v_[i] += 0.5*dt*(f_[i]/m_[i] + g);
            L_[i] += 0.5*dt*tau_[i];
            x_[i] += dt*v_[i];
            rebuild = rebuild || magSqr(x_[i] - xBuilt_[i]) > moveLimit2;
        }
        if (rebuild)
        {
            buildPairs();
        }

        contactForces(dt);
        if (planes_)
        {
            planes_->contactStep(x_, touching_);
        }

        for (label i = 0; i < n; ++i)
        {
            v_[i] += 0.5*dt*(f_[i]/m_[i] + g);
            L_[i] += 0.5*dt*tau_[i];
        }
    }

    scatterSprings();
    const Time& time = cloud.db().time();
    grainGrain_.reportOverlap(time, "cartesianContacts grainGrain");
    grainWall_.reportOverlap(time, "cartesianContacts grainWall");

    // Track every grain along its displacement; the velocity field
    // carries the displacement for the move
    forAll(parcels_, i)
    {
        parcels_[i]->U() = (x_[i] - x0[i])/deltaT;
    }
    td.alongDisplacement() = true;
    cloud.move(cloud, td, deltaT);
    td.alongDisplacement() = false;

    // The parcels that stay keep their order (serial: none is sent away)
    label i = 0;
    for (parcelType& p : cloud)
    {
        while (i < n && parcels_[i] != &p)
        {
            ++i;
        }
        if (i == n)
        {
            FatalErrorInFunction
                << "cartesianContacts: a parcel after the move is not one"
                << " of the step's" << abort(FatalError);
        }
        p.U() = v_[i];
        p.angularMomentum() = L_[i];
        p.f() = f_[i];
        p.torque() = tau_[i];
        ++i;
    }
}


// ************************************************************************* //
