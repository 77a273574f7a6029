# shellcheck shell=bash
# Helpers of the regression checks that run a tutorial in a scratch copy
# (sourced, not run). Sourcing loads OpenFOAM and sets root (the project), PY
# (python3) and bin/functions.sh's info and die.
#
# runTutorialCopy TUTORIAL WORK_DIR [ALLRUN_OPTION...]: copy tutorials/TUTORIAL to
#   WORK_DIR (replacing it), clean it and run its Allrun with the options
#   (log.Allrun, printed after); stops with the logs' tails when Allrun fails, and
#   when the run went on without the function object (OpenFOAM runs on, exit 0,
#   without a function object whose library it cannot load)
# compareWithReference TABLE REFERENCE [--update]: --update stores TABLE as
#   REFERENCE and exits 0; otherwise every column of TABLE must equal REFERENCE's
#   to 1e-6 of its scale (the runs are deterministic, so more is a change of
#   behaviour; another compiler's round-off stays far below), maxSegmentLengthError
#   apart: round-off by nature, it must stay < 1e-10

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
# shellcheck disable=SC1091
. "$root/bin/functions.sh"
loadFoamEnvironment
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

runTutorialCopy() {
    local tutorial="$1" work="$2"
    shift 2
    rm -rf "$work"; mkdir -p "$(dirname "$work")"
    cp -r "$root/tutorials/$tutorial" "$work"
    (cd "$work" && ./Allclean > /dev/null)
    if ! (cd "$work" && DROPLETFIBER_DIR="$root" ./Allrun "$@" > log.Allrun 2>&1); then
        tail -n 30 "$work"/log.* ; die "Allrun $* failed"
    fi
    cat "$work/log.Allrun"
    "$root/bin/checkFunctionObjectRan" "$work" \
        || die "the run of $work went on without the function object"
}

compareWithReference() {
    local table="$1" reference="$2" update="${3:-}"
    if [ "$update" = --update ]; then
        cp "$table" "$reference"
        info "stored $reference"
        exit 0
    fi
    "$PY" "$root/tests/cases/compareTables.py" --skip maxSegmentLengthError \
        "$reference" "$table" 1e-6
    "$PY" "$root/tests/cases/checkSegmentLengthError.py" "$table"
}
