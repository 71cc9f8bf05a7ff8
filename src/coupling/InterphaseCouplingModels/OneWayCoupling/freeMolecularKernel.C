/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)

\*---------------------------------------------------------------------------*/

#include "freeMolecularKernel.H"
#include <cmath>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Vectorised only without errno from sqrt: Make/options has -fno-math-errno
__attribute__((target_clones("avx512f", "avx2", "default")))
void Foam::freeMolecularKernel::pairSums
(
    const scalar* __restrict ux,
    const scalar* __restrict uy,
    const scalar* __restrict uz,
    const scalar* __restrict W,
    const scalar* __restrict E,
    const label n,
    const scalar m,
    const scalar vx,
    const scalar vy,
    const scalar vz,
    scalar out[5]
)
{
    constexpr label L = lanes;
    const scalar halfM = 0.5*m;

    scalar fx[L] = {}, fy[L] = {}, fz[L] = {}, g[L] = {}, r[L] = {};
    for (label j = 0; j < n; j += L)
    {
        for (label k = 0; k < L; ++k)
        {
            const scalar wx = ux[j + k] - vx;
            const scalar wy = uy[j + k] - vy;
            const scalar wz = uz[j + k] - vz;
            const scalar s = wx*wx + wy*wy + wz*wz;
            const scalar a = W[j + k]*std::sqrt(s);
            fx[k] += a*wx;
            fy[k] += a*wy;
            fz[k] += a*wz;
            g[k] += a*(halfM*s + E[j + k]);
            r[k] += a;
        }
    }

    for (label i = 0; i < 5; ++i)
    {
        out[i] = 0;
    }
    for (label k = 0; k < L; ++k)
    {
        out[0] += fx[k];
        out[1] += fy[k];
        out[2] += fz[k];
        out[3] += g[k];
        out[4] += r[k];
    }
}


// ************************************************************************* //
