//! The voxel stores of seed 000 Ch. 7 side by side (`src/octree`, `docs/octree.md`): build
//! time, nodes and bytes of the optimized hash-based octree (§4.3.4), the plain hash-based
//! octree (§4.3.3), the pointer-based octree (§4.3.2) and a dense grid, and global Marching
//! Cubes from each (§3.1.2, Table 7.2), on a sphere, Table 7.1's cube and `twelve.csg`.
//!
//! `cargo bench --bench octree` (256³ and 512³, median of 3) or `cargo bench --bench octree
//! -- --quick` (128³ and 256³, one run); `--json` prints every figure as one JSON object.
//! Each volume is voxelized once (not timed here); every store is then built from its
//! slices in order of z, as the voxelizer hands them over, one thread. Ratios are against
//! the pointer-based octree measured in the same run.

use std::time::Instant;

use csgpix::blist::BlistEval;
use csgpix::octree::mc::marching_cubes;
use csgpix::octree::{from_volume, StoreKind};
use csgpix::scad::parse_csg;
use csgpix::voxelize::{voxelize, Grid, Route, Slicer, Volume};
use glam::DVec3;
use rtl_model::{Equations, WordFormat};
use serde_json::{json, Value};

/// Store budget: the bench's largest store is far below it.
const BUDGET: u64 = 16 << 30;

/// Thesis's sphere had 4800 triangles; `$fn = 70` gives 35 rings, 4896 triangles.
const SPHERE: &str = "sphere($fn = 70, r = 10);";
const CUBE: &str = include_str!("../vectors/scenes/table-7.1-cube.csg");
const TWELVE: &str = include_str!("../vectors/scenes/twelve.csg");

/// A scene and how its grid is laid: `Some(h)` for the box ±h (one empty voxel around a
/// solid of radius 10: h = 10·N/(N − 2.5)), `None` for the scene's bounds.
struct Scene {
    name: &'static str,
    text: &'static str,
    padded: bool,
}

const SCENES: [Scene; 3] = [
    Scene {
        name: "sphere",
        text: SPHERE,
        padded: true,
    },
    Scene {
        name: "cube",
        text: CUBE,
        padded: true,
    },
    Scene {
        name: "twelve",
        text: TWELVE,
        padded: false,
    },
];

/// Median wall time of `n` runs of `f` (seconds) and the last run's result.
fn median<T>(n: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut times = Vec::with_capacity(n);
    let mut last = None;
    for _ in 0..n.max(1) {
        let t0 = Instant::now();
        let r = f();
        times.push(t0.elapsed().as_secs_f64());
        last = Some(r);
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], last.expect("at least one run"))
}

fn volume(s: &Scene, res: usize) -> (Volume, f64) {
    let scene = parse_csg(s.text, s.name).expect("scene parses");
    let grid = if s.padded {
        let h = 10.0 * res as f64 / (res as f64 - 2.5);
        Grid::new([res; 3], DVec3::splat(-h), DVec3::splat(h))
    } else {
        Grid::of_scene(&scene, [res; 3])
    }
    .expect("grid");
    let slicer = Slicer::new(&scene, grid, WordFormat::THESIS).expect("slicer");
    let eval = BlistEval::new(&scene.root);
    let t0 = Instant::now();
    let (v, _) = voxelize(
        &slicer,
        Route::Intervals,
        Equations::Derived.set(),
        &eval,
        &|| {},
    )
    .expect("voxelize");
    (v, t0.elapsed().as_secs_f64())
}

/// One store's figures.
fn measure(kind: StoreKind, v: &Volume, runs: usize, solid: usize) -> Value {
    let (build, store) = median(runs, || from_volume(kind, v, BUDGET).expect("store"));
    let (mc, mesh) = median(runs, || marching_cubes(store.as_ref()));
    let (n, b) = (store.node_count(), store.bytes());
    json!({
        "store": kind.name(),
        "nodes": n,
        "internal_nodes": store.internal_count(),
        "bytes": b,
        "bytes_per_node": b as f64 / n.max(1) as f64,
        "bytes_per_solid_voxel": b as f64 / solid.max(1) as f64,
        "build_s": build,
        "mc_s": mc,
        "triangles": mesh.triangles.len(),
    })
}

/// Ratios of every store against the pointer octree of the same run.
fn with_ratios(mut rows: Vec<Value>) -> Vec<Value> {
    let ptr = rows
        .iter()
        .find(|r| r["store"] == "pointer")
        .cloned()
        .unwrap_or(Value::Null);
    let f = |v: &Value, k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    for r in &mut rows {
        r["build_speedup_vs_pointer"] = json!(f(&ptr, "build_s") / f(r, "build_s"));
        r["mc_speedup_vs_pointer"] = json!(f(&ptr, "mc_s") / f(r, "mc_s"));
        r["bytes_vs_pointer"] = json!(f(r, "bytes") / f(&ptr, "bytes"));
        r["nodes_vs_pointer"] = json!(f(r, "nodes") / f(&ptr, "nodes"));
    }
    rows
}

fn print_rows(scene: &str, res: usize, solid: usize, vox_s: f64, rows: &[Value]) {
    println!("\n{scene} {res}³: {solid} solid voxels (voxelized in {vox_s:.3} s)");
    println!(
        "{:<8} {:>10} {:>9} {:>12} {:>7} {:>7} {:>9} {:>9} {:>9} {:>9} {:>10}",
        "store",
        "nodes",
        "internal",
        "bytes",
        "B/node",
        "B/solid",
        "build s",
        "build ×",
        "MC s",
        "MC ×",
        "triangles"
    );
    for r in rows {
        println!(
            "{:<8} {:>10} {:>9} {:>12} {:>7.2} {:>7.3} {:>9.4} {:>9.2} {:>9.4} {:>9.2} {:>10}",
            r["store"].as_str().unwrap_or(""),
            r["nodes"],
            r["internal_nodes"],
            r["bytes"],
            r["bytes_per_node"].as_f64().unwrap_or(0.0),
            r["bytes_per_solid_voxel"].as_f64().unwrap_or(0.0),
            r["build_s"].as_f64().unwrap_or(0.0),
            r["build_speedup_vs_pointer"].as_f64().unwrap_or(0.0),
            r["mc_s"].as_f64().unwrap_or(0.0),
            r["mc_speedup_vs_pointer"].as_f64().unwrap_or(0.0),
            r["triangles"],
        );
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.iter().any(|a| a == "--quick");
    let as_json = args.iter().any(|a| a == "--json");
    let (sizes, runs) = if quick {
        (vec![128, 256], 1)
    } else {
        (vec![256, 512], 3)
    };
    let mut out = vec![];
    for res in sizes {
        for s in &SCENES {
            let (v, vox_s) = volume(s, res);
            let solid = v.voxels.iter().filter(|&&c| c != 0).count();
            let rows = StoreKind::ALL
                .iter()
                .map(|&k| measure(k, &v, runs, solid))
                .collect();
            let rows = with_ratios(rows);
            if !as_json {
                print_rows(s.name, res, solid, vox_s, &rows);
            }
            out.push(json!({"scene": s.name, "res": res, "solid_voxels": solid,
                "voxelize_s": vox_s, "stores": rows}));
        }
    }
    if as_json {
        let all = json!({"quick": quick, "runs": runs, "results": out});
        println!("{}", serde_json::to_string_pretty(&all).unwrap_or_default());
    }
}
