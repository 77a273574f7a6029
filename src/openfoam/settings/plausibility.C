/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "plausibility.H"
#include "error.H"
#include "OStringStream.H"
#include "PstreamReduceOps.H"

#include <cmath>

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::dropletFiber::plausibleRange
Foam::dropletFiber::fiberRadiusRange
{
    1e-7, 1e-3, "m", "",
    "a radius in micrometres or millimetres given in metres? (3 um is 3e-6 m)"
};

const Foam::dropletFiber::plausibleRange
Foam::dropletFiber::fiberDensityRange
{
    100, 25000, "kg/m3",
    "a density in g/cm3 given in kg/m3? (2.5 g/cm3 is 2500 kg/m3)", ""
};

const Foam::dropletFiber::plausibleRange
Foam::dropletFiber::youngsModulusRange
{
    1e5, 1e12, "Pa",
    "a modulus in MPa or GPa given in Pa? (70 GPa is 7e10 Pa)", ""
};

const Foam::dropletFiber::plausibleRange
Foam::dropletFiber::dropletDensityRange
{
    100, 25000, "kg/m3",
    "a density in g/cm3 given in kg/m3? (1 g/cm3 is 1000 kg/m3)", ""
};

const Foam::dropletFiber::plausibleRange
Foam::dropletFiber::representsRange
{
    1, 1e12, "fibers", "",
    "a glass flow or a count per second given as the fibers one computed"
    " fiber stands for? (a spinner makes 1e8 to 1e9 fibers a second, a run"
    " computes hundreds: represents 1e6 to 1e7)"
};

const Foam::dropletFiber::plausibleRange
Foam::dropletFiber::massFlowRateRange
{
    1e-6, 1, "kg/s", "a flow in g/h given in kg/s?",
    "a spinner's kg/h given in kg/s? (a spinner's glass flow is a few hundred"
    " kg/h: 300 kg/h is 0.083 kg/s)"
};

const Foam::dropletFiber::plausibleRange
Foam::dropletFiber::beltSpeedRange
{
    1e-3, 10, "m/s", "a speed in m/h given in m/s?",
    "a speed in m/min given in m/s? (a forming belt runs at 0.1 to 3 m/s;"
    " 30 m/min is 0.5 m/s)"
};


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

const Foam::dropletFiber::plausibleRange airDensityRange
{
    0.01, 2000, "kg/m3", "", "a density in g/m3 or g/l given in kg/m3?"
};

const Foam::dropletFiber::plausibleRange airViscosityRange
{
    1e-6, 10, "Pa s", "", "a viscosity in mPa s (cP) or uPa s given in Pa s?"
};

//- Warn about entry key of dict when it is given as a number outside range
//  (allowed: a value that is allowed though outside, e.g. 0 for limp fibers)
void warnEntry
(
    const dictionary& dict,
    const word& key,
    const Foam::dropletFiber::plausibleRange& range,
    const scalar allowed = -1
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e || e->isDict() || e->stream().empty() || !e->stream()[0].isNumber())
    {
        return;
    }
    const scalar value = e->stream()[0].number();
    const string text = Foam::dropletFiber::implausible(value, range);
    if (value != allowed && !text.empty())
    {
        IOWarningInFunction(dict)
            << "Entry '" << key << "' " << text.c_str() << endl;
    }
}


void warnMaterial(const dictionary& dict)
{
    warnEntry(dict, "radius", Foam::dropletFiber::fiberRadiusRange);
    warnEntry(dict, "density", Foam::dropletFiber::fiberDensityRange);
    warnEntry(dict, "youngsModulus", Foam::dropletFiber::youngsModulusRange, 0);
}


//- The mesh's mean cell size over its solved directions (collective)
scalar meanCellSize(const fvMesh& mesh)
{
    const boundBox& box = mesh.bounds();
    scalar measure = 1;
    label dimensions = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh.solutionD()[d] > 0)
        {
            measure *= box.span()[d];
            ++dimensions;
        }
    }
    const scalar cells = returnReduce(scalar(mesh.nCells()), sumOp<scalar>());
    return dimensions > 0 && cells > 0
        ? std::pow(measure/cells, 1.0/dimensions)
        : 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::string Foam::dropletFiber::implausible
(
    const scalar value,
    const plausibleRange& range
)
{
    if (value >= range.lo && value <= range.hi)
    {
        return string();
    }
    const bool below = value < range.lo;
    const string slip = below ? range.slipBelow : range.slipAbove;
    OStringStream os;
    os  << "is " << value << " " << range.unit << ": plausible are "
        << range.lo << " to " << range.hi << " " << range.unit;
    if (!slip.empty())
    {
        os  << "; " << slip.c_str();
    }
    os  << " (the run goes on with it)";
    return os.str();
}


void Foam::dropletFiber::warnImplausibleFibers(const dictionary& fibersDict)
{
    warnMaterial(fibersDict);
    for (const char* group : {"injectors", "fixed"})
    {
        const dictionary* sources = fibersDict.findDict(group);
        if (!sources)
        {
            continue;
        }
        for (const entry& e : *sources)
        {
            if (e.isDict())
            {
                warnMaterial(e.dict());
                warnEntry(e.dict(), "represents", representsRange);
                warnEntry(e.dict(), "massFlowRate", massFlowRateRange);
            }
        }
    }
}


void Foam::dropletFiber::warnImplausibleAir(const dictionary& airDict)
{
    warnEntry(airDict, "rho", airDensityRange);
    warnEntry(airDict, "mu", airViscosityRange);
}


void Foam::dropletFiber::warnImplausibleSpacing
(
    const dictionary& gridDict,
    const gridSettings& grid,
    const fvMesh& mesh
)
{
    const scalar cell = meanCellSize(mesh);
    scalar spacing = 0;
    for (int d = 0; d < 3; ++d)
    {
        spacing =
            grid.spec.flat(d) ? spacing : max(spacing, grid.spec.spacing(d));
    }
    if (!(cell > 0) || !(spacing > 0))
    {
        return;
    }
    const scalar ratio = spacing/cell;
    if (ratio >= 0.01 && ratio <= 100)
    {
        return;
    }
    const word key = gridDict.found("spacing") ? "spacing" : "nodes";
    IOWarningInFunction(gridDict)
        << "Entry '" << key << "' gives a node spacing of " << spacing
        << " m, " << ratio << " times the mesh's mean cell size " << cell
        << " m: plausible are 0.01 to 100 times it; "
        << (
               ratio > 100
             ? "a spacing in millimetres given in metres, or too few nodes?"
             : "a spacing in metres given for millimetres, or too many nodes?"
           )
        << " (the run goes on with it)" << endl;
}


// ************************************************************************* //
