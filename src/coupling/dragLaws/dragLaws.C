/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "dragLaws.H"
#include "mathematicalConstants.H"

#include <cmath>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;

constexpr scalar pi = Foam::constant::mathematical::pi;

//- Number of terms of the small-s series
constexpr int nSeries = 8;

//- Coefficients c_m, m = 1..nSeries, of
//      sqrt(pi) s [A(s) + B(s)] = sum_m c_m s^(2m - 2),
//  A = e^(-s^2)(1 + 2 s^2)/(sqrt(pi) s^3),
//  B = erf(s)(4 s^4 + 4 s^2 - 1)/(2 s^4).
//  With e^(-x) = sum (-x)^k/k! and erf(s) = (2/sqrt(pi)) sum (-1)^n
//  s^(2n+1)/(n! (2n+1)):
//      sqrt(pi) A = sum_k (-1)^k (1 - 2k)/k! s^(2k-3),
//      sqrt(pi) B = sum_n (-1)^n/(n! (2n+1))
//                   (4 s^(2n+1) + 4 s^(2n-1) - s^(2n-3)),
//  and the power s^(2m-3) collects k = m and n = m, m-1, m-2.  For m = 0
//  the two give 1 - 1 = 0 (the 1/s^3 terms cancel); c_1 = 16/3,
//  c_2 = 16/15, c_3 = -8/105, ...
struct seriesCoefficients
{
    scalar c[nSeries];

    seriesCoefficients()
    {
        // factorial[j] = j!
        scalar factorial[nSeries + 1];
        factorial[0] = 1;
        for (int j = 1; j <= nSeries; ++j)
        {
            factorial[j] = factorial[j - 1]*j;
        }

        for (int m = 1; m <= nSeries; ++m)
        {
            const scalar sign = (m % 2 ? -1 : 1);    // (-1)^m
            scalar cm =
                sign*(1 - 2*m)/factorial[m]         // A, k = m
              - sign/(factorial[m]*(2*m + 1));      // B, n = m: -s^(2n-3)
            // B, n = m-1: 4 s^(2n-1)
            cm += -sign*4/(factorial[m - 1]*(2*m - 1));
            if (m >= 2)
            {
                // B, n = m-2: 4 s^(2n+1)
                cm += sign*4/(factorial[m - 2]*(2*m - 3));
            }
            c[m - 1] = cm;
        }
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Dimensionless groups  * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::speedRatio(const scalar Ma, const scalar gamma)
{
    return Ma*std::sqrt(0.5*gamma);
}


Foam::scalar Foam::dragLaws::knudsen
(
    const scalar Re,
    const scalar Ma,
    const scalar gamma
)
{
    return std::sqrt(0.5*pi*gamma)*Ma/Re;
}


// * * * * * * * * * * * * * * * Free-molecular sphere  * * * * * * * * * * //

Foam::scalar Foam::dragLaws::sFreeMolecularCd
(
    const scalar s,
    const scalar TpByTg
)
{
    // Re-emission at T_p: regular at s = 0 once multiplied by s
    const scalar wall = (2*std::sqrt(pi)/3)*std::sqrt(TpByTg);

    if (s < freeMolecularSeriesMax)
    {
        static const seriesCoefficients series;

        // Horner in x = s^2
        const scalar x = s*s;
        scalar sum = series.c[nSeries - 1];
        for (int m = nSeries - 2; m >= 0; --m)
        {
            sum = sum*x + series.c[m];
        }
        return sum/std::sqrt(pi) + wall;
    }

    const scalar s2 = s*s;
    const scalar s4 = s2*s2;
    return
        std::exp(-s2)*(2*s2 + 1)/(std::sqrt(pi)*s2)
      + std::erf(s)*(4*s4 + 4*s2 - 1)/(2*s2*s)
      + wall;
}


Foam::scalar Foam::dragLaws::freeMolecularCd
(
    const scalar s,
    const scalar TpByTg
)
{
    return sFreeMolecularCd(s, TpByTg)/s;
}


// * * * * * * * * * * * * * * * * Loth drag  * * * * * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::lothCM(const scalar Ma)
{
    if (Ma <= 1.45)
    {
        return 5.0/3.0 + (2.0/3.0)*std::tanh(3*std::log(Ma + 0.1));
    }
    const scalar l = std::log(Ma/1.5);
    return 2.044 + 0.2*std::exp(-1.8*l*l);
}


Foam::scalar Foam::dragLaws::lothGM(const scalar Ma)
{
    if (Ma <= 0.89)
    {
        const scalar Ma2 = Ma*Ma;
        return 1 - 1.525*Ma2*Ma2;
    }
    return 0.0002 + 0.0008*std::tanh(12.77*(Ma - 2.02));
}


Foam::scalar Foam::dragLaws::lothHM(const scalar Ma)
{
    return 1 - 0.258*lothCM(Ma)/(1 + 514*lothGM(Ma));
}


Foam::scalar Foam::dragLaws::lothCdRarefied
(
    const scalar Re,
    const scalar Ma,
    const scalar gamma,
    const scalar TpByTg
)
{
    const scalar Kn = knudsen(Re, Ma, gamma);
    const scalar s = speedRatio(Ma, gamma);

    // Kn = 0 (Ma = 0): no slip correction, and no 0.55/0
    const scalar fKn =
        Kn > 0 ? 1/(1 + Kn*(2.514 + 0.8*std::exp(-0.55/Kn))) : 1;
    const scalar CdKnRe = 24/Re*(1 + 0.15*std::pow(Re, 0.687))*fKn;

    // 1/C_D,fm = s/(s C_D,fm): 0 at s = 0, where C_D,fm,Re -> 1.63 sqrt(45/Re)
    const scalar invCdFm = s/sFreeMolecularCd(s, TpByTg);
    const scalar CdFmRe =
        1/(invCdFm + (1/1.63 - invCdFm)*std::sqrt(Re/45));

    const scalar Ma2 = Ma*Ma;
    const scalar Ma4 = Ma2*Ma2;
    return (CdKnRe + Ma4*CdFmRe)/(1 + Ma4);
}


Foam::scalar Foam::dragLaws::lothCdCompression
(
    const scalar Re,
    const scalar Ma
)
{
    const scalar CM = lothCM(Ma);
    const scalar GM = lothGM(Ma);
    const scalar HM = 1 - 0.258*CM/(1 + 514*GM);

    return
        24/Re*(1 + 0.15*std::pow(Re, 0.687))*HM
      + 0.42*CM/(1 + 42500*GM/std::pow(Re, 1.16));
}


Foam::scalar Foam::dragLaws::lothCd
(
    const scalar Re,
    const scalar Ma,
    const scalar gamma,
    const scalar TpByTg
)
{
    return
        Re < 45
      ? lothCdRarefied(Re, Ma, gamma, TpByTg)
      : lothCdCompression(Re, Ma);
}


// * * * * * * * * * * * * * * * * Loth lift  * * * * * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::lothCl(const scalar Re, const scalar omegaStar)
{
    if (omegaStar <= 0)
    {
        return 0;
    }

    // Saffman's shear parameter sqrt(omega*/Re)
    const scalar eps = std::sqrt(omegaStar/Re);

    const scalar J =
        0.3
       *(1 + std::tanh(2.5*(std::log10(eps) + 0.191)))
       *(2.0/3.0 + std::tanh(6*eps - 1.92));

    const scalar spin = 0.5*omegaStar;
    const scalar ClSpin =
        1
      - (0.675 + 0.15*(1 + std::tanh(0.28*(spin - 2))))
       *std::tanh(0.18*std::sqrt(Re));

    return (12.92/pi)*J*eps + spin*ClSpin;
}


// * * * * * * * * * * * * * * * * Heat transfer  * * * * * * * * * * * * * //

Foam::scalar Foam::dragLaws::nusseltContinuum
(
    const scalar Re,
    const scalar Pr
)
{
    return 2 + 0.6*std::sqrt(Re)*std::cbrt(Pr);
}


Foam::scalar Foam::dragLaws::nusseltFreeMolecular
(
    const scalar Kn,
    const scalar Pr,
    const scalar gamma,
    const scalar alphaT
)
{
    return alphaT*(gamma + 1)*Pr/(4*gamma*Kn);
}


Foam::scalar Foam::dragLaws::nusselt
(
    const scalar Re,
    const scalar Ma,
    const scalar Pr,
    const scalar gamma,
    const scalar alphaT
)
{
    const scalar NuC = nusseltContinuum(Re, Pr);

    // Nu_c/Nu_fm without the division by alpha_T (which may be 0)
    const scalar b =
        NuC*4*gamma*knudsen(Re, Ma, gamma)/((gamma + 1)*Pr);

    if (alphaT + b <= 0)
    {
        return NuC;   // Kn = 0 and alpha_T = 0: continuum
    }
    return NuC*alphaT/(alphaT + b);
}


// ************************************************************************* //
