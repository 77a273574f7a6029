#!/usr/bin/env bash
# checkFormingLine.sh RUN - checkFormingLine.py on a finished fiberRain run, in the
# project's OpenFOAM environment (dropletFiberFormingLine on PATH with its libraries)
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
loadFoamEnvironment > /dev/null
exec python3 "$here/checkFormingLine.py" "$1"
