//! The voxel stores of seed 000 Ch. 7 side by side (`crates/sculpt/src/octree`, `docs/octree.md`): build
//! time, nodes and bytes of the optimized hash-based octree (§4.3.4), the plain hash-based
//! octree (§4.3.3), the pointer-based octree as the thesis builds it (§4.3.2, §4.2.2), a
//! stronger pointer octree (`pointer-block`) and a dense grid, and global Marching Cubes from
//! each (§3.1.2, Table 7.2), on a sphere, Table 7.1's cube and `twelve.csg`.
//!
//! `cargo bench --features bench --bench octree` (256³ and 512³, median of 3) or `cargo bench
//! --features bench --bench octree -- --quick` (128³ and 256³, one run); `--json` prints every figure as one JSON object.
//! Each volume is voxelized once (not timed here); every store is then built from its
//! slices in order of z, as the voxelizer hands them over, one thread. Times are the
//! thread's own CPU time (`clock_gettime(CLOCK_THREAD_CPUTIME_ID)`, kernel time such as page
//! faults included; wall time if the clock fails), so that other processes on a shared
//! machine do not count; wall times are in the JSON. Ratios are against both pointer
//! octrees measured in the same run. "MC" writes into a triangle buffer kept from an untimed
//! first run (a renderer's triangle list); "MC cold" into a new vector, as
//! `octree::mc::marching_cubes` does. The shared part of the three octree builds (cell
//! layers, and the pyramid that decides every node, with a merge that keeps nothing) is
//! timed on its own.

use std::time::Instant;

use csgpix::openscad::parse_csg;
use csgpix::sculpt::octree::build::{Merge, Pyramid};
use csgpix::sculpt::octree::cell::CellLayers;
use csgpix::sculpt::octree::hashed;
use csgpix::sculpt::octree::key::Key;
use csgpix::sculpt::octree::mc::marching_cubes;
use csgpix::sculpt::octree::{depth_for, from_volume, StoreKind};
use csgpix::voxel::blist::BlistEval;
use csgpix::voxel::{voxelize, Grid, Route, Sampling, Slicer, SlicerOptions, Volume};
use glam::DVec3;
use rtl_model::Equations;
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

/// This thread's CPU time in seconds (`CLOCK_THREAD_CPUTIME_ID`, exact to the call), if known.
fn cpu_time() -> Option<f64> {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid timespec for clock_gettime to write.
    let ok = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) } == 0;
    ok.then_some(t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9)
}

/// A run's CPU time (wall time without it) and wall time, in seconds.
fn timed<T>(f: impl FnOnce() -> T) -> ((f64, f64), T) {
    let (c0, t0) = (cpu_time(), Instant::now());
    let r = f();
    let wall = t0.elapsed().as_secs_f64();
    let cpu = match (c0, cpu_time()) {
        (Some(a), Some(b)) => b - a,
        _ => wall,
    };
    ((cpu, wall), r)
}

/// Median CPU and wall times of `n` runs of `f` (seconds) and the last run's result.
fn median<T>(n: usize, mut f: impl FnMut() -> T) -> ((f64, f64), T) {
    let (mut cpu, mut wall) = (vec![], vec![]);
    let mut last = None;
    for _ in 0..n.max(1) {
        let ((c, w), r) = timed(&mut f);
        cpu.push(c);
        wall.push(w);
        last = Some(r);
    }
    let mid = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    ((mid(cpu), mid(wall)), last.expect("at least one run"))
}

/// A merge that keeps nothing: the pyramid's own work, shared by the three octrees.
struct Nothing;

impl Merge for Nothing {
    type Node = u16;

    fn leaf(&mut self, v: u8) -> u16 {
        v.into()
    }

    fn leaf_value(n: &u16) -> Option<u8> {
        hashed::leaf_value(*n)
    }

    fn internal(&mut self, _: Key, _: [u16; 8]) -> csgpix::sculpt::Result<u16> {
        Ok(hashed::MIXED)
    }
}

/// CPU times of the shared part of the octree builds: cell layers alone, and cell layers
/// with the pyramid.
fn shared_part(v: &Volume, runs: usize) -> Value {
    let depth = depth_for(v.dims).expect("depth");
    let n = (v.dims[0] * v.dims[1]).max(1);
    let ((cells, _), _) = median(runs, || {
        let mut c = CellLayers::new(1 << depth);
        for s in v.voxels.chunks(n) {
            std::hint::black_box(c.next(s, v.dims[0]));
        }
    });
    let ((both, _), internal) = median(runs, || {
        let mut c = CellLayers::new(1 << depth);
        let mut p = Pyramid::new(depth, Nothing);
        for s in v.voxels.chunks(n) {
            p.push_cells(c.next(s, v.dims[0])).expect("layer");
        }
        for _ in v.dims[2]..1 << depth {
            p.push_cells(c.next_empty()).expect("layer");
        }
        p.finish().expect("root").2
    });
    json!({"cells_s": cells, "cells_and_pyramid_s": both, "internal_nodes": internal})
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
    // The thesis's slab sampling, under which docs/octree.md and docs/sculpting.md were measured.
    let slicer = Slicer::new(
        &scene,
        grid,
        SlicerOptions {
            sampling: Sampling::Slab,
            ..SlicerOptions::default()
        },
    )
    .expect("slicer");
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
    let ((build, build_wall), store) =
        median(runs, || from_volume(kind, v, BUDGET).expect("store"));
    let ((mc_cold, _), mesh) = median(runs, || marching_cubes(store.as_ref()));
    let mut tris = Vec::new();
    store.marching_cubes_into(&mut tris);
    let ((mc, mc_wall), ()) = median(runs, || store.marching_cubes_into(&mut tris));
    assert_eq!(tris.len(), mesh.triangles.len(), "{}", kind.name());
    let (n, b) = (store.node_count(), store.bytes());
    json!({
        "store": kind.name(),
        "nodes": n,
        "internal_nodes": store.internal_count(),
        "bytes": b,
        "bytes_per_node": b as f64 / n.max(1) as f64,
        "bytes_per_solid_voxel": b as f64 / solid.max(1) as f64,
        "build_s": build,
        "build_wall_s": build_wall,
        "mc_s": mc,
        "mc_wall_s": mc_wall,
        "mc_cold_s": mc_cold,
        "triangles": mesh.triangles.len(),
    })
}

/// Ratios of every store against both pointer octrees of the same run.
fn with_ratios(mut rows: Vec<Value>) -> Vec<Value> {
    let find = |name: &str| {
        rows.iter()
            .find(|r| r["store"] == name)
            .cloned()
            .unwrap_or(Value::Null)
    };
    let (ptr, blk) = (find("pointer"), find("pointer-block"));
    let f = |v: &Value, k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    for r in &mut rows {
        for (base, suffix) in [(&ptr, "pointer"), (&blk, "pointer_block")] {
            for (time, what) in [
                ("build_s", "build"),
                ("mc_s", "mc"),
                ("mc_cold_s", "mc_cold"),
            ] {
                r[format!("{what}_speedup_vs_{suffix}")] = json!(f(base, time) / f(r, time));
            }
        }
        r["bytes_vs_pointer"] = json!(f(r, "bytes") / f(&ptr, "bytes"));
        r["nodes_vs_pointer"] = json!(f(r, "nodes") / f(&ptr, "nodes"));
    }
    rows
}

fn print_rows(scene: &str, res: usize, solid: usize, vox_s: f64, shared: &Value, rows: &[Value]) {
    println!("\n{scene} {res}³: {solid} solid voxels (voxelized in {vox_s:.3} s)");
    println!(
        "shared part of the octree builds: cell layers {:.4} s, with the pyramid {:.4} s",
        shared["cells_s"].as_f64().unwrap_or(0.0),
        shared["cells_and_pyramid_s"].as_f64().unwrap_or(0.0)
    );
    println!(
        "{:<13} {:>9} {:>11} {:>6} {:>8} {:>7} {:>7} {:>7} {:>7} {:>7} {:>8} {:>7} {:>7} {:>9}",
        "store",
        "nodes",
        "bytes",
        "B/node",
        "build s",
        "×ptr",
        "×blk",
        "MC s",
        "×ptr",
        "×blk",
        "MCcold s",
        "×ptr",
        "×blk",
        "triangles"
    );
    let f = |r: &Value, k: &str| r[k].as_f64().unwrap_or(0.0);
    for r in rows {
        println!(
            "{:<13} {:>9} {:>11} {:>6.2} {:>8.4} {:>7.2} {:>7.2} {:>7.4} {:>7.2} {:>7.2} {:>8.4} {:>7.2} {:>7.2} {:>9}",
            r["store"].as_str().unwrap_or(""),
            r["nodes"],
            r["bytes"],
            f(r, "bytes_per_node"),
            f(r, "build_s"),
            f(r, "build_speedup_vs_pointer"),
            f(r, "build_speedup_vs_pointer_block"),
            f(r, "mc_s"),
            f(r, "mc_speedup_vs_pointer"),
            f(r, "mc_speedup_vs_pointer_block"),
            f(r, "mc_cold_s"),
            f(r, "mc_cold_speedup_vs_pointer"),
            f(r, "mc_cold_speedup_vs_pointer_block"),
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
            let shared = shared_part(&v, runs);
            if !as_json {
                print_rows(s.name, res, solid, vox_s, &shared, &rows);
            }
            out.push(json!({"scene": s.name, "res": res, "solid_voxels": solid,
                "voxelize_s": vox_s, "shared_build": shared, "stores": rows}));
        }
    }
    if as_json {
        let all = json!({"quick": quick, "runs": runs, "time": "thread CPU time, median",
            "results": out});
        println!("{}", serde_json::to_string_pretty(&all).unwrap_or_default());
    }
}
