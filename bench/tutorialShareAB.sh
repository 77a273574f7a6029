#!/usr/bin/env bash
#------------------------------------------------------------------------------
# tutorialShareAB.sh - the function object's share of the channelSpray tutorial
# for several builds of the library, measured in the same session, runs
# interleaved (A B C A B C ...): the machine's speed drifts by 10-30 % between
# runs minutes apart, so only builds measured side by side can be compared.
#
# Usage: bench/tutorialShareAB.sh [-parallel] [-rounds N] [-refine R] [-keep DIR] REV...
#   REV        a git revision (built from a worktree into DIR/lib_<REV>), or
#              "work": the library of the working tree, as ./Allwmake built it
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

declare -A shares
for round in $(seq 1 "$rounds"); do
    for rev in "${revs[@]}"; do
        (
            cd "$dir"
            rm -rf postProcessing processor*/0.[0-9]* processor*/[1-9]* 0.[0-9]* [1-9]*
            libs="$scratch/lib_$rev:$LD_LIBRARY_PATH"
            if [ "$parallel" = true ]; then
                mpirun -np 2 -x LD_LIBRARY_PATH="$libs" "$app" -parallel > "log.$app" 2>&1
            else
                LD_LIBRARY_PATH="$libs" "$app" > "log.$app" 2>&1
            fi
        ) || { echo "tutorialShareAB: run of $rev failed, see $dir/log.$app" >&2; exit 1; }
        line="$(python3 "$here/tutorialShare.py" "$dir" --label "$rev round $round" | grep "function object total")"
        echo "$rev round $round: $line"
        share="$(echo "$line" | sed -n 's/.*= \([0-9.]*\) % of ExecutionTime.*/\1/p')"
        shares[$rev]="${shares[$rev]:-} $share"
    done
done
echo
echo "share of ExecutionTime per build ($([ "$parallel" = true ] && echo "2 ranks" || echo serial), $rounds rounds):"
for rev in "${revs[@]}"; do
    echo "  $rev:${shares[$rev]} %"
done
