/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
\*---------------------------------------------------------------------------*/

#include "SolidParcel.H"
#include "processorPolyPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::SolidParcel<ParcelType>::constantProperties::constantProperties()
:
    ParcelType::constantProperties(),
    T0_(this->dict_, 0.0),
    Cp0_(this->dict_, 0.0),
    specularFraction_(this->dict_, 0.0),
    thermalAccommodation_(this->dict_, 0.0)
{}


template<class ParcelType>
Foam::SolidParcel<ParcelType>::constantProperties::constantProperties
(
    const constantProperties& cp
)
:
    ParcelType::constantProperties(cp),
    T0_(cp.T0_),
    Cp0_(cp.Cp0_),
    specularFraction_(cp.specularFraction_),
    thermalAccommodation_(cp.thermalAccommodation_)
{}


template<class ParcelType>
Foam::SolidParcel<ParcelType>::constantProperties::constantProperties
(
    const dictionary& parentDict
)
:
    ParcelType::constantProperties(parentDict),
    T0_(this->dict_, "T0"),
    Cp0_(this->dict_, "Cp0"),
    specularFraction_(this->dict_, "specularFraction"),
    thermalAccommodation_(this->dict_, "thermalAccommodation")
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
bool Foam::SolidParcel<ParcelType>::hitPatch
(
    TrackCloudType& cloud,
    typename ParcelType::trackingData& td
)
{
    const bool handled = ParcelType::hitPatch(cloud, td);

    // Processor patches hand the parcel on; any other patch that ends its
    // life (escape, or a stick/none model deleting it) counts as its exit
    if (!td.keepParticle && !td.switchProcessor)
    {
        ++cloud.account().escapedStep()[this->patch()];
    }

    return handled;
}


// * * * * * * * * * * * * * * * * * * IO  * * * * * * * * * * * * * * * * * //

#include "SolidParcelIO.C"

// ************************************************************************* //
