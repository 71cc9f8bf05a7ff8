/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "RestartableStochastic.H"
#include "solidModelChecks.H"
#include "TimeScaleModel.H"
#include "cloudAverages.H"

// * * * * * * * * * * * * * * * Input checks  * * * * * * * * * * * * * * * //

template<class CloudType>
void Foam::IsotropyModels::RestartableStochastic<CloudType>::check
(
    const dictionary& subModels,
    const dictionary& cloudProperties
)
{
    solidChecks::timeScale(subModels.subDict(typeName + "Coeffs"));
    solidChecks::isotropyAveraging(cloudProperties, typeName);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::IsotropyModels::RestartableStochastic<CloudType>::RestartableStochastic
(
    const dictionary& dict,
    CloudType& owner
)
:
    IsotropyModel<CloudType>(dict, owner, typeName)
{}


template<class CloudType>
Foam::IsotropyModels::RestartableStochastic<CloudType>::RestartableStochastic
(
    const RestartableStochastic<CloudType>& cm
)
:
    IsotropyModel<CloudType>(cm)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::IsotropyModels::RestartableStochastic<CloudType>::calculate()
{
    CloudType& cloud = this->owner();
    Random& rnd = cloud.rndGen();
    const scalar dt = cloud.db().time().deltaTValue();

    using cloudAverages::find;
    using cloudAverages::make;
    const AveragingMethod<scalar>& mass = find<scalar>(cloud, "massAverage");
    const AveragingMethod<vector>& uMean = find<vector>(cloud, "uAverage");
    const AveragingMethod<scalar>& uSqr = find<scalar>(cloud, "uSqrAverage");

    // Probability of keeping the velocity over the step, exp(-dt/tau_c)
    autoPtr<AveragingMethod<scalar>> keep(make<scalar>(cloud, "keepAverage"));
    keep() =
        exp
        (
          - dt
           *this->timeScaleModel_->oneByTau
            (
                find<scalar>(cloud, "volumeAverage"),
                find<scalar>(cloud, "radiusAverage"),
                uSqr,
                find<scalar>(cloud, "frequencyAverage")
            )
        )();

    // 1. Redraw
    for (auto& p : cloud)
    {
        const tetIndices tetIs(p.currentTetIndices());
        const barycentric& x = p.coordinates();

        if (rnd.sample01<scalar>() > keep->interpolate(x, tetIs))
        {
            // Drawn one by one: the order of a constructor's arguments is
            // unspecified
            const scalar gx = rnd.GaussNormal<scalar>();
            const scalar gy = rnd.GaussNormal<scalar>();
            const scalar gz = rnd.GaussNormal<scalar>();
            const scalar sigma = sqrt(max(uSqr.interpolate(x, tetIs), 0)/3);

            p.U() = uMean.interpolate(x, tetIs) + sigma*vector(gx, gy, gz);
        }
    }

    // 2. The new mean and mean square fluctuation, back to the old ones
    autoPtr<AveragingMethod<vector>> uNew(make<vector>(cloud, "uRedrawn"));
    for (const auto& p : cloud)
    {
        uNew->add
        (
            p.coordinates(),
            p.currentTetIndices(),
            p.nParticle()*p.mass()*p.U()
        );
    }
    uNew->average(mass);

    autoPtr<AveragingMethod<scalar>> uSqrNew
    (
        make<scalar>(cloud, "uSqrRedrawn")
    );
    for (const auto& p : cloud)
    {
        const tetIndices tetIs(p.currentTetIndices());
        uSqrNew->add
        (
            p.coordinates(),
            tetIs,
            p.nParticle()*p.mass()
           *magSqr(p.U() - uNew->interpolate(p.coordinates(), tetIs))
        );
    }
    uSqrNew->average(mass);

    for (auto& p : cloud)
    {
        const tetIndices tetIs(p.currentTetIndices());
        const barycentric& x = p.coordinates();

        const scalar scale =
            sqrt
            (
                max(uSqr.interpolate(x, tetIs), 0)
               /max(uSqrNew->interpolate(x, tetIs), SMALL)
            );
        p.U() =
            uMean.interpolate(x, tetIs)
          + (p.U() - uNew->interpolate(x, tetIs))*scale;
    }
}


// ************************************************************************* //
