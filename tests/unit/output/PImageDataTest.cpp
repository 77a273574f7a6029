// VtkWriter: the parallel ImageData index (.pvti) and its pieces read back: the whole
// extent, one PDataArray per field, one Piece per block with its extent and file, and a
// piece file whose extent and point count are the block's. Expected values are the inputs.
#include "output/VtkWriter.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace dropletFiber;

namespace
{
std::string readAll(const std::string& path)
{
    std::ifstream is(path);
    std::stringstream ss;
    ss << is.rdbuf();
    return ss.str();
}

std::vector<std::smatch> allMatches(const std::string& text, const std::regex& pattern)
{
    std::vector<std::smatch> result;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator();
         ++it)
    {
        result.push_back(*it);
    }
    return result;
}
} // namespace

TEST(PImageData, IndexListsFieldsAndPiecesWithTheirExtents)
{
    const std::string path = "PImageDataTest.pvti";
    const std::vector<VtkField> fields{{"rho", 1, {}}, {"U", 3, {}}};
    const std::vector<VtkPiece> pieces{{{{0, 10, 0, 5, 0, 0}}, "grid_1_0.vti"},
                                       {{{10, 20, 0, 5, 0, 0}}, "grid_1_1.vti"}};
    writePImageData(path, 1.5, Eigen::Vector3d(0.0, 1.0, 2.0), Eigen::Vector3d(0.1, 0.2, 0.3),
                    {{0, 20, 0, 5, 0, 0}}, fields, pieces);
    const std::string text = readAll(path);
    std::smatch whole;
    ASSERT_TRUE(std::regex_search(
        text, whole,
        std::regex("<PImageData WholeExtent=\"([^\"]*)\" GhostLevel=\"0\" Origin=\"([^\"]*)\"")));
    EXPECT_EQ(whole[1].str(), "0 20 0 5 0 0");
    EXPECT_EQ(whole[2].str(), "0 1 2");
    const auto arrays = allMatches(
        text, std::regex("<PDataArray type=\"Float64\" Name=\"(\\w+)\" NumberOfComponents=\"(\\d)\"/>"));
    ASSERT_EQ(arrays.size(), 2u);
    EXPECT_EQ(arrays[0][1].str(), "rho");
    EXPECT_EQ(arrays[1][1].str(), "U");
    EXPECT_EQ(arrays[1][2].str(), "3");
    const auto listed = allMatches(text, std::regex("<Piece Extent=\"([^\"]*)\" Source=\"([^\"]*)\"/>"));
    ASSERT_EQ(listed.size(), 2u);
    EXPECT_EQ(listed[1][1].str(), "10 20 0 5 0 0");
    EXPECT_EQ(listed[1][2].str(), "grid_1_1.vti");
    EXPECT_NE(text.find("</PImageData>\n</VTKFile>"), std::string::npos);
    std::remove(path.c_str());
}

TEST(PImageData, PieceFileHoldsTheBlocksExtentAndPoints)
{
    const std::string path = "PImageDataPiece.vti";
    VtkField rho{"rho", 1, std::vector<double>(3 * 2, 0.25)};
    writeImageDataPiece(path, 1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.1, 0.1, 0.1),
                        {{4, 6, 2, 3, 0, 0}}, {rho});
    const std::string text = readAll(path);
    EXPECT_NE(text.find("<ImageData WholeExtent=\"4 6 2 3 0 0\""), std::string::npos);
    EXPECT_NE(text.find("<Piece Extent=\"4 6 2 3 0 0\">"), std::string::npos);
    rho.values.pop_back();
    EXPECT_THROW(writeImageDataPiece(path, 1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.1, 0.1, 0.1),
                                     {{4, 6, 2, 3, 0, 0}}, {rho}),
                 std::invalid_argument);
    std::remove(path.c_str());
}
