# shellcheck shell=bash
#------------------------------------------------------------------------------
# functions.sh - shell helpers shared by the project's scripts (sourced, not run).
#
#   info MSG...            print a prefixed message
#   die MSG...             print a prefixed error and exit 1
#   run CMD...             print the command, then run it
#   haveFoamEnvironment    true when an OpenFOAM environment is loaded
#   foamKitDir             where installPrerequisites keeps the OpenFOAM kit
#   loadFoamEnvironment    use the loaded OpenFOAM, else source the kit's bashrc
#   installUserTools DIR   copy the user-facing tools into DIR (Allwmake: $FOAM_USER_APPBIN)
#   removeUserTools DIR    remove them from DIR (Allclean)
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

# The user-facing tools, installed like OpenFOAM's own utilities: ./Allwmake copies
# them into $FOAM_USER_APPBIN (on PATH once OpenFOAM's environment is loaded), beside
# reconstructDropletFiberState, so that a tutorial copied anywhere finds them on
# PATH: its Allrun and Allparaview source dropletFiberRunFunctions (found on PATH,
# or in the project's bin/ with DROPLETFIBER_DIR=<project>), whose functions find
# the others the same way. The report's Python modules (tools/dropletFiberReport) go
# into DIR/dropletFiberPython, where the installed report (and the formingHood
# tutorial's helpers) look for them. Copies, not links: the installed tools work
# whatever becomes of this clone's files.
userTools=(dropletFiberRunFunctions dropletFiberReport checkFunctionObjectRan dropletFiberParaView.py)
userToolsModules=dropletFiberPython

installUserTools() {
    local dest="$1" src tool
    src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
    mkdir -p "$dest"
    # the modules first (the report needs them), replaced as a whole: a module
    # removed from the project does not stay behind
    rm -rf "$dest/.$userToolsModules.new"
    mkdir "$dest/.$userToolsModules.new"
    cp "$src"/tools/dropletFiberReport/*.py "$dest/.$userToolsModules.new/"
    rm -rf "$dest/$userToolsModules"
    mv "$dest/.$userToolsModules.new" "$dest/$userToolsModules"
    for tool in "${userTools[@]}"; do
        # install(1) replaces the file (a new inode): a copy running meanwhile goes on
        case "$tool" in
            # a ParaView script and the sourced run functions (as OpenFOAM's RunFunctions) are not commands
            *.py | dropletFiberRunFunctions) install -m 644 "$src/bin/$tool" "$dest/$tool" ;;
            *) install -m 755 "$src/bin/$tool" "$dest/$tool" ;;
        esac
    done
}

removeUserTools() {
    local dest="$1" tool
    for tool in "${userTools[@]}"; do
        rm -f "$dest/$tool"
    done
    rm -rf "${dest:?}/$userToolsModules" "${dest:?}/.$userToolsModules.new"
}
