//! The sculpt job: a spherical tool carved (or added) along a path through the optimized
//! hash-based octree of a scene or a stored volume (seed 000 Ch. 5-6; docs/sculpting.md).

use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

use csgpix_output::Outputs;
use csgpix_scene::mesh;
use csgpix_scene::solid::CsgScene;
use csgpix_sculpt::octree::{self, OptimizedOctree, StoreKind, VoxelStore};
use csgpix_sculpt::{self as sculpt, Frame, Latency, Sculptor, Step, Tool};
use csgpix_voxel::{Slicer, Volume, PROCESS_BYTES};

use crate::voxelize::Voxelization;
use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::grid::{GridOptions, Resolution};
use crate::lib_errors;
use crate::memory::Limit;
use crate::progress::{warn_all, Progress};
use crate::read::ReadSettings;
use crate::Error;

/// The resolution of a `.csg` scene when the grid options give none.
pub const DEFAULT_RES: Resolution = Resolution::Longest(128);

/// Paths of at least this many steps show their progress; shorter ones take well under a
/// second.
const PROGRESS_STEPS: usize = 5000;

/// Sculpt `input` with a spherical tool along `path`; write the mesh to `out`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SculptJob {
    /// A `.csg` scene (voxelized as by `voxelize`) or a `.nrrd` volume: one `voxelize`
    /// wrote, or a dataset with `threshold`.
    pub input: PathBuf,
    /// For a `.nrrd` input: a voxel is filled where its sample is at or above this value
    /// (None: where it is not 0).
    pub threshold: Option<f64>,
    /// The grid of a `.csg` scene (resolution None: [`DEFAULT_RES`]); none of it applies to
    /// a `.nrrd` volume but the sampling.
    pub grid: GridOptions,
    /// The tool's radius in voxels (`--tool sphere:R`, 0 < R <= 128).
    pub tool: f64,
    /// Add material instead of removing it.
    pub add: bool,
    /// Tool positions, CSV x,y,z in scene units.
    pub path: PathBuf,
    /// k of F = k·ΔX (force per scene unit).
    pub stiffness: f64,
    /// Output mesh: .stl (binary), .obj or .ply (binary).
    pub out: PathBuf,
    /// Write each step's contact, displacement and force to this CSV (`-`: standard output).
    pub forces: Option<PathBuf>,
    /// The memory limit in MiB (`--max-memory`); None: the memory available when it runs.
    pub max_memory: Option<u64>,
    /// How the scene is read.
    pub read: ReadSettings,
    /// Standard output is the caller's (the command line's `--json` report): an output to
    /// `-` is refused before anything runs.
    #[serde(skip)]
    pub stdout_taken: bool,
}

impl Default for SculptJob {
    fn default() -> Self {
        SculptJob {
            input: PathBuf::new(),
            threshold: None,
            grid: GridOptions::default(),
            tool: 0.0,
            add: false,
            path: PathBuf::new(),
            stiffness: 1.0,
            out: PathBuf::new(),
            forces: None,
            max_memory: None,
            read: ReadSettings::default(),
            stdout_taken: false,
        }
    }
}

/// What a run did. The JSON fields in this order, as `--json` prints them.
#[derive(Clone, Debug, Serialize)]
pub struct SculptReport {
    /// The input, as given.
    pub input: String,
    /// The volume's voxels along X, Y, Z.
    pub dims: [usize; 3],
    /// The octree's side (a power of two).
    pub side: usize,
    /// A voxel's size, scene units.
    pub voxel: [f64; 3],
    /// The tool's radius, voxels.
    pub radius_voxels: f64,
    /// `add` or `remove`.
    pub mode: &'static str,
    /// k of F = k·ΔX.
    pub stiffness: f64,
    /// Steps along the path.
    pub steps: usize,
    /// Steps in contact with the solid.
    pub contact_steps: usize,
    /// Voxels removed (or added).
    pub voxels_changed: u64,
    /// Cells whose case changed and were re-meshed.
    pub cells_remeshed: u64,
    /// The octree's nodes before the path.
    pub nodes_before: usize,
    /// And after.
    pub nodes_after: usize,
    /// Nodes added by splitting coarse leaves along the paths (7 per level split).
    pub nodes_added: u64,
    /// The mesh's triangles before the path.
    pub triangles_before: usize,
    /// And after.
    pub triangles_after: usize,
    /// Edges of the final mesh not in exactly two triangles: 0 when closed, which it always
    /// is (the cells past the grid's far faces are meshed too).
    pub open_edges: usize,
    /// Per step: collision + update + local re-mesh + force.
    pub latency: Latency,
    /// Median step under 1 ms (the 1 kHz haptic loop, seed 000 §1.1).
    pub median_under_1ms: bool,
    /// 99th percentile under 16.7 ms (60 Hz graphics).
    pub p99_under_16_7ms: bool,
    /// The run's memory estimate, bytes, checked before the store was built (docs/memory.md).
    pub memory_estimate: u64,
    /// Reading the input and building the store.
    pub load_seconds: f64,
    /// The first mesh.
    pub initial_mesh_seconds: f64,
    /// The path's steps.
    pub sculpt_seconds: f64,
    /// Writing the outputs.
    pub write_seconds: f64,
    /// Whether an output went to standard output (the closing lines then go to standard
    /// error).
    #[serde(skip)]
    pub stdout: bool,
}

/// The figures of before the path.
struct Before {
    dims: [usize; 3],
    nodes: usize,
    triangles: usize,
    memory_estimate: u64,
}

/// The run's stages' wall times.
struct Times {
    load_seconds: f64,
    initial_mesh_seconds: f64,
    sculpt_seconds: f64,
    write_seconds: f64,
}

/// An input read and its run planned (docs/memory.md): what the store is built from, its
/// frame and dims, and the memory.
struct Planned {
    source: Source,
    frame: Frame,
    dims: [usize; 3],
    /// What the store's build holds besides its nodes: its budget is the limit less that.
    beside: u64,
    /// The run's estimate.
    need: u64,
}

/// What the store is built from.
enum Source {
    /// A `.nrrd` volume's voxels.
    Volume(Volume),
    /// A scene, voxelized into the store slice by slice.
    Scene(Box<(CsgScene, Slicer)>),
}

impl SculptJob {
    /// The memory plan (docs/memory.md): the input read (the path, the scene or the volume)
    /// and the store's build, the sculpting after it, or the volume's read, whichever is
    /// largest.
    pub fn estimate(&self) -> crate::Result<u64> {
        let path = self.tool_path()?;
        Ok(self.plan(&path, &crate::progress::Quiet)?.need)
    }

    /// Read, build the store, mesh, run every step of the path, write the mesh (and the
    /// forces).
    pub fn run(&self, progress: &dyn Progress) -> crate::Result<SculptReport> {
        let mut outs = Outputs::new();
        let mesh_out = outs.file("-o", &self.out, &mesh::EXTENSIONS)?;
        let format = mesh::Format::of_path(&self.out)?;
        let forces_out = self.forces.as_ref();
        let forces_out = forces_out.map(|f| outs.file_or_stdout("--forces", f, &["csv"]));
        let forces_out = forces_out.transpose()?;
        if self.stdout_taken && outs.uses_stdout() {
            return Err(Error::options(
                "--json",
                "--json prints to standard output: write the outputs to files",
            ));
        }
        self.check_stiffness()?;
        let path = self.tool_path()?;
        let t0 = Instant::now();
        let (store, frame, dims, memory_estimate) = self.load(&path, progress)?;
        let load_seconds = t0.elapsed().as_secs_f64();
        let nodes = store.node_count();
        let t1 = Instant::now();
        let mut s = Sculptor::new(store, frame, dims, self.tool()).map_err(lib_errors::sculpt)?;
        let initial_mesh_seconds = t1.elapsed().as_secs_f64();
        let before = Before {
            dims,
            nodes,
            triangles: s.mesh.len(),
            memory_estimate,
        };
        let t2 = Instant::now();
        let steps = run_path(&mut s, &path, progress)?;
        let sculpt_seconds = t2.elapsed().as_secs_f64();
        let t3 = Instant::now();
        if let Some(out) = forces_out {
            outs.write(out, |w| write_forces(w, &path, &steps))?;
        }
        let comment = format!("csgpix sculpt {}", self.input.display());
        let tris = s.scene_triangles();
        outs.write(mesh_out, |w| mesh::write_format(w, format, &tris, &comment))?;
        let stdout = outs.uses_stdout();
        outs.commit()?;
        let t = Times {
            load_seconds,
            initial_mesh_seconds,
            sculpt_seconds,
            write_seconds: t3.elapsed().as_secs_f64(),
        };
        let r = self.report(&s, &steps, mesh::open_edges(&tris), before, t);
        Ok(SculptReport { stdout, ..r })
    }

    /// The report of the steps done and of the sculptor after them.
    fn report(
        &self,
        s: &Sculptor,
        steps: &[Step],
        open_edges: usize,
        before: Before,
        t: Times,
    ) -> SculptReport {
        let secs: Vec<f64> = steps.iter().map(|s| s.seconds).collect();
        let latency = Latency::of(&secs);
        SculptReport {
            input: self.input.display().to_string(),
            dims: before.dims,
            side: s.store.side(),
            voxel: s.frame.voxel.to_array(),
            radius_voxels: self.tool,
            mode: if self.add { "add" } else { "remove" },
            stiffness: self.stiffness,
            steps: steps.len(),
            contact_steps: steps.iter().filter(|s| s.contact).count(),
            voxels_changed: steps.iter().map(|s| u64::from(s.voxels)).sum(),
            cells_remeshed: steps.iter().map(|s| u64::from(s.cells)).sum(),
            nodes_before: before.nodes,
            nodes_after: s.store.node_count(),
            nodes_added: steps.iter().map(|s| s.nodes_added).sum(),
            triangles_before: before.triangles,
            triangles_after: s.mesh.len(),
            open_edges,
            latency,
            median_under_1ms: latency.median_us < 1000.0,
            p99_under_16_7ms: latency.p99_us < 16_700.0,
            memory_estimate: before.memory_estimate,
            load_seconds: t.load_seconds,
            initial_mesh_seconds: t.initial_mesh_seconds,
            sculpt_seconds: t.sculpt_seconds,
            write_seconds: t.write_seconds,
            stdout: false,
        }
    }

    /// The tool as the sculptor takes it.
    fn tool(&self) -> Tool {
        Tool {
            radius: self.tool,
            add: self.add,
            stiffness: self.stiffness,
        }
    }

    fn check_stiffness(&self) -> crate::Result<()> {
        if self.stiffness.is_finite() && self.stiffness >= 0.0 {
            return Ok(());
        }
        let message = format!(
            "--stiffness {}: must be a finite number >= 0",
            self.stiffness
        );
        Err(Error::options("--stiffness", message))
    }

    /// The tool's centres, scene units, read from the path's CSV.
    fn tool_path(&self) -> crate::Result<Vec<DVec3>> {
        let text = csgpix_scene::input::read_text(&self.path)?;
        Ok(sculpt::parse_path(&text, &self.path.display().to_string())?)
    }

    /// The limit, named as the command line names it.
    fn limit(&self) -> Limit {
        Limit::new(self.max_memory, "--max-memory")
    }

    /// The store, its frame, the volume's dims and the run's memory estimate: the run along
    /// `path` (scene units) planned and checked against the limit first (docs/memory.md).
    fn load(
        &self,
        path: &[DVec3],
        progress: &dyn Progress,
    ) -> crate::Result<(OptimizedOctree, Frame, [usize; 3], u64)> {
        let limit = self.limit();
        let p = self.plan(path, progress)?;
        limit.check(p.need, "this run", "lower --res")?;
        let budget = limit.bytes().saturating_sub(p.beside);
        let store = match &p.source {
            Source::Volume(volume) => OptimizedOctree::from_volume(volume, budget),
            Source::Scene(s) => crate::store::octree_from_scene(&s.1, &s.0.root, budget),
        };
        Ok((store.map_err(lib_errors::sculpt)?, p.frame, p.dims, p.need))
    }

    /// The input read by its kind, and the run planned.
    fn plan(&self, path: &[DVec3], progress: &dyn Progress) -> crate::Result<Planned> {
        let ext = self
            .input
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("");
        match ext.to_ascii_lowercase().as_str() {
            "csg" | "scad" if self.threshold.is_some() => {
                let message = "--threshold applies to .nrrd volumes only";
                Err(Error::options("--threshold", message))
            }
            "csg" | "scad" => self.plan_scene(path, progress),
            "nrrd" if self.grid.res.is_none() && !self.grid.any() => self.plan_nrrd(path),
            "nrrd" => Err(Error::options(
                "--res",
                "--res, --voxel, --pad and --bounds apply to .csg scenes only",
            )),
            _ => Err(Error::options(
                "INPUT",
                format!(
                    "{}: the input must be a .csg scene or a .nrrd volume",
                    self.input.display()
                ),
            )),
        }
    }

    /// A NRRD volume through the general reader (raw or gzip, any sample type, `spacings` or
    /// `space directions`), filled where `threshold` says.
    fn plan_nrrd(&self, path: &[DVec3]) -> crate::Result<Planned> {
        let p = &self.input;
        let n = csgpix_scene::nrrd::read_nrrd_limited(p, self.limit().samples())?;
        let frame = sculpt::nrrd_frame(&n)
            .map_err(|e| lib_errors::sculpt(e).context(p.display().to_string()))?;
        let dims = n.sizes;
        let voxels = sculpt::nrrd_voxels(&n, self.threshold);
        drop(n);
        let volume = Volume { dims, voxels };
        // The volume's own node counts, before the store is built; the read as the reader
        // counts it (16 bytes a sample), already checked by it.
        let counts = octree::estimate::volume_counts(&volume).map_err(lib_errors::sculpt)?;
        let held = volume.voxels.len() as u64 + PROCESS_BYTES;
        let read = (volume.voxels.len() as u64)
            .saturating_mul(16)
            .saturating_add(PROCESS_BYTES);
        let (_, need) = self.need(&counts, frame, dims, path, (held, read))?;
        Ok(Planned {
            source: Source::Volume(volume),
            frame,
            dims,
            // The volume's build is budgeted the whole limit.
            beside: 0,
            need,
        })
    }

    /// The scene voxelized as `voxelize` does (word model, run route, Blist evaluator),
    /// feeding the optimized octree slice by slice. The slicer is the thesis's word with the
    /// job's sampling and the scene's imports, as `voxelize` builds it by default.
    fn plan_scene(&self, path: &[DVec3], progress: &dyn Progress) -> crate::Result<Planned> {
        let name = self.input.display().to_string();
        let options = csgpix_openscad::ReadOptions {
            samples: self.limit().samples(),
            ..self.read.read_options()
        };
        let loaded = csgpix_voxel::sampled::load_scene_with(&self.input, &options)?;
        warn_all(progress, &loaded.scene.warnings);
        let grid = GridOptions {
            res: Some(self.grid.res.unwrap_or(DEFAULT_RES)),
            ..self.grid
        };
        let grid = grid
            .grid(&loaded)
            .map_err(|e| lib_errors::voxel(e).context(&name))?;
        // The thesis word and the scene's imports, as `voxelize` slices them by default.
        let slicer = Voxelization::default()
            .slicer(&loaded, grid, self.grid.sampling)
            .map_err(|e| Error::from(e).context(name))?;
        let scene = loaded.scene;
        // The run route's voxelizer, streaming its slices (`store::octree_from_scene`), the
        // scene's imports, and the store's nodes bounded from the scene (docs/memory.md).
        let eval = csgpix_voxel::blist::BlistEval::new(&scene.root);
        let threads = rayon::current_num_threads();
        let voxelizer = csgpix_voxel::runs::memory_estimates(&slicer, &eval, threads)[0];
        let depth = octree::depth_for(grid.dims).map_err(lib_errors::sculpt)?;
        let counts = csgpix_voxel::cells::cell_counts(&scene, &slicer, depth);
        let held = voxelizer.saturating_add(imports_bytes(&slicer));
        let frame = Frame::of_grid(&grid);
        // Drawing the scene's text came first, and was freed.
        let read = scene.reading_bytes.saturating_add(PROCESS_BYTES);
        let (beside, need) = self.need(&counts, frame, grid.dims, path, (held, read))?;
        Ok(Planned {
            source: Source::Scene(Box::new((scene, slicer))),
            frame,
            dims: grid.dims,
            beside,
            need,
        })
    }

    /// The run's estimate: the store's build beside `held` bytes (the voxelizer's, or the
    /// volume's), the sculpting after it, or what came before (`earlier`: the volume's read),
    /// whichever is largest. Returns what the build holds besides its nodes (its budget is
    /// the limit less that) and the estimate.
    fn need(
        &self,
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
            radius: self.tool,
        };
        let after = sculpt::estimate::memory_estimate(&plan).map_err(lib_errors::sculpt)?;
        let before = held.saturating_add(store.fixed);
        let need = before
            .saturating_add(store.nodes)
            .max(after.saturating_add(PROCESS_BYTES))
            .max(earlier);
        Ok((before, need))
    }
}

/// `--tool`: `sphere:R`, R in voxels (0 < R <= 128): the radius.
pub fn parse_tool(s: &str) -> crate::error::Parsed<f64> {
    sculpt::parse_tool(s).map_err(|e| crate::error::BadValue(lib_errors::sculpt(e).to_string()))
}

/// A finite number (`--threshold`).
pub fn finite(s: &str) -> crate::error::Parsed<f64> {
    match s.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(crate::error::BadValue(format!(
            "{s:?}: expected a finite number"
        ))),
    }
}

/// Every step of the path; a progress stage for long paths.
fn run_path(s: &mut Sculptor, path: &[DVec3], progress: &dyn Progress) -> crate::Result<Vec<Step>> {
    let shown = path.len() >= PROGRESS_STEPS;
    if shown {
        progress.stage("steps", path.len() as u64);
    }
    let mut steps = Vec::with_capacity(path.len());
    for &p in path {
        steps.push(s.step(p)?);
        if shown {
            progress.advance(1);
        }
    }
    if shown {
        progress.finish();
    }
    Ok(steps)
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
            csgpix_voxel::sampled::Shape::Footprint(f) => f.bytes(),
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
