/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
\*---------------------------------------------------------------------------*/

#include "gasCloud.H"
#include "inputChecks.H"
#include "polyMeshTetDecomposition.H"
#include "BinaryCollisionModel.H"
#include "WallInteractionModel.H"
#include "InflowBoundaryModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(gasCloud, 0);
}


// * * * * * * * * * * * * * * * Input checks  * * * * * * * * * * * * * * * //

namespace
{

Foam::IOdictionary readProperties
(
    const Foam::word& cloudName,
    const Foam::fvMesh& mesh
)
{
    using namespace Foam;

    return IOdictionary
    (
        IOobject
        (
            cloudName + "Properties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
}

//- The model name of keyword, which must be in the selection table
template<class Model>
Foam::word modelName(const Foam::dictionary& dict, const Foam::word& keyword)
{
    const Foam::word name(dict.get<Foam::word>(keyword));
    const auto& table = *Model::dictionaryConstructorTablePtr_;

    if (!table.found(name))
    {
        FatalIOErrorInLookup(dict, keyword, name, table)
            << Foam::exit(Foam::FatalIOError);
    }

    return name;
}

} // End anonymous namespace


Foam::wordList Foam::gasCloudInputCheck::checkProperties
(
    const dictionary& dict
)
{
    using namespace inputChecks;

    getPositive(dict, "nEquivalentParticles");
    getLabelOrDefault(dict, "randomSeed", 0, 0, 2000);

    const wordList species(dict.get<wordList>("typeIdList"));
    if (species.empty())
    {
        outOfRange(dict, "typeIdList", species, "a list of one or more species");
    }

    const dictionary& molecules = dict.subDict("moleculeProperties");
    for (const word& name : species)
    {
        const dictionary& props = molecules.subDict(name);
        getPositive(props, "mass");
        getPositive(props, "diameter");
        getClosed(props, "internalDegreesOfFreedom", 0, 10);
        getClosed(props, "omega", 0.5, 1.0);
    }

    typedef DSMCCloud<gasParcel> cloudType;

    const word collision
    (
        modelName<BinaryCollisionModel<cloudType>>(dict, "BinaryCollisionModel")
    );
    if (collision == "VariableHardSphere")
    {
        getPositive(dict.subDict(collision + "Coeffs"), "Tref");
    }
    else if (collision == "LarsenBorgnakkeVariableHardSphere")
    {
        const dictionary& coeffs = dict.subDict(collision + "Coeffs");
        getPositive(coeffs, "Tref");
        getClosed(coeffs, "relaxationCollisionNumber", 1, GREAT);
    }

    const word wall
    (
        modelName<WallInteractionModel<cloudType>>(dict, "WallInteractionModel")
    );
    if (wall == "MixedDiffuseSpecular")
    {
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
        const dictionary& densities =
            dict.subDict("FreeStreamCoeffs").subDict("numberDensities");
        for (const word& name : densities.toc())
        {
            if (!species.found(name))
            {
                notOneOf(densities, "numberDensities", name, species);
            }
            getNonNegative(densities, name);
        }
    }

    return species;
}


void Foam::gasCloudInputCheck::checkInitialise
(
    const dictionary& dict,
    const wordList& species
)
{
    using namespace inputChecks;

    getLabelOrDefault(dict, "randomSeed", 0, 0, 2000);
    getPositive(dict, "temperature");
    dict.get<vector>("velocity");

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
        getNonNegative(densities, name);
    }
}


Foam::gasCloudInputCheck::gasCloudInputCheck
(
    const word& cloudName,
    const fvMesh& mesh
)
{
    checkProperties(readProperties(cloudName, mesh));
}


Foam::gasCloudInputCheck::gasCloudInputCheck
(
    const word& cloudName,
    const fvMesh& mesh,
    const dictionary& initialiseDict
)
{
    checkInitialise
    (
        initialiseDict,
        checkProperties(readProperties(cloudName, mesh))
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::gasCloud::seedFromCase()
{
    // Without the keyword the stream is upstream's, untouched
    label seed = 0;
    if (particleProperties().readIfPresent("randomSeed", seed))
    {
        rndGen().reset(seed*1000003 + Pstream::myProcNo());

        Info<< "Gas random seed " << seed << " (+ processor number)" << endl;
    }
}


void Foam::gasCloud::accountStep(const label nBefore)
{
    // One sum over processors: per patch the simulators removed, then those
    // lost, present now and present before.  Scalars: totals of long runs
    // exceed 32-bit labels
    const label nPatches = nEscapedStep_.size();
    scalarField counts(nPatches + 3);
    forAll(nEscapedStep_, patchi)
    {
        counts[patchi] = nEscapedStep_[patchi];
    }
    counts[nPatches] = nLostStep_;
    counts[nPatches + 1] = this->size();
    counts[nPatches + 2] = nBefore;

    Pstream::listCombineGather(counts, plusEqOp<scalar>());
    Pstream::listCombineScatter(counts);

    const SubField<scalar> escaped(counts, nPatches);
    const scalar lost = counts[nPatches];

    nRemovedLast_ = sum(escaped) + lost;
    nInflowLast_ = counts[nPatches + 1] - counts[nPatches + 2] + nRemovedLast_;
    nPresent_ = counts[nPatches + 1];

    nEscapedTotal_ += escaped;
    nLostTotal_ += lost;
    nInflowTotal_ += nInflowLast_;
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
    rndGen().reset(seed*1000003 + 500001 + Pstream::myProcNo());

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
                    const vector Ui =
                        U + equipartitionLinearVelocity(T, props.mass());
                    const scalar Ei = equipartitionInternalEnergy
                    (
                        T,
                        props.internalDegreesOfFreedom()
                    );

                    addNewParcel(position, celli, Ui, Ei, typeId);
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasCloud::gasCloud(const word& cloudName, const fvMesh& mesh)
:
    gasCloudInputCheck(cloudName, mesh),
    DSMCCloud<gasParcel>(cloudName, mesh, true),
    nEscapedStep_(mesh.boundaryMesh().size(), Zero),
    nEscapedTotal_(mesh.boundaryMesh().size(), Zero),
    nPresent_(returnReduce(this->size(), sumOp<label>()))
{
    seedFromCase();
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
    nEscapedStep_(mesh.boundaryMesh().size(), Zero),
    nEscapedTotal_(mesh.boundaryMesh().size(), Zero)
{
    fill(initialiseDict);
    nPresent_ = returnReduce(this->size(), sumOp<label>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasCloud::evolve()
{
    const label nBefore = this->size();

    nEscapedStep_ = Zero;
    nLostStep_ = 0;

    DSMCCloud<gasParcel>::evolve();

    accountStep(nBefore);
}


void Foam::gasCloud::info() const
{
    DSMCCloud<gasParcel>::info();

    const polyBoundaryMesh& patches = mesh().boundaryMesh();

    Info<< "    Simulators present              = " << nPresent_ << nl
        << "    Simulators in / out this step   = "
        << nInflowLast_ << " / " << nRemovedLast_ << nl
        << "    Simulators in / out since start = "
        << nInflowTotal_ << " / " << sum(nEscapedTotal_) + nLostTotal_
        << nl;

    forAll(nEscapedTotal_, patchi)
    {
        if (nEscapedTotal_[patchi] > 0)
        {
            Info<< "        out through " << patches[patchi].name()
                << " = " << nEscapedTotal_[patchi] << nl;
        }
    }

    if (nLostTotal_ > 0)
    {
        Info<< "        lost away from patches = " << nLostTotal_ << nl;
    }

    Info<< endl;
}


// ************************************************************************* //
