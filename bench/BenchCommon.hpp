// BenchCommon: small helpers shared by the benchmark programs of bench/ (timing with
// repeats, a fast deterministic random generator, a do-not-optimise sink). Benchmarks
// print tables; they are measurements, never pass/fail tests.
//
// Timing convention: every figure is the best (minimum) of `repeats` runs of the same
// work; "spread" is (slowest - fastest) / fastest of those runs, in percent. The machine
// is shared with other work, so the minimum is the figure closest to the code's own cost
// and the spread says how noisy the run was.
//
// Clock: the CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID), not wall time, so
// that time slices given to other processes on a loaded machine do not count (they still
// cost some cache refills). BENCH_CLOCK=wall switches to wall-clock time. All programs
// here are single-threaded.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace bench
{

struct Clock
{
    using time_point = double;
    static bool wall()
    {
        static const bool useWall = []
        {
            const char* v = std::getenv("BENCH_CLOCK");
            return v != nullptr && std::string(v) == "wall";
        }();
        return useWall;
    }
    static double now()
    {
        timespec ts{};
        clock_gettime(wall() ? CLOCK_MONOTONIC : CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }
    static const char* name() { return wall() ? "wall-clock time" : "thread CPU time"; }
};

inline double secondsSince(Clock::time_point start)
{
    return Clock::now() - start;
}

struct Timing
{
    double best = 0.0;  // s
    double worst = 0.0; // s
    int repeats = 0;
    double spreadPercent() const { return best > 0.0 ? 100.0 * (worst - best) / best : 0.0; }
};

// Runs `work` `repeats` times (after `setup` each time, untimed) and keeps best/worst.
template <class Setup, class Work>
Timing timeRepeated(int repeats, Setup&& setup, Work&& work)
{
    Timing t;
    t.repeats = repeats;
    t.best = 1e300;
    for (int r = 0; r < repeats; ++r)
    {
        setup();
        const auto start = Clock::now();
        work();
        const double s = secondsSince(start);
        t.best = std::min(t.best, s);
        t.worst = std::max(t.worst, s);
    }
    return t;
}

template <class Work>
Timing timeRepeated(int repeats, Work&& work)
{
    return timeRepeated(
        repeats, [] {}, work);
}

// splitmix64: fast, deterministic, good enough for positions and directions.
class Random
{
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next()
    {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    // uniform in [0, 1)
    double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
    double uniform(double a, double b) { return a + (b - a) * uniform(); }

private:
    std::uint64_t state_;
};

// Keeps a value alive so the compiler cannot drop the computation that made it.
inline void sink(double value)
{
    static volatile double keep = 0.0;
    keep = value;
    (void)keep;
}

inline double envDouble(const char* name, double fallback)
{
    const char* v = std::getenv(name);
    return v ? std::atof(v) : fallback;
}

inline std::string formatCount(double n)
{
    char buffer[32];
    const double e = std::floor(std::log10(n) + 1e-9);
    const double m = n / std::pow(10.0, e);
    if (std::abs(m - 1.0) < 1e-9)
    {
        std::snprintf(buffer, sizeof buffer, "1e%d", static_cast<int>(e));
    }
    else
    {
        std::snprintf(buffer, sizeof buffer, "%.3g", n);
    }
    return buffer;
}

} // namespace bench
