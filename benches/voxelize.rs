//! Voxelizing `vectors/scenes/twelve.csg` (13 convex solids under union, difference and
//! intersection): csgpix's routes and evaluators against a peer, the `fidget` crate's JIT
//! evaluating the same solids as an implicit expression, in two modes (dense and pruned); then
//! the floor: each route's whole run against allocating, filling and writing the volume, on
//! three scenes. See `docs/voxelize-bench.md`.
//!
//! `cargo bench --features bench --bench voxelize` (full: the twelve.csg section at 128³ and
//! 256³, median of 3, then the floor at 256³, 512³ and 1024³), `-- --quick` (64³ and 128³ for both, one run),
//! `-- --floor` (the floor section only), `-- --process` (whole processes against the floor's
//! process, new and replaced outputs, at 1024³ unless `--sizes`), `--sizes A,B,…` (the floor's
//! sizes), `--cells A,B,…`
//! (the pruned peer's cell sides, [`pruned::CELLS`] by default), `--no-dense` (the floor without
//! the dense peer, about 200 s a run at 1024³); `--json` prints every figure
//! as one JSON object instead of the table. Every figure comes from this run, measured back to
//! back, so ratios suffer less from a busy machine than figures from separate runs would (they
//! still move: see the doc). Threads: rayon's default pool (all cores).
//!
//! * `word`: [`Route::Intervals`] with each evaluator. Wall time is from the parsed scene to
//!   the volume ([`Slicer::new`] + [`voxelize`]); voxels/s is voxels of the grid over it; state
//!   is [`SliceEval::state_bytes`] per voxel.
//! * `cycle` vs `word`: the array routes (every P·Vz frame simulated) at small sizes only.
//! * peer, dense mode: every convex solid is the max over its faces of n·p − d (outward unit
//!   normal by Newell's method); union = min, intersection = max, difference = max(a, −b),
//!   complement = −a; JIT-compiled, evaluated one Z-slice per call at the voxel centres
//!   ([`Grid::centre`]), inside when the value is <= 0: every clause at every voxel. Its wall
//!   time includes building and compiling the expression. It samples the centre point where
//!   csgpix samples the centre's Z-segment (`crates/voxel/src/drive.rs`), so the two may
//!   differ at surfaces only: the agreement figures count differing voxels and how many of
//!   them lie on a surface of either volume.
//! * peer, pruned mode (`voxelize/pruned.rs`): the same expression evaluated as fidget's own
//!   renderers do, by recursive subdivision with interval arithmetic and tape simplification;
//!   voxel for voxel the dense mode's (asserted at the smallest size).
//! * phases: the word route's work split into passes (slicer setup, per-pixel slab ranges,
//!   toggle lists, the slab-mask sweep, evaluation, colour codes, assembly), each pass over
//!   all slabs in parallel except assembly, which `voxelize` also does on one thread.
//! * floor (`voxelize/floor.rs`): twelve.csg, csg-logo.csg and figure-5.6.csg (a dataset
//!   beside solids), each route of [`floor_routes`] and both peers from the scene to the NRRD
//!   file, against allocating, filling and writing the same bytes.

use std::time::Instant;

use csgpix::openscad::parse_csg;
use csgpix::scene::solid::{ConvexSolid, CsgNode, CsgScene};
use csgpix::voxel::evaluate::{colour_labels, direct, LeafOrder, StackEval, TreeEval};
use csgpix::voxel::slice::{Labels, Mask, OpCounts, SliceEval};
use csgpix::voxel::{
    voxelize, word_ranges, Grid, Route, Sampling, SlabRanges, Slicer, SlicerOptions, Volume,
};
use fidget::context::Tree;
use fidget::jit::JitShape;
use fidget::shape::EzShape;
use glam::DVec3;
use rayon::prelude::*;
use rtl_model::{Equations, WordFormat};
use serde_json::{json, Value};

// In a folder of their own, which cargo does not take for bench targets.
#[path = "voxelize/floor.rs"]
mod floor;
#[path = "voxelize/process.rs"]
mod process;
#[path = "voxelize/pruned.rs"]
mod pruned;

const SCENE: &str = include_str!("../vectors/scenes/twelve.csg");
const FMT: WordFormat = WordFormat::THESIS;

// ---------------------------------------------------------------------------------------------
// Evaluators

/// THE BLIST PLUG: the §4.5 Blist evaluator (`crates/voxel/src/blist.rs`). This is the only place it
/// enters the bench; every table, summary and JSON figure picks it up as `blist`. Return
/// `None` to measure without it.
fn blist(scene: &CsgScene) -> Option<Box<dyn SliceEval>> {
    Some(Box::new(csgpix::voxel::blist::BlistEval::new(&scene.root)))
}

/// The evaluators measured, Blist first when there is one.
fn evaluators(scene: &CsgScene) -> Vec<(&'static str, Box<dyn SliceEval>)> {
    let mut v: Vec<(&'static str, Box<dyn SliceEval>)> = Vec::new();
    if let Some(b) = blist(scene) {
        v.push(("blist", b));
    }
    v.push(("tree", Box::new(TreeEval::new(&scene.root))));
    v.push(("stack", Box::new(StackEval::new(&scene.root))));
    v
}

/// THE ROUTE PLUG: the routes the floor section measures (`floor.rs`), each with the Blist
/// evaluator. A route added here is measured, printed and in the JSON with nothing else to
/// change.
fn floor_routes() -> Vec<(&'static str, Route)> {
    vec![
        ("runs", Route::Runs { float: false }),
        ("runs-float", Route::Runs { float: true }),
        ("intervals", Route::Intervals),
        ("float", Route::Float),
    ]
}

// ---------------------------------------------------------------------------------------------
// Timing

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

fn grid(scene: &CsgScene, n: usize) -> Grid {
    Grid::of_scene(scene, [n; 3]).expect("grid")
}

/// The bench's slicer: the thesis's slab sampling, under which the figures of
/// docs/voxelize-bench.md were measured (the peer comparison counts the difference from
/// centre sampling).
fn slicer(scene: &CsgScene, n: usize) -> Slicer {
    Slicer::new(
        scene,
        grid(scene, n),
        SlicerOptions {
            fmt: FMT,
            sampling: Sampling::Slab,
            ..SlicerOptions::default()
        },
    )
    .expect("slicer")
}

/// Membership of the volume under centre sampling (csgpix's default), for the agreement
/// with the peer, which samples voxel centres too.
fn centre_inside(scene: &CsgScene, n: usize, route: Route, eval: &dyn SliceEval) -> Vec<bool> {
    let slicer = Slicer::new(
        scene,
        grid(scene, n),
        SlicerOptions {
            fmt: FMT,
            sampling: Sampling::Centre,
            ..SlicerOptions::default()
        },
    )
    .expect("slicer");
    let (v, _) =
        voxelize(&slicer, route, Equations::Derived.set(), eval, &|| {}).expect("voxelize");
    inside_of(&v)
}

/// csgpix from the parsed scene to the volume.
fn csgpix_run(scene: &CsgScene, n: usize, route: Route, eval: &dyn SliceEval) -> Volume {
    let slicer = slicer(scene, n);
    voxelize(&slicer, route, Equations::Derived.set(), eval, &|| {})
        .expect("voxelize")
        .0
}

fn inside_of(v: &Volume) -> Vec<bool> {
    v.voxels.iter().map(|&c| c != 0).collect()
}

// ---------------------------------------------------------------------------------------------
// The peer: fidget

/// Newell's normal of face `f` (not normalized; outward, the face being CCW seen from
/// outside) and the mean of its vertices.
fn newell(s: &ConvexSolid, f: &[u32]) -> (DVec3, DVec3) {
    let p = |i: usize| DVec3::from(s.vertices[f[i] as usize]);
    let (mut n, mut c) = (DVec3::ZERO, DVec3::ZERO);
    for i in 0..f.len() {
        let (a, b) = (p(i), p((i + 1) % f.len()));
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
        c += a;
    }
    (n, c / f.len().max(1) as f64)
}

/// A convex solid as the max over its faces of n·p − d (outward unit normal n).
fn solid_tree(s: &ConvexSolid) -> Tree {
    let (x, y, z) = Tree::axes();
    let mut planes = s.faces.iter().filter_map(|f| {
        let (n, c) = newell(s, f);
        let len = n.length();
        (f.len() >= 3 && len > 1e-12).then(|| {
            let n = n / len;
            let d = n.dot(c);
            x.clone() * n.x as f32 + y.clone() * n.y as f32 + z.clone() * n.z as f32 - d as f32
        })
    });
    let first = planes.next().unwrap_or_else(|| Tree::constant(1e30));
    planes.fold(first, |acc, t| acc.max(t))
}

/// The CSG tree as an implicit expression (negative inside).
fn csg_tree(node: &CsgNode, solids: &[Tree]) -> Tree {
    let nothing = || Tree::constant(1e30);
    let kids: Vec<Tree> = node
        .children()
        .iter()
        .map(|c| csg_tree(c, solids))
        .collect();
    let fold = |f: fn(&Tree, Tree) -> Tree| {
        let mut it = kids.iter().cloned();
        match it.next() {
            Some(first) => it.fold(first, |a, b| f(&a, b)),
            None => nothing(),
        }
    };
    match node {
        CsgNode::Solid(i) => solids[*i].clone(),
        CsgNode::Empty => nothing(),
        CsgNode::Union(_) => fold(|a, b| a.min(b)),
        CsgNode::Intersection(_) => fold(|a, b| a.max(b)),
        CsgNode::Difference(_) => fold(|a, b| a.max(-b)),
        CsgNode::Complement(_) => -kids[0].clone(),
    }
}

/// What the peer builds before evaluating: the expression, JIT-compiled.
fn peer_build(scene: &CsgScene) -> (JitShape, usize) {
    let solids: Vec<Tree> = scene.solids.iter().map(solid_tree).collect();
    let tree = csg_tree(&scene.root, &solids);
    let shape = JitShape::from(tree);
    let size = shape.size();
    (shape, size)
}

/// The dense peer's evaluation: every Z-slice in one bulk call (every clause at every voxel
/// centre), slices in parallel; membership 1 inside (value <= 0), 0 outside.
fn dense_eval(shape: &JitShape, g: &Grid) -> Vec<u8> {
    let tape = shape.ez_float_slice_tape();
    let [nx, ny, nz] = g.dims;
    let xs: Vec<f32> = (0..nx * ny)
        .map(|i| g.centre(i % nx, 0, 0).x as f32)
        .collect();
    let ys: Vec<f32> = (0..nx * ny)
        .map(|i| g.centre(0, i / nx, 0).y as f32)
        .collect();
    let mut voxels = vec![0u8; nx * ny * nz];
    voxels.par_chunks_mut(nx * ny).enumerate().for_each_init(
        || (JitShape::new_float_slice_eval(), vec![0f32; nx * ny]),
        |(eval, zs), (k, slice)| {
            zs.fill(g.centre(0, 0, k).z as f32);
            let out = eval.eval(&tape, &xs, &ys, zs).expect("peer eval");
            for (o, &v) in slice.iter_mut().zip(out) {
                *o = u8::from(v <= 0.0);
            }
        },
    );
    voxels
}

/// The dense peer from the parsed scene to the membership volume: build, compile, evaluate.
fn dense_run(scene: &CsgScene, n: usize) -> Vec<u8> {
    dense_eval(&peer_build(scene).0, &grid(scene, n))
}

/// The pruned peer from the parsed scene to the membership volume: build, compile, evaluate
/// by subdivision into cells of the sides `cells`.
fn pruned_run(scene: &CsgScene, n: usize, cells: &[usize]) -> Vec<u8> {
    pruned::pruned_eval(&peer_build(scene).0, &grid(scene, n), cells)
}

fn membership(v: &[u8]) -> Vec<bool> {
    v.iter().map(|&c| c != 0).collect()
}

/// How two membership volumes differ.
struct Agreement {
    /// Voxels whose membership differs.
    differing: usize,
    /// Of those, voxels on a surface of either volume: a 6-neighbour with the other
    /// membership (outside the grid counts as outside).
    on_a_surface: usize,
    /// Of those, voxels whose Z-neighbour (k ± 1) has the other membership in either volume.
    along_z: usize,
    /// Differing voxels inside `a` only, and inside `b` only.
    a_only: usize,
    b_only: usize,
}

fn agreement(a: &[bool], b: &[bool], dims: [usize; 3]) -> Agreement {
    let [nx, ny, nz] = dims;
    let at = |v: &[bool], i: i64, j: i64, k: i64| {
        (0..nx as i64).contains(&i)
            && (0..ny as i64).contains(&j)
            && (0..nz as i64).contains(&k)
            && v[(k as usize * ny + j as usize) * nx + i as usize]
    };
    let mut r = Agreement {
        differing: 0,
        on_a_surface: 0,
        along_z: 0,
        a_only: 0,
        b_only: 0,
    };
    const NEAR: [(i64, i64, i64); 6] = [
        (0, 0, 1),
        (0, 0, -1),
        (1, 0, 0),
        (-1, 0, 0),
        (0, 1, 0),
        (0, -1, 0),
    ];
    for idx in (0..a.len()).filter(|&i| a[i] != b[i]) {
        r.differing += 1;
        if a[idx] {
            r.a_only += 1;
        } else {
            r.b_only += 1;
        }
        let (i, j, k) = (
            (idx % nx) as i64,
            ((idx / nx) % ny) as i64,
            (idx / (nx * ny)) as i64,
        );
        let other = |&(di, dj, dk): &(i64, i64, i64)| {
            at(a, i + di, j + dj, k + dk) != a[idx] || at(b, i + di, j + dj, k + dk) != b[idx]
        };
        if NEAR.iter().any(other) {
            r.on_a_surface += 1;
        }
        if NEAR[..2].iter().any(other) {
            r.along_z += 1;
        }
    }
    r
}

fn agreement_json(a: &[bool], b: &[bool], dims: [usize; 3]) -> Value {
    let r = agreement(a, b, dims);
    json!({
        "differing": r.differing,
        "fraction": r.differing as f64 / a.len() as f64,
        "differing_on_a_surface": r.on_a_surface,
        "differing_with_a_z_neighbour_of_the_other_membership": r.along_z,
        "inside_first_only": r.a_only,
        "inside_second_only": r.b_only,
    })
}

// ---------------------------------------------------------------------------------------------
// Phases of the word route

/// The word route split into passes, each over all slabs in parallel and each the median of
/// `runs`: what `voxelize` does fused per slab.
fn phases(
    scene: &CsgScene,
    n: usize,
    runs: usize,
    evals: &[(&'static str, Box<dyn SliceEval>)],
) -> Value {
    let (setup, slicer) = median(runs, || slicer(scene, n));
    let (ranges_s, ranges) = median(runs, || {
        (0..slicer.lists.len())
            .into_par_iter()
            .map(|p| word_ranges(&slicer, p).expect("ranges"))
            .collect::<Vec<SlabRanges>>()
    });
    let (toggles_s, toggles) = median(runs, || {
        ranges
            .par_iter()
            .map(|r| r.toggles(n))
            .collect::<Vec<Vec<Vec<u32>>>>()
    });
    // The masks swept forward as `voxelize` does: chunks of consecutive slabs, the first slab
    // of a chunk built pixel by pixel, every later one by flipping the pixels that change.
    let chunk = (n / (4 * rayon::current_num_threads())).max(1);
    let sweep = |keep: bool| {
        (0..n.div_ceil(chunk))
            .into_par_iter()
            .map(|c| {
                let (a, b) = (c * chunk, ((c + 1) * chunk).min(n));
                let mut masks: Vec<Mask> = ranges.iter().map(|r| r.mask(a)).collect();
                let mut out = vec![];
                for k in a..b {
                    if k > a {
                        for (t, m) in toggles.iter().zip(&mut masks) {
                            t[k].iter().for_each(|&i| m.toggle(i as usize));
                        }
                    }
                    if keep {
                        out.push(masks.clone());
                    } else {
                        std::hint::black_box(&masks);
                    }
                }
                out
            })
            .flatten()
            .collect::<Vec<Vec<Mask>>>()
    };
    let (masks_s, _) = median(runs, || sweep(false));
    let masks = sweep(true);
    let mut per_eval = serde_json::Map::new();
    for (name, eval) in evals {
        let (eval_s, labels) = median(runs, || {
            masks
                .par_iter()
                .map(|m| eval.eval(m, &mut OpCounts::default()))
                .collect::<Vec<Labels>>()
        });
        let (colour_s, colours) = median(runs, || {
            labels
                .par_iter()
                .map(|l| {
                    l.iter()
                        .map(|&l| {
                            if l == 0 {
                                0
                            } else {
                                slicer.colours[l as usize - 1]
                            }
                        })
                        .collect::<Vec<u8>>()
                })
                .collect::<Vec<_>>()
        });
        let (assemble_s, filled) = median(runs, || {
            let volume = colours.concat();
            volume.iter().filter(|&&v| v != 0).count()
        });
        std::hint::black_box(filled);
        per_eval.insert(
            name.to_string(),
            json!({"eval_s": eval_s, "colour_codes_s": colour_s, "assemble_s": assemble_s}),
        );
    }
    // How much of the stack evaluator's time is membership and how much the colour rule every
    // evaluator shares.
    let order = LeafOrder::new(&scene.root);
    let stack = StackEval::new(&scene.root);
    let (stack_inside_s, inside) = median(runs, || {
        masks
            .par_iter()
            .map(|m| stack.inside(m, &mut OpCounts::default()))
            .collect::<Vec<Mask>>()
    });
    let (colour_rule_s, labels) = median(runs, || {
        masks
            .par_iter()
            .zip(&inside)
            .map(|(m, i)| colour_labels(&order, m, i))
            .collect::<Vec<Labels>>()
    });
    std::hint::black_box(labels);
    json!({
        "display_list_planes": slicer.lists.iter().map(|l| l.planes.len()).sum::<usize>(),
        "slicer_setup_s": setup,
        "ranges_s": ranges_s,
        "toggles_s": toggles_s,
        "masks_sweep_s": masks_s,
        "evaluators": per_eval,
        "stack_membership_only_s": stack_inside_s,
        "colour_rule_s": colour_rule_s,
    })
}

/// One line of the phases.
fn phases_line(ph: &Value) -> String {
    let f = |v: &Value| format!("{:.4}", v.as_f64().unwrap_or(f64::NAN));
    let mut s = format!(
        "setup {} s, ranges ({} planes) {} s, toggles {} s, mask sweep {} s",
        f(&ph["slicer_setup_s"]),
        ph["display_list_planes"],
        f(&ph["ranges_s"]),
        f(&ph["toggles_s"]),
        f(&ph["masks_sweep_s"])
    );
    if let Some(m) = ph["evaluators"].as_object() {
        for (name, e) in m {
            s += &format!(
                "; {name}: eval {} s, colour codes {} s, assemble {} s",
                f(&e["eval_s"]),
                f(&e["colour_codes_s"]),
                f(&e["assemble_s"])
            );
        }
    }
    s + &format!(
        "; stack membership only {} s, colour rule {} s",
        f(&ph["stack_membership_only_s"]),
        f(&ph["colour_rule_s"])
    )
}

/// The peer's expression checked against plain f64 half-space tests and [`direct`] at the
/// same voxel centres: voxels that differ (f32 rounding at a plane can make a few).
fn peer_self_check(scene: &CsgScene, n: usize) -> usize {
    let g = grid(scene, n);
    let planes: Vec<Vec<(DVec3, f64)>> = scene
        .solids
        .iter()
        .map(|s| {
            s.faces
                .iter()
                .filter_map(|f| {
                    let (nrm, c) = newell(s, f);
                    let len = nrm.length();
                    (f.len() >= 3 && len > 1e-12).then(|| (nrm / len, (nrm / len).dot(c)))
                })
                .collect()
        })
        .collect();
    let [nx, ny, nz] = g.dims;
    let reference: Vec<bool> = (0..nx * ny * nz)
        .into_par_iter()
        .map(|idx| {
            let p = g.centre(idx % nx, (idx / nx) % ny, idx / (nx * ny));
            direct(&scene.root, |i| {
                planes[i].iter().all(|(m, d)| m.dot(p) - d <= 0.0)
            })
        })
        .collect();
    let peer = membership(&dense_run(scene, n));
    reference.iter().zip(&peer).filter(|(a, b)| a != b).count()
}

// ---------------------------------------------------------------------------------------------

/// The section on twelve.csg: every evaluator on the word route, the float route, the
/// peers, agreement, phases and the array routes; its JSON fields and summary lines.
fn word_section(
    opts: &Opts,
    say: &dyn Fn(String),
) -> (serde_json::Map<String, Value>, Vec<String>) {
    let (sizes, cycle_sizes, runs) = if opts.quick {
        ([64usize, 128], vec![32usize], 1)
    } else {
        ([128usize, 256], vec![32usize, 64], 3)
    };
    let scene = parse_csg(SCENE, "twelve.csg").expect("twelve.csg");
    let evals = evaluators(&scene);
    let threads = rayon::current_num_threads();
    say(format!(
        "voxelize bench: twelve.csg, {} solids, {} threads, median of {runs}{}",
        scene.solids.len(),
        threads,
        if opts.quick { " (quick)" } else { "" }
    ));
    if evals[0].0 != "blist" {
        say("note: no Blist evaluator yet (see blist() in benches/voxelize.rs)".into());
    }

    let check_n = 64;
    let self_check = peer_self_check(&scene, check_n);
    say(format!(
        "peer self-check {check_n}^3: {self_check} voxels differ from f64 half-spaces + direct()"
    ));

    let mut sizes_json = serde_json::Map::new();
    let mut summary = Vec::new();
    for n in sizes {
        let voxels = (n * n * n) as f64;
        let pixels = n * n;
        let mut word_json = serde_json::Map::new();
        let mut word_volume: Option<Volume> = None;
        let mut times = Vec::new();
        for (name, eval) in &evals {
            let (t, v) = median(runs, || {
                csgpix_run(&scene, n, Route::Intervals, eval.as_ref())
            });
            let bpv = eval.state_bytes(pixels) as f64 / pixels as f64;
            say(format!(
                "{n}^3 word {name:5}: {t:8.3} s  {:.3e} voxels/s  {bpv:.3} B/voxel state",
                voxels / t
            ));
            if let Some(w) = &word_volume {
                assert_eq!(
                    inside_of(w),
                    inside_of(&v),
                    "{n}^3: {name} disagrees with {}",
                    evals[0].0
                );
            }
            word_json.insert(
                name.to_string(),
                json!({"wall_s": t, "voxels_per_s": voxels / t, "state_bytes_per_voxel": bpv}),
            );
            times.push((*name, t, bpv));
            word_volume.get_or_insert(v);
        }
        let word_volume = word_volume.expect("an evaluator");
        let filled = word_volume.voxels.iter().filter(|&&v| v != 0).count();
        let (t_float, float_volume) = median(1, || {
            csgpix_run(
                &scene,
                n,
                Route::Float,
                evals.last().expect("stack").1.as_ref(),
            )
        });
        say(format!("{n}^3 float stack: {t_float:8.3} s (one run)"));

        let (t_build, (_, peer_size)) = median(runs, || peer_build(&scene));
        let peer_planes: usize = scene
            .solids
            .iter()
            .map(|s| {
                s.faces
                    .iter()
                    .filter(|f| f.len() >= 3 && newell(s, f).0.length() > 1e-12)
                    .count()
            })
            .sum();
        let (t_peer, peer) = median(runs, || dense_run(&scene, n));
        let peer = membership(&peer);
        say(format!(
            "{n}^3 peer fidget dense (jit, every clause at every voxel): {t_peer:8.3} s  \
             {:.3e} voxels/s  (of which build+compile {t_build:.4} s, {peer_size} tape clauses \
             over {peer_planes} face planes)",
            voxels / t_peer
        ));
        let row = PeerRow {
            n,
            runs,
            dense: &peer,
            t_dense: t_peer,
            smallest: n == sizes[0],
        };
        let (t_pruned, pruned_json) = pruned_row(&scene, &row, &opts.cells, say);
        let dims = [n; 3];
        let w_in = inside_of(&word_volume);
        let f_in = inside_of(&float_volume);
        let vs_float = agreement_json(&peer, &f_in, dims);
        let vs_word = agreement_json(&peer, &w_in, dims);
        let word_vs_float = agreement_json(&w_in, &f_in, dims);
        let stack_eval = evals.last().expect("stack").1.as_ref();
        let wc_in = centre_inside(&scene, n, Route::Intervals, stack_eval);
        let fc_in = centre_inside(&scene, n, Route::Float, stack_eval);
        let vs_float_centre = agreement_json(&peer, &fc_in, dims);
        let vs_word_centre = agreement_json(&peer, &wc_in, dims);
        for (what, a) in [
            ("peer vs float", &vs_float),
            ("peer vs word", &vs_word),
            ("word vs float", &word_vs_float),
            ("peer vs float (centre)", &vs_float_centre),
            ("peer vs word (centre)", &vs_word_centre),
        ] {
            say(format!(
                "{n}^3 {what}: {} differing voxels ({:.3e} of the grid), {} of them on a \
                 surface ({} along Z); inside the first only {}, the second only {}",
                a["differing"],
                a["fraction"].as_f64().unwrap_or(f64::NAN),
                a["differing_on_a_surface"],
                a["differing_with_a_z_neighbour_of_the_other_membership"],
                a["inside_first_only"],
                a["inside_second_only"]
            ));
        }
        let ph = phases(&scene, n, runs, &evals);
        say(format!("{n}^3 word phases: {}", phases_line(&ph)));

        for &(name, t, bpv) in &times {
            summary.push(format!(
                "summary {n}^3 word {name} wall {t:.3} s, {:.3e} voxels/s, {bpv:.3} B/voxel state{}",
                voxels / t,
                if n == 256 {
                    format!(
                        " (target < 1 s on 2 cores: {})",
                        if t < 1.0 { "met" } else { "NOT met" }
                    )
                } else {
                    String::new()
                }
            ));
            summary.push(format!(
                "summary {n}^3 {name}/dense peer time ratio {:.3}, /pruned peer {:.3}",
                t / t_peer,
                t / t_pruned
            ));
        }
        if evals[0].0 != "blist" {
            summary.push(format!(
                "summary {n}^3 word blist: not measured (no Blist SliceEval yet)"
            ));
        }
        summary.push(format!(
            "summary {n}^3 pruned peer {t_pruned:.3} s, {:.3} of the dense peer's time",
            t_pruned / t_peer
        ));
        summary.push(format!(
            "summary {n}^3 dense peer {t_peer:.3} s; differs from float in {} voxels ({:.2e}, {} on a \
             surface), from word in {} ({:.2e}, {} on a surface)",
            vs_float["differing"],
            vs_float["fraction"].as_f64().unwrap_or(f64::NAN),
            vs_float["differing_on_a_surface"],
            vs_word["differing"],
            vs_word["fraction"].as_f64().unwrap_or(f64::NAN),
            vs_word["differing_on_a_surface"]
        ));
        sizes_json.insert(
            format!("{n}"),
            json!({
                "voxels": n * n * n,
                "filled": filled,
                "word": word_json,
                "float_stack_wall_s": t_float,
                "peer": {
                    "mode": "dense",
                    "wall_s": t_peer,
                    "voxels_per_s": voxels / t_peer,
                    "build_compile_s": t_build,
                    "tape_clauses": peer_size,
                    "face_planes": peer_planes,
                    "vs_float": vs_float,
                    "vs_word": vs_word,
                    "vs_float_centre": vs_float_centre,
                    "vs_word_centre": vs_word_centre,
                },
                "peer_pruned": pruned_json,
                "word_vs_float": word_vs_float,
                "phases": ph,
            }),
        );
    }

    // The array routes: cycle is clock by clock, so small sizes only.
    let mut cycle_json = serde_json::Map::new();
    let stack = StackEval::new(&scene.root);
    for n in cycle_sizes {
        let (tc, vc) = median(runs, || {
            csgpix_run(&scene, n, Route::Array { cycle: true }, &stack)
        });
        let (ta, va) = median(runs, || {
            csgpix_run(&scene, n, Route::Array { cycle: false }, &stack)
        });
        let (ti, vi) = median(runs, || csgpix_run(&scene, n, Route::Intervals, &stack));
        let same = vc == va && va == vi;
        say(format!(
            "{n}^3 array cycle {tc:.3} s, array word {ta:.3} s, intervals {ti:.4} s; \
             volumes identical: {same}"
        ));
        summary.push(format!(
            "summary {n}^3 cycle/word-array time ratio {:.1}, cycle/intervals {:.0}, \
             word-array/intervals {:.0} (identical volumes: {same})",
            tc / ta,
            tc / ti,
            ta / ti
        ));
        cycle_json.insert(
            format!("{n}"),
            json!({
                "array_cycle_s": tc,
                "array_word_s": ta,
                "intervals_s": ti,
                "identical": same,
            }),
        );
    }
    let mut report = serde_json::Map::new();
    for (k, v) in [
        ("scene", json!("vectors/scenes/twelve.csg")),
        ("solids", json!(scene.solids.len())),
        ("threads", json!(rayon::current_num_threads())),
        ("runs", json!(runs)),
        ("quick", json!(opts.quick)),
        ("blist_available", json!(evals[0].0 == "blist")),
        (
            "peer_self_check",
            json!({"n": check_n, "differing": self_check}),
        ),
        ("sizes", Value::Object(sizes_json)),
        ("array_routes", Value::Object(cycle_json)),
    ] {
        report.insert(k.to_string(), v);
    }
    (report, summary)
}

/// What `pruned_row` compares the pruned peer with: the dense peer at N³.
struct PeerRow<'a> {
    n: usize,
    runs: usize,
    /// The dense peer's membership and time.
    dense: &'a [bool],
    t_dense: f64,
    /// The smallest size of the section, where the two must agree voxel for voxel.
    smallest: bool,
}

/// The pruned peer at N³ beside the dense one: its time (median of `runs`, from the parsed
/// scene, as the dense peer's) and the voxels where the two differ. Interval arithmetic only
/// prunes what no centre of the cell can change, so there should be none; the bench asserts
/// it at the smallest size and reports the count at every size.
fn pruned_row(
    scene: &CsgScene,
    row: &PeerRow,
    cells: &[usize],
    say: &dyn Fn(String),
) -> (f64, Value) {
    let n = row.n;
    let (t, v) = median(row.runs, || pruned_run(scene, n, cells));
    let differing = membership(&v)
        .iter()
        .zip(row.dense)
        .filter(|(a, b)| a != b)
        .count();
    let voxels = (n * n * n) as f64;
    say(format!(
        "{n}^3 peer fidget pruned (cells {cells:?}): {t:8.3} s  {:.3e} voxels/s  \
         pruned/dense time {:.3}; {differing} voxels differ from the dense peer",
        voxels / t,
        t / row.t_dense
    ));
    if row.smallest {
        assert_eq!(
            differing, 0,
            "{n}^3: the pruned peer differs from the dense one"
        );
    }
    let figures = json!({
        "mode": "pruned",
        "cells": cells,
        "wall_s": t,
        "voxels_per_s": voxels / t,
        "over_dense": t / row.t_dense,
        "vs_dense_differing": differing,
    });
    (t, figures)
}

struct Opts {
    quick: bool,
    json: bool,
    /// `--floor`: the floor section only.
    floor_only: bool,
    /// `--process`: the whole-process section only, at `floor_sizes` (default 1024).
    process_only: bool,
    /// `--sizes A,B,…`: the floor section's N.
    floor_sizes: Vec<usize>,
    /// `--cells A,B,…`: the pruned peer's cell sides, top level first.
    cells: Vec<usize>,
    /// `--no-dense`: the floor section leaves the dense peer out.
    dense: bool,
}

impl Opts {
    fn parse() -> Opts {
        let args: Vec<String> = std::env::args().skip(1).collect();
        let quick = args.iter().any(|a| a == "--quick");
        let process_only = args.iter().any(|a| a == "--process");
        let default_sizes = match (quick, process_only) {
            (true, _) => vec![64, 128],
            (false, true) => vec![1024],
            (false, false) => vec![256, 512, 1024],
        };
        Opts {
            process_only,
            quick,
            json: args.iter().any(|a| a == "--json"),
            floor_only: args.iter().any(|a| a == "--floor"),
            floor_sizes: list_arg(&args, "--sizes").unwrap_or(default_sizes),
            cells: list_arg(&args, "--cells").unwrap_or(pruned::CELLS.to_vec()),
            dense: !args.iter().any(|a| a == "--no-dense"),
        }
    }
}

/// `NAME A,B,…` or `NAME=A,B,…` among `args`, as numbers.
fn list_arg(args: &[String], name: &str) -> Option<Vec<usize>> {
    let at = args.iter().position(|a| a == name);
    let text = match at {
        Some(i) => args.get(i + 1).map(String::as_str),
        None => args
            .iter()
            .find_map(|a| a.strip_prefix(&format!("{name}="))),
    }?;
    let list: Vec<usize> = text
        .split(',')
        .map(|v| {
            v.trim()
                .parse()
                .unwrap_or_else(|e| panic!("{name} {text}: {e}"))
        })
        .collect();
    assert!(
        list.iter().all(|&v| v > 0),
        "{name} {text}: every value must be positive"
    );
    Some(list)
}

fn main() {
    if let Ok(spec) = std::env::var(process::FLOOR_CHILD) {
        process::floor_child(&spec);
        return;
    }
    let opts = Opts::parse();
    let t_all = Instant::now();
    let say = |s: String| {
        if !opts.json {
            println!("{s}");
        }
    };
    let (mut report, mut summary) = if opts.floor_only || opts.process_only {
        Default::default()
    } else {
        word_section(&opts, &say)
    };
    if opts.process_only {
        let v = process::process(&opts.floor_sizes, opts.quick, &say);
        summary.extend(process::summary(&v));
        report.insert("process".into(), v);
    } else {
        let floor = floor::floor(&floor::FloorArgs {
            sizes: &opts.floor_sizes,
            quick: opts.quick,
            cells: &opts.cells,
            dense: opts.dense,
            say: &say,
        });
        summary.extend(floor::summary(&floor));
        report.insert("floor".into(), floor);
    }
    let total = t_all.elapsed().as_secs_f64();
    if opts.json {
        report.insert("summary".into(), json!(summary));
        report.insert("total_s".into(), json!(total));
        println!("{}", Value::Object(report));
    } else {
        for s in &summary {
            println!("{s}");
        }
        println!("bench total {total:.1} s");
    }
}
