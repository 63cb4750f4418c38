"""The mesh-boolean peer of `csgpix voxelize` (docs/voxelize-bench.md, "Mesh-boolean peer
(Manifold)"): the pipeline users run instead of csgpix. Manifold (the `manifold3d` binding)
turns the CSG scene into one mesh, which is then voxelized on the same grid.

    cargo build --release --bin csgpix --example scene_meshes
    pip install manifold3d numpy
    python python/bench/manifold_peer.py --res 64,256 --json
    python python/bench/manifold_peer.py --generated 10000   # generated scenes of 10,000 primitives

For every scene (default: every vectors/designs/meshes/*.csg and *.csg.gz, the latter gunzipped
to a temporary file, beside the design's own font files where it ships them (`scene_file`),
plus vectors/scenes/{twelve,csg-logo,figure-5.2}.csg) and every grid:

- csgpix: the wall time of the whole process `csgpix voxelize SCENE --res N -o out.nrrd --json`
  and its peak RSS (one more run under `/usr/bin/time -f %M`).
- Manifold, in a child process of this script (its peak RSS from `/usr/bin/time -f %M`):
  (a) the scene read: `scene_meshes` (examples/scene_meshes.rs, csgpix's own reader printing
      every primitive as a mesh, the tree and the grid box) and `json.loads`: reported, not
      counted, since it stands for the user's own scene reader;
  (b) the mesh step: one `Manifold(mesh=Mesh64(...))` per primitive, the tree evaluated with
      `Manifold.batch_boolean` (union, intersection, difference = head minus the union of
      the tail) and the result's `to_mesh64()`;
  (c) voxelizing the mesh: written as a binary STL (float32) and voxelized by the whole
      process `csgpix voxelize` of a scene `import("mesh.stl");` with `--bounds` the scene's
      grid box and the same `--res`, voxel centres as for the scene (`--sampling centre`).
  Full pipeline = mesh step + voxelize-mesh.
- Agreement: IoU of the two occupancy volumes (voxel != 0), read from the NRRD files.

Times are the best of 3 runs (1 run when the first takes over 30 s). Ratios are Manifold /
csgpix (above 1: csgpix is faster). If `manifold3d` is not importable, the script says so and
exits 0 (the peer is optional).
"""

import argparse
import gzip
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from processes import SLOW, best_of, run_timed

ROOT = Path(__file__).resolve().parents[2]


# ---------------------------------------------------------------- NRRD


def read_nrrd(path):
    """The occupancy (voxel != 0) of a uint8 NRRD csgpix wrote: text header, blank line, raw or
    gzip data; shape (z, y, x)."""
    import numpy as np

    data = Path(path).read_bytes()
    end = data.index(b"\n\n")
    fields = {}
    for line in data[:end].decode().splitlines()[1:]:
        if line.startswith("#") or ":" not in line:
            continue
        k, v = line.split(":", 1)
        fields[k.strip()] = v.strip()
    if fields.get("type") not in ("uint8", "uchar", "unsigned char"):
        raise ValueError(f"{path}: type {fields.get('type')}, not uint8")
    sizes = [int(s) for s in fields["sizes"].split()]
    raw = data[end + 2:]
    if fields.get("encoding") in ("gzip", "gz"):
        raw = gzip.decompress(raw)
    elif fields.get("encoding") != "raw":
        raise ValueError(f"{path}: encoding {fields.get('encoding')}")
    vol = np.frombuffer(raw, dtype=np.uint8, count=sizes[0] * sizes[1] * sizes[2])
    return vol.reshape(sizes[::-1]) != 0


def iou(a, b):
    import numpy as np

    union = int(np.count_nonzero(a | b))
    if union == 0:
        return 1.0
    return int(np.count_nonzero(a & b)) / union


# ---------------------------------------------------------------- the Manifold child


def mesh_step(scene_json, stl_path):
    """In the child: read the scene's JSON, evaluate it with Manifold (best of 3), write the
    result as a binary STL; print the figures as JSON."""
    import numpy as np
    import manifold3d as m3d

    t0 = time.perf_counter()
    scene = json.loads(Path(scene_json).read_text())
    t_parse = time.perf_counter() - t0
    prims = []
    for p in scene["primitives"]:
        v = np.asarray(p["vertices"], dtype=np.float64).reshape(-1, 3)
        t = np.asarray(p["triangles"], dtype=np.uint32).reshape(-1, 3)
        prims.append((np.ascontiguousarray(v), np.ascontiguousarray(t)))
    t_arrays = time.perf_counter() - t0 - t_parse
    nodes = scene["nodes"]
    problems = []

    def evaluate():
        problems.clear()
        leaves = []
        for i, (v, t) in enumerate(prims):
            if len(t) == 0:
                leaves.append(m3d.Manifold())
                continue
            # Manifold needs outward triangles; csgpix does not care about imported meshes'
            # orientation, so turn inside-out ones (negative signed volume) around.
            a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
            if np.einsum("ij,ij->", a, np.cross(b, c)) < 0:
                t = np.ascontiguousarray(t[:, ::-1])
            mesh = m3d.Mesh64(vert_properties=v, tri_verts=t)
            mesh.merge()
            m = m3d.Manifold(mesh=mesh)
            if m.status() != m3d.Error.NoError:
                problems.append(f"primitive {i}: {m.status()}")
            leaves.append(m)
        done = []
        for n in nodes:
            op = n["op"]
            if op == "solid":
                done.append(leaves[n["index"]])
            elif op == "empty":
                done.append(m3d.Manifold())
            elif op == "complement":
                raise ValueError("complement: Manifold has no unbounded solids")
            else:
                kids = [done[k] for k in n["children"]]
                if op == "union":
                    r = m3d.Manifold.batch_boolean(kids, m3d.OpType.Add)
                elif op == "intersection":
                    r = m3d.Manifold.batch_boolean(kids, m3d.OpType.Intersect)
                else:
                    r = m3d.Manifold.batch_boolean(kids, m3d.OpType.Subtract)
                done.append(r)
        result = done[-1]
        out = result.to_mesh64()
        return result, out

    times = []
    for k in range(3):
        t1 = time.perf_counter()
        result, out = evaluate()
        times.append(time.perf_counter() - t1)
        if k == 0 and times[0] > SLOW:
            break
    verts = np.asarray(out.vert_properties)[:, :3]
    tris = np.asarray(out.tri_verts).astype(np.int64)
    write_stl(stl_path, verts, tris)
    print(json.dumps({
        "parse_s": t_parse,
        "arrays_s": t_arrays,
        "mesh_s": min(times),
        "mesh_runs": times,
        "triangles_in": int(sum(len(t) for _, t in prims)),
        "triangles_out": int(len(tris)),
        "status": str(result.status()),
        "problems": problems[:5],
    }))


def write_stl(path, verts, tris):
    import numpy as np

    rec = np.zeros(len(tris), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["v"] = verts[tris].astype(np.float32)
    with open(path, "wb") as f:
        f.write(b"manifold_peer".ljust(80, b" "))
        f.write(np.uint32(len(tris)).tobytes())
        f.write(rec.tobytes())


# ---------------------------------------------------------------- the parent


def default_scenes():
    d = ROOT / "vectors/designs/meshes"
    scenes = sorted(list(d.glob("*.csg")) + list(d.glob("*.csg.gz")), key=lambda p: p.name)
    scenes += [ROOT / f"vectors/scenes/{n}.csg" for n in ("twelve", "csg-logo", "figure-5.2")]
    return scenes


def generated_scenes(counts, work):
    """Scenes of thousands of primitives, written into `work` (issue 41: thousands of primitives):
    for each N, `generated-union-N.csg` (N/2 cubes and N/2 spheres of 12 segments scattered in a
    100-unit box, one union, seed 1) and `generated-holes-N.csg` (a 100×100×4 slab minus N
    cylinders of 8 segments on a square grid). The same N gives the same files."""
    import random

    out = []
    for n in counts:
        rnd = random.Random(1)
        lines = ["union() {"]
        for i in range(n):
            x, y, z = (rnd.uniform(0, 100) for _ in range(3))
            m = f"multmatrix([[1,0,0,{x:.4f}],[0,1,0,{y:.4f}],[0,0,1,{z:.4f}],[0,0,0,1]])"
            prim = "cube(size = [2, 2, 2], center = false);" if i % 2 else "sphere(r = 1.2, $fn = 12);"
            lines.append(f"  {m} {prim}")
        lines.append("}")
        union = work / f"generated-union-{n}.csg"
        union.write_text("\n".join(lines) + "\n")
        side = max(1, round(n ** 0.5))
        pitch = 100.0 / side
        lines = ["difference() {", "  cube(size = [100, 100, 4], center = false);"]
        for i in range(n):
            x, y = (i % side + 0.5) * pitch, (i // side + 0.5) * pitch
            m = f"multmatrix([[1,0,0,{x:.4f}],[0,1,0,{y:.4f}],[0,0,1,-1],[0,0,0,1]])"
            lines.append(f"  {m} cylinder(h = 6, r1 = {pitch / 3:.4f}, r2 = {pitch / 3:.4f}, center = false, $fn = 8);")
        lines.append("}")
        holes = work / f"generated-holes-{n}.csg"
        holes.write_text("\n".join(lines) + "\n")
        out += [union, holes]
    return out


def design_name(p):
    n = p.name
    for s in (".csg.gz", ".csg"):
        if n.endswith(s):
            return n[: -len(s)]
    return n


def scene_file(path, work):
    """The file the bench reads for scene `path`: the file itself, or a copy in a folder of its
    own under `work`, gunzipped, with its design's own font files beside it. A `.csg` has lost
    the `use <x.ttf>` lines of its `.scad`, and csgpix reads the font files in the `.csg`'s
    folder instead (docs/volume-scenes.md, "Fonts"): a design that ships its font
    (vectors/designs/NAME/*.ttf) is then drawn in it, not in fontconfig's substitute."""
    name = design_name(path)
    fonts = []
    if path.parent == ROOT / "vectors/designs/meshes":
        own = ROOT / "vectors/designs" / name
        fonts = sorted(f for f in own.glob("*") if f.suffix.lower() in (".ttf", ".otf"))
    if not fonts and not path.name.endswith(".gz"):
        return path
    folder = work / name
    folder.mkdir(exist_ok=True)
    scene = folder / f"{name}.csg"
    opener = gzip.open if path.name.endswith(".gz") else open
    with opener(path, "rb") as f, open(scene, "wb") as g:
        shutil.copyfileobj(f, g)
    for f in fonts:
        shutil.copy(f, folder / f.name)
    return scene


def fmt(x, nd=3):
    return "—" if x is None else f"{x:.{nd}f}"


def bench_scene(path, resolutions, csgpix, meshes_bin, work):
    name = design_name(path)
    row = {"design": name, "file": str(path.relative_to(ROOT) if path.is_relative_to(ROOT) else path)}
    scene = scene_file(path, work)
    # (a) the scene read: the example and the JSON parse (in the child).
    js = work / f"{name}.json"
    t_read, rss_read, code, err = run_timed([str(meshes_bin), str(scene)], stdout_path=js)
    row["scene_meshes_s"] = t_read
    if code != 0:
        row["error"] = "scene_meshes: " + err.strip().splitlines()[-1] if err.strip() else f"exit {code}"
    else:
        head = json.loads(js.read_text())
        row["primitives"] = len(head["primitives"])
        bounds = head["bounds"]
        del head
    # (b) the mesh step, in a child (its peak RSS).
    stl = work / f"{name}.stl"
    if "error" not in row:
        child = work / f"{name}.child.json"
        wall, rss, code, err = run_timed(
            [sys.executable, __file__, "--mesh-step", str(js), str(stl)], stdout_path=child, rss=True)
        if code != 0:
            last = err.strip().splitlines()[-1] if err.strip() else f"exit {code}"
            row["manifold_error"] = last
        else:
            row.update(json.loads(child.read_text()))
            row["manifold_child_rss_mib"] = rss
    row["grids"] = {}
    for n in resolutions:
        g = {}
        row["grids"][str(n)] = g
        out = work / f"{name}.{n}.nrrd"

        def run_csgpix():
            w, r, c, e = run_timed([str(csgpix), "voxelize", str(scene), "--res", f"{n}x{n}x{n}",
                                    "-o", str(out), "--json"])
            if c != 0:
                g["csgpix_error"] = e.strip().splitlines()[-1] if e.strip() else f"exit {c}"
                return None
            if SUBSTITUTED in e:
                g["font_substituted"] = True
            return w, r

        b = best_of(run_csgpix)
        if b:
            g["csgpix_s"] = b[0]
            g["csgpix_rss_mib"] = run_timed([str(csgpix), "voxelize", str(scene), "--res", f"{n}x{n}x{n}",
                                             "-o", str(out)], rss=True)[1]
        if "mesh_s" not in row:
            continue
        mout = work / f"{name}.{n}.mesh.nrrd"
        if row.get("triangles_out", 0) == 0:
            g["voxelize_mesh_s"] = 0.0
            mesh_occ = None
        else:
            mscene = work / f"{name}.mesh.csg"
            mscene.write_text(f'import("{stl.name}");\n')
            bstr = ",".join(repr(float(x)) for x in bounds[0] + bounds[1])

            def run_mesh():
                w, r, c, e = run_timed([str(csgpix), "voxelize", str(mscene), "--res", f"{n}x{n}x{n}",
                                        "--bounds", bstr, "-o", str(mout), "--json"])
                if c != 0:
                    g["voxelize_mesh_error"] = e.strip().splitlines()[-1] if e.strip() else f"exit {c}"
                    return None
                return w, r

            b = best_of(run_mesh)
            if b:
                g["voxelize_mesh_s"] = b[0]
                g["voxelize_mesh_rss_mib"] = run_timed(
                    [str(csgpix), "voxelize", str(mscene), "--res", f"{n}x{n}x{n}", "--bounds", bstr,
                     "-o", str(mout)], rss=True)[1]
        if "voxelize_mesh_s" in g:
            g["manifold_full_s"] = row["mesh_s"] + g["voxelize_mesh_s"]
        if "csgpix_s" in g and "manifold_full_s" in g:
            g["ratio_full"] = g["manifold_full_s"] / g["csgpix_s"]
            g["ratio_mesh"] = row["mesh_s"] / g["csgpix_s"]
            a = read_nrrd(out)
            bvol = read_nrrd(mout) if row.get("triangles_out", 0) else a & False
            g["iou"] = iou(a, bvol)
            g["csgpix_filled"] = int(a.sum())
            g["manifold_filled"] = int(bvol.sum())
        for f in (out, mout):
            f.unlink(missing_ok=True)
    for f in (js, stl, work / f"{name}.child.json", work / f"{name}.mesh.csg"):
        f.unlink(missing_ok=True)
    if scene != path:
        scene.unlink(missing_ok=True)
    return row


# Issue 41's target: designs whose Manifold mesh takes at least this long (seconds).
SLOW_MESH = 0.05


def floor_s(n, csgpix, work):
    """The floor of a whole `csgpix voxelize` at n³: one cube filling the grid, so the process
    is its start, the n³ volume and its write (best of 3)."""
    scene = work / "floor.csg"
    scene.write_text("cube(size = [1, 1, 1], center = false);\n")
    out = work / "floor.nrrd"
    cmd = [str(csgpix), "voxelize", str(scene), "--res", f"{n}x{n}x{n}", "-o", str(out)]

    def once():
        wall, _, code, _ = run_timed(cmd)
        return (wall,) if code == 0 else None

    b = best_of(once)
    out.unlink(missing_ok=True)
    return b[0] if b else None


# What csgpix's warning says of a `text()` whose font is not installed (text.rs,
# `Fonts::find_or_substitute`): the run drew fontconfig's match after asking `fc-match`, which
# costs milliseconds and draws a face other than the one OpenSCAD's reference mesh has.
SUBSTITUTED = "fontconfig's match"


def target_summary(rows, n, floor):
    """On the designs whose mesh takes at least SLOW_MESH: the median of mesh / csgpix at n³,
    how many are below 1× and 2×, the lowest three, those drawn in a substitute font (their
    times depend on the fonts installed), and the same ratios were every csgpix run at the
    floor (`floor` seconds): the most any whole process writing the volume can show."""
    gs = [(r["design"], r["mesh_s"], r["grids"][str(n)]) for r in rows
          if "vectors/designs/" in r["file"] and r.get("mesh_s", 0) >= SLOW_MESH
          and "ratio_mesh" in r["grids"].get(str(n), {})]
    if not gs:
        return None
    ratios = sorted((g["ratio_mesh"], d) for d, _, g in gs)
    out = {
        "designs": len(gs),
        "median_mesh_over_csgpix": statistics.median(x for x, _ in ratios),
        "below_1x": sum(x < 1 for x, _ in ratios),
        "below_2x": sum(x < 2 for x, _ in ratios),
        "lowest": [[d, x] for x, d in ratios[:3]],
        "font_substituted": [d for d, _, g in gs if g.get("font_substituted")],
    }
    if floor:
        bound = [m / floor for _, m, _ in gs]
        out["floor_s"] = floor
        out["median_mesh_over_floor"] = statistics.median(bound)
        out["below_2x_at_floor"] = sum(x < 2 for x in bound)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scenes", nargs="*", type=Path, help="scenes (default: the designs and three scenes)")
    ap.add_argument("--res", default="64,256", help="grid sides, comma-separated (default 64,256)")
    ap.add_argument("--generated", default="", metavar="N,…",
                    help="also generated scenes of N primitives each (a scattered union and a slab "
                         "with N holes); with no scenes named, only these")
    ap.add_argument("--json", action="store_true", help="print every figure as JSON")
    ap.add_argument("--csgpix", type=Path, default=ROOT / "target/release/csgpix")
    ap.add_argument("--scene-meshes", type=Path, default=ROOT / "target/release/examples/scene_meshes")
    ap.add_argument("--mesh-step", nargs=2, metavar=("SCENE_JSON", "OUT_STL"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.mesh_step:
        mesh_step(*args.mesh_step)
        return 0
    try:
        import manifold3d  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        print(f"manifold_peer: {e}; the Manifold peer is optional: `pip install manifold3d numpy` "
              "to run it. Nothing measured.")
        return 0
    for b in (args.csgpix, args.scene_meshes):
        if not b.exists():
            print(f"manifold_peer: {b} missing: cargo build --release --bin csgpix --example scene_meshes",
                  file=sys.stderr)
            return 2
    resolutions = [int(x) for x in args.res.split(",")]
    counts = [int(x) for x in args.generated.split(",") if x]
    scenes = [p.resolve() for p in args.scenes] or ([] if counts else default_scenes())
    rows = []
    load_start = os.getloadavg()
    with tempfile.TemporaryDirectory(prefix="manifold_peer.") as tmp:
        work = Path(tmp)
        scenes += generated_scenes(counts, work)
        for p in scenes:
            row = bench_scene(p, resolutions, args.csgpix, args.scene_meshes, work)
            rows.append(row)
            print(summary_line(row, resolutions), file=sys.stderr, flush=True)
    medians = {}
    designs = [r for r in rows if "vectors/designs/" in r["file"]]
    for n in resolutions:
        gs = [r["grids"][str(n)] for r in designs if "ratio_full" in r["grids"].get(str(n), {})]
        if gs:
            medians[str(n)] = {
                "designs": len(gs),
                "ratio_full": statistics.median(g["ratio_full"] for g in gs),
                "ratio_mesh": statistics.median(g["ratio_mesh"] for g in gs),
                "iou": statistics.median(g["iou"] for g in gs),
                "iou_min": min(g["iou"] for g in gs),
            }
    targets = {}
    with tempfile.TemporaryDirectory(prefix="manifold_peer.floor.") as tmp:
        for n in resolutions:
            t = target_summary(rows, n, floor_s(n, args.csgpix, Path(tmp)))
            if t:
                targets[str(n)] = t
    report = {
        "date": time.strftime("%Y-%m-%d %H:%M:%S %Z"),
        "nproc": os.cpu_count(),
        "loadavg_start_end": [load_start, os.getloadavg()],
        "manifold3d": manifold_version(),
        "resolutions": resolutions,
        "medians_designs": medians,
        "target": targets,
        "rows": rows,
    }
    print_table(rows, resolutions, medians)
    print_targets(targets)
    if args.json:
        print(json.dumps(report, indent=1))
    return 0


def manifold_version():
    try:
        from importlib.metadata import version

        return version("manifold3d")
    except Exception:
        return None


def summary_line(r, resolutions):
    parts = [r["design"], f"prims={r.get('primitives')}", f"mesh={fmt(r.get('mesh_s'))}"]
    for n in resolutions:
        g = r["grids"].get(str(n), {})
        parts.append(f"{n}: csgpix={fmt(g.get('csgpix_s'))} vox={fmt(g.get('voxelize_mesh_s'))} "
                     f"ratio={fmt(g.get('ratio_full'), 2)} iou={fmt(g.get('iou'), 4)}")
    for k in ("error", "manifold_error"):
        if k in r:
            parts.append(f"{k}: {r[k]}")
    for n in resolutions:
        g = r["grids"].get(str(n), {})
        for k in ("csgpix_error", "voxelize_mesh_error"):
            if k in g:
                parts.append(f"{n} {k}: {g[k]}")
    return "  ".join(parts)


def print_table(rows, resolutions, medians):
    for n in resolutions:
        print(f"\n{n}³: design | primitives | csgpix s | scene read s | Manifold mesh s | voxelize-mesh s "
              "| ratio full | ratio mesh | IoU | csgpix MiB | mesh-step MiB | voxelize-mesh MiB")
        for r in rows:
            g = r["grids"].get(str(n), {})
            read = r.get("scene_meshes_s", 0) + r.get("parse_s", 0) + r.get("arrays_s", 0)
            print(f"{r['design']} | {r.get('primitives', '—')} | {fmt(g.get('csgpix_s'))} | {fmt(read)} | "
                  f"{fmt(r.get('mesh_s'))} | {fmt(g.get('voxelize_mesh_s'))} | "
                  f"{fmt(g.get('ratio_full'), 2)} | {fmt(g.get('ratio_mesh'), 2)} | {fmt(g.get('iou'), 4)} | "
                  f"{fmt(g.get('csgpix_rss_mib'), 0)} | {fmt(r.get('manifold_child_rss_mib'), 0)} | "
                  f"{fmt(g.get('voxelize_mesh_rss_mib'), 0)}")
        if str(n) in medians:
            m = medians[str(n)]
            print(f"median over {m['designs']} designs at {n}³: full {m['ratio_full']:.2f}, "
                  f"mesh step {m['ratio_mesh']:.2f}, IoU {m['iou']:.4f} (min {m['iou_min']:.4f})")


def print_targets(targets):
    for n, t in targets.items():
        low = ", ".join(f"{d} {x:.2f}" for d, x in t["lowest"])
        print(f"\n{n}³, the {t['designs']} designs whose Manifold mesh takes ≥ {SLOW_MESH * 1000:.0f} ms: "
              f"median mesh / csgpix {t['median_mesh_over_csgpix']:.2f}, {t['below_1x']} below 1×, "
              f"{t['below_2x']} below 2× (lowest: {low})")
        if t.get("font_substituted"):
            print(f"  drawn in a substitute font (the font named is not installed; .ci/run installs "
                  f"the designs' fonts), their times with fontconfig's lookup: "
                  f"{', '.join(t['font_substituted'])}")
        if "floor_s" in t:
            print(f"  floor (one cube, the whole process) {t['floor_s']:.3f} s: at the floor the median "
                  f"would be {t['median_mesh_over_floor']:.2f}, {t['below_2x_at_floor']} below 2×")


if __name__ == "__main__":
    sys.exit(main())
