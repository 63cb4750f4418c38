//! Whole processes (`--process`): `csgpix voxelize` from start to exit against a floor
//! process that allocates, fills and writes the same NRRD bytes and exits, for a new output
//! and for one that replaces the last run's, in the same run.
//!
//! What a process pays that the in-process floor section does not see is its end: `close`
//! and the rename over an old output, where a file system may write the file out before it
//! returns (ext4's `auto_da_alloc`: crates/output/src/replace.rs). Each case is run
//! [`ROUNDS`] times after a `sync(2)` (untimed, so that no run waits for an earlier one's
//! write-back) and reported as its best and its median; the ratios are of the bests, as the
//! floor is the least a run can cost.
//!
//! * floor, new: this bench's own binary run again as a child ([`FLOOR_CHILD`]): the scene
//!   loaded (to make its grid), N³ bytes allocated and every one written as in the floor
//!   section (`filled`), then the NRRD file written through a `BufWriter<File>`, every byte,
//!   created where no file was, and the process ends.
//! * floor, replace: the same, its last file removed first (the cheapest way to replace a
//!   file that is written in place: `File::create` over it truncates it, which makes ext4
//!   write the new one out on `close`).
//! * csgpix, new and replace: `csgpix voxelize SCENE --res NxNxN -o v.nrrd` (the same grid
//!   as the floor's), without and then over its last output; and replace with `--sync`, which
//!   puts the file on the disk before it replaces the old one.

use std::path::Path;
use std::process::Command;
use std::time::Instant;

use serde_json::{json, Map, Value};

use super::floor::{filled, write_every_byte, SCENES};

/// The environment variable that makes this binary the floor's child: `SCENE|N|OUT`, the
/// scene's path, N and the NRRD file to write (an old one there removed first).
pub const FLOOR_CHILD: &str = "CSGPIX_BENCH_FLOOR_CHILD";

/// Runs of each case.
pub const ROUNDS: usize = 3;

/// The scenes of the section: the floor section's solid scenes (figure-5.6's dataset makes
/// its run the voxelizer's, not the write's).
const PROCESS_SCENES: [&str; 2] = [SCENES[0], SCENES[1]];

/// The floor's child: called first thing in `main` when [`FLOOR_CHILD`] is set.
pub fn floor_child(spec: &str) {
    let [scene, n, out]: [&str; 3] = spec
        .splitn(3, '|')
        .collect::<Vec<_>>()
        .try_into()
        .expect("SCENE|N|OUT");
    let n: usize = n.parse().expect("N");
    let loaded = csgpix::voxel::sampled::load_scene(Path::new(scene)).expect("the scene");
    let grid = loaded.grid([n; 3]).expect("grid");
    let voxels = filled(&grid);
    let out = Path::new(out);
    match std::fs::remove_file(out) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => panic!("remove {out:?}: {e}"),
        _ => {}
    }
    write_every_byte(out, &grid, &voxels, "floor");
}

/// The section: every scene of [`PROCESS_SCENES`] at every size.
pub fn process(sizes: &[usize], quick: bool, say: &dyn Fn(String)) -> Value {
    let dir = tempfile::tempdir().expect("temporary directory");
    let rounds = if quick { 1 } else { ROUNDS };
    say(format!(
        "process: sizes {sizes:?}, {rounds} round(s) of each case after sync(2)"
    ));
    let mut scenes = Map::new();
    for name in PROCESS_SCENES {
        let mut per = Map::new();
        for &n in sizes {
            per.insert(n.to_string(), scene_at(name, n, rounds, dir.path(), say));
        }
        scenes.insert(name.to_string(), Value::Object(per));
    }
    json!({"sizes": sizes, "rounds": rounds, "scenes": scenes})
}

/// A case: its name, its command, and what is done before each run (untimed).
type Case<'a> = (&'a str, &'a dyn Fn() -> Command, &'a dyn Fn());

/// The five cases for one scene at N³, in rounds.
fn scene_at(name: &str, n: usize, rounds: usize, dir: &Path, say: &dyn Fn(String)) -> Value {
    let scene = super::floor::scene_path(name);
    let floor_out = dir.join("floor.nrrd");
    let csg_out = dir.join("v.nrrd");
    let me = std::env::current_exe().expect("this bench's binary");
    let floor = || {
        let mut c = Command::new(&me);
        let spec = format!("{}|{n}|{}", scene.display(), floor_out.display());
        c.env(FLOOR_CHILD, spec);
        c
    };
    let csgpix = |sync: bool| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_csgpix"));
        c.arg("voxelize").arg(&scene).arg("--res");
        c.arg(format!("{n}x{n}x{n}")).arg("-o").arg(&csg_out);
        if sync {
            c.arg("--sync");
        }
        c
    };
    let gone = |p: &Path| {
        let _ = std::fs::remove_file(p);
    };
    let cases: [Case; 5] = [
        ("floor_new", &floor, &|| gone(&floor_out)),
        ("floor_replace", &floor, &|| {}),
        ("csgpix_new", &|| csgpix(false), &|| gone(&csg_out)),
        ("csgpix_replace", &|| csgpix(false), &|| {}),
        ("csgpix_replace_sync", &|| csgpix(true), &|| {}),
    ];
    let mut times = vec![Vec::new(); cases.len()];
    for _ in 0..rounds {
        for (i, (_, cmd, before)) in cases.iter().enumerate() {
            before();
            times[i].push(timed_process(&mut cmd()));
        }
    }
    gone(&floor_out);
    gone(&csg_out);
    let mut figures = Map::new();
    for ((case, _, _), t) in cases.iter().zip(&mut times) {
        t.sort_by(f64::total_cmp);
        figures.insert(
            case.to_string(),
            json!({"best_s": t[0], "median_s": t[t.len() / 2], "runs_s": t}),
        );
    }
    let best = |c: &str| figures[c]["best_s"].as_f64().unwrap_or(f64::NAN);
    let new = best("csgpix_new") / best("floor_new");
    let replace = best("csgpix_replace") / best("floor_replace");
    say(format!(
        "process {name} {n}^3 (best of {rounds}): floor new {:.3} s, replace {:.3} s; csgpix \
         new {:.3} s ({new:.2}x floor), replace {:.3} s ({replace:.2}x floor), replace --sync \
         {:.3} s",
        best("floor_new"),
        best("floor_replace"),
        best("csgpix_new"),
        best("csgpix_replace"),
        best("csgpix_replace_sync"),
    ));
    figures.insert("new_over_floor".into(), json!(new));
    figures.insert("replace_over_floor".into(), json!(replace));
    Value::Object(figures)
}

/// Wall seconds of `cmd` from spawn to exit, after a `sync(2)`; it must succeed.
fn timed_process(cmd: &mut Command) -> f64 {
    // SAFETY: sync(2) takes no arguments and cannot fail.
    unsafe { libc::sync() };
    let t0 = Instant::now();
    let out = cmd.output().expect("spawn");
    let t = t0.elapsed().as_secs_f64();
    assert!(
        out.status.success(),
        "{cmd:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    t
}

/// The summary lines: each scene and size's ratios.
pub fn summary(v: &Value) -> Vec<String> {
    let mut lines = Vec::new();
    let Some(scenes) = v["scenes"].as_object() else {
        return lines;
    };
    for (name, sizes) in scenes {
        for (n, f) in sizes.as_object().into_iter().flatten() {
            lines.push(format!(
                "summary process {name} {n}^3: csgpix/floor new {:.2}, replace {:.2}",
                f["new_over_floor"].as_f64().unwrap_or(f64::NAN),
                f["replace_over_floor"].as_f64().unwrap_or(f64::NAN),
            ));
        }
    }
    lines
}
