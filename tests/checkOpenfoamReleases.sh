#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkOpenfoamReleases.sh - the OpenFOAM layer compiles against a newer
# openfoam.com release (CTest build.openfoamReleases.<release>).
#
# No newer OpenFOAM is installed here, and none can be: the library sources of the
# release, OpenFOAM-<release>-src.tar.xz in $DROPLETFIBER_OPENFOAM_SOURCES (default:
# ../shared/openfoam-esi beside the project), are unpacked into the cache folder
# once, with the flat lnInclude folders the release's own wmake/wmakeLnInclude makes
# for every library folder (kept between runs; made again when the archive changes).
#
# Then every source that ./Allwmake compiles against OpenFOAM, read from Make/files
# and applications/*/Make/files (all but src/core, plain C++ that includes no
# OpenFOAM header), is compiled syntax-only (-fsyntax-only: nothing can link without
# a built OpenFOAM) with the compile line wmake would use there: the release's rules
# and the preprocessed Make/options (openfoamReleases/compileFlags.mk), so
# -DOPENFOAM=<release number> and the #if OPENFOAM guards of Make/options and of the
# sources take the release's branch.
#
# Usage: checkOpenfoamReleases.sh <release, e.g. v2312> <cache folder> [jobs]
#        (the release is kept in <cache folder>/noLink/<release>)
# Exit:  0 every file compiles, 1 one does not (its errors are printed),
#        77 skipped: no archive of that release (CTest SKIP_RETURN_CODE)
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
project="$(cd "$here/.." && pwd)"
release="${1:?usage: $0 <release> <cache folder> [jobs]}"
cache="${2:?usage: $0 <release> <cache folder> [jobs]}"
jobs="${3:-1}"
sources="${DROPLETFIBER_OPENFOAM_SOURCES:-$project/../shared/openfoam-esi}"
archive="$sources/OpenFOAM-$release-src.tar.xz"
start=$(date +%s)

if [ ! -f "$archive" ]; then
    echo "SKIPPED: no $archive, so OpenFOAM $release is not checked."
    echo "    Set DROPLETFIBER_OPENFOAM_SOURCES to the folder holding OpenFOAM-$release-src.tar.xz."
    exit 77
fi

# The release unpacked, with its lnInclude folders: made once per archive, its checksum
# written last (the stamp), so that a run stopped half-way never leaves a tree that
# looks ready. In a folder named noLink: wmake links every header under the project's
# folder (the build folder included) into the project's lnInclude, which comes before
# OpenFOAM's own on the include path, so a release's headers found there would be
# compiled into the v1912 library; wmakeLnInclude skips folders named noLink
mkdir -p "$cache/noLink"
cache="$(cd "$cache/noLink" && pwd)"
tree="$cache/$release/OpenFOAM-$release"
stamp="$cache/$release/archive.sha256"
sum="$(sha256sum < "$archive" | cut -d' ' -f1)"
if [ ! -d "$tree" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$sum" ]; then
    echo "unpacking $archive into $cache/$release (once, kept for the next runs)"
    rm -rf "${cache:?}/$release"
    work="$cache/$release.new.$$"
    rm -rf "$work"
    mkdir -p "$work"
    tar -xJf "$archive" -C "$work"
    [ -d "$work/OpenFOAM-$release/src" ] \
        || { echo "FAILED: $archive holds no OpenFOAM-$release/src"; exit 1; }
    # wmakeLnInclude links each library's headers and templates into <library>/lnInclude;
    # a library folder is one with a Make/ folder, as OpenFOAM's own Allwmake builds them
    # (each folder's own lnInclude: independent, so $jobs at a time)
    find "$work/OpenFOAM-$release/src" -type d -name Make -prune -print0 | sed -z 's|/Make$||' \
        | xargs -0 -P "$jobs" -n 1 bash "$work/OpenFOAM-$release/wmake/wmakeLnInclude" -s 2>/dev/null \
        || { echo "FAILED: the release's wmakeLnInclude"; exit 1; }
    mkdir -p "$cache/$release"
    mv "$work/OpenFOAM-$release" "$tree"
    rm -rf "$work"
    echo "$sum" > "$stamp"
    echo "unpacked with $(find "$tree/src" -path '*/lnInclude/*' | wc -l) lnInclude links in $(( $(date +%s) - start )) s"
fi

# One list of work: "<folder holding Make/><TAB><source>" for every source wmake
# compiles against OpenFOAM, and the compile line of each folder (in a file)
lines="$cache/$release/compileLines"
rm -rf "$lines" "$cache/$release/logs"
mkdir -p "$lines" "$cache/$release/logs"
work="$cache/$release/work"
: > "$work"
expected="-DOPENFOAM=${release#v}"
folders=("$project")
for app in "$project"/applications/*/; do
    [ -f "$app/Make/files" ] && folders+=("${app%/}")
done
for i in "${!folders[@]}"; do
    dir="${folders[$i]}"
    flags() {
        make -s -f "$here/openfoamReleases/compileFlags.mk" WM_PROJECT_DIR="$tree" \
            MAKE_DIR="$dir/Make" OPTIONS="$lines/options.$i" "$1"
    }
    line="$(flags compileLine)"
    # the version guards can only be checked when the line defines the release number
    case " $line " in
        *" $expected "*) ;;
        *) echo "FAILED: the compile line of $dir has no $expected: $line"; exit 1 ;;
    esac
    echo "$line" > "$lines/line.$i"
    echo "$dir" >> "$lines/folders"
    flags sources | grep -v '^src/core/' | sed "s|^|$i\t|" >> "$work" || true
done
nFiles=$(wc -l < "$work")
[ "$nFiles" -gt 0 ] || { echo "FAILED: Make/files lists no OpenFOAM-layer source"; exit 1; }

# Compile one entry "<folder index><TAB><source>" syntax-only; its output in logs/
compileOne() {
    local i="${1%%	*}" src="${1#*	}" dir log
    dir="$(sed -n "$((i + 1))p" "$lines/folders")"
    log="$cache/$release/logs/$(echo "$i/$src" | tr '/' '_').log"
    # shellcheck disable=SC2046  # the compile line is a list of words
    if (cd "$dir" && $(cat "$lines/line.$i") -fsyntax-only "$src") > "$log" 2>&1; then
        echo "ok $src"
    else
        echo "FAILED $src"
        grep -E "error|required from" "$log" | head -20 | sed 's/^/    /'
    fi
}
export -f compileOne
export cache release lines
echo "compiling $nFiles files syntax-only against OpenFOAM $release ($expected), $jobs at a time"
results="$cache/$release/results"
# shellcheck disable=SC2016  # $1 is bash -c's argument
tr '\n' '\0' < "$work" \
    | xargs -0 -P "$jobs" -I{} bash -c 'compileOne "$1"' _ {} \
    | tee "$results"
failed=$(grep -c '^FAILED' "$results" || true)
echo "$((nFiles - failed)) of $nFiles files compile against OpenFOAM $release, $failed fail ($(( $(date +%s) - start )) s)"
[ "$failed" -eq 0 ]
