/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The tables: the per-step table and its log line, the parallel
    statistics, the binder distribution and the fibers' dispersion.

\*---------------------------------------------------------------------------*/

#include "couplingOutput.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::couplingOutput::writeParallelStatisticsHeader
(
    OFstream& os
)
{
    writeHeader
    (
        os,
        "Per time step, maxima over processors; the work (parcels to"
        " cpuFibers, thread CPU time in s) as maximum and mean"
    );
    writeCommented(os, "Time");
    writeTabbed(os, "nodesHeldMax");
    writeTabbed(os, "fibersHeldMax");
    writeTabbed(os, "bytesSentMax");
    writeTabbed(os, "bytesParcelsMax");
    writeTabbed(os, "bytesGridQueriesMax");
    writeTabbed(os, "bytesFibersMax");
    // In the order of parallelStatistics::work::operator[]
    for
    (
        const char* figure :
        {
            "parcels", "parcelCopies", "nodeWeights", "collisionSamples",
            "fiberPoints", "cpuDeposit", "cpuCollision", "cpuFibers"
        }
    )
    {
        writeTabbed(os, word(figure) + "Max");
        writeTabbed(os, word(figure) + "Mean");
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::dropletFiber::couplingOutput::tableColumns
(
    const wordList& columns
)
{
    // The table's layout: the fibers, the parcels and the grid, the capture,
    // the fibers' mass and the solver; depletion's binder balance (eq. 9
    // before the limit, the mass taken from the parcels = capturedStep, the
    // parcel mass flying on), the clouds' own figures (sprayed = airborne +
    // evaporated + escaped + capturedTotal) and the captured mass per liquid
    // species (captured_<species>); with a belt the glass and binder laid so
    // far; the stages' wall times (gather and deposit; collision and
    // depletion's removal; the fibers' injection, step and hand-over)
    static const wordList layout
    {
        "fibers", "fibersRepresented", "parcels", "droplets", "parcelMass",
        "massOnGrid", "massOutsideGrid", "capturedStep", "capturedTotal",
        "fiberMass", "maxSegmentLengthError",
        "demandedStep", "removedStep", "airborneMass",
        "sprayedMass", "evaporatedMass", "escapedMass", "captured_",
        "laidGlass", "laidBinder",
        "wallTimeDeposition", "wallTimeCollision", "wallTimeFibers"
    };
    const auto place = [](const word& column)
    {
        const label i = layout.find(column);
        if (i >= 0)
        {
            return i;
        }
        if (column.starts_with("captured_"))
        {
            return layout.find("captured_");
        }
        FatalErrorInFunction
            << "Column '" << column << "' is not in the table's layout "
            << layout << abort(FatalError);
        return label(-1);
    };
    // Stable: the species in the order given
    labelList order(identity(columns.size()));
    std::stable_sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b)
        {
            return place(columns[a]) < place(columns[b]);
        }
    );
    wordList ordered(columns.size());
    forAll(order, i)
    {
        ordered[i] = columns[order[i]];
    }
    return ordered;
}


void Foam::dropletFiber::couplingOutput::writeTableHeader
(
    const wordList& columns
)
{
    columns_ = tableColumns(columns);
    if (!writeToFile())
    {
        return;
    }
    OFstream& os = file();
    writeHeader(os, "Droplet-fiber coupling, per time step (masses in kg, times in s)");
    writeCommented(os, "Time");
    for (const word& column : columns_)
    {
        writeTabbed(os, column);
    }
    os  << endl;
}


void Foam::dropletFiber::couplingOutput::writeStep(const stepFigures& step)
{
    if (owner_.log)
    {
        Info<< type() << " " << name() << ": parcels "
            << label(step["parcels"]) << ", fibers " << label(step["fibers"])
            << ", captured " << step["capturedStep"] << " kg (total "
            << step["capturedTotal"] << " kg), segment-length error "
            << step["maxSegmentLengthError"] << ", sub-steps "
            << label(step["subSteps"]);
        if (step.found("removedStep"))
        {
            Info<< ", removed from the parcels " << step["removedStep"]
                << " kg, airborne " << step["airborneMass"] << " kg";
        }
        Info<< endl;
    }

    if (writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        for (const word& column : columns_)
        {
            os  << tab;
            step.write(os, column);
        }
        os  << endl;
    }
}


void Foam::dropletFiber::couplingOutput::writeParallelStatistics
(
    const parallelStatistics::spread& all
)
{
    // Also in a serial run (one processor: sends nothing, max = mean), the
    // reference of the work per processor
    if (!writeToFile())
    {
        return;
    }
    if (!parallelStatisticsFile_.valid())
    {
        parallelStatisticsFile_ = createFile("parallelStatistics");
        writeParallelStatisticsHeader(parallelStatisticsFile_());
    }
    OFstream& os = parallelStatisticsFile_();
    const parallelStatistics::figures& maxima = all.maxima;
    writeCurrentTime(os);
    os  << tab << maxima.nodesHeld
        << tab << maxima.fibersHeld
        << tab << maxima.bytesSent
        << tab << maxima.bytesParcels
        << tab << maxima.bytesGridQueries
        << tab << maxima.bytesFibers;
    for (label i = 0; i < parallelStatistics::work::size; ++i)
    {
        os  << tab << all.maxWork[i] << tab << all.meanWork[i];
    }
    os  << endl;
}


void Foam::dropletFiber::couplingOutput::writeBinderDistribution
(
    const ::dropletFiber::BinderSums& sums,
    const word& collisionMode
)
{
    if (!writeToFile() || !Pstream::master())
    {
        return;
    }
    const ::dropletFiber::BinderFigures figures =
        ::dropletFiber::binderFigures(sums);
    if (!binderFile_.valid())
    {
        binderFile_ = createFile("binderDistribution");
        OFstream& os = binderFile_();
        writeHeader
        (
            os,
            "Binder along all fibers, per segment sigma = captured mass /"
            " length (docs/model.md sec. 3, discrete hits); collision mode "
          + collisionMode
          + "; expected*: the expected mode's mass on the same fibers"
        );
        writeCommented(os, "Time");
        for
        (
            const char* column :
            {
                "fiberLength", "segments", "bareFraction", "meanSigma",
                "sigmaCoV", "hitsPerLength", "expectedBareFraction",
                "expectedMeanSigma", "expectedSigmaCoV"
            }
        )
        {
            writeTabbed(os, column);
        }
        os  << endl;
    }
    OFstream& os = binderFile_();
    writeCurrentTime(os);
    os  << tab << figures.length
        << tab << label(sums.values[5])
        << tab << figures.bareFraction
        << tab << figures.meanSigma
        << tab << figures.sigmaVariation
        << tab << figures.hitsPerLength
        << tab << figures.expectedBareFraction
        << tab << figures.expectedMeanSigma
        << tab << figures.expectedSigmaVariation
        << endl;
}


void Foam::dropletFiber::couplingOutput::writeFiberDispersion(const List<scalar>& sums)
{
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
