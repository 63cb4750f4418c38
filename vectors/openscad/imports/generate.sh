#!/bin/sh
# Regenerate the import() of OFF, AMF and 3MF cases: for each line of cases.txt, OpenSCAD
# writes the CSG export (NAME.csg) of the statement and, from that file, its own mesh
# (NAME.off). The meshes imported are made by make_inputs.py (committed; run it first only to
# change them). Needs the `openscad` binary (Debian's openscad 2021.01, lib3mf 1.8.1, made the
# checked-in files); the tests (tests/openscad_imports.rs) only read them.
set -eu
cd "$(dirname "$0")"
grep -v '^#' cases.txt | while IFS="$(printf '\t')" read -r name stmt; do
    printf '%s\n' "$stmt" > ".$name.scad"
    openscad -q -o "$name.csg" ".$name.scad" </dev/null
    rm -f ".$name.scad"
    openscad -q -o "$name.off" "$name.csg" </dev/null
done
openscad --version 2>&1 | head -1 > VERSION
