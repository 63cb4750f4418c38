#!/bin/sh
# Regenerate the import() of DXF cases: for each line of cases.txt, OpenSCAD writes the CSG
# export (NAME.csg) of the statement, written beside the DXF files for the time of the run,
# and, from that file, its own CGAL mesh (NAME.off). Needs the `openscad` binary (Debian's
# openscad 2021.01 made the checked-in files); the tests (tests/openscad_dxf.rs) only read them.
set -eu
cd "$(dirname "$0")"
grep -v '^#' cases.txt | while IFS="$(printf '\t')" read -r name stmt; do
    printf '%s\n' "$stmt" > ".$name.scad"
    openscad -q -o "$name.csg" ".$name.scad" </dev/null
    rm -f ".$name.scad"
    openscad -q -o "$name.off" "$name.csg" </dev/null
done
openscad --version 2>&1 | head -1 > VERSION
