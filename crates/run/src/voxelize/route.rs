//! Running the slices (§4.4) into the job's output: a NRRD file streamed slice by slice as
//! the run route sweeps them, a Zarr store by chunk rows or bricks, or the volume in memory
//! (with a voxel store built beside it, `--store`) for the outputs that need it whole.

use std::io::Write;
use std::time::Instant;

use csgpix_output::Out;
use csgpix_scene::nrrd::VolumeFormat;
use csgpix_scene::solid::CsgScene;
use csgpix_sculpt::octree::{self, StoreKind};
use csgpix_voxel::blist::BlistTable;
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{voxelize, voxelize_slabs, Error as VoxelError, Route, Slicer, Volume, Work};
use rtl_model::EquationSet;
use serde::Serialize;

use super::outputs::{MeshReport, Staged};
use super::plan::{route_name, Budget, Plan};
#[cfg(feature = "zarr")]
use super::Format;
use super::{VoxelizeJob, VoxelizeReport, ZarrReport};
use crate::progress::Progress;
use crate::{lib_errors, store};

/// The store `--store` built.
#[derive(Serialize, Clone, Debug)]
pub struct StoreReport {
    pub kind: StoreKind,
    /// Octree levels below the root (cell grid side 2^depth).
    pub depth: u32,
    pub side: usize,
    /// Nodes held (pointer and hash: 8·I + 1 with the root; octree: 7·I + 1; dense: cells).
    pub nodes: usize,
    pub internal_nodes: usize,
    pub bytes: usize,
    pub bytes_per_node: f64,
    /// Time spent in the store's builder (slices in, store out), voxelization excluded.
    pub build_seconds: f64,
}

/// What a run made, for its report.
pub struct Ran {
    pub work: Work,
    pub store: Option<StoreReport>,
    pub zarr: Option<ZarrReport>,
    pub mesh: Option<MeshReport>,
    /// Seconds from the first slice to the last output staged.
    pub wall: f64,
    /// An output went to standard output.
    pub to_stdout: bool,
}

/// Boundary edges × voxels of the open meshes' outlines past which the run route shows its
/// progress whatever the grid's size: about a second of winding numbers where every sample
/// is summed (docs/volume-scenes.md, "Open and non-manifold meshes").
const OPEN_MESH_HEAVY: u64 = 200_000_000;

/// The progress of a run that takes a while: slices on the slab routes, bands of rows on
/// the run route (which ticks once per band, and once per row of an open mesh's outline),
/// bricks for a Zarr store by bricks (`bricks`). Light runs show none.
fn stage(slicer: &Slicer, route: Route, bricks: Option<usize>, progress: &dyn Progress) {
    let [_, _, nz] = slicer.grid.dims;
    let voxels = slicer.grid.slice_len() * nz;
    let heavy = match route {
        Route::Array { .. } => true,
        // An open mesh's winding numbers can outlast the voxels (a soup of loose triangles).
        Route::Runs { .. } => {
            voxels > 100_000_000 || csgpix_voxel::runs::open_mesh_work(slicer) > OPEN_MESH_HEAVY
        }
        _ => voxels * slicer.primitive_count() > 50_000_000,
    };
    if !heavy {
        return;
    }
    match (bricks, route) {
        (Some(n), _) => progress.stage("bricks", n as u64),
        (None, Route::Runs { .. }) => {
            progress.stage("row bands", csgpix_voxel::runs::ticks(slicer) as u64)
        }
        (None, _) => progress.stage("slices", nz as u64),
    }
}

/// Run `plan` into the outputs `staged` names, and commit them.
pub fn run(
    job: &VoxelizeJob,
    plan: &Plan,
    budget: &Budget,
    staged: Staged,
    progress: &dyn Progress,
) -> crate::Result<Ran> {
    let t0 = Instant::now();
    #[cfg(feature = "zarr")]
    if job.format() == Format::Zarr {
        return zarr(job, plan, staged, progress, t0);
    }
    let tick = || progress.advance(1);
    if budget.stream {
        stage(&plan.slicer, plan.route, None, progress);
        let mut staged = staged;
        let (out, head) = (staged.nrrd, staged.nrrd_format(job, &plan.slicer));
        let comment = format!("csgpix voxelize {}", job.name());
        let work = plan.pool.install(|| {
            let e = plan.eval.as_ref();
            let route = (plan.route, job.voxels.equations.set());
            stream_nrrd(
                &mut staged.outs,
                out,
                &plan.slicer,
                route,
                e,
                &tick,
                (&comment, &head),
            )
        })?;
        progress.finish();
        let wall = t0.elapsed().as_secs_f64();
        let to_stdout = staged.outs.uses_stdout();
        staged.outs.commit()?;
        let (store, zarr, mesh) = (None, None, None);
        return Ok(Ran {
            work,
            store,
            zarr,
            mesh,
            wall,
            to_stdout,
        });
    }
    in_memory(job, plan, budget, staged, progress, t0)
}

/// The volume in memory (and the store beside it), then every output made of it.
fn in_memory(
    job: &VoxelizeJob,
    plan: &Plan,
    budget: &Budget,
    staged: Staged,
    progress: &dyn Progress,
    t0: Instant,
) -> crate::Result<Ran> {
    stage(&plan.slicer, plan.route, None, progress);
    let tick = || progress.advance(1);
    let rest = job.max_memory.bytes().saturating_sub(budget.need);
    let (slicer, e) = (&plan.slicer, plan.eval.as_ref());
    let route = (plan.route, job.voxels.equations.set());
    let (volume, work, store) = match job.outputs.store {
        None => plan
            .pool
            .install(|| voxelize(slicer, route.0, route.1, e, &tick))
            .map(|(v, w)| (v, w, None))?,
        Some(kind) => {
            // The nodes are charged against what the estimate kept for them.
            let budget = rest.saturating_add(budget.store_nodes.unwrap_or(0));
            let (v, w, st) = plan
                .pool
                .install(|| with_store(slicer, route, e, &tick, kind, budget))?;
            (v, w, Some(st))
        }
    };
    progress.finish();
    let wall = t0.elapsed().as_secs_f64();
    let (mesh, to_stdout) = staged.write_volume(job, plan, &volume, rest)?;
    Ok(Ran {
        work,
        store,
        zarr: None,
        mesh,
        wall,
        to_stdout,
    })
}

/// Voxelizes while building the store from each slice as it comes (`--store`, through
/// [`store::feed`]); the store's budget is what the memory limit leaves.
fn with_store(
    slicer: &Slicer,
    route: (Route, EquationSet),
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    kind: StoreKind,
    budget: u64,
) -> crate::Result<(Volume, Work, StoreReport)> {
    let dims = slicer.grid.dims;
    let mut b = octree::builder(kind, dims, budget).map_err(lib_errors::sculpt)?;
    let mut voxels = Vec::with_capacity(dims.iter().product());
    let mut build = std::time::Duration::ZERO;
    let work = store::feed(slicer, route, eval, tick, &mut |k, s| {
        voxels.extend_from_slice(s);
        let t = Instant::now();
        let r = b.push(k, s);
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
    Ok((Volume { dims, voxels }, work, r))
}

/// The Zarr store `-o`: its metadata, then its chunk rows (by bricks on the run route).
#[cfg(feature = "zarr")]
fn zarr(
    job: &VoxelizeJob,
    plan: &Plan,
    staged: Staged,
    progress: &dyn Progress,
    t0: Instant,
) -> crate::Result<Ran> {
    let root = staged.outs.stage_root(staged.nrrd)?;
    let store = job.create_store(&plan.slicer.grid, &root);
    let store = store.map_err(|e| job.zarr_message(e))?;
    let rows = store.chunk_rows().len();
    let bricks = super::plan::by_bricks(plan.route).then_some(rows * store.tiles().len());
    stage(&plan.slicer, plan.route, bricks, progress);
    let work = plan.write_rows(job, &store, 0..rows, None, progress);
    let work = work.map_err(|e| match e {
        crate::Error::Zarr(e) => job.zarr_message(e),
        e => e,
    })?;
    progress.finish();
    let wall = t0.elapsed().as_secs_f64();
    staged.outs.commit()?;
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
    let (store, mesh, to_stdout) = (None, None, false);
    Ok(Ran {
        work,
        store,
        zarr,
        mesh,
        wall,
        to_stdout,
    })
}

/// The NRRD file `out`: its header, then every slice in order of k as the run route sweeps
/// the columns' runs ([`voxelize_slabs`]), so memory is the runs and one slice, not the
/// volume, and the bytes are those of the volume written whole.
fn stream_nrrd(
    outs: &mut csgpix_output::Outputs,
    out: Out,
    slicer: &Slicer,
    (route, set): (Route, EquationSet),
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    (comment, format): (&str, &VolumeFormat),
) -> crate::Result<Work> {
    let nz = slicer.grid.dims[2];
    let mut done: Option<Result<Work, Stop>> = None;
    let written = outs.write_sparse(out, super::outputs::VOLUME_HOLE, |w| {
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

impl Plan {
    /// The report of the job's run.
    pub fn report(
        &self,
        job: &VoxelizeJob,
        scene: &CsgScene,
        ran: Ran,
        memory_estimate: u64,
    ) -> VoxelizeReport {
        let (slicer, v) = (&self.slicer, &job.voxels);
        let pixels = slicer.grid.slice_len();
        let table = BlistTable::compile(&scene.root);
        let sampled = slicer.sampled.iter().filter_map(|s| s.warning());
        VoxelizeReport {
            memory_estimate,
            dims: slicer.grid.dims,
            sampling: crate::named::Named::name(job.grid.sampling),
            voxel: slicer.grid.voxel().to_array(),
            min: slicer.grid.min.to_array(),
            max: slicer.grid.max.to_array(),
            model: v.model.name(),
            route: route_name(self.route),
            eval: crate::named::Named::name(v.eval),
            solids: scene.solids.len(),
            imports: scene.imports.len(),
            values: v.values(),
            label_bits: table.label_bits,
            blist_rows: table.rows.len(),
            state_bits_per_voxel: self.eval.state_bytes(pixels) * 8 / pixels.max(1),
            work: ran.work,
            store: ran.store,
            zarr: ran.zarr,
            mesh: ran.mesh,
            hardware_seconds: ran.work.cycles as f64 * 1e-7,
            wall_seconds: ran.wall,
            warnings: scene
                .warnings
                .iter()
                .map(|w| w.to_string())
                .chain(sampled.map(|w| w.to_string()))
                .collect(),
            to_stdout: ran.to_stdout,
        }
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Mutex;

    use csgpix_scene::grid::Grid;
    use csgpix_voxel::sampled::load_scene;
    use csgpix_voxel::SlicerOptions;
    use glam::DVec3;

    use super::*;

    /// A sink that keeps the stages it is told of.
    #[derive(Default)]
    struct Stages(Mutex<Vec<(String, u64)>>);

    impl Progress for Stages {
        fn stage(&self, what: &str, total: u64) {
            self.0.lock().unwrap().push((what.to_string(), total));
        }
    }

    /// The stages the run route shows for `vectors/openmesh/open-box.csg` (a box open at
    /// the top: 4 boundary edges) on an `n`³ grid.
    fn open_box_stages(n: usize) -> (Vec<(String, u64)>, usize) {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../vectors/openmesh/open-box.csg"
        );
        let l = load_scene(std::path::Path::new(path)).unwrap();
        let grid = Grid::new([n; 3], DVec3::splat(-1.0), DVec3::splat(11.0)).unwrap();
        let opts = SlicerOptions {
            sampled: l.sampled.clone(),
            ..SlicerOptions::default()
        };
        let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
        let kept = Stages::default();
        stage(&slicer, Route::Runs { float: false }, None, &kept);
        let stages = kept.0.into_inner().unwrap();
        (stages, csgpix_voxel::runs::ticks(&slicer))
    }

    /// A grid under the voxels that make a run heavy shows its progress when an open mesh's
    /// winding numbers are work enough (the soup's case), with a tick for each row of the
    /// mesh's outline; a small one shows none.
    #[test]
    fn an_open_meshs_winding_numbers_make_a_run_heavy() {
        let (stages, _) = open_box_stages(32);
        assert!(stages.is_empty(), "{stages:?}");
        // 440³ is 85 million voxels (light by voxels); the box's outline, about 367² columns
        // of 440 samples and 4 boundary edges, 2.4e8 edge-samples (heavy).
        let (stages, ticks) = open_box_stages(440);
        assert_eq!(stages, [("row bands".to_string(), ticks as u64)]);
    }
}
