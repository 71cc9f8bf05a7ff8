/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam

Description
    Registers the interphase coupling models (SPEC.md section 4) for
    solidCloud, with gasCloud as the gas.

\*---------------------------------------------------------------------------*/

#include "solidCloud.H"
#include "gasCloud.H"

#include "InterphaseCouplingModel.H"
#include "NoInterphaseCoupling.H"
#include "OneWayCoupling.H"
#include "LothCoupling.H"
#include "AdaptiveCoupling.H"
#include "TwoWayDirectCoupling.H"
#include "TwoWayIndirectCoupling.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeInterphaseCouplingModel(solidCloud);

makeInterphaseCouplingModelType(NoInterphaseCoupling, solidCloud);
makeInterphaseCouplingModelType(OneWayCoupling, solidCloud);
makeInterphaseCouplingModelType(LothCoupling, solidCloud);
makeInterphaseCouplingModelType(AdaptiveCoupling, solidCloud);
makeInterphaseCouplingModelType(TwoWayDirectCoupling, solidCloud);
makeInterphaseCouplingModelType(TwoWayIndirectCoupling, solidCloud);


// ************************************************************************* //
