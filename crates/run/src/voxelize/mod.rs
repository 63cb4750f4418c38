//! The voxelize job: a CSG scene, slice by slice through the array (§4.4), evaluated per
//! slice (§4.5 Blist, §4.2 tree, §3.4.1 stack), written as a NRRD volume, or as an OME-Zarr
//! store a chunk row at a time (`--format zarr`, docs/zarr.md).
//!
//! By stage: [`scene`] reads the input, [`plan`] makes the grid, the slicer, the evaluator,
//! the route and the memory estimate, [`outputs`] names and writes the outputs, `zarr`
//! creates and fills OME-Zarr stores, and [`route`] runs the slices (streamed NRRD, Zarr rows
//! or bricks, in memory) into them and builds the report. Each stage uses only the ones
//! before it (`.ci/module_cycles.py`).

use std::path::PathBuf;

use csgpix_draw::Model;
use csgpix_openscad::Fallback;
use csgpix_sculpt::octree::StoreKind;
use csgpix_voxel::blend::Union;
use csgpix_voxel::sampled::Binding;
use csgpix_voxel::Work;
use rtl_model::{Equations, WordFormat};
use serde::{Deserialize, Serialize};

use crate::grid::GridOptions;
use crate::memory::{default_limit, Limit};
use crate::read::ReadSettings;
use crate::Error;

pub mod outputs;
pub mod plan;
pub mod route;
pub mod scene;
mod text;
#[cfg(feature = "zarr")]
pub mod zarr;

#[cfg(feature = "zarr")]
pub use self::zarr::ZarrReport;
pub use crate::grid::{grid_spec, parse_bounds, parse_res, Resolution};
pub use outputs::{mesh, MeshReport};
pub use plan::Workers;
pub use route::StoreReport;

/// Without Zarr stores (the `zarr` feature off) the report's `zarr` is always null.
#[cfg(not(feature = "zarr"))]
pub type ZarrReport = ();

/// `--route` (`route=` in Python): which way the voxels are computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RouteKind {
    #[default]
    Runs,
    Intervals,
    Array,
}

named!(own RouteKind: "route" {
    RouteKind::Runs => "runs": "Column by column: each primitive's runs along every pixel's ray, the tree evaluated once per run (the same voxels as `intervals`; `intervals` where voxels take a dataset's grey value or a blend)",
    RouteKind::Intervals => "intervals": "Slab by slab: per-pixel depth intervals intersected with every slab",
    RouteKind::Array => "array": "Every P·Vz frame on the word array (with --model word)",
});

/// `--eval` (`eval=` in Python): the CSG tree's evaluator per slice.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Eval {
    #[default]
    Blist,
    Tree,
    Stack,
}

named!(own Eval: "eval" {
    Eval::Blist => "blist": "Blist (§4.3-4.5): one label register per voxel",
    Eval::Tree => "tree": "Recursive tree evaluation per voxel (§4.2)",
    Eval::Stack => "stack": "Slice-stack sweep, 64 voxels per word operation (§3.4.1)",
});

/// `--format`: what `-o` is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Format {
    #[default]
    Nrrd,
    Zarr,
}

named!(own Format: "format" {
    Format::Nrrd => "nrrd": "A NRRD volume (one file; streamed on the run route, else held in memory)",
    Format::Zarr => "zarr": "An OME-Zarr 0.5 store (a directory; written a brick or a chunk row at a time)",
});

named!(StoreKind: "store" {
    StoreKind::Octree => "octree": "Optimized hash-based octree: leaves only (seed 000 §4.3.4)",
    StoreKind::Pointer => "pointer": "Pointer-based octree as the thesis builds it: a node per allocation, every cell a node before merging (§4.3.2, §4.2.2)",
    StoreKind::PointerBlock => "pointer-block": "Pointer-based octree, 8 children per allocation, shared bottom-up builder",
    StoreKind::Hash => "hash": "Plain hash-based octree: every node (§4.3.3)",
    StoreKind::Dense => "dense": "Dense grid of cells",
});

named!(Fallback: "fallback" {
    Fallback::Refuse => "none": "Refuse the node, at its line and column",
    Fallback::Openscad => "openscad": "Ask openscad to mesh that subtree",
});

/// What decides a voxelization's voxels beside its grid (and its sampling, a grid option):
/// `--model`, `--route`, `--eval`, `--equations`, `--word`, `--panel`, `--grey`, `--blend`,
/// and the Python binding's keyword arguments of the same names.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Voxelization {
    /// The processor model (§2.3): `cycle`, `word` or `float`.
    #[serde(with = "crate::named::by_name")]
    pub model: Model,
    /// The route the model takes where the run route does not apply.
    pub route: RouteKind,
    /// The evaluator of the CSG tree per slice.
    pub eval: Eval,
    /// Select equations (array routes).
    #[serde(with = "crate::named::by_name")]
    pub equations: Equations,
    /// The depth word (§2.3.1).
    #[serde(with = "text::word")]
    pub word: WordFormat,
    /// Array routes: panels of NX×NY pixels simulated per primitive (None: the whole array).
    pub panel: Option<[usize; 2]>,
    /// Voxels won by a dataset take its grey value (§4.5).
    pub grey: bool,
    /// Grey-valued output by §3.3's blending operators.
    #[serde(with = "text::blend")]
    pub blend: Option<Union>,
}

impl Default for Voxelization {
    fn default() -> Self {
        Voxelization {
            model: Model::Word,
            route: RouteKind::Runs,
            eval: Eval::Blist,
            equations: Equations::Derived,
            word: WordFormat::THESIS,
            panel: Some(csgpix_voxel::DEFAULT_PANEL),
            grey: false,
            blend: None,
        }
    }
}

/// What the job writes: `-o` and the outputs beside it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct OutputOptions {
    /// The NRRD file (`-` standard output) or the Zarr store's directory (`-o`).
    pub out: PathBuf,
    /// What `out` is (None: by its extension, `.zarr` a store, else NRRD).
    #[serde(with = "text::opt_name")]
    pub format: Option<Format>,
    /// NRRD: gzip-compressed data.
    pub compress: bool,
    /// Zarr: the chunk shape, Z, Y, X (None: the default cube).
    pub chunk: Option<[usize; 3]>,
    /// Zarr: chunks per shard side (1: unsharded; None: the default).
    pub shard: Option<usize>,
    /// Zarr: multiscale levels (None: as many as the grid and chunk allow, down to 256).
    pub levels: Option<usize>,
    /// Every slice as a PNG into this directory.
    pub slices: Option<PathBuf>,
    /// A PNG of the volume seen along Z, Y and X.
    pub preview: Option<PathBuf>,
    /// The volume's surface as a mesh (.stl, .obj or .ply).
    pub mesh: Option<PathBuf>,
    /// A voxel store built slice by slice beside the volume.
    #[serde(with = "text::opt_name")]
    pub store: Option<StoreKind>,
    /// The report goes to standard output (`--json`): no output may.
    pub report_to_stdout: bool,
}

/// Voxelize a scene (or a CSG expression over bound files) on a grid and write it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct VoxelizeJob {
    /// An OpenSCAD `.csg` (or `.scad`) scene.
    pub scene: Option<PathBuf>,
    /// Instead of a scene: a CSG expression over named primitives, each bound by `prim`.
    pub expr: Option<String>,
    /// `NAME=FILE[,threshold=T]`: the expression's primitives.
    #[serde(with = "text::prims")]
    pub prim: Vec<Binding>,
    /// The grid and sampling.
    pub grid: GridOptions,
    /// What decides the voxels beside the grid.
    pub voxels: Voxelization,
    /// What is written.
    pub outputs: OutputOptions,
    /// Worker threads (None: all cores).
    pub threads: Option<usize>,
    /// The memory limit, named as its caller names it (`--max-memory`, `max_memory`); not
    /// serialized: the memory available is the machine's, now.
    #[serde(skip, default = "default_limit")]
    pub max_memory: Limit,
    /// How scenes are read.
    pub read: ReadSettings,
    /// What becomes of a node csgpix does not draw.
    #[serde(with = "crate::named::by_name")]
    pub fallback: Fallback,
}

impl Default for VoxelizeJob {
    fn default() -> Self {
        VoxelizeJob {
            scene: None,
            expr: None,
            prim: vec![],
            grid: GridOptions::default(),
            voxels: Voxelization::default(),
            outputs: OutputOptions::default(),
            threads: None,
            max_memory: default_limit(),
            read: ReadSettings::default(),
            fallback: Fallback::Refuse,
        }
    }
}

/// What a voxelize run did: the JSON report, fields in the order `--json` has always
/// printed them (`tests/identity.rs`).
#[derive(Serialize)]
pub struct VoxelizeReport {
    pub dims: [usize; 3],
    /// The voxelization's memory estimate, bytes, checked before it ran (docs/memory.md).
    pub memory_estimate: u64,
    /// `centre` or `slab` (--sampling).
    pub sampling: &'static str,
    /// Voxel size in scene units, and the grid's box.
    pub voxel: [f64; 3],
    pub min: [f64; 3],
    pub max: [f64; 3],
    pub model: &'static str,
    pub route: &'static str,
    pub eval: &'static str,
    pub solids: usize,
    /// Datasets and meshes.
    pub imports: usize,
    /// What the voxel values mean.
    pub values: &'static str,
    /// Width of the Blist label register (§4.3.3), whichever evaluator ran.
    pub label_bits: u32,
    /// Rows of the Blist table (one per primitive occurrence).
    pub blist_rows: usize,
    /// Bits of per-voxel intermediate state the chosen evaluator keeps.
    pub state_bits_per_voxel: usize,
    #[serde(flatten)]
    pub work: Work,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub store: Option<StoreReport>,
    /// With --format zarr: the store's layout and files.
    #[serde(flatten)]
    pub zarr: Option<ZarrReport>,
    /// With `--mesh`: its triangles and open edges.
    #[serde(flatten)]
    pub mesh: Option<MeshReport>,
    /// Hardware time at the thesis's 10 MHz clock.
    pub hardware_seconds: f64,
    pub wall_seconds: f64,
    /// What the scene reader warned of (also on stderr): empty primitives, ignored 2D
    /// children, subtrees meshed by `--fallback openscad`; and imported meshes that are not
    /// closed, voxelized by their winding number. Left out when there are none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// An output went to standard output (`-o -`): the text report goes to standard error.
    #[serde(skip)]
    pub to_stdout: bool,
}

impl VoxelizeJob {
    /// How messages and the outputs' comments name the input: its path, or `--expr "…"`.
    pub fn name(&self) -> String {
        match (&self.scene, &self.expr) {
            (Some(p), _) => p.display().to_string(),
            (None, Some(e)) => format!("--expr {e:?}"),
            (None, None) => "(no scene)".into(),
        }
    }

    /// The output's format: `format`, else `out`'s extension (`.zarr` a Zarr store, else
    /// NRRD).
    pub fn format(&self) -> Format {
        let zarr = self.outputs.out.extension().is_some_and(|e| e == "zarr");
        self.outputs.format.unwrap_or(match zarr {
            true => Format::Zarr,
            false => Format::Nrrd,
        })
    }

    /// How a refusal over the memory limit says to need less, in its caller's words.
    pub fn memory_fix(&self) -> &'static str {
        match (self.max_memory.name, self.format()) {
            ("max_memory", _) => "lower res (or z, or chunk)",
            (_, Format::Nrrd) => "lower --res",
            (_, Format::Zarr) => "lower --res or --chunk",
        }
    }

    /// The memory plan of [`VoxelizeJob::run`], bytes: the scene is read and planned.
    pub fn estimate(&self) -> crate::Result<u64> {
        let q = crate::progress::Quiet;
        let loaded = self.load(&q)?;
        let plan = self.plan(&loaded)?;
        Ok(plan.budget(self, &loaded.scene)?.need)
    }

    /// Read the scene, plan, check the estimate against the limit, voxelize and write.
    pub fn run(&self, progress: &dyn crate::progress::Progress) -> crate::Result<VoxelizeReport> {
        self.check_format()?;
        let staged = outputs::Staged::name(self)?;
        let pool = plan::Workers::new(self.threads)?;
        let loaded = pool.install(|| self.load(progress))?;
        let plan = self.plan_with(&loaded, pool)?;
        let budget = plan.budget(self, &loaded.scene)?;
        self.max_memory
            .check(budget.need, "this run", self.memory_fix())?;
        let ran = route::run(self, &plan, &budget, staged, progress)?;
        Ok(plan.report(self, &loaded.scene, ran, budget.need))
    }
}

impl VoxelizeJob {
    /// Slabs `z` (k0, k1; None: all) of the volume of the loaded scene `loaded` (the Python
    /// binding's `voxelize`): the slices' bytes, x fastest, then y, then k, and the grid.
    /// The estimate of those slabs is checked against the limit first.
    pub fn slabs(
        &self,
        loaded: &csgpix_voxel::sampled::Loaded,
        z: Option<(usize, usize)>,
        progress: &dyn crate::progress::Progress,
    ) -> crate::Result<(Vec<u8>, csgpix_voxel::Grid)> {
        let grid = self.grid.grid(loaded)?;
        let nz = grid.dims[2];
        let z = match z {
            None => 0..nz,
            Some((a, b)) if a <= b && b <= nz => a..b,
            Some((a, b)) => {
                let message = format!("z=({a}, {b}): the grid has slabs 0..{nz}");
                return Err(Error::options("z", message));
            }
        };
        let plan = self.plan_on(loaded, grid)??;
        let need = plan.slabs_estimate(&z);
        self.max_memory.check(need, "this run", self.memory_fix())?;
        let steps = match plan.runs() {
            true => csgpix_voxel::runs::ticks(&plan.slicer),
            false => z.len(),
        };
        progress.stage("slices", steps as u64);
        let bytes = plan.slabs(&self.voxels, z, &|| progress.advance(1))?;
        progress.finish();
        Ok((bytes, grid))
    }
}

/// Panels of NX×NY pixels, or none (`whole`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PanelArg(pub Option<[usize; 2]>);

/// `NXxNY` panels, or `whole` for none.
pub fn parse_panel(s: &str) -> crate::error::Parsed<PanelArg> {
    if s == "whole" {
        return Ok(PanelArg(None));
    }
    let [x, y] = s.split('x').collect::<Vec<_>>()[..] else {
        return Err("expected NXxNY (e.g. 32x32) or `whole`".into());
    };
    let n = |v: &str| match v.trim().parse::<usize>() {
        Ok(0) => Err("a panel needs at least one pixel".into()),
        Ok(n) => Ok(n),
        Err(e) => Err(crate::error::BadValue(format!("{v:?}: {e}"))),
    };
    Ok(PanelArg(Some([n(x)?, n(y)?])))
}

/// `--chunk`: N (a cube) or XxYxZ, each side 1..=65536; held Z, Y, X.
pub fn parse_chunk(s: &str) -> crate::error::Parsed<[usize; 3]> {
    let n = |v: &str| v.trim().parse::<usize>().map_err(|e| format!("{v:?}: {e}"));
    let parts: Vec<&str> = s.split(['x', 'X']).collect();
    let chunk = match parts[..] {
        [a] => [n(a)?; 3],
        // Given X×Y×Z as --res is; held Z, Y, X as the array's (and zarr-python's) order.
        [x, y, z] => [n(z)?, n(y)?, n(x)?],
        _ => return Err("expected N or XxYxZ, e.g. 64 or 256x256x16".into()),
    };
    if chunk.iter().any(|&c| c == 0 || c > 65536) {
        return Err(crate::error::BadValue(format!(
            "{s}: each side must be 1..=65536"
        )));
    }
    Ok(chunk)
}

/// `--shard`: N chunks a side (1..=65536), or `none` for 1.
pub fn parse_shard(s: &str) -> crate::error::Parsed<usize> {
    if s == "none" {
        return Ok(1);
    }
    match s.trim().parse::<usize>() {
        Ok(n) if (1..=65536).contains(&n) => Ok(n),
        Ok(_) => Err(crate::error::BadValue(format!(
            "{s}: 1..=65536 chunks a side, or `none`"
        ))),
        Err(e) => Err(crate::error::BadValue(format!(
            "{s:?}: {e}; expected N or `none`"
        ))),
    }
}

/// `sum:KS,KD` or `max`.
pub fn parse_blend(s: &str) -> crate::error::Parsed<Union> {
    if s == "max" {
        return Ok(Union::Max);
    }
    let k = s
        .strip_prefix("sum:")
        .and_then(|k| k.split_once(','))
        .ok_or_else(|| format!("{s:?}: expected `max` or `sum:KS,KD` (e.g. sum:0.5,0.5)"))?;
    let f = |v: &str| match v.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x >= 0.0 => Ok(x),
        _ => Err(crate::error::BadValue(format!(
            "{v:?}: a blending factor is a number >= 0"
        ))),
    };
    Ok(Union::Sum {
        ks: f(k.0)?,
        kd: f(k.1)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_job_goes_through_json_unchanged() {
        let mut job = VoxelizeJob {
            expr: Some("a - b".into()),
            prim: vec![Binding {
                name: "a".into(),
                file: "head.nrrd".into(),
                threshold: Some(300.0),
            }],
            fallback: Fallback::Openscad,
            ..VoxelizeJob::default()
        };
        job.voxels.blend = Some(Union::Sum { ks: 0.5, kd: 0.25 });
        job.voxels.word = WordFormat::new(8, 9, 10).unwrap();
        job.outputs.store = Some(StoreKind::PointerBlock);
        job.outputs.format = Some(Format::Zarr);
        let text = serde_json::to_string(&job).unwrap();
        let mut back: VoxelizeJob = serde_json::from_str(&text).unwrap();
        // The limit is the machine's, not the job's data.
        back.max_memory = job.max_memory;
        assert_eq!(back, job);
        let empty: VoxelizeJob = serde_json::from_str("{}").unwrap();
        assert_eq!(empty.voxels, Voxelization::default());
    }
}
