/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The collision mass of the fibers' segments: their sample points (one at
    the midpoint, or one per grid spacing), the droplet field there from the
    coupling grid (one exchange), and the arithmetic of eq. 9.

\*---------------------------------------------------------------------------*/

#include "fiberCapture.H"
#include "collisionSettings.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::fiberCapture::fiberCapture
(
    const functionObject& owner,
    const fvMesh& mesh
)
:
    couplingStage(owner, mesh),
    depletion_(true),
    depletionSteps_(0),
    limitedSteps_(0),
    captured_(0),
    loggedLimit_(false),
    loggedHitsCut_(false),
    warnedSamplesOutside_(false)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::vector<Eigen::Vector3d>
Foam::dropletFiber::fiberCapture::collisionSamplePoints
(
    const heldFibers& held,
    const ::dropletFiber::GridSpec& spec,
    std::vector<int>& samplesPerSegment
) const
{
    std::vector<Eigen::Vector3d> points;
    samplesPerSegment.clear();
    for (const ::dropletFiber::Fiber& fiber : held.fibers)
    {
        const Eigen::Matrix3Xd& x = fiber.positions();
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            const int samples =
                ::dropletFiber::collisionSamples
                (
                    spec, x.col(j), x.col(j + 1), collision_
                );
            samplesPerSegment.push_back(samples);
            for (int s = 0; s < samples; ++s)
            {
                points.push_back
                (
                    ::dropletFiber::samplePoint(x.col(j), x.col(j + 1), samples, s)
                );
            }
        }
    }
    return points;
}


Foam::label Foam::dropletFiber::fiberCapture::collisionMasses
(
    const heldFibers& held,
    const scalar dt,
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<int>& samplesPerSegment,
    double* sampleMasses,
    ::dropletFiber::CaptureSources& capture
) const
{
    const std::vector<::dropletFiber::Fiber>& fibers = held.fibers;
    capture.clear();
    capture.resize(fibers.size());
    label samplesOutside = 0;
    std::size_t next = 0;
    std::size_t segment = 0;
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        const ::dropletFiber::Fiber& fiber = fibers[f];
        const Eigen::Matrix3Xd& x = fiber.positions();
        const Eigen::Matrix3Xd& v = fiber.velocities();
        capture[f].resize(fiber.segmentCount());
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            const Eigen::Vector3d segmentVelocity = 0.5*(v.col(j) + v.col(j + 1));
            const int samples = samplesPerSegment[segment++];
            const ::dropletFiber::SegmentCollision c =
                ::dropletFiber::collisionMassFromSamples
                (
                    fields.data() + next,
                    samples,
                    x.col(j),
                    x.col(j + 1),
                    fiber.material().radius,
                    segmentVelocity,
                    dt,
                    collision_,
                    sampleMasses ? sampleMasses + next : nullptr
                );
            next += std::size_t(samples);
            capture[f][j].mass = c.mass;
            capture[f][j].momentum = c.momentum;
            samplesOutside += c.samplesOutside;
        }
    }
    return samplesOutside;
}


void Foam::dropletFiber::fiberCapture::warnSamplesOutside
(
    const label samplesOutside,
    const ::dropletFiber::GridSpec& g
)
{
    if (samplesOutside > 0)
    {
        WarningInFunction
            << type() << " " << name() << ": " << samplesOutside
            << " collision sample points of fiber segments lie outside the"
            << " grid box at time " << time_.timeName()
            << ": those segments see no droplets there." << nl
            << "    Enlarge grid lower (" << g.lower.x() << ' ' << g.lower.y()
            << ' ' << g.lower.z() << ") / upper (" << g.upper.x() << ' '
            << g.upper.y() << ' ' << g.upper.z() << ") to cover the fibers"
            << " (warned once)." << endl;
        warnedSamplesOutside_ = true;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberCapture::read
(
    const dictionary& dict,
    const bool running
)
{
    collision_ = readCollisionSettings(dict);
    spread_ = readSpreadSettings(dict);
    const bool depletion = readDepletion(dict);
    if (running && depletion != depletion_)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'collision.depletion' was edited during the run ("
            << Switch(depletion_).c_str() << " -> "
            << Switch(depletion).c_str() << "): it is read at the start"
            << " only (the per-step table's columns follow it). Restart"
            << " the run to change it." << exit(FatalIOError);
    }
    depletion_ = depletion;
}


::dropletFiber::CaptureSources Foam::dropletFiber::fiberCapture::collide
(
    const heldFibers& held,
    couplingGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const scalar dt,
    parallelStatistics& statistics
)
{
    // The sample points of the segments of the fibers held here, then their
    // field values from the grid's blocks (one exchange), then the masses:
    // the arithmetic of collisionMass
    using stage = parallelStatistics::stage;
    std::vector<int> samplesPerSegment;
    std::vector<Eigen::Vector3d> points;
    statistics.timed
    (
        stage::collision,
        [&]() { points = collisionSamplePoints(held, grid.spec(), samplesPerSegment); }
    );
    statistics.countCollisionSamples(points.size());
    // Depletion: each sample's interpolated mass sum too; every sample's
    // mass (the hits are counted per sample)
    std::vector<double> massSums;
    std::vector<double> sampleMasses(points.size());
    const std::vector<::dropletFiber::DropletFieldValue> fields =
        grid.sample(points, statistics, depletion_ ? &massSums : nullptr);

    ::dropletFiber::CaptureSources capture;
    label samplesOutside = 0;
    statistics.timed
    (
        stage::collision,
        [&]()
        {
            samplesOutside = collisionMasses
            (
                held, dt, fields, samplesPerSegment,
                sampleMasses.data(), capture
            );
        }
    );
    // Once warned, no more reductions (the flag is the same on every
    // processor: it follows a reduced count)
    if (!warnedSamplesOutside_)
    {
        warnSamplesOutside
        (
            returnReduce(samplesOutside, sumOp<label>()), grid.spec()
        );
    }
    if (depletion_)
    {
        const std::vector<double> granted =
            limitCapture
            (
                held, grid, parcels, fields, points, massSums, sampleMasses,
                samplesPerSegment, dt, capture, statistics
            );
        countHits
        (
            held, grid, parcels, fields, granted, samplesPerSegment, capture,
            statistics
        );
    }
    else
    {
        countHits
        (
            held, grid, parcels, fields, sampleMasses, samplesPerSegment,
            capture, statistics
        );
    }
    return capture;
}


void Foam::dropletFiber::fiberCapture::countCaptured
(
    const heldFibers& held,
    const ::dropletFiber::CaptureSources& capture
)
{
    // Every physical fiber a computed one stands for took its capture
    scalar m = 0;
    for (std::size_t f = 0; f < capture.size(); ++f)
    {
        const scalar n = held.fibers[f].represents();
        for (const auto& segment : capture[f])
        {
            m += n*segment.mass;
        }
    }
    const scalar capturedStep = returnReduce(m, sumOp<scalar>());
    capturedStep_ = capturedStep;
    captured_ += capturedStep;
    if (depletion_)
    {
        step_.captured = capturedStep;
        run_.demanded += step_.demanded;
        run_.captured += step_.captured;
        run_.removed += step_.removed;
        ++depletionSteps_;
        limitedSteps_ += step_.nodesLimited > 0 ? 1 : 0;
    }
}


Foam::wordList Foam::dropletFiber::fiberCapture::stepColumns() const
{
    wordList columns{"capturedStep", "capturedTotal"};
    if (depletion_)
    {
        columns.append(wordList{"demandedStep", "removedStep", "airborneMass"});
    }
    return columns;
}


void Foam::dropletFiber::fiberCapture::addStepFigures(stepFigures& step) const
{
    step.add("capturedStep", capturedStep_);
    step.add("capturedTotal", captured_);
    if (depletion_)
    {
        step.add("demandedStep", step_.demanded);
        step.add("removedStep", step_.removed);
        step.add("airborneMass", step_.airborne);
    }
}


void Foam::dropletFiber::fiberCapture::report(Ostream& os) const
{
    os  << "    collision: samples per segment " << collision_.samples
        << " (1: midpoint, 0: one per grid spacing), radiusAverage "
        << radiusAverageName(collision_.radiusAverage)
        << ", mode " << collisionModeReport(collision_).c_str()
        << ", depletion " << Switch(depletion_).c_str()
        << (
               depletion_
             ? " (the captured droplets leave their parcels)"
             : " (the spray keeps every droplet: the paper's behaviour)"
           ) << nl;
}


void Foam::dropletFiber::fiberCapture::writeState
(
    const fileName&,
    dictionary&,
    dictionary& totals
)
{
    totals.add("captured", captured_);
}


void Foam::dropletFiber::fiberCapture::readState
(
    const dictionary& state,
    const fileName&
)
{
    captured_ = getCheckedScalar
    (
        state.subDict("totals"), "captured", nullptr,
        [](scalar v) { return v >= 0; }, ">= 0"
    );
}


//- The function object's entries the capture reads (collision's own: collisionSettings.C)
static const Foam::wordList captureKeys
{
    "collision"
};


Foam::wordList Foam::dropletFiber::fiberCapture::entries()
{
    return captureKeys;
}


// ************************************************************************* //
