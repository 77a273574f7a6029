#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The project's dropletFiberParaView.py in ParaView itself, headless, as a tutorial's
# Allparaview -batch runs it: pvbatch runs it on a copy of the tutorial's finished
# -short run (the regression run), with the case and the screenshot, on a virtual X
# display of 24 bits (Xvfb), then checkParaView.py checks the pipeline it built
# (every source with data at the last time, coloured by its own array with a colour
# map of its own whose range holds the array's values at every time) and the
# screenshot it wrote.
#
# Usage: checkParaView.sh TUTORIAL RUN WORK
#   TUTORIAL  channelSpray | channelSprayRAS | formingHood
#   RUN       the tutorial's finished run (not changed: a copy is viewed)
#   WORK      a scratch folder (replaced)
# Exit 77 (CTest: skipped, saying why) without pvbatch (bin/installPrerequisites
# -paraview installs it) or without Xvfb and a display.
#------------------------------------------------------------------------------
set -euo pipefail
tutorial="$1"; run="$2"; work="$3"
here="$(cd "${0%/*}" && pwd)"
root="$(cd "$here/../.." && pwd)"

if ! command -v pvbatch > /dev/null; then
    echo "skipped: no pvbatch (ParaView) on this machine; bin/installPrerequisites -paraview installs Debian's"
    exit 77
fi
rm -rf "$work"
mkdir -p "$work"
cp -r "$run" "$work/case"

# A display of our own: Xvfb picks a free number and writes it once it accepts
# clients (-displayfd), so parallel tests never race for one (xvfb-run -a can)
xvfb=
stopDisplay() {
    if [ -n "$xvfb" ]; then
        kill "$xvfb" 2> /dev/null && wait "$xvfb" 2> /dev/null
        xvfb=
    fi
    return 0
}
trap stopDisplay EXIT
startDisplay() {
    rm -f "$work/display"
    Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3> "$work/display" 2> "$work/Xvfb.log" &
    xvfb=$!
    for _ in $(seq 100); do
        [ -s "$work/display" ] && break
        kill -0 "$xvfb" 2> /dev/null || { cat "$work/Xvfb.log"; echo "Xvfb did not start"; exit 1; }
        sleep 0.1
    done
    [ -s "$work/display" ] || { cat "$work/Xvfb.log"; echo "Xvfb gave no display in 10 s"; exit 1; }
    export DISPLAY=":$(head -1 "$work/display")"
}
if ! command -v Xvfb > /dev/null && [ -z "${DISPLAY:-}" ]; then
    echo "skipped: no Xvfb and no DISPLAY for pvbatch; bin/installPrerequisites -paraview installs xvfb"
    exit 77
fi

# The project's script from this project (not whatever PATH has), run from another
# folder than the case's, given the case as the launcher gives it. A display that
# refuses ParaView's window (seen now and then on a shared machine: "bad X server
# connection") is replaced, twice at most.
cd "$work"
for attempt in 1 2 3; do
    if command -v Xvfb > /dev/null; then
        startDisplay
    fi
    set +e
    pvbatch "$here/checkParaView.py" "$root/bin/dropletFiberParaView.py" "$work/case" \
        "$work/case/$tutorial.paraview.png" > "$work/pvbatch.log" 2>&1
    status=$?
    set -e
    cat "$work/pvbatch.log"
    stopDisplay
    if [ "$status" -eq 0 ] || ! grep -q "bad X server connection" "$work/pvbatch.log"; then
        exit "$status"
    fi
    echo "(attempt $attempt: the display refused the window; again with a new one)"
done
exit "$status"
