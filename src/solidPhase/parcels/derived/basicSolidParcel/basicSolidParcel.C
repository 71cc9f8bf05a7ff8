/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "basicSolidParcel.H"
#include "Cloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    // The names written in the cloud's files are the ones cases have
    // always carried ("Cloud<solidParcel>"), so existing runs restart
    defineTemplateTypeNameAndDebugWithName(basicSolidParcel, "solidParcel", 0);
    defineTemplateTypeNameAndDebugWithName
    (
        Cloud<basicSolidParcel>,
        "Cloud<solidParcel>",
        0
    );
}


// ************************************************************************* //
