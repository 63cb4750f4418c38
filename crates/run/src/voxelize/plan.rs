//! The plan of a voxelization: its grid, the slicer of the scene on it (§4.4; the one place
//! its options are made), the evaluator of the tree per slice (§4.2, §3.4.1, §4.5), the
//! route, the worker threads, and the memory estimate (docs/memory.md).

use std::ops::Range;

use csgpix_draw::Model;
use csgpix_scene::solid::CsgScene;
use csgpix_sculpt::octree;
use csgpix_voxel::blend::BlendEval;
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::evaluate::{StackEval, TreeEval};
use csgpix_voxel::sampled::Loaded;
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{voxelize_slabs, Error as VoxelError, Grid, Route, Slicer, SlicerOptions};

use super::{Eval, Format, RouteKind, Voxelization, VoxelizeJob};
use crate::lib_errors::voxel as voxel_error;
#[cfg(feature = "zarr")]
use crate::memory::imports_estimate;
use crate::{lib_errors, Error};
#[cfg(feature = "zarr")]
use csgpix_voxel::PixelBox;
#[cfg(feature = "zarr")]
use csgpix_zarr::Layout;

/// A job's worker threads: rayon's global pool (one thread per core) by default, or a pool
/// of the `--threads` asked. The job reads its scene, plans and runs on them, so the count
/// asked holds for all three and the default makes no second pool beside the global one.
pub struct Workers(Option<rayon::ThreadPool>);

impl Workers {
    /// The global pool (`threads` None), or a pool of `threads`.
    pub fn new(threads: Option<usize>) -> crate::Result<Workers> {
        let pool = threads.map(|n| rayon::ThreadPoolBuilder::new().num_threads(n).build());
        Ok(Workers(pool.transpose()?))
    }

    /// `f` run with these threads as rayon's.
    pub fn install<R: Send>(&self, f: impl FnOnce() -> R + Send) -> R {
        match &self.0 {
            Some(pool) => pool.install(f),
            None => f(),
        }
    }

    /// How many there are.
    pub fn count(&self) -> usize {
        self.install(rayon::current_num_threads)
    }
}

/// A voxelization planned on a loaded scene.
pub struct Plan {
    /// The scene cut into slices on the grid (`slicer.grid`).
    pub slicer: Slicer,
    /// The tree's evaluator per slice.
    pub eval: Box<dyn SliceEval + Send + Sync>,
    /// The route the model and route options take on this slicer.
    pub route: Route,
    /// Worker threads.
    pub threads: usize,
    /// Their pool.
    pub pool: Workers,
}

/// What the plan holds in memory, and how the NRRD output goes.
pub struct Budget {
    /// The estimate checked against the limit, bytes.
    pub need: u64,
    /// The NRRD file is written slice by slice, the volume never held.
    pub stream: bool,
    /// `--store`: the bytes of its nodes, bounded from the scene.
    pub store_nodes: Option<u64>,
}

impl Voxelization {
    /// The slicer of `loaded` on `grid` with `sampling` (§4.4).
    pub fn slicer(
        &self,
        loaded: &Loaded,
        grid: Grid,
        sampling: csgpix_voxel::Sampling,
    ) -> Result<Slicer, VoxelError> {
        let scene = &loaded.scene;
        let opts = SlicerOptions {
            fmt: self.word,
            sampling,
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
            Eval::Tree => Box::new(TreeEval::new(&scene.root)),
            Eval::Stack => Box::new(StackEval::new(&scene.root)),
            Eval::Blist => Box::new(BlistEval::new(&scene.root)),
        }
    }

    /// The route the model and the route option ask for on `slicer`: the run route where it
    /// gives the volume ([`csgpix_voxel::runs::applies`]), else its slab route.
    pub fn route(&self, slicer: &Slicer) -> Route {
        let r = match (self.model, self.route) {
            (Model::Cycle, _) => Route::Array { cycle: true },
            (Model::Word, RouteKind::Array) => Route::Array { cycle: false },
            (Model::Word, RouteKind::Intervals) => Route::Intervals,
            (Model::Word, RouteKind::Runs) => Route::Runs { float: false },
            (Model::Float, RouteKind::Runs) => Route::Runs { float: true },
            (Model::Float, _) => Route::Float,
        };
        match csgpix_voxel::runs::applies(slicer) {
            true => r,
            false => r.by_slab(),
        }
    }

    /// What the voxel values mean, as the report says it.
    pub fn values(&self) -> &'static str {
        if self.blend.is_some() {
            "grey (blended, §3.3)"
        } else if self.grey {
            "colour codes, datasets grey"
        } else {
            "colour codes"
        }
    }
}

/// `--json`'s name of a route: the float model's slab route is `float`, as it always was.
pub(super) fn route_name(route: Route) -> &'static str {
    match route {
        Route::Array { .. } => "array",
        Route::Intervals => "intervals",
        Route::Float => "float",
        Route::Runs { .. } => "runs",
    }
}

impl VoxelizeJob {
    /// The plan on `loaded`, its errors in the command line's words and said of the input.
    pub fn plan(&self, loaded: &Loaded) -> crate::Result<Plan> {
        self.plan_with(loaded, Workers::new(self.threads)?)
    }

    /// [`VoxelizeJob::plan`] on the threads `pool` (those the scene was read on).
    pub fn plan_with(&self, loaded: &Loaded, pool: Workers) -> crate::Result<Plan> {
        let name = self.name();
        let grid = self.grid.grid(loaded).map_err(voxel_error);
        let grid = grid.map_err(|e| e.context(&name))?;
        let plan = self.plan_in(loaded, grid, pool);
        plan.map_err(|e| Error::from(e).context(&name))
    }

    /// The plan on `loaded` and `grid`: the voxelizer's error (outer), or the pool's (inner).
    pub fn plan_on(&self, loaded: &Loaded, grid: Grid) -> Result<crate::Result<Plan>, VoxelError> {
        match Workers::new(self.threads) {
            Ok(pool) => self.plan_in(loaded, grid, pool).map(Ok),
            Err(e) => Ok(Err(e)),
        }
    }

    /// The plan on `loaded` and `grid` with the threads `pool`, the slicer made on them.
    pub fn plan_in(&self, loaded: &Loaded, grid: Grid, pool: Workers) -> Result<Plan, VoxelError> {
        let threads = pool.count();
        let slicer = pool.install(|| self.voxels.slicer(loaded, grid, self.grid.sampling))?;
        let eval = self.voxels.evaluator(&loaded.scene);
        let route = self.voxels.route(&slicer);
        Ok(Plan {
            slicer,
            eval,
            route,
            threads,
            pool,
        })
    }
}

impl Plan {
    /// Whether the run goes by the run route.
    pub fn runs(&self) -> bool {
        matches!(self.route, Route::Runs { .. })
    }

    /// The memory of the job's run (docs/memory.md), by route and output: the run route's
    /// follows the primitives' footprints, the slab routes' every primitive's per-pixel
    /// ranges; and whether the NRRD output is streamed.
    pub fn budget(&self, job: &VoxelizeJob, scene: &CsgScene) -> crate::Result<Budget> {
        let (slicer, e, threads) = (&self.slicer, self.eval.as_ref(), self.threads);
        // The run route's NRRD estimates, with and without the volume: they decide whether
        // the file is streamed, and the one that applies is the run's. They walk a dataset's
        // columns to count its runs: on the run's own threads.
        let runs_nrrd = (self.runs() && job.format() == Format::Nrrd).then(|| {
            let each = || csgpix_voxel::runs::memory_estimates(slicer, e, threads);
            self.pool.install(each)
        });
        // Beside the route's own memory: the planes held and what the reader freed, which
        // stays with the process (CsgScene::reading_bytes).
        let beside = slicer
            .planes_bytes(scene, self.runs(), threads)
            .saturating_add(scene.reading_bytes);
        let room = job.max_memory.bytes().saturating_sub(beside);
        let stream = streams(job, self.route, runs_nrrd, room);
        let store_nodes = self.store_nodes(job, scene)?;
        let need = self
            .pool
            .install(|| self.estimate(job, stream, runs_nrrd))?
            .saturating_add(beside);
        let read = scene
            .reading_bytes
            .saturating_add(csgpix_voxel::PROCESS_BYTES);
        Ok(Budget {
            need: need.saturating_add(store_nodes.unwrap_or(0)).max(read),
            stream,
            store_nodes,
        })
    }

    /// `--store`: its nodes bounded from the scene (docs/memory.md).
    fn store_nodes(&self, job: &VoxelizeJob, scene: &CsgScene) -> crate::Result<Option<u64>> {
        let Some(kind) = job.outputs.store else {
            return Ok(None);
        };
        let dims = self.slicer.grid.dims;
        let depth = octree::depth_for(dims).map_err(lib_errors::sculpt)?;
        let counts = csgpix_voxel::cells::cell_counts(scene, &self.slicer, depth);
        Ok(Some(
            octree::estimate::store_bytes(kind, dims, &counts)?.nodes,
        ))
    }

    /// An upper bound of the run's memory beside the store's nodes.
    fn estimate(
        &self,
        job: &VoxelizeJob,
        stream: bool,
        runs_nrrd: Option<[u64; 2]>,
    ) -> crate::Result<u64> {
        let (slicer, eval, threads) = (&self.slicer, self.eval.as_ref(), self.threads);
        #[cfg(feature = "zarr")]
        if job.format() == Format::Zarr {
            // Nothing else is held: the format's check refuses --store beside a Zarr store.
            let layout = job.zarr_layout();
            let need = zarr_estimate(slicer, self.route, eval, threads, (&layout, None));
            return need.map_err(|e| job.zarr_message(e));
        }
        let grid = &slicer.grid;
        // Streamed, the NRRD output holds the runs and a slice, as a Zarr row sweep does.
        let whole_volume = job.outputs.store.is_none() && !stream;
        let mut need = match self.runs() {
            true => runs_nrrd
                .unwrap_or_else(|| csgpix_voxel::runs::memory_estimates(slicer, eval, threads))
                [usize::from(whole_volume)],
            false => crate::memory::slab_route_estimate(slicer, grid, threads),
        };
        if job.outputs.preview.is_some() {
            need = need.saturating_add(preview_bytes(grid.dims));
        }
        if let Some(st) = job.outputs.store {
            need = need.saturating_add(octree::memory_estimate(st, grid.dims)?);
            if self.runs() {
                // The volume is gathered slice by slice beside the store.
                need = need.saturating_add(grid.dims.iter().map(|&d| d as u64).product());
            }
        }
        Ok(need)
    }

    /// An upper bound of the memory of [`Plan::slabs`] over `z` (docs/memory.md): the slabs
    /// it returns beside the route's working memory. On the run route that is the runs of
    /// the whole grid, swept along z; on a slab route the slab ranges and per-thread state of
    /// a volume only `z` deep, and the imported primitives.
    pub fn slabs_estimate(&self, z: &Range<usize>) -> u64 {
        let slicer = &self.slicer;
        let out = (z.len() as u64).saturating_mul(slicer.grid.slice_len() as u64);
        if self.runs() {
            let e = self.eval.as_ref();
            let each = || csgpix_voxel::runs::memory_estimates(slicer, e, self.threads);
            return self.pool.install(each)[0].saturating_add(out);
        }
        let mut held = slicer.grid;
        held.dims[2] = z.len().max(1);
        crate::memory::slab_route_estimate(slicer, &held, self.threads)
    }

    /// Slabs `z` of the volume: the slices' bytes, x fastest, then y, then k; `tick` once a
    /// slice (or a band of rows on the run route).
    pub fn slabs(
        &self,
        voxels: &Voxelization,
        z: Range<usize>,
        tick: &(dyn Fn() + Sync),
    ) -> Result<Vec<u8>, VoxelError> {
        let mut out = Vec::with_capacity(z.len() * self.slicer.grid.slice_len());
        let set = voxels.equations.set();
        let e = self.eval.as_ref();
        self.pool.install(|| {
            let mut sink = |_: usize, s: &[u8]| {
                out.extend_from_slice(s);
                Ok(())
            };
            voxelize_slabs::<VoxelError>(&self.slicer, self.route, set, e, tick, z, &mut sink)
        })?;
        Ok(out)
    }
}

/// The memory of `--preview` beside the volume (`outputs::write_preview`): the three views'
/// codes and depths (4 + 16 bytes a pixel), one view's colours, the image scaled towards 256
/// pixels and the encoder's copy of it (3 bytes a pixel each).
pub fn preview_bytes([nx, ny, nz]: [usize; 3]) -> u64 {
    let views = [(nx, ny), (nx, nz), (ny, nz)].map(|(w, h)| (w as u64, h as u64));
    let scale = (256 / nx.max(ny).max(nz).max(1)).max(1) as u64;
    let codes: u64 = views.iter().map(|(w, h)| w * h * 20).sum();
    let colours = views.iter().map(|(w, h)| w * h * 3).max().unwrap_or(0);
    let width: u64 = views.iter().map(|(w, _)| w * scale + 4).sum();
    let height = views.iter().map(|(_, h)| h * scale).max().unwrap_or(1);
    codes + colours + 2 * 3 * width * height
}

/// Whether the NRRD file is written slice by slice as the run route sweeps them, the volume
/// never held: when nothing else needs it (no --slices, --preview, --mesh or --store) and the
/// estimate of the columns' runs, held for the sweep, is below the whole volume's or within
/// `room` (the memory limit less what either way holds beside). Swept, the run is faster and
/// its peak lower on every design measured (docs/memory.md, "Written slice by slice"): its
/// bound counts each primitive on every column of its outline box, so it can pass the volume
/// where the runs do not; the volume is held only where that bound does not fit. `runs_nrrd`:
/// the run route's NRRD estimates, without and with the volume.
fn streams(job: &VoxelizeJob, route: Route, runs_nrrd: Option<[u64; 2]>, room: u64) -> bool {
    let o = &job.outputs;
    let alone = o.slices.is_none() && o.preview.is_none() && o.mesh.is_none();
    let runs = matches!(route, Route::Runs { .. });
    let eligible = job.format() == Format::Nrrd && o.store.is_none() && alone && runs;
    eligible && runs_nrrd.is_some_and(|[swept, whole]| swept <= whole || swept <= room)
}

/// Whether the store is written brick by brick (a chunk row of one XY tile: the run route)
/// rather than a whole chunk row at a time.
pub fn by_bricks(route: Route) -> bool {
    matches!(route, Route::Runs { .. })
}

#[cfg(feature = "zarr")]
/// The memory of voxelizing chunk rows of a store cut by `layout` on the slicer's grid with
/// `threads` threads (docs/memory.md): on the run route a tile's runs (of `tiles`, a task's
/// share of [`csgpix_zarr::ZarrVolume::tiles`], or of any tile) and the writer's bricks, else the rows'
/// slabs, the writer's and the imports' samples.
pub fn zarr_estimate(
    slicer: &Slicer,
    route: Route,
    eval: &dyn SliceEval,
    threads: usize,
    (layout, tiles): (&Layout, Option<Range<usize>>),
) -> Result<u64, csgpix_zarr::Error> {
    let grid = &slicer.grid;
    if by_bricks(route) {
        let levels = csgpix_zarr::plan(grid.dims, layout)?;
        let tile = csgpix_zarr::tile(grid.dims, &levels);
        let writer = csgpix_zarr::writer_bytes_bricks(grid.dims, layout, threads)?;
        // A task's tiles: only their panels' datasets are walked to count their runs.
        let boxes = csgpix_zarr::tile_boxes(grid.dims, tile);
        let within = tiles.and_then(|t| boxes.get(t)).map(|b| {
            let all = b.iter().copied().reduce(PixelBox::union);
            all.unwrap_or(PixelBox::new(0, 0, 0, 0))
        });
        let runs = csgpix_voxel::runs::memory_estimate_bricks(slicer, eval, threads, tile, within);
        return Ok(runs.saturating_add(writer));
    }
    let prims = slicer.primitive_count();
    let rows = csgpix_zarr::memory_estimate(grid, layout, prims, threads)?;
    Ok(rows.saturating_add(imports_estimate(slicer)))
}

#[cfg(test)]
mod tests {
    use super::Workers;

    /// `--threads n` gives a pool of n, whose threads the work installed sees as rayon's;
    /// no count runs on the global pool, in the caller's thread.
    #[test]
    fn workers_are_the_threads_asked_or_the_global_pool() {
        for n in [1, 3] {
            let w = Workers::new(Some(n)).unwrap();
            assert_eq!(w.count(), n);
            let inside = w.install(rayon::current_thread_index);
            assert!(inside.is_some_and(|i| i < n), "{inside:?}");
        }
        let w = Workers::new(None).unwrap();
        assert_eq!(w.count(), rayon::current_num_threads());
        let caller = std::thread::current().id();
        assert_eq!(w.install(|| std::thread::current().id()), caller);
    }
}
