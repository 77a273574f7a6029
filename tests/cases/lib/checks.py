"""Counted checks of the case tests' Python scripts, as prepareCase.sh's check and
checkSummary are for the shell scripts.

- check(ok, what, quiet=False): count a check as passed or failed and print
  `ok: what` or `FAILED: what` (quiet: failures only).
- failures(): how many failed so far.
- finish(): print `N passed, N failed` and exit, non-zero when any failed.
"""
import sys

_passed = 0
_failed = 0


def check(ok, what, quiet=False):
    global _passed, _failed
    if ok:
        _passed += 1
        if not quiet:
            print("ok: " + what)
    else:
        _failed += 1
        print("FAILED: " + what)


def failures():
    return _failed


def finish():
    print("%d passed, %d failed" % (_passed, _failed))
    sys.exit(1 if _failed else 0)
