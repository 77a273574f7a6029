#!/usr/bin/env bash
# What a finished run says is true: each cloud's gathering route is logged as it is
# read; the table has one wall-time column per stage; the .series indices and the VTK
# files' TimeValue carry the time folders' names; parallelStatistics.dat is written,
# and a serial run sends nothing. Usage: checkRunMessages.sh serial|parallel CASE_RUN (a finished
# run of fixedFiber: a kinematic cloud, pimpleFoam, writes at 0.1 and 0.2)
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
mode="$1"; run="$2"
out="$run/postProcessing/dropletFiber/0"
log="$run/log.pimpleFoam"

check "grep -q \"cloud 'kinematicCloud' (type Cloud<basicKinematicCollidingParcel>) read parcel by parcel\" '$log'" \
    "the cloud's route is not logged"
check "[ \"\$(grep -c \"cloud 'kinematicCloud' (type\" '$log')\" = 1 ]" "the cloud's route is logged more than once"
check "grep -q -P '^# Time.*\\twallTimeDeposition *\\twallTimeCollision *\\twallTimeFibers *$' '$out/dropletFiber.dat'" \
    "the table's last columns are not wallTimeDeposition, wallTimeCollision, wallTimeFibers"
# a parallel run's series are named by the pieces' index they list (ParaView's reader)
p=""; [ "$mode" = parallel ] && p=p
for series in fibers.${p}vtp.series grid.${p}vti.series; do
    check "[ \"\$(grep -o '\"time\" : [^ ]*' '$out/$series' | tr '\n' ' ')\" = '\"time\" : 0.1 \"time\" : 0.2 ' ]" \
        "$series: the times are not the folders' names 0.1 and 0.2: $(grep -o '"time" : [^ ]*' "$out/$series" | tr '\n' ' ')"
done
vtk="$out/grid_0.1.vti"; [ "$mode" = parallel ] && vtk="$out/grid_0.1.pvti"
check "grep -q '\"TimeValue\"[^>]*>0.1<' '$vtk'" "$vtk: TimeValue is not 0.1"
check "[ -f '$out/parallelStatistics.dat' ]" "no parallelStatistics.dat in a $mode run"
if [ "$mode" = serial ]; then
    check "awk '!/^#/ { n++; if (\$4 != 0) bad = 1 } END { exit bad || !n }' '$out/parallelStatistics.dat'" \
        "a serial run's parallelStatistics.dat counts bytes sent (bytesSentMax not 0)"
fi
checkSummary
