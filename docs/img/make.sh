#!/usr/bin/env bash
# Regenerates the pictures of README.md and docs/*.md (docs/img) with csgpix.
#
#   bash docs/img/make.sh              write every checked picture into docs/img
#   bash docs/img/make.sh --out DIR    ... into DIR instead
#   bash docs/img/make.sh --all        also the UNCHECKED (timing) pictures below
#   bash docs/img/make.sh --check      regenerate into a temporary directory and compare each
#                                      checked picture byte for byte with docs/img: prints
#                                      `stale: docs/img/X` for each difference, exits 1 if any
#
# Run from the repository root (tests/pictures.rs runs --check). The binary is
# ${CSGPIX:-target/release/csgpix} (`cargo build --release` first). extrusions.png needs
# `openscad` (a .scad scene) and thesis-grid.png `python3` (it is a montage of twelve renders);
# without them they are skipped, unless CSGPIX_OPENSCAD=require / CSGPIX_PYTHON=require.
#
# Every picture here is deterministic (the plots too: plotters draws with a bundled font, and
# two runs give the same bytes) except the UNCHECKED ones:
#
# UNCHECKED: charts of measured wall time, different on every run; made only with --all, never
# in --check. Commit them only together with the numbers docs/tradeoffs.md quotes from the same
# run.
#   study-cmc-wall.png          (wall.png of) csgpix study vectors/scenes/cube-minus-cylinder.csg
#                                 --sampling slab --models cycle,word,float -o study/cmc
#   study-logo-cycle-wall.png   (wall.png of) csgpix study vectors/scenes/csg-logo.csg
#                                 --sampling slab --models cycle,word --fragments 8,16,32
#                                 --slabs 16,32 -o study/logo-cycle
# EXTERNAL: made with a program this script does not run; kept as committed, never checked.
#   printer-small-knob-layer200.png   layer 200 of `csgpix print small-knob.csg -o c.sl1` beside
#                                     PrusaSlicer 2.5's of OpenSCAD's mesh (`prusa-slicer
#                                     --export-sla`, python/bench/resin_peer.py's command) and
#                                     their difference (docs/printer.md)
# (No checked picture takes more than ~15 s on 2 cores; the longest is the cube-minus-cylinder
# study, which runs the cycle model on 96 points.)
set -euo pipefail

usage() { sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; }

out=docs/img check=0 all=0
while [[ $# -gt 0 ]]; do
    case "$1" in
        --out) out=${2:?--out needs a directory}; shift 2 ;;
        --out=*) out=${1#--out=}; shift ;;
        --check) check=1; shift ;;
        --all) all=1; shift ;;
        -h|--help) usage; exit 0 ;;
        *) echo "make.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
    esac
done
if [[ $check == 1 && $all == 1 ]]; then
    echo "make.sh: --all's pictures depend on timing and cannot be checked" >&2; exit 2
fi

csgpix=${CSGPIX:-target/release/csgpix}
if [[ ! -x $csgpix ]]; then
    echo "make.sh: no csgpix at '$csgpix' (cargo build --release, or set CSGPIX)" >&2; exit 2
fi
if [[ ! -f vectors/thesis/cube.dl || ! -d docs/img ]]; then
    echo "make.sh: run from the repository root" >&2; exit 2
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
gen=$tmp/gen
mkdir -p "$gen" "$tmp/work"

run() {
    if ! "$csgpix" "$@" >"$tmp/log" 2>&1; then
        cat "$tmp/log" >&2
        echo "make.sh: failed: csgpix $*" >&2
        exit 1
    fi
}

# Pictures a missing tool keeps from being made (reported, not compared).
skipped=()
have() {  # have TOOL REQUIRE_VAR PICTURE
    if command -v "$1" >/dev/null 2>&1; then return 0; fi
    if [[ ${!2:-} == require ]]; then
        echo "make.sh: $3 needs $1, which is missing ($2=require)" >&2; exit 1
    fi
    echo "skipped: docs/img/$3 (no $1)" >&2
    skipped+=("$3")
    return 1
}

# --- The checked pictures: name, then the command that makes it --------------------------

CHECKED=()

# README's table and docs/rendering.md: the thesis display lists at 250x250, bit-serial
# array (`cycle`, the default) and exact ray casting (`float`); docs/select-logic.md: the cube
# under the thesis's printed select equations.
thesis() {  # thesis NAME CSGPIX-RENDER-ARGS...
    local name=$1; shift
    CHECKED+=("$name-cycle.png" "$name-float.png")
    run render "$@" -o "$gen/$name-cycle.png"
    run render "$@" --model float -o "$gen/$name-float.png"
}
thesis cube vectors/thesis/cube.dl
thesis box1 vectors/thesis/box1.dl
thesis box1-corrected vectors/thesis/box1-corrected.dl
thesis box2 vectors/thesis/box2.dl
thesis a-not-b vectors/thesis/box1-corrected.dl vectors/thesis/box2.dl --clip 'A.!B'
thesis a-not-b-printed vectors/thesis/box1.dl vectors/thesis/box2.dl --clip 'A.!B'

CHECKED+=(cube-printed.png)
run render vectors/thesis/cube.dl --equations printed -o "$gen/cube-printed.png"

# docs/rendering.md: the six thesis renders side by side, `cycle` above, `float` below
# (250x250 tiles, 5 white pixels after each), composed from the pictures above.
if have python3 CSGPIX_PYTHON thesis-grid.png; then
    CHECKED+=(thesis-grid.png)
    python3 - "$gen" <<'EOF'
import struct, sys, zlib
gen = sys.argv[1]

def load(path):  # 8-bit RGB or indexed, non-interlaced: what csgpix writes
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    i, idat, pal = 8, b"", None
    while i < len(data):
        (n,) = struct.unpack(">I", data[i:i + 4])
        kind, body = data[i + 4:i + 8], data[i + 8:i + 8 + n]
        i += 12 + n
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, inter = struct.unpack(">IIBBBBB", body)
        elif kind == b"PLTE":
            pal = [body[k:k + 3] for k in range(0, len(body), 3)]
        elif kind == b"IDAT":
            idat += body
    assert depth == 8 and inter == 0 and ctype in (2, 3), path
    bpp = 3 if ctype == 2 else 1
    raw, stride, rows, prev, k = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp), 0
    for _ in range(h):
        f, line = raw[k], bytearray(raw[k + 1:k + 1 + stride])
        k += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prev = line
        rows.append(bytes(line) if ctype == 2 else b"".join(pal[v] for v in line))
    return w, h, rows

names = ["cube", "box1", "box1-corrected", "box2", "a-not-b-printed", "a-not-b"]
tile, gap = 250, 5
W, H = len(names) * (tile + gap), 2 * (tile + gap)
canvas = [bytearray(b"\xff" * (3 * W)) for _ in range(H)]
for j, model in enumerate(["cycle", "float"]):
    for i, name in enumerate(names):
        w, h, rows = load(f"{gen}/{name}-{model}.png")
        assert (w, h) == (tile, tile)
        for y, row in enumerate(rows):
            x0 = 3 * i * (tile + gap)
            canvas[j * (tile + gap) + y][x0:x0 + 3 * tile] = row

def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

raw = b"".join(b"\0" + bytes(r) for r in canvas)
with open(f"{gen}/thesis-grid.png", "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
EOF
fi

# docs/microarchitecture.md: the timing diagram of pixel (120,100) of the thesis cube.
CHECKED+=(cube-wave.svg)
run render vectors/thesis/cube.dl --probe 120,100 --wave "$gen/cube-wave.svg" \
    --wave-clocks 0..140 -o "$tmp/work/cube.png"

# README and docs/rendering.md: OpenSCAD scenes, iso, cycle, shaded.
CHECKED+=(csg-logo.png cube-minus-cylinder.png)
run render vectors/scenes/csg-logo.csg --shade -o "$gen/csg-logo.png"
run render vectors/scenes/cube-minus-cylinder.csg --shade -o "$gen/cube-minus-cylinder.png"

# README and docs/voxelization.md: previews (seen along Z, Y, X) at 128³, a slice at 64³.
CHECKED+=(voxel-twelve.png voxel-figure-5.2.png voxel-hollow-cube-slice32.png)
run voxelize vectors/scenes/twelve.csg --res 128x128x128 --preview "$gen/voxel-twelve.png" \
    -o "$tmp/work/twelve.nrrd"
run voxelize vectors/scenes/figure-5.2.csg --res 128x128x128 \
    --preview "$gen/voxel-figure-5.2.png" -o "$tmp/work/fig52.nrrd"
run voxelize vectors/scenes/hollow-cube.csg --res 64x64x64 --slices "$tmp/work/hollow" \
    -o "$tmp/work/hollow.nrrd"
cp "$tmp/work/hollow/slice-0032.png" "$gen/voxel-hollow-cube-slice32.png"

# README and docs/volume-scenes.md: Figure 5.6 at 128³ with --grey, its preview and slice 70.
CHECKED+=(figure-5.6-grey.png figure-5.6-slice.png)
run voxelize vectors/scenes/figure-5.6.csg --res 128x128x128 --grey \
    --preview "$gen/figure-5.6-grey.png" --slices "$tmp/work/head" -o "$tmp/work/head.nrrd"
cp "$tmp/work/head/slice-0070.png" "$gen/figure-5.6-slice.png"

# docs/volume-scenes.md: a .scad scene (read through openscad).
if have openscad CSGPIX_OPENSCAD extrusions.png; then
    CHECKED+=(extrusions.png)
    run voxelize vectors/scenes/extrusions.scad --voxel 0.5 --preview "$gen/extrusions.png" \
        -o "$tmp/work/e.nrrd"
fi

# docs/throughput.md: Figures 2.12 and 5.11 and two scenes' frame rates on panels.
CHECKED+=(figure-2.12.png figure-5.11.png scene-csg-logo-iso.png scene-twelve-top.png)
run throughput --plots "$tmp/work/plots" --scene vectors/scenes/csg-logo.csg
run throughput --plots "$tmp/work/plots" --scene vectors/scenes/twelve.csg --view top
cp "$tmp/work/plots"/{figure-2.12,figure-5.11,scene-csg-logo-iso,scene-twelve-top}.png "$gen/"

# docs/tradeoffs.md: the study's charts (wall.png is UNCHECKED, above).
CHECKED+=(study-cmc-bits.png study-cmc-fragments.png study-cmc-depth.png)
run study vectors/scenes/cube-minus-cylinder.csg --sampling slab --models cycle,word,float \
    -o "$tmp/work/cmc"
CHECKED+=(study-logo-bits.png study-logo-fragments.png study-logo-depth.png)
run study vectors/scenes/csg-logo.csg --sampling slab -o "$tmp/work/logo"
for s in cmc logo; do
    for c in bits fragments depth; do cp "$tmp/work/$s/$c.png" "$gen/study-$s-$c.png"; done
done

# --- The unchecked pictures (--all only) ---------------------------------------------------

UNCHECKED=()
if [[ $all == 1 ]]; then
    UNCHECKED+=(study-cmc-wall.png study-logo-cycle-wall.png)
    cp "$tmp/work/cmc/wall.png" "$gen/study-cmc-wall.png"
    run study vectors/scenes/csg-logo.csg --sampling slab --models cycle,word \
        --fragments 8,16,32 --slabs 16,32 -o "$tmp/work/logo-cycle"
    cp "$tmp/work/logo-cycle/wall.png" "$gen/study-logo-cycle-wall.png"
fi

# --- Write or compare ----------------------------------------------------------------------

for name in "${CHECKED[@]}" "${UNCHECKED[@]}"; do
    [[ -f $gen/$name ]] || { echo "make.sh: $name was not made" >&2; exit 1; }
done

if [[ $check == 0 ]]; then
    mkdir -p "$out"
    for name in "${CHECKED[@]}" "${UNCHECKED[@]}"; do
        cmp -s "$gen/$name" "$out/$name" || echo "wrote: $out/$name"
        cp "$gen/$name" "$out/$name"
    done
    exit 0
fi

stale=0
for name in "${CHECKED[@]}"; do
    if ! cmp -s "$gen/$name" "docs/img/$name"; then
        echo "stale: docs/img/$name"
        stale=1
    fi
done
# Every file in docs/img is either checked, unchecked, skipped, external or this script.
for path in docs/img/*; do
    name=${path#docs/img/}
    case " ${CHECKED[*]} ${skipped[*]:-} make.sh study-cmc-wall.png study-logo-cycle-wall.png printer-small-knob-layer200.png " in
        *" $name "*) ;;
        *) echo "unknown: $path (not made by docs/img/make.sh)"; stale=1 ;;
    esac
done
if [[ $stale == 0 ]]; then
    echo "make.sh: ${#CHECKED[@]} pictures current${skipped[*]:+, skipped: ${skipped[*]}}"
fi
exit $stale
