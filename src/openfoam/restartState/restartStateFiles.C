/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Writing and reading the files of a restart state (restartStateFiles.H).

\*---------------------------------------------------------------------------*/

#include "restartStateFiles.H"
#include "fiberStateIO.H"
#include "IFstream.H"
#include "scalarList.H"
#include "grid/GridQuantities.hpp"
#include <cmath>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

void Foam::dropletFiber::writeStateDictionary
(
    const fileName& path,
    const dictionary& state,
    const string& headline
)
{
    writeAtomically
    (
        path,
        IOstream::ASCII,
        [&](OFstream& os)
        {
            os.precision(17);
            os  << "// " << headline.c_str() << nl;
            state.write(os, false);
        }
    );
}


void Foam::dropletFiber::writeWindowList
(
    const fileName& file,
    const std::vector<double>& values
)
{
    writeAtomically
    (
        file,
        IOstream::BINARY,
        [&values](OFstream& os)
        {
            // Written straight from the window's buffer (a view, no copy)
            os  << UList<scalar>
            (
                const_cast<scalar*>(values.data()),
                label(values.size())
            );
        }
    );
}


Foam::label Foam::dropletFiber::requiredCount
(
    const dictionary& dict,
    const word& key
)
{
    const label value = dict.get<label>(key);
    if (value < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' is " << value
            << ": allowed are counts >= 0." << exit(FatalIOError);
    }
    return value;
}


std::vector<std::int64_t> Foam::dropletFiber::windowCounters
(
    const dictionary& state
)
{
    const scalarList counters = state.get<scalarList>("gridWindowCounters");
    std::vector<std::int64_t> result;
    result.reserve(counters.size());
    forAll(counters, i)
    {
        const scalar c = counters[i];
        if (!std::isfinite(c) || c != std::floor(c) || mag(c) > 1e15)
        {
            FatalIOErrorInFunction(state)
                << "Entry 'gridWindowCounters': value " << i << " is " << c
                << ": allowed are integers (the window's layout)."
                << exit(FatalIOError);
        }
        result.push_back(std::int64_t(c));
    }
    return result;
}


std::vector<double> Foam::dropletFiber::windowValues
(
    const fileName& file,
    const label expected,
    const bool nodeValues
)
{
    if (!isFile(file))
    {
        FatalIOErrorInFunction(file)
            << "Restart state " << file << " is missing: it holds the "
            << expected << " values of the averaging window." << nl
            << "    Restart from an earlier time, or set 'restart fresh;'."
            << exit(FatalIOError);
    }
    IFstream is(file, IOstream::BINARY);
    const scalarList values(is);
    if (!is.good() || values.size() != expected)
    {
        FatalIOErrorInFunction(file)
            << "Restart state " << file << " holds " << values.size()
            << " values, the state's entry 'gridWindowValueCount' says "
            << expected << "." << exit(FatalIOError);
    }
    const label nQ = ::dropletFiber::nQuantities;
    forAll(values, i)
    {
        if (!nodeValues)
        {
            if (!std::isfinite(values[i]))
            {
                FatalIOErrorInFunction(file)
                    << "Restart state " << file << ": value " << i << " is "
                    << values[i] << ": allowed are finite values (the"
                    << " parcels deposited in the averaging window's steps)."
                    << exit(FatalIOError);
            }
            continue;
        }
        const bool mayBeNegative = i % nQ >= ::dropletFiber::quantityMomentumX;
        if (!std::isfinite(values[i]) || (!mayBeNegative && values[i] < 0))
        {
            FatalIOErrorInFunction(file)
                << "Restart state " << file << ": value " << i
                << " (quantity " << i % nQ << " of " << nQ << ") is "
                << values[i] << ": allowed are finite values, >= 0 for the"
                << " droplet mass, count and radius sums (quantities 0 to 3)."
                << exit(FatalIOError);
        }
    }
    return toStdVector(values);
}

// ************************************************************************* //
