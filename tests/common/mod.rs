//! Helpers shared by the integration tests: running the binary, its memory, OpenSCAD's
//! meshes; the random scenes are csgpix-testkit's.
// Each test crate uses only some of these.
#![allow(dead_code)]

use csgpix_testkit::iou;

/// Run the `csgpix` binary from the crate's root.
pub fn csgpix(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run csgpix")
}

/// A volume from a voxel predicate (1 inside, 0 outside; X fastest).
pub fn volume(dims: [usize; 3], f: impl Fn(usize, usize, usize) -> bool) -> csgpix::voxel::Volume {
    let mut voxels = Vec::with_capacity(dims.iter().product());
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                voxels.push(u8::from(f(x, y, z)));
            }
        }
    }
    csgpix::voxel::Volume { dims, voxels }
}

/// The estimate a run checks, in MiB: the number in its refusal under `--max-memory 1`.
pub fn estimate_mib(args: &[&str]) -> u64 {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .args(["--max-memory", "1"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    let after = err
        .split("needs about ")
        .nth(1)
        .unwrap_or_else(|| panic!("{err}"));
    after.split(' ').next().unwrap().parse().unwrap()
}

/// Run csgpix and return its peak resident memory in MiB (the kernel's ru_maxrss), through
/// GNU time (`/usr/bin/time`, installed by .ci/run): a process forked from this one starts
/// with this one's high-water mark, and keeps it across exec, so csgpix's own peak is only
/// seen in a child of a small process. Without GNU time, csgpix is this process's child and
/// the figure is at least this process's resident memory.
#[cfg(target_os = "linux")]
pub fn peak_mib(args: &[&str]) -> u64 {
    let time = std::path::Path::new("/usr/bin/time");
    if !time.exists() {
        return peak_mib_direct(args);
    }
    let out = tempfile::NamedTempFile::new().unwrap();
    let status = std::process::Command::new(time)
        .args(["-f", "%M", "-o"])
        .arg(out.path())
        .arg(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .unwrap();
    assert!(status.success(), "{args:?}");
    let text = std::fs::read_to_string(out.path()).unwrap();
    let kib: u64 = text.trim().parse().unwrap_or_else(|_| panic!("{text}"));
    kib.div_ceil(1024)
}

/// [`peak_mib`] with csgpix as this process's own child (wait4's ru_maxrss).
#[cfg(target_os = "linux")]
#[allow(clippy::zombie_processes)] // reaped by wait4, which also gives its rusage
fn peak_mib_direct(args: &[&str]) -> u64 {
    let child = std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let (mut status, mut usage) = (0, unsafe { std::mem::zeroed::<libc::rusage>() });
    // SAFETY: wait4(2) on our own child, reaped here and nowhere else.
    let pid = unsafe { libc::wait4(child.id() as i32, &mut status, 0, &mut usage) };
    assert_eq!(pid, child.id() as i32);
    assert!(
        libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0,
        "{args:?}"
    );
    (usage.ru_maxrss as u64).div_ceil(1024)
}

/// The triangles of an OFF mesh as OpenSCAD writes it (each face fanned from its first
/// vertex); None when the text is not such a mesh.
#[allow(dead_code)]
pub fn off_triangles(text: &str) -> Option<Vec<[[f64; 3]; 3]>> {
    let mut words = text.split_whitespace();
    if words.next()? != "OFF" {
        return None;
    }
    let mut next = || words.next();
    let nv: usize = next()?.parse().ok()?;
    let nf: usize = next()?.parse().ok()?;
    next()?;
    let mut v = Vec::with_capacity(nv);
    for _ in 0..nv {
        let mut p = [0.0; 3];
        for c in &mut p {
            *c = next()?.parse().ok()?;
        }
        v.push(p);
    }
    let mut tris = vec![];
    for _ in 0..nf {
        let k: usize = next()?.parse().ok()?;
        let mut f = Vec::with_capacity(k);
        for _ in 0..k {
            let i: usize = next()?.parse().ok()?;
            f.push(*v.get(i)?);
        }
        for i in 1..k.saturating_sub(1) {
            tris.push([f[0], f[i], f[i + 1]]);
        }
    }
    Some(tris)
}

/// OpenSCAD's OFF mesh file as triangles (each face fanned from its first vertex).
pub fn read_off(path: &std::path::Path) -> Vec<[[f64; 3]; 3]> {
    let text = std::fs::read_to_string(path).unwrap();
    off_triangles(&text).unwrap_or_else(|| panic!("{}: not an OFF mesh", path.display()))
}

/// The occupancy of a scene on `grid` by `route` (Blist, derived equations), its imports
/// loaded relative to `base`.
pub fn scene_occupancy(
    scene: &csgpix::scene::solid::CsgScene,
    base: &std::path::Path,
    grid: &csgpix::voxel::Grid,
    route: csgpix::voxel::Route,
) -> Result<Vec<bool>, String> {
    use csgpix::voxel::{voxelize, Slicer, SlicerOptions};
    let sampled =
        csgpix::voxel::sampled::load_imports(scene, "t.csg", base).map_err(|e| e.to_string())?;
    let opts = SlicerOptions {
        sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(scene, *grid, opts).map_err(|e| e.to_string())?;
    let eval = csgpix::voxel::blist::BlistEval::new(&scene.root);
    let set = rtl_model::Equations::Derived.set();
    let (v, _) = voxelize(&slicer, route, set, &eval, &|| {}).map_err(|e| e.to_string())?;
    Ok(v.voxels.iter().map(|&c| c != 0).collect())
}

/// Whether `openscad` runs; without it a test says so and passes, unless
/// `CSGPIX_OPENSCAD=require` (.ci/run sets it), where its absence fails.
pub fn have_openscad() -> bool {
    let found = std::process::Command::new("openscad")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        assert_ne!(
            std::env::var("CSGPIX_OPENSCAD").as_deref(),
            Ok("require"),
            "CSGPIX_OPENSCAD=require but openscad is not on PATH"
        );
        eprintln!("openscad is not on PATH: skipped");
    }
    found
}

/// (float IoU, word IoU) at 64³ of csgpix's reading of `DIR/NAME.csg` against OpenSCAD's
/// `DIR/NAME.off` (the word side by `word`); Err with
/// csgpix's message when it refuses the file.
pub fn compare_with_off(
    dir: &std::path::Path,
    name: &str,
    word: csgpix::voxel::Route,
) -> Result<(f64, f64), String> {
    use csgpix::scene::solid::{CsgNode, CsgScene, Import};
    use csgpix::voxel::{Grid, Route};
    use glam::DVec3;
    let text = std::fs::read_to_string(dir.join(format!("{name}.csg"))).unwrap();
    // Files the export names (an SVG drawing) are found beside it.
    let options = csgpix::openscad::ReadOptions {
        dir: Some(dir.to_path_buf()),
        ..Default::default()
    };
    let ours = csgpix::openscad::parse_csg_with(&text, &format!("{name}.csg"), &options)
        .map_err(|e| e.to_string())?;
    let tris = read_off(&dir.join(format!("{name}.off")));
    let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
    for p in tris.iter().flatten() {
        lo = lo.min(DVec3::from(*p));
        hi = hi.max(DVec3::from(*p));
    }
    // A margin of about two voxels round OpenSCAD's box, an odd fraction of the size so that
    // no voxel centre falls on the cases' round coordinates (a centre on a face is a tie the
    // two sides may break differently).
    let pad = (hi - lo) * 0.0371;
    let grid = Grid::new([64; 3], lo - pad, hi + pad).unwrap();
    let theirs = CsgScene {
        solids: vec![],
        imports: vec![Import {
            file: format!("{name}.off"),
            threshold: None,
            matrix: None,
            colour: None,
            line: 1,
            col: 1,
            footprint: None,
            mesh: Some(std::sync::Arc::new(tris)),
        }],
        root: CsgNode::Solid(0),
        warnings: vec![],
        reading_bytes: 0,
    };
    let b = scene_occupancy(&theirs, dir, &grid, Route::Float).unwrap();
    let a = scene_occupancy(&ours, dir, &grid, Route::Float).unwrap();
    let float = iou(&a, &b);
    let word = iou(&scene_occupancy(&ours, dir, &grid, word).unwrap(), &b);
    Ok((float, word))
}

/// Every case of `DIR/cases.txt` (a name, a tab, the statement; `#` lines are comments)
/// compared by [`compare_with_off`], each printed; the number compared, or the cases under
/// 0.999 (float) or 0.99 (word) and those refused.
#[allow(dead_code)]
pub fn compare_cases(
    dir: &std::path::Path,
    word: csgpix::voxel::Route,
) -> Result<usize, Vec<String>> {
    let cases = std::fs::read_to_string(dir.join("cases.txt")).unwrap();
    let mut failures = vec![];
    let mut compared = 0;
    for line in cases.lines().filter(|l| !l.starts_with('#')) {
        let name = line.split('\t').next().unwrap();
        match compare_with_off(dir, name, word) {
            Ok((float, word)) => {
                compared += 1;
                println!("{name:16} IoU float {float:.5}, word {word:.5}");
                if float < 0.999 || word < 0.99 {
                    failures.push(format!("{name}: float {float:.5}, word {word:.5}"));
                }
            }
            Err(e) => failures.push(format!("{name}: refused: {e}")),
        }
    }
    if failures.is_empty() {
        Ok(compared)
    } else {
        Err(failures)
    }
}
