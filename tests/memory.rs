//! Memory limits through the CLI: estimates checked before allocating, `--max-memory` whose
//! default follows `ulimit -v`, limits that cannot wrap, bounded `--threads` (docs/memory.md).

mod common;
use common::estimate_mib;
#[cfg(target_os = "linux")]
use common::peak_mib;
use std::path::Path;
use std::process::Command;

/// Run csgpix under `ulimit -v KIB` (address space), in a temporary directory beside the
/// crate's files, and return its output.
fn under_ulimit(kib: u64, args: &[&str]) -> std::process::Output {
    let cmd = format!("ulimit -v {kib}; exec \"$0\" \"$@\"");
    Command::new("sh")
        .arg("-c")
        .arg(cmd)
        .arg(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run sh")
}

/// The memory estimate (bytes) a run reports in `--json`: where `--max-memory 1` is refused by
/// a limit that follows it (a dataset's samples, the reader's vertices) before the run's own.
fn json_estimate(args: &[&str]) -> u64 {
    let out = common::csgpix(&[args, &["--json"]].concat());
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    report["memory_estimate"].as_u64().unwrap()
}

fn refused(out: &std::process::Output, needle: &str) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains(needle), "{err}");
}

#[test]
fn large_runs_are_refused_under_ulimit_before_allocating() {
    let dir = tempfile::tempdir().unwrap();
    let o = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let (png, nrrd, phantom, stl) = (o("r.png"), o("v.nrrd"), o("p.nrrd"), o("s.stl"));
    let cases: Vec<Vec<&str>> = vec![
        vec![
            "render",
            "vectors/thesis/cube.dl",
            "--size",
            "8192x8192",
            "-o",
            &png,
        ],
        vec![
            "render",
            "vectors/thesis/cube.dl",
            "--size",
            "8192x8192",
            "--model",
            "word",
            "-o",
            &png,
        ],
        vec![
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "1500x1500x1500",
            "--route",
            "intervals",
            "-o",
            &nrrd,
        ],
        // The run route streams the file, but a preview needs the volume.
        vec![
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "1500x1500x1500",
            "--preview",
            &png,
            "-o",
            &nrrd,
        ],
        vec!["phantom", "--size", "1024", "-o", &phantom],
        vec![
            "requirements",
            "vectors/scenes/twelve.csg",
            "--res",
            "16384x16384x16384",
        ],
        vec![
            "sculpt",
            "vectors/scenes/twelve.csg",
            "--res",
            "1500x1500x1500",
            "--tool",
            "sphere:1",
            "--path",
            "vectors/paths/carve.csv",
            "-o",
            &stl,
        ],
    ];
    // 1 GiB of address space: the default --max-memory is then 7/8 GiB.
    for args in cases {
        let out = under_ulimit(1 << 20, &args);
        refused(&out, "--max-memory");
    }
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none());
}

/// The run route writes the NRRD file slice by slice: a 1 GiB volume is written under 512 MiB
/// of address space, the bytes those of the volume held whole (the slab route's for csg-logo;
/// for figure-5.6, whose dataset the slab routes take seconds over, the run route's with the
/// volume held for a preview). figure-5.6 streams because its dataset's runs are counted, not
/// bounded by the slabs (its estimate was 1.8 GiB).
#[cfg(target_os = "linux")]
#[test]
fn a_streamed_volume_is_larger_than_the_address_space() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("p.png");
    let held_by = [
        ("csg-logo", vec!["--route", "intervals"]),
        ("figure-5.6", vec!["--preview", png.to_str().unwrap()]),
    ];
    for (scene, hold) in held_by {
        let (a, b) = (dir.path().join("a.nrrd"), dir.path().join("b.nrrd"));
        let file = format!("vectors/scenes/{scene}.csg");
        let args = |out: &Path| {
            let o = out.to_str().unwrap().to_string();
            let words = ["voxelize", &file, "--res", "1024x1024x1024", "-o", &o];
            words.map(String::from).to_vec()
        };
        let streamed = args(&a);
        let streamed: Vec<&str> = streamed.iter().map(String::as_str).collect();
        let out = under_ulimit(512 << 10, &streamed);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{scene}: {err}");
        let whole = args(&b);
        let mut whole: Vec<&str> = whole.iter().map(String::as_str).collect();
        whole.extend(&hold);
        let held = common::csgpix(&whole);
        let err = String::from_utf8_lossy(&held.stderr);
        assert!(held.status.success(), "{scene}: {err}");
        let (x, y) = (std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
        assert!(
            x.len() > 1 << 30 && x == y,
            "{scene}: {} and {} bytes",
            x.len(),
            y.len()
        );
    }
}

/// The NRRD file is streamed wherever the runs' bound fits the limit, though it pass the
/// whole volume's (forty layers over every column of a 64³ grid: a run each, a bound above the
/// 256 KiB volume), and the volume is held only under a limit between the two bounds; a limit
/// below both is refused with the smaller. The same file either way.
#[test]
fn the_volume_is_held_only_where_the_streamed_bound_does_not_fit() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("layers.csg");
    let layers: String = (0..40)
        .map(|i| format!(" multmatrix([[1,0,0,0],[0,1,0,0],[0,0,1,{}],[0,0,0,1]]) cube(size = [10, 10, 1]);\n", 2 * i))
        .collect();
    std::fs::write(&scene, format!("union() {{\n{layers}}}\n")).unwrap();
    let out = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let run = |o: &str, limit: Option<u64>| {
        let mut args = vec![
            "voxelize",
            scene.to_str().unwrap(),
            "--res",
            "64x64x64",
            "-o",
            o,
        ];
        let limit = limit.map(|m| m.to_string());
        if let Some(m) = &limit {
            args.extend(["--max-memory", m.as_str()]);
        }
        json_estimate(&args)
    };
    let streamed = run(&out("s.nrrd"), None);
    // A limit just below the streamed bound (MiB, rounded down).
    let between = (streamed >> 20) - u64::from(streamed % (1 << 20) == 0);
    let held = run(&out("h.nrrd"), Some(between));
    assert!(held < streamed, "held {held}, streamed {streamed}");
    assert!(held <= between << 20, "held {held} over {between} MiB");
    let (a, b) = (
        std::fs::read(out("s.nrrd")).unwrap(),
        std::fs::read(out("h.nrrd")).unwrap(),
    );
    assert!(a == b && a.len() > 64 * 64 * 64);
    let below = (held >> 20).saturating_sub(1).to_string();
    let o = out("r.nrrd");
    let args = [
        "voxelize",
        scene.to_str().unwrap(),
        "--res",
        "64x64x64",
        "-o",
        &o,
    ];
    let refused_run = common::csgpix(&[&args[..], &["--max-memory", &below]].concat());
    refused(
        &refused_run,
        &format!("about {} MiB", held.div_ceil(1 << 20)),
    );
}

#[test]
fn a_difference_of_thousands_of_solids_is_refused_by_render_and_voxelized_in_blist() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("holes.csg");
    let mut text = String::from("difference() {\n cube(size = [10, 10, 10]);\n");
    for i in 0..5000 {
        let (x, y, z) = (i % 10, i / 10 % 10, i / 100 % 10);
        text += &format!(
            " multmatrix([[1,0,0,{x}],[0,1,0,{y}],[0,0,1,{z}],[0,0,0,1]]) cube(size = [0.5, 0.5, 0.5]);\n"
        );
    }
    std::fs::write(&scene, text + "}\n").unwrap();
    let s = scene.to_str().unwrap();
    let png = dir.path().join("h.png");
    let out = under_ulimit(
        1 << 20,
        &["render", s, "--size", "32x32", "-o", png.to_str().unwrap()],
    );
    // Refused from the tree before the 5,001 solids are projected: the bound is the lower one.
    refused(&out, "holes.csg: the clipping program would have at least");
    assert!(!png.exists());
    let out = under_ulimit(1 << 20, &["requirements", s, "--res", "16x16x16"]);
    refused(&out, "clipping program");
    // Blist is linear in the solids: the same scene voxelizes under the same limit.
    let nrrd = dir.path().join("h.nrrd");
    let out = under_ulimit(
        1 << 20,
        &[
            "voxelize",
            s,
            "--res",
            "16x16x16",
            "-o",
            nrrd.to_str().unwrap(),
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(nrrd.exists());
}

/// A difference nested 900 deep (A − (B − (C − …)): 450 products of up to 900 literals) is
/// refused by `throughput --scene` from its tree, before 900 solids are projected onto its
/// screen (which took 12 s to end in the same refusal).
#[test]
fn throughput_refuses_a_deep_difference_before_projecting_it() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("deep.csg");
    let mut text = String::new();
    for i in 0..900 {
        text += &format!(
            "difference(){{multmatrix([[1,0,0,{}],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(size=[100,100,100]);",
            i as f64 * 0.01
        );
    }
    text += "cube(size=[1,1,1]);";
    text += &"}".repeat(900);
    std::fs::write(&scene, text).unwrap();
    let t0 = std::time::Instant::now();
    let out = under_ulimit(1 << 20, &["throughput", "--scene", scene.to_str().unwrap()]);
    refused(&out, "deep.csg: the clipping program would have at least");
    let secs = t0.elapsed().as_secs_f64();
    assert!(secs < 5.0, "{secs} s to refuse");
}

#[test]
fn limits_that_would_wrap_and_unbounded_threads_are_refused() {
    let nrrd = std::env::temp_dir().join("csgpix-never-written.nrrd");
    let n = nrrd.to_str().unwrap();
    let base = [
        "voxelize",
        "vectors/scenes/twelve.csg",
        "--res",
        "8x8x8",
        "-o",
        n,
    ];
    for extra in [
        &["--max-memory", "18446744073709551615"][..],
        &["--max-memory", "8796093022209"],
        &["--max-memory", "0"],
        &["--threads", "0"],
        &["--threads", "100000"],
    ] {
        let out = under_ulimit(1 << 22, &[&base[..], extra].concat());
        refused(&out, extra[0]);
    }
    assert!(!Path::new(n).exists());
    // The largest limit is accepted and does not wrap into a small one.
    let out = under_ulimit(
        1 << 22,
        &[&base[..], &["--max-memory", "8796093022208"]].concat(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::remove_file(n).unwrap();
}

#[test]
fn the_default_limit_follows_ulimit() {
    let out = under_ulimit(1 << 20, &["voxelize", "--help"]);
    let help = String::from_utf8_lossy(&out.stdout);
    // 1 GiB less the process's own 64 MiB and 8 MiB a thread (crates/run/src/memory.rs).
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let default = 1024 - 64 - 8 * threads;
    assert!(help.contains(&format!("[default: {default}]")), "{help}");
}

/// Runs that used to abort under an address-space limit (SIGABRT, the staged file left):
/// the default limit now leaves room for the process itself, an explicit one above the
/// address space is lowered with a note, and an allocation that fails anyway ends the run
/// in one line. Each run succeeds or is refused (exit 2, one line besides the note), and
/// leaves nothing but its output.
#[cfg(target_os = "linux")]
#[test]
fn no_run_aborts_under_an_address_space_limit() {
    let dir = tempfile::tempdir().unwrap();
    let o = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let (nrrd, zarr, phantom) = (o("v.nrrd"), o("v.zarr"), o("p.nrrd"));
    let twelve = "vectors/scenes/twelve.csg";
    let cases: Vec<(u64, Vec<&str>)> = vec![
        (
            400_000,
            vec!["voxelize", twelve, "--res", "512", "-o", &nrrd],
        ),
        (
            1 << 20,
            vec!["voxelize", twelve, "--res", "860", "-o", &nrrd],
        ),
        (
            400_000,
            vec!["voxelize", twelve, "--res", "512", "-o", &zarr],
        ),
        (1 << 20, vec!["requirements", twelve, "--res", "4096"]),
        (
            4 << 20,
            vec![
                "phantom",
                "--size",
                "1024",
                "--max-memory",
                "8796093022208",
                "-o",
                &phantom,
            ],
        ),
    ];
    for (kib, args) in cases {
        let out = under_ulimit(kib, &args);
        let err = String::from_utf8_lossy(&out.stderr);
        let code = out.status.code();
        assert!(
            matches!(code, Some(0 | 2)),
            "{args:?} under {kib} KiB: {code:?} {err}"
        );
        let lines: Vec<&str> = err
            .lines()
            .filter(|l| !l.starts_with("csgpix: note: "))
            .collect();
        if code == Some(2) {
            assert_eq!(lines.len(), 1, "{args:?}: {err}");
        }
        let left: Vec<String> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.starts_with('.'))
            .collect();
        assert!(left.is_empty(), "{args:?} left {left:?}");
    }
    // The explicit limit above the address space was lowered, and said so.
    let out = under_ulimit(
        4 << 20,
        &[
            "phantom",
            "--size",
            "1024",
            "--max-memory",
            "8796093022208",
            "-o",
            &phantom,
        ],
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("csgpix: note: --max-memory 8796093022208 is above"),
        "{err}"
    );
    assert!(err.contains("ulimit -v"), "{err}");
}

/// Every estimate is above the peak it stands for (docs/memory.md's tables, at sizes a test
/// can afford). Before, render counted the array alone (20 MiB at 1024², peak 109 MiB),
/// voxelize one volume where two were held (159 MiB at 512³, peak 232 MiB), and the octree
/// stores none of their nodes (sculpt at 256: 35 MiB, peak 97 MiB).
#[cfg(target_os = "linux")]
#[test]
fn estimates_are_above_the_measured_peaks() {
    let dir = tempfile::tempdir().unwrap();
    let o = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let (png, nrrd, phantom, zarr) = (o("r.png"), o("v.nrrd"), o("p.nrrd"), o("v.zarr"));
    let (stl, verilog, study) = (o("s.stl"), o("verilog"), o("study"));
    let sphere = o("sphere.scad");
    std::fs::write(&sphere, "sphere(10, $fn = 400);").unwrap();
    let sculpt = |res| {
        vec![
            "sculpt",
            "vectors/scenes/twelve.csg",
            "--res",
            res,
            "--tool",
            "sphere:4",
            "--path",
            "vectors/paths/carve.csv",
            "-o",
            &stl,
        ]
    };
    let store = |kind| {
        vec![
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "256",
            "--store",
            kind,
            "-o",
            &nrrd,
        ]
    };
    let runs: Vec<Vec<&str>> = vec![
        // The octree's nodes, the sculptor's mesh and the path's splits, bounded from the
        // scene (docs/memory.md, "Octree nodes"): 20 MiB for a peak of 31, 35 for 97 before.
        sculpt("128"),
        sculpt("256"),
        store("pointer"),
        store("octree"),
        vec![
            "export-verilog",
            "--scene",
            "vectors/thesis/cube.dl",
            "--origin",
            "56,90",
            "-o",
            &verilog,
        ],
        // A long array: the expected states are written a clock at a time (held whole, they
        // were 878 MiB estimated against an 887 MiB peak at 65536x1).
        vec![
            "export-verilog",
            "--scene",
            "vectors/thesis/cube.dl",
            "--size",
            "2048x2",
            "-o",
            &verilog,
        ],
        vec![
            "render",
            "vectors/thesis/cube.dl",
            "--size",
            "1024x1024",
            "-o",
            &png,
        ],
        vec![
            "render",
            "vectors/thesis/cube.dl",
            "--size",
            "1024x1024",
            "--model",
            "word",
            "-o",
            &png,
        ],
        vec![
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "512x512x512",
            "-o",
            &nrrd,
        ],
        // --format zarr: sharded with a pyramid of 2 levels (the defaults at 512³), and one
        // file a chunk, each run replacing the store of the one before.
        vec![
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "512x512x512",
            "--format",
            "zarr",
            "-o",
            &zarr,
        ],
        vec![
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "512x512x512",
            "--format",
            "zarr",
            "--shard",
            "none",
            "-o",
            &zarr,
        ],
        // By bricks of 128² columns (shards of 2 chunks a side), 16 a chunk row.
        vec![
            "voxelize",
            "vectors/scenes/csg-logo.csg",
            "--res",
            "512x512x512",
            "--format",
            "zarr",
            "--shard",
            "2",
            "-o",
            &zarr,
        ],
        // The preview's views and image beside the volume: 727 MiB estimated for a 753 MiB
        // peak before they were counted.
        vec![
            "voxelize",
            "vectors/scenes/twelve.csg",
            "--res",
            "1024",
            "-o",
            &nrrd,
            "--preview",
            &png,
        ],
        vec!["phantom", "--size", "256", "-o", &phantom],
        // The sweep's largest voxelizations at once.
        vec!["study", "vectors/scenes/twelve.csg", "-o", &study],
        // A record and a bin a panel, 1,048,576 of them (the estimate was 0 before).
        vec![
            "throughput",
            "--scene",
            "vectors/scenes/twelve.csg",
            "--screen",
            "1024x1024",
            "--panel",
            "1x1",
        ],
        vec![
            "throughput",
            "--scene",
            "vectors/scenes/twelve.csg",
            "--screen",
            "512x512",
            "--simulate",
        ],
        vec![
            "requirements",
            "vectors/scenes/twelve.csg",
            "--res",
            "2048x2048x2048",
        ],
    ];
    for args in runs {
        let (estimate, peak) = (estimate_mib(&args), peak_mib(&args));
        assert!(
            estimate >= peak,
            "{args:?}: estimate {estimate} MiB, peak {peak} MiB"
        );
        eprintln!(
            "{}: estimate {estimate} MiB, peak {peak} MiB",
            args.join(" ")
        );
    }
    // A dataset's runs are counted and the file streamed (at 1024³ the estimate was 1.8 GiB
    // and the volume held). Its estimate from --json: under `--max-memory 1` the dataset's
    // sample limit refuses the file first.
    for res in ["512x512x512", "1024x1024x1024"] {
        let args = ["voxelize", "vectors/scenes/figure-5.6.csg", "--res", res];
        let args = [&args[..], &["-o", &nrrd]].concat();
        let estimate = json_estimate(&args) >> 20;
        let peak = peak_mib(&args);
        eprintln!("figure-5.6 at {res}: estimate {estimate} MiB, peak {peak} MiB");
        assert!(
            estimate >= peak,
            "{res}: estimate {estimate} MiB, peak {peak} MiB"
        );
        assert!(
            estimate < 256,
            "{res}: estimate {estimate} MiB, not streamed"
        );
    }
    // A solid of 80,000 faces: its faces, display list and plane words are held through the
    // run (Slicer::planes_bytes): 24 MiB estimated for a 33 MiB peak before they were counted.
    // Its estimate from --json: under `--max-memory 1` the reader's vertex limit refuses first.
    let args = ["voxelize", &sphere, "--res", "256", "-o", &nrrd];
    let (estimate, peak) = (json_estimate(&args) >> 20, peak_mib(&args));
    eprintln!("sphere($fn = 400) at 256: estimate {estimate} MiB, peak {peak} MiB");
    assert!(estimate >= peak, "estimate {estimate} MiB, peak {peak} MiB");
    // 900 circles of 1,080 fragments in one extrusion (the pulley plate's make-up): the
    // reader's outlines, freed before the run, stay with the process (CsgScene::reading_bytes):
    // 218 and 211 MiB estimated for peaks of 223 and 221 MiB before they were counted. Read as
    // one footprint (972,000 points, the default) and as prisms (`--footprints off`).
    let plate = o("plate.scad");
    std::fs::write(
        &plate,
        "$fn = 1080;\nlinear_extrude(2) for (x = [0 : 29], y = [0 : 29]) \
         translate([x * 3, y * 3]) circle(1);\n",
    )
    .unwrap();
    for (res, fp) in [
        ("64", "100000"),
        ("256", "100000"),
        ("64", "off"),
        ("256", "off"),
    ] {
        let args = [
            "voxelize",
            &plate,
            "--res",
            res,
            "--footprints",
            fp,
            "-o",
            &nrrd,
        ];
        let (estimate, peak) = (json_estimate(&args) >> 20, peak_mib(&args));
        eprintln!(
            "900 circles at {res}, --footprints {fp}: estimate {estimate} MiB, peak {peak} MiB"
        );
        assert!(
            estimate >= peak,
            "{res} --footprints {fp}: estimate {estimate} MiB, peak {peak} MiB"
        );
    }
}

/// Work by footprint: a slab with 10,000 square holes through it (10,001 primitives) costs
/// what its primitives cover, not primitives × pixels (that estimate was 5 GiB at 256³).
#[cfg(target_os = "linux")]
#[test]
fn ten_thousand_primitives_fit_by_their_footprints() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("holes.csg");
    let mut text = String::from("difference() {\n cube(size = [100, 100, 10]);\n");
    for i in 0..10_000 {
        let (x, y) = (i % 100, i / 100);
        text += &format!(
            " multmatrix([[1,0,0,{x}.25],[0,1,0,{y}.25],[0,0,1,2],[0,0,0,1]]) cube(size = [0.5, 0.5, 20]);\n"
        );
    }
    std::fs::write(&scene, text + "}\n").unwrap();
    let nrrd = dir.path().join("h.nrrd");
    let args = [
        "voxelize",
        scene.to_str().unwrap(),
        "--res",
        "256x256x256",
        "-o",
        nrrd.to_str().unwrap(),
    ];
    // The estimate from --json: under `--max-memory 1` the reader's vertex limit, which follows
    // the memory limit, refuses the scene before the run's estimate is reached.
    let estimate = json_estimate(&args).div_ceil(1 << 20);
    let peak = peak_mib(&args);
    eprintln!("10,001 primitives at 256³: estimate {estimate} MiB, peak {peak} MiB");
    assert!(estimate >= peak, "estimate {estimate} MiB, peak {peak} MiB");
    assert!(estimate <= 400, "estimate {estimate} MiB");
    // Every hole is cut: voxel centres inside the slab and outside every hole, as counted
    // here (the grid spans 0..100 × 0..100 × 0..22; no centre lies on a face).
    let (_, voxels) = csgpix::scene::nrrd::read(&std::fs::read(&nrrd).unwrap()).unwrap();
    let in_hole = |c: f64| (0.25..=0.75).contains(&(c - c.floor()));
    let centre = |i: usize, size: f64| (i as f64 + 0.5) * size / 256.0;
    let mut want = 0;
    for k in (0..256).filter(|&k| centre(k, 22.0) <= 10.0) {
        // The holes start at z = 2.
        let cut = centre(k, 22.0) >= 2.0;
        for j in 0..256 {
            for i in 0..256 {
                let hole = cut && in_hole(centre(i, 100.0)) && in_hole(centre(j, 100.0));
                want += usize::from(!hole);
            }
        }
    }
    let filled = voxels.iter().filter(|&&v| v != 0).count();
    assert_eq!(filled, want);
}

/// `text()` is charged by its outline's points while it is drawn (`TEXT_POINT_VERTICES`
/// scene vertices each, within the vertex budget `--max-memory` gives the reader): 3,000
/// characters under `--max-memory 50` are refused in one line before they are drawn (they
/// passed at a 138 MiB peak), 500 characters pass below the limit.
#[cfg(target_os = "linux")]
#[test]
fn text_is_drawn_within_the_memory_limit() {
    let dir = tempfile::tempdir().unwrap();
    let font = "vectors/fonts/LiberationSans-Regular.ttf";
    std::fs::copy(font, dir.path().join("LiberationSans-Regular.ttf")).unwrap();
    let scene = |n: usize| {
        // Letters and digits in a fixed, varied order.
        let chars: Vec<u8> = (b'a'..=b'z')
            .chain(b'A'..=b'Z')
            .chain(b'0'..=b'9')
            .collect();
        let s: String = (0..n).map(|i| chars[i * 7 % chars.len()] as char).collect();
        let path = dir.path().join(format!("t{n}.csg"));
        let text = format!(
            "linear_extrude(height = 2) {{ text(text = \"{s}\", size = 5, \
             font = \"Liberation Sans\"); }}\n"
        );
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_string()
    };
    let out = dir.path().join("v.nrrd");
    let o = out.to_str().unwrap();
    let stl = dir.path().join("s.stl").to_str().unwrap().to_string();
    let long = scene(3000);
    let args = [
        "voxelize",
        &long,
        "--res",
        "64",
        "-o",
        o,
        "--max-memory",
        "50",
    ];
    let refused = Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("points csgpix accepts"), "{err}");
    assert!(!out.exists());
    let short = scene(500);
    let args = [
        "voxelize",
        &short,
        "--res",
        "64",
        "-o",
        o,
        "--max-memory",
        "50",
    ];
    let peak = peak_mib(&args);
    assert!(out.exists(), "500 characters were not voxelized");
    assert!(
        peak <= 50,
        "500 characters: peak {peak} MiB over --max-memory 50"
    );
    // Without a limit, the run's estimate counts the text drawn (it was 42 MiB against a
    // 138 MiB peak at 3,000 characters), for voxelize and for sculpt.
    for n in [1000, 3000] {
        let text = scene(n);
        let voxelize = ["voxelize", &text, "--res", "64", "-o", o];
        let sculpt = [
            "sculpt",
            &text,
            "--res",
            "64",
            "--tool",
            "sphere:4",
            "--path",
            "vectors/paths/carve.csv",
            "-o",
            stl.as_str(),
        ];
        for args in [&voxelize[..], &sculpt[..]] {
            let (estimate, peak) = (json_estimate(args) >> 20, peak_mib(args));
            eprintln!(
                "{} at {n} characters: estimate {estimate} MiB, peak {peak} MiB",
                args[0]
            );
            assert!(
                estimate >= peak,
                "{args:?}: estimate {estimate} MiB, peak {peak} MiB"
            );
        }
    }
}
