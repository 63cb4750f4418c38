//! `csgpix voxelize`: flags to a [`VoxelizeJob`], its report as text lines or `--json`.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_draw::Model;
use csgpix_run::array_args::parse_word;
use csgpix_run::grid::{parse_res, Resolution};
use csgpix_run::voxelize::{
    parse_blend, parse_chunk, parse_panel, parse_shard, Eval, Format, OutputOptions, PanelArg,
    RouteKind, Voxelization, VoxelizeJob, VoxelizeReport,
};
use csgpix_sculpt::octree::StoreKind;
use csgpix_voxel::blend::Union;
use csgpix_voxel::sampled::{parse_binding, Binding};
use rtl_model::{Equations, WordFormat};

use super::common::{named, GridArgs, MaxMemory, ReadArgs, SweepArgs};
use super::progress::Bars;

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
    #[arg(long, value_parser = named::<Model>(), default_value = "word")]
    model: Model,
    /// `runs` (word or float): each primitive's depths along every pixel's column, the tree
    /// evaluated once per run of constant membership (docs/voxelization.md); `intervals`: the
    /// same depths intersected with every slab, slab by slab; both proven voxel for voxel
    /// equal to the array (word). `array` (word) runs every P·Vz frame on the word array.
    #[arg(long, value_parser = named::<RouteKind>(), default_value = "runs")]
    route: RouteKind,
    /// Evaluator of the CSG tree per slice.
    #[arg(long, value_parser = named::<Eval>(), default_value = "blist")]
    eval: Eval,
    /// Select equations (array routes).
    #[arg(long, value_parser = named::<Equations>(), default_value = "derived")]
    equations: Equations,
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
    #[arg(long, value_parser = named::<Format>())]
    format: Option<Format>,
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
    #[command(flatten)]
    sweep: SweepArgs,
    #[command(flatten)]
    mem: MaxMemory,
    #[command(flatten)]
    openscad: ReadArgs,
    /// Also build a voxel store of the volume's dual cells, slice by slice while voxelizing
    /// (seed 000 Ch. 4; docs/octree.md), and report its nodes, bytes and build time.
    #[arg(long, value_parser = named::<StoreKind>())]
    store: Option<StoreKind>,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
}

impl Args {
    fn job(&self) -> VoxelizeJob {
        VoxelizeJob {
            scene: self.scene.clone(),
            expr: self.expr.clone(),
            prim: self.prim.clone(),
            grid: self.grid.options(self.res),
            voxels: Voxelization {
                model: self.model,
                route: self.route,
                eval: self.eval,
                equations: self.equations,
                word: self.word,
                panel: self.panel.0,
                grey: self.grey,
                blend: self.blend,
            },
            outputs: self.outputs(),
            threads: self.sweep.threads(),
            max_memory: self.mem.limit(),
            read: self.sweep.reading(self.openscad.into()),
            fallback: self.sweep.fallback,
        }
    }

    fn outputs(&self) -> OutputOptions {
        OutputOptions {
            out: self.out.clone(),
            format: self.format,
            compress: self.compress,
            chunk: self.chunk,
            shard: self.shard,
            levels: self.levels.map(usize::from),
            slices: self.slices.clone(),
            preview: self.preview.clone(),
            mesh: self.mesh.clone(),
            store: self.store,
            report_to_stdout: self.json,
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a.job().run(&Bars::default())?;
    super::print(a.json, &report, |r| print_text(&a, r))
}

/// The closing lines: on standard output, or on standard error when an output went there.
fn print_text(a: &Args, r: &VoxelizeReport) {
    let say = |line: String| super::report_line(&line, r.to_stdout);
    let work = &r.work;
    say(format!(
        "{}: {}x{}x{} voxels, {} filled; {} frames, {} clocks ({:.3} s at 10 MHz); {:.3} s wall",
        a.out.display(),
        r.dims[0],
        r.dims[1],
        r.dims[2],
        work.filled,
        work.frames,
        work.cycles,
        r.hardware_seconds,
        r.wall_seconds
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

#[cfg(test)]
mod tests {
    use super::*;
    use csgpix_openscad::Fallback;

    fn parse(args: &[&str]) -> Args {
        let a = parsed!(Voxelize, args);
        a
    }

    /// The flags' defaults are the job's documented defaults.
    #[test]
    fn flags_make_the_default_job() {
        let a = parse(&["csgpix", "voxelize", "s.csg", "--res", "8", "-o", "s.nrrd"]);
        let job = a.job();
        let mut want = VoxelizeJob {
            scene: Some("s.csg".into()),
            ..VoxelizeJob::default()
        };
        want.grid.res = Some(Resolution::Longest(8));
        want.outputs.out = "s.nrrd".into();
        // The memory available moves between two readings of it.
        want.max_memory.mib = job.max_memory.mib;
        assert_eq!(job, want);
    }

    #[test]
    fn named_values_parse_as_before() {
        let a = parse(&[
            "csgpix",
            "voxelize",
            "s.csg",
            "--res",
            "8",
            "-o",
            "s.zarr",
            "--route",
            "intervals",
            "--eval",
            "stack",
            "--store",
            "pointer-block",
            "--fallback",
            "openscad",
            "--equations",
            "printed",
            "--format",
            "zarr",
            "--sampling",
            "center",
        ]);
        let job = a.job();
        assert_eq!(job.voxels.route, RouteKind::Intervals);
        assert_eq!(job.voxels.eval, Eval::Stack);
        assert_eq!(job.outputs.store, Some(StoreKind::PointerBlock));
        assert_eq!(job.fallback, Fallback::Openscad);
        assert_eq!(job.voxels.equations, Equations::Printed);
        assert_eq!(job.outputs.format, Some(Format::Zarr));
    }
}
