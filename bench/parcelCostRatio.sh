#!/usr/bin/env bash
#------------------------------------------------------------------------------
# parcelCostRatio.sh - target (b) of docs/performance.md: the function object's
# cost per parcel-step against OpenFOAM's own parcel tracking, on the
# channelSpray tutorial (serial, full run), from one profile (perf record with
# call graphs, inclusive samples: a function's own and everything it calls,
# OpenFOAM's and the C library's code included):
#   per-parcel work: dropletFiberCollision::depositParcels (gathering the
#     parcels, the deposit, the step into the window) + gridBlocks::removeCaptured
#     (the parcels' depths and losses, P14) + ::depleteParcels (written back to
#     the clouds), the parts that scale with the parcels;
#   the whole function object: dropletFiberCollision::execute + ::write (the
#     fibers, collision, air sampling and output included);
#   OpenFOAM's tracking: KinematicCloud::evolveCloud (injection, tracking,
#     forces, the cloud's interpolation), run once per step over the same
#     parcels.
# Prints the shares of the run's samples and the ratios to the tracking.
#
# Usage: bench/parcelCostRatio.sh [libDir]
#   libDir  folder with the libdropletFiber.so to measure (default: $FOAM_USER_LIBBIN)
# Environment: PARCELCOST_DIR scratch folder (default: a new mktemp -d folder),
#              PARCELCOST_SHORT=1 runs 'Allrun -short' (0.04 s) instead.
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
cp -r "$root/tutorials/channelSpray" "$dir"
cd "$dir"
./Allclean > /dev/null 2>&1 || true
if [ "${PARCELCOST_SHORT:-0}" = 1 ]; then
    printf 'endTime         0.04;\n' > system/controlDict.short
else
    rm -f system/controlDict.short
fi
cp -r 0.orig 0
blockMesh > log.blockMesh 2>&1 || die "parcelCostRatio: blockMesh failed ($dir)"
LD_LIBRARY_PATH="$lib:$LD_LIBRARY_PATH" perf record -q -e cpu-clock -F 400 --call-graph dwarf,16384 \
    -o perf.data pimpleFoam > log.pimpleFoam 2>&1 || die "parcelCostRatio: pimpleFoam failed ($dir)"
"$root/bin/checkFunctionObjectRan" log.pimpleFoam || die "parcelCostRatio: the function object did not run"
perf report -i perf.data --children --sort symbol --stdio -g none 2> /dev/null > report.txt
python3 - report.txt <<'PY'
import re, sys
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
parcels = (inclusive(prefix + r"depositParcels$") + inclusive(prefix + r"depleteParcels$")
           + inclusive(r"^Foam::dropletFiber::gridBlocks::removeCaptured"))
cloud = inclusive(r"KinematicCloud<.*>::evolveCloud<")
if not cloud:
    sys.exit("parcelCostRatio: no evolveCloud samples in the profile")
print(f"  OpenFOAM's tracking (evolveCloud): {cloud:.1f} % of the samples")
print(f"  per-parcel work (depositParcels + removeCaptured + depleteParcels): {parcels:.1f} %: ratio {parcels / cloud:.2f}")
print(f"  whole function object (execute + write): {whole:.1f} %: ratio {whole / cloud:.2f}")
PY
