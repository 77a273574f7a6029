#!/usr/bin/env bash
#------------------------------------------------------------------------------
# tutorialShareAB.sh - the function object's share of the channelSpray tutorial
# for several builds of the library, measured in the same session, runs
# interleaved (A B C A B C ...): the machine's speed drifts by 10-30 % between
# runs minutes apart, so only builds measured side by side can be compared.
#
# Usage: bench/tutorialShareAB.sh [-parallel] [-rounds N] [-refine R] [-keep DIR] REV...
#   REV        a git revision (built from a worktree into DIR/lib_<REV>), or
#              "work": the library of the working tree, as ./Allwmake built it, or
#              "none": the case without the dropletFiber function object (removed
#              from the copy's controlDict for that run); then the marginal cost
#              of each build is printed too, (T_build - T_none) / T_build of the
#              solver's ExecutionTime per round: what the coupling really adds,
#              including the work it shares with the cloud (the point field of U)
#   -parallel  2 ranks instead of serial
#   -rounds N  runs per build (default 3)
#   -refine R  the scratch copy's CFD mesh refined R times in x and y (25R x 75R
#              cells) and its time step divided by R (the same Courant number);
#              the function object's settings, the spray and the fibers are
#              unchanged: how the share falls as the flow solver's work grows
#              (default 1, the tutorial as it is)
#   -keep DIR  scratch directory (default: a new mktemp -d directory)
# Prints one line per run (bench/tutorialShare.py) and, per build, the shares
# of all rounds. Needs the OpenFOAM environment (bin/functions.sh loads it).
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
root="$(cd "$here/.." && pwd)"
parallel=false
rounds=3
refine=1
scratch=""
revs=()
while [ $# -gt 0 ]; do
    case "$1" in
        -parallel) parallel=true ;;
        -rounds) rounds="$2"; shift ;;
        -refine) refine="$2"; shift ;;
        -keep) scratch="$2"; shift ;;
        -*) echo "usage: $0 [-parallel] [-rounds N] [-refine R] [-keep DIR] REV..." >&2; exit 2 ;;
        *) revs+=("$1") ;;
    esac
    shift
done
[ "${#revs[@]}" -gt 0 ] || { echo "usage: $0 [-parallel] [-rounds N] [-refine R] [-keep DIR] REV..." >&2; exit 2; }
case "$refine" in
    '' | *[!0-9]* | 0) echo "tutorialShareAB: -refine takes a positive integer, got '$refine'" >&2; exit 2 ;;
esac
# shellcheck disable=SC1091
. "$root/bin/functions.sh"
loadFoamEnvironment
scratch="${scratch:-$(mktemp -d /tmp/tutorialShareAB.XXXXXX)}"
mkdir -p "$scratch"
echo "scratch: $scratch"

# One library per build
for rev in "${revs[@]}"; do
    lib="$scratch/lib_$rev"
    mkdir -p "$lib"
    [ "$rev" = none ] && continue
    if [ "$rev" = work ]; then
        cp "$FOAM_USER_LIBBIN/libdropletFiber.so" "$lib/"
        continue
    fi
    tree="$scratch/tree_$rev"
    [ -d "$tree" ] || git -C "$root" worktree add --detach "$tree" "$rev" > /dev/null
    echo "building $rev ..."
    (cd "$tree" && FOAM_USER_LIBBIN="$lib" ./Allwmake > "$scratch/Allwmake_$rev.log" 2>&1) || {
        echo "tutorialShareAB: building $rev failed, see $scratch/Allwmake_$rev.log" >&2
        exit 1
    }
done

# The case, meshed (and decomposed) once
dir="$scratch/channelSpray"
rm -rf "$dir"
cp -r "$root/tutorials/channelSpray" "$dir"
(
    cd "$dir"
    ./Allclean > /dev/null 2>&1 || true
    rm -f system/controlDict.short
    cp -r 0.orig 0
    if [ "$refine" != 1 ]; then
        # 25 x 75 cells -> 25R x 75R, deltaT 5e-4 -> 5e-4 / R
        sed -i "s/(25 75 1)/($((25 * refine)) $((75 * refine)) 1)/" system/blockMeshDict
        grep -q "($((25 * refine)) $((75 * refine)) 1)" system/blockMeshDict || {
            echo "tutorialShareAB: could not refine system/blockMeshDict" >&2; exit 1; }
        foamDictionary -entry deltaT -set "$(python3 -c "print(5e-4 / $refine)")" system/controlDict > /dev/null
    fi
    blockMesh > log.blockMesh 2>&1
    if [ "$parallel" = true ]; then
        decomposePar > log.decomposePar 2>&1
    fi
)
app="$(foamDictionary -entry application -value "$dir/system/controlDict")"

# The controlDict with and without the coupling (foamDictionary -remove edits in place)
cp "$dir/system/controlDict" "$dir/system/controlDict.full"
cp "$dir/system/controlDict" "$dir/system/controlDict.none"
foamDictionary -entry functions/dropletFiber -remove "$dir/system/controlDict.none" > /dev/null
[ -s "$dir/system/controlDict.none" ] && ! grep -q dropletFiberCollision "$dir/system/controlDict.none" || {
    echo "tutorialShareAB: could not remove the dropletFiber function object" >&2; exit 1; }

declare -A shares executions
for round in $(seq 1 "$rounds"); do
    for rev in "${revs[@]}"; do
        (
            cd "$dir"
            rm -rf postProcessing processor*/0.[0-9]* processor*/[1-9]* 0.[0-9]* [1-9]*
            if [ "$rev" = none ]; then
                cp system/controlDict.none system/controlDict
            else
                cp system/controlDict.full system/controlDict
            fi
            libs="$scratch/lib_$rev:$LD_LIBRARY_PATH"
            if [ "$parallel" = true ]; then
                mpirun -np 2 -x LD_LIBRARY_PATH="$libs" "$app" -parallel > "log.$app" 2>&1
            else
                LD_LIBRARY_PATH="$libs" "$app" > "log.$app" 2>&1
            fi
        ) || { echo "tutorialShareAB: run of $rev failed, see $dir/log.$app" >&2; exit 1; }
        execution="$(sed -n 's/^ExecutionTime = \([0-9.eE+-]*\) s.*/\1/p' "$dir/log.$app" | tail -1)"
        executions[$rev]="${executions[$rev]:-} $execution"
        if [ "$rev" = none ]; then
            echo "none round $round: ExecutionTime $execution s (no coupling)"
            continue
        fi
        "$root/bin/checkFunctionObjectRan" "$dir/log.$app" || {
            echo "tutorialShareAB: the run of $rev went on without the function object" >&2
            exit 1
        }
        line="$(python3 "$here/tutorialShare.py" "$dir" --label "$rev round $round" | grep "function object total")"
        echo "$rev round $round: $line"
        share="$(echo "$line" | sed -n 's/.*= \([0-9.]*\) % of ExecutionTime.*/\1/p')"
        shares[$rev]="${shares[$rev]:-} $share"
    done
done
cp "$dir/system/controlDict.full" "$dir/system/controlDict"
echo
echo "share of ExecutionTime per build ($([ "$parallel" = true ] && echo "2 ranks" || echo serial), $rounds rounds):"
for rev in "${revs[@]}"; do
    [ "$rev" = none ] && continue
    echo "  $rev:${shares[$rev]} %"
done
if [ -n "${executions[none]:-}" ]; then
    echo "marginal cost, (ExecutionTime - ExecutionTime without the coupling) / ExecutionTime, per round:"
    for rev in "${revs[@]}"; do
        [ "$rev" = none ] && continue
        echo "  $rev: $(python3 -c "
import sys
full = [float(x) for x in sys.argv[1].split()]
none = [float(x) for x in sys.argv[2].split()]
print(' '.join('%.1f' % (100 * (f - n) / f) for f, n in zip(full, none)), '%')
" "${executions[$rev]}" "${executions[none]}")"
    done
fi
