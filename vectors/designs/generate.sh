#!/bin/sh
# Regenerate the reference outputs of the real-world designs (see README.md): for each design,
# OpenSCAD's CSG export (meshes/NAME.csg, gzipped when over 200 kB) and OpenSCAD's own CGAL
# mesh of that export (meshes/NAME.off.gz). The wall time of the mesh step goes to meshes/times.tsv
# (name, seconds, status: ok, timeout or fail:RC). Needs `openscad` (Debian's 2021.01 made
# the checked-in files) and the fonts the designs name for text(): Liberation (fonts-liberation2), Roboto
# (fonts-roboto) and Inter (fonts-inter). OpenSCAD also sees the fonts bundled in vectors/fonts
# (OPENSCAD_FONT_PATH, read by its FontCache), the ones csgpix finds without system fonts.
# fridge-magnet-letters asks for "Ubuntu Bold:style=bold": no font has the family "Ubuntu Bold"
# (the Ubuntu font's Bold face is family "Ubuntu", style "Bold"), so fontconfig gives OpenSCAD
# its fallback, DejaVu Sans Bold, even with the Ubuntu font installed; csgpix refuses it.
#
# Designs named bosl2-* include BOSL2 (BSD-2-Clause, not copied here): put a checkout of
# BelfrySCAD/BOSL2 at the commit given in README.md in a folder named BOSL2 inside a folder
# on OPENSCADPATH. Designs named mcad-* and openscad-example023 `use` MCAD from OpenSCAD's
# installed library folder (Debian: /usr/share/openscad/libraries/MCAD, package openscad-mcad).
# LIMIT (seconds, default 900) bounds each openscad run; every run is `nice -n 10`.
#
#   sh generate.sh              # every design
#   sh generate.sh NAME...      # only these (their rows of times.tsv are replaced)
#   LIMIT=300 OPENSCADPATH=/path/to/libs sh generate.sh bosl2-gears
set -eu
cd "$(dirname "$0")"
here=$(pwd)
OPENSCAD_FONT_PATH="$(cd ../fonts && pwd)${OPENSCAD_FONT_PATH:+:$OPENSCAD_FONT_PATH}"
export OPENSCAD_FONT_PATH
mkdir -p meshes
limit=${LIMIT:-900}
tab=$(printf '\t')
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

now() {
    t=$(date +%s.%N)
    case "$t" in *N) date +%s ;; *) printf '%s\n' "$t" ;; esac
}

if [ "$#" -gt 0 ]; then
    names="$*"
else
    names=$( { ls -- *.scad 2>/dev/null | sed 's/\.scad$//'; \
               ls -d -- */main.scad 2>/dev/null | sed 's#/main\.scad$##'; } | sort)
fi

[ -f meshes/times.tsv ] || printf 'name\tseconds\tstatus\n' > meshes/times.tsv

for name in $names; do
    if [ -f "$name.scad" ]; then
        src=$name.scad
    elif [ -f "$name/main.scad" ]; then
        src=$name/main.scad
    else
        echo "generate.sh: no design $name" >&2
        exit 1
    fi
    rm -f "meshes/$name.csg" "meshes/$name.csg.gz" "meshes/$name.off" "meshes/$name.off.gz"

    # CSG export (the tree as OpenSCAD evaluates it). Absolute output paths: OpenSCAD 2021.01
    # writes a relative CSG output path relative to the design's own directory.
    # `$preview = false`: the tree OpenSCAD renders (F6, STL export), not the one it previews
    # (a CSG export alone evaluates `$preview` as true, so a design's `if ($preview)`
    # assembly view would be compared with the printed parts of the mesh below).
    if ! nice -n 10 timeout "$limit" openscad -q -D '$preview=false' -o "$here/meshes/$name.csg" "$src" </dev/null 2>"$tmp/err"; then
        echo "generate.sh: $name: CSG export failed" >&2
        cat "$tmp/err" >&2
    fi
    # The mesh is made from that export, so both are one evaluation of the design (a design
    # drawing with rands() without a seed differs run to run): the export is read beside
    # the design so its relative file names resolve, with the design's own directory among
    # the font directories (the export has lost its `use <x.ttf>` lines).
    dir=$(dirname "$src")
    cp "meshes/$name.csg" "$dir/.$name.mesh.csg" 2>/dev/null || true

    # CGAL mesh, timed
    start=$(now)
    status=ok
    OPENSCAD_FONT_PATH="$(cd "$dir" && pwd):$OPENSCAD_FONT_PATH" \
    nice -n 10 timeout "$limit" openscad -q -o "$here/meshes/$name.off" "$dir/.$name.mesh.csg" </dev/null 2>"$tmp/err" || {
        rc=$?
        if [ "$rc" -eq 124 ]; then status=timeout; else status="fail:$rc"; fi
    }
    end=$(now)
    rm -f "$dir/.$name.mesh.csg"
    if [ -f "meshes/$name.csg" ] && [ "$(wc -c < "meshes/$name.csg")" -gt 204800 ]; then
        gzip -9n "meshes/$name.csg"
    fi
    secs=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')
    if [ "$status" = ok ] && [ ! -s "meshes/$name.off" ]; then status=fail:empty; fi
    if [ "$status" != ok ]; then
        echo "generate.sh: $name: mesh $status after ${secs}s" >&2
        cat "$tmp/err" >&2
        rm -f "meshes/$name.off"
    else
        gzip -9n "meshes/$name.off"
    fi

    grep -v "^$name$tab" meshes/times.tsv > "$tmp/times" || true
    printf '%s\t%s\t%s\n' "$name" "$secs" "$status" >> "$tmp/times"
    { head -n 1 "$tmp/times"; tail -n +2 "$tmp/times" | sort; } > meshes/times.tsv
    echo "$name	$secs	$status"
done
