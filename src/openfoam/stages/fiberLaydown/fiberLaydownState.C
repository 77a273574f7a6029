/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The mat's part of the restart state: the map's cells and the totals
    laid, the same on every processor.
\*---------------------------------------------------------------------------*/

#include "fiberLaydown.H"
#include "dictionaryChecks.H"
#include "matCellsIO.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberLaydown::writeState
(
    const fileName&,
    dictionary& state,
    dictionary&
)
{
    if (!on_)
    {
        return;
    }
    const auto& cells = map_->cells();
    labelList columns(cells.size()), rows(cells.size());
    scalarList glass(cells.size()), binder(cells.size());
    scalarList fibers(cells.size()), orientation(cells.size());
    // The error sums (P60): per cell the MatCell sums after the first four
    constexpr label errorSums = ::dropletFiber::MatCell::sumCount - 4;
    scalarList errors(errorSums*cells.size());
    label k = 0;
    for (const auto& [key, c] : cells)
    {
        columns[k] = label(key.first);
        rows[k] = label(key.second);
        glass[k] = c.glass;
        binder[k] = c.binder;
        fibers[k] = c.fibers;
        orientation[k] = c.orientationSum;
        const auto sums = c.sums();
        for (label e = 0; e < errorSums; ++e)
        {
            errors[errorSums*k + e] = sums[std::size_t(4 + e)];
        }
        ++k;
    }
    dictionary mat;
    mat.add("computed", totals_.computed);
    mat.add("physical", totals_.physical);
    mat.add("glass", totals_.glass);
    mat.add("binder", totals_.binder);
    mat.add("firstTime", totals_.zone.firstTime);
    mat.add("footMin", totals_.zone.footMin);
    mat.add("footMax", totals_.zone.footMax);
    mat.add("footReach", totals_.zone.reach);
    mat.add("cell", map_->cell());
    // The belt as the settings give it (for dropletFiberFormingLine; not read back)
    mat.add("acrossMin", map_->acrossMin());
    mat.add("acrossMax", map_->acrossMax());
    mat.add("beltSpeed", belt_.speed());
    mat.add("steadyFrom", steadyFrom_);
    mat.add("columns", columns);
    mat.add("rows", rows);
    mat.add("cellGlass", glass);
    mat.add("cellBinder", binder);
    mat.add("cellFibers", fibers);
    mat.add("cellOrientation", orientation);
    mat.add("cellErrorSums", errors);
    state.add("laydown", mat);
}


void Foam::dropletFiber::fiberLaydown::readCells
(
    const dictionary& mat,
    const fileName& path
)
{
    if (!readMatCells(mat, path, *map_))
    {
        WarningInFunction
            << type() << " " << name() << ": the restart state " << path
            << " has no error sums of the mat (written before the mat had"
            << " errors): the " << map_->cells().size() << " cells laid before"
            << " carry none, their errors and the CoV's noise are too small."
            << endl;
    }
}

void Foam::dropletFiber::fiberLaydown::readState
(
    const dictionary& state,
    const fileName& path
)
{
    const dictionary* mat = state.findDict("laydown");
    if (!on_)
    {
        if (mat)
        {
            WarningInFunction
                << type() << " " << name() << ": the restart state " << path
                << " holds a mat, but fibers.laydown is not given: fibers"
                << " are no longer laid, the mat is not continued." << endl;
        }
        return;
    }
    if (!mat)
    {
        Info<< type() << " " << name() << ": the restart state " << path
            << " has no mat (the run restarted from laid none): the mat"
            << " starts empty" << nl;
        return;
    }
    const scalar cell = mat->get<scalar>("cell");
    if (cell != map_->cell())
    {
        FatalIOErrorInFunction(*mat)
            << "The restart state " << path << " has a mat of cells " << cell
            << " m, fibers.laydown.cell is " << map_->cell() << " m: the map"
            << " cannot continue on other cells." << nl
            << "    Restart with cell " << cell << ", or set 'restart fresh;'."
            << exit(FatalIOError);
    }
    totals_.computed = mat->get<label>("computed");
    totals_.physical = mat->get<scalar>("physical");
    totals_.glass = mat->get<scalar>("glass");
    totals_.binder = mat->get<scalar>("binder");
    totals_.zone.firstTime = mat->get<scalar>("firstTime");
    totals_.zone.footMin = mat->get<scalar>("footMin");
    totals_.zone.footMax = mat->get<scalar>("footMax");
    // A state written before fibers were laid along their length: whole
    totals_.zone.reach = mat->lookupOrDefault<scalar>("footReach", 0);
    readCells(*mat, path);
}


// ************************************************************************* //
