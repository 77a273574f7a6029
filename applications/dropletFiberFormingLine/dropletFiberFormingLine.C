/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Application
    dropletFiberFormingLine

Description
    The mat of a forming line: k hoods laying onto one belt, built from the
    mat one hood laid (docs/model.md sec. 11, P62). Reads the mat of the
    function object's restart state at a time (the map's cells with their
    error sums, the laying zone, the belt), takes its complete rows (P48)
    and lays k of them, `shift` rows apart, onto each row of the line. Prints
    for the hood and for the line the glass area weight and the LOI of the
    complete rows with their standard errors, and the across-width CoV split
    into counting noise and the mat's own (P60, P61); writes the profiles
    across the width to postProcessing/formingLine/<time>/profile.dat.

    The k hoods stand at the same place across, each a realisation of the
    same steady laying: the line's LOI and its own CoV are the hood's, its
    area weight k times, the counting noise 1/sqrt(k) of the hood's.

Usage
    \b dropletFiberFormingLine [OPTION]

    Options:
      - \par -hoods \<k\>
        The hoods of the line (default 3)

      - \par -shift \<rows\>
        The rows of the hood's mat between two hoods' crossings (default:
        the complete rows over k, spread evenly)

      - \par -name \<name\>
        The dropletFiberCollision function object (default dropletFiber)

      - \par -time \<time\>
        The time whose restart state is read (default: the latest with one)

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "matCellsIO.H"

#include "laydown/FormingLine.hpp"
#include "laydown/LayingZone.hpp"
#include "laydown/MatUncertainty.hpp"

#include <stdexcept>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

//- The restart state of function object `name` at `timeName`: in the case
//  (a serial run, or reconstructed) or in processor0 (the mat is the same on
//  every processor); empty when none
fileName statePath(const fileName& caseDir, const word& timeName, const word& name)
{
    for (const fileName& dir : {caseDir, caseDir/"processor0"})
    {
        const fileName path = dir/timeName/"uniform"/"dropletFiber"/name;
        if (isFile(path))
        {
            return path;
        }
    }
    return fileName::null;
}


//- The hood's mat from the state's laydown entry
::dropletFiber::MatMap readMat(const dictionary& mat, const fileName& path)
{
    ::dropletFiber::MatMap map
    (
        mat.get<scalar>("cell"), mat.get<scalar>("acrossMin"),
        mat.get<scalar>("acrossMax")
    );
    Foam::dropletFiber::readMatCells(mat, path, map);
    return map;
}

//- The time to read: -time, or the latest whose state exists
word stateTime(const argList& args, const word& name)
{
    if (args.found("time"))
    {
        return args.opt<word>("time");
    }
    instantList times = Time::findTimes(args.path());
    if (Foam::isDir(args.path()/"processor0"))
    {
        times.append(Time::findTimes(args.path()/"processor0"));
    }
    word timeName;
    scalar latest = -GREAT;
    for (const instant& t : times)
    {
        if (t.value() > latest && !statePath(args.path(), t.name(), name).empty())
        {
            latest = t.value();
            timeName = t.name();
        }
    }
    return timeName;
}


//- The laying zone from the state's laydown entry
::dropletFiber::LayingZone readZone(const dictionary& mat)
{
    ::dropletFiber::LayingZone zone;
    zone.firstTime = mat.get<scalar>("firstTime");
    zone.footMin = mat.get<scalar>("footMin");
    zone.footMax = mat.get<scalar>("footMax");
    zone.reach = mat.get<scalar>("footReach");
    return zone;
}


//- The state's mat, with its error sums and belt
const dictionary* laydownEntry(const dictionary& state, const fileName& path)
{
    const dictionary* mat = state.findDict("laydown");
    if (!mat || !mat->found("cellErrorSums") || !mat->found("beltSpeed"))
    {
        FatalIOErrorInFunction(state)
            << "The restart state " << path << " has no mat with error sums"
            << " and belt (fibers.laydown, written by this version): run the"
            << " case with fibers.laydown." << exit(FatalIOError);
    }
    return mat;
}


//- The log's lines of a mat over rows [from, to]
void report(const word& what, const ::dropletFiber::AcrossProfile& profile)
{
    const ::dropletFiber::NonUniformity u = ::dropletFiber::nonUniformity(profile);
    Info<< "    " << what << ": glass area weight " << 1000*u.mean << " +- "
        << 1000*Foam::sqrt(profile.meanVariance) << " g/m2, LOI "
        << 100*profile.loiAll.value << " +- " << 100*profile.loiAll.error
        << " %, across-width CoV " << u.observed << " (counting noise "
        << u.noise << ", the mat's own " << u.real << ", two-sigma bound "
        << u.realUpper << ")" << nl;
}


//- The profiles across the width, one row per column
void writeProfiles
(
    const fileName& file,
    const ::dropletFiber::MatMap& hood,
    const ::dropletFiber::AcrossProfile& one,
    const ::dropletFiber::AcrossProfile& line,
    const label hoods
)
{
    OFstream os(file);
    os  << "# The mat across the belt's width: one hood and a line of " << hoods
        << " (dropletFiberFormingLine); area weight [g/m2] and LOI [%] with their"
        << " standard errors" << nl
        << "# across\thoodAreaWeight\thoodAreaWeightError\thoodLOI\thoodLOIError"
        << "\tlineAreaWeight\tlineAreaWeightError\tlineLOI\tlineLOIError" << nl;
    for (std::size_t k = 0; k < one.areaWeight.size(); ++k)
    {
        const scalar i = scalar(k);
        os  << hood.acrossMin() + (i + 0.5)*hood.cell()
            << tab << 1000*one.areaWeight[k].value << tab << 1000*one.areaWeight[k].error
            << tab << 100*one.loi[k].value << tab << 100*one.loi[k].error
            << tab << 1000*line.areaWeight[k].value << tab << 1000*line.areaWeight[k].error
            << tab << 100*line.loi[k].value << tab << 100*line.loi[k].error << nl;
    }
}


// * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "The mat of a forming line of k hoods from the mat one hood laid"
        " (the dropletFiberCollision restart state): area weight, LOI and"
        " across-width CoV with their errors"
    );
    argList::noParallel();
    argList::addOption("hoods", "k", "the hoods of the line (default 3)");
    argList::addOption("shift", "rows", "rows between two hoods' crossings");
    argList::addOption("name", "name", "the function object (default dropletFiber)");
    argList::addOption("time", "time", "the time to read (default: the latest)");
    #include "setRootCase.H"
    #include "createTime.H"

    const word name = args.opt<word>("name", "dropletFiber");
    const label hoods = args.opt<label>("hoods", 3);
    if (hoods < 1)
    {
        FatalErrorInFunction
            << "Option -hoods is " << hoods << ": allowed are 1 or more."
            << exit(FatalError);
    }
    const word timeName = stateTime(args, name);
    const fileName path =
        timeName.empty() ? fileName::null : statePath(args.path(), timeName, name);
    if (path.empty())
    {
        FatalErrorInFunction
            << "No restart state of function object '" << name << "'"
            << (args.found("time") ? string(" at time " + timeName) : string())
            << " in " << args.path() << " (or processor0): allowed are a"
            << " dropletFiberCollision's -name and a time it wrote."
            << exit(FatalError);
    }
    IFstream is(path);
    const dictionary state(is);
    const dictionary* mat = laydownEntry(state, path);
    const ::dropletFiber::LayingZone zone = readZone(*mat);
    const ::dropletFiber::MatMap hood = readMat(*mat, path);
    const std::pair<long, long> rows = zone.completeRows
    (
        mat->get<scalar>("beltSpeed"), hood.cell(), mat->get<scalar>("steadyFrom"),
        readScalar(timeName)
    );
    const long n = rows.second - rows.first + 1;
    const long shift = args.opt<label>("shift", ::dropletFiber::evenShift(n, hoods));
    Info<< "Forming line of " << hoods << " hoods from " << path << ": the hood's"
        << " complete rows " << rows.first << " to " << rows.second << " (" << max(n, 0L)
        << "), the hoods " << shift << " rows apart" << nl;
    try
    {
        const ::dropletFiber::MatMap line =
            ::dropletFiber::formingLine(hood, rows.first, rows.second, int(hoods), shift);
        const auto one = ::dropletFiber::acrossProfileWithErrors(hood, rows.first, rows.second);
        const auto all = ::dropletFiber::acrossProfileWithErrors(line, rows.first, rows.second);
        report("one hood", one);
        report("the line of " + Foam::name(hoods), all);
        const fileName dir = args.path()/"postProcessing"/"formingLine"/timeName;
        mkDir(dir);
        writeProfiles(dir/"profile.dat", hood, one, all, hoods);
        Info<< "    profiles across: " << dir/"profile.dat" << nl;
    }
    catch (const std::invalid_argument& e)
    {
        FatalErrorInFunction
            << e.what() << " (option -hoods " << hoods << ", -shift " << shift
            << "): run the case longer (its mat's complete rows grow by V dt"
            << " a step), or give fewer hoods or a smaller shift."
            << exit(FatalError);
    }
    Info<< nl << "End" << nl << endl;
    return 0;
}

// ************************************************************************* //
