# shellcheck shell=bash
# Helpers of the regression checks that run a tutorial in a scratch copy
# (sourced, not run). Sourcing loads OpenFOAM and sets root (the project), PY
# (python3) and bin/functions.sh's info and die.
#
# runTutorialCopy TUTORIAL WORK_DIR [ALLRUN_OPTION...]: runs tutorials/TUTORIAL as a
#   user who copied it would: copied (and cleaned) into a new folder outside the
#   project, its Allrun run there with the options, with neither DROPLETFIBER_DIR nor
#   USER set, so that it finds the project's tools on PATH, where ./Allwmake installed
#   them ($FOAM_USER_APPBIN); the finished case is then moved to WORK_DIR (replacing
#   it; its log.Allrun printed). Stops with the logs' tails when Allrun fails, when the
#   tools it used are not the installed ones, and when the run went on without the
#   function object (OpenFOAM runs on, exit 0, without a function object whose library
#   it cannot load)
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
    local tutorial="$1" work="$2" scratch copy tool
    shift 2
    for tool in checkFunctionObjectRan dropletFiberReport; do
        [ "$(command -v "$tool")" = "$FOAM_USER_APPBIN/$tool" ] \
            || die "$tool on PATH is '$(command -v "$tool")', not the one ./Allwmake installs in $FOAM_USER_APPBIN: run ./Allwmake"
    done
    # the run functions Allrun sources: the first on PATH ('.' takes that one)
    tool="$(IFS=:; for folder in $PATH; do [ -f "$folder/dropletFiberRunFunctions" ] && echo "$folder/dropletFiberRunFunctions" && break; done)"
    [ "$tool" = "$FOAM_USER_APPBIN/dropletFiberRunFunctions" ] \
        || die "dropletFiberRunFunctions on PATH is '$tool', not the one ./Allwmake installs in $FOAM_USER_APPBIN: run ./Allwmake"
    scratch="$(mktemp -d "${TMPDIR:-/tmp}/dropletFiber-$tutorial.XXXXXX")"
    copy="$scratch/$tutorial"
    cp -r "$root/tutorials/$tutorial" "$copy"
    (cd "$copy" && ./Allclean > /dev/null)
    if ! (cd "$copy" && env -u DROPLETFIBER_DIR -u USER ./Allrun "$@" > log.Allrun 2>&1); then
        tail -n 30 "$copy"/log.*; rm -rf "$scratch"; die "Allrun $* failed in a copy of tutorials/$tutorial"
    fi
    rm -rf "$work"; mkdir -p "$(dirname "$work")"
    mv "$copy" "$work"
    rm -rf "$scratch"
    cat "$work/log.Allrun"
    grep -q -x "dropletFiber tools: $FOAM_USER_APPBIN/checkFunctionObjectRan, $FOAM_USER_APPBIN/dropletFiberReport" \
        "$work/log.Allrun" || die "the copy's Allrun did not use the tools installed in $FOAM_USER_APPBIN"
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
