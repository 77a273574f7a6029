// VtkWriter: the numbers in the ASCII data arrays read back as exactly the doubles that
// were written (shortest round-trip formatting), and non-finite values are written as 0.
// The expected values are the inputs themselves.
#include "output/VtkWriter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// The numbers between the DataArray tags named `name`, parsed with strtod
std::vector<double> arrayValues(const std::string& path, const std::string& name)
{
    std::ifstream is(path);
    std::stringstream ss;
    ss << is.rdbuf();
    const std::string text = ss.str();
    const std::size_t tag = text.find("Name=\"" + name + "\"");
    EXPECT_NE(tag, std::string::npos) << name;
    const std::size_t begin = text.find('>', tag) + 1;
    const std::size_t end = text.find("</DataArray>", begin);
    std::istringstream values(text.substr(begin, end - begin));
    std::vector<double> parsed;
    std::string word;
    while (values >> word)
    {
        parsed.push_back(std::strtod(word.c_str(), nullptr));
    }
    return parsed;
}
} // namespace

TEST(VtkNumbers, imageDataValuesReadBackBitForBit)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<double> written{
        0.1, 1.0 / 3.0, -2.5e-300,           4.9e-324,         1.7976931348623157e308,
        0.0, -0.0,      123456789.123456789, 2.0 / 3.0 * 1e-7, nan,
        inf, -inf};
    const std::string path = testing::TempDir() + "numbers.vti";
    dropletFiber::writeImageData(path, 0.25, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(),
                                 {{static_cast<int>(written.size()), 1, 1}}, {{"rho", 1, written}});
    const std::vector<double> read = arrayValues(path, "rho");
    ASSERT_EQ(read.size(), written.size());
    for (std::size_t i = 0; i < written.size(); ++i)
    {
        const double expected = std::isfinite(written[i]) ? written[i] : 0.0;
        EXPECT_EQ(read[i], expected) << "value " << i;
        EXPECT_EQ(std::signbit(read[i]), std::signbit(expected)) << "value " << i;
    }
    std::remove(path.c_str());
}

TEST(VtkNumbers, polylinePointsReadBackBitForBit)
{
    const std::vector<Eigen::Vector3d> points{{0.1, 0.2, 0.3}, {1.0 / 7.0, -1e-17, 5e-3}};
    const std::string path = testing::TempDir() + "numbers.vtp";
    dropletFiber::writePolylines(path, 0.5, points, {0}, {{"sigma", 1, {1e-6 / 3.0, 2e-6}}},
                                 {{"tension", 1, {3.0e-9 / 7.0}}});
    std::ifstream is(path);
    std::stringstream ss;
    ss << is.rdbuf();
    const std::string text = ss.str();
    // after the '>' of the DataArray tag inside <Points>
    const std::size_t start = text.find('>', text.find("<DataArray", text.find("<Points>"))) + 1;
    std::istringstream values(text.substr(start, text.find("</DataArray>", start) - start));
    std::vector<double> read;
    std::string word;
    while (values >> word)
    {
        read.push_back(std::strtod(word.c_str(), nullptr));
    }
    ASSERT_EQ(read.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i)
    {
        EXPECT_EQ(read[i], points[i / 3][static_cast<Eigen::Index>(i % 3)]) << "coordinate " << i;
    }
    EXPECT_EQ(arrayValues(path, "sigma")[0], 1e-6 / 3.0);
    EXPECT_EQ(arrayValues(path, "tension")[0], 3.0e-9 / 7.0);
    std::remove(path.c_str());
}
