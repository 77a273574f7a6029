// SeriesFile: the .series index keeps one entry per time, sorted, and a restarted
// run drops the entries from the restart time on (they are rewritten).
#include "output/VtkWriter.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace
{
std::string slurp(const std::string& path)
{
    std::ifstream is(path);
    std::stringstream ss;
    ss << is.rdbuf();
    return ss.str();
}

int count(const std::string& text, const std::string& what)
{
    int n = 0;
    for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1))
    {
        ++n;
    }
    return n;
}
} // namespace

TEST(SeriesFile, restartDropsLaterTimesAndReplacesSameTime)
{
    const std::string path = testing::TempDir() + "fibers.vtp.series";
    std::remove(path.c_str());
    {
        dropletFiber::SeriesFile series(path);
        series.add("fibers_0.1.vtp", 0.1);
        series.add("fibers_0.2.vtp", 0.2);
        series.add("fibers_0.3.vtp", 0.3);
    }
    dropletFiber::SeriesFile restarted(path);
    restarted.load(0.2); // restart from t = 0.2: 0.2 and 0.3 are written again
    EXPECT_EQ(restarted.size(), 1u);
    restarted.add("fibers_0.2.vtp", 0.2);
    restarted.add("fibers_0.2.vtp", 0.2); // same time twice: one entry
    const std::string text = slurp(path);
    EXPECT_EQ(count(text, "\"name\""), 2);
    EXPECT_LT(text.find("fibers_0.1.vtp"), text.find("fibers_0.2.vtp"));
    EXPECT_EQ(text.find("fibers_0.3.vtp"), std::string::npos);
}

TEST(VtkWriter, polylineHasOneLineCellPerSegment)
{
    const std::string path = testing::TempDir() + "two.vtp";
    // two fibers: 3 points (2 segments) and 2 points (1 segment)
    std::vector<Eigen::Vector3d> points(5, Eigen::Vector3d::Zero());
    dropletFiber::VtkField tension{"tension", 1, {1.0, 2.0, 3.0}};
    dropletFiber::writePolylines(path, 0.5, points, {0, 3}, {}, {tension});
    const std::string text = slurp(path);
    EXPECT_NE(text.find("NumberOfPoints=\"5\" NumberOfLines=\"3\""), std::string::npos);
    // connectivity: 0 1, 1 2, 3 4 (no segment from 2 to 3)
    EXPECT_NE(text.find("\n          3 4\n"), std::string::npos);
    EXPECT_EQ(text.find("\n          2 3\n"), std::string::npos);
    EXPECT_THROW(dropletFiber::writePolylines(path, 0.5, points, {0, 3}, {}, {{"bad", 1, {1.0}}}),
                 std::invalid_argument);
}
