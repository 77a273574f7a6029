# shellcheck shell=bash
# A helper of the checks that damage or change a written file (sourced, not run).
#
# edit FILE PATTERN REPLACEMENT: replace the first match of a Python regular
# expression (re.S: '.' matches newlines too) in FILE; fails when nothing matches,
# so that a check never passes on a file it did not change.

edit() {
    local py=/usr/bin/python3
    [ -x "$py" ] || py=python3
    "$py" - "$@" <<'PY'
import re, sys
path, pattern, replacement = sys.argv[1:4]
text = open(path).read()
new = re.sub(pattern, replacement, text, count=1, flags=re.S)
assert new != text, "no match for " + pattern
open(path, "w").write(new)
PY
}
