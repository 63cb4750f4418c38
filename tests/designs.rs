//! The corpus of real-world OpenSCAD designs (`vectors/designs`, sources and licences in its
//! README): each design's CSG export (made by OpenSCAD 2021.01, `generate.sh`) read by csgpix
//! and voxelized at 64³ on the box of OpenSCAD's own CGAL mesh (padded 5 %), against that mesh
//! voxelized on the same grid. Prints the table of docs/voxelization.md:
//! `cargo test --release --test designs -- --nocapture`.
//!
//! The designs are read as `csgpix voxelize` reads them by default; with `openscad` on PATH
//! the ones refused are read again with `--fallback openscad` (reported apart).

mod common;

use common::{have_openscad, scene_occupancy};
use csgpix_testkit::iou;

use std::io::Read;
use std::path::{Path, PathBuf};
use std::time::Instant;

use csgpix::openscad::Fallback;
use csgpix::scene::solid::{CsgNode, CsgScene, Import};
use csgpix::voxel::{Grid, Route};
use glam::DVec3;

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

/// csgpix's voxels of a design's CSG export through the command line (`csgpix voxelize
/// --res 64 --bounds …`, `route` word or float), its wall time, or its one-line refusal; a run
/// past [`TIMEOUT`] is stopped and counted as refused.
fn csgpix_voxels(
    csg: &Path,
    (lo, hi): (DVec3, DVec3),
    model: &str,
    fallback: Fallback,
) -> Result<(Vec<bool>, f64), String> {
    let out = csg.with_extension(format!("{model}.nrrd"));
    let bounds = format!("{},{},{},{},{},{}", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"));
    cmd.args([
        "voxelize",
        csg.to_str().unwrap(),
        "--res",
        "64x64x64",
        "--bounds",
        &bounds,
    ]);
    cmd.args(["--model", model, "-o", out.to_str().unwrap()]);
    if fallback == Fallback::Openscad {
        cmd.args(["--fallback", "openscad"]);
    }
    cmd.stdout(std::process::Stdio::null());
    cmd.stderr(std::process::Stdio::piped());
    let t = Instant::now();
    let mut child = cmd.spawn().unwrap();
    while child.try_wait().unwrap().is_none() {
        if t.elapsed().as_secs_f64() > TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("over {TIMEOUT} s"));
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let seconds = t.elapsed().as_secs_f64();
    let o = child.wait_with_output().unwrap();
    if !o.status.success() {
        let e = String::from_utf8_lossy(&o.stderr);
        let last = e.lines().rfind(|l| !l.contains("warning:")).unwrap_or("");
        return Err(last.trim_start_matches("csgpix: ").to_string());
    }
    let (_, v) = csgpix::scene::nrrd::read(&std::fs::read(&out).unwrap()).unwrap();
    Ok((v.iter().map(|&c| c != 0).collect(), seconds))
}

/// A design's run stops after this many seconds (the corpus's median is well under one).
const TIMEOUT: f64 = 90.0;

fn measure(name: &str, openscad_s: f64, fallback: Fallback, tmp: &Path) -> Row {
    let csg = mesh_file(&format!("{name}.csg")).expect("the CSG export");
    let off = mesh_file(&format!("{name}.off")).expect("OpenSCAD's mesh");
    let tris = common::off_triangles(&off).expect("an OFF mesh");
    let (mesh, lo, hi) = reference(tris);
    let grid = Grid::new([N; 3], lo, hi).unwrap();
    // The export beside the design's own files, so its relative file names resolve.
    let folder = designs().join(name);
    let base = if folder.is_dir() {
        folder
    } else {
        tmp.to_path_buf()
    };
    let file = base.join(format!(".{name}.test.csg"));
    std::fs::write(&file, &csg).unwrap();
    let outcome = (|| {
        let (word, seconds) = csgpix_voxels(&file, (lo, hi), "word", fallback)?;
        let (float, _) = csgpix_voxels(&file, (lo, hi), "float", fallback)?;
        let theirs = scene_occupancy(&mesh, &base, &grid, Route::Float)?;
        Ok((iou(&word, &theirs), iou(&float, &theirs), seconds))
    })();
    // A refusal names the export as the user's `NAME.csg`, not the test's hidden copy.
    let outcome = outcome
        .map_err(|e: String| e.replace(file.to_str().unwrap_or_default(), &format!("{name}.csg")));
    for f in [
        file.clone(),
        file.with_extension("word.nrrd"),
        file.with_extension("float.nrrd"),
    ] {
        let _ = std::fs::remove_file(f);
    }
    Row {
        name: name.to_string(),
        openscad_s,
        outcome,
        fallback: fallback == Fallback::Openscad,
    }
}

#[test]
fn real_world_designs_against_openscad() {
    let times = std::fs::read_to_string(designs().join("meshes/times.tsv")).unwrap();
    let tmp = tempfile::tempdir().unwrap();
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
        let mut row = measure(name, seconds, Fallback::Refuse, tmp.path());
        let timed_out = matches!(&row.outcome, Err(e) if e.starts_with("over "));
        if row.outcome.is_err() && !timed_out && have_openscad() {
            let again = measure(name, seconds, Fallback::Openscad, tmp.path());
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
    // The targets (docs/voxelization.md): at least 95 % accepted without the fallback, and
    // every accepted design at IoU >= 0.99 (word) and >= 0.999 (float).
    if only.is_none() {
        assert!(
            by_default * 100 >= 95 * rows.len(),
            "accepted by default: {by_default} of {}",
            rows.len()
        );
        let below: Vec<&str> = rows
            .iter()
            .filter(|r| matches!(r.outcome, Ok((w, f, _)) if w < 0.99 || f < 0.999))
            .map(|r| r.name.as_str())
            .collect();
        assert!(below.is_empty(), "below the IoU targets: {below:?}");
    }
}
