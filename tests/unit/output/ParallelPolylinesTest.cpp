// writeParallelPolylines: the .pvtp index of fibers written in pieces (one .vtp per
// processor) lists every piece in order and declares the arrays the pieces hold, so
// that ParaView reads the pieces as one data set; an empty piece is valid.
#include "output/VtkWriter.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::string slurp(const std::string& path)
{
    std::ifstream is(path);
    std::stringstream ss;
    ss << is.rdbuf();
    return ss.str();
}

// The values of attribute `name` of every element `tag`, in file order.
std::vector<std::string> attributes(const std::string& xml, const std::string& tag, const std::string& name)
{
    const std::regex element("<" + tag + "\\b[^>]*\\b" + name + "=\"([^\"]*)\"");
    std::vector<std::string> values;
    for (std::sregex_iterator it(xml.begin(), xml.end(), element), end; it != end; ++it)
    {
        values.push_back((*it)[1].str());
    }
    return values;
}
} // namespace

TEST(ParallelPolylines, indexListsPiecesAndArrays)
{
    const std::string path = testing::TempDir() + "fibers_0.1.pvtp";
    const std::vector<std::string> pieces{"fibers_0.1/processor0.vtp", "fibers_0.1/processor1.vtp",
                                          "fibers_0.1/processor2.vtp"};
    dropletFiber::writeParallelPolylines(path, 0.1, pieces, {{"velocity", 3, {}}, {"fiberId", 1, {}}},
                                         {{"tension", 1, {}}});
    const std::string xml = slurp(path);

    EXPECT_EQ(attributes(xml, "VTKFile", "type"), std::vector<std::string>{"PPolyData"});
    EXPECT_EQ(attributes(xml, "Piece", "Source"), pieces);
    EXPECT_EQ(attributes(xml, "PDataArray", "Name"),
              (std::vector<std::string>{"velocity", "fiberId", "tension"}));
    EXPECT_EQ(attributes(xml, "PDataArray", "NumberOfComponents"),
              (std::vector<std::string>{"3", "3", "1", "1"})); // points first
    // The arrays in their blocks: velocity and fiberId per point, tension per cell
    const auto pointData = xml.find("<PPointData>");
    const auto cellData = xml.find("<PCellData>");
    ASSERT_NE(pointData, std::string::npos);
    ASSERT_NE(cellData, std::string::npos);
    EXPECT_LT(pointData, xml.find("Name=\"velocity\""));
    EXPECT_LT(xml.find("Name=\"fiberId\""), cellData);
    EXPECT_LT(cellData, xml.find("Name=\"tension\""));
    EXPECT_NE(xml.find("Name=\"TimeValue\""), std::string::npos);
    EXPECT_EQ(xml.find("<PPolyData"), xml.find("<PPolyData GhostLevel=\"0\">"));
    EXPECT_NE(xml.find("</VTKFile>"), std::string::npos);
}

TEST(ParallelPolylines, emptyPieceIsValid)
{
    // A processor holding no fiber writes a piece without points or lines
    const std::string path = testing::TempDir() + "emptyPiece.vtp";
    dropletFiber::writePolylines(path, 0.1, {}, {}, {{"velocity", 3, {}}}, {{"tension", 1, {}}});
    const std::string xml = slurp(path);
    EXPECT_EQ(attributes(xml, "Piece", "NumberOfPoints"), std::vector<std::string>{"0"});
    EXPECT_EQ(attributes(xml, "Piece", "NumberOfLines"), std::vector<std::string>{"0"});
    EXPECT_EQ(attributes(xml, "DataArray", "Name").size(), 5u); // TimeValue, 2 lines, 2 fields
}
