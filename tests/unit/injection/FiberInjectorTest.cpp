// FiberInjector: counts and placement by hand.
#include "injection/FiberInjector.hpp"

#include <gtest/gtest.h>

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
