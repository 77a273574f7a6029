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
# Tolerance: 1e-6 of each column's scale, maxSegmentLengthError < 1e-10
# (tests/cases/lib/tutorialRun.sh, compareWithReference).
#------------------------------------------------------------------------------
set -euo pipefail
mode="$1"; work="$2"; update="${3:-}"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../cases/lib/tutorialRun.sh"

args=(-short); [ "$mode" = parallel ] && args+=(-parallel)
runTutorialCopy channelSpray "$work" "${args[@]}"
# The tutorial's deposit is a small share of its run: no deposit warning
# (src/openfoam/depositReport; the figures at write times are there)
! grep -q "deposit of the parcels takes" "$work"/log.pimpleFoam || die "the tutorial warned of its deposit's share"
grep -q "% of the wall time over" "$work"/log.pimpleFoam || die "the tutorial's log has no deposit figures"
compareWithReference "$work/postProcessing/dropletFiber/0/dropletFiber.dat" \
    "$here/reference.$mode.dat" "$update"
