/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The start-up note on the OpenFOAM release (src/openfoam/settings/
    openfoamRelease.C), run by tests/openfoamReleases/checkReleaseNote.sh:
    its text for each pair of compiled and running releases, and, linked to
    the installed libOpenFOAM (v1912) with openfoamRelease.C compiled for the
    release given as argv[1] (-DOPENFOAM), the note logged once however
    often it is asked for. Exit 0 when all hold, 1 naming each that fails.

\*---------------------------------------------------------------------------*/

#include "openfoamRelease.H"
#include "foamVersion.H"
#include "OStringStream.H"

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{

int failures = 0;

void check(const bool ok, const std::string& what, const std::string& text)
{
    std::cout << (ok ? "ok " : "FAILED ") << what << '\n';
    if (!ok)
    {
        std::cout << "    the note was: \"" << text << "\"\n";
        ++failures;
    }
}

bool has(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

std::size_t count(const std::string& text, const std::string& part)
{
    std::size_t n = 0;
    for
    (
        std::size_t at = text.find(part);
        at != std::string::npos;
        at = text.find(part, at + 1)
    )
    {
        ++n;
    }
    return n;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    using Foam::dropletFiber::openfoamReleaseNote;
    if (argc != 2)
    {
        std::cout << "usage: releaseNoteTest <release openfoamRelease.C was compiled for>\n";
        return 1;
    }
    const int compiledFor = std::atoi(argv[1]);

    std::string note = openfoamReleaseNote(1912, 1912);
    check(note.empty(), "v1912 built and run: no note (the tested log unchanged)", note);

    note = openfoamReleaseNote(2312, 2312);
    check
    (
        has(note, "OpenFOAM: v2312") && !has(note, "Warning"),
        "v2312 built and run: the release named, no warning", note
    );

    note = openfoamReleaseNote(2312, 2506);
    check
    (
        has(note, "OpenFOAM: v2506")
     && has(note, "compiled for OpenFOAM v2312 but runs on v2506"),
        "built for v2312, run on v2506: the release and the mismatch", note
    );

    note = openfoamReleaseNote(2506, 1912);
    check
    (
        !has(note, "OpenFOAM: v") && has(note, "compiled for OpenFOAM v2506 but runs on v1912"),
        "built for v2506, run on v1912: the mismatch only", note
    );

    // The real thing: this libOpenFOAM's foamVersion::api against the OPENFOAM
    // openfoamRelease.C was compiled with, asked for three times
    Foam::OStringStream os;
    for (int i = 0; i < 3; ++i)
    {
        Foam::dropletFiber::reportOpenfoamRelease(os);
    }
    const std::string logged = os.str();
    const std::string expected =
        openfoamReleaseNote(compiledFor, Foam::foamVersion::api);
    check
    (
        logged == expected,
        "logged once: compiled for " + std::to_string(compiledFor)
      + ", running libOpenFOAM " + std::to_string(Foam::foamVersion::api),
        logged
    );
    if (compiledFor != Foam::foamVersion::api)
    {
        check
        (
            count(logged, "Warning") == 1,
            "a library built for another release is warned of, once", logged
        );
    }

    std::cout << (failures ? "FAILED" : "passed") << '\n';
    return failures ? 1 : 0;
}


// ************************************************************************* //
