/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "cellExtent.H"
#include "gasCellAverage.H"
#include "cellFields.H"
#include "inputChecks.H"
#include "keywordChecks.H"
#include "randomStreams.H"
#include "restartState.H"
#include "sortByCell.H"
#include "polyMeshTetDecomposition.H"
#include "BinaryCollisionModel.H"
#include "WallInteractionModel.H"
#include "InflowBoundaryModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(gasCloud, 0);
}

constexpr Foam::scalar Foam::gasCloud::fastShareLimit;
constexpr Foam::label Foam::gasCloud::sortInterval_;


// * * * * * * * * * * * * * * * Input checks  * * * * * * * * * * * * * * * //

void Foam::gasCloudInputCheck::checkVibration(const dictionary& props)
{
    using namespace inputChecks;

    const word& modesKeyword = vibrationalModes::modesKeyword;
    const word& relaxationKeyword = vibrationalModes::relaxationKeyword;
    if (!props.found(modesKeyword))
    {
        if (props.found(relaxationKeyword))
        {
            outOfRange
            (
                props, relaxationKeyword, valueText(props, relaxationKeyword),
                "an entry only beside " + modesKeyword
            );
        }
        return;
    }
    if (!props.isDict(modesKeyword))
    {
        outOfRange
        (
            props, modesKeyword, valueText(props, modesKeyword),
            "a dictionary { <mode> { temperature <theta K>; degeneracy"
            " <count>; } ... }"
        );
    }

    const dictionary& modes = props.subDict(modesKeyword);
    if (modes.empty())
    {
        outOfRange(props, modesKeyword, "{}", "one or more modes");
    }
    for (const word& mode : modes.toc())
    {
        if (!modes.isDict(mode))
        {
            outOfRange
            (
                modes, mode, valueText(modes, mode),
                "a dictionary { temperature <theta K>; degeneracy <count>; }"
            );
        }
        const dictionary& d = modes.subDict(mode);
        rejectUnknown(d, {"temperature", "degeneracy"});
        getPositive(d, "temperature");
        getLabelOrDefault(d, "degeneracy", 1, 1, 10);
    }
    getInterval(props, relaxationKeyword, 1, VGREAT, false, true, true, 0);
}


bool Foam::gasCloudInputCheck::cartesianTracking(const dictionary& dict)
{
    return
        inputChecks::getChoiceOrDefault
        (
            dict, "tracking", "cartesian", {"cartesian", "barycentric"}
        )
     == "cartesian";
}


Foam::wordList Foam::gasCloudInputCheck::checkProperties
(
    const dictionary& dict
)
{
    using namespace inputChecks;

    getPositive(dict, "nEquivalentParticles");
    getLabelOrDefault(dict, "randomSeed", 0, 0, 2000);
    getBoolOrDefault(dict, "randomEntryTime", false);
    cartesianTracking(dict);

    const wordList species(dict.get<wordList>("typeIdList"));
    if (species.empty())
    {
        outOfRange(dict, "typeIdList", species, "a list of one or more species");
    }

    const dictionary& molecules = dict.subDict("moleculeProperties");
    for (const word& name : species)
    {
        const dictionary& props = molecules.subDict(name);
        rejectUnknown
        (
            props,
            {
                "mass", "diameter", "internalDegreesOfFreedom", "omega",
                vibrationalModes::modesKeyword,
                vibrationalModes::relaxationKeyword
            }
        );
        getPositive(props, "mass");
        getPositive(props, "diameter");
        getClosed(props, "internalDegreesOfFreedom", 0, 10);
        getClosed(props, "omega", 0.5, 1.0);
        checkVibration(props);
    }

    typedef DSMCCloud<gasParcel> cloudType;

    const word collision
    (
        modelName<BinaryCollisionModel<cloudType>>(dict, "BinaryCollisionModel")
    );
    if (collision == "VariableHardSphere")
    {
        const dictionary& coeffs = dict.subDict(collision + "Coeffs");
        rejectUnknown(coeffs, {"Tref"});
        getPositive(coeffs, "Tref");
    }
    else if (collision == "LarsenBorgnakkeVariableHardSphere")
    {
        const dictionary& coeffs = dict.subDict(collision + "Coeffs");
        rejectUnknown(coeffs, {"Tref", "relaxationCollisionNumber"});
        getPositive(coeffs, "Tref");
        getInterval
        (
            coeffs, "relaxationCollisionNumber", 1, VGREAT, false, true, true, 0
        );
    }
    // Only our Larsen-Borgnakke form exchanges vibrational energy
    const word vibrating("LarsenBorgnakkeVariableSoftSphere");
    for (const word& name : species)
    {
        if
        (
            collision != vibrating
         && molecules.subDict(name).found(vibrationalModes::modesKeyword)
        )
        {
            FatalIOErrorInFunction(dict)
                << "BinaryCollisionModel " << collision << " in "
                << dict.name() << ": species " << name << " has "
                << vibrationalModes::modesKeyword << ", which only "
                << vibrating << " exchanges; valid choices with "
                << "vibrational modes: (" << vibrating << ")"
                << exit(FatalIOError);
        }
    }

    if
    (
        collision == "VariableSoftSphere"
     || collision == "LarsenBorgnakkeVariableSoftSphere"
    )
    {
        const dictionary& coeffs = dict.subDict(collision + "Coeffs");
        const bool exchange = collision != "VariableSoftSphere";
        wordList valid({"Tref", "alpha", "alphaPairs"});
        if (exchange)
        {
            valid.append("relaxationCollisionNumber");
            getInterval
            (
                coeffs, "relaxationCollisionNumber",
                1, VGREAT, false, true, true, 0
            );
        }
        rejectUnknown(coeffs, valid);
        getPositive(coeffs, "Tref");

        // The scattering exponents: every species, the pairs optional,
        // from 1 (isotropic, VHS) to 2
        const dictionary& alpha = coeffs.subDict("alpha");
        for (const word& name : alpha.toc())
        {
            if (!species.found(name))
            {
                notOneOf(alpha, "alpha", name, species);
            }
        }
        for (const word& name : species)
        {
            getClosed(alpha, name, 1, 2);
        }
        const dictionary pairs(coeffs.subOrEmptyDict("alphaPairs"));
        for (const word& p : pairs.toc())
        {
            if (!species.found(p) || !pairs.isDict(p))
            {
                notOneOf(pairs, "alphaPairs", p, species);
            }
            const dictionary& partners = pairs.subDict(p);
            for (const word& q : partners.toc())
            {
                if (!species.found(q))
                {
                    notOneOf(partners, p, q, species);
                }
                getClosed(partners, q, 1, 2);
            }
        }
    }

    const word wall
    (
        modelName<WallInteractionModel<cloudType>>(dict, "WallInteractionModel")
    );
    if (wall == "MixedDiffuseSpecular")
    {
        rejectUnknown
        (
            dict.subDict("MixedDiffuseSpecularCoeffs"), {"diffuseFraction"}
        );
        getClosed
        (
            dict.subDict("MixedDiffuseSpecularCoeffs"), "diffuseFraction", 0, 1
        );
    }

    const word inflow
    (
        modelName<InflowBoundaryModel<cloudType>>(dict, "InflowBoundaryModel")
    );
    if (inflow == "FreeStream")
    {
        rejectUnknown(dict.subDict("FreeStreamCoeffs"), {"numberDensities"});
        const dictionary& densities =
            dict.subDict("FreeStreamCoeffs").subDict("numberDensities");
        for (const word& name : densities.toc())
        {
            if (!species.found(name))
            {
                notOneOf(densities, "numberDensities", name, species);
            }
            getNonNegativeOrDefault(densities, name, 0);
        }
    }

    // The top level's plain entries: upstream's and ours (axisymmetricMode,
    // randomSeed, randomEntryTime); the dictionaries there are upstream's,
    // required where a selected model reads them
    rejectMisspelt
    (
        dict,
        {
            "nEquivalentParticles", "typeIdList", "BinaryCollisionModel",
            "WallInteractionModel", "InflowBoundaryModel", "randomSeed",
            "randomEntryTime", "axisymmetric", "radialExtent",
            "maxRadialWeight", "tracking"
        },
        false
    );

    return species;
}


void Foam::gasCloudInputCheck::checkInitialise
(
    const dictionary& dict,
    const wordList& species
)
{
    using namespace inputChecks;

    rejectMisspelt
    (
        dict, {"numberDensities", "temperature", "velocity", "randomSeed"}
    );
    getLabelOrDefault(dict, "randomSeed", 0, 0, 2000);
    getPositive(dict, "temperature");
    getVector(dict, "velocity");

    const dictionary& densities = dict.subDict("numberDensities");
    if (densities.empty())
    {
        outOfRange(dict, "numberDensities", "{}", "one entry per species");
    }
    for (const word& name : densities.toc())
    {
        if (!species.found(name))
        {
            notOneOf(densities, "numberDensities", name, species);
        }
        getNonNegativeOrDefault(densities, name, 0);
    }
}


const Foam::dictionary& Foam::gasCloudInputCheck::checked
(
    const dictionary& dict
)
{
    checkProperties(dict);
    return dict;
}


const Foam::dictionary& Foam::gasCloudInputCheck::checked
(
    const dictionary& dict,
    const dictionary& initialiseDict
)
{
    checkInitialise(initialiseDict, checkProperties(dict));
    return dict;
}


Foam::gasCloudInputCheck::gasCloudInputCheck
(
    const word& cloudName,
    const fvMesh& mesh
)
:
    axisymmetric_
    (
        checked(inputChecks::readCloudProperties(cloudName, mesh)),
        mesh,
        "gas"
    )
{}


Foam::gasCloudInputCheck::gasCloudInputCheck
(
    const word& cloudName,
    const fvMesh& mesh,
    const dictionary& initialiseDict
)
:
    axisymmetric_
    (
        checked
        (
            inputChecks::readCloudProperties(cloudName, mesh),
            initialiseDict
        ),
        mesh,
        "gas"
    )
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::gasCloud::seedFromCase()
{
    // Without the keyword the stream is upstream's, untouched
    label seed = 0;
    if (particleProperties().readIfPresent("randomSeed", seed))
    {
        rndGen().reset(randomStreams::seed(seed, randomStreams::gas));

        Info<< "Gas random seed " << seed << " (+ processor number)" << endl;
    }
}


void Foam::gasCloud::readState()
{
    const dictionary state(restartState::read(mesh(), name(), typeName));
    restartState::get(state, "random", rndGen());

    scalarList remainder;
    if
    (
        restartState::get
        (
            state, "collisionSelectionRemainder", mesh().nCells(), remainder
        )
    )
    {
        collisionSelectionRemainder() = remainder;
    }
}


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


void Foam::gasCloud::addVibrationToFields()
{
    volScalarField& internalE =
        const_cast<volScalarField&>(this->internalE());
    volScalarField& iDof = const_cast<volScalarField&>(this->iDof());

    const scalarField& V = mesh().cellVolumes();
    forAll(V, celli)
    {
        const scalar scale = nParticle()/V[celli];
        internalE[celli] += scale*now_->vibrationalEnergy(celli);
        iDof[celli] += scale*now_->vibrationalDof(celli);
    }

    internalE.correctBoundaryConditions();
    iDof.correctBoundaryConditions();
}


void Foam::gasCloud::evolveCartesian()
{
    gasParcel::trackingData td(*this);

    // Every few steps: simulators cross a fraction of a cell per step, so
    // the order decays slowly, and the sort costs as much as a third of a
    // step (measured on freeSpacePeriodic: 14 % of the run when sorted at
    // every step)
    if (mesh().time().timeIndex() % sortInterval_ == 0)
    {
        Foam::sortByCell(*this);
    }

    // Upstream's resetFields: the sampled fields' patch values sum this
    // step's wall hits (gasParcel::hitWallPatch), their cell values are
    // set by sampleWeighted
    auto value = [](const volScalarField& field, const scalar v)
    {
        return dimensionedScalar("0", field.dimensions(), v);
    };
    const_cast<volScalarField&>(q()) = value(q(), Zero);
    const_cast<volVectorField&>(fD()) =
        dimensionedVector("0", fD().dimensions(), Zero);
    const_cast<volScalarField&>(rhoN()) = value(rhoN(), VSMALL);
    const_cast<volScalarField&>(rhoM()) = value(rhoM(), VSMALL);
    const_cast<volScalarField&>(dsmcRhoN()) = value(dsmcRhoN(), Zero);
    const_cast<volScalarField&>(linearKE()) = value(linearKE(), Zero);
    const_cast<volScalarField&>(internalE()) = value(internalE(), Zero);
    const_cast<volScalarField&>(iDof()) = value(iDof(), VSMALL);
    const_cast<volVectorField&>(momentum()) =
        dimensionedVector("0", momentum().dimensions(), Zero);

    inflowBoundary().inflow();

    Cloud<gasParcel>::move(*this, td, mesh().time().deltaTValue());

    // Upstream's occupancy, read by the coupling and the samples
    auto& occupancy =
        const_cast<List<DynamicList<gasParcel*>>&>(cellOccupancy());
    for (auto& members : occupancy)
    {
        members.clear();
    }
    for (gasParcel& p : *this)
    {
        occupancy[p.cell()].append(&p);
    }

    collide();

    sampleWeighted();
}


void Foam::gasCloud::collide()
{
    if (!binaryCollision().active())
    {
        return;
    }

    const scalar dt = mesh().time().deltaTValue();
    const scalarField& V = mesh().cellVolumes();
    const vectorField& centres = mesh().cellCentres();
    scalarField& majorant = sigmaTcRMax().primitiveFieldRef();
    scalarField& remainder = collisionSelectionRemainder();
    Random& rnd = rndGen();

    // Counted by evolve from the majorants before and after
    ntcSelection::excess uncounted;

    List<DynamicList<label>> octants(8);
    DynamicList<label> octantOf;
    label nTried = 0;
    label nCollided = 0;

    forAll(cellOccupancy(), celli)
    {
        const DynamicList<gasParcel*>& members = cellOccupancy()[celli];
        const label n = members.size();
        if (n < 2)
        {
            continue;
        }

        for (auto& octant : octants)
        {
            octant.clear();
        }
        octantOf.resize(n);
        forAll(members, i)
        {
            label k = members[i]->octant();
            if (k == gasParcel::noOctant)
            {
                // (in the axisymmetric mode the quadrant in the plane)
                const vector r(position(*members[i]) - centres[celli]);
                k = pos0(r.x()) + 2*pos0(r.y())
                  + (wedges_ ? 0 : 4*pos0(r.z()));
            }
            octants[k].append(i);
            octantOf[i] = k;
        }

        const scalar drawnMax = majorant[celli];
        const label nCandidates = ntcSelection::candidates
        (
            0.5*n*(n - 1)*nParticle()*drawnMax*dt/V[celli],
            remainder[celli]
        );
        nTried += nCandidates;

        for (label c = 0; c < nCandidates; ++c)
        {
            const label i = rnd.position<label>(0, n - 1);
            const DynamicList<label>& octant = octants[octantOf[i]];
            const label nOctant = octant.size();

            label j = i;
            while (j == i)
            {
                j = nOctant > 1
                  ? octant[rnd.position<label>(0, nOctant - 1)]
                  : rnd.position<label>(0, n - 1);
            }

            gasParcel& p = *members[i];
            gasParcel& q = *members[j];

            if
            (
                ntcSelection::accept
                (
                    vhs_->active()
                  ? vhs_->sigmaTcR(p, q)
                  : binaryCollision().sigmaTcR(p, q),
                    drawnMax, majorant[celli], rnd, uncounted
                )
            )
            {
                binaryCollision().collide(p, q);
                ++nCollided;
            }
        }
    }

    sigmaTcRMax().correctBoundaryConditions();

    // Upstream's log lines
    reduce(nTried, sumOp<label>());
    reduce(nCollided, sumOp<label>());
    if (nTried)
    {
        Info<< "    Collisions                      = " << nCollided << nl
            << "    Acceptance rate                 = "
            << scalar(nCollided)/nTried << nl << endl;
    }
    else
    {
        Info<< "    No collisions" << endl;
    }
}


void Foam::gasCloud::sampleWeighted()
{
    // Upstream exposes its sampled fields read-only; this cloud owns them
    // and replaces upstream's unweighted sums
    volScalarField& rhoN = const_cast<volScalarField&>(this->rhoN());
    volScalarField& rhoM = const_cast<volScalarField&>(this->rhoM());
    volScalarField& dsmcRhoN = const_cast<volScalarField&>(this->dsmcRhoN());
    volScalarField& linearKE = const_cast<volScalarField&>(this->linearKE());
    volScalarField& internalE =
        const_cast<volScalarField&>(this->internalE());
    volScalarField& iDof = const_cast<volScalarField&>(this->iDof());
    volVectorField& momentum = const_cast<volVectorField&>(this->momentum());

    // Upstream's starting values (VSMALL keeps divisions by rhoN finite);
    // the boundary values are the wall samples of this step's move
    rhoN.primitiveFieldRef() = VSMALL;
    rhoM.primitiveFieldRef() = VSMALL;
    dsmcRhoN.primitiveFieldRef() = Zero;
    linearKE.primitiveFieldRef() = Zero;
    internalE.primitiveFieldRef() = Zero;
    iDof.primitiveFieldRef() = VSMALL;
    momentum.primitiveFieldRef() = Zero;

    for (const gasParcel& p : *this)
    {
        const label celli = p.cell();
        const auto& props = constProps(p.typeId());
        const scalar w =
            axisymmetric_.weighted() ? axisymmetric_.weightAt(position(p)) : 1;
        const scalar m = props.mass();

        rhoN[celli] += w;
        rhoM[celli] += w*m;
        dsmcRhoN[celli] += 1;
        linearKE[celli] += w*0.5*m*magSqr(p.U());
        internalE[celli] += w*p.Ei();
        iDof[celli] += w*props.internalDegreesOfFreedom();
        momentum[celli] += w*m*p.U();
    }

    // Simulators per unit volume (already VSMALL-started) to real densities
    const scalarField scale(nParticle()/mesh().cellVolumes());

    rhoN.primitiveFieldRef() *= scale;
    rhoM.primitiveFieldRef() *= scale;
    linearKE.primitiveFieldRef() *= scale;
    internalE.primitiveFieldRef() *= scale;
    iDof.primitiveFieldRef() *= scale;
    momentum.primitiveFieldRef() *= scale;

    rhoN.correctBoundaryConditions();
    rhoM.correctBoundaryConditions();
    dsmcRhoN.correctBoundaryConditions();
    linearKE.correctBoundaryConditions();
    internalE.correctBoundaryConditions();
    iDof.correctBoundaryConditions();
    momentum.correctBoundaryConditions();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasCloud::gasCloud(const word& cloudName, const fvMesh& mesh)
:
    gasCloudInputCheck(cloudName, mesh),
    DSMCCloud<gasParcel>(cloudName, mesh, true),
    vibration_(readVibration()),
    account_("Simulators", mesh.boundaryMesh(), this->size()),
    randomEntryTime_
    (
        particleProperties().getOrDefault<bool>
        (
            "randomEntryTime",
            axisymmetric_.active()
        )
    ),
    boxes_(nullptr),
    wedges_(nullptr),
    writeState_(true),
    atCollisionsIndex_(-1)
{
    if (cartesianTracking(particleProperties()))
    {
        label nWalkable = 0;
        if (axisymmetric_.active())
        {
            wedges_ = &wedgeWalk::New(mesh);
            nWalkable = wedges_->nWalkable();
        }
        else
        {
            boxes_ = &boxWalk::New(mesh);
            nWalkable = boxes_->nWalkable();
        }
        Info<< "Gas tracking: Cartesian through "
            << returnReduce(nWalkable, sumOp<label>())
            << " of " << returnReduce(mesh.nCells(), sumOp<label>())
            << " cells, barycentric elsewhere" << nl << endl;
    }

    vhs_.reset(new vhsCrossSection(*this));
    seedFromCase();
    readState();
    account_.read(mesh, cloudName, mesh.boundaryMesh());
    setWeighting();
    drawMissingLevels();
}


Foam::gasCloud::gasCloud
(
    const word& cloudName,
    const fvMesh& mesh,
    const IOdictionary& initialiseDict
)
:
    gasCloudInputCheck(cloudName, mesh, initialiseDict),
    DSMCCloud<gasParcel>(cloudName, mesh, emptied(initialiseDict)),
    vibration_(readVibration()),
    account_("Simulators", mesh.boundaryMesh(), 0),
    randomEntryTime_(false),    // the fill moves nothing
    boxes_(nullptr),
    wedges_(nullptr),
    writeState_(false),
    atCollisionsIndex_(-1)
{
    setWeighting();
    fill(initialiseDict);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::gasCloud::~gasCloud()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasCloud::arrive(const label celli)
{
    // The k-th arrival adds (RWF_c - 1) k of upstream's per-pair
    // candidates: over N arrivals (RWF_c - 1) N (N - 1)/2 of them
    const label k = nArrived_[celli]++;

    if (k)
    {
        collisionSelectionRemainder()[celli] +=
            (cellWeight_[celli] - 1)*k*nParticle()
           *sigmaTcRMax()[celli]*mesh().time().deltaTValue()
           /mesh().cellVolumes()[celli];
    }
}


bool Foam::gasCloud::weighMove
(
    gasParcel& p,
    const scalar w0,
    const scalar w1,
    const bool complete
)
{
    if (!axisymmetric_.weighted())
    {
        return true;
    }

    const label nCopies = axisymmetricMode::copies(w0, w1, rndGen());

    // Clones appended to the cloud being moved: the move loop reaches a
    // clone (or not, if appended while the last member moves) with the
    // step already done, so its move does nothing, and it is in the cell
    // for this step's collisions.  (A clone made at a processor boundary
    // is moved on from there like its parent.)
    const bool kept = axisymmetricMode::keepCopies
    (
        *this, p, nCopies, account_,
        [&](const gasParcel& clone)
        {
            if (complete)
            {
                arrive(clone.cell());
            }
        }
    );
    if (!kept)
    {
        return false;
    }

    if (complete)
    {
        arrive(p.cell());
    }

    return true;
}


Foam::scalar Foam::gasCloud::collisionTemperature(const label celli)
{
    const label index = mesh().time().timeIndex();
    if (atCollisionsIndex_ != index)
    {
        if (!atCollisions_.valid())
        {
            atCollisions_.reset(new gasCellAverage(*this, 1));
        }
        atCollisions_->sample(*this);
        atCollisionsIndex_ = index;
    }
    return atCollisions_->T(celli);
}


void Foam::gasCloud::drawInflowLevels(gasParcel& p)
{
    if (p.vibLevels().size() == vibration_.nOscillators(p.typeId()))
    {
        return;     // drawn by the inflow model itself (PatchInflow)
    }

    if (inflowT_.empty())
    {
        // FreeStream's patches: every plain patch
        inflowT_.setSize(mesh().nCells(), Zero);
        scalarField nFaces(mesh().nCells(), Zero);
        forAll(mesh().boundaryMesh(), patchi)
        {
            const polyPatch& patch = mesh().boundaryMesh()[patchi];
            if (!isType<polyPatch>(patch))
            {
                continue;
            }
            const scalarField& T = boundaryT().boundaryField()[patchi];
            forAll(patch, facei)
            {
                const label celli = patch.faceCells()[facei];
                inflowT_[celli] += T[facei];
                nFaces[celli] += 1;
            }
        }
        forAll(inflowT_, celli)
        {
            if (nFaces[celli] > 0)
            {
                inflowT_[celli] /= nFaces[celli];
            }
        }
    }

    vibration_.draw
    (
        p.typeId(), inflowT_[p.cell()], rndGen(), p.vibLevels()
    );
}


Foam::tmp<Foam::scalarField> Foam::gasCloud::collisionCandidates() const
{
    tmp<scalarField> tcandidates(new scalarField(mesh().nCells(), Zero));
    if (!binaryCollision().active())
    {
        return tcandidates;
    }

    scalarField& candidates = tcandidates.ref();
    const scalarField& majorant =
        const_cast<gasCloud&>(*this).sigmaTcRMax().primitiveField();
    const scalar dt = mesh().time().deltaTValue();
    const scalarField& V = mesh().cellVolumes();
    forAll(candidates, celli)
    {
        const scalar n = cellOccupancy()[celli].size();
        const scalar rwf = cellWeight_.size() ? cellWeight_[celli] : 1;
        candidates[celli] =
            0.5*n*max(n - 1, 0)*nParticle()*rwf*majorant[celli]*dt
           /V[celli];
    }
    return tcandidates;
}


void Foam::gasCloud::evolve()
{
    const label nBefore = this->size();

    if (axisymmetric_.weighted())
    {
        nArrived_ = 0;
    }

    // Upstream's collisions draw each cell's candidates from its
    // majorant and raise it for the next step when a candidate exceeds it
    const scalarField drawnMax(sigmaTcRMax().primitiveField());

    if (boxes_ || wedges_)
    {
        evolveCartesian();
    }
    else
    {
        DSMCCloud<gasParcel>::evolve();
    }

    forAll(drawnMax, celli)
    {
        const scalar raised = sigmaTcRMax()[celli];
        if (raised > drawnMax[celli])
        {
            majorantExcess_.n += 1;
            majorantExcess_.largest =
                max(majorantExcess_.largest, raised/drawnMax[celli]);
        }
    }

    if (axisymmetric_.weighted() && !boxes_ && !wedges_)
    {
        sampleWeighted();
    }

    sampleCells();

    if (vibration_.active())
    {
        addVibrationToFields();
    }

    // Inflow is not reported by upstream's model: it is the balance
    account_.closeStep(nBefore, this->size());
}


const Foam::gasCellAverage& Foam::gasCloud::cellState() const
{
    return now_();
}


void Foam::gasCloud::sampleCells()
{
    if (!now_.valid())
    {
        now_.reset(new gasCellAverage(*this, 1));
        sinceWrite_.reset(new gasCellAverage(*this, 0));
    }

    now_->sample(*this);
    sinceWrite_->add(now_());

    if (mesh().time().writeTime())
    {
        lambda_ = sinceWrite_->lambda();
        writeCellField(mesh(), "gas", "lambda", dimLength, lambda_);
        if (vibration_.active())
        {
            writeVibrationalT(sinceWrite_());
        }
        reportStepCriteria(sinceWrite_());
        reportMajorantExcess();
        sinceWrite_->reset();
    }
}


void Foam::gasCloud::writeVibrationalT(const gasCellAverage& average) const
{
    writeCellField
    (
        mesh(), "gas", "vibrationalT", dimTemperature,
        average.vibrationalT(-1)()
    );
    forAll(typeIdList(), typei)
    {
        if (vibration_.nOscillators(typei))
        {
            writeCellField
            (
                mesh(), typeIdList()[typei], "vibrationalT", dimTemperature,
                average.vibrationalT(typei)()
            );
        }
    }
}


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


void Foam::gasCloud::writeFields() const
{
    DSMCCloud<gasParcel>::writeFields();
    if (!writeState_)
    {
        return;
    }

    // Upstream's accessors of the stream and the remainders are non-const
    gasCloud& cloud = const_cast<gasCloud&>(*this);
    dictionary state;
    restartState::put(state, "random", cloud.rndGen());
    restartState::put
    (
        state,
        "collisionSelectionRemainder",
        cloud.collisionSelectionRemainder()
    );
    restartState::write(mesh(), name(), typeName, state);
    account_.write(mesh(), name(), mesh().boundaryMesh());
}


// ************************************************************************* //
