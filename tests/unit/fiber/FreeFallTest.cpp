// Free fall without drag: the centre of mass follows g t^2 / 2 and the shape is
// kept. The midpoint rule integrates constant acceleration exactly.
#include "FiberTestSupport.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{

void checkFreeFall(Fiber fiber, const char* label)
{
    FiberSolverSettings settings;
    FiberSolver solver(settings);
    std::vector<Fiber> fibers{fiber};
    const Eigen::Vector3d com0 = fiber.centreOfMass();
    const Eigen::Matrix3Xd shape0 = fiber.positions().colwise() - com0;
    const double dt = 1e-3;
    const int steps = 200;
    const RunSummary summary = run(solver, fibers, dt, steps);

    const double t = dt * steps;
    const Eigen::Vector3d expectedDrop = 0.5 * settings.gravity * t * t;
    const Eigen::Vector3d com = fibers[0].centreOfMass();
    const double comError = (com - com0 - expectedDrop).norm() / expectedDrop.norm();
    const Eigen::Matrix3Xd shape = fibers[0].positions().colwise() - com;
    const double shapeError = (shape - shape0).cwiseAbs().maxCoeff() / fibers[0].length();
    std::printf("free fall (%s): centre-of-mass error %.3e, shape error %.3e, segment error %.3e\n", label,
                comError, shapeError, summary.worstSegmentError);
    EXPECT_LT(comError, 1e-9);
    EXPECT_LT(shapeError, 1e-9);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
}

} // namespace

TEST(FreeFall, LimpCurvedFiberKeepsShape)
{
    // An arc (no bending stiffness: any shape is stress-free).
    const int segments = 50;
    Eigen::Matrix3Xd points(3, segments + 1);
    for (int i = 0; i <= segments; ++i)
    {
        const double phi = 1.5 * i / segments;
        points.col(i) = Eigen::Vector3d(0.01 * std::cos(phi), 0.01 * std::sin(phi), 0.003 * phi);
    }
    FiberMaterial limp = glassFiber();
    limp.youngsModulus = 0.0;
    checkFreeFall(Fiber(points, limp), "limp arc");
}

TEST(FreeFall, StiffStraightTiltedFiberKeepsShape)
{
    checkFreeFall(
        Fiber(straightPoints(50, Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(1.0, 0.5, 2.0), 0.02),
              glassFiber()),
        "stiff straight");
}
