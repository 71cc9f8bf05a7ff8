/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
\*---------------------------------------------------------------------------*/

#include "gasParcel.H"
#include "gasCloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

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
    nLost_(owner(cloud).account().lostStep())
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


// ************************************************************************* //
