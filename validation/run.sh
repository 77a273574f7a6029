#!/bin/bash
# Regenerates the validation against the paper's section 6 (issue 6): docs/validation.md,
# docs/validation/*.png and the CSVs beside them. From anywhere:
#     validation/run.sh            full experiments (about 1-2 minutes on 2 cores)
#     validation/run.sh --reduced  the reduced sizes of the CTest run (a quick look)
# Steps: CMake build of paperValidation and validationTests into build-validation, the
# CTest checks (ctest -R validation), the experiments (CSVs), the depletion tests' tables,
# plot.py, report.py.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-validation"
out="$root/docs/validation"
python=/usr/bin/python3   # Debian python with python3-matplotlib (not a pyenv python)

"$python" -c "import matplotlib" 2>/dev/null || {
  echo "run.sh: $python has no matplotlib (apt-get install -y python3-matplotlib)" >&2; exit 1; }

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j2 --target paperValidation validationTests depletionUnitTests

mkdir -p "$out"
(cd "$build" && ctest -R '^validation\.' 2>&1) | tee "$out/ctest.txt"

start=$(date +%s)
(cd "$root" && "$build/validation/paperValidation" --out docs/validation "$@") | tee "$out/timing.txt"
echo "total $(( $(date +%s) - start )) s wall on $(nproc) cores" | tee -a "$out/timing.txt"

# Depletion (docs/model.md sec. 7): the unit tests' tables (depletionRows.csv, depletionMat.csv).
DROPLETFIBER_DEPLETION_CSV="$out" "$build/tests/depletionUnitTests" --gtest_filter='DepletionValidation.*:DenseMat.*' \
  > "$out/depletion.txt"

"$python" "$root/validation/plot.py" "$out" "$out"
"$python" "$root/validation/report.py" "$out" "$root/docs/validation.md" validation
