// TurbulentAir (docs/model.md sec. 8) in homogeneous isotropic turbulence with zero mean
// air: the variance 2k/3 seen by the points, the autocorrelation exp(-tau/T_L) in time
// (at a step as long as T_L: the update is exact at any step), the correlation
// exp(-ds/L) along a fiber, Taylor's dispersion of tracers and of fibers whose response
// time is short against T_L, k = 0 identical to no turbulence, and the realisation
// independent of the order and grouping of the fibers (decomposition) and of restarts.
// Statistical tolerances: 4 standard errors of the estimate, stated at each check.
#include "FiberTestSupport.hpp"

#include "fiber/TurbulentAir.hpp"

#include <cmath>
#include <iostream>

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{

// k = 0.015 m^2/s^2 (sigma^2 = 0.01 m^2/s^2), epsilon = 0.075 m^2/s^3: with the
// default coefficients T_L = 0.5 k/epsilon = 0.1 s, L = 0.16432 k^1.5/epsilon = 4.02 mm.
constexpr double kinetic = 0.015;
constexpr double dissipation = 0.075;
constexpr double variance = 2.0 * kinetic / 3.0;
constexpr double timeScale = 0.1;
const double lengthScale = 0.16432 * std::pow(kinetic, 1.5) / dissipation;

TurbulenceSettings ornsteinUhlenbeck(double lengthScaleCoeff = 0.16432)
{
    TurbulenceSettings s;
    s.model = TurbulenceModelType::ornsteinUhlenbeck;
    s.lengthScaleCoeff = lengthScaleCoeff;
    s.seed = 2011u;
    return s;
}

// count straight fibers of `segments` segments of length spacing, 1 cm apart.
std::vector<Fiber> fiberRow(int count, int segments, double spacing)
{
    std::vector<Fiber> fibers;
    for (int f = 0; f < count; ++f)
    {
        fibers.emplace_back(straightPoints(segments, Eigen::Vector3d(0, 0.01 * f, 0),
                                           Eigen::Vector3d::UnitX(), segments * spacing),
                            glassFiber());
    }
    return fibers;
}

std::vector<std::uint64_t> idsFrom(std::uint64_t first, std::size_t count)
{
    std::vector<std::uint64_t> ids(count);
    for (std::size_t f = 0; f < count; ++f)
        ids[f] = first + f;
    return ids;
}

TurbulenceSample uniformTurbulence(const std::vector<Fiber>& fibers, double k, double epsilon)
{
    const Eigen::Index n = airSampleLayout(fibers).pointCount;
    return {Eigen::VectorXd::Constant(n, k), Eigen::VectorXd::Constant(n, epsilon)};
}

// k and epsilon as smooth fields of position (what a CFD sample gives).
TurbulenceSample turbulenceField(const std::vector<Fiber>& fibers)
{
    const Eigen::Matrix3Xd x = airSamplePoints(fibers);
    TurbulenceSample s{Eigen::VectorXd(x.cols()), Eigen::VectorXd(x.cols())};
    for (Eigen::Index i = 0; i < x.cols(); ++i)
    {
        s.kineticEnergy(i) = 0.01 * (1.0 + 0.5 * std::sin(300.0 * x(0, i) + 40.0 * x(1, i)));
        s.dissipation(i) = 0.05 * (1.0 + 0.5 * std::cos(200.0 * x(2, i) + 30.0 * x(1, i)));
    }
    return s;
}

void advance(std::vector<Fiber>& fibers, const std::vector<std::uint64_t>& ids, const TurbulenceSettings& s,
             std::uint64_t step, double dt)
{
    advanceTurbulentVelocities(fibers, ids, uniformTurbulence(fibers, kinetic, dissipation), s, step, dt);
}

} // namespace

// 2000 fibers x 5 independent points x 3 components = 30000 values: the sample
// variance's relative standard error is sqrt(2/30000) = 0.0082; tolerance 0.033.
TEST(TurbulentAir, VarianceIsTwoThirdsK)
{
    std::vector<Fiber> fibers = fiberRow(2000, 4, 1e-3);
    const std::vector<std::uint64_t> ids = idsFrom(0, fibers.size());
    for (std::uint64_t step = 1; step <= 6; ++step)
    {
        advance(fibers, ids, ornsteinUhlenbeck(1e-9), step, 0.3 * timeScale);
        double sum2 = 0.0;
        for (const Fiber& fiber : fibers)
            sum2 += fiber.state().turbulentVelocity.squaredNorm();
        std::cout << "variance / (2k/3) at step " << step << ": " << sum2 / (30000 * variance) << "\n";
        EXPECT_NEAR(sum2 / (30000 * variance), 1.0, 0.033) << "step " << step; // first: stationary start
    }
}

// Correlation estimates of 30000 pairs: standard error <= sqrt(2/30000) = 0.0082;
// tolerance 0.033. dt = 0.7 T_L: an Euler scheme would be far off here.
TEST(TurbulentAir, AutocorrelationInTimeIsExponential)
{
    std::vector<Fiber> fibers = fiberRow(2000, 4, 1e-3);
    const std::vector<std::uint64_t> ids = idsFrom(100, fibers.size());
    const double dt = 0.7 * timeScale;
    advance(fibers, ids, ornsteinUhlenbeck(1e-9), 1, dt);
    std::vector<Eigen::Matrix3Xd> start;
    for (const Fiber& fiber : fibers)
        start.push_back(fiber.state().turbulentVelocity);
    for (std::uint64_t lag = 1; lag <= 3; ++lag)
    {
        advance(fibers, ids, ornsteinUhlenbeck(1e-9), 1 + lag, dt);
        double cross = 0.0;
        for (std::size_t f = 0; f < fibers.size(); ++f)
            cross += (start[f].array() * fibers[f].state().turbulentVelocity.array()).sum();
        std::cout << "autocorrelation at tau = " << double(lag) * dt / timeScale
                  << " T_L: " << cross / (30000 * variance)
                  << ", exp(-tau/T_L) = " << std::exp(-double(lag) * dt / timeScale) << "\n";
        EXPECT_NEAR(cross / (30000 * variance), std::exp(-double(lag) * dt / timeScale), 0.033)
            << "lag " << lag;
    }
}

// One pair (point 10, point 10 + j) per fiber and component, 4000 fibers, at 5 steps
// 5 T_L apart (correlated by e^-5 only): 60000 pairs, standard error <= 0.0058;
// tolerance 0.025. Segments L/4 long: expected exp(-j/4).
TEST(TurbulentAir, CorrelationAlongFiberIsExponential)
{
    std::vector<Fiber> fibers = fiberRow(4000, 40, 0.25 * lengthScale);
    const std::vector<std::uint64_t> ids = idsFrom(7, fibers.size());
    const std::vector<Eigen::Index> lags{1, 2, 4, 8, 16};
    std::vector<double> cross(lags.size(), 0.0);
    for (std::uint64_t step = 1; step <= 5; ++step)
    {
        advance(fibers, ids, ornsteinUhlenbeck(), step, 5 * timeScale);
        for (const Fiber& fiber : fibers)
        {
            const Eigen::Matrix3Xd& u = fiber.state().turbulentVelocity;
            for (std::size_t j = 0; j < lags.size(); ++j)
                cross[j] += u.col(10).dot(u.col(10 + lags[j]));
        }
    }
    for (std::size_t j = 0; j < lags.size(); ++j)
    {
        std::cout << "correlation at ds = " << 0.25 * double(lags[j])
                  << " L: " << cross[j] / (60000 * variance)
                  << ", exp(-ds/L) = " << std::exp(-0.25 * double(lags[j])) << "\n";
        EXPECT_NEAR(cross[j] / (60000 * variance), std::exp(-0.25 * double(lags[j])), 0.025)
            << "lag " << lags[j];
    }
}

// Tracers dX/dt = u' (trapezoidal in time, dt = T_L/20): Taylor (1921) for the
// exponential autocorrelation, MSD = 2 sigma^2 T_L (t - T_L (1 - exp(-t/T_L))), which
// is sigma^2 t^2 for t << T_L and 2 sigma^2 T_L t for t >> T_L. 16000 independent
// tracers x 3 components: relative standard error of the MSD sqrt(2/48000) = 0.0065;
// tolerance 0.03, plus the limits' own departure where they are checked.
TEST(TurbulentAir, TracersDisperseAsTaylor)
{
    std::vector<Fiber> fibers = fiberRow(8000, 1, 1e-3);
    const std::vector<std::uint64_t> ids = idsFrom(0, fibers.size());
    const double dt = timeScale / 20.0;
    std::vector<Eigen::Matrix3Xd> displacement(fibers.size(), Eigen::Matrix3Xd::Zero(3, 2));
    advance(fibers, ids, ornsteinUhlenbeck(1e-9), 0, dt);
    for (int step = 1; step <= 200; ++step)
    {
        std::vector<Eigen::Matrix3Xd> before;
        for (const Fiber& fiber : fibers)
            before.push_back(fiber.state().turbulentVelocity);
        advance(fibers, ids, ornsteinUhlenbeck(1e-9), std::uint64_t(step), dt);
        double msd = 0.0;
        for (std::size_t f = 0; f < fibers.size(); ++f)
        {
            displacement[f] += 0.5 * dt * (before[f] + fibers[f].state().turbulentVelocity);
            msd += displacement[f].squaredNorm();
        }
        msd /= 3.0 * 2.0 * double(fibers.size());
        const double t = step * dt;
        const double taylor = 2 * variance * timeScale * (t - timeScale * (1 - std::exp(-t / timeScale)));
        if (step == 1 || step == 5 || step == 20 || step == 100 || step == 200)
        {
            std::cout << "tracers: t/T_L = " << t / timeScale << ", MSD / Taylor = " << msd / taylor << "\n";
            EXPECT_NEAR(msd / taylor, 1.0, 0.03) << "t/T_L = " << t / timeScale;
        }
        if (step == 1) // ballistic: sigma^2 t^2 (the exact law is 1.7 % below at t = T_L/20)
            EXPECT_NEAR(msd / (variance * t * t), 1.0, 0.03 + 0.017);
        if (step == 200) // diffusive: 2 sigma^2 T_L t (the exact law is 10 % below at 10 T_L)
            EXPECT_NEAR(msd / (2 * variance * timeScale * t), 1.0, 0.03 + 0.10);
    }
}

namespace
{

FiberSolverSettings oseenDrag()
{
    FiberSolverSettings s;
    s.drag.model = DragModelType::slenderBodyOseen;
    return s;
}

// Mixed fibers (pinned, clamped, free, an immobile one) in air with a mean velocity.
std::vector<Fiber> mixedFibers()
{
    std::vector<Fiber> fibers;
    fibers.emplace_back(straightPoints(12, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0.2), 0.01),
                        glassFiber(), EndCondition::pinnedEnd(), EndCondition::freeEnd());
    fibers.emplace_back(straightPoints(9, Eigen::Vector3d(0, 0.01, 0), Eigen::Vector3d(0, 1, 1), 0.02),
                        glassFiber(), EndCondition::clampedEnd(Eigen::Vector3d(0.01, 0, 0)),
                        EndCondition::freeEnd());
    fibers.push_back(Fiber::immobileFiber(
        straightPoints(5, Eigen::Vector3d(0, 0, -0.01), Eigen::Vector3d::UnitY(), 0.01), glassFiber()));
    fibers.emplace_back(straightPoints(15, Eigen::Vector3d(0.02, 0, 0), Eigen::Vector3d(0, 0, 1), 0.015),
                        glassFiber());
    fibers.emplace_back(straightPoints(6, Eigen::Vector3d(0.03, 0.01, 0), Eigen::Vector3d(1, 1, 0), 0.005),
                        glassFiber());
    return fibers;
}

// Steps [from, to) of the coupled update: u' first, then the fiber step with it.
void coupledSteps(std::vector<Fiber>& fibers, const std::vector<std::uint64_t>& ids,
                  const TurbulenceSettings& t, std::uint64_t from, std::uint64_t to, bool zeroK = false)
{
    FiberSolver solver(oseenDrag());
    for (std::uint64_t step = from; step < to; ++step)
    {
        TurbulenceSample k = turbulenceField(fibers);
        if (zeroK)
            k.kineticEnergy.setZero();
        advanceTurbulentVelocities(fibers, ids, k, t, step, 1e-3);
        solver.step(fibers, 1e-3, uniformAir(fibers, Eigen::Vector3d(0.5, 0.1, 0.0), 1.2, 1.8e-5));
    }
}

void expectSameBits(const std::vector<Fiber>& a, const std::vector<Fiber>& b)
{
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t f = 0; f < a.size(); ++f)
    {
        EXPECT_TRUE(a[f].positions() == b[f].positions()) << "fiber " << f;
        EXPECT_TRUE(a[f].velocities() == b[f].velocities()) << "fiber " << f;
        EXPECT_TRUE(a[f].tension() == b[f].tension()) << "fiber " << f;
        EXPECT_TRUE(a[f].state().turbulentVelocity == b[f].state().turbulentVelocity) << "fiber " << f;
    }
}

} // namespace

TEST(TurbulentAir, ZeroKineticEnergyIsNoTurbulenceToTheBit)
{
    std::vector<Fiber> laminar = mixedFibers(), zeroK = mixedFibers();
    const std::vector<std::uint64_t> ids = idsFrom(0, laminar.size());
    coupledSteps(laminar, ids, TurbulenceSettings(), 0, 30);
    coupledSteps(zeroK, ids, ornsteinUhlenbeck(), 0, 30, true);
    for (std::size_t f = 0; f < zeroK.size(); ++f)
    {
        if (!zeroK[f].immobile())
            EXPECT_TRUE(zeroK[f].state().turbulentVelocity.isZero(0.0));
        EXPECT_TRUE(laminar[f].positions() == zeroK[f].positions());
        EXPECT_TRUE(laminar[f].velocities() == zeroK[f].velocities());
        EXPECT_TRUE(laminar[f].tension() == zeroK[f].tension());
    }
    // ... and turbulence does move them (the comparison above could not pass by accident)
    std::vector<Fiber> turbulent = mixedFibers();
    coupledSteps(turbulent, ids, ornsteinUhlenbeck(), 0, 30);
    EXPECT_GT((turbulent[0].positions() - laminar[0].positions()).norm(), 1e-6);
}

// Two "processors" holding the fibers in other groups and orders give the bits of one.
TEST(TurbulentAir, IndependentOfDecompositionAndOrder)
{
    std::vector<Fiber> all = mixedFibers();
    const std::vector<std::uint64_t> ids{3, 10, 11, std::uint64_t(1) << 33, 42};
    coupledSteps(all, ids, ornsteinUhlenbeck(), 5, 25);

    const std::vector<Fiber> initial = mixedFibers();
    std::vector<Fiber> first{initial[4], initial[1]}, second{initial[3], initial[2], initial[0]};
    coupledSteps(first, {ids[4], ids[1]}, ornsteinUhlenbeck(), 5, 25);
    coupledSteps(second, {ids[3], ids[2], ids[0]}, ornsteinUhlenbeck(), 5, 25);
    expectSameBits(all, {second[2], first[1], second[1], second[0], first[0]});
}

// The state saved after 12 steps, loaded into new fibers and a new solver, continues
// the realisation of an uninterrupted run to the bit.
TEST(TurbulentAir, RestartContinuesTheRealisation)
{
    std::vector<Fiber> straight = mixedFibers();
    const std::vector<std::uint64_t> ids = idsFrom(20, straight.size());
    coupledSteps(straight, ids, ornsteinUhlenbeck(), 0, 25);

    std::vector<Fiber> before = mixedFibers();
    coupledSteps(before, ids, ornsteinUhlenbeck(), 0, 12);
    std::vector<Fiber> restarted;
    for (const Fiber& fiber : before)
        restarted.emplace_back(FiberState(fiber.state()));
    coupledSteps(restarted, ids, ornsteinUhlenbeck(), 12, 25);
    expectSameBits(straight, restarted);
}

// Fibers of 3 points (1 mm) with isotropic linear drag c, response time
// tau = line density / c = T_L / 100, no gravity, no mean air. The centre of mass obeys
// dV/dt = (ubar - V)/tau, ubar = sum_i w_i u'_i, w = nodal length / fiber length =
// (1/4, 1/2, 1/4) (internal forces cancel; lumped masses follow the nodal lengths), so
// for tau << T_L the centre disperses as a tracer of variance
// var(ubar) = sigma^2 sum_ij w_i w_j r^|i-j|, r = exp(-l/L) (the model's correlation
// along the fiber), and time scale T_L: MSD = 2 var(ubar) T_L (t - T_L (1 - e^-t/T_L)).
// Measured after 20 tau of warm-up (the fibers start at rest). 2000 fibers x 3
// components: relative standard error sqrt(2/6000) = 0.018; tolerance 0.08 (4.4 of them).
TEST(TurbulentAir, ShortResponseFibersDisperseAsTaylor)
{
    std::vector<Fiber> fibers = fiberRow(2000, 2, 0.5e-3);
    const std::vector<std::uint64_t> ids = idsFrom(0, fibers.size());
    const double lineDensity = glassFiber().density * M_PI * std::pow(glassFiber().radius, 2);
    FiberSolverSettings settings;
    settings.gravity.setZero();
    settings.drag.model = DragModelType::linear;
    settings.drag.normalCoefficient = settings.drag.tangentialCoefficient = lineDensity / (timeScale / 100);
    FiberSolver solver(settings);
    const AirSample still = uniformAir(fibers, Eigen::Vector3d::Zero(), 1.2, 1.8e-5);
    const double dt = timeScale / 20.0;
    auto step = [&](std::uint64_t n)
    {
        advance(fibers, ids, ornsteinUhlenbeck(), n, dt);
        solver.step(fibers, dt, still);
    };
    step(0); // warm-up: 5 steps = 25 tau
    for (std::uint64_t n = 1; n < 5; ++n)
        step(n);
    std::vector<Eigen::Vector3d> start;
    for (const Fiber& fiber : fibers)
        start.push_back(fiber.centreOfMass());

    const double r = std::exp(-0.5e-3 / lengthScale);
    const double meanVariance = variance * (0.375 + 0.5 * r + 0.125 * r * r);
    for (int n = 1; n <= 100; ++n)
    {
        step(std::uint64_t(n + 4));
        if (n != 4 && n != 100)
            continue;
        double msd = 0.0;
        for (std::size_t f = 0; f < fibers.size(); ++f)
            msd += (fibers[f].centreOfMass() - start[f]).squaredNorm();
        msd /= 3.0 * double(fibers.size());
        const double t = n * dt;
        const double taylor = 2 * meanVariance * timeScale * (t - timeScale * (1 - std::exp(-t / timeScale)));
        std::cout << "fibers: t/T_L = " << t / timeScale << ", MSD / Taylor = " << msd / taylor << "\n";
        EXPECT_NEAR(msd / taylor, 1.0, 0.08) << "t/T_L = " << t / timeScale;
    }
}

// Turbulence switched off (a run-time edit, or a restart with model none from a
// turbulent state): u' is dropped and the fibers go on as in laminar air, to the bit.
TEST(TurbulentAir, SwitchedOffGoesOnAsLaminar)
{
    std::vector<Fiber> fibers = mixedFibers();
    const std::vector<std::uint64_t> ids = idsFrom(0, fibers.size());
    coupledSteps(fibers, ids, ornsteinUhlenbeck(), 0, 10);
    ASSERT_FALSE(fibers[0].state().turbulentVelocity.isZero(0.0));
    std::vector<Fiber> laminar;
    for (const Fiber& fiber : fibers)
    {
        FiberState state = fiber.state();
        state.turbulentVelocity.resize(3, 0);
        laminar.emplace_back(state);
    }
    coupledSteps(fibers, ids, TurbulenceSettings(), 10, 20);
    coupledSteps(laminar, ids, TurbulenceSettings(), 10, 20);
    expectSameBits(fibers, laminar);
    EXPECT_EQ(fibers[0].state().turbulentVelocity.cols(), 0);
}
