/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

Description
    gasCloud: the initial fill, the radial weights of the cells and the
    vibrational levels of simulators read without them.

\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "gasCellAverage.H"
#include "randomStreams.H"
#include "polyMeshTetDecomposition.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::IOdictionary Foam::gasCloud::emptied(const IOdictionary& initialiseDict)
{
    IOobject io(initialiseDict);
    io.readOpt() = IOobject::NO_READ;
    io.registerObject() = false;

    IOdictionary dict(io, initialiseDict);

    dictionary& densities = dict.subDict("numberDensities");
    for (const word& name : densities.toc())
    {
        densities.set(name, scalar(0));
    }

    return dict;
}


void Foam::gasCloud::fill(const dictionary& initialiseDict)
{
    const label seed =
        initialiseDict.getOrDefault<label>("randomSeed", 0);
    rndGen().reset(randomStreams::seed(seed, randomStreams::gasFill));

    const scalar T = initialiseDict.get<scalar>("temperature");
    const vector U = initialiseDict.get<vector>("velocity");
    const dictionary& densities = initialiseDict.subDict("numberDensities");

    // Simulators per unit volume of each species (zero if not listed)
    scalarList nSim(typeIdList().size(), Zero);
    forAll(nSim, typeId)
    {
        nSim[typeId] =
            densities.getOrDefault<scalar>(typeIdList()[typeId], 0)
           /nParticle();
    }

    const fvMesh& mesh = this->mesh();
    const bool weighted = axisymmetric_.weighted();

    forAll(mesh.cells(), celli)
    {
        for
        (
            const tetIndices& tetIs
          : polyMeshTetDecomposition::cellTetIndices(mesh, celli)
        )
        {
            const tetPointRef tet = tetIs.tet(mesh);
            const scalar volume = tet.mag();

            forAll(nSim, typeId)
            {
                if (nSim[typeId] <= 0)
                {
                    continue;
                }

                const scalar expected = nSim[typeId]*volume;
                label n = label(expected);
                if (expected - n > rndGen().sample01<scalar>())
                {
                    ++n;
                }

                const auto& props = constProps(typeId);

                for (label i = 0; i < n; ++i)
                {
                    const point position = tet.randomPoint(rndGen());

                    // Radial weighting: keep with probability 1/RWF
                    if
                    (
                        weighted
                     && rndGen().sample01<scalar>()
                       *axisymmetric_.weightAt(position) > 1
                    )
                    {
                        continue;
                    }

                    const vector Ui =
                        U + equipartitionLinearVelocity(T, props.mass());
                    const scalar Ei = equipartitionInternalEnergy
                    (
                        T,
                        props.internalDegreesOfFreedom()
                    );

                    gasParcel* p =
                        new gasParcel(mesh, position, celli, Ui, Ei, typeId);
                    p->settle();
                    if (vibration_.active())
                    {
                        vibration_.draw(typeId, T, rndGen(), p->vibLevels());
                    }
                    addParticle(p);
                }
            }
        }
    }

    // Largest sigmaT*cR to start NTC selection from (Bird 1994, p. 222)
    const auto& major = constProps(findMax(nSim));
    sigmaTcRMax().primitiveFieldRef() =
        major.sigmaT()*maxwellianMostProbableSpeed(T, major.mass());
    sigmaTcRMax().correctBoundaryConditions();
}


void Foam::gasCloud::setWeighting()
{
    if (!axisymmetric_.weighted())
    {
        return;
    }

    account_.countWeighting();

    const vectorField& centres = mesh().cellCentres();
    cellWeight_.setSize(centres.size());
    forAll(centres, celli)
    {
        cellWeight_[celli] = axisymmetric_.weightAt(centres[celli]);
    }

    nArrived_.setSize(centres.size(), 0);
}


Foam::vibrationalModes Foam::gasCloud::readVibration() const
{
    scalarList omega(typeIdList().size());
    forAll(omega, typei)
    {
        omega[typei] = constProps(typei).omega();
    }
    return vibrationalModes
    (
        particleProperties().subDict("moleculeProperties"),
        typeIdList(),
        omega
    );
}


void Foam::gasCloud::drawMissingLevels()
{
    if (!vibration_.active())
    {
        return;
    }

    // Translational temperature of each cell from its simulators
    gasCellAverage now(*this, 1);
    now.sample(*this);

    label nDrawn = 0;
    for (gasParcel& p : *this)
    {
        if (p.vibLevels().size() == vibration_.nOscillators(p.typeId()))
        {
            continue;
        }
        vibration_.draw(p.typeId(), now.T(p.cell()), rndGen(), p.vibLevels());
        ++nDrawn;
    }

    reduce(nDrawn, sumOp<label>());
    if (nDrawn)
    {
        Info<< "Vibrational levels drawn at their cell's translational"
            << " temperature for " << nDrawn << " simulators read without"
            << " them" << endl;
    }
}


// ************************************************************************* //
