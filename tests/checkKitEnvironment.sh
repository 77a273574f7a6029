#!/usr/bin/env bash
# The OpenFOAM kit's etc/bashrc (prepared by bin/installPrerequisites) gives the same
# environment without USER as with it (containers and CI may not set USER), sourced
# from bash and from POSIX sh (dash): FOAM_USER_LIBBIN where ./Allwmake puts the
# library, WM_PROJECT_DIR the kit, wmake and the solvers on PATH.
# Exit 77 (skipped) without a kit, or when another OpenFOAM is loaded (then that one
# is used and the kit is not).
cd "$(dirname "$0")/.." || exit 1
# shellcheck disable=SC1091
. bin/functions.sh
kit="$(foamKitDir)"
[ -f "$kit/.dropletFiber-kit" ] || { echo "SKIPPED: no OpenFOAM kit at $kit"; exit 77; }
if [ -n "${WM_PROJECT_DIR:-}" ] && ! [ "$WM_PROJECT_DIR" -ef "$kit" ]; then
    echo "SKIPPED: another OpenFOAM is loaded ($WM_PROJECT_DIR), the kit is not used"
    exit 77
fi
posixShell=/bin/sh
for dash in /bin/dash /usr/bin/dash; do
    [ -x "$dash" ] && { posixShell="$dash"; break; }
done

# environment SHELL [USER=...]: what a shell started with nothing but HOME and PATH
# gets from the kit's etc/bashrc (KIT passes the kit: bashrc reads its arguments)
environment() {
    local shell="$1"; shift
    # shellcheck disable=SC2016
    env -i HOME="$HOME" PATH=/usr/bin:/bin KIT="$kit" "$@" "$shell" -c \
        '. "$KIT/etc/bashrc"; echo "FOAM_USER_LIBBIN=$FOAM_USER_LIBBIN"; echo "WM_PROJECT_DIR=$WM_PROJECT_DIR"
         echo "wmake=$(command -v wmake)"; echo "pimpleFoam=$(command -v pimpleFoam)"' 2>&1
}
expected="$(environment bash USER="$(id -un)")"
echo "with USER=$(id -un), bash:"
echo "$expected" | sed 's/^/    /'
libbin="$(echo "$expected" | sed -n 's/^FOAM_USER_LIBBIN=//p')"

passed=0; failed=0
for shell in bash "$posixShell"; do
    got="$(environment "$shell")"
    if [ "$got" = "$expected" ]; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAILED: without USER, sourced from $shell, the kit's etc/bashrc gives"
        echo "$got" | sed 's/^/    /'
        echo "    (run bin/installPrerequisites: it prepares the kit's etc/bashrc for this)"
    fi
done
case "$libbin" in
    "$HOME/OpenFOAM/$(id -un)-"*) passed=$((passed + 1)) ;;
    *) failed=$((failed + 1)); echo "FAILED: FOAM_USER_LIBBIN '$libbin' is not under $HOME/OpenFOAM/$(id -un)-<version>" ;;
esac
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
