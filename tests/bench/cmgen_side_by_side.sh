#!/usr/bin/env bash
# Facet's IBL precompute beside Filament's cmgen at equal work, in one run (issue 12): for each
# HDRI, cmgen -x (prefiltered cube and SH) and facet bake (prefiltered cube, irradiance cube, SH9
# and the DFG tables) with the same cube size and GGX samples per texel, taking turns, each run a
# fresh process with an empty cache. Prints wall time (fastest and median of the repeats), peak
# memory, and the time facet bake itself reports (its work without process start-up).
#
# Usage: tests/bench/cmgen_side_by_side.sh [--facet PATH] [--size N] [--samples N] [--repeat N]
#            [HDRI ...]
#   default: build/ci/bin/facet, size 128, 128 samples, 3 repeats, the CC0 maps studio, forest
#   and night from packaging/fetch-assets.sh.
# Needs cmgen (Debian: apt-get install libfilament-tools) and oiiotool (openimageio-tools): cmgen
# reads ZIP-compressed EXR only, so every map is rewritten as ZIP half EXR first (both tools read
# that copy). Checks nothing: it measures (docs/benchmarks.md has the figures).
set -euo pipefail

facet=build/ci/bin/facet
size=128
samples=128
repeat=3
maps=()
while [ $# -gt 0 ]; do
    case "$1" in
    --facet) facet=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --samples) samples=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    -h | --help) sed -n '2,14p' "$0"; exit 0 ;;
    *) maps+=("$1"); shift ;;
    esac
done
assets=${FACET_ASSETS_DIR:-$HOME/.local/share/facet/assets}
if [ ${#maps[@]} -eq 0 ]; then
    maps=("$assets/hdri/studio.exr" "$assets/hdri/forest.exr" "$assets/hdri/night.exr")
fi
for tool in cmgen oiiotool "$facet"; do
    if ! command -v "$tool" > /dev/null; then
        echo "cmgen_side_by_side: $tool not found (cmgen: apt-get install libfilament-tools)" >&2
        exit 1
    fi
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Runs "$@" under /usr/bin/time; prints "seconds peak_MiB".
timed() {
    /usr/bin/time -f '%e %M' -o "$work/time" "$@" > "$work/out" 2>&1 || {
        echo "cmgen_side_by_side: failed: $*" >&2
        cat "$work/out" >&2
        exit 1
    }
    awk '{ printf "%s %.0f\n", $1, $2 / 1024 }' "$work/time"
}
# Fastest and median of the numbers on stdin.
summary() { sort -g | awk '{ v[NR] = $1 } END { printf "%.2f / %.2f", v[1], v[int((NR + 1) / 2)] }'; }

echo "cube $size, $samples GGX samples per texel, $repeat runs each taking turns; fresh process and empty cache each run"
echo
echo "| map | size | cmgen s (fastest / median) | cmgen MiB | facet bake s (fastest / median) | facet MiB | facet's own s | facet / cmgen (fastest) |"
echo "|---|---|---|---|---|---|---|---|"
for map in "${maps[@]}"; do
    name=$(basename "$map" .exr)
    zip="$work/$name.exr"
    oiiotool "$map" -d half --compression zip -o "$zip"
    dims=$(oiiotool --info "$zip" | awk '{ sub(",", "", $5); print $3 "x" $5 }')
    : > "$work/cmgen.s"; : > "$work/facet.s"; : > "$work/facet.own"
    cmgenMiB=0; facetMiB=0
    for ((i = 0; i < repeat; ++i)); do
        rm -rf "$work/cmgen-out" && mkdir "$work/cmgen-out"
        read -r s m < <(timed cmgen --quiet -x "$work/cmgen-out" --size="$size" --ibl-samples="$samples" "$zip")
        echo "$s" >> "$work/cmgen.s"; cmgenMiB=$((m > cmgenMiB ? m : cmgenMiB))

        rm -rf "$work/facet-out" "$work/cache" && mkdir "$work/cache"
        read -r s m < <(FACET_CACHE_DIR="$work/cache" timed "$facet" bake "$zip" --ibl-size "$size" \
            --cube-size "$size" --samples "$samples" -o "$work/facet-out")
        echo "$s" >> "$work/facet.s"; facetMiB=$((m > facetMiB ? m : facetMiB))
        # "facet bake: wrote ... (..., default, 0.59 s)"
        sed -n 's/.*, \([0-9.]*\) s)$/\1/p' "$work/out" >> "$work/facet.own"
    done
    cm=$(summary < "$work/cmgen.s")
    fa=$(summary < "$work/facet.s")
    own=$(summary < "$work/facet.own")
    ratio=$(awk -v a="${fa%% *}" -v b="${cm%% *}" 'BEGIN { printf "%.2f", a / b }')
    echo "| $name | $dims | $cm | $cmgenMiB | $fa | $facetMiB | $own | $ratio |"
done
