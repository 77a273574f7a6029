/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The mat's cells read from the restart state's laydown entry.
\*---------------------------------------------------------------------------*/

#include "matCellsIO.H"
#include "scalarList.H"
#include "labelList.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::dropletFiber::readMatCells
(
    const dictionary& mat,
    const fileName& path,
    ::dropletFiber::MatMap& map
)
{
    const labelList columns = mat.get<labelList>("columns");
    const labelList rows = mat.get<labelList>("rows");
    const scalarList glass = mat.get<scalarList>("cellGlass");
    const scalarList binder = mat.get<scalarList>("cellBinder");
    const scalarList fibers = mat.get<scalarList>("cellFibers");
    const scalarList orientation = mat.get<scalarList>("cellOrientation");
    const label n = columns.size();
    constexpr label errorSums = ::dropletFiber::MatCell::sumCount - 4;
    const scalarList errors =
        mat.lookupOrDefault<scalarList>("cellErrorSums", scalarList());
    if
    (
        rows.size() != n || glass.size() != n || binder.size() != n
     || fibers.size() != n || orientation.size() != n
     || (!errors.empty() && errors.size() != errorSums*n)
    )
    {
        FatalIOErrorInFunction(mat)
            << "The restart state " << path << ": the mat's cell lists have"
            << " different lengths (columns " << n << ", rows " << rows.size()
            << ", glass " << glass.size() << ", error sums " << errors.size()
            << " of " << errorSums << " per cell): the state is damaged."
            << exit(FatalIOError);
    }
    forAll(columns, k)
    {
        std::array<double, ::dropletFiber::MatCell::sumCount> sums{};
        sums[0] = glass[k];
        sums[1] = binder[k];
        sums[2] = fibers[k];
        sums[3] = orientation[k];
        for (label e = 0; e < errorSums && !errors.empty(); ++e)
        {
            sums[std::size_t(4 + e)] = errors[errorSums*k + e];
        }
        ::dropletFiber::MatCell c;
        c.setSums(sums);
        map.setCell(columns[k], rows[k], c);
    }
    return !errors.empty();
}


// ************************************************************************* //
