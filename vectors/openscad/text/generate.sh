#!/bin/sh
# Regenerate OpenSCAD's reference data for text(): for each case of cases.txt, OpenSCAD
# writes the CSG export of `linear_extrude(height = 2) text(...)` (NAME.csg) and, from that
# file, its own mesh (NAME.off). crates/voxel/tests/openscad_text.rs reads both. Needs the `openscad`
# binary (Debian's openscad 2021.01 with fonts-liberation2 2.1.5 made the checked-in files,
# the same font files as vectors/fonts); the tests only read the results.
set -eu
cd "$(dirname "$0")"
here=$(pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -v '^#' cases.txt | while IFS="$(printf '\t')" read -r name stmt; do
    printf 'linear_extrude(height = 2) %s\n' "$stmt" > "$tmp/$name.scad"
    openscad -q -o "$here/$name.csg" "$tmp/$name.scad" </dev/null
    openscad -q -o "$here/$name.off" "$here/$name.csg" </dev/null
done
openscad --version 2>&1 | head -1 > VERSION
