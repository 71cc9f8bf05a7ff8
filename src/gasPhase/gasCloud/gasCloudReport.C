/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    gasCloud: the log: the step criteria and the NTC majorant excess at a
    write time, and the cloud's figures; the largest cell transit now
    (for the solver's adjustTimeStep).

\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "gasCellAverage.H"
#include "Pair.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- v from the processor whose local largest is the global largest (the
//  others give -GREAT to the maximum)
Foam::vector fromLargest
(
    const Foam::scalar local,
    const Foam::scalar global,
    const Foam::vector& v
)
{
    Foam::vector out
    (
        local == global ? v : Foam::vector::uniform(-Foam::GREAT)
    );
    Foam::reduce(out, Foam::maxOp<Foam::vector>());
    return out;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasCloud::reportStepCriteria(const gasCellAverage& average) const
{
    using constant::mathematical::pi;

    const scalar dt = mesh().time().deltaTValue();
    const bool weighted = axisymmetric_.weighted();

    scalar collisionMax = 0;
    scalar transitMax = 0;
    scalar fastMax = 0;
    label collisionCells = 0;
    label transitCells = 0;
    label fastCells = 0;
    label transitWorst = -1;
    label fastWorst = -1;
    forAll(mesh().cells(), celli)
    {
        const scalar h = extents_[celli];

        // Share of the cell's kinetic energy carried by the simulators now
        // in it that cross more than the cell in a step: a fast beam
        // through a slower gas, which the cell's mean state hides
        scalar fast = 0;
        scalar all = 0;
        for (const gasParcel* p : cellOccupancy()[celli])
        {
            const scalar e =
                (weighted ? axisymmetric_.weightAt(position(*p)) : 1)
               *constProps(p->typeId()).mass()*magSqr(p->U());
            all += e;
            if (mag(p->U())*dt > h)
            {
                fast += e;
            }
        }
        const scalar fastShare = all > 0 ? fast/all : 0;
        if (fastShare > fastMax)
        {
            fastMax = fastShare;
            fastWorst = celli;
        }
        fastCells += (fastShare > fastShareLimit);

        const scalar lambda = average.lambda(celli);
        const scalar R = average.R(celli);
        const scalar T = average.T(celli);
        if (!(lambda > 0 && R > 0 && T > 0))
        {
            continue;       // no gas sampled here
        }

        const scalar meanSpeed = std::sqrt(8*R*T/pi);
        const scalar collision = dt*meanSpeed/lambda;
        const scalar transit =
            (mag(average.U(celli)) + 2*std::sqrt(2*R*T))*dt/h;

        collisionMax = max(collisionMax, collision);
        if (transit > transitMax)
        {
            transitMax = transit;
            transitWorst = celli;
        }
        collisionCells += (collision > 1);
        transitCells += (transit > 1);
    }

    // Where the largest transit and share are, and a state of their cells:
    // the global largest, with the centre and state from its processor
    const vectorField& C = mesh().cellCentres();
    auto largestAt = [&](scalar& largest, const label celli, const vector& v)
    {
        const scalar local = largest;
        reduce(largest, maxOp<scalar>());
        return Pair<vector>
        (
            fromLargest(local, largest, celli < 0 ? Zero : C[celli]),
            fromLargest(local, largest, v)
        );
    };
    const label t = transitWorst;
    const label f = fastWorst;
    const Pair<vector> transitAt
    (
        largestAt
        (
            transitMax, t,
            t < 0
          ? Zero
          : vector(mag(average.U(t)), average.T(t), extents_[t])
        )
    );
    const Pair<vector> fastAt
    (
        largestAt
        (
            fastMax, f,
            f < 0 ? Zero : vector(cellOccupancy()[f].size(), extents_[f], 0)
        )
    );

    reduce(collisionMax, maxOp<scalar>());
    reduce(collisionCells, sumOp<label>());
    reduce(transitCells, sumOp<label>());
    reduce(fastCells, sumOp<label>());

    Info<< "Gas step criteria since the last write: deltaT/(mean collision"
        << " time) largest " << collisionMax << " (" << collisionCells
        << " cells above 1), cell transit (|U| + 2 c_mp) deltaT/h largest "
        << transitMax << " (" << transitCells << " cells above 1";
    if (transitMax > 0)
    {
        Info<< ", the largest at " << transitAt.first() << " m: |U| "
            << transitAt.second().x() << " m/s, T "
            << transitAt.second().y() << " K, h "
            << transitAt.second().z() << " m";
    }
    Info<< "); share of a cell's kinetic energy in simulators crossing more"
        << " than the cell largest " << fastMax << " (" << fastCells
        << " cells above " << fastShareLimit;
    if (fastMax > 0)
    {
        Info<< ", the largest at " << fastAt.first() << " m: "
            << label(fastAt.second().x()) << " simulators, h "
            << fastAt.second().y() << " m";
    }
    Info<< ")" << endl;

    if (collisionCells || transitCells || fastCells)
    {
        WarningInFunction
            << "deltaT " << dt << " s is too long for the gas in "
            << collisionCells << " cells (deltaT above the mean collision"
            << " time, up to " << collisionMax << " times), "
            << transitCells << " cells (simulators cross more than the cell"
            << " in a step, up to " << transitMax << " times) and "
            << fastCells << " cells (more than " << fastShareLimit
            << " of the kinetic energy in simulators that cross more than"
            << " the cell in a step, up to " << fastMax << "): shorten"
            << " deltaT in system/controlDict, or refine the mesh only"
            << " where the transit fails" << endl;
    }
}


Foam::scalar Foam::gasCloud::largestTransitRate() const
{
    // Each cell's simulators as the last step left them (the occupancy is
    // built after the move, and nothing moves after it; at a restart, by
    // the constructor): their mass, momentum and twice their kinetic
    // energy
    scalar largest = 0;
    forAll(cellOccupancy(), celli)
    {
        scalar m = 0;
        vector mc(Zero);
        scalar mcc = 0;
        for (const gasParcel* p : cellOccupancy()[celli])
        {
            const scalar mass = constProps(p->typeId()).mass();
            m += mass;
            mc += mass*p->U();
            mcc += mass*magSqr(p->U());
        }
        if (m > 0)
        {
            const vector U(mc/m);

            // 2 R T = 2 p/rho = 2/3 of the mean squared thermal speed
            const scalar twoRT = max(2*(mcc/m - magSqr(U))/3, scalar(0));

            largest =
                max(largest, (mag(U) + 2*std::sqrt(twoRT))/extents_[celli]);
        }
    }

    return returnReduce(largest, maxOp<scalar>());
}


void Foam::gasCloud::reportMajorantExcess()
{
    majorantExcess_.reduce();

    Info<< "Gas NTC since the last write: cell-steps whose (sigma c_r)_max"
        << " was exceeded " << majorantExcess_.n << ", largest acceptance"
        << " probability " << majorantExcess_.largest << endl;

    if (majorantExcess_.largest > ntcExcessLimit)
    {
        WarningInFunction
            << "a collision candidate had an acceptance probability of "
            << majorantExcess_.largest << " (above " << ntcExcessLimit
            << "): its cell's (sigma c_r)_max was far below the pairs now"
            << " in it (a fast stream entering a slower gas), and the"
            << " collisions beyond one that such a candidate stood for were"
            << " lost in that step" << endl;
    }

    majorantExcess_ = ntcSelection::excess();
}


void Foam::gasCloud::info() const
{
    // Upstream's figures (DSMCCloud::info) from one pass over the
    // simulators instead of four; each simulator counts its radial weight
    // factor (unweighted, the figures are upstream's to the bit: the same
    // sums in the same order)
    const bool weighted = axisymmetric_.weighted();
    const label simulators = returnReduce(size(), sumOp<label>());
    scalar weights = 0;
    scalar mass = 0;
    vector momentum(Zero);
    scalar linearKE = 0;
    scalar internalE = 0;
    for (const gasParcel& p : *this)
    {
        const scalar w = weighted ? axisymmetric_.weightAt(position(p)) : 1;
        const scalar m = w*constProps(p.typeId()).mass();
        weights += w;
        mass += m;
        momentum += m*p.U();
        linearKE += 0.5*m*(p.U() & p.U());
        internalE += w*p.Ei();
    }
    const scalar W = nParticle();
    const scalar molecules =
        weighted ? W*returnReduce(weights, sumOp<scalar>()) : simulators*W;
    reduce(mass, sumOp<scalar>());
    reduce(momentum, sumOp<vector>());
    reduce(linearKE, sumOp<scalar>());
    reduce(internalE, sumOp<scalar>());
    momentum *= W;
    linearKE *= W;
    internalE *= W;

    Info<< "Cloud name: " << name() << nl
        << "    Number of dsmc particles        = " << simulators << endl;
    if (simulators)
    {
        Info<< "    Number of molecules             = " << molecules << nl
            << "    Mass in system                  = " << W*mass << nl
            << "    Average linear momentum         = "
            << momentum/molecules << nl
            << "   |Average linear momentum|        = "
            << mag(momentum)/molecules << nl
            << "    Average linear kinetic energy   = "
            << linearKE/molecules << nl
            << "    Average internal energy         = "
            << internalE/molecules << nl
            << "    Average total energy            = "
            << (internalE + linearKE)/molecules << endl;
    }

    account_.info(mesh().boundaryMesh());
}


// ************************************************************************* //
