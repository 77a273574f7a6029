#!/usr/bin/env bash
#------------------------------------------------------------------------------
# spray3D/run.sh - the channelSpray tutorial made 3D with parcels of thousands of
# droplets, run once; prints the function object's share of the solver's wall
# time and the widest kernels the function object reported: the cost of spray
# parcels of many droplets (docs/performance.md, wide kernels).
#
# Usage: bench/spray3D/run.sh [-baseline] [-refine R] [libDir]
#   libDir     folder with the libdropletFiber.so to measure (default: the one
#              ./Allwmake built, $FOAM_USER_LIBBIN)
#   -refine R  the CFD mesh R times finer in every direction (25R x 75R x 5R
#              cells) and the time step R times shorter; the grid, the spray
#              (parcels per second), the fibers and the function object
#              unchanged: the case whose CFD dominates (target (a) of
#              docs/performance.md for this case)
#   -spacing S the grid's node spacing in m (default: the tutorial's 1e-3)
#   -baseline  also run the same case without the function object (the cloud and
#              the air unchanged) and print the whole function object's cost as
#              the difference of the two runs' ExecutionTime (CPU time): every
#              part, the writes at write times included, which the table's
#              per-step columns do not hold
# Environment: SPRAY3D_DIR scratch folder (default: a new mktemp -d folder),
#              SPRAY3D_END end time in s (default 0.2: 400 steps),
#              SPRAY3D_MALLOC=default: glibc's own malloc thresholds (see below)
#
# The case, generated from tutorials/channelSpray (same channel, air, nozzles,
# fibers and function-object settings):
#   - 3D: 25 x 75 x 5 cells of 2 mm (the tutorial's 1 cell in z), the front and
#     back walls no-slip walls the parcels escape through; the grid 1 mm in
#     every direction (51 x 151 x 11 nodes);
#   - parcelsPerSecond 1000 instead of 10000 at the same mass flow
#     (parcelBasisType mass): 5e-8 kg per parcel, about 3,400 droplets of
#     30 um, 11,000 of 20 um (the tutorial: 340 of 30 um);
#   - no rMaxCap (the tutorial has 6 mm), every other grid entry at its
#     default: the cost of default settings.
# The share is the function object's wall time (its table's deposition and
# fiber columns) over the solver's ExecutionTime (bench/tutorialShare.py).
# A profile: SPRAY3D_DIR=DIR bench/spray3D/run.sh, then in DIR 'foamListTimes -rm'
# and, with the malloc thresholds fixed (MALLOC_MMAP_THRESHOLD_=67108864
# MALLOC_TRIM_THRESHOLD_=268435456), 'perf record -e cpu-clock -F 500 --call-graph
# dwarf,16384 pimpleFoam; perf report --children'.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck disable=SC1091
. "$root/bin/functions.sh"
loadFoamEnvironment
baseline=false
refine=1
spacing=
while [ $# -gt 0 ]; do
    case "$1" in
        -baseline) baseline=true ;;
        -refine) [ $# -ge 2 ] || die "spray3D: -refine needs a value"; refine="$2"; shift ;;
        -spacing) [ $# -ge 2 ] || die "spray3D: -spacing needs a value"; spacing="$2"; shift ;;
        *) break ;;
    esac
    shift
done
case "$refine" in
    '' | *[!0-9]* | 0) die "spray3D: -refine takes a positive integer, got '$refine'" ;;
esac
lib="${1:-$FOAM_USER_LIBBIN}"
[ -f "$lib/libdropletFiber.so" ] || die "no libdropletFiber.so in $lib"
lib="$(cd "$lib" && pwd)"
endTime="${SPRAY3D_END:-0.2}"
# glibc serves blocks above 128 kB (the solver's field temporaries of this mesh) from
# fresh mmap'd pages, and raises that threshold only after such a block is freed, so
# whether the CFD pays a page fault per page of every temporary depends on what else
# the process allocated: on the VMs measured here page faults are slow, and the same
# CFD took 8.3 or 18.1 s of CPU time with the 2 mm grid (docs/performance.md). Fixed
# thresholds make the solver's cost independent of the function object's allocations;
# set SPRAY3D_MALLOC=default to run with glibc's own.
if [ "${SPRAY3D_MALLOC:-fixed}" != default ]; then
    export MALLOC_MMAP_THRESHOLD_=67108864 MALLOC_TRIM_THRESHOLD_=268435456
fi
dir="${SPRAY3D_DIR:-$(mktemp -d /tmp/spray3D.XXXXXX)}"
rm -rf "$dir"
cp -r "$root/tutorials/channelSpray" "$dir"
cd "$dir"
./Allclean > /dev/null 2>&1 || true
rm -f system/controlDict.short

# edit FILE OLD NEW: replace a line's text, and fail when it is not there
edit() {
    grep -qF -- "$2" "$1" || die "spray3D: '$2' not found in $1 (tutorial changed?)"
    python3 - "$@" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
open(path, "w").write(text.replace(old, new))
PY
}
edit system/blockMeshDict "(25 75 1)" "($((25 * refine)) $((75 * refine)) $((5 * refine)))"
edit system/blockMeshDict "type empty;" "type wall;"
python3 - <<'PY'
# frontAndBack: no-slip walls for the air (U), zero gradient for p
import re
for name, bc in (("0.orig/U", "noSlip;"), ("0.orig/p", "zeroGradient;")):
    text = open(name).read()
    text, n = re.subn(r"(frontAndBack\s*\{\s*type\s+)empty;", r"\g<1>" + bc, text)
    assert n == 1, name
    open(name, "w").write(text)
PY
edit constant/kinematicCloudProperties "parcelsPerSecond 10000;" "parcelsPerSecond 1000;"
edit constant/kinematicCloudProperties "            outlet
            {
                type        escape;
            }" "            outlet
            {
                type        escape;
            }
            frontAndBack
            {
                type        escape;
            }"
foamDictionary system/controlDict -entry functions/dropletFiber/grid/rMaxCap -remove > /dev/null
! grep -q rMaxCap system/controlDict || die "spray3D: could not remove rMaxCap"
foamDictionary system/controlDict -entry endTime -set "$endTime" > /dev/null
if [ -n "$spacing" ]; then
    foamDictionary system/controlDict -entry functions/dropletFiber/grid/spacing \
        -set "$spacing" > /dev/null || die "spray3D: could not set the grid spacing"
fi
if [ "$refine" != 1 ]; then
    deltaT="$(foamDictionary -entry deltaT -value system/controlDict)"
    foamDictionary system/controlDict -entry deltaT \
        -set "$(python3 -c "print($deltaT / $refine)")" > /dev/null
fi
foamDictionary system/controlDict -entry writeInterval -set "$(python3 -c "print($endTime / 4)")" > /dev/null

cp -r 0.orig 0
blockMesh > log.blockMesh 2>&1 || die "spray3D: blockMesh failed, see $dir/log.blockMesh"
info "spray3D: $dir, endTime $endTime s, library $lib/libdropletFiber.so"
LD_LIBRARY_PATH="$lib:$LD_LIBRARY_PATH" pimpleFoam > log.pimpleFoam 2>&1 \
    || die "spray3D: pimpleFoam failed, see $dir/log.pimpleFoam"
"$root/bin/checkFunctionObjectRan" log.pimpleFoam \
    || die "spray3D: the run went on without the function object"

python3 "$root/bench/tutorialShare.py" . --label "spray3D ($lib)"
python3 - <<'PY'
# droplets per parcel over the run (the table's parcels and droplets columns)
rows, names = [], None
for line in open("postProcessing/dropletFiber/0/dropletFiber.dat"):
    if line.startswith("#"):
        names = line[1:].split()
    elif line.strip():
        rows.append(dict(zip(names, map(float, line.split()))))
rows = [r for r in rows if r["parcels"] > 0]
mean = sum(r["droplets"] for r in rows) / max(sum(r["parcels"] for r in rows), 1)
print(f"  droplets per parcel (mean over the run): {mean:.0f}; parcels in the last step: {rows[-1]['parcels']:.0f}")
PY
echo "  the function object's deposit report (log.pimpleFoam):"
python3 - <<'PY'
# each report: its first line and the indented lines that follow it
import re
start = re.compile(r"(deposit of the parcels takes|: deposit [0-9]+ % of the wall time)")
lines = open("log.pimpleFoam", errors="replace").read().splitlines()
shown = 0
for i, line in enumerate(lines):
    if start.search(line):
        print("    " + line.strip())
        for follow in lines[i + 1:]:
            if not re.match(r"\s{4}", follow) or follow.strip().startswith(("number of", "mass in")):
                break
            print("    " + follow)
        shown += 1
if not shown:
    print("    (none: is this build older than the deposit report?)")
PY

if [ "$baseline" = true ]; then
    # The same case without the coupling: the function object's whole cost is the
    # difference of the CPU times (writes included); reported, not judged.
    with="$(sed -n 's/^ExecutionTime = \([0-9.eE+-]*\) s.*/\1/p' log.pimpleFoam | tail -1)"
    cp system/controlDict system/controlDict.full
    foamDictionary -entry functions/dropletFiber -remove system/controlDict > /dev/null
    ! grep -q dropletFiberCollision system/controlDict \
        || die "spray3D: could not remove the dropletFiber function object"
    rm -rf 0.[0-9]* [1-9]* postProcessing
    pimpleFoam > log.pimpleFoam.baseline 2>&1 \
        || die "spray3D: the run without the function object failed, see $dir/log.pimpleFoam.baseline"
    cp system/controlDict.full system/controlDict
    without="$(sed -n 's/^ExecutionTime = \([0-9.eE+-]*\) s.*/\1/p' log.pimpleFoam.baseline | tail -1)"
    python3 - "$with" "$without" <<'PY'
import sys
w, wo = map(float, sys.argv[1:3])
print(f"  without the function object: ExecutionTime {wo:.2f} s; with it {w:.2f} s:"
      f" the whole function object {w - wo:.2f} s = {100 * (w - wo) / w:.1f} % of ExecutionTime")
PY
fi
