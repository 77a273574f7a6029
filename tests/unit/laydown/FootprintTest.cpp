// A laid fiber's footprint on the map (P58-P59): its own line clipped to the cells by hand,
// folded at the belt's edges; its population's hat integrated over the cells by hand; and
// a uniform rain of tilted fibers, whose complete rows each hold exactly the glass laid per
// row (the comb's overlaps integrate over whole periods).
#include "laydown/Footprint.hpp"
#include "laydown/MatMap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace dropletFiber;

namespace
{
// Shares by (column, row).
std::map<std::pair<long, long>, CellShare> byCell(const std::vector<CellShare>& shares)
{
    std::map<std::pair<long, long>, CellShare> m;
    for (const CellShare& s : shares)
        m[{s.column, s.row}] = s;
    return m;
}

LaidFiber lineFiber(double across, double along, const Eigen::Vector3d& orientation, double endToEnd)
{
    LaidFiber f;
    f.across = across;
    f.along = along;
    f.orientation = orientation;
    f.endToEnd = endToEnd;
    f.glassMass = 1e-9;
    f.represents = 1.0;
    return f;
}
} // namespace

TEST(Footprint, LineClippedToCells)
{
    const MapLattice lattice{0.1, 0.0, 0.3};
    // Across: 0.08 to 0.16 in row 0: a quarter in column 0, three quarters in column 1
    auto s = byCell(footprint(lineFiber(0.12, 0.05, {1, 0, 0}, 0.08), lattice));
    ASSERT_EQ(s.size(), 2u);
    EXPECT_NEAR((s[{0, 0}].line), 0.25, 1e-12);
    EXPECT_NEAR((s[{1, 0}].line), 0.75, 1e-12);
    // (0.6, 0.8) in (across, along), 0.1 long, centre (0.15, 0.12): along runs against e_a,
    // so from (0.12, 0.16) to (0.18, 0.08), crossing along = 0.1 at three quarters
    s = byCell(footprint(lineFiber(0.15, 0.12, {0.6, 0.8, 0}, 0.1), lattice));
    ASSERT_EQ(s.size(), 2u);
    EXPECT_NEAR((s[{1, 1}].line), 0.75, 1e-12);
    EXPECT_NEAR((s[{1, 0}].line), 0.25, 1e-12);
    // Standing normal to the belt: whole in its centre's cell
    s = byCell(footprint(lineFiber(0.25, 0.05, {0, 0, 1}, 0.1), lattice));
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ((s[{2, 0}].line), 1.0);
    EXPECT_EQ((s[{2, 0}].population), 0.0);
}

TEST(Footprint, LineFoldedAtTheEdges)
{
    // Width 0.25: columns 0, 1 and the cut column 2 (0.2 to 0.25)
    const MapLattice lattice{0.1, 0.0, 0.25};
    // 0.17 to 0.27: 0.03 in column 1, 0.05 in column 2, 0.02 past the edge back into 2
    auto s = byCell(footprint(lineFiber(0.22, 0.05, {1, 0, 0}, 0.1), lattice));
    ASSERT_EQ(s.size(), 2u);
    EXPECT_NEAR((s[{1, 0}].line), 0.3, 1e-12);
    EXPECT_NEAR((s[{2, 0}].line), 0.7, 1e-12);
    // -0.03 to 0.07 at the near edge: 0.03 folds back to 0 to 0.03, all in column 0
    s = byCell(footprint(lineFiber(0.02, 0.05, {1, 0, 0}, 0.1), lattice));
    ASSERT_EQ(s.size(), 1u);
    EXPECT_NEAR((s[{0, 0}].line), 1.0, 1e-12);
}

TEST(Footprint, PopulationHatByHand)
{
    const MapLattice lattice{0.1, 0.0, 0.3};
    LaidFiber f = lineFiber(0.15, 0.15, {0, 0, 1}, 0.0);
    f.represents = 10.0;
    f.spread = 0.1;
    // The unit hat of half-width h over the cell of its centre: 3/4; each neighbour 1/8
    auto s = byCell(footprint(f, lattice));
    ASSERT_EQ(s.size(), 9u);
    EXPECT_NEAR((s[{1, 1}].population), 0.75 * 0.75, 1e-12);
    EXPECT_NEAR((s[{0, 1}].population), 0.125 * 0.75, 1e-12);
    EXPECT_NEAR((s[{2, 0}].population), 0.125 * 0.125, 1e-12);
    EXPECT_EQ((s[{1, 1}].line), 1.0);
    // At the edge: column 0 keeps 3/4 and the 1/8 folded back from beyond the edge
    f.across = 0.05;
    s = byCell(footprint(f, lattice));
    ASSERT_EQ(s.size(), 6u);
    EXPECT_NEAR((s[{0, 1}].population), 0.875 * 0.75, 1e-12);
    EXPECT_NEAR((s[{1, 1}].population), 0.125 * 0.75, 1e-12);
    // The map: the line's fiber and the nine others over the hat
    MatMap map(0.1, 0.0, 0.3);
    map.add(f);
    EXPECT_NEAR(map.total().glass, 10e-9, 1e-21);
    EXPECT_NEAR(map.cells().at({0, 1}).glass, (1.0 + 9.0 * 0.875 * 0.75) * 1e-9, 1e-21);
    EXPECT_NEAR(map.total().computed, 1.0, 1e-12);
}

TEST(Footprint, UniformRainOfTiltedFibers)
{
    // Fibers 8 mm long at 30 deg to the motion, one every mm along, in one column: every
    // 10 mm row the laying passed wholly holds 10 fibers' glass
    MatMap map(0.01, 0.0, 0.05);
    const double pi = std::acos(-1.0);
    const Eigen::Vector3d o(std::sin(pi / 6), std::cos(pi / 6), 0);
    for (int k = 0; k < 200; ++k)
        map.add(lineFiber(0.025, 0.0005 + 0.001 * k, o, 0.008));
    for (long row = 1; row < 19; ++row)
    {
        double glass = 0.0;
        for (long column = 0; column < 5; ++column)
        {
            auto it = map.cells().find({column, row});
            glass += it == map.cells().end() ? 0.0 : it->second.glass;
        }
        EXPECT_NEAR(glass, 10e-9, 1e-21) << "row " << row;
    }
}
