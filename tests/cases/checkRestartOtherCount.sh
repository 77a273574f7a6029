#!/usr/bin/env bash
# Restart with another number of processors: the averaging window is kept per
# processor's block of the grid, so a state written on 2 processors and restarted
# serially (after reconstructPar) stops with a FatalIOError naming the state, the
# processor counts and what to do; reconstructDropletFiberState, which merges
# the processors' states, stops naming the file and the entry when one is
# missing, of a run on another count, or disagrees on the totals; on 2
# processors again the restart continues.
# Usage: checkRestartOtherCount.sh CASE_DIR WORK_DIR T
set -euo pipefail
caseDir="$1"; work="$2"; half="$3"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
loadFoamEnvironment

rm -rf "$work"; mkdir -p "$work"
cp -r "$caseDir" "$work/case"
cd "$work/case"
end="$(foamDictionary -entry endTime -value system/controlDict)"
sed -i "s/^endTime .*/endTime         $half;/" system/controlDict
./Allrun -parallel > /dev/null
app="$(foamDictionary -entry application -value system/controlDict)"
sed -i "s/^endTime .*/endTime         $end;/" system/controlDict
reconstructPar -latestTime > log.reconstructPar 2>&1
[ -f "$half/uniform/dropletFiber/dropletFiber" ] || die "reconstructPar did not carry the restart state"

status=0
"$app" > log.serialRestart 2>&1 || status=$?
[ "$status" -ne 0 ] || { tail -20 log.serialRestart; die "the serial restart from a 2-processor state ran"; }
grep -q "FOAM FATAL IO ERROR" log.serialRestart || { tail -20 log.serialRestart; die "no FatalIOError"; }
# (the fibers' state is checked first: it names the processor count and the remedy)
for text in "of a run on 2 processors" "this run is \"serial\"" "Restart on 2 processors" \
    "reconstructPar and reconstructDropletFiberState, then decomposePar" "restart fresh"; do
    grep -q "$text" log.serialRestart || { tail -30 log.serialRestart; die "the error does not say '$text'"; }
done
echo "ok: a serial restart from a 2-processor state stops, saying why and what to do"

# mergeStops WHAT PATTERN: reconstructDropletFiberState (on a copy) stops with a
# FatalIOError saying PATTERN
mergeStops() {
    local status=0
    reconstructDropletFiberState -time "$half" > log.merge 2>&1 || status=$?
    [ "$status" -ne 0 ] && grep -q "FOAM FATAL IO ERROR" log.merge && grep -q -E -- "$2" log.merge \
        || { tail -20 log.merge; die "the merge with $1 did not stop saying '$2'"; }
    echo "ok: the merge with $1 stops: $(grep -A1 'FOAM FATAL IO ERROR' log.merge | tail -1)"
}
state="$half/uniform/dropletFiber/dropletFiber"
rm -rf ../merge; cp -r . ../merge
(
    cd ../merge
    mv "processor1/$state" "processor1/$state.away"
    mergeStops "processor 1's state missing" "processor1/$state\" is missing"
    mv "processor1/$state.away" "processor1/$state"
    cp -r processor1 processor2
    mergeStops "a third processor directory" "entries .processors. 2 .*allowed are processors 3"
    rm -rf processor2
    sed -i 's/^\( *captured  *\)[^;]*;/\10.5;/' "processor1/$state"
    mergeStops "processor 1's totals edited" "entry 'totals.captured' is 0.5"
)
rm -rf ../merge

mpirun -np 2 "$app" -parallel > log.parallelRestart 2>&1 || { tail -30 log.parallelRestart; die "restart on 2 processors failed"; }
grep -q "restarted from" log.parallelRestart || die "the 2-processor restart did not read its state"
echo "ok: the restart on 2 processors continues"
