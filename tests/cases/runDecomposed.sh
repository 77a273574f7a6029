#!/usr/bin/env bash
#------------------------------------------------------------------------------
# runDecomposed.sh - runCase.sh on N processors with a decomposition of its own
# (method simple, n (NX NY NZ)): the grid's blocks then cut where the fibers and
# the kernels cross them. Runs with more processors than cores are oversubscribed.
#
# Usage: runDecomposed.sh CASE_DIR WORK_DIR NX NY NZ [CHECK_COMMAND ...]
#------------------------------------------------------------------------------
set -euo pipefail
caseDir="$1"; workDir="$2"; nx="$3"; ny="$4"; nz="$5"; shift 5
here="$(cd "${0%/*}" && pwd)"
source="$(mktemp -d)"
trap 'rm -rf "$source"' EXIT
cp -r "$caseDir"/. "$source"
cat > "$source/system/decomposeParDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains $((nx * ny * nz));
method          simple;
coeffs          { n ($nx $ny $nz); }
DICT
export OMPI_MCA_rmaps_base_oversubscribe=true
"$here/runCase.sh" "$source" "$workDir" parallel "$@"
