#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Regression run of the channel-spray tutorial: the shortened run (Allrun -short,
# 80 time steps) in a scratch copy, its per-step table compared with the stored
# reference of the same mode, and its physical sanity checked on its own
# (the report that Allrun ends with, bin/dropletFiberReport: the binder balance,
# captured binder <= sprayed binder, parcel and fiber mass balances).
#
# Usage: check.sh serial|parallel WORK_DIR [--update]
#   --update  store this run's table as the new reference (only through
#             update-references.sh, after a deliberate change of results)
#
# Tolerance: 1e-6 of each column's scale. The run is deterministic (same
# decomposition, same random seeds), so a larger difference is a change of
# behaviour; round-off from another compiler or library stays far below it.
# maxSegmentLengthError is round-off by nature: it is checked to stay < 1e-10.
#------------------------------------------------------------------------------
set -euo pipefail
mode="$1"; work="$2"; update="${3:-}"
here="$(cd "${0%/*}" && pwd)"
root="$(cd "$here/../../.." && pwd)"
. "$root/bin/functions.sh"
loadFoamEnvironment
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

rm -rf "$work"; mkdir -p "$(dirname "$work")"
cp -r "$root/tutorials/channelSpray" "$work"
(cd "$work" && ./Allclean > /dev/null)
args=(-short); [ "$mode" = parallel ] && args+=(-parallel)
if ! (cd "$work" && ./Allrun "${args[@]}"); then
    tail -n 30 "$work"/log.* ; die "Allrun ${args[*]} failed"
fi
# A run without the function object (library not loaded) fails here too, whatever
# the Allrun does
"$root/bin/checkFunctionObjectRan" "$work" || die "the run of $work went on without the function object"
# The tutorial's deposit is a small share of its run: no deposit warning
# (src/openfoam/depositReport; the figures at write times are there)
! grep -q "deposit of the parcels takes" "$work"/log.pimpleFoam || die "the tutorial warned of its deposit's share"
grep -q "% of the wall time over" "$work"/log.pimpleFoam || die "the tutorial's log has no deposit figures"
table="$work/postProcessing/dropletFiber/0/dropletFiber.dat"
reference="$here/reference.$mode.dat"
if [ "$update" = --update ]; then
    cp "$table" "$reference"
    info "stored $reference"
    exit 0
fi
"$PY" "$root/tests/cases/compareTables.py" --skip maxSegmentLengthError "$reference" "$table" 1e-6
"$PY" - "$table" <<'PYEOF'
import sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
header = [l for l in open(sys.argv[1]) if l.startswith("#")][-1][1:].split("\t")
col = [h.strip() for h in header if h.strip()].index("maxSegmentLengthError")
worst = max(float(r[col]) for r in rows)
print("largest segment-length error %.3g (must stay < 1e-10)" % worst)
sys.exit(0 if worst < 1e-10 else 1)
PYEOF
