#!/usr/bin/env bash
#------------------------------------------------------------------------------
# tutorialShare.sh - run the channelSpray tutorial in a scratch copy, serial and
# on 2 ranks, and report the dropletFiber function object's share of the
# solver's time (bench/tutorialShare.py). The tutorial in the tree is not
# touched; the copies stay in the scratch directory for inspection.
#
# Usage: bench/tutorialShare.sh [-short] [-keep DIR]
#   -short     the tutorial's regression variant (endTime 0.04 s instead of 0.4 s)
#   -keep DIR  scratch directory (default: a new mktemp -d directory)
# Needs the library built (./Allwmake) and the OpenFOAM environment
# (loaded here with bin/functions.sh: loadFoamEnvironment).
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
root="$(cd "$here/.." && pwd)"
short=""
scratch=""
while [ $# -gt 0 ]; do
    case "$1" in
        -short) short="-short" ;;
        -keep) scratch="$2"; shift ;;
        *) echo "usage: $0 [-short] [-keep DIR]" >&2; exit 2 ;;
    esac
    shift
done
# shellcheck disable=SC1091
. "$root/bin/functions.sh"
loadFoamEnvironment
# the tutorial's Allrun takes this project's tools, whatever ./Allwmake installed last
export DROPLETFIBER_DIR="$root"
tutorial="$root/tutorials/channelSpray"
if ! grep -q "dropletFiberCollision" "$tutorial/system/controlDict"; then
    echo "tutorialShare: $tutorial/system/controlDict has no dropletFiberCollision function object" >&2
    exit 1
fi
scratch="${scratch:-$(mktemp -d /tmp/tutorialShare.XXXXXX)}"
mkdir -p "$scratch"
echo "scratch: $scratch"

for mode in serial parallel; do
    dir="$scratch/$mode/channelSpray"
    rm -rf "${scratch:?}/$mode"
    mkdir -p "$scratch/$mode"
    cp -r "$tutorial" "$dir"
    if ! (cd "$dir" && ./Allclean >/dev/null 2>&1); then
        echo "tutorialShare: Allclean failed in $dir (continuing)" >&2
    fi
    args="$short"
    [ "$mode" = parallel ] && args="-parallel $short"
    echo "running channelSpray $args ..."
    start=$(date +%s)
    # shellcheck disable=SC2086
    (cd "$dir" && ./Allrun $args) > "$scratch/$mode/Allrun.log" 2>&1 || {
        echo "tutorialShare: Allrun $args failed, see $scratch/$mode/Allrun.log and $dir/log.*" >&2
        exit 1
    }
    # a run without the function object would report a share of nothing
    "$root/bin/checkFunctionObjectRan" "$dir" || {
        echo "tutorialShare: the $mode run went on without the function object" >&2
        exit 1
    }
    echo "  done in $(( $(date +%s) - start )) s"
done

echo
echo "| run | steps | mean parcels | mean fibers | ExecutionTime s | ClockTime s | deposition s | fibers s | share of ExecutionTime | share of ClockTime |"
echo "|---|---|---|---|---|---|---|---|---|---|"
python3 "$here/tutorialShare.py" "$scratch/serial/channelSpray" --label "serial $short" --markdown
python3 "$here/tutorialShare.py" "$scratch/parallel/channelSpray" --label "2 ranks $short" --markdown
echo
python3 "$here/tutorialShare.py" "$scratch/serial/channelSpray" --label "serial $short"
python3 "$here/tutorialShare.py" "$scratch/parallel/channelSpray" --label "2 ranks $short"
