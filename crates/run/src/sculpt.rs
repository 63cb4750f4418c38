//! `csgpix sculpt`: a spherical tool carved (or added) along a path through the optimized
//! hash-based octree of a scene or a stored volume (seed 000 Ch. 5-6; docs/sculpting.md).

use crate::Error;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use csgpix_output::Outputs;
use csgpix_scene::mesh;
use csgpix_sculpt::octree::{self, OptimizedOctree, StoreKind, VoxelStore};
use csgpix_sculpt::{self as sculpt, Frame, Latency, Sculptor, Step, Tool};
use csgpix_voxel::{Slicer, SlicerOptions, Volume, PROCESS_BYTES};
use glam::DVec3;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::io::Write;

use super::lib_errors;
use super::voxelize::{parse_res, GridArgs, Resolution};

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix sculpt vectors/scenes/twelve.csg --res 128 --bounds=-15,-15,-15,15,15,15 --tool sphere:4 --path vectors/paths/carve.csv -o carved.stl\n  \
    csgpix sculpt vectors/scenes/twelve.csg --res 256 --bounds=-15,-15,-15,15,15,15 --tool sphere:8 --path vectors/paths/carve.csv --json --forces f.csv -o carved.ply\n  \
    csgpix sculpt part.nrrd --tool sphere:3 --add --path path.csv --stiffness 0.5 -o grown.obj\n\n\
    PATH.csv: columns x,y,z in scene units, one tool centre per row; a header row, blank\n  \
    lines and # comments are allowed. Each row is one haptic step: collision by key lookup,\n  \
    removal (or --add) of every voxel whose centre is inside the sphere, the changed cells'\n  \
    case bytes rewritten and re-meshed, and the spring force F = k·(P_s − P_c), P_s where the\n  \
    contact began (seed 000 §6; docs/sculpting.md).")]
pub struct Args {
    /// A `.csg` scene (voxelized as by `voxelize`) or a `.nrrd` volume: one `voxelize`
    /// wrote, or a dataset with `--threshold`.
    input: PathBuf,
    /// For a `.nrrd` input: a voxel is filled where its sample is at or above this value
    /// (default: where it is not 0).
    #[arg(long, value_parser = finite)]
    threshold: Option<f64>,
    /// Voxels along X, Y, Z for a `.csg` scene: N or NXxNYxNZ (default 128).
    #[arg(long, value_parser = parse_res)]
    res: Option<Resolution>,
    #[command(flatten)]
    grid: GridArgs,
    /// The tool: sphere:R, R in voxels (0 < R <= 128).
    #[arg(long, value_parser = parse_tool)]
    tool: f64,
    /// Add material instead of removing it.
    #[arg(long)]
    add: bool,
    /// Tool positions, CSV x,y,z in scene units.
    #[arg(long)]
    path: PathBuf,
    /// k of F = k·ΔX (force per scene unit).
    #[arg(long, default_value_t = 1.0)]
    stiffness: f64,
    /// Output mesh: .stl (binary), .obj or .ply (binary).
    #[arg(short = 'o', long)]
    out: PathBuf,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
    /// Write each step's contact, displacement and force to this CSV.
    #[arg(long)]
    forces: Option<PathBuf>,
    #[command(flatten)]
    mem: super::memory::MaxMemory,
    #[command(flatten)]
    openscad: super::read_args::ReadArgs,
}

/// What a run did.
#[derive(Serialize)]
struct Report {
    input: String,
    dims: [usize; 3],
    side: usize,
    voxel: [f64; 3],
    radius_voxels: f64,
    mode: &'static str,
    stiffness: f64,
    steps: usize,
    contact_steps: usize,
    voxels_changed: u64,
    cells_remeshed: u64,
    nodes_before: usize,
    nodes_after: usize,
    /// Nodes added by splitting coarse leaves along the paths (7 per level split).
    nodes_added: u64,
    triangles_before: usize,
    triangles_after: usize,
    /// Edges of the final mesh not in exactly two triangles: 0 when closed, which it always
    /// is (the cells past the grid's far faces are meshed too).
    open_edges: usize,
    /// Per step: collision + update + local re-mesh + force.
    latency: Latency,
    /// Median step under 1 ms (the 1 kHz haptic loop, seed 000 §1.1).
    median_under_1ms: bool,
    /// 99th percentile under 16.7 ms (60 Hz graphics).
    p99_under_16_7ms: bool,
    /// The run's memory estimate, bytes, checked before the store was built (docs/memory.md).
    memory_estimate: u64,
    load_seconds: f64,
    initial_mesh_seconds: f64,
    sculpt_seconds: f64,
    write_seconds: f64,
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let mut outs = Outputs::new();
    let mesh_out = outs.file("-o", &a.out, &mesh::EXTENSIONS)?;
    let format = mesh::Format::of_path(&a.out)?;
    let forces_out = a.forces.as_ref();
    let forces_out = forces_out.map(|f| outs.file_or_stdout("--forces", f, &["csv"]));
    let forces_out = forces_out.transpose()?;
    if a.json && outs.uses_stdout() {
        return Err(Error::options(
            "--json",
            "--json prints to standard output: write the outputs to files",
        ));
    }
    if !(a.stiffness.is_finite() && a.stiffness >= 0.0) {
        let message = format!("--stiffness {}: must be a finite number >= 0", a.stiffness);
        return Err(Error::options("--stiffness", message));
    }
    let text = csgpix_scene::input::read_text(&a.path)?;
    let path = sculpt::parse_path(&text, &a.path.display().to_string())?;
    let t0 = Instant::now();
    let (store, frame, dims, memory_estimate) = load(&a, &path)?;
    let load_seconds = t0.elapsed().as_secs_f64();
    let nodes_before = store.node_count();
    let tool = Tool {
        radius: a.tool,
        add: a.add,
        stiffness: a.stiffness,
    };
    let t1 = Instant::now();
    let mut s = Sculptor::new(store, frame, dims, tool).map_err(lib_errors::sculpt)?;
    let initial_mesh_seconds = t1.elapsed().as_secs_f64();
    let triangles_before = s.mesh.len();
    let t2 = Instant::now();
    let steps = run_path(&mut s, &path)?;
    let sculpt_seconds = t2.elapsed().as_secs_f64();
    let t3 = Instant::now();
    if let Some(out) = forces_out {
        outs.write(out, |w| write_forces(w, &path, &steps))?;
    }
    let comment = format!("csgpix sculpt {}", a.input.display());
    let tris = s.scene_triangles();
    outs.write(mesh_out, |w| mesh::write_format(w, format, &tris, &comment))?;
    let to_stderr = outs.uses_stdout();
    outs.commit()?;
    let write_seconds = t3.elapsed().as_secs_f64();
    let secs: Vec<f64> = steps.iter().map(|s| s.seconds).collect();
    let latency = Latency::of(&secs);
    let r = Report {
        input: a.input.display().to_string(),
        dims,
        side: s.store.side(),
        voxel: frame.voxel.to_array(),
        radius_voxels: a.tool,
        mode: if a.add { "add" } else { "remove" },
        stiffness: a.stiffness,
        steps: steps.len(),
        contact_steps: steps.iter().filter(|s| s.contact).count(),
        voxels_changed: steps.iter().map(|s| u64::from(s.voxels)).sum(),
        cells_remeshed: steps.iter().map(|s| u64::from(s.cells)).sum(),
        nodes_before,
        nodes_after: s.store.node_count(),
        nodes_added: steps.iter().map(|s| s.nodes_added).sum(),
        triangles_before,
        triangles_after: s.mesh.len(),
        open_edges: mesh::open_edges(&tris),
        latency,
        median_under_1ms: latency.median_us < 1000.0,
        p99_under_16_7ms: latency.p99_us < 16_700.0,
        memory_estimate,
        load_seconds,
        initial_mesh_seconds,
        sculpt_seconds,
        write_seconds,
    };
    print_report(&a, &r, to_stderr)?;
    Ok(ExitCode::SUCCESS)
}

/// Every step of the path, with a progress bar for long paths.
fn run_path(s: &mut Sculptor, path: &[DVec3]) -> crate::Result<Vec<Step>> {
    let bar = if path.len() >= 5000 {
        ProgressBar::new(path.len() as u64)
    } else {
        ProgressBar::hidden()
    };
    if let Ok(style) =
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} steps")
    {
        bar.set_style(style);
    }
    let mut steps = Vec::with_capacity(path.len());
    for &p in path {
        steps.push(s.step(p)?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    Ok(steps)
}

/// `--tool`: `sphere:R`, R in voxels.
fn parse_tool(s: &str) -> crate::error::Parsed<f64> {
    sculpt::parse_tool(s).map_err(|e| crate::error::BadValue(lib_errors::sculpt(e).to_string()))
}

fn finite(s: &str) -> crate::error::Parsed<f64> {
    match s.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(crate::error::BadValue(format!(
            "{s:?}: expected a finite number"
        ))),
    }
}

/// What [`load`] gives: the store, its frame, the volume's dims and the run's memory estimate.
type Loaded = (OptimizedOctree, Frame, [usize; 3], u64);

/// The store, its frame and the volume's dims, from a `.csg` scene or a `.nrrd` volume; the
/// run along `path` (scene units) estimated first (docs/memory.md).
fn load(a: &Args, path: &[DVec3]) -> crate::Result<Loaded> {
    let ext = a.input.extension().and_then(|e| e.to_str()).unwrap_or("");
    match ext.to_ascii_lowercase().as_str() {
        "csg" | "scad" if a.threshold.is_some() => {
            let message = "--threshold applies to .nrrd volumes only";
            Err(Error::options("--threshold", message))
        }
        "csg" | "scad" => load_scene(a, path),
        "nrrd" if a.res.is_none() && !a.grid.any() => load_nrrd(a, path),
        "nrrd" => Err(Error::options(
            "--res",
            "--res, --voxel, --pad and --bounds apply to .csg scenes only",
        )),
        _ => Err(Error::options(
            "INPUT",
            format!(
                "{}: the input must be a .csg scene or a .nrrd volume",
                a.input.display()
            ),
        )),
    }
}

/// A NRRD volume through the general reader (raw or gzip, any sample type, `spacings` or
/// `space directions`), filled where `--threshold` says.
fn load_nrrd(a: &Args, path: &[DVec3]) -> crate::Result<Loaded> {
    let p = &a.input;
    let n = csgpix_scene::nrrd::read_nrrd_limited(p, a.mem.samples())?;
    let frame = sculpt::nrrd_frame(&n)
        .map_err(|e| lib_errors::sculpt(e).context(p.display().to_string()))?;
    let dims = n.sizes;
    let voxels = sculpt::nrrd_voxels(&n, a.threshold);
    drop(n);
    let volume = Volume { dims, voxels };
    // The volume's own node counts, before the store is built; the read as the reader
    // counts it (16 bytes a sample), already checked by it.
    let counts = octree::estimate::volume_counts(&volume).map_err(lib_errors::sculpt)?;
    let held = volume.voxels.len() as u64 + PROCESS_BYTES;
    let read = (volume.voxels.len() as u64)
        .saturating_mul(16)
        .saturating_add(PROCESS_BYTES);
    let (_, need) = check(a, &counts, frame, dims, path, (held, read))?;
    let store = OptimizedOctree::from_volume(&volume, a.mem.bytes()).map_err(lib_errors::sculpt)?;
    Ok((store, frame, dims, need))
}

/// Checks the run against `--max-memory`: the store's build beside `held` bytes (the
/// voxelizer's, or the volume's), the sculpting after it, or what came before (`earlier`:
/// the volume's read), whichever is largest. Returns what the build holds besides its nodes
/// (its budget is the limit less that) and the estimate.
fn check(
    a: &Args,
    counts: &octree::estimate::CellCounts,
    frame: Frame,
    dims: [usize; 3],
    path: &[DVec3],
    (held, earlier): (u64, u64),
) -> crate::Result<(u64, u64)> {
    let store = octree::estimate::store_bytes(StoreKind::Octree, dims, counts)?;
    let centres: Vec<DVec3> = path.iter().map(|&p| frame.to_voxel(p)).collect();
    let plan = sculpt::estimate::Plan {
        dims,
        counts,
        path: &centres,
        radius: a.tool,
    };
    let after = sculpt::estimate::memory_estimate(&plan).map_err(lib_errors::sculpt)?;
    let before = held.saturating_add(store.fixed);
    let need = before
        .saturating_add(store.nodes)
        .max(after.saturating_add(PROCESS_BYTES))
        .max(earlier);
    a.mem.check(need, "this run", "lower --res")?;
    Ok((before, need))
}

/// Voxelizes the scene as `voxelize` does (word model, run route, Blist evaluator),
/// feeding the optimized octree slice by slice.
fn load_scene(a: &Args, path: &[DVec3]) -> crate::Result<Loaded> {
    let name = a.input.display().to_string();
    let options = csgpix_openscad::ReadOptions {
        samples: a.mem.samples(),
        ..a.openscad.read_options()
    };
    let loaded = csgpix_voxel::sampled::load_scene_with(&a.input, &options)?;
    crate::read_args::print_warnings(&loaded.scene.warnings);
    let scene = &loaded.scene;
    let grid = a
        .grid
        .grid(Some(a.res.unwrap_or(Resolution::Longest(128))), &loaded)
        .map_err(|e| e.context(&name))?;
    let threads = rayon::current_num_threads();
    let opts = SlicerOptions {
        sampling: a.grid.sampling.sampling(),
        sampled: loaded.sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(scene, grid, opts).map_err(|e| Error::from(e).context(name))?;
    // The run route's voxelizer, streaming its slices (`store::octree_from_scene`), the
    // scene's imports, and the store's nodes bounded from the scene (docs/memory.md).
    let eval = csgpix_voxel::blist::BlistEval::new(&scene.root);
    let voxelizer = csgpix_voxel::runs::memory_estimates(&slicer, &eval, threads)[0];
    let depth = octree::depth_for(grid.dims).map_err(lib_errors::sculpt)?;
    let counts = csgpix_voxel::cells::cell_counts(scene, &slicer, depth);
    let held = voxelizer.saturating_add(imports_bytes(&slicer));
    let (before, need) = check(
        a,
        &counts,
        Frame::of_grid(&grid),
        grid.dims,
        path,
        (held, 0),
    )?;
    let budget = a.mem.bytes().saturating_sub(before);
    let store = crate::store::octree_from_scene(&slicer, &scene.root, budget)
        .map_err(lib_errors::sculpt)?;
    Ok((store, Frame::of_grid(&grid), grid.dims, need))
}

/// Bytes of the scene's imports while they are voxelized: a dataset's samples, a mesh's
/// vertices and triangles.
fn imports_bytes(slicer: &Slicer) -> u64 {
    slicer
        .sampled
        .iter()
        .map(|s| match &s.shape {
            csgpix_voxel::sampled::Shape::Dataset { data, .. } => {
                data.nrrd.samples.len() as u64 * 4
            }
            csgpix_voxel::sampled::Shape::Mesh(m) => {
                m.vertices.len() as u64 * 24 + m.triangles.len() as u64 * 12
            }
            csgpix_voxel::sampled::Shape::OpenMesh(m, _) => {
                let m = m.mesh();
                m.vertices.len() as u64 * 24 + m.triangles.len() as u64 * 12
            }
        })
        .sum()
}

/// One row per step: position, contact, voxels and cells changed, ΔX, F, microseconds.
fn write_forces(w: &mut dyn Write, hips: &[DVec3], steps: &[Step]) -> std::io::Result<()> {
    {
        writeln!(
            w,
            "step,x,y,z,contact,voxels,cells,dx,dy,dz,fx,fy,fz,f,micros"
        )?;
        for (i, (p, s)) in hips.iter().zip(steps).enumerate() {
            let [dx, dy, dz] = s.displacement;
            let [fx, fy, fz] = s.force;
            let f = DVec3::from_array(s.force).length();
            writeln!(
                w,
                "{i},{},{},{},{},{},{},{dx},{dy},{dz},{fx},{fy},{fz},{f},{:.3}",
                p.x,
                p.y,
                p.z,
                u8::from(s.contact),
                s.voxels,
                s.cells,
                s.seconds * 1e6
            )?;
        }
        Ok(())
    }
}

fn print_report(a: &Args, r: &Report, to_stderr: bool) -> crate::Result<()> {
    if a.json {
        println!("{}", serde_json::to_string_pretty(r)?);
        return Ok(());
    }
    let say = |line: String| super::report_line(&line, to_stderr);
    say(format!(
        "{}: {} steps ({} in contact), {} voxels {}, {} cells re-meshed; {} -> {} triangles",
        a.out.display(),
        r.steps,
        r.contact_steps,
        r.voxels_changed,
        if a.add { "added" } else { "removed" },
        r.cells_remeshed,
        r.triangles_before,
        r.triangles_after
    ));
    say(format!(
        "{} open edges; octree {} -> {} nodes (+{} from splits); step median {:.1} us, p99 {:.1} us, max {:.1} us",
        r.open_edges,
        r.nodes_before,
        r.nodes_after,
        r.nodes_added,
        r.latency.median_us,
        r.latency.p99_us,
        r.latency.max_us
    ));
    Ok(())
}
