// Footprint: where on the mat's map a laid fiber's glass and binder go (docs/model.md
// sec. 11, P58-P59). The fiber lies along its length: its own line is the straight segment
// between its ends' feet on the belt, centred on its centre's foot, and each map cell takes
// the share of that segment it holds (exact clipping). A weighted fiber's population, the
// N - 1 physical fibers it stands for besides its own line (docs/model.md sec. 12), lies
// spread around the line by the hat of its level (half-width `spread`, the tensor product
// of the 1D hats across and along): each cell takes the hat's integral over it, the line
// sampled at points a quarter of the hat apart. Nothing leaves the belt's width: a share
// beyond an edge is folded back across it (the hood's walls return what they meet).
#pragma once

#include "laydown/Belt.hpp"

#include <vector>

namespace dropletFiber
{

// One cell's shares of a laid fiber: of its own line and of its population (each summing
// to 1 over the cells; the population's 0 without a spread).
struct CellShare
{
    long column = 0, row = 0;
    double line = 0.0;
    double population = 0.0;
};

// The lattice of the map: square cells of side `cell` from across = acrossMin (the belt's
// edge) and along = 0; the belt's width ends at acrossMax (the last column may be cut).
struct MapLattice
{
    double cell = 0.0;
    double acrossMin = 0.0, acrossMax = 0.0;

    long columns() const;
    long column(double across) const;
    long row(double along) const;
    // The width of column i on the belt (the last one may be cut by the edge).
    double columnWidth(long i) const;
    // across folded into [acrossMin, acrossMax] by reflection at the edges.
    double fold(double across) const;
};

// The cells a laid fiber's glass covers, in (column, row) order.
std::vector<CellShare> footprint(const LaidFiber& fiber, const MapLattice& lattice);

// The fiber as the map laid it before P58: no extent and no spread, so that all its N
// fibers lie in the cell of its centre's foot (fibers.laydown.footprint centre).
LaidFiber wholeAtCentre(LaidFiber fiber);

// The integral of the unit hat of half-width h centred at 0 from -infinity to x.
double hatIntegral(double x, double h);

} // namespace dropletFiber
