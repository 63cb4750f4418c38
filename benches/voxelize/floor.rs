//! The floor: what producing an N³ volume costs at the least on this machine, against which
//! each route's whole run is measured, in the same run, for the scenes of [`SCENES`].
//!
//! * floor: allocate N³ bytes and write every one (`vec![0u8; n]`, then each Z-slice filled
//!   with its index, slices over rayon's pool as `voxelize` writes its volume), plus writing
//!   them as an NRRD file, every byte (`nrrd::write_volume` into a `BufWriter<File>`, in a
//!   temporary directory; no fsync, as the command does none).
//! * each route of [`floor_routes`](super::floor_routes): `Slicer::new` + `voxelize` with
//!   the Blist evaluator (the command's default options: centre sampling, the scene's
//!   imports loaded) + the NRRD file as `csgpix voxelize` writes it: its 4 KiB blocks of
//!   zeros left as holes (`csgpix_output::Sparse`), the same bytes read back.
//! * the peers (fidget), dense and pruned, built from the parsed scene and written as the
//!   routes are (their membership, 1 inside): for scenes without imports only, as the
//!   peer's expression has no datasets or meshes.
//!
//! Every figure is the median of [`runs_at`] runs, each component (allocation, voxelizing,
//! writing) its own median and the total the median of the runs' totals. Volumes are dropped
//! as soon as they are written: at 1024³ each is 1 GiB.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

use csgpix::scene::grid::Grid;
use csgpix::voxel::blist::BlistEval;
use csgpix::voxel::sampled::{load_scene, Loaded};
use csgpix::voxel::{voxelize, Route, Slicer, SlicerOptions};
use rayon::prelude::*;
use rtl_model::Equations;
use serde_json::{json, Map, Value};

use super::pruned::pruned_eval;
use super::{dense_eval, floor_routes, peer_build};

/// The scenes, in `vectors/scenes/`: figure-5.6.csg imports `phantom.nrrd` beside it.
pub const SCENES: [&str; 3] = ["twelve.csg", "csg-logo.csg", "figure-5.6.csg"];

/// What the floor section is asked for.
pub struct FloorArgs<'a> {
    pub sizes: &'a [usize],
    pub quick: bool,
    /// The pruned peer's cell sides.
    pub cells: &'a [usize],
    /// Whether to run the dense peer too (`--no-dense` leaves it out: about 200 s at 1024³).
    pub dense: bool,
    pub say: &'a dyn Fn(String),
}

/// Runs per figure at N³: one in quick mode; one at 1024³ and above, where three of every
/// figure (the dense peer alone takes about 100 s a run there) would take the section past
/// five minutes; three otherwise.
pub fn runs_at(n: usize, quick: bool) -> usize {
    if quick || n >= 1024 {
        1
    } else {
        3
    }
}

/// The floor section: every scene at every size, as one JSON object.
pub fn floor(a: &FloorArgs) -> Value {
    let dir = tempfile::tempdir().expect("temporary directory");
    let out = dir.path().join("volume.nrrd");
    let runs: Map<String, Value> = a
        .sizes
        .iter()
        .map(|&n| (n.to_string(), json!(runs_at(n, a.quick))))
        .collect();
    (a.say)(format!(
        "floor: sizes {:?}, runs per size {}, pruned peer cells {:?}",
        a.sizes,
        Value::Object(runs.clone()),
        a.cells
    ));
    let mut scenes = Map::new();
    for name in SCENES {
        scenes.insert(name.to_string(), scene_figures(a, name, &out));
    }
    json!({"sizes": a.sizes, "runs": runs, "pruned_cells": a.cells, "scenes": scenes})
}

pub fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("vectors/scenes")
        .join(name)
}

/// One scene at every size.
fn scene_figures(a: &FloorArgs, name: &str, out: &Path) -> Value {
    let path = scene_path(name);
    let loaded = load_scene(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
    let scene = &loaded.scene;
    // The peer's expression is built from convex solids' face planes only.
    let peer = scene.imports.is_empty();
    if !peer {
        (a.say)(format!(
            "floor {name}: peer skipped ({} import(s): the peer's expression has no datasets \
             or meshes)",
            scene.imports.len()
        ));
    }
    let smallest = a.sizes.iter().copied().min();
    let mut sizes = Map::new();
    for &n in a.sizes {
        let figures = size_figures(a, &loaded, name, n, out, peer && Some(n) == smallest);
        sizes.insert(n.to_string(), figures);
    }
    json!({
        "path": format!("vectors/scenes/{name}"),
        "solids": scene.solids.len(),
        "imports": scene.imports.len(),
        "peer": if peer { "measured" } else { "skipped: the scene imports a dataset or mesh" },
        "sizes": sizes,
    })
}

/// One scene at N³: the floor, every route, and the peers when `loaded` has no imports;
/// `compare`: also count the voxels where the pruned peer differs from the dense one.
fn size_figures(
    a: &FloorArgs,
    loaded: &Loaded,
    name: &str,
    n: usize,
    out: &Path,
    compare: bool,
) -> Value {
    let runs = runs_at(n, a.quick);
    let grid = loaded.grid([n; 3]).expect("grid");
    let comment = format!("csgpix voxelize vectors/scenes/{name}");
    let write = |v: &[u8]| write_nrrd(out, &grid, v, &comment, Blocks::Sparse);
    let ([fill, written, floor], ()) = medians(runs, || {
        let (t_fill, v) = timed(|| filled(&grid));
        let t_write = write_nrrd(out, &grid, &v, &comment, Blocks::Every);
        ([t_fill, t_write, t_fill + t_write], ())
    });
    let say = |s: String| (a.say)(format!("floor {name} {n}^3: {s}"));
    say(format!(
        "alloc+fill {fill:.4} s + write {written:.4} s = floor {floor:.4} s ({})",
        runs_text(runs)
    ));
    let peers = loaded
        .scene
        .imports
        .is_empty()
        .then(|| peer_figures(a, loaded, &grid, runs, compare, &write, &say));
    let pruned_s = peers
        .as_ref()
        .map(|p| p["pruned"]["total_s"].as_f64().unwrap_or(f64::NAN));
    let mut routes = Map::new();
    for (route_name, route) in floor_routes() {
        let ([vox, wr, total], ()) = medians(runs, || {
            let (t, v) = route_volume(loaded, &grid, route);
            let t_write = write(&v);
            ([t, t_write, t + t_write], ())
        });
        let vs_peer = pruned_s.map(|p| total / p);
        say(format!(
            "{route_name}: {total:.4} s (slicer+voxelize {vox:.4} + write {wr:.4}) = {:.2}x floor{}",
            total / floor,
            vs_peer.map_or(String::new(), |r| format!(", {r:.3}x the pruned peer"))
        ));
        routes.insert(
            route_name.to_string(),
            json!({
                "voxelize_s": vox,
                "write_s": wr,
                "write": "blocks of zeros as holes",
                "total_s": total,
                "over_floor": total / floor,
                "over_pruned_peer": vs_peer,
            }),
        );
    }
    json!({
        "runs": runs,
        "voxels": n * n * n,
        "floor": {"alloc_fill_s": fill, "write_s": written, "total_s": floor, "write": "every byte"},
        "routes": routes,
        "peer": peers,
    })
}

/// The dense and the pruned peer at `grid`: build + evaluate, write, and their ratio.
fn peer_figures(
    a: &FloorArgs,
    loaded: &Loaded,
    grid: &Grid,
    runs: usize,
    compare: bool,
    write: &dyn Fn(&[u8]) -> f64,
    say: &dyn Fn(String),
) -> Value {
    let scene = &loaded.scene;
    // The last run's volume is kept only when compared (at the smallest size).
    let peer = |eval: &dyn Fn() -> Vec<u8>| {
        medians(runs, || {
            let (t, v) = timed(eval);
            let t_write = write(&v);
            ([t, t_write, t + t_write], if compare { v } else { vec![] })
        })
    };
    let (dense, dense_v) = match a.dense {
        true => peer(&|| dense_eval(&peer_build(scene).0, grid)),
        false => ([f64::NAN; 3], vec![]),
    };
    let (pruned, pruned_v) = peer(&|| pruned_eval(&peer_build(scene).0, grid, a.cells));
    let differing = (compare && a.dense).then(|| {
        let differ = dense_v.iter().zip(&pruned_v).filter(|(x, y)| x != y);
        differ.count()
    });
    let [n, ..] = grid.dims;
    say(format!(
        "peer dense {:.4} s (build+eval {:.4} + write {:.4}), pruned {:.4} s \
         (build+eval {:.4} + write {:.4}), pruned/dense {:.3}{}",
        dense[2],
        dense[0],
        dense[1],
        pruned[2],
        pruned[0],
        pruned[1],
        pruned[2] / dense[2],
        differing.map_or(String::new(), |d| format!("; {d} voxels differ"))
    ));
    if let Some(d) = differing {
        assert_eq!(d, 0, "{n}^3: the pruned peer differs from the dense one");
    }
    let part = |t: [f64; 3]| json!({"eval_s": t[0], "write_s": t[1], "total_s": t[2]});
    json!({
        "dense": part(dense),
        "pruned": part(pruned),
        "pruned_over_dense": pruned[2] / dense[2],
        "pruned_vs_dense_differing": differing,
    })
}

/// N³ bytes allocated and every one written: each Z-slice filled with its index, slices in
/// parallel (a memset each, the cheapest write of every byte).
pub fn filled(grid: &Grid) -> Vec<u8> {
    let [nx, ny, nz] = grid.dims;
    let mut v = vec![0u8; nx * ny * nz];
    v.par_chunks_mut(nx * ny)
        .enumerate()
        .for_each(|(k, s)| s.fill(k as u8));
    std::hint::black_box(v)
}

/// The route's volume as `csgpix voxelize` makes it (default options, the imports loaded,
/// the Blist evaluator) and the seconds from `Slicer::new` to the volume. The imports' clone
/// and the evaluator are made before the clock starts, as the command builds them before its
/// own.
fn route_volume(loaded: &Loaded, grid: &Grid, route: Route) -> (f64, Vec<u8>) {
    let opts = SlicerOptions {
        sampled: loaded.sampled.clone(),
        ..SlicerOptions::default()
    };
    let eval = BlistEval::new(&loaded.scene.root);
    let t0 = Instant::now();
    let slicer = Slicer::new(&loaded.scene, *grid, opts).expect("slicer");
    let (v, _) =
        voxelize(&slicer, route, Equations::Derived.set(), &eval, &|| {}).expect("voxelize");
    (t0.elapsed().as_secs_f64(), v.voxels)
}

/// How an NRRD file's blocks are written.
#[derive(Clone, Copy)]
enum Blocks {
    /// Every byte: the floor.
    Every,
    /// Blocks of zeros left as holes, as `csgpix voxelize` writes its file.
    Sparse,
}

/// Seconds to write `voxels` as an NRRD file at `path`, which is then removed (so its dirty
/// pages do not pile up across runs).
fn write_nrrd(path: &Path, grid: &Grid, voxels: &[u8], comment: &str, blocks: Blocks) -> f64 {
    let t0 = Instant::now();
    match blocks {
        Blocks::Every => write_every_byte(path, grid, voxels, comment),
        Blocks::Sparse => {
            let mut file = File::create(path).expect("create the NRRD file");
            // csgpix voxelize's shortest hole (crates/run/src/voxelize/outputs.rs).
            let mut w = csgpix::output::Sparse::new(&mut file, 1 << 20).expect("the NRRD file");
            csgpix::scene::nrrd::write_volume(&mut w, grid, voxels, comment)
                .expect("write the NRRD file");
            w.finish().expect("finish the NRRD file");
        }
    }
    let t = t0.elapsed().as_secs_f64();
    std::fs::remove_file(path).expect("remove the NRRD file");
    t
}

/// `voxels` as an NRRD file at `path`, every byte, through a `BufWriter`, and closed: the
/// floor's write.
pub fn write_every_byte(path: &Path, grid: &Grid, voxels: &[u8], comment: &str) {
    let mut w = BufWriter::new(File::create(path).expect("create the NRRD file"));
    csgpix::scene::nrrd::write_volume(&mut w, grid, voxels, comment).expect("write the NRRD file");
    w.flush().expect("flush the NRRD file");
}

/// `f`'s seconds and result.
fn timed<T>(f: impl FnOnce() -> T) -> (f64, T) {
    let t0 = Instant::now();
    let r = f();
    (t0.elapsed().as_secs_f64(), r)
}

/// Each component's median over `runs` runs of `f` (seconds), and the last run's result.
fn medians<const K: usize, T>(runs: usize, mut f: impl FnMut() -> ([f64; K], T)) -> ([f64; K], T) {
    let mut all = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs.max(1) {
        // The previous run's result is dropped first: at 1024³ it is 1 GiB.
        drop(last.take());
        let (t, r) = f();
        all.push(t);
        last = Some(r);
    }
    let median = |c: usize| {
        let mut v: Vec<f64> = all.iter().map(|t: &[f64; K]| t[c]).collect();
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    (std::array::from_fn(median), last.expect("at least one run"))
}

fn runs_text(runs: usize) -> String {
    if runs == 1 {
        "one run".into()
    } else {
        format!("median of {runs}")
    }
}

/// One summary line per scene and size of the section's JSON.
pub fn summary(floor: &Value) -> Vec<String> {
    let mut lines = vec![];
    let Some(scenes) = floor["scenes"].as_object() else {
        return lines;
    };
    for (name, scene) in scenes {
        let Some(sizes) = scene["sizes"].as_object() else {
            continue;
        };
        for (n, f) in sizes {
            lines.push(format!("summary floor {name} {n}^3: {}", size_summary(f)));
        }
    }
    lines
}

fn size_summary(f: &Value) -> String {
    let s = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    let mut line = format!(
        "floor {:.3} s ({});",
        s(&f["floor"]["total_s"]),
        runs_text(f["runs"].as_u64().unwrap_or(0) as usize)
    );
    if let Some(routes) = f["routes"].as_object() {
        for (route, r) in routes {
            line += &format!(
                " {route} {:.3} s = {:.2}x floor",
                s(&r["total_s"]),
                s(&r["over_floor"])
            );
            if let Some(p) = r["over_pruned_peer"].as_f64() {
                line += &format!(" = {p:.3}x pruned peer");
            }
            line += ";";
        }
    }
    let p = &f["peer"];
    if p.is_null() {
        return line + " peer skipped (imports)";
    }
    line + &format!(
        " peer dense {:.3} s, pruned {:.3} s (pruned/dense {:.3})",
        s(&p["dense"]["total_s"]),
        s(&p["pruned"]["total_s"]),
        s(&p["pruned_over_dense"])
    )
}
