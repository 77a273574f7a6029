/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "openfoamRelease.H"
#include "foamVersion.H"

#include <string>

// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

std::string Foam::dropletFiber::openfoamReleaseNote
(
    const int compiled,
    const int running
)
{
    const std::string tested = "v" + std::to_string(testedOpenfoamRelease);
    std::string note;
    if (running != testedOpenfoamRelease)
    {
        note +=
            "    OpenFOAM: v" + std::to_string(running)
          + " (dropletFiber's results are tested on " + tested
          + "; v2312 and v2506 are checked to compile only)\n";
    }
    if (compiled != running)
    {
        note +=
            "    Warning: this libdropletFiber.so was compiled for OpenFOAM v"
          + std::to_string(compiled) + " but runs on v" + std::to_string(running)
          + ": build it again (./Allwmake) with this OpenFOAM's environment"
            " loaded\n";
    }
    return note;
}


void Foam::dropletFiber::reportOpenfoamRelease(Ostream& os)
{
    static bool reported = false;
    if (reported)
    {
        return;
    }
    reported = true;
    // OPENFOAM: this library's release (wmake's -DOPENFOAM); foamVersion::api:
    // the release of the libOpenFOAM.so that loaded it
    os  << openfoamReleaseNote(OPENFOAM, foamVersion::api).c_str();
}


// ************************************************************************* //
