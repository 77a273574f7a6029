#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The tutorial's balance script (tutorials/formingHood/hoodBalance.py) on a
# made-up case whose figures are chosen by hand: a cloud report at t = 0.002 s
# (introduced 1, in the air 0.5, phase change 0.2, escaped 0.05 through the
# walls and 0.15 through the outlet, which the cloud counts as leaving the
# "system") and a table whose capturedTotal is 0.1 at 0.001 s and 0.3 at 0.002 s.
# The cloud reports before the function object of its step removes the captured
# droplets, so the balance 1 = 0.5 + 0.2 + 0.05 + 0.15 + 0.1 closes with the
# previous step's 0.1: exit 0. The same with 0.25 through the outlet (or with the
# same step's 0.3) does not close: exit 1.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
script="$here/../../../tutorials/formingHood/hoodBalance.py"
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
# the script reads the log and the table with the report's modules: this project's
export DROPLETFIBER_DIR="$here/../../.."
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
mkdir -p "$work/postProcessing/dropletFiber/0"
printf '# Time\tfibers\tcapturedTotal\n0.001\t1\t0.1\n0.002\t1\t0.3\n' \
    > "$work/postProcessing/dropletFiber/0/dropletFiber.dat"
report() { # outlet mass
    cat <<LOG
Time = 0.002

Cloud: sprayCloud
    Current number of parcels       = 10
    Current mass in system          = 0.5
    Injector binderRing:
      - parcels added               = 20
      - mass introduced             = 1
    Parcel fate: system (number, mass)
      - escape                      = 3, $1
    Parcel fate: patch (number, mass) outlet
      - escape                      = 0, 0
      - stick                       = 0, 0
    Parcel fate: patch (number, mass) walls
      - escape                      = 1, 0.05
      - stick                       = 0, 0
    Temperature min/max             = 290, 300
    Mass transfer phase change      = 0.2

LOG
}
report 0.15 > "$work/log.closes"
report 0.25 > "$work/log.open"
"$PY" "$script" "$work" log.closes || { echo "FAILED: a closed balance was not found closed"; exit 1; }
if "$PY" "$script" "$work" log.open; then echo "FAILED: an open balance passed"; exit 1; fi
echo "hoodBalance.py: closed balance passes, open balance fails"
