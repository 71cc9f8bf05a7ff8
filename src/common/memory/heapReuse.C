/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "heapReuse.H"

#include <climits>
#include <malloc.h>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::heapReuse()
{
    // No block mapped on its own (every one from the heap), and the free
    // memory at the heap's top kept up to the largest threshold allowed
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, INT_MAX);
}


// ************************************************************************* //
