/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
  Copyright (C) 2026 The rarefiedMultiphaseFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
\*---------------------------------------------------------------------------*/

#include "writeGuard.H"
#include "OSspecific.H"
#include "OFstream.H"
#include "IFstream.H"
#include "Pstream.H"
#include "regIOobject.H"

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The message of the SIGXFSZ handler, set at each write time (the handler
// may only copy it out)
char xfszMessage[256] = "file size limit exceeded while writing\n";

extern "C" void fileSizeExceeded(int)
{
    const ssize_t n = ::write(2, xfszMessage, std::strlen(xfszMessage));
    (void)n;
    ::_exit(1);
}


fileName marker(const fileName& timePath)
{
    return timePath/"uniform"/"writing";
}


// The test hook's object (writeGuard.H): writing it kills the process
class killWhileWriting
:
    public regIOobject
{
public:

    explicit killWhileWriting(const IOobject& io)
    :
        regIOobject(io)
    {}

    bool writeData(Ostream&) const
    {
        return true;
    }

    bool writeObject
    (
        IOstream::streamFormat,
        IOstream::versionNumber,
        IOstream::compressionType,
        const bool
    ) const
    {
        std::raise(SIGKILL);
        return false;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::writeGuard::skipIncomplete(const argList& args)
{
    std::signal(SIGXFSZ, fileSizeExceeded);

    const fileName controlDict
    (
        args.rootPath()/args.globalCaseName()/"system"/"controlDict"
    );
    IFstream is(controlDict);
    if (!is.good())
    {
        return;
    }
    const dictionary dict(is);
    if (dict.getOrDefault<word>("startFrom", "latestTime") != "latestTime")
    {
        return;
    }

    // Latest time whose write finished here, then on every processor
    const instantList times(Time::findTimes(args.path()));
    scalar start = -GREAT;
    for (label i = times.size() - 1; i >= 0; --i)
    {
        if (!isFile(marker(args.path()/times[i].name())))
        {
            start = times[i].value();
            break;
        }
    }
    if (Pstream::parRun())
    {
        reduce(start, minOp<scalar>());
    }

    for (const instant& t : times)
    {
        if (t.value() > start)
        {
            const fileName dir(args.path()/t.name());
            Pout<< "--> writeGuard: time directory " << dir
                << (isFile(marker(dir)) ? " was not written to the end" :
                    " is complete here but not on every processor")
                << " (the run stopped while writing it): set aside as "
                << t.name() << ".incomplete; the run starts from the"
                << " latest complete time" << endl;
            mvBak(dir, "incomplete");
        }
    }
}


void Foam::writeGuard::begin(const Time& runTime)
{
    if (!runTime.writeTime())
    {
        return;
    }

    const fileName path(marker(runTime.timePath()));
    mkDir(path.path());
    OFstream(path)() << "being written" << nl;

    const char* killAt = std::getenv("RMF_TEST_KILL_WHILE_WRITING");
    if (killAt && runTime.timeName() == killAt)
    {
        regIOobject::store
        (
            new killWhileWriting
            (
                IOobject
                (
                    "writeGuardKillWhileWriting",
                    runTime.timeName(),
                    runTime,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                )
            )
        );
        Info<< "--> writeGuard: test hook RMF_TEST_KILL_WHILE_WRITING: the"
            << " process kills itself while writing time "
            << runTime.timeName() << endl;
    }

    std::snprintf
    (
        xfszMessage, sizeof(xfszMessage),
        "\n--> FOAM FATAL ERROR: file size limit exceeded (ulimit -f) while"
        " writing time %s in %s; its directory is set aside at the next"
        " restart, the earlier ones are intact\n",
        runTime.timeName().c_str(), runTime.path().c_str()
    );
}


void Foam::writeGuard::end(const Time& runTime, const bool written)
{
    if (!runTime.writeTime())
    {
        return;
    }

    if (!returnReduce(written, andOp<bool>()))
    {
        FatalErrorInFunction
            << "Writing time " << runTime.timeName() << " failed (a full"
            << " disk or a file-size limit?); its directory stays marked"
            << " and is set aside at the next restart, the earlier ones"
            << " are intact" << exit(FatalError);
    }

    rm(marker(runTime.timePath()));
}


// ************************************************************************* //
