#!/usr/bin/env bash
#------------------------------------------------------------------------------
# compareRuns.sh A B - two finished runs of a case with the dropletFiber function
# object (e.g. the channelSpray tutorial built from two revisions) compared bit for
# bit: the per-step table without its wall-time columns, every VTK file and
# every restart-state file (serial and processor* directories). For changes that
# must not change results (refactoring, build flags). Prints each difference;
# exit 0 when identical.
#------------------------------------------------------------------------------
set -u
a=$1; b=$2; status=0
ta=$(ls "$a"/postProcessing/dropletFiber/0/dropletFiber.dat) || exit 2
tb=$(ls "$b"/postProcessing/dropletFiber/0/dropletFiber.dat) || exit 2
# the wall-time columns (named wallTime* in the header) left out, however many
strip() {
    awk -F'\t' 'BEGIN{OFS="\t"}
        /^# Time/ { for (i = 1; i <= NF; i++) if ($i ~ /wallTime/) skip[i] = 1; next }
        /^#/ { next }
        { line = ""; n = 0
          for (i = 1; i <= NF; i++) if (!(i in skip)) { line = (n++ ? line OFS : "") $i }
          print line }' "$1"
}
if ! cmp -s <(strip "$ta") <(strip "$tb"); then echo "DIFFER: table"; status=1; fi
echo "table rows: $(strip "$ta" | wc -l)"
n=0
a=$(cd "$a" && pwd); b=$(cd "$b" && pwd)
for f in $(cd "$a" && find postProcessing -name "*.vt?" && find . -path '*uniform/dropletFiber*' -type f); do
    n=$((n+1))
    if ! cmp -s "$a/$f" "$b/$f"; then echo "DIFFER: $f"; status=1; fi
done
echo "files compared: $n"
[ $status -eq 0 ] && echo "IDENTICAL" 
exit $status
