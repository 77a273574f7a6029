#!/usr/bin/env bash
#------------------------------------------------------------------------------
# parcelCostRatio.sh - target (b) of docs/performance.md: the function object's
# cost per parcel-step against OpenFOAM's own parcel tracking, on the
# channelSpray tutorial (serial, full run), from one profile (perf record with
# call graphs, inclusive samples: a function's own and everything it calls,
# OpenFOAM's and the C library's code included):
#   per-parcel work: couplingGrid::deposit (the deposit, the step into the
#     window) + gridBlocks::removeCaptured (the parcels' depths and losses, P14)
#     + sprayParcels::writeBack and fiberCapture::closeRemoval (written back to
#     the clouds, the step's sums), the parts that scale with the parcels;
#   the whole function object: dropletFiberCollision::execute + ::write (the
#     fibers, collision, air sampling and output included);
#   OpenFOAM's tracking: KinematicCloud::evolveCloud (injection, tracking,
#     forces, the cloud's interpolation), run once per step over the same
#     parcels.
# Prints the shares of the run's samples and the ratios to the tracking.
# PARCELCOST_CASE=DIR profiles another case instead (its application from its
# controlDict, serial), e.g. tests/cases/sprayBox: sprayFoam's evaporating
# water + C16H34 spray. Its cloud's code is instantiated in the (stripped)
# solver, so the profile cannot name evolveCloud: the tracking is then taken from
# OpenFOAM's own profiling (switched on in the copy: 'cloud::solve', i.e.
# evolveCloud and the cloud's report, against the function object's 'execute'),
# ratio = (per-parcel / execute samples) x (execute / cloud::solve time).
#
# Usage: bench/parcelCostRatio.sh [libDir]
#   libDir  folder with the libdropletFiber.so to measure (default: $FOAM_USER_LIBBIN)
# Environment: PARCELCOST_DIR scratch folder (default: a new mktemp -d folder),
#              PARCELCOST_SHORT=1 runs 'Allrun -short' (0.04 s) instead,
#              PARCELCOST_CASE=DIR another case (default: the tutorial),
#              PARCELCOST_ENDTIME=T its endTime (default: the case's).
# Needs perf (linux-perf); figures, not a test (the machine is shared: repeat
# and report the spread).
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
root="$(cd "$here/.." && pwd)"
# shellcheck disable=SC1091
. "$root/bin/functions.sh"
loadFoamEnvironment
command -v perf > /dev/null || die "parcelCostRatio: perf is not installed"
lib="${1:-$FOAM_USER_LIBBIN}"
[ -f "$lib/libdropletFiber.so" ] || die "no libdropletFiber.so in $lib"
lib="$(cd "$lib" && pwd)"
dir="${PARCELCOST_DIR:-$(mktemp -d /tmp/parcelCost.XXXXXX)}"
rm -rf "$dir"
source="${PARCELCOST_CASE:-$root/tutorials/channelSpray}"
[ -d "$source/system" ] || die "parcelCostRatio: no case in $source"
cp -r "$source" "$dir"
cd "$dir"
./Allclean > /dev/null 2>&1 || true
if [ -z "${PARCELCOST_CASE:-}" ]; then
    if [ "${PARCELCOST_SHORT:-0}" = 1 ]; then
        printf 'endTime         0.04;\n' > system/controlDict.short
    else
        rm -f system/controlDict.short
    fi
fi
if [ -n "${PARCELCOST_CASE:-}" ]; then
    printf 'profiling { active true; cpuInfo false; memInfo false; sysInfo false; }\n' \
        >> system/controlDict
fi
if [ -n "${PARCELCOST_ENDTIME:-}" ]; then
    foamDictionary system/controlDict -entry endTime -set "$PARCELCOST_ENDTIME" > /dev/null
fi
rm -rf 0 && cp -r 0.orig 0
application="$(foamDictionary system/controlDict -entry application -value)"
blockMesh > log.blockMesh 2>&1 || die "parcelCostRatio: blockMesh failed ($dir)"
LD_LIBRARY_PATH="$lib:$LD_LIBRARY_PATH" perf record -q -e cpu-clock -F 400 --call-graph dwarf,16384 \
    -o perf.data "$application" > "log.$application" 2>&1 \
    || die "parcelCostRatio: $application failed ($dir)"
"$root/bin/checkFunctionObjectRan" "log.$application" \
    || die "parcelCostRatio: the function object did not run"
perf report -i perf.data --children --sort symbol --stdio -g none 2> /dev/null > report.txt
python3 - report.txt <<'PY'
import glob, re, sys
children = {}
for line in open(sys.argv[1], errors="replace"):
    m = re.match(r"\s+([0-9.]+)%\s+([0-9.]+)%\s+\[\.\]\s+(.*\S)", line)
    if m:
        name = re.split(r"\s{2,}", m.group(3))[0]  # the symbol column, padded
        children[name] = max(children.get(name, 0.0), float(m.group(1)))
def inclusive(pattern):
    hits = [v for k, v in children.items() if re.search(pattern, k)]
    return max(hits) if hits else 0.0
prefix = r"^Foam::functionObjects::dropletFiberCollision::"
whole = inclusive(prefix + r"execute$") + inclusive(prefix + r"write$")
stages = r"^Foam::dropletFiber::"
parcels = (inclusive(stages + r"couplingGrid::deposit$")
           + inclusive(stages + r"sprayParcels::writeBack$")
           + inclusive(stages + r"fiberCapture::closeRemoval$")
           + inclusive(stages + r"gridBlocks::removeCaptured"))
cloud = inclusive(r"KinematicCloud<.*>::evolveCloud<")
if not cloud:
    # OpenFOAM's profiling of the last time written: total times [s]
    files = sorted(glob.glob("*/uniform/profiling"), key=lambda f: float(f.split("/")[0]))
    if not files:
        sys.exit("parcelCostRatio: no evolveCloud samples in the profile, no profiling")
    text = open(files[-1]).read()
    def total(pattern):
        m = re.search(r'description\s+"' + pattern + r'";\s*calls\s+\d+;\s*totalTime\s+([0-9.eE+-]+)', text)
        return float(m.group(1)) if m else 0.0
    solve = total(r"cloud::solve")
    execute = total(r"functionObject::[^\"]*::execute")
    inner = inclusive(prefix + r"execute$")
    if not (solve and execute and inner):
        sys.exit("parcelCostRatio: no cloud::solve or execute in " + files[-1])
    print(f"  OpenFOAM's profiling: cloud::solve {solve:.3f} s, the function object's execute {execute:.3f} s")
    print(f"  per-parcel work (deposit + removeCaptured + writeBack): {parcels:.1f} % of the samples, "
          f"{parcels / inner:.2f} of execute: ratio {parcels / inner * execute / solve:.2f}")
    print(f"  execute against cloud::solve: ratio {execute / solve:.2f}")
    sys.exit(0)
print(f"  OpenFOAM's tracking (evolveCloud): {cloud:.1f} % of the samples")
print(f"  per-parcel work (deposit + removeCaptured + writeBack): {parcels:.1f} %: ratio {parcels / cloud:.2f}")
print(f"  whole function object (execute + write): {whole:.1f} %: ratio {whole / cloud:.2f}")
PY
