//! Sculpting step latency (seed 000 Ch. 5-6; `crates/sculpt/src/sculpt.rs`, docs/sculpting.md): a spherical
//! tool of R = 4 and 8 voxels carving a groove around a ball, a cube and
//! `vectors/scenes/twelve.csg`, each held in the optimized hash-based octree.
//!
//! `cargo bench --features bench --bench sculpt` (256³ and 512³, 4000 steps) or `-- --quick`
//! (128³ and 256³, 1000 steps); `--json` prints every figure as one JSON object instead of the table. One
//! thread. A step is what the haptic loop would run per tick: collision (key lookups with
//! ancestor fallback), removal, the changed cells' bytes (splitting coarse leaves), local
//! Marching Cubes of those cells and the spring force. Targets: median < 1 ms (1 kHz haptic
//! loop), p99 < 16.7 ms (60 Hz graphics).
//!
//! The path: the tool's centre spirals inwards about the grid's vertical axis in one
//! horizontal plane, 0.5 voxel per step (a stylus at 0.5 voxel/ms), its radius shrinking by
//! R/2 per turn so that every turn carves fresh material. It starts on the ball's and the
//! cube's surface (half the tool in the material where it meets it) in the middle plane, and
//! at 8.6 scene units in z = 2 for `twelve` (the rounded block's faces are at 8). Latency is
//! given over every step and over the carving steps (those that removed a voxel).
//!
//! `literal_nodes_after`: the node count had every coarse leaf that was split been expanded
//! down to the cells (seed 000 §5.2 scenario 2 read literally: 8^(d−L) − 1 more nodes for a
//! leaf at level L), against the split along the path only that sculpting does.

use std::time::Instant;

use csgpix::openscad::parse_csg;
use csgpix::sculpt::octree::{self, optimized::Leaves, OptimizedOctree, VoxelStore};
use csgpix::sculpt::{Frame, Latency, Sculptor, Tool};
use csgpix::voxel::{Grid, Sampling, Slicer, SlicerOptions};
use glam::DVec3;
use serde_json::{json, Value};

const TWELVE: &str = include_str!("../vectors/scenes/twelve.csg");

/// A store built slice by slice from `filled(x, y, z)` over an N³ grid.
fn store_of(n: usize, filled: impl Fn(usize, usize, usize) -> bool) -> OptimizedOctree {
    let depth = octree::depth_for([n; 3]).expect("depth");
    let mut b = octree::build_tree(depth, n, Leaves::new(depth, u64::MAX));
    let mut slice = vec![0u8; n * n];
    for z in 0..n {
        for (i, v) in slice.iter_mut().enumerate() {
            *v = u8::from(filled(i % n, i / n, z));
        }
        octree::StoreBuilder::push(&mut b, z, &slice).expect("push");
    }
    b.finish_store().expect("store")
}

const UNIT: Frame = Frame {
    origin: DVec3::ZERO,
    voxel: DVec3::ONE,
};

/// A ball of radius 0.4·N about the grid's centre.
fn ball(n: usize) -> (OptimizedOctree, Frame, f64) {
    let (c, r) = (n as f64 / 2.0, 0.4 * n as f64);
    let s = store_of(n, |x, y, z| {
        let d = DVec3::new(x as f64, y as f64, z as f64) - DVec3::splat(c);
        d.length_squared() <= r * r
    });
    (s, UNIT, r)
}

/// A cube of side 0.8·N about the grid's centre.
fn cube(n: usize) -> (OptimizedOctree, Frame, f64) {
    let (lo, hi) = (n / 10, n - n / 10);
    let s = store_of(n, |x, y, z| {
        [x, y, z].iter().all(|&c| (lo..hi).contains(&c))
    });
    (s, UNIT, (hi - lo) as f64 / 2.0)
}

/// `twelve.csg` voxelized as `voxelize` does, in ±15 scene units (room around the scene).
fn twelve(n: usize) -> (OptimizedOctree, Frame, f64) {
    let scene = parse_csg(TWELVE, "twelve.csg").expect("scene");
    let grid = Grid::new([n; 3], DVec3::splat(-15.0), DVec3::splat(15.0)).expect("grid");
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
    let store =
        csgpix::run::store::octree_from_scene(&slicer, &scene.root, u64::MAX).expect("store");
    (store, Frame::of_grid(&grid), 8.6)
}

/// `steps` positions about 0.5 voxel apart on a spiral about the vertical axis through
/// `centre`, in its plane, starting at `radius` (scene units) and shrinking by `shrink` per
/// turn.
fn spiral(frame: &Frame, centre: DVec3, radius: f64, shrink: f64, steps: usize) -> Vec<DVec3> {
    let (mut t, mut out) = (0.0f64, Vec::with_capacity(steps));
    for _ in 0..steps {
        let r = (radius - shrink * t / std::f64::consts::TAU).max(frame.voxel.x);
        out.push(centre + DVec3::new(r * t.cos(), r * t.sin(), 0.0));
        t += 0.5 * frame.voxel.x / r;
    }
    out
}

/// Nodes had every coarse leaf of `before` that `after` no longer holds been expanded down to
/// the cells.
fn literal_nodes(before: &OptimizedOctree, after: &OptimizedOctree) -> u64 {
    let d = before.depth();
    let mut extra = 0u64;
    before.for_each_leaf(&mut |k, _| {
        let l = csgpix::sculpt::octree::key::level(k);
        if l < d && after.table().get(k).is_none() {
            extra += 8u64.pow(d - l) - 1;
        }
    });
    before.node_count() as u64 + extra
}

/// One scene at one size, both radii.
fn measure(name: &str, n: usize, steps: usize, as_json: bool) -> Vec<Value> {
    let t0 = Instant::now();
    let (store, frame, radius) = match name {
        "sphere" => ball(n),
        "cube" => cube(n),
        _ => twelve(n),
    };
    let build_s = t0.elapsed().as_secs_f64();
    let centre = match name {
        "twelve" => DVec3::new(0.0, 0.0, 2.0),
        _ => DVec3::splat(n as f64 / 2.0),
    };
    let mut rows = vec![];
    for r in [4.0, 8.0] {
        let path = spiral(&frame, centre, radius, r / 2.0 * frame.voxel.x, steps);
        let row = run(name, n, (store.clone(), frame), &path, r, build_s);
        if !as_json {
            print_row(&row);
        }
        rows.push(row);
    }
    rows
}

fn run(
    name: &str,
    n: usize,
    (store, frame): (OptimizedOctree, Frame),
    path: &[DVec3],
    r: f64,
    build_s: f64,
) -> Value {
    let nodes0 = store.node_count();
    let original = store.clone();
    let tool = Tool {
        radius: r,
        add: false,
        stiffness: 1.0,
    };
    let t = Instant::now();
    let mut s = Sculptor::new(store, frame, [n; 3], tool).expect("sculptor");
    let mesh_s = t.elapsed().as_secs_f64();
    let tris0 = s.mesh.len();
    let (mut secs, mut carving) = (Vec::with_capacity(path.len()), vec![]);
    let (mut voxels, mut cells) = (0u64, 0u64);
    for &p in path {
        let st = s.step(p).expect("step");
        secs.push(st.seconds);
        if st.voxels > 0 {
            carving.push(st.seconds);
        }
        voxels += u64::from(st.voxels);
        cells += u64::from(st.cells);
    }
    let l = Latency::of(&secs);
    let c = Latency::of(&carving);
    json!({"scene": name, "res": n, "radius": r, "steps": path.len(),
        "voxels_removed": voxels, "cells_remeshed": cells,
        "nodes_before": nodes0, "nodes_after": s.store.node_count(),
        "literal_nodes_after": literal_nodes(&original, &s.store),
        "carving_steps": c.steps, "carving_median_us": c.median_us, "carving_p99_us": c.p99_us,
        "triangles_before": tris0, "triangles_after": s.mesh.len(),
        "build_s": build_s, "initial_mesh_s": mesh_s,
        "median_us": l.median_us, "p99_us": l.p99_us, "max_us": l.max_us, "mean_us": l.mean_us,
        "median_under_1ms": l.median_us < 1000.0, "p99_under_16_7ms": l.p99_us < 16_700.0})
}

fn print_row(r: &Value) {
    println!(
        "| {} | {} | {} | {} | {} | {} → {} | {} | {:.1} | {:.1} | {:.1} | {:.1} | {} | {:.1} | {:.1} |",
        r["scene"].as_str().unwrap_or(""),
        r["res"],
        r["radius"],
        r["voxels_removed"],
        r["cells_remeshed"],
        r["nodes_before"],
        r["nodes_after"],
        r["literal_nodes_after"],
        r["median_us"].as_f64().unwrap_or(0.0),
        r["p99_us"].as_f64().unwrap_or(0.0),
        r["max_us"].as_f64().unwrap_or(0.0),
        r["mean_us"].as_f64().unwrap_or(0.0),
        r["carving_steps"],
        r["carving_median_us"].as_f64().unwrap_or(0.0),
        r["carving_p99_us"].as_f64().unwrap_or(0.0),
    );
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.iter().any(|a| a == "--quick");
    let as_json = args.iter().any(|a| a == "--json");
    let (sizes, steps) = if quick {
        (vec![128, 256], 1000)
    } else {
        (vec![256, 512], 4000)
    };
    if !as_json {
        println!("| scene | N | R | voxels removed | cells re-meshed | nodes | fully expanded | median µs | p99 µs | max µs | mean µs | carving steps | their median µs | their p99 µs |");
        println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    }
    let mut out = vec![];
    for n in sizes {
        for name in ["sphere", "cube", "twelve"] {
            out.extend(measure(name, n, steps, as_json));
        }
    }
    if as_json {
        let all = json!({"quick": quick, "steps": steps, "results": out});
        println!("{}", serde_json::to_string_pretty(&all).unwrap_or_default());
    }
}
