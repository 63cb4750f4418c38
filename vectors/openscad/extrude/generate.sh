#!/bin/sh
# Regenerate the extrusion cases: for each line of cases.txt, OpenSCAD writes the CSG export
# (NAME.csg) and, from that file, its own CGAL mesh (NAME.off). Needs the `openscad` binary
# (Debian's openscad 2021.01 made the checked-in files); the tests
# (tests/openscad_extrude.rs) only read them.
set -eu
cd "$(dirname "$0")"
here=$(pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -v '^#' cases.txt | while IFS="$(printf '\t')" read -r name stmt; do
    printf '%s\n' "$stmt" > "$tmp/$name.scad"
    openscad -q -o "$here/$name.csg" "$tmp/$name.scad" </dev/null
    openscad -q -o "$here/$name.off" "$here/$name.csg" </dev/null
done
openscad --version 2>&1 | head -1 > VERSION
