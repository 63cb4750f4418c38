//! Every command's outputs, byte for byte, against those of a reference binary.
//!
//! `tests/data/identity.txt` holds, for each case below, the exit status and the length and
//! FNV-1a 64 digest of every file the command writes, of its standard output and of its
//! standard error, as the `csgpix` binary built at commit 78e15d7 (the last one before the
//! source was split into crates) wrote them, except for lines re-recorded on purpose since:
//! the `--json` reports of the voxelize cases and `bad-memory`'s message when the run route
//! became the default (its route name, counts per run and memory estimate; every volume
//! unchanged), and `bad-memory`'s message again when the run route's NRRD output came to be
//! written slice by slice (the memory estimate without the volume; the files unchanged), and
//! the `--slices` PNGs when they became indexed PNGs whose pixel indices are the label codes,
//! and the voxelize cases' NRRD files when volumes came to say `space: 3D-right-handed` (8
//! bytes shorter; the voxels unchanged; the cases give `--res` per axis since `--res N` came
//! to mean the longest side), and `bad-prim`'s message when `--expr` errors came to give the
//! line and column (`--expr:1:3: primitive …`), and `voxelize-expr`'s `--json` report when a
//! dataset's runs came to be counted (its memory estimate, 18,197,312 → 17,368,484; the volume
//! unchanged), and the `--json` reports of `voxelize-fig52` and `voxelize-fig56-grey` when
//! `--preview` came to be counted in the estimate (17,463,104 → 18,725,696 and 16,950,016 →
//! 18,104,896, by `plan::preview_bytes` exactly; every other byte unchanged), and the five
//! voxelize cases' `--json` reports when the planes a run holds came to be counted in the
//! estimate (`Slicer::planes_bytes`; figure-5.2's 17,672,768 → 17,707,616; every other byte
//! unchanged), and the standard output of the ten voxelize cases, `requirements-twelve`,
//! `requirements-text` and `throughput-scene` and `study-small`'s CSV when a solid's slice list
//! stopped repeating as silhouette planes the sides it stands on perpendicular to the screen
//! (`project::closed_list`: fewer planes, so fewer clocks, slices/s and estimate bytes;
//! voxelize-fig52's clocks 314,580 → 187,180; every volume, image and other file unchanged),
//! and the five voxelize cases' `--json` reports when a solid's faces came to be held in one
//! vector of 32-bit indices (`scene::solid::Faces`: the estimate's solids are fewer bytes,
//! figure-5.2's 17,486,176 → 17,481,120; every other byte unchanged), and the `--json`
//! reports of `voxelize-fig52`, `voxelize-hollow-voxel` and `voxelize-expr` when the run route
//! came to copy a column whose primitive runs are its left neighbour's instead of evaluating
//! its segments again (`ops`' `comparisons` and `label_writes`: figure-5.2's 5,918 → 641;
//! every volume and other byte unchanged), and the `--json` reports of `voxelize-fig52`,
//! `voxelize-hollow-voxel` and `voxelize-expr` and `bad-memory`'s message when the run
//! route's bound on a panel's runs came to count each primitive on the columns of its
//! outline only (`runs::primitive_runs`: figure-5.2's estimate 18,743,712 → 18,479,378,
//! bad-memory's 608 → 585 MiB; every other byte unchanged).
//! A refactoring that changes no behaviour leaves every line equal. Timings (`*seconds*`, `*_s` JSON fields, `time` lines) are removed from
//! standard output before digesting: they are the only bytes that differ from run to run.
//!
//! To record the file from another binary (after a change that alters outputs on purpose):
//! `CSGPIX_IDENTITY_RECORD=path/to/csgpix cargo test --release --test identity`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A case: its name, its arguments (`{out}` is a fresh output directory), and the files it
/// writes there.
struct Case {
    name: &'static str,
    args: &'static [&'static str],
    files: &'static [&'static str],
}

const fn case(
    name: &'static str,
    args: &'static [&'static str],
    files: &'static [&'static str],
) -> Case {
    Case { name, args, files }
}

const CASES: &[Case] = &[
    case(
        "render-cube-cycle",
        &[
            "render",
            "vectors/thesis/cube.dl",
            "-o",
            "{out}/c.png",
            "--json",
        ],
        &["c.png"],
    ),
    case(
        "render-cube-word",
        &[
            "render",
            "vectors/thesis/cube.dl",
            "--model",
            "word",
            "-o",
            "{out}/c.png",
        ],
        &["c.png"],
    ),
    case(
        "render-cube-float",
        &[
            "render",
            "vectors/thesis/cube.dl",
            "--model",
            "float",
            "-o",
            "{out}/c.png",
        ],
        &["c.png"],
    ),
    case(
        "render-printed",
        &[
            "render",
            "vectors/thesis/cube.dl",
            "--equations",
            "printed",
            "--size",
            "64x64",
            "-o",
            "{out}/c.png",
        ],
        &["c.png"],
    ),
    case(
        "render-clip",
        &[
            "render",
            "vectors/thesis/box1-corrected.dl",
            "vectors/thesis/box2.dl",
            "--clip",
            "A.!B",
            "--size",
            "96x96",
            "-o",
            "{out}/c.png",
        ],
        &["c.png"],
    ),
    case(
        "render-vcd",
        &[
            "render",
            "vectors/thesis/cube.dl",
            "--size",
            "32x32",
            "--vcd",
            "{out}/w.vcd",
            "--probe",
            "10,10;20,5",
            "-o",
            "{out}/c.png",
        ],
        &["c.png", "w.vcd"],
    ),
    case(
        "render-logo",
        &[
            "render",
            "vectors/scenes/csg-logo.csg",
            "--shade",
            "--view",
            "iso",
            "--size",
            "128x128",
            "-o",
            "{out}/l.png",
            "--json",
        ],
        &["l.png"],
    ),
    case(
        "render-panel",
        &[
            "render",
            "vectors/scenes/twelve.csg",
            "--panel",
            "32x32",
            "--size",
            "96x96",
            "-o",
            "{out}/t.png",
            "--json",
        ],
        &["t.png"],
    ),
    case(
        "voxelize-fig52",
        &[
            "voxelize",
            "vectors/scenes/figure-5.2.csg",
            "--res",
            "32x32x32",
            "--slices",
            "{out}/s",
            "--preview",
            "{out}/p.png",
            "--mesh",
            "{out}/m.stl",
            "-o",
            "{out}/v.nrrd",
            "--json",
        ],
        &[
            "v.nrrd",
            "p.png",
            "m.stl",
            "s/slice-0000.png",
            "s/slice-0016.png",
            "s/slice-0031.png",
        ],
    ),
    case(
        "voxelize-hollow-voxel",
        &[
            "voxelize",
            "vectors/scenes/hollow-cube.csg",
            "--voxel",
            "0.5",
            "--pad",
            "2",
            "--mesh",
            "{out}/m.obj",
            "-o",
            "{out}/v.nrrd",
            "--json",
        ],
        &["v.nrrd", "m.obj"],
    ),
    case(
        "voxelize-twelve-cycle",
        &[
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "16x16x16",
            "--model",
            "cycle",
            "-o",
            "{out}/v.nrrd",
            "--json",
        ],
        &["v.nrrd"],
    ),
    case(
        "voxelize-twelve-float-slab",
        &[
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "40x40x40",
            "--model",
            "float",
            "--sampling",
            "slab",
            "--mesh",
            "{out}/m.ply",
            "-o",
            "{out}/v.nrrd",
        ],
        &["v.nrrd", "m.ply"],
    ),
    case(
        "voxelize-tree",
        &[
            "voxelize",
            "vectors/scenes/csg-logo.csg",
            "--res",
            "24x20x28",
            "--eval",
            "tree",
            "-o",
            "{out}/v.nrrd",
        ],
        &["v.nrrd"],
    ),
    case(
        "voxelize-stack",
        &[
            "voxelize",
            "vectors/scenes/cube-minus-cylinder.csg",
            "--res",
            "24x24x24",
            "--eval",
            "stack",
            "--route",
            "array",
            "-o",
            "{out}/v.nrrd",
        ],
        &["v.nrrd"],
    ),
    case(
        "voxelize-fig56-grey",
        &[
            "voxelize",
            "vectors/scenes/figure-5.6.csg",
            "--res",
            "40x40x40",
            "--grey",
            "--preview",
            "{out}/p.png",
            "-o",
            "{out}/v.nrrd",
            "--json",
        ],
        &["v.nrrd", "p.png"],
    ),
    case(
        "voxelize-blend",
        &[
            "voxelize",
            "vectors/scenes/figure-5.6.csg",
            "--res",
            "24x24x24",
            "--blend",
            "sum:0.5,0.25",
            "-o",
            "{out}/v.nrrd",
        ],
        &["v.nrrd"],
    ),
    case(
        "voxelize-expr",
        &[
            "voxelize",
            "--expr",
            "H-(A+B)",
            "--prim",
            "H=vectors/scenes/phantom.nrrd,threshold=300",
            "--prim",
            "A=vectors/scenes/hollow-cube.csg",
            "--prim",
            "B=vectors/scenes/table-7.1-cube.csg",
            "--res",
            "24x24x24",
            "-o",
            "{out}/v.nrrd",
            "--json",
        ],
        &["v.nrrd"],
    ),
    case(
        "voxelize-bounds",
        &[
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "20x20x20",
            "--bounds=-15,-15,-15,15,15,15",
            "--word",
            "10/11/12",
            "-o",
            "{out}/v.nrrd",
        ],
        &["v.nrrd"],
    ),
    case(
        "phantom",
        &["phantom", "-o", "{out}/h.nrrd", "--size", "24"],
        &["h.nrrd"],
    ),
    case(
        "phantom-raw",
        &[
            "phantom",
            "-o",
            "{out}/h.nrrd",
            "--size",
            "16",
            "--encoding",
            "raw",
        ],
        &["h.nrrd"],
    ),
    case(
        "sculpt-carve",
        &[
            "sculpt",
            "vectors/scenes/twelve.csg",
            "--res",
            "64x64x64",
            "--bounds=-15,-15,-15,15,15,15",
            "--tool",
            "sphere:3",
            "--path",
            "vectors/paths/carve.csv",
            "--forces",
            "{out}/f.csv",
            "-o",
            "{out}/c.stl",
        ],
        &["c.stl", "f.csv"],
    ),
    case(
        "sculpt-add-nrrd",
        &[
            "sculpt",
            "vectors/scenes/phantom.nrrd",
            "--threshold",
            "300",
            "--tool",
            "sphere:2",
            "--add",
            "--path",
            "vectors/paths/carve.csv",
            "--stiffness",
            "0.5",
            "-o",
            "{out}/g.obj",
        ],
        &["g.obj"],
    ),
    case("blist-fig44", &["blist", "(A+B)-((C+(D-E)).(F+G))"], &[]),
    case(
        "blist-json-trace",
        &[
            "blist",
            "(A+B)-((C+(D-E)).(F+G))",
            "--json",
            "--trace",
            "0100110",
        ],
        &[],
    ),
    case(
        "requirements-twelve",
        &[
            "requirements",
            "vectors/scenes/twelve.csg",
            "--res",
            "32x32x32",
            "--json",
        ],
        &[],
    ),
    case(
        "requirements-text",
        &[
            "requirements",
            "vectors/scenes/csg-logo.csg",
            "--precision",
            "0.01",
        ],
        &[],
    ),
    case(
        "study-small",
        &[
            "study",
            "vectors/scenes/cube-minus-cylinder.csg",
            "--bits",
            "6,10",
            "--fragments",
            "8",
            "--slabs",
            "16",
            "--models",
            "word,float",
            "--res",
            "16",
            "-o",
            "{out}/st",
        ],
        &["st/study.csv"],
    ),
    case("verify-select", &["verify-select", "--json"], &[]),
    case(
        "verify-select-printed",
        &["verify-select", "--equations", "printed"],
        &[],
    ),
    case("gen-vectors-check", &["gen-vectors", "--check"], &[]),
    case("export-verilog-check", &["export-verilog", "--check"], &[]),
    case("throughput", &["throughput", "--json"], &[]),
    case(
        "throughput-scene",
        &[
            "throughput",
            "--scene",
            "vectors/scenes/twelve.csg",
            "--view",
            "top",
            "--screen",
            "128x128",
            "--simulate",
            "--plots",
            "{out}/pl",
            "--json",
        ],
        &["pl/figure-2.12.png", "pl/figure-5.11.png"],
    ),
    case(
        "throughput-area",
        &["throughput", "--area", "100000", "--lut", "6"],
        &[],
    ),
    case(
        "bad-dl",
        &["render", "tests/data/identity/bad.dl", "-o", "{out}/x.png"],
        &[],
    ),
    case(
        "bad-csg",
        &[
            "voxelize",
            "tests/data/identity/bad.csg",
            "--res",
            "8x8x8",
            "-o",
            "{out}/x.nrrd",
        ],
        &[],
    ),
    case("bad-expr", &["blist", "(A+B"], &[]),
    case(
        "bad-clip",
        &[
            "render",
            "vectors/thesis/cube.dl",
            "--clip",
            "A.!",
            "-o",
            "{out}/x.png",
        ],
        &[],
    ),
    case(
        "bad-prim",
        &[
            "voxelize",
            "--expr",
            "A-B",
            "--prim",
            "A=vectors/scenes/hollow-cube.csg",
            "--res",
            "8x8x8",
            "-o",
            "{out}/x.nrrd",
        ],
        &[],
    ),
    case(
        "bad-word",
        &[
            "render",
            "vectors/scenes/twelve.csg",
            "--word",
            "10/3/10",
            "-o",
            "{out}/x.png",
        ],
        &[],
    ),
    case(
        "bad-tool",
        &[
            "sculpt",
            "vectors/scenes/twelve.csg",
            "--res",
            "16x16x16",
            "--tool",
            "cube:3",
            "--path",
            "vectors/paths/carve.csv",
            "-o",
            "{out}/x.stl",
        ],
        &[],
    ),
    case(
        "bad-no-bounds",
        &[
            "voxelize",
            "tests/data/identity/empty.csg",
            "--res",
            "8x8x8",
            "-o",
            "{out}/x.nrrd",
        ],
        &[],
    ),
    case(
        "bad-bounds",
        &[
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "8x8x8",
            "--bounds=0,0,0,0,1,1",
            "-o",
            "{out}/x.nrrd",
        ],
        &[],
    ),
    case(
        "bad-memory",
        &[
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "2000x2000x2000",
            "--max-memory",
            "64",
            "-o",
            "{out}/x.nrrd",
        ],
        &[],
    ),
];

/// FNV-1a, 64 bits.
fn fnv(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// Standard output without the timings, and with the output directory named `{out}`.
fn steady(stdout: &[u8], out: &Path) -> Vec<u8> {
    let text = String::from_utf8_lossy(stdout).replace(&out.display().to_string(), "{out}");
    let timing = |l: &str| {
        let l = l.to_ascii_lowercase();
        l.contains("seconds") || l.contains("_s\"") || l.contains("time")
    };
    let kept: Vec<String> = text.lines().filter(|l| !timing(l)).map(untimed).collect();
    kept.join("\n").into_bytes()
}

/// A line with every duration (a number before `s`, `ms`, `us` or `µs`) as `T`.
fn untimed(line: &str) -> String {
    let words: Vec<&str> = line.split(' ').collect();
    let unit = |w: &str| {
        let w = w.trim_end_matches(|c: char| c.is_ascii_punctuation());
        matches!(w, "s" | "ms" | "us" | "µs")
    };
    let number = |w: &str| {
        w.trim_matches(|c: char| !c.is_ascii_digit())
            .parse::<f64>()
            .is_ok()
    };
    (0..words.len())
        .map(|i| match words.get(i + 1) {
            Some(next) if number(words[i]) && unit(next) => "T",
            _ => words[i],
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// A written file's bytes without what depends on the machine's speed: the last column of
/// `sculpt --forces` (`micros`) and of `study` (`wall_s`).
fn steady_file(name: &str, bytes: Vec<u8>) -> Vec<u8> {
    let text = String::from_utf8_lossy(&bytes);
    let first = text.lines().next().unwrap_or("");
    if !(name.ends_with(".csv") && (first.ends_with(",micros") || first.ends_with(",wall_s"))) {
        return bytes;
    }
    let rows: Vec<&str> = text
        .lines()
        .map(|l| l.rsplit_once(',').map_or(l, |(keep, _)| keep))
        .collect();
    rows.join("\n").into_bytes()
}

/// One case's record lines, run with `bin` from the repository's root.
fn record(bin: &Path, c: &Case) -> String {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path();
    let args: Vec<String> = c
        .args
        .iter()
        .map(|a| a.replace("{out}", &out.display().to_string()))
        .collect();
    let o = Command::new(bin)
        .args(&args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("RAYON_NUM_THREADS", "2")
        .output()
        .unwrap();
    let mut s = String::new();
    let mut line = |what: &str, b: &[u8]| {
        writeln!(s, "{} {what} {} {:016x}", c.name, b.len(), fnv(b)).unwrap()
    };
    line(&format!("status={}", o.status.code().unwrap_or(-1)), &[]);
    line("stdout", &steady(&o.stdout, out));
    let stderr = String::from_utf8_lossy(&o.stderr).replace(&out.display().to_string(), "{out}");
    line("stderr", stderr.as_bytes());
    for f in c.files {
        match std::fs::read(out.join(f)) {
            Ok(b) => line(f, &steady_file(f, b)),
            Err(_) => line(&format!("{f}=missing"), &[]),
        }
    }
    s
}

fn golden_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/identity.txt")
}

#[test]
fn every_output_equals_the_reference_binarys_output() {
    let record_with = std::env::var_os("CSGPIX_IDENTITY_RECORD");
    let bin = match &record_with {
        Some(b) => PathBuf::from(b),
        None => PathBuf::from(env!("CARGO_BIN_EXE_csgpix")),
    };
    let got: String = CASES.iter().map(|c| record(&bin, c)).collect();
    if record_with.is_some() {
        std::fs::write(golden_path(), &got).unwrap();
        return;
    }
    let want = std::fs::read_to_string(golden_path()).unwrap();
    let differ: Vec<String> = want
        .lines()
        .zip(got.lines())
        .filter(|(w, g)| w != g)
        .map(|(w, g)| format!("want {w}\n got {g}"))
        .collect();
    assert!(
        differ.is_empty() && want.lines().count() == got.lines().count(),
        "{} lines differ from the reference:\n{}",
        differ.len(),
        differ.join("\n")
    );
}

/// The record is not vacuous: each case ran and wrote what it names (a missing file or a
/// crash would show up as `=missing` or a status other than 0, 1 or 2).
#[test]
fn the_reference_record_is_complete() {
    let want = std::fs::read_to_string(golden_path()).unwrap();
    assert!(!want.contains("=missing"), "a reference case wrote nothing");
    for c in CASES {
        let status = want
            .lines()
            .find(|l| l.starts_with(&format!("{} status=", c.name)))
            .unwrap_or_else(|| panic!("{} not recorded", c.name));
        let code = match c.name {
            n if n.starts_with("bad-") => "status=2 ",
            // The printed equations mismatch 26 care rows (docs/select-logic.md): exit 1.
            "verify-select-printed" => "status=1 ",
            _ => "status=0 ",
        };
        assert!(status.contains(code), "{status}");
    }
}
