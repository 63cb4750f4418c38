#!/bin/sh
# Regenerate the malformed-part cases: for each line of cases.txt, OpenSCAD writes the CSG
# export (NAME.csg) of the statement and its own CGAL mesh (NAME.off) of the same .scad (not
# of the export: an infinite number is written to the export as `inf`, which OpenSCAD reads
# back as an unknown variable), and its warnings (NAME.warnings). Needs the `openscad`
# binary (Debian's openscad 2021.01 made the checked-in files); the tests
# (tests/openscad_lenient.rs) only read them.
set -eu
cd "$(dirname "$0")"
grep -v '^#' cases.txt | while IFS="$(printf '\t')" read -r name stmt; do
    printf '%s\n' "$stmt" > ".$name.scad"
    openscad -q -o "$name.csg" ".$name.scad" </dev/null 2>/dev/null
    openscad -o "$name.off" ".$name.scad" </dev/null 2>&1 \
        | grep -E '^(WARNING|ERROR)' | sed "s#$PWD/##; s#\.$name\.scad#$name.scad#" > "$name.warnings" || true
    rm -f ".$name.scad"
done
openscad --version 2>&1 | head -1 > VERSION
