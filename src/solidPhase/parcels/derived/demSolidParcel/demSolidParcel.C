/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "demSolidParcel.H"
#include "Cloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTemplateTypeNameAndDebugWithName
    (
        demSolidParcel, "demSolidParcel", 0
    );
    defineTemplateTypeNameAndDebugWithName
    (
        Cloud<demSolidParcel>,
        "Cloud<demSolidParcel>",
        0
    );
}


// ************************************************************************* //
