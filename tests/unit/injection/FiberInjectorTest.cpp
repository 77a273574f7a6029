// FiberInjector: counts and placement by hand.
#include "injection/FiberInjector.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using dropletFiber::FiberInjector;
using dropletFiber::FiberInjectorSpec;

namespace
{
FiberInjectorSpec stream()
{
    FiberInjectorSpec s;
    s.name = "stream";
    s.position = Eigen::Vector3d(0.0, 1.0, 0.0);
    s.direction = Eigen::Vector3d(2.0, 0.0, 0.0); // normalised by the injector
    s.velocity = Eigen::Vector3d(0.0, -0.5, 0.0);
    s.length = 0.1;
    s.points = 11;
    s.rate = 10.0; // one fiber every 0.1 s
    s.startTime = 0.05;
    s.endTime = 0.35; // births at 0.05, 0.15, 0.25 only
    s.material = {4e-6, 2500.0, 7e10};
    return s;
}
} // namespace

TEST(FiberInjector, countsBirthsInsideTheWindowOnly)
{
    FiberInjector injector(stream());
    EXPECT_EQ(injector.bornBy(0.0), 0);
    EXPECT_EQ(injector.bornBy(0.05), 1); // born exactly at the start
    EXPECT_EQ(injector.bornBy(0.149), 1);
    EXPECT_EQ(injector.bornBy(0.15), 2);
    EXPECT_EQ(injector.bornBy(10.0), 3); // 0.35 is the end: no fourth fiber
}

TEST(FiberInjector, sameFibersWhateverTheStepSize)
{
    FiberInjector coarse(stream()), fine(stream());
    std::vector<dropletFiber::Fiber> a = coarse.inject(0.3);
    std::vector<dropletFiber::Fiber> b;
    for (int s = 1; s <= 30; ++s)
    {
        for (auto& f : fine.inject(0.01 * s))
        {
            b.push_back(f);
        }
    }
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(b.size(), 3u);
    // The fiber born at 0.15 has moved 0.5 m/s * (0.3 - 0.15) s down by t = 0.3 in
    // the coarse call; in the fine run it was placed at its birth step (t = 0.15)
    // and is still at y = 1 - 0 there.
    EXPECT_NEAR(a[1].positions()(1, 0), 1.0 - 0.5 * 0.15, 1e-12);
    EXPECT_NEAR(b[1].positions()(1, 0), 1.0, 1e-9);
    // Laid along +x with the given length
    EXPECT_NEAR(a[0].positions()(0, 10) - a[0].positions()(0, 0), 0.1, 1e-14);
    EXPECT_NEAR(a[0].length(), 0.1, 1e-14);
    EXPECT_EQ(coarse.injectedCount(), 3);
    EXPECT_TRUE(coarse.inject(1.0).empty());
}

TEST(FiberInjector, restartFromCountContinuesTheStream)
{
    FiberInjector first(stream());
    first.inject(0.2); // two fibers
    FiberInjector restarted(stream());
    restarted.setInjectedCount(first.injectedCount());
    const auto next = restarted.inject(0.3);
    ASSERT_EQ(next.size(), 1u); // only the one born at 0.25
    EXPECT_NEAR(next[0].positions()(1, 0), 1.0 - 0.5 * 0.05, 1e-12);
}

TEST(FiberInjector, badEntriesAreNamed)
{
    auto s = stream();
    s.rate = 0.0;
    try
    {
        FiberInjector bad(s);
        FAIL() << "no exception";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("'rate'"), std::string::npos);
    }
    s = stream();
    s.endTime = s.startTime;
    EXPECT_THROW(FiberInjector{s}, std::invalid_argument);
}

// Rates above ~9,000 per second without an endTime: the adapter's default endTime is
// 1e15 s, and (endTime - startTime) * rate no longer fits a 64-bit integer.
TEST(FiberInjector, highRateWithoutEndTimeCountsExactly)
{
    auto s = stream();
    s.rate = 2e4; // one fiber every 50 microseconds
    s.startTime = 0.0;
    s.endTime = 1e15; // no endTime given
    FiberInjector injector(s);
    // t = 1 ms: births at k * 50 us for k = 0..20 (0.001 * 2e4 rounds to 20 exactly)
    EXPECT_EQ(injector.bornBy(0.001), 21);
    EXPECT_EQ(injector.inject(0.001).size(), 21u);
    EXPECT_EQ(injector.injectedCount(), 21);
    // t = 1 s: k = 0..20000
    EXPECT_EQ(injector.bornBy(1.0), 20001);

    // 1e12 per second for 1000 s: k = 0..1e15 (1000 * 1e12 is exact)
    s.rate = 1e12;
    EXPECT_EQ(FiberInjector(s).bornBy(1000.0), 1000000000000001L);
}

TEST(FiberInjector, endTimeStillCapsHighRates)
{
    auto s = stream();
    s.rate = 1e6;
    s.startTime = 0.0;
    s.endTime = 2.5e-5; // births at 0, 1, ..., 24 microseconds: 25
    EXPECT_EQ(FiberInjector(s).bornBy(1.0), 25);
}

TEST(FiberInjector, countsBeyondExactIntegersNameTheRate)
{
    auto s = stream();
    s.rate = 1e300;
    s.startTime = 0.0;
    s.endTime = 1e15;
    FiberInjector injector(s);
    EXPECT_EQ(injector.bornBy(-1.0), 0);
    try
    {
        injector.bornBy(1.0);
        FAIL() << "no exception";
    }
    catch (const std::overflow_error& e)
    {
        EXPECT_NE(std::string(e.what()).find("'rate'"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("'stream'"), std::string::npos);
    }
}

// A production flow as the stream's weight (docs/model.md sec. 9): 800 kg/h of glass in
// fibers of 4 um diameter, 30 mm long, 2500 kg/m^3 is 0.2222 kg/s / 9.4248e-10 kg per fiber
// = 2.3579e8 fibers/s; at 800 computed fibers/s each stands for 2.9473e5.
TEST(FiberInjector, representsFollowsFromTheGlassMassFlow)
{
    dropletFiber::FiberMaterial glass{2e-6, 2500.0, 7e10};
    const double perFiber = 2500.0 * M_PI * 2e-6 * 2e-6 * 0.03; // 9.42478e-10 kg, by hand
    const double n = dropletFiber::representsForMassFlow(800.0 / 3600.0, 800.0, 0.03, glass);
    EXPECT_NEAR(n, 800.0 / 3600.0 / perFiber / 800.0, 1e-9 * n);
    EXPECT_NEAR(n, 2.9473e5, 0.0001e5);
    FiberInjectorSpec s = stream();
    s.represents = 12.5;
    FiberInjector injector(s);
    EXPECT_NEAR(injector.spec().massFlow(), 10.0 * 12.5 * 2500.0 * M_PI * 16e-12 * 0.1, 1e-20);
    for (const auto& fiber : injector.inject(1.0))
    {
        EXPECT_EQ(fiber.represents(), 12.5); // every fiber of the stream
    }
    EXPECT_THROW(dropletFiber::representsForMassFlow(0.0, 800.0, 0.03, glass), std::invalid_argument);
    s.represents = 0.0;
    EXPECT_THROW(FiberInjector{s}, std::invalid_argument);
}
