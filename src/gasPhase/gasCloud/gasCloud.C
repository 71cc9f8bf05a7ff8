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
    checkProperties(inputChecks::readCloudProperties(cloudName, mesh));
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
        checkProperties(inputChecks::readCloudProperties(cloudName, mesh))
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
    account_("Simulators", mesh.boundaryMesh(), this->size())
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
    account_("Simulators", mesh.boundaryMesh(), 0)
{
    fill(initialiseDict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasCloud::evolve()
{
    const label nBefore = this->size();

    DSMCCloud<gasParcel>::evolve();

    // Inflow is not reported by upstream's model: it is the balance
    account_.closeStep(nBefore, this->size());
}


void Foam::gasCloud::info() const
{
    DSMCCloud<gasParcel>::info();

    account_.info(mesh().boundaryMesh());
}


// ************************************************************************* //
