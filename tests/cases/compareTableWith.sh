#!/usr/bin/env bash
# compareTableWith.sh REFERENCE TOLERANCE CASE: the case's per-step table against a
# stored one (compareTables.py: the reference's columns, wall times left out).
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
"$PY" "$here/compareTables.py" "$1" "$3/postProcessing/dropletFiber/0/dropletFiber.dat" "$2"
