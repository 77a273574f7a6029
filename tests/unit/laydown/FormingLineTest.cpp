// The laying zone's complete rows (P48) and the forming line's mat (P62), by hand.
#include "laydown/FormingLine.hpp"
#include "laydown/LayingZone.hpp"
#include "laydown/MatUncertainty.hpp"

#include <gtest/gtest.h>

using namespace dropletFiber;

TEST(LayingZone, CompleteRowsByHand)
{
    // Feet from -0.5 to 0.5 m on a belt at 0.2 m/s, the first fiber at 0.25 s; footprints
    // reach 0.015 m along. Rows of 0.05 m. At 6 s: rows from (0.2 x 0.25 + 0.5 + 0.015) /
    // 0.05 = 11.3 -> 12 to (0.2 x 6 - 0.5 - 0.015) / 0.05 = 13.7 -> 13, less 1: 12
    LayingZone zone;
    LaidFiber f;
    f.time = 0.25;
    f.along = 0.2 * 0.25 + 0.5; // foot -0.5
    f.endToEnd = 0.03;
    f.orientation = Eigen::Vector3d(0, 1, 0);
    zone.add(f, 0.2);
    f.time = 1.0;
    f.along = 0.2 * 1.0 - 0.5; // foot 0.5
    f.orientation = Eigen::Vector3d(1, 0, 0);
    zone.add(f, 0.2);
    EXPECT_EQ(zone.reach, 0.015);
    EXPECT_EQ(zone.completeRows(0.2, 0.05, -1.0, 6.0), std::make_pair(12L, 12L));
    // Steady from 0.5 s: from (0.1 + 0.515) / 0.05 = 12.3 -> 13: none yet; at 7 s to 17.7 -> 16
    EXPECT_GT(zone.completeRows(0.2, 0.05, 0.5, 6.0).first, zone.completeRows(0.2, 0.05, 0.5, 6.0).second);
    EXPECT_EQ(zone.completeRows(0.2, 0.05, 0.5, 7.0), std::make_pair(13L, 16L));
    // No belt speed, no fibers: none
    EXPECT_GT(LayingZone().completeRows(0.2, 0.05, -1.0, 6.0).first, 0L);
}

TEST(FormingLine, SumsOfShiftedRows)
{
    // A hood's mat of 4 complete rows (1 to 4), one column of 0.1 m: row r holds r
    // fibers of 1 ng, each whole in its cell
    MatMap hood(0.1, 0.0, 0.2);
    LaidFiber f;
    f.glassMass = 1e-9;
    f.binderMass = 1e-10;
    f.across = 0.05;
    for (long r = 1; r <= 4; ++r)
        for (long k = 0; k < r; ++k)
        {
            f.along = 0.1 * r + 0.05;
            hood.add(f);
        }
    // Two hoods two rows apart: line row 1 = rows 1 + 3, 2 = 2 + 4, 3 = 3 + 1, 4 = 4 + 2
    const MatMap line = formingLine(hood, 1, 4, 2, evenShift(4, 2));
    EXPECT_EQ(evenShift(4, 2), 2);
    for (long r = 1; r <= 4; ++r)
    {
        const long other = (r + 1) % 4 + 1;
        EXPECT_NEAR(line.cells().at({0, r}).glass, (r + other) * 1e-9, 1e-21);
        // Independent draws: the variances add (each fiber's glass squared)
        EXPECT_NEAR(line.cells().at({0, r}).glassSquares, (r + other) * 1e-18, 1e-30);
    }
    EXPECT_NEAR(line.total().glass, 2 * hood.total().glass, 1e-21);
    // The line's LOI the hood's; its area weight twice, its relative error 1/sqrt 2 of it
    const AcrossProfile one = acrossProfileWithErrors(hood, 1, 4), two = acrossProfileWithErrors(line, 1, 4);
    EXPECT_NEAR(two.loiAll.value, one.loiAll.value, 1e-12);
    EXPECT_NEAR(two.areaWeight[0].value, 2 * one.areaWeight[0].value, 1e-12);
    EXPECT_NEAR(two.areaWeight[0].error / two.areaWeight[0].value,
                one.areaWeight[0].error / one.areaWeight[0].value / std::sqrt(2.0), 1e-12);
    EXPECT_THROW(formingLine(hood, 1, 4, 3, 2), std::invalid_argument);
    EXPECT_THROW(formingLine(hood, 1, 4, 0, 1), std::invalid_argument);
}
