/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The output's settings, the VTK files' folder and series, the mass
    balances in the log.

\*---------------------------------------------------------------------------*/

#include "couplingOutput.H"
#include "dictionaryChecks.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- dict with the per-step table's writePrecision: the entry, else 10 (more
//  digits than OpenFOAM's default: the table is compared across runs).
//  writeFile opens the table in its constructor with the precision in force
//  then, so the constructor must be given this too.
Foam::dictionary tableFileDict(const Foam::dictionary& dict)
{
    Foam::dictionary fileDict(dict);
    if (!fileDict.found("writePrecision"))
    {
        fileDict.add("writePrecision", 10);
    }
    return fileDict;
}


//- The ParaView series index of stem's files in dir: ParaView picks the
//  reader of a series by the extension before ".series", so a parallel
//  run's index, which lists the pieces' indices (.pvtp, .pvti), is named by
//  them. One of a parallel run written before (named .vtp, .vti) is renamed
//  so that a restart continues it (the master's: only it writes the index)
Foam::fileName seriesPath
(
    const Foam::fileName& dir,
    const Foam::word& stem,
    const Foam::word& extension
)
{
    using namespace Foam;
    if (!Pstream::parRun())
    {
        return dir/stem + "." + extension + ".series";
    }
    const fileName path = dir/stem + ".p" + extension + ".series";
    const fileName earlier = dir/stem + "." + extension + ".series";
    if (Pstream::master() && !isFile(path) && isFile(earlier))
    {
        mv(earlier, path);
    }
    return path;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::couplingOutput::couplingOutput
(
    const functionObject& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    couplingStage(owner, mesh),
    writeFile(mesh, owner.name(), "dropletFiber", tableFileDict(dict)),
    writeVtk_(true),
    writeGridVtk_(true)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dropletFiber::couplingOutput::read(const dictionary& dict)
{
    writeFile::read(tableFileDict(dict));
    writeVtk_ = getSwitch(dict, "writeVtk", true);
    writeGridVtk_ = getSwitch(dict, "writeGridVtk", true);
    return true;
}


void Foam::dropletFiber::couplingOutput::startVtk(const dictionary& dict)
{
    const fileName vtkDir =
        baseFileDir()/name()/time_.timeName(time_.startTime().value());
    if (Pstream::master() && (writeVtk_ || writeGridVtk_))
    {
        mkDir(vtkDir);
    }
    fibersSeries_.reset
    (
        new ::dropletFiber::SeriesFile(seriesPath(vtkDir, "fibers", "vtp"))
    );
    gridSeries_.reset
    (
        new ::dropletFiber::SeriesFile(seriesPath(vtkDir, "grid", "vti"))
    );
    checkedCoreCall
    (
        dict,
        [this]()
        {
            fibersSeries_->load(time_.value() + 0.5*time_.deltaTValue());
            gridSeries_->load(time_.value() + 0.5*time_.deltaTValue());
        }
    );
}


void Foam::dropletFiber::couplingOutput::writeVtk(const vtkWriter& fibers, const vtkWriter& grid)
{
    if (!writeVtk_ && !writeGridVtk_)
    {
        return;
    }
    const fileName dir =
        baseFileDir()/name()/time_.timeName(time_.startTime().value());
    if (Pstream::master())
    {
        mkDir(dir);
    }
    // The time folder's name as the files' time: 0.3, not the sum of the
    // steps (0.30000000000000004)
    const scalar t = readScalar(time_.timeName());

    // Both collective in parallel: every processor writes its piece (its
    // fibers, its block of the grid), the master the index of the pieces
    if (writeVtk_)
    {
        fibers(dir, t, *fibersSeries_);
    }
    if (writeGridVtk_)
    {
        grid(dir, t, *gridSeries_);
    }
}


void Foam::dropletFiber::couplingOutput::reportConservationHeading() const
{
    Info<< type() << " " << name() << " conservation at time "
        << time_.timeName() << ", summed over all steps so far:" << nl;
}


void Foam::dropletFiber::couplingOutput::report(Ostream& os) const
{
    os  << "    output: writeVtk " << Switch(writeVtk_).c_str()
        << ", writeGridVtk " << Switch(writeGridVtk_).c_str() << nl;
}


//- The function object's entries the output reads besides writeFile's
static const Foam::wordList outputKeys
{
    "writeVtk", "writeGridVtk"
};


Foam::wordList Foam::dropletFiber::couplingOutput::entries()
{
    return outputKeys;
}


// ************************************************************************* //
