//! The corpus of public OpenSCAD designs (`vectors/designs`, sources and licences in its
//! README) against its ledger (`vectors/designs/ledger.tsv`). Each design's CSG export (made
//! by OpenSCAD 2021.01, `generate.sh`) is read by `csgpix voxelize` and voxelized at 64³ on
//! the box of OpenSCAD's own CGAL mesh (padded 5 %), word and float model, against that mesh
//! voxelized on the same grid. The test fails when a design the ledger records as accepted is
//! refused, or when its centre IoU drops more than [`SLACK`] below the ledger's; it prints the
//! table of every design and the improvements (newly accepted, IoU up).
//!
//! - `cargo test --release --test designs -- --nocapture`: compare and print.
//! - `CSGPIX_LEDGER=write`: rewrite the ledger from this run (the rows of the designs measured).
//! - `CSGPIX_DESIGNS=a,b`: measure only those designs.
//! - `CSGPIX_DESIGNS_FALLBACK=1`: a design refused is read again with `--fallback openscad`
//!   (needs `openscad`; printed apart, never written to the ledger).

mod common;

use common::{have_openscad, scene_occupancy};

use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::time::Instant;

use csgpix::openscad::Fallback;
use csgpix::scene::solid::{CsgNode, CsgScene, Import};
use csgpix::voxel::{Grid, Route};
use glam::DVec3;
use rayon::prelude::*;

const N: usize = 64;

/// How far below the ledger's IoU a design may fall before the test fails (the ledger's
/// figures are rounded to 4 decimals).
const SLACK: f64 = 0.001;

/// A design's run stops after this many seconds (the corpus's median is well under one).
const TIMEOUT: f64 = 90.0;

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
        footprint: None,
        mesh: Some(std::sync::Arc::new(tris)),
    };
    let scene = CsgScene {
        solids: vec![],
        imports: vec![import],
        root: CsgNode::Solid(0),
        warnings: vec![],
        reading_bytes: 0,
    };
    (scene, lo - pad, hi + pad)
}

/// csgpix's voxels of a design's CSG export through the command line (`csgpix voxelize
/// --res 64 --bounds …`, `model` word or float), its wall time, or the first line of its
/// refusal; a run past [`TIMEOUT`] is stopped and counted as refused.
fn csgpix_voxels(
    csg: &Path,
    (lo, hi): (DVec3, DVec3),
    model: &str,
    fallback: Fallback,
) -> Result<(Vec<bool>, f64), String> {
    let out = csg.with_extension(format!("{model}.nrrd"));
    let bounds = format!("{},{},{},{},{},{}", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"));
    cmd.args(["voxelize", csg.to_str().unwrap(), "--res", "64x64x64"]);
    cmd.args([
        "--bounds",
        &bounds,
        "--model",
        model,
        "-o",
        out.to_str().unwrap(),
    ]);
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
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    let seconds = t.elapsed().as_secs_f64();
    let o = child.wait_with_output().unwrap();
    if !o.status.success() {
        let e = String::from_utf8_lossy(&o.stderr);
        let first = e.lines().find(|l| !l.contains("warning:")).unwrap_or("");
        return Err(first.trim_start_matches("csgpix: ").to_string());
    }
    let (_, v) = csgpix::scene::nrrd::read(&std::fs::read(&out).unwrap()).unwrap();
    Ok((v.iter().map(|&c| c != 0).collect(), seconds))
}

/// One design's measurement: (IoU word, IoU float, csgpix's seconds), or its refusal.
struct Row {
    name: String,
    openscad_s: f64,
    outcome: Result<(f64, f64, f64), String>,
    fallback: bool,
}

fn measure(name: &str, openscad_s: f64, fallback: Fallback, tmp: &Path) -> Row {
    let csg = mesh_file(&format!("{name}.csg")).expect("the CSG export");
    let off = mesh_file(&format!("{name}.off")).expect("OpenSCAD's mesh");
    let tris = common::off_triangles(&off).expect("an OFF mesh");
    let (mesh, lo, hi) = reference(tris.clone());
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
        let w = csgpix_testkit::band::centre_iou(&word, &theirs, &tris, &grid);
        let f = csgpix_testkit::band::centre_iou(&float, &theirs, &tris, &grid);
        Ok((w, f, seconds))
    })();
    // A refusal names the export as the user's `NAME.csg`, not the test's hidden copy.
    let outcome = outcome.map_err(|e: String| {
        let e = e.replace(file.to_str().unwrap_or_default(), &format!("{name}.csg"));
        // Other files by their path under vectors/designs, whichever checkout this is.
        let e = e.replace(&format!("{}/", base.display()), "");
        e.replace(&format!("{}/", designs().display()), "")
            .replace('\t', " ")
    });
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

/// A ledger row: `accepted` with its two IoUs, or `refused: <first line of the error>`.
#[derive(Clone, Debug, PartialEq)]
enum Entry {
    Accepted { word: f64, float: f64 },
    Refused(String),
}

const LEDGER_HEADER: &str = "name\tstate\tiou_word\tiou_float";

fn ledger_path() -> PathBuf {
    designs().join("ledger.tsv")
}

/// The ledger's rows by design name (empty when there is no ledger yet).
fn read_ledger(text: &str) -> BTreeMap<String, Entry> {
    let mut rows = BTreeMap::new();
    for (n, line) in text.lines().enumerate().skip(1) {
        let f: Vec<&str> = line.split('\t').collect();
        let bad = || format!("ledger.tsv:{}: not `{LEDGER_HEADER}`: {line}", n + 1);
        let entry = match f.as_slice() {
            [_, "accepted", w, fl] => Entry::Accepted {
                word: w.parse().unwrap_or_else(|_| panic!("{}", bad())),
                float: fl.parse().unwrap_or_else(|_| panic!("{}", bad())),
            },
            [_, s, _, _] if s.starts_with("refused: ") => Entry::Refused(s[9..].to_string()),
            _ => panic!("{}", bad()),
        };
        rows.insert(f[0].to_string(), entry);
    }
    rows
}

fn write_ledger(rows: &BTreeMap<String, Entry>) -> String {
    let mut out = format!("{LEDGER_HEADER}\n");
    for (name, e) in rows {
        match e {
            Entry::Accepted { word, float } => {
                out += &format!("{name}\taccepted\t{word:.4}\t{float:.4}\n")
            }
            Entry::Refused(m) => out += &format!("{name}\trefused: {m}\t\t\n"),
        }
    }
    out
}

/// The entry a measured row gives the ledger (IoUs rounded as the ledger writes them).
fn entry_of(row: &Row) -> Entry {
    let round = |x: f64| (x * 1e4).round() / 1e4;
    match &row.outcome {
        Ok((w, f, _)) => Entry::Accepted {
            word: round(*w),
            float: round(*f),
        },
        Err(e) => Entry::Refused(e.clone()),
    }
}

/// The regressions (accepted before and refused now, an IoU more than [`SLACK`] below the
/// ledger's, a design missing from either side) and the improvements of `now` against
/// `ledger`, each one line.
fn compare_ledger(
    ledger: &BTreeMap<String, Entry>,
    now: &BTreeMap<String, Entry>,
    whole: bool,
) -> (Vec<String>, Vec<String>) {
    let (mut worse, mut better) = (vec![], vec![]);
    for (name, e) in now {
        match (ledger.get(name), e) {
            (None, _) => worse.push(format!("{name}: not in the ledger")),
            (Some(Entry::Accepted { .. }), Entry::Refused(m)) => {
                worse.push(format!("{name}: accepted in the ledger, now refused: {m}"))
            }
            (Some(Entry::Refused(_)), Entry::Accepted { word, float }) => better.push(format!(
                "{name}: newly accepted (IoU word {word:.4}, float {float:.4})"
            )),
            (Some(Entry::Refused(was)), Entry::Refused(m)) if was != m => {
                better.push(format!("{name}: still refused, now: {m}"))
            }
            (
                Some(Entry::Accepted {
                    word: w0,
                    float: f0,
                }),
                Entry::Accepted { word, float },
            ) => {
                for (what, old, new) in [("word", w0, word), ("float", f0, float)] {
                    if *new < old - SLACK {
                        worse.push(format!("{name}: IoU {what} {new:.4} < ledger {old:.4}"));
                    } else if *new > *old {
                        better.push(format!("{name}: IoU {what} {old:.4} -> {new:.4}"));
                    }
                }
            }
            _ => {}
        }
    }
    if whole {
        for name in ledger.keys().filter(|n| !now.contains_key(*n)) {
            worse.push(format!("{name}: in the ledger but not in the corpus"));
        }
    }
    (worse, better)
}

/// The designs of `meshes/times.tsv` whose mesh OpenSCAD made, with its seconds.
fn corpus() -> Vec<(String, f64)> {
    let times = std::fs::read_to_string(designs().join("meshes/times.tsv")).unwrap();
    times
        .lines()
        .skip(1)
        .map(|l| l.split('\t').collect::<Vec<_>>())
        .filter(|f| f.get(2) == Some(&"ok"))
        .map(|f| (f[0].to_string(), f[1].parse().unwrap_or(f64::NAN)))
        .collect()
}

fn print_table(rows: &[Row]) {
    println!("| design | accepted | IoU word | IoU float | csgpix s | OpenSCAD s |");
    println!("|---|---|---|---|---|---|");
    for r in rows {
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
    let accepted: Vec<_> = rows
        .iter()
        .filter_map(|r| r.outcome.as_ref().ok())
        .collect();
    let word_ok = accepted.iter().filter(|a| a.0 >= 0.99).count();
    let float_ok = accepted.iter().filter(|a| a.1 >= 0.999).count();
    println!(
        "{} designs; accepted {}; IoU word >= 0.99: {word_ok}, float >= 0.999: {float_ok}",
        rows.len(),
        accepted.len()
    );
}

#[test]
fn designs_against_ledger() {
    let start = Instant::now();
    let tmp = tempfile::tempdir().unwrap();
    let only = std::env::var("CSGPIX_DESIGNS").ok();
    let wanted = |n: &str| only.as_ref().is_none_or(|o| o.split(',').any(|x| x == n));
    let names: Vec<(String, f64)> = corpus().into_iter().filter(|(n, _)| wanted(n)).collect();
    assert!(
        only.is_some() || names.len() >= 150,
        "{} designs",
        names.len()
    );
    let mut rows: Vec<Row> = names
        .par_iter()
        .map(|(n, s)| measure(n, *s, Fallback::Refuse, tmp.path()))
        .collect();
    let now: BTreeMap<String, Entry> = rows.iter().map(|r| (r.name.clone(), entry_of(r))).collect();
    let fallback = std::env::var("CSGPIX_DESIGNS_FALLBACK").is_ok_and(|v| v == "1");
    if fallback && have_openscad() {
        for r in rows.iter_mut().filter(|r| r.outcome.is_err()) {
            let again = measure(&r.name, r.openscad_s, Fallback::Openscad, tmp.path());
            if again.outcome.is_ok() {
                *r = again;
            }
        }
    }
    print_table(&rows);
    println!("measured in {:.1} s", start.elapsed().as_secs_f64());

    let text = std::fs::read_to_string(ledger_path()).unwrap_or_default();
    let ledger = read_ledger(&text);
    if std::env::var("CSGPIX_LEDGER").as_deref() == Ok("write") {
        let mut next = if only.is_some() {
            ledger
        } else {
            BTreeMap::new()
        };
        next.extend(now);
        std::fs::write(ledger_path(), write_ledger(&next)).unwrap();
        println!("wrote {} ({} rows)", ledger_path().display(), next.len());
        return;
    }
    let (worse, better) = compare_ledger(&ledger, &now, only.is_none());
    for b in &better {
        println!("improved: {b}");
    }
    assert!(
        worse.is_empty(),
        "against vectors/designs/ledger.tsv (rewrite it with CSGPIX_LEDGER=write once a \
         change is meant):\n{}",
        worse.join("\n")
    );
}

/// The comparison itself: what the ledger guards, on rows made up here.
#[test]
fn ledger_comparison_flags_regressions_only() {
    let acc = |w, f| Entry::Accepted { word: w, float: f };
    let ledger: BTreeMap<String, Entry> = [
        ("a", acc(0.9990, 1.0)),
        ("b", acc(0.9500, 0.9600)),
        ("c", Entry::Refused("x.csg:1:1: no".into())),
        ("d", acc(1.0, 1.0)),
        ("gone", acc(1.0, 1.0)),
    ]
    .into_iter()
    .map(|(n, e)| (n.to_string(), e))
    .collect();
    let now: BTreeMap<String, Entry> = [
        ("a", acc(0.9981, 1.0)),
        ("b", acc(0.9489, 0.9700)),
        ("c", acc(0.99, 0.999)),
        ("d", Entry::Refused("x.csg:2:1: no".into())),
        ("new", acc(1.0, 1.0)),
    ]
    .into_iter()
    .map(|(n, e)| (n.to_string(), e))
    .collect();
    let (worse, better) = compare_ledger(&ledger, &now, true);
    assert_eq!(
        worse,
        [
            "b: IoU word 0.9489 < ledger 0.9500",
            "d: accepted in the ledger, now refused: x.csg:2:1: no",
            "new: not in the ledger",
            "gone: in the ledger but not in the corpus",
        ]
    );
    assert_eq!(
        better,
        [
            "b: IoU float 0.9600 -> 0.9700",
            "c: newly accepted (IoU word 0.9900, float 0.9990)"
        ]
    );
    // The ledger reads back what it writes.
    assert_eq!(read_ledger(&write_ledger(&ledger)), ledger);
}
