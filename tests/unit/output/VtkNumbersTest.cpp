// VtkWriter: the numbers in the data arrays read back as exactly the doubles that were
// written (ASCII: shortest round-trip formatting; the grid's binary arrays: base64 of a
// UInt64 byte count and the doubles, decoded here by a decoder of this test's own), and
// non-finite values are written as 0. The expected values are the inputs themselves.
#include "output/VtkWriter.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// RFC 4648 base64, whitespace skipped; the padding is checked: whole quanta of 4
// characters, and as many '=' at the end as the byte count leaves over.
std::vector<unsigned char> decodeBase64(const std::string& text)
{
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string compact;
    for (const char c : text)
    {
        if (!std::isspace(static_cast<unsigned char>(c)))
        {
            compact += c;
        }
    }
    EXPECT_EQ(compact.size() % 4, 0u) << "not whole quanta";
    const std::size_t padding = compact.size() - compact.find_last_not_of('=') - 1;
    EXPECT_EQ(compact.find('='), padding == 0 ? std::string::npos : compact.size() - padding)
        << "'=' inside the stream";
    std::vector<unsigned char> bytes;
    unsigned buffer = 0;
    int bits = 0;
    for (const char c : text)
    {
        const std::size_t value = alphabet.find(c);
        if (value == std::string::npos)
        {
            continue; // whitespace and padding
        }
        buffer = (buffer << 6) | static_cast<unsigned>(value);
        bits += 6;
        if (bits >= 8)
        {
            bits -= 8;
            bytes.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
        }
    }
    EXPECT_EQ((3 - bytes.size() % 3) % 3, padding) << "padding of " << bytes.size() << " bytes";
    return bytes;
}

// A binary array's doubles after its UInt64 byte count, which must match.
std::vector<double> binaryValues(const std::string& encoded)
{
    const std::vector<unsigned char> bytes = decodeBase64(encoded);
    std::uint64_t count = 0;
    EXPECT_GE(bytes.size(), sizeof count);
    std::memcpy(&count, bytes.data(), sizeof count);
    EXPECT_EQ(count, bytes.size() - sizeof count);
    std::vector<double> values(static_cast<std::size_t>(count) / sizeof(double));
    std::memcpy(values.data(), bytes.data() + sizeof count, values.size() * sizeof(double));
    return values;
}

// The numbers between the DataArray tags named `name`: parsed with strtod, or decoded
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
    if (text.substr(tag, begin - tag).find("format=\"binary\"") != std::string::npos)
    {
        EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
        return binaryValues(text.substr(begin, end - begin));
    }
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

TEST(VtkNumbers, gridArraysOfEveryPaddingReadBackBitForBit)
{
    // 8 (n + 1) bytes: n = 1, 2, 3 end base64 with one, no and two padding characters
    for (int n = 1; n <= 3; ++n)
    {
        std::vector<double> written;
        for (int i = 0; i < n; ++i)
        {
            written.push_back(0.1 * (i + 1) - 1e-3 / 7.0);
        }
        const std::string path = testing::TempDir() + "padding.vti";
        dropletFiber::writeImageData(path, 0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {{n, 1, 1}},
                                     {{"rho", 1, written}});
        EXPECT_EQ(arrayValues(path, "rho"), written) << n << " values";
        std::remove(path.c_str());
    }
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
