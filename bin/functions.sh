# shellcheck shell=bash
#------------------------------------------------------------------------------
# functions.sh - shell helpers shared by the project's scripts (sourced, not run).
#
#   info MSG...            print a prefixed message
#   die MSG...             print a prefixed error and exit 1
#   run CMD...             print the command, then run it
#   haveFoamEnvironment    true when an OpenFOAM environment is loaded
#   foamKitDir             where installPrerequisites keeps the OpenFOAM kit
#   loadFoamEnvironment    use the loaded OpenFOAM, else source the kit's bashrc;
#                          exports DROPLETFIBER_DIR (this project), where the case
#                          scripts find bin/checkFunctionObjectRan and bin/dropletFiberReport
#------------------------------------------------------------------------------

info() { printf '[dropletFiber] %s\n' "$*"; }
die()  { printf '[dropletFiber] Error: %s\n' "$*" >&2; exit 1; }
run()  { printf '[dropletFiber] + %s\n' "$*"; "$@"; }

haveFoamEnvironment() {
    [ -n "${WM_PROJECT_DIR:-}" ] && command -v wmake >/dev/null 2>&1
}

foamKitDir() {
    echo "${DROPLETFIBER_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/dropletFiber}/openfoam-v1912-kit"
}

loadFoamEnvironment() {
    # OpenFOAM derives user paths from $USER, which batch shells may not set
    export USER="${USER:-$(id -un)}"
    # The tutorial's Allrun, run from a copy, checks its run with this project's
    # bin/checkFunctionObjectRan
    DROPLETFIBER_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
    export DROPLETFIBER_DIR
    if haveFoamEnvironment; then
        return 0
    fi
    local kit
    kit="$(foamKitDir)"
    [ -f "$kit/etc/bashrc" ] || die "no OpenFOAM environment loaded and no kit at $kit.
    Run bin/installPrerequisites (as root on a fresh Debian machine), or source your
    OpenFOAM's etc/bashrc first."
    # OpenFOAM's bashrc is not written for 'set -eu'
    local oldOpts
    oldOpts="$(set +o)"
    set +eu
    # shellcheck disable=SC1091
    . "$kit/etc/bashrc"
    eval "$oldOpts"
    # Open MPI refuses to run as root unless told (CI and containers run as root)
    if [ "$(id -u)" -eq 0 ]; then
        export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    fi
    haveFoamEnvironment || die "sourcing $kit/etc/bashrc did not give a working wmake"
}
