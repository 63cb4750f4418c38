//! The corpus of real-world OpenSCAD designs (`vectors/designs`, sources and licences in its
//! README): each design's CSG export (made by OpenSCAD 2021.01, `generate.sh`) read by csgpix
//! and voxelized at 64³ on the box of OpenSCAD's own CGAL mesh (padded 5 %), against that mesh
//! voxelized on the same grid. Prints the table of docs/voxelization.md:
//! `cargo test --release --test designs -- --nocapture`.
//!
//! The designs are read as `csgpix voxelize` reads them by default; with `openscad` on PATH
//! the ones refused are read again with `--fallback openscad` (reported apart).

mod common;

use std::io::Read;
use std::path::{Path, PathBuf};
use std::time::Instant;

use csgpix::blist::BlistEval;
use csgpix::sampled::load_imports;
use csgpix::scad::{parse_csg_with, Fallback, ReadOptions};
use csgpix::solid::{CsgNode, CsgScene, Import};
use csgpix::voxel::{voxelize, Grid, Route, Slicer, SlicerOptions};
use glam::DVec3;
use rtl_model::Equations;

const N: usize = 64;

fn designs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/designs")
}

/// A file of `meshes/`, gunzipped when it was stored as NAME.gz.
fn mesh_file(name: &str) -> Option<String> {
    let plain = designs().join("meshes").join(name);
    if let Ok(t) = std::fs::read_to_string(&plain) {
        return Some(t);
    }
    let gz = std::fs::File::open(plain.with_file_name(format!("{name}.gz"))).ok()?;
    let mut text = String::new();
    flate2::read::GzDecoder::new(gz)
        .read_to_string(&mut text)
        .ok()?;
    Some(text)
}

fn occupancy(
    scene: &CsgScene,
    base: &Path,
    grid: &Grid,
    route: Route,
) -> Result<Vec<bool>, String> {
    let sampled = load_imports(scene, "design", base).map_err(|e| e.to_string())?;
    let opts = SlicerOptions {
        sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(scene, grid.clone(), opts).map_err(|e| e.to_string())?;
    let eval = BlistEval::new(&scene.root);
    let (v, _) = voxelize(&slicer, route, Equations::Derived.set(), &eval, &|| {})
        .map_err(|e| e.to_string())?;
    Ok(v.voxels.iter().map(|&c| c != 0).collect())
}

fn iou(a: &[bool], b: &[bool]) -> f64 {
    let both = a.iter().zip(b).filter(|(x, y)| **x && **y).count();
    let either = a.iter().zip(b).filter(|(x, y)| **x || **y).count();
    if either == 0 {
        1.0
    } else {
        both as f64 / either as f64
    }
}

/// OpenSCAD's mesh as a scene of one closed-mesh primitive, and its padded box.
fn reference(tris: Vec<[[f64; 3]; 3]>) -> (CsgScene, DVec3, DVec3) {
    let mut lo = DVec3::INFINITY;
    let mut hi = DVec3::NEG_INFINITY;
    for p in tris.iter().flatten() {
        lo = lo.min(DVec3::from(*p));
        hi = hi.max(DVec3::from(*p));
    }
    let pad = (hi - lo) * 0.05 + DVec3::splat(1e-3);
    let import = Import {
        file: "openscad".into(),
        threshold: None,
        matrix: None,
        colour: None,
        line: 1,
        col: 1,
        mesh: Some(std::sync::Arc::new(tris)),
    };
    let scene = CsgScene {
        solids: vec![],
        imports: vec![import],
        root: CsgNode::Solid(0),
        warnings: vec![],
    };
    (scene, lo - pad, hi + pad)
}

/// One design's row: None where csgpix refuses it (with the reason).
struct Row {
    name: String,
    openscad_s: f64,
    outcome: Result<(f64, f64, f64), String>,
    fallback: bool,
}

fn measure(name: &str, openscad_s: f64, fallback: Fallback) -> Row {
    let csg = mesh_file(&format!("{name}.csg")).expect("the CSG export");
    let off = mesh_file(&format!("{name}.off")).expect("OpenSCAD's mesh");
    let tris = common::off_triangles(&off).expect("an OFF mesh");
    let (mesh, lo, hi) = reference(tris);
    let grid = Grid::new([N; 3], lo, hi).unwrap();
    let folder = designs().join(name);
    let base = if folder.is_dir() { folder } else { designs() };
    let options = ReadOptions {
        fallback,
        dir: Some(base.clone()),
    };
    let outcome = (|| {
        let t = Instant::now();
        let scene = parse_csg_with(&csg, name, &options).map_err(|e| e.to_string())?;
        let word = occupancy(&scene, &base, &grid, Route::Intervals)?;
        let seconds = t.elapsed().as_secs_f64();
        let float = occupancy(&scene, &base, &grid, Route::Float)?;
        let theirs = occupancy(&mesh, &base, &grid, Route::Float)?;
        Ok((iou(&word, &theirs), iou(&float, &theirs), seconds))
    })();
    Row {
        name: name.to_string(),
        openscad_s,
        outcome,
        fallback: fallback == Fallback::Openscad,
    }
}

fn have_openscad() -> bool {
    std::process::Command::new("openscad")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

#[test]
fn real_world_designs_against_openscad() {
    let times = std::fs::read_to_string(designs().join("meshes/times.tsv")).unwrap();
    // CSGPIX_DESIGNS=a,b measures only those designs.
    let only = std::env::var("CSGPIX_DESIGNS").ok();
    let mut rows = vec![];
    for line in times.lines().skip(1) {
        let f: Vec<&str> = line.split('\t').collect();
        let (name, seconds) = (f[0], f[1].parse::<f64>().unwrap_or(f64::NAN));
        if only
            .as_ref()
            .is_some_and(|o| !o.split(',').any(|n| n == name))
        {
            continue;
        }
        let mut row = measure(name, seconds, Fallback::Refuse);
        if row.outcome.is_err() && have_openscad() {
            let again = measure(name, seconds, Fallback::Openscad);
            if again.outcome.is_ok() {
                row = again;
            }
        }
        rows.push(row);
    }
    println!("| design | accepted | IoU word | IoU float | csgpix s | OpenSCAD s |");
    println!("|---|---|---|---|---|---|");
    for r in &rows {
        match &r.outcome {
            Ok((w, f, s)) => {
                let how = if r.fallback {
                    "with --fallback openscad"
                } else {
                    "yes"
                };
                println!(
                    "| {} | {how} | {w:.4} | {f:.4} | {s:.2} | {:.1} |",
                    r.name, r.openscad_s
                );
            }
            Err(e) => println!(
                "| {} | no: {} | | | | {:.1} |",
                r.name,
                e.replace('|', "/"),
                r.openscad_s
            ),
        }
    }
    let by_default = rows
        .iter()
        .filter(|r| r.outcome.is_ok() && !r.fallback)
        .count();
    let accepted: Vec<_> = rows
        .iter()
        .filter_map(|r| r.outcome.as_ref().ok())
        .collect();
    let word_ok = accepted.iter().filter(|a| a.0 >= 0.99).count();
    let float_ok = accepted.iter().filter(|a| a.1 >= 0.999).count();
    println!(
        "{} designs; accepted {by_default} by default, {} with --fallback openscad; \
         IoU word >= 0.99: {word_ok}, float >= 0.999: {float_ok}",
        rows.len(),
        accepted.len()
    );
    assert!(only.is_some() || rows.len() >= 50);
}
