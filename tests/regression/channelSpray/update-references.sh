#!/usr/bin/env bash
# Regenerate the stored regression references of the channel-spray tutorial
# (serial and 2 ranks). Run only after a deliberate change of results, and say
# why in the commit message.
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
for mode in serial parallel; do
    "$here/check.sh" "$mode" "/tmp/dropletFiber-reference-$mode" --update
done
