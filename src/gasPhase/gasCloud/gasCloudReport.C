/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    gasCloud: the log: the step criteria and the NTC majorant excess at a
    write time, and the cloud's figures.

\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "gasCellAverage.H"
#include "cellExtent.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasCloud::reportStepCriteria(const gasCellAverage& average) const
{
    using constant::mathematical::pi;

    const scalar dt = mesh().time().deltaTValue();
    const scalarField extents(smallestCellExtents(mesh()));
    const bool weighted = axisymmetric_.weighted();

    scalar collisionMax = 0;
    scalar transitMax = 0;
    scalar fastMax = 0;
    label collisionCells = 0;
    label transitCells = 0;
    label fastCells = 0;
    forAll(mesh().cells(), celli)
    {
        const scalar h = extents[celli];

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
        fastMax = max(fastMax, fastShare);
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
        transitMax = max(transitMax, transit);
        collisionCells += (collision > 1);
        transitCells += (transit > 1);
    }
    reduce(collisionMax, maxOp<scalar>());
    reduce(transitMax, maxOp<scalar>());
    reduce(fastMax, maxOp<scalar>());
    reduce(collisionCells, sumOp<label>());
    reduce(transitCells, sumOp<label>());
    reduce(fastCells, sumOp<label>());

    Info<< "Gas step criteria since the last write: deltaT/(mean collision"
        << " time) largest " << collisionMax << " (" << collisionCells
        << " cells above 1), cell transit (|U| + 2 c_mp) deltaT/h largest "
        << transitMax << " (" << transitCells << " cells above 1);"
        << " share of a cell's kinetic energy in simulators crossing more"
        << " than the cell largest " << fastMax << " (" << fastCells
        << " cells above " << fastShareLimit << ")" << endl;

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
