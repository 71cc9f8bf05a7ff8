/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "progressReport.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::progressReport::progressReport(const Time& runTime)
:
    runTime_(runTime),
    startTime_(runTime.value()),
    wallStart_(runTime.elapsedClockTime())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::progressReport::report() const
{
    const scalar span = runTime_.endTime().value() - startTime_;
    const scalar done = runTime_.value() - startTime_;
    const double wall = runTime_.elapsedClockTime() - wallStart_;
    const scalar fraction = span > 0 ? done/span : 1;
    const double left =
        fraction > 0 ? wall*(1 - fraction)/fraction : 0;

    Info<< "Progress: t = " << runTime_.timeName()
        << " (" << label(100*fraction + 0.5) << "%), ExecutionTime = "
        << runTime_.elapsedCpuTime() << " s  ClockTime = "
        << runTime_.elapsedClockTime() << " s  left ~ "
        << label(left + 0.5) << " s" << nl << endl;
}


// ************************************************************************* //
