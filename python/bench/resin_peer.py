"""The slicer peer of `csgpix print`: the pipeline resin-printer users run instead of csgpix.
OpenSCAD meshes the design (CGAL), PrusaSlicer 2.5 slices the mesh into the Original Prusa
SL1's archive; csgpix slices the CSG scene itself into the same archive.

    cargo build --release --bin csgpix
    apt-get install prusa-slicer python3-numpy python3-pil      # Debian 12: PrusaSlicer 2.5.0
    /usr/bin/python3 python/bench/resin_peer.py --limit 12
    /usr/bin/python3 python/bench/resin_peer.py --designs openscad-example002,usb-cap --json

For every design (default: every design `accepted` in vectors/designs/ledger.tsv with both a
cached CSG export, vectors/designs/meshes/NAME.csg or NAME.csg.gz (gunzipped to a temporary
file), and OpenSCAD's CGAL mesh, meshes/NAME.off.gz; `--designs a,b,c` to choose them,
`--limit N` for the first N):

- csgpix route: the wall time of the whole process
  `csgpix print NAME.csg -o c.sl1 --aa 1 --json` (SL1 profile, 1 sample per pixel: a pixel
  is lit iff its centre is inside), and its peak RSS (one more run under `/usr/bin/time -f %M`).
- PrusaSlicer route: the OFF mesh is converted to a binary STL by this script (not timed;
  polygons triangulated by fan), then the wall time of the whole process
  `prusa-slicer --export-sla --load prusa-sl1.ini --supports-enable=0 --pad-enable=0
  --gamma-correction=0 mesh.stl -o p.sl1` (gamma 0 = anti-aliasing off, AGG coverage
  thresholded at 128) and its peak RSS (one more run under /usr/bin/time). prusa-sl1.ini
  (next to this script) is the SL1 profile bundle flattened: printer "Original Prusa SL1",
  print "0.05 Normal", material "Prusa Orange Tough @0.05" (0.05 mm layers, first 0.05 mm).
  Both tools centre the part's XY box on the display and put its bottom on the platform.
- OpenSCAD mesh time: with `--openscad`, `openscad -o mesh.stl DESIGN.scad` run in the
  design's folder in this run (once; OPENSCAD_FONT_PATH as in vectors/designs/generate.sh);
  the bosl2-* designs are skipped there (BOSL2 is not installed) and use the cached figure.
  Otherwise (and for those) the figure is meshes/times.tsv's: the wall time of
  `openscad -o NAME.off NAME.csg` (CGAL on the CSG export), taken with `nice -n 10` on a
  loaded 2-core machine (vectors/designs/README.md) -- marked "c" in the table.

Columns of the table (times are the best of 3 runs, one run when the first takes over 30 s):
  design
  layers c/p: layer PNGs in csgpix's / PrusaSlicer's archive
  min IoU, mean IoU: per-layer IoU of the masks (pixel >= 128) of the two AA-off archives,
    layers matched by index (a layer missing on one side is empty there; two empty layers
    count 1). The JSON's iou_min_common is the minimum over the layers both sides hold.
  csgpix s, prusa s: wall time of the whole process
  prusa/csgpix: PrusaSlicer s / csgpix s (above 1: csgpix is faster)
  openscad s: OpenSCAD's mesh time (suffix c: the cached times.tsv figure)
  (os+prusa)/csgpix: the mesh-then-slice pipeline (OpenSCAD + PrusaSlicer) over csgpix
  csgpix MiB, prusa MiB: peak RSS
  AA |dgrey|: with anti-aliasing on both sides (csgpix `--aa 4`: grey = round(255 *
    inside/16); PrusaSlicer gamma 1, the profile's default: grey = AGG area coverage), the
    mean absolute grey difference over the pixels lit (> 0) on either side, all layers
    (reported, no target; one untimed run each).
Medians are over the designs measured on both sides. Designs csgpix or PrusaSlicer refuse
(e.g. csgpix exits 2 with "does not fit" the SL1 display) are listed with the reason and
not counted. For the worst layer of every design the JSON holds a diagnosis: lit pixels,
pixels lit on one side only, the lit bounding boxes (PNG rows/columns), the shift of the lit
pixels' centroid, the best IoU when csgpix's mask is shifted by up to 2 pixels or so that the
lit boxes' corners meet, and the IoU against csgpix's mask mirrored.

`--json` prints every figure as JSON on stdout instead of the table (`--table-from FILE` prints
the table of such a file). Progress goes to stderr.
If numpy or Pillow is missing, or PrusaSlicer is not installed, the script says so and exits
0 (the peer is optional). Installing Debian's prusa-slicer brings the Noto fonts, which
fontconfig then prefers for sans-serif bold: the text designs of tests/designs.rs leave their
ledger on such a machine, and fridge-magnet-letters is drawn in another font than its cached
mesh. `dpkg --remove --force-depends fonts-noto-core fonts-noto-hinted fonts-noto-ui-core`
after the install removes them and keeps prusa-slicer (`apt-get remove` takes it too).
"""

import argparse
import gzip
import io
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import zipfile
from pathlib import Path

from processes import best_of, run_timed

ROOT = Path(__file__).resolve().parents[2]
DESIGNS = ROOT / "vectors/designs"
MESHES = DESIGNS / "meshes"
INI = Path(__file__).resolve().parent / "prusa-sl1.ini"
LAYER_H = 0.05  # the SL1 profile's layer height and initial layer height, mm
LAYER_RE = re.compile(r"^[^/]*?(\d{5})\.png$")


# ---------------------------------------------------------------- processes


def last_line(text, code):
    """The last meaningful stderr line (PrusaSlicer's progress and trace lines skipped)."""
    lines = [l.strip() for l in text.strip().splitlines() if l.strip()]
    keep = [l for l in lines if "=>" not in l and "[trace]" not in l and "[info]" not in l]
    return (keep or lines or [f"exit {code}"])[-1][:300]


# ---------------------------------------------------------------- meshes


def off_to_stl(off_gz, stl_path):
    """OpenSCAD's OFF (gzipped) to a binary STL (float32); polygons fanned. Triangle count."""
    import numpy as np

    text = gzip.decompress(Path(off_gz).read_bytes()).decode("ascii", "replace")
    lines = [l.split("#", 1)[0].split() for l in text.splitlines()]
    lines = [l for l in lines if l]
    if not lines or not lines[0][0].endswith("OFF"):
        raise ValueError(f"{off_gz}: not an OFF file")
    if len(lines[0]) > 1:  # "OFF nv nf ne" on one line (OpenSCAD) or "OFF" then the counts
        counts, body = lines[0][1:], lines[1:]
    else:
        counts, body = lines[1], lines[2:]
    nv, nf = int(counts[0]), int(counts[1])
    verts = np.array([l[:3] for l in body[:nv]], dtype=np.float64).reshape(nv, 3)
    tris = []
    for l in body[nv:nv + nf]:  # "n i0 i1 ... [colour]": a fan from i0
        n = int(l[0])
        idx = [int(x) for x in l[1:1 + n]]
        tris += [(idx[0], idx[k], idx[k + 1]) for k in range(1, n - 1)]
    t = np.asarray(tris, dtype=np.int64).reshape(-1, 3)
    rec = np.zeros(len(t), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["v"] = verts[t].astype(np.float32)
    a, b, c = verts[t[:, 0]], verts[t[:, 1]], verts[t[:, 2]]
    nrm = np.cross(b - a, c - a)
    ln = np.linalg.norm(nrm, axis=1, keepdims=True)
    rec["n"] = (nrm / np.where(ln > 0, ln, 1)).astype(np.float32)
    with open(stl_path, "wb") as f:
        f.write(b"resin_peer: OpenSCAD OFF".ljust(80, b" "))
        f.write(np.uint32(len(t)).tobytes())
        f.write(rec.tobytes())
    lo, hi = verts.min(axis=0) if nv else None, verts.max(axis=0) if nv else None
    return len(t), (None if lo is None else [lo.tolist(), hi.tolist()])


# ---------------------------------------------------------------- archives


def layer_names(z):
    """Layer PNGs of an SL1 archive by index (thumbnails and inis skipped)."""
    out = {}
    for n in z.namelist():
        m = LAYER_RE.match(n)
        if m:
            out[int(m.group(1))] = n
    return out


def read_layer(z, name):
    import numpy as np
    from PIL import Image

    im = Image.open(io.BytesIO(z.read(name)))
    if im.mode != "L":
        im = im.convert("L")
    return np.asarray(im)


def bbox(mask):
    import numpy as np

    rows = np.flatnonzero(mask.any(axis=1))
    if len(rows) == 0:
        return None
    cols = np.flatnonzero(mask.any(axis=0))
    return [int(rows[0]), int(rows[-1]), int(cols[0]), int(cols[-1])]


def iou(a, b):
    import numpy as np

    union = int(np.count_nonzero(a | b))
    if union == 0:
        return 1.0
    return int(np.count_nonzero(a & b)) / union


def shifted(m, dr, dc):
    import numpy as np

    out = np.zeros_like(m)
    h, w = m.shape
    out[max(dr, 0):h + min(dr, 0), max(dc, 0):w + min(dc, 0)] = \
        m[max(-dr, 0):h + min(-dr, 0), max(-dc, 0):w + min(-dc, 0)]
    return out


def diagnose(a, b, layer, n):
    """What the masks of the worst layer look like: a = csgpix, b = PrusaSlicer."""
    import numpy as np

    d = {
        "layer": layer,
        "z_mm": LAYER_H / 2 if layer == 0 else LAYER_H + (layer - 0.5) * LAYER_H,
        "where": "bottom" if layer < 3 else ("top" if layer >= n - 3 else "mid"),
        "csgpix_lit": int(a.sum()),
        "prusa_lit": int(b.sum()),
        "csgpix_only": int((a & ~b).sum()),
        "prusa_only": int((b & ~a).sum()),
        "csgpix_bbox_rows_cols": bbox(a),
        "prusa_bbox_rows_cols": bbox(b),
    }
    bb = bbox(a | b)
    if bb:
        r0, r1, c0, c1 = max(bb[0] - 3, 0), bb[1] + 4, max(bb[2] - 3, 0), bb[3] + 4
        ca, cb = a[r0:r1, c0:c1], b[r0:r1, c0:c1]
        best = (iou(ca, cb), 0, 0)
        for dr in range(-2, 3):
            for dc in range(-2, 3):
                if dr or dc:
                    v = iou(shifted(ca, dr, dc), cb)
                    if v > best[0]:
                        best = (v, dr, dc)
        d["best_shift_iou"] = best[0]
        d["best_shift_rows_cols"] = [best[1], best[2]]  # csgpix moved by this to match
        ba, bp = d["csgpix_bbox_rows_cols"], d["prusa_bbox_rows_cols"]
        if ba and bp:
            # the lit pixels' centroids (sub-pixel shifts show here) and csgpix's mask moved so
            # that the top-left corners of the two lit boxes meet (whole shifts of any size)
            ra, ca_ = np.nonzero(a)
            rb, cb_ = np.nonzero(b)
            d["centroid_shift_rows_cols"] = [float(rb.mean() - ra.mean()), float(cb_.mean() - ca_.mean())]
            dr, dc = bp[0] - ba[0], bp[2] - ba[2]
            d["bbox_aligned_shift_rows_cols"] = [dr, dc]
            d["bbox_aligned_iou"] = iou(shifted(a, dr, dc), b)
        d["iou_csgpix_mirrored_cols"] = iou(a[:, ::-1], b)
        d["iou_csgpix_mirrored_rows"] = iou(a[::-1, :], b)
        # which rows / columns hold the one-sided pixels
        diff = a ^ b
        rs = np.flatnonzero(diff.any(axis=1))
        cs = np.flatnonzero(diff.any(axis=0))
        d["diff_rows"] = [int(rs[0]), int(rs[-1])] if len(rs) else None
        d["diff_cols"] = [int(cs[0]), int(cs[-1])] if len(cs) else None
    return d


def compare_masks(c_path, p_path):
    """Per-layer IoU of the masks (>= 128) of two archives; the worst layer diagnosed."""
    import numpy as np

    with zipfile.ZipFile(c_path) as zc, zipfile.ZipFile(p_path) as zp:
        lc, lp = layer_names(zc), layer_names(zp)
        n = max(max(lc, default=-1), max(lp, default=-1)) + 1
        ious = []
        inter_sum = union_sum = 0
        worst = None
        empty = None
        for l in range(n):
            a = read_layer(zc, lc[l]) >= 128 if l in lc else None
            b = read_layer(zp, lp[l]) >= 128 if l in lp else None
            if a is None:
                a = np.zeros_like(b)
            if b is None:
                b = np.zeros_like(a)
            if a.shape != b.shape:
                raise ValueError(f"layer {l}: image {a.shape[::-1]} vs {b.shape[::-1]}")
            inter = int(np.count_nonzero(a & b))
            union = int(np.count_nonzero(a | b))
            v = inter / union if union else 1.0
            ious.append(v)
            inter_sum += inter
            union_sum += union
            if worst is None or v < worst[0]:
                worst = (v, l)
                worst_masks = (a, b)
        res = {
            "layers_csgpix": len(lc),
            "layers_prusa": len(lp),
            "iou_min": min(ious) if ious else None,
            "iou_mean": statistics.fmean(ious) if ious else None,
            "iou_all_layers": inter_sum / union_sum if union_sum else 1.0,
            # layers both archives hold (a layer-count difference left out)
            "iou_min_common": min((v for l, v in enumerate(ious) if l in lc and l in lp), default=None),
            "layers_below_0.99": sum(1 for v in ious if v < 0.99),
            "layers_below_0.99_first": [l for l, v in enumerate(ious) if v < 0.99][:20],
        }
        if worst is not None:
            res["worst"] = diagnose(worst_masks[0], worst_masks[1], worst[1], n)
            res["worst"]["iou"] = worst[0]
        return res


def compare_grey(c_path, p_path):
    """Mean |grey difference| over the pixels lit (> 0) on either side, all layers."""
    import numpy as np

    with zipfile.ZipFile(c_path) as zc, zipfile.ZipFile(p_path) as zp:
        lc, lp = layer_names(zc), layer_names(zp)
        n = max(max(lc, default=-1), max(lp, default=-1)) + 1
        total = 0
        count = 0
        for l in range(n):
            a = read_layer(zc, lc[l]) if l in lc else None
            b = read_layer(zp, lp[l]) if l in lp else None
            if a is None:
                a = np.zeros_like(b)
            if b is None:
                b = np.zeros_like(a)
            lit = (a > 0) | (b > 0)
            count += int(lit.sum())
            total += int(np.abs(a[lit].astype(np.int32) - b[lit].astype(np.int32)).sum())
        return {"aa_mean_abs_grey_diff": total / count if count else 0.0, "aa_lit_pixels": count}


# ---------------------------------------------------------------- designs


def ledger_accepted():
    rows = (DESIGNS / "ledger.tsv").read_text().splitlines()[1:]
    return [r.split("\t")[0] for r in rows if len(r.split("\t")) > 1 and r.split("\t")[1] == "accepted"]


def cached_times():
    out = {}
    for r in (MESHES / "times.tsv").read_text().splitlines()[1:]:
        f = r.split("\t")
        if len(f) >= 3:
            try:
                out[f[0]] = (float(f[1]), f[2])
            except ValueError:
                pass
    return out


def scene_file(name):
    for s in (".csg", ".csg.gz"):
        if (MESHES / (name + s)).exists():
            return MESHES / (name + s)
    return None


def design_source(name):
    if (DESIGNS / f"{name}.scad").exists():
        return DESIGNS / f"{name}.scad"
    if (DESIGNS / name / "main.scad").exists():
        return DESIGNS / name / "main.scad"
    return None


def fmt(x, nd=3):
    return "—" if x is None else f"{x:.{nd}f}"


def bench_design(name, args, work, times):
    row = {"design": name}
    src = scene_file(name)
    off = MESHES / f"{name}.off.gz"
    if src is None or not off.exists():
        row["skipped"] = "no cached .csg(.gz) or .off.gz"
        return row
    scene = src
    if src.name.endswith(".gz"):
        scene = work / f"{name}.csg"
        with gzip.open(src, "rb") as f, open(scene, "wb") as g:
            shutil.copyfileobj(f, g)
    d = work / name
    d.mkdir()
    c_sl1, p_sl1 = d / "c.sl1", d / "p.sl1"
    c_aa, p_aa = d / "ca.sl1", d / "pa.sl1"
    try:
        # 1. csgpix
        cjson = d / "c.json"
        cmd = [str(args.csgpix), "print", str(scene), "-o", str(c_sl1), "--aa", "1", "--json"]

        def run_c():
            w, _, code, err = run_timed(cmd, stdout_path=cjson)
            if code != 0:
                msg = last_line(err, code)
                row["skipped"] = (msg if msg.startswith("csgpix:") else "csgpix: " + msg) + f" (exit {code})"
                return None
            return (w,)

        b = best_of(run_c)
        if b is None:
            return row
        row["csgpix_s"] = b[0]
        rep = json.loads(cjson.read_text())
        row["csgpix_report"] = {k: rep.get(k) for k in
                                ("layers", "wall_seconds", "memory_estimate", "material_ml",
                                 "part_pixels", "part_origin", "warnings")}
        row["csgpix_rss_mib"] = run_timed(cmd[:-1], rss=True)[1]

        # 2. the mesh
        stl = d / "mesh.stl"
        try:
            row["mesh_triangles"], row["mesh_bounds"] = off_to_stl(off, stl)
        except (ValueError, IndexError) as e:
            row["skipped"] = f"OFF: {e}"
            return row
        if row["mesh_triangles"] == 0:
            row["skipped"] = "OpenSCAD's mesh is empty"
            return row

        # 3. PrusaSlicer
        pcmd = [args.prusa, "--export-sla", "--load", str(args.ini), "--supports-enable=0",
                "--pad-enable=0", "--gamma-correction=0", str(stl), "-o", str(p_sl1)]

        def run_p():
            w, _, code, err = run_timed(pcmd, cwd=d)
            if code != 0 or not p_sl1.exists():
                row["skipped"] = "prusa-slicer: " + last_line(err, code) + f" (exit {code})"
                return None
            return (w,)

        b = best_of(run_p)
        if b is None:
            return row
        row["prusa_s"] = b[0]
        row["prusa_rss_mib"] = run_timed(pcmd, rss=True, cwd=d)[1]
        row["ratio_prusa_csgpix"] = row["prusa_s"] / row["csgpix_s"]

        # 4. OpenSCAD
        cached = times.get(name)
        row["openscad_cached_s"] = cached[0] if cached and cached[1] == "ok" else None
        if args.openscad:
            dsrc = design_source(name)
            if name.startswith("bosl2-"):
                row["openscad_note"] = "BOSL2 not installed: cached times.tsv figure"
            elif dsrc is None:
                row["openscad_note"] = "no design source: cached times.tsv figure"
            else:
                env = dict(os.environ)
                fonts = [str(dsrc.parent), str(ROOT / "vectors/fonts")]
                if env.get("OPENSCAD_FONT_PATH"):
                    fonts.append(env["OPENSCAD_FONT_PATH"])
                env["OPENSCAD_FONT_PATH"] = ":".join(fonts)
                w, r, code, err = run_timed(["openscad", "-q", "-o", str(d / "os.stl"), dsrc.name],
                                            cwd=dsrc.parent, env=env, rss=True)
                if code == 0 and (d / "os.stl").exists():
                    row["openscad_s"] = w
                    row["openscad_rss_mib"] = r
                else:
                    row["openscad_note"] = "openscad failed: " + last_line(err, code) + \
                        "; cached times.tsv figure"
        if "openscad_s" in row:
            row["openscad_source"] = "run"
        elif row["openscad_cached_s"] is not None:
            row["openscad_s"] = row["openscad_cached_s"]
            row["openscad_source"] = "times.tsv"
        if row.get("openscad_s") is not None:
            row["ratio_pipeline_csgpix"] = (row["openscad_s"] + row["prusa_s"]) / row["csgpix_s"]

        # 5. the masks
        try:
            row.update(compare_masks(c_sl1, p_sl1))
        except (ValueError, KeyError, OSError) as e:
            row["compare_error"] = str(e)
        c_sl1.unlink(missing_ok=True)
        p_sl1.unlink(missing_ok=True)
        if not args.no_aa:
            w, _, code, err = run_timed([str(args.csgpix), "print", str(scene), "-o", str(c_aa),
                                         "--aa", "4"])
            w2, _, code2, err2 = run_timed([args.prusa, "--export-sla", "--load", str(args.ini),
                                            "--supports-enable=0", "--pad-enable=0", str(stl),
                                            "-o", str(p_aa)], cwd=d)
            row["csgpix_aa4_s"] = w
            row["prusa_aa_s"] = w2
            if code == 0 and code2 == 0 and p_aa.exists():
                try:
                    row.update(compare_grey(c_aa, p_aa))
                except (ValueError, KeyError, OSError) as e:
                    row["aa_error"] = str(e)
            else:
                row["aa_error"] = (f"csgpix --aa 4: {last_line(err, code)}" if code else
                                   f"prusa-slicer gamma 1: {last_line(err2, code2)}")
        return row
    finally:
        shutil.rmtree(d, ignore_errors=True)
        if scene != src:
            scene.unlink(missing_ok=True)


def measured(r):
    return "skipped" not in r and "prusa_s" in r and r.get("iou_min") is not None


def medians_of(rows):
    ok = [r for r in rows if measured(r)]
    keys = ["iou_min", "iou_mean", "csgpix_s", "prusa_s", "ratio_prusa_csgpix", "openscad_s",
            "ratio_pipeline_csgpix", "csgpix_rss_mib", "prusa_rss_mib", "aa_mean_abs_grey_diff"]
    out = {"designs": len(ok)}
    for k in keys:
        v = [r[k] for r in ok if r.get(k) is not None]
        out[k] = statistics.median(v) if v else None
    return out


def summary_line(r):
    if "skipped" in r:
        return f"{r['design']}: skipped: {r['skipped']}"
    return (f"{r['design']}: layers {r.get('layers_csgpix')}/{r.get('layers_prusa')} "
            f"IoU min {fmt(r.get('iou_min'), 4)} mean {fmt(r.get('iou_mean'), 4)} "
            f"csgpix {fmt(r.get('csgpix_s'))} s prusa {fmt(r.get('prusa_s'))} s "
            f"openscad {fmt(r.get('openscad_s'), 1)} s ({r.get('openscad_source')}) "
            f"AA |dgrey| {fmt(r.get('aa_mean_abs_grey_diff'), 2)}"
            + (f" compare_error: {r['compare_error']}" if "compare_error" in r else "")
            + (f" aa_error: {r['aa_error']}" if "aa_error" in r else ""))


def print_table(rows, med):
    head = ["design", "layers c/p", "min IoU", "mean IoU", "csgpix s", "prusa s", "prusa/csgpix",
            "openscad s", "(os+prusa)/csgpix", "csgpix MiB", "prusa MiB", "AA |dgrey|"]
    lines = [head]
    for r in rows:
        if not measured(r):
            continue
        os_s = r.get("openscad_s")
        os_txt = "—" if os_s is None else f"{os_s:.1f}" + ("c" if r.get("openscad_source") == "times.tsv" else "")
        lines.append([r["design"], f"{r['layers_csgpix']}/{r['layers_prusa']}", fmt(r["iou_min"], 4),
                      fmt(r["iou_mean"], 4), fmt(r["csgpix_s"], 2), fmt(r["prusa_s"], 2),
                      fmt(r["ratio_prusa_csgpix"], 2), os_txt, fmt(r.get("ratio_pipeline_csgpix"), 2),
                      fmt(r.get("csgpix_rss_mib"), 0), fmt(r.get("prusa_rss_mib"), 0),
                      fmt(r.get("aa_mean_abs_grey_diff"), 2)])
    lines.append(["median", f"({med['designs']})", fmt(med["iou_min"], 4), fmt(med["iou_mean"], 4),
                  fmt(med["csgpix_s"], 2), fmt(med["prusa_s"], 2), fmt(med["ratio_prusa_csgpix"], 2),
                  fmt(med["openscad_s"], 1), fmt(med["ratio_pipeline_csgpix"], 2),
                  fmt(med["csgpix_rss_mib"], 0), fmt(med["prusa_rss_mib"], 0),
                  fmt(med["aa_mean_abs_grey_diff"], 2)])
    w = [max(len(l[i]) for l in lines) for i in range(len(head))]
    for k, l in enumerate(lines):
        print(" | ".join(s.ljust(w[i]) if i == 0 else s.rjust(w[i]) for i, s in enumerate(l)))
        if k == 0 or k == len(lines) - 2:
            print("-+-".join("-" * x for x in w))
    print("openscad s: suffix c = meshes/times.tsv (CGAL on the CSG export, nice -n 10, loaded machine); "
          "otherwise measured in this run")
    skipped = [r for r in rows if not measured(r)]
    if skipped:
        print("\nnot counted:")
        for r in skipped:
            print(f"  {r['design']}: {r.get('skipped') or r.get('compare_error') or 'not measured'}")
    low = [r for r in rows if measured(r) and r["iou_min"] < 0.99]
    if low:
        print("\nmin IoU < 0.99 (worst layer):")
        for r in low:
            w_ = r.get("worst", {})
            print(f"  {r['design']}: layer {w_.get('layer')} ({w_.get('where')}, z {fmt(w_.get('z_mm'))} mm) "
                  f"IoU {fmt(w_.get('iou'), 4)}; lit c/p {w_.get('csgpix_lit')}/{w_.get('prusa_lit')}, "
                  f"only c/p {w_.get('csgpix_only')}/{w_.get('prusa_only')}; bbox rows,cols c "
                  f"{w_.get('csgpix_bbox_rows_cols')} p {w_.get('prusa_bbox_rows_cols')}; best shift "
                  f"{w_.get('best_shift_rows_cols')} -> {fmt(w_.get('best_shift_iou'), 4)}"
                  + (f", box-aligned {w_['bbox_aligned_shift_rows_cols']} -> {fmt(w_['bbox_aligned_iou'], 4)}"
                     f", centroid shift p-c {[round(x, 2) for x in w_['centroid_shift_rows_cols']]}"
                     if "bbox_aligned_iou" in w_ else "")
                  + f"; {r.get('layers_below_0.99')} layers < 0.99; min IoU over common layers "
                  f"{fmt(r.get('iou_min_common'), 4)}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--designs", default="", help="comma-separated design names (default: the ledger's)")
    ap.add_argument("--limit", type=int, default=0, help="only the first N designs")
    ap.add_argument("--openscad", action="store_true", help="also time openscad on the design in this run")
    ap.add_argument("--no-aa", action="store_true", help="skip the anti-aliased grey comparison")
    ap.add_argument("--json", action="store_true", help="print every figure as JSON instead of the table")
    ap.add_argument("--csgpix", type=Path, default=ROOT / "target/release/csgpix")
    ap.add_argument("--prusa", default=shutil.which("prusa-slicer") or "/usr/bin/prusa-slicer")
    ap.add_argument("--ini", type=Path, default=INI, help="flattened SL1 profile for --load")
    ap.add_argument("--table-from", type=Path, metavar="JSON",
                    help="print the table of an earlier --json output; nothing run")
    args = ap.parse_args()
    if args.table_from:
        report = json.loads(args.table_from.read_text())
        print_table(report["rows"], report["medians"])
        return 0
    try:
        import numpy  # noqa: F401
        import PIL  # noqa: F401
    except ImportError as e:
        print(f"resin_peer: {e}; the slicer peer needs numpy and Pillow (Debian: "
              "apt-get install python3-numpy python3-pil, then run it with /usr/bin/python3). "
              "Nothing measured.")
        return 0
    if not Path(args.prusa).exists():
        print(f"resin_peer: {args.prusa} missing; the slicer peer needs PrusaSlicer 2.5 "
              "(Debian: apt-get install prusa-slicer). Nothing measured.")
        return 0
    if not args.csgpix.exists():
        print(f"resin_peer: {args.csgpix} missing: cargo build --release --bin csgpix", file=sys.stderr)
        return 2
    if args.designs:
        names = [n.strip() for n in args.designs.split(",") if n.strip()]
    else:
        names = [n for n in ledger_accepted()
                 if scene_file(n) is not None and (MESHES / f"{n}.off.gz").exists()]
    if args.limit:
        names = names[:args.limit]
    times = cached_times()
    rows = []
    load_start = os.getloadavg()
    t0 = time.time()
    with tempfile.TemporaryDirectory(prefix="resin_peer.") as tmp:
        work = Path(tmp)
        for n in names:
            row = bench_design(n, args, work, times)
            rows.append(row)
            print(summary_line(row), file=sys.stderr, flush=True)
    med = medians_of(rows)
    if args.json:
        pv = subprocess.run([args.prusa, "--help"], capture_output=True, text=True).stdout.splitlines()
        report = {
            "date": time.strftime("%Y-%m-%d %H:%M:%S %Z"),
            "nproc": os.cpu_count(),
            "loadavg_start_end": [load_start, os.getloadavg()],
            "total_seconds": time.time() - t0,
            "prusaslicer": pv[0] if pv else None,
            "csgpix": str(args.csgpix),
            "ini": str(args.ini),
            "openscad_run": args.openscad,
            "medians": med,
            "rows": rows,
        }
        print(json.dumps(report, indent=1))
    else:
        print_table(rows, med)
    return 0


if __name__ == "__main__":
    sys.exit(main())
