/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "vibrationalModes.H"
#include "fundamentalConstants.H"
#include "physicoChemicalConstants.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::word Foam::vibrationalModes::modesKeyword("vibrationalModes");

const Foam::word Foam::vibrationalModes::relaxationKeyword
(
    "vibrationalRelaxationCollisionNumber"
);

namespace
{
    // The grid of the phi tables: ln(x) evenly from xMin to xMax, held
    // outside
    const Foam::scalar xMin = 0.05;
    const Foam::scalar xMax = 30;
    const Foam::label nGrid = 48;
    const Foam::scalar dLnX = std::log(xMax/xMin)/(nGrid - 1);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::vibrationalModes::deficitFraction
(
    const scalar x,
    const scalar a
)
{
    // Mean new level of a cold oscillator (E_c = E_t, in units of kT),
    // over E_t distributed as E_t^a exp(-E_t) (midpoint rule, 45 kT)
    const label n = 8000;
    const scalar h = 45.0/n;
    scalar level = 0;
    scalar norm = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar E = (i + 0.5)*h;
        const scalar w = std::pow(E, a)*std::exp(-E);
        const label jMax = label(E/x);
        scalar s0 = 0;
        scalar s1 = 0;
        for (label j = 0; j <= jMax; ++j)
        {
            const scalar pj = std::pow(1 - j*x/E, a);
            s0 += pj;
            s1 += j*pj;
        }
        level += w*s1/s0;
        norm += w;
    }

    // Over the equilibrium mean level 1/(e^x - 1)
    return level/norm*std::expm1(x);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::vibrationalModes::vibrationalModes
(
    const dictionary& moleculeProperties,
    const wordList& species,
    const scalarList& omega
)
:
    modeNames_(species.size()),
    modeTheta_(species.size()),
    degeneracy_(species.size()),
    theta_(species.size()),
    mode_(species.size()),
    Zv_(species.size(), Zero),
    phi_(species.size()),
    maxOscillators_(0)
{
    // (values checked by gasCloudInputCheck)
    forAll(species, p)
    {
        const dictionary& props = moleculeProperties.subDict(species[p]);
        const dictionary modes(props.subOrEmptyDict(modesKeyword));
        if (modes.empty())
        {
            continue;
        }

        Zv_[p] = props.get<scalar>(relaxationKeyword);
        modeNames_[p] = modes.toc();

        DynamicList<scalar> theta;
        DynamicList<label> mode;
        forAll(modeNames_[p], m)
        {
            const dictionary& d = modes.subDict(modeNames_[p][m]);
            const scalar t = d.get<scalar>("temperature");
            const label g = d.getOrDefault<label>("degeneracy", 1);
            modeTheta_[p].append(t);
            degeneracy_[p].append(g);
            for (label k = 0; k < g; ++k)
            {
                theta.append(t);
                mode.append(m);
            }
        }
        theta_[p] = theta;
        mode_[p] = mode;
        maxOscillators_ = max(maxOscillators_, theta_[p].size());

        // phi against every partner, on the grid of ln(x)
        phi_[p].setSize(species.size());
        forAll(species, q)
        {
            const scalar a = 1.5 - 0.5*(omega[p] + omega[q]);
            scalarList& table = phi_[p][q];
            table.setSize(nGrid);
            forAll(table, i)
            {
                table[i] = deficitFraction(xMin*std::exp(i*dLnX), a);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::vibrationalModes::oscillators
(
    const dictionary& moleculeProperties,
    const wordList& species
)
{
    labelList n(species.size(), Zero);
    forAll(species, p)
    {
        const dictionary modes
        (
            moleculeProperties.subDict(species[p]).subOrEmptyDict
            (
                modesKeyword
            )
        );
        for (const word& name : modes.toc())
        {
            n[p] += modes.subDict(name).getOrDefault<label>("degeneracy", 1);
        }
    }
    return n;
}


Foam::scalar Foam::vibrationalModes::energy
(
    const label typei,
    const labelList& levels
) const
{
    const scalarList& theta = theta_[typei];
    scalar sum = 0;
    forAll(levels, k)
    {
        sum += levels[k]*theta[k];
    }
    return constant::physicoChemical::k.value()*sum;
}


Foam::scalar Foam::vibrationalModes::equilibriumEnergy
(
    const label typei,
    const scalar T
) const
{
    if (!(T > 0))
    {
        return 0;
    }
    scalar sum = 0;
    for (const scalar theta : theta_[typei])
    {
        sum += theta/std::expm1(theta/T);
    }
    return constant::physicoChemical::k.value()*sum;
}


void Foam::vibrationalModes::draw
(
    const label typei,
    const scalar T,
    Random& rnd,
    labelList& levels
) const
{
    const scalarList& theta = theta_[typei];
    levels.setSize(theta.size());
    forAll(theta, k)
    {
        // Geometric: floor(ln U/ln q) with ln q = -theta/T
        levels[k] =
            T > 0
          ? label(-std::log(1 - rnd.sample01<scalar>())*T/theta[k])
          : 0;
    }
}


Foam::scalar Foam::vibrationalModes::selection
(
    const label p,
    const label q,
    const scalar theta,
    const scalar T
) const
{
    const scalarList& table = phi_[p][q];
    const scalar x = T > 0 ? theta/T : GREAT;

    // Held outside the table (below xMin phi is within 0.5 % of its
    // classical limit (a + 1)/(a + 2), a = 3/2 - omega)
    scalar phi = table[0];
    if (x >= xMax)
    {
        phi = table.last();
    }
    else if (x > xMin)
    {
        const scalar s = std::log(x/xMin)/dLnX;
        const label i = min(label(s), nGrid - 2);
        const scalar f = s - i;
        phi = (1 - f)*table[i] + f*table[i + 1];
    }

    return min(scalar(1), 1/(Zv_[p]*phi));
}


Foam::scalar Foam::vibrationalModes::modeTemperature
(
    const scalar theta,
    const label g,
    const scalar level
)
{
    // Mean level sum of g oscillators: g/(exp(theta/T) - 1)
    return level > 0 ? theta/std::log1p(g/level) : 0;
}


Foam::scalar Foam::vibrationalModes::modeDof
(
    const scalar theta,
    const label g,
    const scalar level
)
{
    return level > 0 ? 2*level*std::log1p(g/level) : 0;
}


// ************************************************************************* //
