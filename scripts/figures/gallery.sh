#!/usr/bin/env bash
# Regenerates the figures of docs/viewer-and-plots.md 'The figure gallery' (assets/figures/; README.md
# shows one of them, run-rail-smooth-motion.png): one rail run on the smooth skin (flat plate,
# 0.1 mm/s) and one incipient run on fingerprint-v2 (acrylic plate, external markers, 0.3 mm/s),
# each drawn by `tactip plot` into assets/figures/run-NAME-FIGURE.png.
# Usage, from the repository:
#   scripts/figures/gallery.sh [path/to/tactip]        (default: build/release/tactip)
# The datasets and CSVs go to a temporary folder that is removed afterwards; only the PNGs
# are kept (the same commands by hand give the CSVs too).
set -euo pipefail

repo="$(cd "$(dirname "$0")/../.." && pwd)"
tactip="${1:-$repo/build/release/tactip}"
out="$repo/assets/figures"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Seed 7: the runs shown in the gallery (change it here to show others).
"$tactip" generate rail --runs 1 --seed 7 --speed-mm-s 0.1 --stimulus flat --skin smooth --quiet \
  --out "$work/rail.h5"
"$tactip" generate incipient --runs 1 --seed 7 --speed-mm-s 0.3 --skin fingerprint-v2 --quiet \
  --out "$work/incipient.h5"

for name in rail-smooth incipient-v2; do
  file="$work/rail.h5"
  [[ "$name" == incipient-v2 ]] && file="$work/incipient.h5"
  "$tactip" plot "$file" --run 0 --out "$work/$name"
  for png in "$work/$name"/*.png; do
    cp "$png" "$out/run-$name-$(basename "$png")"
  done
done
ls -l "$out"/run-*.png
