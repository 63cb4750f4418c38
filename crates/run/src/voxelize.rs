//! `csgpix voxelize`: a CSG scene, slice by slice through the array (§4.4), evaluated per
//! slice (§4.5 Blist, §4.2 tree, §3.4.1 stack), written as a NRRD volume, or as an OME-Zarr
//! store a chunk row at a time (`--format zarr`, docs/zarr.md).

use crate::Error;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use clap::ValueEnum;
use csgpix_draw::palette::rgb;
use csgpix_draw::Model;
use csgpix_output::{Out, Outputs};
use csgpix_scene::nrrd::{Encoding, VolumeFormat};
use csgpix_scene::solid::CsgScene;
use csgpix_sculpt::octree::{self, StoreKind};
use csgpix_voxel::blend::{BlendEval, Union};
use csgpix_voxel::blist::{BlistEval, BlistTable};
use csgpix_voxel::evaluate::{StackEval, TreeEval};
use csgpix_voxel::sampled::{
    load_scene_with, parse_binding, scene_from_expr_with, Binding, Loaded,
};
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{
    voxelize, voxelize_slabs, voxelize_streaming, BindingProblem, Error as VoxelError, Grid, Route,
    Sampling, Slicer, SlicerOptions, Volume, Work,
};
use glam::DVec3;
use indicatif::{ProgressBar, ProgressStyle};
use rtl_model::{Equations, WordFormat};
use serde::Serialize;

use super::array_args::parse_word;
use super::lib_errors;
use super::EquationsArg;
pub use crate::grid::{grid_spec, parse_bounds, parse_res, Resolution};

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix voxelize vectors/scenes/figure-5.2.csg --res 64 --preview fig52.png -o fig52.nrrd\n  \
    csgpix voxelize vectors/scenes/csg-logo.csg --res 128 --eval tree --json -o logo.nrrd\n  \
    csgpix voxelize vectors/scenes/hollow-cube.csg --res 32 --model cycle --slices slices/ -o hollow.nrrd\n  \
    csgpix voxelize vectors/scenes/extrusions.scad --voxel 0.5 --openscad-timeout 600 -o part.nrrd\n  \
    csgpix voxelize scene.csg --res 64x64x32 --bounds -10,-10,-10,10,10,10 -o part.nrrd\n  \
    csgpix voxelize vectors/scenes/cube-minus-cylinder.csg --voxel 0.5 --pad 1 --mesh part.stl -o part.nrrd\n  \
    csgpix voxelize vectors/scenes/hollow-cube.csg --res 32 --sampling slab -o thesis-slabs.nrrd\n  \
    csgpix voxelize vectors/scenes/figure-5.6.csg --res 64 --grey -o head.nrrd\n  \
    csgpix voxelize vectors/scenes/twelve.csg --res 1024 --chunk 64 -o twelve.zarr\n  \
    csgpix voxelize --expr '(head + box) - hole' --prim head=vectors/scenes/phantom.nrrd,threshold=300 \\\n    \
    --prim box=vectors/scenes/figure-5.2.csg --prim hole=part.stl --res 64 --blend max -o blend.nrrd")]
pub struct Args {
    /// OpenSCAD `.csg` scene; `import("x.nrrd", threshold = t)`, `import("x.stl")` and
    /// `import("x.obj")` bring in datasets and meshes (docs/volume-scenes.md).
    #[arg(required_unless_present = "expr", conflicts_with = "expr")]
    scene: Option<PathBuf>,
    /// Instead of a scene file: a CSG expression over named primitives (`+` union, `.`
    /// intersection, `-` difference, `!` complement), each bound by --prim.
    #[arg(long, requires = "prim")]
    expr: Option<String>,
    /// NAME=FILE[,threshold=T]: bind a name of --expr to a `.csg` scene, a `.nrrd` dataset (with
    /// its iso threshold) or a closed `.stl`/`.obj` mesh. Repeat for every name.
    #[arg(long, value_parser = parse_binding)]
    prim: Vec<Binding>,
    /// Voxels won by a dataset take its grey value instead of its colour code (§4.5): the
    /// sample scaled from the dataset's range to 16..255 (1..15 remain colour codes).
    #[arg(long)]
    grey: bool,
    /// Grey-valued output by §3.3's blending operators instead of labels: union `max` or
    /// `sum:KS,KD` (C = KS·Cs + KD·Cd), intersection min, difference max(Cd − Cs, 0).
    #[arg(long, value_parser = parse_blend, conflicts_with = "grey")]
    blend: Option<Union>,
    /// N: N cubic voxels along the bounds' longest side, the other sides covered by as many
    /// (centred on the bounds); NXxNYxNZ: voxels along X, Y and Z over the bounds.
    #[arg(long, value_parser = parse_res, required_unless_present = "voxel")]
    res: Option<Resolution>,
    #[command(flatten)]
    grid: GridArgs,
    /// Processor model: `cycle` simulates every P·Vz frame clock by clock; `word` uses the
    /// array's plane words (see --route); `float` exact intervals, the reference.
    #[arg(long, value_parser = super::model_parser(), default_value = "word")]
    model: Model,
    /// `runs` (word or float): each primitive's depths along every pixel's column, the tree
    /// evaluated once per run of constant membership (docs/voxelization.md); `intervals`: the
    /// same depths intersected with every slab, slab by slab; both proven voxel for voxel
    /// equal to the array (word). `array` (word) runs every P·Vz frame on the word array.
    #[arg(long, value_enum, default_value_t)]
    route: RouteArg,
    /// Evaluator of the CSG tree per slice.
    #[arg(long, value_enum, default_value_t)]
    eval: EvalArg,
    /// Select equations (array routes).
    #[arg(long, value_enum, default_value_t)]
    equations: EquationsArg,
    /// Depth word FRACTION/INTEGER/OVERFLOW bits.
    #[arg(long, default_value = "10/10/11", value_parser = parse_word)]
    word: WordFormat,
    /// Array routes: simulate, per primitive, only the panels (of NXxNY pixels) and slabs its
    /// footprint touches; `whole` simulates the whole array for every frame. Same voxels.
    #[arg(long, default_value = "32x32", value_parser = parse_panel)]
    panel: PanelArg,
    /// Output: a NRRD volume (`*.nrrd`, uint8 colour codes, 0 empty; `-` for standard
    /// output) or an OME-Zarr store (a directory `*.zarr`): the extension says which.
    #[arg(short = 'o', long)]
    out: PathBuf,
    /// What -o is, where its extension does not say (by default: `zarr` for *.zarr, else
    /// `nrrd`). `nrrd`: one file, written slice by slice on the run route when nothing else needs the
    /// volume (no --preview, --slices, --mesh or --store), else assembled in memory. `zarr`:
    /// an OME-Zarr 0.5 (Zarr v3) store written a brick (a chunk row of one XY tile) at a time
    /// on the run route, a chunk row at a time otherwise, so memory does not grow with the
    /// grid's depth (docs/zarr.md); not with --preview, --slices, --mesh or --store.
    #[arg(long, value_enum)]
    format: Option<FormatArg>,
    /// NRRD output: the data gzip-compressed (`encoding: gzip`, as 3D Slicer, ParaView and
    /// pynrrd read it), written as it is computed.
    #[arg(long)]
    compress: bool,
    /// Zarr store: the chunk shape, N for N×N×N or XxYxZ as --res (the store's `chunk_shape`
    /// is Z, Y, X, the array's order); each side cut to the grid's.
    /// Memory holds one chunk row: Z × NY × NX bytes.
    #[arg(long, value_parser = parse_chunk)]
    chunk: Option<[usize; 3]>,
    /// Zarr store: chunks per shard side across Y and X (a shard file is one chunk deep
    /// and N×N chunks wide, cut to the grid), or `none` (or 1) for one file per chunk.
    /// Costs no memory: shards are written a chunk at a time. Default 64.
    #[arg(long, value_parser = parse_shard)]
    shard: Option<usize>,
    /// Zarr store: multiscale levels, 1 for none; each halves every axis of the one
    /// before, a voxel taking the most frequent non-zero label of its 8 (docs/zarr.md).
    /// Default: until the largest side is at most 256, as far as the chunk depth halves.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=32))]
    levels: Option<u16>,
    /// Also write every slice as a PNG into this directory: indexed, its pixel indices the
    /// voxels' label codes (or grey values), shown in the palette's colours.
    #[arg(long)]
    slices: Option<PathBuf>,
    /// Also write a PNG of the volume seen along Z, Y and X (first filled voxel, shaded by
    /// depth), side by side.
    #[arg(long)]
    preview: Option<PathBuf>,
    /// Also write the volume's surface as a mesh (.stl, .obj or .ply), by global Marching
    /// Cubes over the optimized octree (docs/octree.md), in scene units: closed and wound
    /// outward (outside the grid counts as empty); --json reports its triangles and open edges.
    #[arg(long)]
    mesh: Option<PathBuf>,
    /// Worker threads, 1 to 256 (default: all cores). The output does not depend on it;
    /// each thread holds a slab's masks, counted in the memory estimate.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
    threads: Option<u16>,
    #[command(flatten)]
    mem: super::memory::MaxMemory,
    #[command(flatten)]
    openscad: super::read_args::ReadArgs,
    /// Also build a voxel store of the volume's dual cells, slice by slice while voxelizing
    /// (seed 000 Ch. 4; docs/octree.md), and report its nodes, bytes and build time.
    #[arg(long, value_enum)]
    store: Option<StoreArg>,
    /// What becomes of a node csgpix does not draw (`surface()`, a 2D import, a node it
    /// does not know): refused (`none`), or meshed by openscad, that subtree alone, and
    /// drawn as a closed mesh primitive, reported on stderr and in --json's `warnings`
    /// (a choice, so not with `--strict`, which refuses every warning).
    #[arg(long, value_enum, default_value_t, conflicts_with = "strict")]
    fallback: FallbackArg,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
}

/// `--fallback`.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FallbackArg {
    /// Refuse the node, at its line and column.
    #[default]
    None,
    /// Ask openscad to mesh that subtree.
    Openscad,
}

impl From<FallbackArg> for csgpix_openscad::Fallback {
    fn from(f: FallbackArg) -> Self {
        match f {
            FallbackArg::None => csgpix_openscad::Fallback::Refuse,
            FallbackArg::Openscad => csgpix_openscad::Fallback::Openscad,
        }
    }
}

/// The grid and sampling options `voxelize` and `sculpt` share (beside their own `--res`).
#[derive(clap::Args, Debug)]
pub struct GridArgs {
    /// Instead of --res: cubic voxels of this side (scene units), as many as cover the
    /// bounds, the grid centred on them.
    #[arg(long, conflicts_with = "res")]
    voxel: Option<f64>,
    /// Add this many empty voxels on every side of the grid (the voxel size is kept).
    #[arg(long, default_value_t = 0)]
    pad: usize,
    /// `centre`: a voxel is inside when its centre is inside the solid (binvox, OpenVDB);
    /// `slab`: when the segment through its centre along Z meets each primitive (the thesis's
    /// §4.4 slab, which dilates subtracted solids). docs/voxelization.md.
    #[arg(long, value_enum, default_value_t)]
    pub sampling: SamplingArg,
    /// Region to voxelize, X0,Y0,Z0,X1,Y1,Z1 in scene units (default: the scene's bounds).
    #[arg(long, value_parser = parse_bounds, allow_hyphen_values = true)]
    pub bounds: Option<(DVec3, DVec3)>,
}

impl GridArgs {
    /// The grid of `res` (or of `--voxel`) over `--bounds` or the scene's.
    pub fn grid(&self, res: Option<Resolution>, scene: &Loaded) -> crate::Result<Grid> {
        let spec = grid_spec(res, self.voxel, self.pad);
        scene.grid_over(&spec, self.bounds).map_err(flag_message)
    }

    /// Whether any grid option was given (they apply to scenes only).
    pub fn any(&self) -> bool {
        self.voxel.is_some() || self.pad > 0 || self.bounds.is_some()
    }
}

/// `--sampling`, shared with `sculpt`.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq)]
pub enum SamplingArg {
    /// A voxel is inside when its centre is inside the solid.
    #[default]
    #[value(alias = "center")]
    Centre,
    /// A voxel is inside a primitive when its segment along Z meets it (§4.4).
    Slab,
}

impl SamplingArg {
    pub fn sampling(self) -> Sampling {
        match self {
            SamplingArg::Centre => Sampling::Centre,
            SamplingArg::Slab => Sampling::Slab,
        }
    }

    fn name(self) -> &'static str {
        match self {
            SamplingArg::Centre => "centre",
            SamplingArg::Slab => "slab",
        }
    }
}

from_value_name!(SamplingArg: "sampling", RouteArg: "route", EvalArg: "eval", FormatArg: "format");

/// What decides a voxelization's voxels beside its grid: the flags `voxelize` reads and the
/// Python binding's keyword arguments, the same options for both.
#[derive(Clone, Copy, Debug)]
pub struct Voxelization {
    /// `--sampling`.
    pub sampling: SamplingArg,
    /// `--model`.
    pub model: Model,
    /// `--route`.
    pub route: RouteArg,
    /// `--eval`.
    pub eval: EvalArg,
    /// `--equations`.
    pub equations: Equations,
    /// `--word`.
    pub word: WordFormat,
    /// `--panel` (None: the whole array).
    pub panel: Option<[usize; 2]>,
    /// `--grey`.
    pub grey: bool,
    /// `--blend`.
    pub blend: Option<Union>,
}

impl Voxelization {
    /// The slicer of `loaded` on `grid` (§4.4).
    pub fn slicer(&self, loaded: &Loaded, grid: Grid) -> Result<Slicer, VoxelError> {
        let scene = &loaded.scene;
        let opts = SlicerOptions {
            fmt: self.word,
            sampling: self.sampling.sampling(),
            panel: self.panel,
            grey: self.grey,
            blend: self.blend.map(|u| BlendEval::new(&scene.root, u)),
            sampled: loaded.sampled.clone(),
        };
        Slicer::new(scene, grid, opts)
    }

    /// The evaluator of `scene`'s tree per slice (§4.2, §3.4.1, §4.5).
    pub fn evaluator(&self, scene: &CsgScene) -> Box<dyn SliceEval + Send + Sync> {
        match self.eval {
            EvalArg::Tree => Box::new(TreeEval::new(&scene.root)),
            EvalArg::Stack => Box::new(StackEval::new(&scene.root)),
            EvalArg::Blist => Box::new(BlistEval::new(&scene.root)),
        }
    }

    /// The route the model and `--route` ask for on `slicer`: the run route where it gives
    /// the volume ([`csgpix_voxel::runs::applies`]), else its slab route.
    pub fn route(&self, slicer: &Slicer) -> Route {
        route_of(self.model, self.route, slicer)
    }

    /// An upper bound of the memory of [`Voxelization::slabs`] over `z` (docs/memory.md):
    /// the slabs it returns beside the route's working memory. On the run route that is the
    /// runs of the whole grid, swept along z; on a slab route the slab ranges and per-thread
    /// state of a volume only `z` deep, and the imported primitives.
    pub fn slabs_estimate(
        &self,
        slicer: &Slicer,
        eval: &dyn SliceEval,
        z: &std::ops::Range<usize>,
        threads: usize,
    ) -> u64 {
        let out = (z.len() as u64).saturating_mul(slicer.grid.slice_len() as u64);
        if matches!(self.route(slicer), Route::Runs { .. }) {
            let swept = csgpix_voxel::runs::memory_estimates(slicer, eval, threads)[0];
            return swept.saturating_add(out);
        }
        let mut held = slicer.grid;
        held.dims[2] = z.len().max(1);
        crate::memory::slab_route_estimate(slicer, &held, threads)
    }

    /// Slabs `z` of the volume: the slices' bytes, x fastest, then y, then k.
    pub fn slabs(
        &self,
        slicer: &Slicer,
        eval: &dyn SliceEval,
        z: std::ops::Range<usize>,
    ) -> Result<Vec<u8>, VoxelError> {
        let mut out = Vec::with_capacity(z.len() * slicer.grid.slice_len());
        let set = self.equations.set();
        let route = self.route(slicer);
        voxelize_slabs::<VoxelError>(slicer, route, set, eval, &|| {}, z, &mut |_, s| {
            out.extend_from_slice(s);
            Ok(())
        })?;
        Ok(out)
    }
}

/// The voxelizer's worker threads: `threads` of them, or by default one per core (rayon's).
pub fn thread_pool(threads: Option<usize>) -> crate::Result<rayon::ThreadPool> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads.unwrap_or(0));
    Ok(pool.build()?)
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
enum StoreArg {
    /// Optimized hash-based octree: leaves only (seed 000 §4.3.4).
    Octree,
    /// Pointer-based octree as the thesis builds it: a node per allocation, every cell a
    /// node before merging (§4.3.2, §4.2.2).
    Pointer,
    /// Pointer-based octree, 8 children per allocation, shared bottom-up builder.
    PointerBlock,
    /// Plain hash-based octree: every node (§4.3.3).
    Hash,
    /// Dense grid of cells.
    Dense,
}

impl StoreArg {
    fn kind(self) -> StoreKind {
        match self {
            StoreArg::Octree => StoreKind::Octree,
            StoreArg::Pointer => StoreKind::Pointer,
            StoreArg::PointerBlock => StoreKind::PointerBlock,
            StoreArg::Hash => StoreKind::Hash,
            StoreArg::Dense => StoreKind::Dense,
        }
    }
}

/// The store `--store` built.
#[derive(Serialize)]
struct StoreReport {
    kind: StoreKind,
    /// Octree levels below the root (cell grid side 2^depth).
    depth: u32,
    side: usize,
    /// Nodes held (pointer and hash: 8·I + 1 with the root; octree: 7·I + 1; dense: cells).
    nodes: usize,
    internal_nodes: usize,
    bytes: usize,
    bytes_per_node: f64,
    /// Time spent in the store's builder (slices in, store out), voxelization excluded.
    build_seconds: f64,
}

/// `--format`: what `-o` is.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq)]
pub enum FormatArg {
    /// A NRRD volume (one file; streamed on the run route, else held in memory).
    #[default]
    Nrrd,
    /// An OME-Zarr 0.5 store (a directory; written a brick or a chunk row at a time).
    Zarr,
}

/// `--route` (`route=` in Python): which way the voxels are computed.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq)]
pub enum RouteArg {
    /// Column by column: each primitive's runs along every pixel's ray, the tree evaluated
    /// once per run (the same voxels as `intervals`; `intervals` where voxels take a
    /// dataset's grey value or a blend).
    #[default]
    Runs,
    /// Slab by slab: per-pixel depth intervals intersected with every slab.
    Intervals,
    /// Every P·Vz frame on the word array (with --model word).
    Array,
}

/// `--eval` (`eval=` in Python): the CSG tree's evaluator per slice.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq)]
pub enum EvalArg {
    /// Blist (§4.3-4.5): one label register per voxel.
    #[default]
    Blist,
    /// Recursive tree evaluation per voxel (§4.2).
    Tree,
    /// Slice-stack sweep, 64 voxels per word operation (§3.4.1).
    Stack,
}

/// Panels of NX×NY pixels, or none (`whole`).
#[derive(Clone, Copy, Debug)]
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

#[derive(Serialize)]
struct Report {
    dims: [usize; 3],
    /// The voxelization's memory estimate, bytes, checked before it ran (docs/memory.md).
    memory_estimate: u64,
    /// `centre` or `slab` (--sampling).
    sampling: &'static str,
    /// Voxel size in scene units, and the grid's box.
    voxel: [f64; 3],
    min: [f64; 3],
    max: [f64; 3],
    model: &'static str,
    route: &'static str,
    eval: &'static str,
    solids: usize,
    /// Datasets and meshes.
    imports: usize,
    /// What the voxel values mean.
    values: &'static str,
    /// Width of the Blist label register (§4.3.3), whichever evaluator ran.
    label_bits: u32,
    /// Rows of the Blist table (one per primitive occurrence).
    blist_rows: usize,
    /// Bits of per-voxel intermediate state the chosen evaluator keeps.
    state_bits_per_voxel: usize,
    #[serde(flatten)]
    work: Work,
    #[serde(skip_serializing_if = "Option::is_none")]
    store: Option<StoreReport>,
    /// With --format zarr: the store's layout and files.
    #[serde(flatten)]
    zarr: Option<ZarrReport>,
    /// With `--mesh`: its triangles and open edges.
    #[serde(flatten)]
    mesh: Option<MeshReport>,
    /// Hardware time at the thesis's 10 MHz clock.
    hardware_seconds: f64,
    wall_seconds: f64,
    /// What the scene reader warned of (also on stderr): empty primitives, ignored 2D
    /// children, subtrees meshed by `--fallback openscad`; and imported meshes that are not
    /// closed, voxelized by their winding number. Left out when there are none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    warnings: Vec<String>,
}

/// Without Zarr stores (the `zarr` feature off) the report's `zarr` is always null.
#[cfg(not(feature = "zarr"))]
type ZarrReport = ();

/// The `--format zarr` figures of the JSON report.
#[cfg(feature = "zarr")]
#[derive(Serialize, Clone, Debug)]
struct ZarrReport {
    /// Level 0's chunk shape (a shard's inner chunk), Z, Y, X.
    chunk: [usize; 3],
    chunk_rows: usize,
    /// Level 0's shard shape, Z, Y, X; null when unsharded (--shard none).
    shard: Option<[usize; 3]>,
    /// Multiscale levels, level 0 included.
    levels: usize,
    /// Files written per level: shard files, or chunk files when unsharded (all-0 shards
    /// and chunks have none).
    files_written: Vec<u64>,
    /// A brick's columns, X, Y (the run route writes brick by brick; else null).
    tile: Option<[usize; 2]>,
    /// Bricks written (chunk rows × tiles), or null.
    bricks: Option<usize>,
    /// Chunks of every level by what they hold: `empty` (skipped), `uniform` (one value,
    /// compressed once), `mixed`.
    chunks: csgpix_zarr::ChunksHeld,
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

/// What the run names its input in messages and the NRRD comment.
impl Args {
    /// How the NRRD volume is written: gzip with `--compress`; the `space` of the first
    /// dataset the scene imports that declares one, else the neutral `3D-right-handed`.
    pub fn nrrd_format(&self, slicer: &Slicer) -> VolumeFormat {
        let declared = slicer.sampled.iter().find_map(|s| s.space());
        VolumeFormat {
            space: declared.unwrap_or(csgpix_scene::nrrd::NEUTRAL_SPACE).into(),
            encoding: match self.compress {
                true => Encoding::Gzip,
                false => Encoding::Raw,
            },
        }
    }

    /// The output's format: `--format`, else `-o`'s extension (`.zarr` a Zarr store, else
    /// NRRD).
    pub fn format(&self) -> FormatArg {
        let zarr = self.out.extension().is_some_and(|e| e == "zarr");
        self.format.unwrap_or(match zarr {
            true => FormatArg::Zarr,
            false => FormatArg::Nrrd,
        })
    }

    /// The options that decide the voxels, as flags gave them.
    pub fn voxelization(&self) -> Voxelization {
        Voxelization {
            sampling: self.grid.sampling,
            model: self.model,
            route: self.route,
            eval: self.eval,
            equations: self.equations.into(),
            word: self.word,
            panel: self.panel.0,
            grey: self.grey,
            blend: self.blend,
        }
    }
}

fn input_name(a: &Args) -> String {
    match (&a.scene, &a.expr) {
        (Some(p), _) => p.display().to_string(),
        (None, Some(e)) => format!("--expr {e:?}"),
        (None, None) => "(no scene)".into(),
    }
}

fn load(a: &Args) -> crate::Result<Loaded> {
    match (&a.scene, &a.expr) {
        (Some(p), _) => {
            // The scene's vertices count against --max-memory too.
            let options = csgpix_openscad::ReadOptions {
                fallback: a.fallback.into(),
                max_vertices: Some(csgpix_openscad::ReadOptions::max_vertices_for(
                    a.mem.bytes(),
                )),
                samples: a.mem.samples(),
                ..a.openscad.read_options()
            };
            let loaded = load_scene_with(p, &options).map_err(flag_message)?;
            crate::read_args::print_warnings(&loaded.scene.warnings);
            Ok(loaded)
        }
        (None, Some(e)) => {
            let options = csgpix_openscad::ReadOptions {
                samples: a.mem.samples(),
                ..a.openscad.read_options()
            };
            scene_from_expr_with(e, &a.prim, &options).map_err(flag_message)
        }
        (None, None) => Err(Error::options("--expr", "give a scene file or --expr")),
    }
}

/// A loading error in the words of this command's flags (`--bounds`, `--expr`, `--prim`).
pub fn flag_message(e: VoxelError) -> Error {
    match e {
        VoxelError::NeedsBounds => Error::options("--bounds", format!("{e}: give --bounds")),
        VoxelError::Expr(m) => Error::options("--expr", format!("--expr:{m}")),
        VoxelError::Unbound { name, col } => Error::options(
            "--expr",
            format!("--expr:1:{col}: primitive `{name}` needs a file: --prim {name}=FILE"),
        ),
        VoxelError::Binding {
            name,
            problem: BindingProblem::NotInExpression,
        } => Error::options(
            "--prim",
            format!("--prim {name}: the expression has no primitive `{name}`"),
        ),
        VoxelError::Binding { name, problem } => {
            Error::options("--prim", format!("--prim {name}: {problem}"))
        }
        e => e.into(),
    }
}

/// `--format zarr` with what it cannot do, refused in one line before anything is named:
/// the options that need the whole volume in memory, and standard output.
fn check_format(a: &Args) -> crate::Result<()> {
    #[cfg(not(feature = "zarr"))]
    if a.format() == FormatArg::Zarr {
        let message = "-o: this csgpix is built without Zarr stores (the `zarr` feature): \
                       write a .nrrd file";
        return Err(Error::options("-o", message));
    }
    if a.format() == FormatArg::Nrrd {
        let zarr_only = [
            ("--chunk", a.chunk.is_some()),
            ("--shard", a.shard.is_some()),
            ("--levels", a.levels.is_some()),
        ];
        return match zarr_only.iter().find(|(_, given)| *given) {
            Some((flag, _)) => Err(Error::options(
                flag,
                format!("{flag} applies to a Zarr store only (-o OUT.zarr)"),
            )),
            None => Ok(()),
        };
    }
    if a.compress {
        let message = "--compress applies to a NRRD file (a Zarr store's chunks are gzip already)";
        return Err(Error::options("--compress", message));
    }
    if a.out.as_os_str() == "-" {
        let message = "-o -: --format zarr writes a directory (OUT.zarr), not standard output";
        return Err(Error::options("-o", message));
    }
    let whole = [
        ("--preview", a.preview.is_some()),
        ("--slices", a.slices.is_some()),
        ("--mesh", a.mesh.is_some()),
        ("--store", a.store.is_some()),
    ];
    match whole.iter().find(|(_, given)| *given) {
        Some((flag, _)) => Err(Error::options(
            flag,
            format!(
                "{flag} needs the whole volume in memory: not with a Zarr store, which is \
                 written a brick at a time (write a .nrrd file)"
            ),
        )),
        None => Ok(()),
    }
}

/// The run's outputs, named before anything is computed.
struct Named {
    outs: Outputs,
    /// `-o`: the NRRD file, or the Zarr store's directory.
    nrrd: Out,
    slices: Option<Out>,
    preview: Option<Out>,
    mesh: Option<(Out, csgpix_scene::mesh::Format)>,
}

fn name_outputs(a: &Args) -> crate::Result<Named> {
    let mut outs = Outputs::new();
    let nrrd = match a.format() {
        FormatArg::Nrrd => outs.file_or_stdout("-o", &a.out, &["nrrd"])?,
        FormatArg::Zarr => outs.tree("-o", &a.out, &["zarr"], "zarr.json")?,
    };
    let slices = a
        .slices
        .as_ref()
        .map(|d| outs.series("--slices", d, "slice-", ".png"))
        .transpose()?;
    let preview = a.preview.as_ref();
    let preview = preview.map(|p| outs.file_or_stdout("--preview", p, &["png"]));
    let preview = preview.transpose()?;
    let mesh = match &a.mesh {
        Some(p) => {
            let out = outs.file("--mesh", p, &csgpix_scene::mesh::EXTENSIONS)?;
            Some((out, csgpix_scene::mesh::Format::of_path(p)?))
        }
        None => None,
    };
    if a.json && outs.uses_stdout() {
        return Err(Error::options(
            "--json",
            "--json prints to standard output: write the outputs to files",
        ));
    }
    Ok(Named {
        outs,
        nrrd,
        slices,
        preview,
        mesh,
    })
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    check_format(&a)?;
    let name = input_name(&a);
    let mut named = name_outputs(&a)?;
    let loaded = load(&a)?;
    let grid = a.grid.grid(a.res, &loaded).map_err(|e| e.context(&name))?;
    let scene = &loaded.scene;
    let threads = a
        .threads
        .map_or_else(rayon::current_num_threads, usize::from);
    let vox = a.voxelization();
    let slicer = vox
        .slicer(&loaded, grid)
        .map_err(|e| Error::from(e).context(&name))?;
    let eval = vox.evaluator(scene);
    let route = vox.route(&slicer);
    // The run route's NRRD estimates, with and without the volume: they decide whether the
    // file is streamed, and the one that applies is the run's.
    // The estimates walk a dataset's columns to count its runs: on the run's own threads.
    let pool = thread_pool(Some(threads))?;
    let runs_nrrd =
        (matches!(route, Route::Runs { .. }) && a.format() == FormatArg::Nrrd).then(|| {
            pool.install(|| csgpix_voxel::runs::memory_estimates(&slicer, eval.as_ref(), threads))
        });
    let stream = streams(&a, route, runs_nrrd);
    // `--store`: its nodes bounded from the scene (docs/memory.md).
    let store_bytes = match a.store {
        Some(st) => {
            let depth = octree::depth_for(grid.dims).map_err(lib_errors::sculpt)?;
            let counts = csgpix_voxel::cells::cell_counts(scene, &slicer, depth);
            Some(octree::estimate::store_bytes(
                st.kind(),
                grid.dims,
                &counts,
            )?)
        }
        None => None,
    };
    let e = eval.as_ref();
    let need = pool.install(|| estimate(&a, &slicer, route, e, threads, (stream, runs_nrrd)))?;
    let need = need.saturating_add(store_bytes.map_or(0, |b| b.nodes));
    let fix = match a.format() {
        FormatArg::Nrrd => "lower --res",
        FormatArg::Zarr => "lower --res or --chunk",
    };
    a.mem.check(need, "this run", fix)?;
    let set = vox.equations.set();
    let t0 = Instant::now();
    let bar = progress(&slicer, route);
    let tick = || bar.inc(1);
    // Refused by check_format when built without Zarr stores.
    #[cfg(feature = "zarr")]
    if a.format() == FormatArg::Zarr {
        let layout = zarr_layout(&a);
        let root = named.outs.stage_root(named.nrrd)?;
        let (grey, blend) = (a.grey, a.blend.is_some());
        let store = crate::zarr::create_store(&root, &grid, &layout, &name, grey, blend)
            .map_err(|e| zarr_message(e, &a))?;
        let rows = store.chunk_rows().len();
        let bricks = crate::zarr::by_bricks(route).then_some(rows * store.tiles().len());
        if let Some(n) = bricks {
            bar.set_length(n as u64);
            bar.set_message("bricks");
        }
        let work = pool
            .install(|| {
                let e = eval.as_ref();
                crate::zarr::write_bricks(&slicer, route, set, e, &tick, &store, 0..rows, None)
            })
            .map_err(|e| match e {
                Error::Zarr(e) => zarr_message(e, &a),
                e => e,
            })?;
        bar.finish_and_clear();
        let wall = t0.elapsed().as_secs_f64();
        named.outs.commit()?;
        let zarr = Some(ZarrReport {
            chunk: store.chunk(),
            chunk_rows: rows,
            shard: store.levels()[0].shard,
            levels: store.levels().len(),
            files_written: store.files_written(),
            tile: bricks.map(|_| store.tile()),
            bricks,
            chunks: store.chunks_held(),
        });
        return report(
            &a,
            scene,
            &slicer,
            eval.as_ref(),
            (work, None, None),
            (wall, false, need),
            zarr,
        );
    }
    let nrrd_format = a.nrrd_format(&slicer);
    if stream {
        let comment = format!("csgpix voxelize {name}");
        let head = (comment.as_str(), &nrrd_format);
        let out = named.nrrd;
        let work = pool.install(|| {
            stream_nrrd(
                &mut named.outs,
                out,
                &slicer,
                route,
                set,
                eval.as_ref(),
                &tick,
                head,
            )
        })?;
        bar.finish_and_clear();
        let wall = t0.elapsed().as_secs_f64();
        let to_stdout = named.outs.uses_stdout();
        named.outs.commit()?;
        let run = (wall, to_stdout, need);
        return report(
            &a,
            scene,
            &slicer,
            eval.as_ref(),
            (work, None, None),
            run,
            None,
        );
    }
    let budget = a.mem.bytes().saturating_sub(need);
    let (volume, work, store) = match a.store {
        None => pool
            .install(|| voxelize(&slicer, route, set, eval.as_ref(), &tick))
            .map(|(v, w)| (v, w, None))?,
        Some(st) => {
            // The nodes are charged against what the estimate kept for them.
            let budget = budget.saturating_add(store_bytes.map_or(0, |b| b.nodes));
            pool.install(|| {
                with_store(&slicer, route, set, eval.as_ref(), &tick, st.kind(), budget)
            })?
        }
    };
    bar.finish_and_clear();
    let wall = t0.elapsed().as_secs_f64();
    let grey = match (a.blend.is_some(), a.grey) {
        (true, _) => Values::Grey,
        (false, true) => Values::Mixed,
        (false, false) => Values::Codes,
    };
    let outs = &mut named.outs;
    if let Some(dir) = named.slices {
        write_slices(outs, dir, &volume, grey)?;
    }
    if let Some(out) = named.preview {
        write_preview(outs, out, &volume, grey)?;
    }
    let comment = format!("csgpix voxelize {name}");
    let mesh = match named.mesh {
        Some(m) => Some(write_mesh(outs, m, &grid, &volume, budget, &comment)?),
        None => None,
    };
    let voxels = &volume.voxels;
    outs.write_sparse(named.nrrd, |w| {
        csgpix_scene::nrrd::write_volume_as(w, &grid, voxels, &comment, &nrrd_format)
    })?;
    let to_stdout = outs.uses_stdout();
    named.outs.commit()?;
    let figures = (work, store, mesh);
    let run = (wall, to_stdout, need);
    report(&a, scene, &slicer, eval.as_ref(), figures, run, None)
}

/// Whether the NRRD file is written slice by slice as the run route sweeps them, the volume
/// never held: when nothing else needs it (no --slices, --preview, --mesh or --store) and the
/// columns' runs, held for the sweep, are estimated below the volume (thousands of small
/// primitives can make them the larger).
/// `runs_nrrd`: the run route's NRRD estimates, without and with the volume.
fn streams(a: &Args, route: Route, runs_nrrd: Option<[u64; 2]>) -> bool {
    let alone = a.slices.is_none() && a.preview.is_none() && a.mesh.is_none();
    let runs = matches!(route, Route::Runs { .. });
    let eligible = a.format() == FormatArg::Nrrd && a.store.is_none() && alone && runs;
    eligible && runs_nrrd.is_some_and(|[swept, whole]| swept <= whole)
}

/// The NRRD file `out`: its header, then every slice in order of k as the run route sweeps
/// the columns' runs ([`voxelize_slabs`]), so memory is the runs and one slice, not the
/// volume, and the bytes are those of the volume written whole.
#[allow(clippy::too_many_arguments)]
fn stream_nrrd(
    outs: &mut Outputs,
    out: Out,
    slicer: &Slicer,
    route: Route,
    set: rtl_model::EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    (comment, format): (&str, &VolumeFormat),
) -> crate::Result<Work> {
    let nz = slicer.grid.dims[2];
    let mut done: Option<Result<Work, Stop>> = None;
    let written = outs.write_sparse(out, |w| {
        let head = csgpix_scene::nrrd::header_as(&slicer.grid, comment, format);
        w.write_all(head.as_bytes())?;
        let mut data = csgpix_scene::nrrd::data_writer(w, format.encoding);
        // The sink's own error is the file's, told apart from the voxelizer's.
        let mut sink = |_: usize, s: &[u8]| data.write_all(s).map_err(Stop::Io);
        match voxelize_slabs(slicer, route, set, eval, tick, 0..nz, &mut sink) {
            Err(Stop::Io(e)) => Err(e),
            r => {
                let failed = r.is_err();
                done = Some(r);
                match failed {
                    true => Err(std::io::Error::other("the voxelization failed")),
                    false => data.finish(),
                }
            }
        }
    });
    match (done, written) {
        // The voxelizer's error, as the whole-volume path reports it.
        (Some(Err(Stop::Voxel(e))), _) => Err(e.into()),
        (_, Err(e)) => Err(e.into()),
        (Some(Ok(work)), Ok(_)) => Ok(work),
        // The fill returns an I/O error as the file's and sets `done` whenever it succeeds.
        (Some(Err(Stop::Io(_))) | None, Ok(_)) => unreachable!("a fill that succeeded"),
    }
}

/// Why a streamed NRRD sweep stopped: the file's write or the voxelizer.
enum Stop {
    Io(std::io::Error),
    Voxel(VoxelError),
}

impl From<VoxelError> for Stop {
    fn from(e: VoxelError) -> Stop {
        Stop::Voxel(e)
    }
}

/// An upper bound of the run's memory (docs/memory.md), by route and output: the run route's
/// follows the primitives' footprints, the slab routes' every primitive's per-pixel ranges.
fn estimate(
    a: &Args,
    slicer: &Slicer,
    route: Route,
    eval: &dyn SliceEval,
    threads: usize,
    (stream, runs_nrrd): (bool, Option<[u64; 2]>),
) -> crate::Result<u64> {
    #[cfg(feature = "zarr")]
    if a.format() == FormatArg::Zarr {
        // Nothing else is held: check_format refuses --store beside a Zarr store.
        let layout = zarr_layout(a);
        let need = crate::zarr::estimate(slicer, route, eval, threads, (&layout, None));
        return need.map_err(|e| zarr_message(e, a));
    }
    let grid = &slicer.grid;
    let runs = matches!(route, Route::Runs { .. });
    // Streamed, the NRRD output holds the runs and a slice, as a Zarr row sweep does.
    let whole_volume = a.store.is_none() && !stream;
    let mut need = match runs {
        true => runs_nrrd
            .unwrap_or_else(|| csgpix_voxel::runs::memory_estimates(slicer, eval, threads))
            [usize::from(whole_volume)],
        false => crate::memory::slab_route_estimate(slicer, grid, threads),
    };
    if let Some(st) = a.store {
        need = need.saturating_add(octree::memory_estimate(st.kind(), grid.dims)?);
        if runs {
            // The volume is gathered slice by slice beside the store.
            need = need.saturating_add(grid.dims.iter().map(|&d| d as u64).product());
        }
    }
    Ok(need)
}

/// The store's layout from --chunk, --shard and --levels.
#[cfg(feature = "zarr")]
fn zarr_layout(a: &Args) -> csgpix_zarr::Layout {
    csgpix_zarr::Layout {
        chunk: a.chunk.unwrap_or([csgpix_zarr::DEFAULT_CHUNK; 3]),
        shard: a.shard.unwrap_or(csgpix_zarr::DEFAULT_SHARD),
        levels: a.levels.map(usize::from),
    }
}

/// A Zarr store's error, naming `-o` where the library names the staging directory.
#[cfg(feature = "zarr")]
fn zarr_message(e: csgpix_zarr::Error, a: &Args) -> Error {
    use csgpix_zarr::Error as Z;
    match e {
        Z::Store { message, .. } => {
            Error::options("-o", format!("-o {}: {message}", a.out.display()))
        }
        Z::BadLevels { levels, max, depth } => Error::options(
            "--levels",
            format!(
                "--levels {levels}: at most {max} here (with more than one chunk row, \
                 2^(levels-1) must divide the chunk depth, {depth}; and no level past a \
                 1x1x1 one)"
            ),
        ),
        e @ Z::BadChunk { .. } => Error::options("--chunk", format!("--chunk: {e}")),
        e => e.into(),
    }
}

/// The `--mesh` figures of the JSON report.
#[derive(Serialize, Clone, Copy, Debug)]
struct MeshReport {
    mesh_triangles: usize,
    /// The mesh step's memory estimate, bytes, checked before it ran (docs/memory.md).
    mesh_memory_estimate: u64,
    /// Edges not in exactly two triangles (0: closed).
    mesh_open_edges: usize,
}

/// Bytes the mesh step holds per surface voxel beyond the octree's estimate: Marching
/// Cubes' triangles (about 3 a surface voxel, 36 bytes each, and their copy in scene units)
/// and the writer's welded vertices; measured 196-404 bytes (docs/memory.md).
const MESH_BYTES_PER_SURFACE_VOXEL: u64 = 420;

/// Write the volume's surface (`--mesh`, [`mesh`]) and report it.
fn write_mesh(
    outs: &mut Outputs,
    (out, format): (Out, csgpix_scene::mesh::Format),
    grid: &Grid,
    v: &Volume,
    budget: u64,
    comment: &str,
) -> crate::Result<MeshReport> {
    let (tris, need) = mesh(grid, v, budget)?;
    outs.write(out, |w| {
        csgpix_scene::mesh::write_format(w, format, &tris, comment)
    })?;
    Ok(MeshReport {
        mesh_triangles: tris.len(),
        mesh_memory_estimate: need,
        mesh_open_edges: csgpix_scene::mesh::open_edges(&tris),
    })
}

/// The surface of `v` on `grid` by global Marching Cubes over the optimized octree, in scene
/// units: closed and wound outward, as the cells past the grid's far faces are meshed too
/// (docs/octree.md); and its memory estimate, refused when over `budget` bytes.
pub fn mesh(
    grid: &Grid,
    v: &Volume,
    budget: u64,
) -> crate::Result<(Vec<csgpix_scene::mesh::Tri>, u64)> {
    let surface = csgpix_voxel::surface_voxels(v);
    let need = octree::memory_estimate(octree::StoreKind::Octree, v.dims)?
        .saturating_add(surface.saturating_mul(MESH_BYTES_PER_SURFACE_VOXEL));
    if need > budget {
        let message = format!(
            "--mesh: the mesh of {surface} surface voxels needs about {} MiB more, over \
             --max-memory: lower --res or raise the limit",
            need.div_ceil(1 << 20)
        );
        return Err(Error::options("--mesh", message));
    }
    let store = octree::OptimizedOctree::from_volume(v, budget).map_err(lib_errors::sculpt)?;
    let frame = csgpix_sculpt::Frame::of_grid(grid);
    let tris: Vec<csgpix_scene::mesh::Tri> = octree::mc::marching_cubes(&store)
        .triangles
        .iter()
        .map(|t| t.map(|p| frame.to_scene(p)))
        .collect();
    Ok((tris, need))
}

/// Voxelizes while building the store from each slice as it comes (`--store`); the store's
/// budget is what `--max-memory` leaves.
fn with_store(
    slicer: &Slicer,
    route: Route,
    set: rtl_model::EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    kind: StoreKind,
    budget: u64,
) -> crate::Result<(Volume, Work, Option<StoreReport>)> {
    let dims = slicer.grid.dims;
    let mut b = octree::builder(kind, dims, budget).map_err(lib_errors::sculpt)?;
    let mut voxels = Vec::with_capacity(dims.iter().product());
    let mut build = std::time::Duration::ZERO;
    let work = voxelize_streaming(slicer, route, set, eval, tick, &mut |k, s| {
        voxels.extend_from_slice(s);
        let t = Instant::now();
        let r = b.push(k, s).map_err(lib_errors::sculpt);
        build += t.elapsed();
        r
    })?;
    let t = Instant::now();
    let st = b.finish().map_err(lib_errors::sculpt)?;
    build += t.elapsed();
    let r = StoreReport {
        kind,
        depth: st.depth(),
        side: st.side(),
        nodes: st.node_count(),
        internal_nodes: st.internal_count(),
        bytes: st.bytes(),
        bytes_per_node: st.bytes() as f64 / st.node_count().max(1) as f64,
        build_seconds: build.as_secs_f64(),
    };
    Ok((Volume { dims, voxels }, work, Some(r)))
}

/// The route a model and `--route` ask for: the run route where it gives the volume
/// ([`csgpix_voxel::runs::applies`]), else its slab route.
fn route_of(model: Model, route: RouteArg, slicer: &Slicer) -> Route {
    let r = match (model, route) {
        (Model::Cycle, _) => Route::Array { cycle: true },
        (Model::Word, RouteArg::Array) => Route::Array { cycle: false },
        (Model::Word, RouteArg::Intervals) => Route::Intervals,
        (Model::Word, RouteArg::Runs) => Route::Runs { float: false },
        (Model::Float, RouteArg::Runs) => Route::Runs { float: true },
        (Model::Float, _) => Route::Float,
    };
    match csgpix_voxel::runs::applies(slicer) {
        true => r,
        false => r.by_slab(),
    }
}

/// `--json`'s name of a route: the float model's slab route is `float`, as it always was.
fn route_name(route: Route) -> &'static str {
    match route {
        Route::Array { .. } => "array",
        Route::Intervals => "intervals",
        Route::Float => "float",
        Route::Runs { .. } => "runs",
    }
}

/// A progress bar for runs that take a while: slices on the slab routes, bands of rows on
/// the run route (which ticks once per band).
fn progress(slicer: &Slicer, route: Route) -> ProgressBar {
    let [_, _, nz] = slicer.grid.dims;
    let voxels = slicer.grid.slice_len() * nz;
    let (len, unit) = match route {
        Route::Runs { .. } => (csgpix_voxel::runs::ticks(slicer), "row bands"),
        _ => (nz, "slices"),
    };

    let heavy = match route {
        Route::Array { .. } => true,
        Route::Runs { .. } => voxels > 100_000_000,
        _ => voxels * slicer.primitive_count() > 50_000_000,
    };
    let bar = match heavy {
        true => ProgressBar::new(len as u64),
        false => ProgressBar::hidden(),
    };
    // The unit is the message, so that a Zarr run by bricks can count bricks instead.
    let template = "{elapsed_precise} [{bar:40}] {pos}/{len} {msg}";
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style);
    }
    bar.set_message(unit);
    bar
}

fn report(
    a: &Args,
    scene: &CsgScene,
    slicer: &Slicer,
    eval: &dyn SliceEval,
    (work, store, mesh): (Work, Option<StoreReport>, Option<MeshReport>),
    (wall, to_stderr, memory_estimate): (f64, bool, u64),
    zarr: Option<ZarrReport>,
) -> crate::Result<ExitCode> {
    let say = |line: String| super::report_line(&line, to_stderr);
    let pixels = slicer.grid.slice_len();
    let table = BlistTable::compile(&scene.root);
    let r = Report {
        memory_estimate,
        dims: slicer.grid.dims,
        sampling: a.grid.sampling.name(),
        voxel: slicer.grid.voxel().to_array(),
        min: slicer.grid.min.to_array(),
        max: slicer.grid.max.to_array(),
        model: a.model.name(),
        route: route_name(route_of(a.model, a.route, slicer)),
        eval: match a.eval {
            EvalArg::Blist => "blist",
            EvalArg::Tree => "tree",
            EvalArg::Stack => "stack",
        },
        solids: scene.solids.len(),
        imports: scene.imports.len(),
        values: if a.blend.is_some() {
            "grey (blended, §3.3)"
        } else if a.grey {
            "colour codes, datasets grey"
        } else {
            "colour codes"
        },
        label_bits: table.label_bits,
        blist_rows: table.rows.len(),
        state_bits_per_voxel: eval.state_bytes(pixels) * 8 / pixels.max(1),
        work,
        store,
        zarr,
        mesh,
        hardware_seconds: work.cycles as f64 * 1e-7,
        wall_seconds: wall,
        warnings: scene
            .warnings
            .iter()
            .chain(slicer.sampled.iter().filter_map(|s| s.warning()))
            .map(|w| w.to_string())
            .collect(),
    };
    if a.json {
        println!("{}", serde_json::to_string_pretty(&r)?);
    } else {
        say(format!(
            "{}: {}x{}x{} voxels, {} filled; {} frames, {} clocks ({:.3} s at 10 MHz); {:.3} s wall",
            a.out.display(),
            r.dims[0],
            r.dims[1],
            r.dims[2],
            r.work.filled,
            work.frames,
            work.cycles,
            r.hardware_seconds,
            wall
        ));
        if work.simulated_pixel_clocks > 0 {
            say(format!(
                "simulated {} of the whole array's {} pixel-clocks ({:.1}%, --panel)",
                work.simulated_pixel_clocks,
                work.full_pixel_clocks,
                100.0 * work.simulated_pixel_clocks as f64 / work.full_pixel_clocks.max(1) as f64
            ));
        }
        if let Some(st) = &r.store {
            say(format!(
                "store {}: {} nodes ({} internal), {} bytes, built in {:.3} s",
                st.kind.name(),
                st.nodes,
                st.internal_nodes,
                st.bytes,
                st.build_seconds
            ));
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// One view of the volume along an axis: per pixel the first filled voxel's colour code and
/// its depth along the axis. `axis` 2 looks along +Z (X right, Y down), 1 along +Y (X right,
/// Z down), 0 along +X (Y right, Z down).
fn view(v: &Volume, axis: usize) -> (usize, usize, Vec<u32>, Vec<Option<f64>>) {
    let [nx, ny, nz] = v.dims;
    let at = |i: usize, j: usize, k: usize| v.voxels[(k * ny + j) * nx + i];
    let (w, h, depth) = match axis {
        2 => (nx, ny, nz),
        1 => (nx, nz, ny),
        _ => (ny, nz, nx),
    };
    let (mut codes, mut depths) = (vec![0u32; w * h], vec![None; w * h]);
    for r in 0..h {
        for c in 0..w {
            let hit = (0..depth).find_map(|d| {
                let code = match axis {
                    2 => at(c, r, d),
                    1 => at(c, d, r),
                    _ => at(d, c, r),
                };
                (code != 0).then_some((code, d))
            });
            if let Some((code, d)) = hit {
                codes[r * w + c] = code as u32;
                depths[r * w + c] = Some(d as f64);
            }
        }
    }
    (w, h, codes, depths)
}

/// The three axis views side by side, 4 pixels apart, scaled up by a whole factor towards 256
/// pixels.
/// What a volume's values mean, for pictures.
#[derive(Clone, Copy, PartialEq)]
enum Values {
    /// Palette codes.
    Codes,
    /// Palette codes below GREY_BASE, grey levels from it (`--grey`).
    Mixed,
    /// Grey levels (`--blend`).
    Grey,
}

impl Values {
    fn rgb(self, c: u8) -> [u8; 3] {
        match self {
            Values::Grey => [c; 3],
            Values::Mixed if c >= csgpix_voxel::GREY_BASE => [c; 3],
            _ => rgb(c as u32),
        }
    }
}

fn write_preview(outs: &mut Outputs, out: Out, v: &Volume, grey: Values) -> crate::Result<()> {
    let views: Vec<_> = (0..3).rev().map(|a| view(v, a)).collect();
    let scale = (256 / v.dims.iter().copied().max().unwrap_or(1)).max(1);
    let width: usize = views.iter().map(|x| x.0 * scale + 4).sum();
    let height = views.iter().map(|x| x.1 * scale).max().unwrap_or(1);
    let mut img =
        image::RgbImage::from_pixel(width as u32, height as u32, image::Rgb([255, 255, 255]));
    let mut left = 0;
    for (w, h, codes, depths) in &views {
        let rgb = match grey {
            Values::Codes => csgpix_draw::palette::image_rgb(codes, Some(depths)),
            _ => shaded(codes, depths, grey),
        };
        for (i, c) in rgb.iter().enumerate() {
            for dy in 0..scale {
                for dx in 0..scale {
                    let (x, y) = (left + (i % w) * scale + dx, (i / w) * scale + dy);
                    img.put_pixel(x as u32, y as u32, image::Rgb(*c));
                }
            }
        }
        left += w * scale + 4;
        let _ = h;
    }
    Ok(outs.write(out, |w| crate::png::write_png(w, &img))?)
}

/// Values shaded by depth as the palette view shades colours: nearest full, farthest 45%.
fn shaded(codes: &[u32], depths: &[Option<f64>], values: Values) -> Vec<[u8; 3]> {
    let ds = depths.iter().flatten();
    let (lo, hi) = ds.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &d| {
        (a.min(d), b.max(d))
    });
    codes
        .iter()
        .zip(depths)
        .map(|(&c, d)| {
            let t = d.map_or(0.0, |d| if hi > lo { (d - lo) / (hi - lo) } else { 0.0 });
            values
                .rgb(c as u8)
                .map(|x| (x as f64 * (1.0 - 0.55 * t)).round() as u8)
        })
        .collect()
}

/// Every slice as `slice-KKKK.png`, staged with the run's other outputs: an indexed PNG whose
/// pixel indices are the voxels' values (label codes, or grey values with `grey`/`blend`),
/// so the codes survive, shown in the palette's colours (or grey levels).
fn write_slices(outs: &mut Outputs, dir: Out, v: &Volume, grey: Values) -> crate::Result<()> {
    let [nx, ny, nz] = v.dims;
    // Entries up to the largest value of the volume: every slice's indices are in range.
    let top = v.voxels.iter().copied().max().unwrap_or(0);
    let palette: Vec<[u8; 3]> = (0..=top).map(|c| grey.rgb(c)).collect();
    for k in 0..nz {
        let slice = &v.voxels[k * nx * ny..(k + 1) * nx * ny];
        let name = format!("slice-{k:04}.png");
        let size = (nx as u32, ny as u32);
        outs.write_in(dir, &name, |w| {
            crate::png::write_indexed_png(w, size, slice, &palette)
        })?;
    }
    Ok(())
}
