#!/bin/sh
# Regenerate the surface() cases: the PNG images (made here by python3's zlib, no imaging
# library), then for each line of cases.txt OpenSCAD's CSG export (NAME.csg) of the statement,
# written beside the .dat and .png files for the time of the run, and, from that file, its own
# CGAL mesh (NAME.off). Needs python3 and the `openscad` binary (Debian's openscad 2021.01 made
# the checked-in files); the tests (tests/openscad_surface.rs) only read them.
set -eu
cd "$(dirname "$0")"
python3 - <<'PY'
import struct, zlib

def png(name, w, h, colour, depth, rows, palette=None):
    """Writes a PNG of `rows` (bytes of each scanline, unfiltered)."""
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    raw = b"".join(b"\0" + bytes(r) for r in rows)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, colour, 0, 0, 0))
    if palette:
        out += chunk(b"PLTE", bytes(palette))
    out += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(name, "wb").write(out)

# 8-bit grey, 12 x 9: a ramp with ripples.
png("grey.png", 12, 9, 0, 8,
    [[(x * 20 + y * 13 + (x * y) % 7 * 9) % 256 for x in range(12)] for y in range(9)])
# 8-bit RGB, 10 x 8: each channel its own pattern, so the weights of the grey matter.
png("rgb.png", 10, 8, 2, 8,
    [sum(([(x * 25) % 256, (y * 31 + x * 7) % 256, (x * y * 11) % 256] for x in range(10)), [])
     for y in range(8)])
# 8-bit palette of 5 colours, 8 x 6, index 9 past the palette (black, as lodepng draws it).
pal = [0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 200, 200, 200]
png("palette.png", 8, 6, 3, 8, [[9 if (x, y) == (3, 2) else (x + 2 * y) % 5 for x in range(8)]
                               for y in range(6)], pal)
# 16-bit grey, 9 x 7: high and low bytes differ (lodepng keeps the high one).
png("grey16.png", 9, 7, 0, 16,
    [sum(([(x * 29 + y * 17) % 256, (x * 101 + y * 53) % 256] for x in range(9)), [])
     for y in range(7)])
PY
grep -v '^#' cases.txt | while IFS="$(printf '\t')" read -r name stmt; do
    printf '%s\n' "$stmt" > ".$name.scad"
    openscad -q -o "$name.csg" ".$name.scad" </dev/null
    rm -f ".$name.scad"
    openscad -q -o "$name.off" "$name.csg" </dev/null
done
openscad --version 2>&1 | head -1 > VERSION
