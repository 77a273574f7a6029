#!/usr/bin/env bash
#------------------------------------------------------------------------------
# scaleOut.sh - how the dropletFiber function object scales with the number of
# processors: the channelSpray tutorial made 3D (bench/scaleOutCase.py: mesh
# 25 x 75 x 10 cells over 5 x 15 x 2 cm, the tutorial's spray, 12 fiber streams
# giving several hundred fibers, no write time) run for a few steps with density
# grids of ~1e5, 1e6 and 4e6 nodes on 1, 2 and 4 processors (decomposePar,
# simple, the channel cut along its length). One line per run:
#
#   ranks=N nodes=M nodesHeldMax=H peakRssMaxMiB=R bytesSentPerStepMax=B
#   fibersHeldMax=F depositMsPerStep=T depositImbalance=X fiberImbalance=Y
#   collisionImbalance=Z couplingCpuMsPerStep=C
#
# maxima over processors (and steps): H grid nodes stored, F fibers held, B
# bytes sent in the function object's exchanges in one step (the function
# object's postProcessing/dropletFiber/0/parallelStatistics.dat); R peak resident
# memory of a processor (GNU time); T the table's wallTimeDeposition (master:
# gather, deposit, parcel copies to the blocks their kernels reach) in ms, mean over the steps after the
# first 5. X, Y, Z: max / mean over processors of the deposit's, fiber step's and
# collision's thread CPU time per step (the work columns of parallelStatistics.dat,
# summed over the same steps; 1 is even); C the sum of the three stages' maximum
# thread CPU time per step in ms (scaleOutCase.py report). With -blocks, a second
# line gives the deposit's max / mean and busiest ms per step by phase: the window's
# fill (steps 6-10), the steady steps (after 10, but every balanceSteps-th) with the
# coupling's ms, those after the first weighing, those of the run's second half
# (developed: the localised spray's parcels per step level off after ~140 steps),
# and the re-partition steps. Runs with more processors
# than cores are oversubscribed: on a small machine T then includes the waiting of
# processes sharing a core (the thread CPU times do not). A benchmark: nothing is
# judged; compare figures only from the same session.
#
# Usage: bench/scaleOut.sh [-nodes "1e5 1e6 4e6"] [-ranks "1 2 4"] [-steps 30]
#                          [-samplesPerSegment N] [-localised] [-holders RULE]
#                          [-blocks subdomains|balanced] [-balanceSteps N]
#                          [-tiny] [-keep DIR]
#   -nodes    grid sizes (about; the spacing is chosen to give them)
#   -ranks    processor counts
#   -steps    time steps per run (5e-4 s each)
#   -samplesPerSegment N  collision samples per fiber segment (default: the
#             tutorial's, one per grid spacing: the corner queries then grow as
#             the spacing shrinks)
#   -localised the spray and the fibers in the top ~3 cm of the channel only (as
#             nozzles and spinner streams in a hood; scaleOutCase.py case --localised)
#   -holders RULE  the fibers' holders (fibers.holders: cells, roundRobin)
#   -blocks KIND   the grid blocks (grid.blocks: subdomains, balanced; balanced
#             re-partitions after every 5th step: the steps measured follow)
#   -balanceSteps N  with -blocks balanced: re-partition every N steps (5)
#   -tiny     a check of the script: grid 1e4 nodes, 1 and 2 processors, 8 steps
#   -keep DIR scratch directory, kept (default: a new mktemp -d directory,
#             removed at the end)
# Needs the library built (./Allwmake), the OpenFOAM environment (loaded here with
# bin/functions.sh: loadFoamEnvironment) and GNU time (/usr/bin/time, Debian
# package time, in bin/installPrerequisites). Memory: a processor holds its block
# of the grid (~630 bytes per owned node with averagingSteps 10)
# and the fibers it holds (4e6 nodes: ~2.7 GB serial, ~0.8 GB per processor on 4).
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
root="$(cd "$here/.." && pwd)"
nodesList="1e5 1e6 4e6"
ranksList="1 2 4"
steps=30
samples=0
localised=""
holders=""
blocks=""
balanceSteps=5
scratch=""
while [ $# -gt 0 ]; do
    case "$1" in
        -nodes) nodesList="$2"; shift ;;
        -ranks) ranksList="$2"; shift ;;
        -steps) steps="$2"; shift ;;
        -samplesPerSegment) samples="$2"; shift ;;
        -localised) localised="--localised" ;;
        -holders) holders="$2"; shift ;;
        -blocks) blocks="$2"; shift ;;
        -balanceSteps) balanceSteps="$2"; shift ;;
        -tiny) nodesList="1e4"; ranksList="1 2"; steps=8 ;;
        -keep) scratch="$2"; shift ;;
        -h | -help)
            sed -n '2,53p' "$0"
            exit 0
            ;;
        *) echo "usage: $0 [-nodes LIST] [-ranks LIST] [-steps N] [-samplesPerSegment N] [-localised] [-tiny] [-keep DIR]" >&2; exit 2 ;;
    esac
    shift
done
# shellcheck disable=SC1091
. "$root/bin/functions.sh"
loadFoamEnvironment
set -euo pipefail   # loading the environment may have reset them
timeCommand=/usr/bin/time
if ! "$timeCommand" -f "%M" true >/dev/null 2>&1; then
    echo "scaleOut: GNU time ($timeCommand) is needed for the peak memory: apt-get install time" >&2
    exit 1
fi
keep=true
if [ -z "$scratch" ]; then
    scratch="$(mktemp -d /tmp/scaleOut.XXXXXX)"
    keep=false
fi
mkdir -p "$scratch"
cores="$(nproc)"
echo "# scratch $scratch;${localised:+ localised spray and fibers;}${holders:+ fibers.holders $holders;}${blocks:+ grid.blocks $blocks;} $cores cores; load average $(cut -d' ' -f1-3 /proc/loadavg); $steps steps per run"

# One run: case in $1, $2 processors; peak RSS of each rank into rss.<rank>
runCase() {
    local dir="$1" ranks="$2"
    (
        cd "$dir"
        rm -rf 0 && cp -r 0.orig 0
        blockMesh > log.blockMesh 2>&1
        if [ "$ranks" -eq 1 ]; then
            "$timeCommand" -f "%M" -o rss.0 pimpleFoam > log.pimpleFoam 2>&1
        else
            decomposePar > log.decomposePar 2>&1
            local oversubscribe=""
            [ "$ranks" -gt "$cores" ] && oversubscribe="--oversubscribe"
            # Each rank under GNU time, its file named by its MPI rank
            # shellcheck disable=SC2016,SC2086
            mpirun $oversubscribe -np "$ranks" sh -c \
                'exec "$0" -f "%M" -o "rss.${OMPI_COMM_WORLD_RANK:-0}" pimpleFoam -parallel' \
                "$timeCommand" > log.pimpleFoam 2>&1
        fi
    )
}

for nodes in $nodesList; do
    for ranks in $ranksList; do
        dir="$scratch/nodes$nodes-ranks$ranks"
        rm -rf "$dir"
        cp -r "$root/tutorials/channelSpray" "$dir"
        rm -rf "$dir"/processor* "$dir"/postProcessing "$dir"/log.* "$dir/system/controlDict.short"
        total="$(python3 "$here/scaleOutCase.py" case "$dir" --nodes "$nodes" --steps "$steps" --ranks "$ranks" --samples-per-segment "$samples" ${localised:+"$localised"} ${holders:+--holders "$holders"} ${blocks:+--blocks "$blocks" --balance-steps "$balanceSteps"})"
        start=$(date +%s)
        if ! runCase "$dir" "$ranks"; then
            echo "scaleOut: the run with $ranks processors and $total nodes failed: see $dir/log.*" >&2
            exit 1
        fi
        python3 "$here/scaleOutCase.py" report "$dir" --ranks "$ranks" --nodes "$total" ${blocks:+--balance-steps "$balanceSteps"}
        echo "#   $(( $(date +%s) - start )) s, load average $(cut -d' ' -f1-3 /proc/loadavg)"
    done
done
[ "$keep" = true ] || rm -rf "$scratch"
