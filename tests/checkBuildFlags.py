#!/usr/bin/env python3
"""One build truth: the core compiled by wmake (the shipped libdropletFiber.so) and by
CMake (the unit-tested and benchmarked core) must be the same sources with the same
result-relevant flags and warnings.

Usage: checkBuildFlags.py <compile_commands.json> <project dir>

Needs a loaded OpenFOAM environment and a wmake build (./Allwmake: its preprocessed
Make/$WM_OPTIONS/options); exits 77 (skipped) without them. Compares, per core source:
  - the sources: Make/files' src/core entries against CMake's core sources;
  - the effective -O level, -std, -march/-mtune, preprocessor defines (OpenFOAM's own
    -DOPENFOAM, -DWM_*, -DNoRepository excepted), every other -f/-m option that can
    change generated code (hardening, debug info and paths excepted);
  - the effective warnings (-W... / -Wno-...; Debian's and FOAM_EXTRA_CXXFLAGS' own
    hardening warnings, which come from the environment, excepted).
Prints both builds' figures and every difference; exit 1 on drift.
"""
import json
import os
import shlex
import subprocess
import sys

OPENFOAM_DEFINES = ("OPENFOAM", "WM_", "NoRepository")
# Options that do not change the generated arithmetic: position independence,
# hardening, debug information, paths, diagnostics, template depth, threads
NEUTRAL_PREFIXES = (
    "-fPIC", "-fpic", "-fPIE", "-fpie", "-fstack-protector", "-fstack-clash",
    "-fcf-protection", "-ffile-prefix-map", "-fdebug-prefix-map",
    "-fmacro-prefix-map", "-ftemplate-depth", "-fdiagnostics", "-fmessage-length",
    "-pthread", "-g", "-pipe",
)


def signature(tokens, environment_warnings):
    """The result-relevant content of a compile line, as a dict of comparable values."""
    sig = {"opt": "-O0", "std": None, "march": None, "mtune": None,
           "defines": {}, "codegen": set(), "warnings": {}}
    skip_next = False
    for t in tokens[1:]:  # tokens[0]: the compiler
        if skip_next:
            skip_next = False
            continue
        if t in ("-o", "-isystem", "-include", "-MF", "-MT", "-MQ", "-x"):
            skip_next = True
        elif t in ("-c", "-MD", "-MMD", "-MP") or not t.startswith("-"):
            continue
        elif t.startswith(("-I", "-isystem")):
            continue
        elif t.startswith("-O"):
            sig["opt"] = t
        elif t.startswith("-std="):
            sig["std"] = t
        elif t.startswith("-march="):
            sig["march"] = t
        elif t.startswith("-mtune="):
            sig["mtune"] = t
        elif t.startswith("-D"):
            name, _, value = t[2:].partition("=")
            if not name.startswith(OPENFOAM_DEFINES):
                sig["defines"][name] = value
        elif t.startswith("-U"):
            sig["defines"].pop(t[2:], None)
        elif t.startswith("-W"):
            if t in environment_warnings:
                continue
            if t.startswith("-Wno-"):
                sig["warnings"][t[5:]] = "off"
            elif not t.startswith(("-Wl,", "-Wa,", "-Wp,")):
                sig["warnings"][t[2:]] = "on"
        elif t.startswith(NEUTRAL_PREFIXES):
            continue
        else:
            sig["codegen"].add(t)
    sig["codegen"] = sorted(sig["codegen"])
    return sig


def wmake_compile_line(project):
    """wmake's compile line for the library's sources: its compiler and flags plus the
    project's EXE_INC, evaluated by make from wmake's own preprocessed Make/options."""
    wm_options = os.environ.get("WM_OPTIONS", "")
    options = os.path.join(project, "Make", wm_options, "options")
    if not wm_options or not os.path.isfile(options):
        print(f"SKIPPED: no wmake build ({options} missing): run ./Allwmake first")
        sys.exit(77)
    compiler = subprocess.run(["wmake", "-show-compile-cxx"], cwd=project,
                              capture_output=True, text=True, check=True).stdout
    makefile = f"include {options}\nprint:\n\t@echo $(EXE_INC)\n"
    exe_inc = subprocess.run(["make", "-s", "-f", "-", "print"], cwd=project,
                             input=makefile, capture_output=True, text=True,
                             check=True).stdout
    # wmake: c++FLAGS = arch, defines, warnings, -O, ..., then EXE_INC, then -fPIC
    return shlex.split(compiler) + shlex.split(exe_inc)


def environment_warnings():
    """Warnings that Debian's build flags and FOAM_EXTRA_CXXFLAGS add to wmake's line."""
    tokens = shlex.split(os.environ.get("FOAM_EXTRA_CXXFLAGS", ""))
    try:
        tokens += shlex.split(subprocess.run(["dpkg-buildflags", "--get", "CXXFLAGS"],
                                             capture_output=True, text=True).stdout)
    except OSError:
        pass
    return {t for t in tokens if t.startswith("-W")}


def make_files_core_sources(project):
    with open(os.path.join(project, "Make", "files")) as f:
        return {line.strip() for line in f if line.strip().startswith("src/core/")}


def cmake_core_compile_lines(compile_commands, project):
    with open(compile_commands) as f:
        entries = json.load(f)
    core = os.path.join(os.path.realpath(project), "src", "core") + os.sep
    lines = {}
    for e in entries:
        path = os.path.realpath(os.path.join(e["directory"], e["file"]))
        if path.startswith(core):
            rel = os.path.relpath(path, os.path.realpath(project))
            lines[rel] = e["arguments"] if "arguments" in e else shlex.split(e["command"])
    return lines


def describe(sig):
    return (f"{sig['opt']} {sig['std']} march={sig['march']} mtune={sig['mtune']}\n"
            f"      defines  {sorted(sig['defines'].items())}\n"
            f"      codegen  {sig['codegen']}\n"
            f"      warnings {sorted(sig['warnings'].items())}")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    compile_commands, project = sys.argv[1], os.path.abspath(sys.argv[2])
    if not os.environ.get("WM_PROJECT_DIR"):
        print("SKIPPED: no OpenFOAM environment loaded")
        return 77
    failures = []

    wmake_sources = make_files_core_sources(project)
    cmake_lines = cmake_core_compile_lines(compile_commands, project)
    for src in sorted(wmake_sources - set(cmake_lines)):
        failures.append(f"{src}: in Make/files (wmake) but not built by CMake")
    for src in sorted(set(cmake_lines) - wmake_sources):
        failures.append(f"{src}: built by CMake but not in Make/files (wmake)")

    env_warnings = environment_warnings()
    wmake_sig = signature(wmake_compile_line(project), env_warnings)
    print(f"wmake:  {describe(wmake_sig)}")
    shown = False
    for src, tokens in sorted(cmake_lines.items()):
        sig = signature(tokens, env_warnings)
        if not shown:
            print(f"CMake:  {describe(sig)}")
            shown = True
        for key in wmake_sig:
            if sig[key] != wmake_sig[key]:
                failures.append(f"{src}: {key} differs: CMake {sig[key]} / wmake {wmake_sig[key]}")
    print(f"{len(cmake_lines)} core sources compared")
    for f in failures:
        print("FAILED: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
