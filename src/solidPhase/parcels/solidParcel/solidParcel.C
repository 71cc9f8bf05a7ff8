/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
\*---------------------------------------------------------------------------*/

#include "solidParcel.H"
#include "Cloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTemplateTypeNameAndDebug(solidParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<solidParcel>, 0);
}


// ************************************************************************* //
