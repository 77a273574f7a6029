/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The fibers' turbulent air (docs/model.md sec. 8): the fluctuation u' of
    the held fibers' points advanced each step before the fiber step, keyed
    by (seed, fiber id, point, time index) so that the realisation does not
    depend on the decomposition or on restarts (the time index continues
    over a restart and u' is part of each fiber's restart state); the log
    line saying whether it is on and why; the dispersion table.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "PstreamReduceOps.H"

#include <cmath>
#include <cstdint>
#include <vector>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dropletFiberCollision::advanceTurbulence
(
    const scalar dt,
    const ::dropletFiber::TurbulenceSample& turbulence
)
{
    // A model without k (Spalart-Allmaras, or k not yet developed) gives
    // k = 0: no fluctuation, which the log line would not tell
    // (collective: every processor calls this, with its points or none)
    const label points =
        returnReduce(label(turbulence.pointCount()), sumOp<label>());
    const scalar kMax = returnReduce
    (
        turbulence.pointCount() ? turbulence.kineticEnergy.maxCoeff() : 0.0,
        maxOp<scalar>()
    );
    if (points > 0 && kMax <= 0 && !warnedZeroK_)
    {
        WarningInFunction
            << type() << " " << name() << ": fibers.turbulence is "
            << ::dropletFiber::turbulenceModelName(turbulence_.settings.model).c_str()
            << " but the case's turbulence model gives k = 0 at every fiber"
            << " point at time " << time_.timeName() << " (a model without k,"
            << " such as Spalart-Allmaras?): the fibers see the mean air only"
            << " (said once)." << endl;
        warnedZeroK_ = true;
    }
    if (turbulence.pointCount() == 0)
    {
        return;   // no air sampled here (no movable fiber, or no drag)
    }
    const std::vector<std::uint64_t> ids(held_.id.begin(), held_.id.end());
    ::dropletFiber::advanceTurbulentVelocities
    (
        held_.fibers,
        ids,
        turbulence,
        turbulence_.settings,
        std::uint64_t(time_.timeIndex()),
        dt
    );
}


void Foam::functionObjects::dropletFiberCollision::reportTurbulence() const
{
    const auto& s = turbulence_.settings;
    Info<< "    fibers.turbulence: "
        << ::dropletFiber::turbulenceModelName(s.model).c_str() << " ("
        << turbulence_.reason.c_str() << ")";
    if (s.model != ::dropletFiber::TurbulenceModelType::none)
    {
        Info<< ": u' with variance 2k/3, T_L = " << s.timeScaleCoeff
            << " k/epsilon, L = " << s.lengthScaleCoeff
            << " k^1.5/epsilon along the fibers, seed " << label(s.seed);
    }
    else
    {
        Info<< ": the fibers see the mean air only";
    }
    if
    (
        s.model != ::dropletFiber::TurbulenceModelType::none
     && solverSettings_.drag.model == ::dropletFiber::DragModelType::none
    )
    {
        Info<< " (no effect: fibers.drag is none)";
    }
    Info<< nl;
}


void Foam::functionObjects::dropletFiberCollision::writeFiberDispersion()
{
    if (turbulence_.settings.model == ::dropletFiber::TurbulenceModelType::none)
    {
        return;
    }
    // Sums over the movable fibers of all processors: count, centres and
    // their squares per direction; points and u'^2 per component
    List<scalar> sums(11, Zero);
    for (const ::dropletFiber::Fiber& fiber : held_.fibers)
    {
        if (fiber.immobile())
        {
            continue;
        }
        const Eigen::Vector3d c = fiber.centreOfMass();
        sums[0] += 1;
        for (int d = 0; d < 3; ++d)
        {
            sums[1 + d] += c(d);
            sums[4 + d] += c(d)*c(d);
        }
        const Eigen::Matrix3Xd& u = fiber.state().turbulentVelocity;
        sums[7] += scalar(fiber.pointCount());
        for (int d = 0; d < 3 && u.cols(); ++d)
        {
            sums[8 + d] += u.row(d).squaredNorm();
        }
    }
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    if (!writeToFile() || !Pstream::master())
    {
        return;
    }
    if (!dispersionFile_.valid())
    {
        dispersionFile_ = createFile("fiberDispersion");
        OFstream& os = dispersionFile_();
        writeHeader(os, "Movable fibers: centres of mass and turbulent velocity u' (docs/model.md sec. 8)");
        writeCommented(os, "Time");
        for
        (
            const char* column :
            {
                "fibers", "meanCentreX", "meanCentreY", "meanCentreZ",
                "spreadX", "spreadY", "spreadZ",
                "uTurbRmsX", "uTurbRmsY", "uTurbRmsZ"
            }
        )
        {
            writeTabbed(os, column);
        }
        os  << endl;
    }
    OFstream& os = dispersionFile_();
    writeCurrentTime(os);
    const scalar n = max(sums[0], scalar(1));
    const scalar points = max(sums[7], scalar(1));
    os  << tab << label(sums[0]);
    for (int d = 0; d < 3; ++d)
    {
        os  << tab << sums[1 + d]/n;
    }
    for (int d = 0; d < 3; ++d)
    {
        const scalar mean = sums[1 + d]/n;
        os  << tab << std::sqrt(max(sums[4 + d]/n - mean*mean, scalar(0)));
    }
    for (int d = 0; d < 3; ++d)
    {
        os  << tab << std::sqrt(sums[8 + d]/points);
    }
    os  << endl;
}

// ************************************************************************* //
