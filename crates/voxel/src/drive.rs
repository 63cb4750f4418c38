//! Driving a run (§4.4): every slab's primitive masks from their source, evaluated slice by
//! slice, slabs in parallel; the result assembled as a volume ([`voxelize`]) or handed on in
//! order of k ([`voxelize_streaming`]).

use rtl_model::EquationSet;

use csgpix_scene::grid::{Grid, Volume};

use crate::error::Result;
use crate::footprint::{footprints, Footprint};
use crate::masks::{array_mask_in, slice_ops};
use crate::pixel_box::PixelBox;
use crate::ranges::{float_ranges, sampled_runs_in, word_ranges};
use crate::slabs::{SlabRanges, SlabRuns};
use crate::slice::{Mask, OpCounts, SliceEval};
use crate::slicer::{Route, Slicer};
use csgpix_scene::trimesh::Window;
// Here before crate::work took them: the public paths stay.
pub use crate::work::{SliceSink, Work, PROCESS_BYTES};

/// Per-slice masks of every primitive: the solids' by route, then the imports'.
struct Source {
    convex: ConvexSource,
    sampled: Vec<SampledSource>,
}

/// Where an import's slab masks come from.
enum SampledSource {
    /// A mesh: its slab runs per pixel and, per slab, the pixels that flip there.
    Runs(SlabRuns, Vec<Vec<u32>>),
    /// A dataset (import j): sampled slab by slab.
    Dataset(usize),
}

impl SampledSource {
    fn mask(&self, slicer: &Slicer, k: usize) -> Mask {
        match self {
            SampledSource::Runs(r, _) => r.mask(k),
            SampledSource::Dataset(j) => slicer.sampled[*j].dataset_mask(&slicer.grid, k),
        }
    }

    /// The mask of slab k from that of slab k − 1.
    fn advance(&self, slicer: &Slicer, k: usize, m: &mut Mask) {
        match self {
            SampledSource::Runs(_, toggles) => {
                toggles[k].iter().for_each(|&i| m.toggle(i as usize))
            }
            SampledSource::Dataset(_) => *m = self.mask(slicer, k),
        }
    }
}

/// Per-slice masks of the convex solids, by route.
enum ConvexSource {
    /// Slab ranges of every primitive and, per slab, the pixels whose membership flips there.
    Ranges(Vec<(SlabRanges, Vec<Vec<u32>>)>),
    Array {
        cycle: bool,
        set: EquationSet,
        /// Per primitive, where it is (when the slicer prunes to panels).
        footprints: Option<Vec<Footprint>>,
    },
}

impl ConvexSource {
    fn ranges(r: Vec<SlabRanges>, slabs: usize) -> ConvexSource {
        ConvexSource::Ranges(
            r.into_iter()
                .map(|r| {
                    let t = r.toggles(slabs);
                    (r, t)
                })
                .collect(),
        )
    }

    /// The masks of slabs `a..b`, each handed to `f` in order. From ranges, slab a is built
    /// pixel by pixel and every later one by flipping the pixels whose membership changes.
    fn sweep_convex(
        &self,
        slicer: &Slicer,
        a: usize,
        b: usize,
        simulated: &mut u64,
        f: &mut dyn FnMut(usize, &[Mask]),
    ) -> Result<()> {
        match self {
            ConvexSource::Ranges(r) => {
                let mut masks: Vec<Mask> = r.iter().map(|(r, _)| r.mask(a)).collect();
                for k in a..b {
                    if k > a {
                        for ((_, toggles), m) in r.iter().zip(&mut masks) {
                            toggles[k].iter().for_each(|&i| m.toggle(i as usize));
                        }
                    }
                    f(k, &masks);
                }
            }
            ConvexSource::Array {
                cycle,
                set,
                footprints,
            } => {
                for k in a..b {
                    let masks = (0..slicer.lists.len())
                        .map(|p| {
                            let fp = footprints.as_ref().map(|f| &f[p]);
                            let (m, px_clocks) = frame_mask(slicer, p, k, *cycle, set, fp)?;
                            *simulated += px_clocks;
                            Ok(m)
                        })
                        .collect::<Result<Vec<_>>>()?;
                    f(k, &masks);
                }
            }
        }
        Ok(())
    }
}

impl Source {
    /// Every primitive's masks of slabs `a..b` (solids, then imports), handed to `f` in order.
    fn sweep(
        &self,
        slicer: &Slicer,
        a: usize,
        b: usize,
        simulated: &mut u64,
        f: &mut dyn FnMut(usize, &[Mask]),
    ) -> Result<()> {
        if self.sampled.is_empty() {
            return self.convex.sweep_convex(slicer, a, b, simulated, f);
        }
        let mut imported: Vec<Mask> = vec![];
        let mut all: Vec<Mask> = vec![];
        self.convex
            .sweep_convex(slicer, a, b, simulated, &mut |k, convex| {
                if k == a {
                    imported = self.sampled.iter().map(|s| s.mask(slicer, k)).collect();
                } else {
                    for (s, m) in self.sampled.iter().zip(&mut imported) {
                        s.advance(slicer, k, m);
                    }
                }
                all.clear();
                all.extend_from_slice(convex);
                all.extend_from_slice(&imported);
                f(k, &all);
            })
    }
}

/// A run of consecutive slabs: each slab's colour codes and evaluator counts, and the
/// pixel-clocks simulated for them.
type Chunk = (Vec<(Vec<u8>, OpCounts)>, u64);

/// The mask of P·Vz on the array route and the pixel-clocks simulated for it: the whole array,
/// or with a footprint only the panels it touches, and nothing in a slab it misses.
fn frame_mask(
    slicer: &Slicer,
    p: usize,
    k: usize,
    cycle: bool,
    set: &EquationSet,
    fp: Option<&Footprint>,
) -> Result<(Mask, u64)> {
    let [w, h] = [slicer.grid.dims[0], slicer.grid.dims[1]];
    let bx = match (fp, slicer.panel) {
        (None, _) | (_, None) => PixelBox {
            x0: 0,
            y0: 0,
            x1: w,
            y1: h,
        },
        (Some(fp), Some(panel)) => match fp.pixels {
            Some(b) if fp.holds(k) => b.to_panels(panel, w, h),
            _ => return Ok((Mask::new(w * h), 0)),
        },
    };
    let (m, clocks) = array_mask_in(slicer, p, k, cycle, set.clone(), bx)?;
    Ok((m, clocks * bx.pixels() as u64))
}

/// Voxelize: every slab's primitive masks by `route`, evaluated by `eval`, slabs in
/// parallel; the result does not depend on the number of threads. `tick` is called once per
/// finished slab (for a progress bar); on [`Route::Runs`] once per band of rows
/// ([`crate::runs::ticks`] in all), which computes the volume column by column instead.
pub fn voxelize(
    slicer: &Slicer,
    route: Route,
    set: EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
) -> Result<(Volume, Work)> {
    use rayon::prelude::*;
    let [nx, ny, nz] = slicer.grid.dims;
    let mut work = counted_work(slicer, nz)?;
    if let Route::Runs { float } = route {
        if crate::runs::applies(slicer) {
            return crate::runs::voxelize_runs(slicer, float, eval, tick, work);
        }
    }
    let source = source_for(slicer, route.by_slab(), &set)?;
    // Chunks of consecutive slabs, a few per thread, so masks can be swept forward; each
    // chunk's slices go straight into their place in the volume (one volume held, not two).
    let chunk = (nz / (4 * rayon::current_num_threads())).max(1);
    let mut voxels = csgpix_output::try_zeroed(nx * ny * nz)?;
    let counted: Vec<(u64, OpCounts)> = voxels
        .par_chunks_mut(chunk * nx * ny)
        .enumerate()
        .map(|(c, place)| {
            let a = c * chunk;
            let (slices, simulated) =
                slab_chunk(slicer, &source, eval, tick, a, (a + chunk).min(nz))?;
            let mut ops = OpCounts::default();
            for ((colours, counts), into) in slices.into_iter().zip(place.chunks_mut(nx * ny)) {
                // A slice is as long as its longest mask: shorter (empty, with no primitive
                // at all) it is outside past its end, as the volume already is.
                into[..colours.len()].copy_from_slice(&colours);
                ops += counts;
            }
            Ok((simulated, ops))
        })
        .collect::<Result<_>>()?;
    for (simulated, ops) in counted {
        work.simulated_pixel_clocks += simulated;
        work.ops += ops;
    }
    work.filled = voxels.iter().filter(|&&v| v != 0).count();
    Ok((
        Volume {
            dims: slicer.grid.dims,
            voxels,
        },
        work,
    ))
}

/// An upper bound of a run's memory (docs/memory.md): the volume, the per-pixel slab ranges
/// of every primitive, per thread a slab's masks and labels and the slices of the chunk in
/// hand (an eighth of the volume at most, [`voxelize`]), and the process itself.
pub fn memory_estimate(grid: &Grid, prims: usize, threads: usize) -> u64 {
    let [nx, ny, nz] = grid.dims.map(|d| d as u64);
    let pixels = nx.saturating_mul(ny);
    let (prims, threads) = (prims as u64, threads as u64);
    let volume = pixels.saturating_mul(nz);
    let chunk = (nz / (4 * threads.max(1))).max(1);
    let per_thread = pixels.saturating_mul((prims / 8 + 1 + 8).saturating_add(chunk));
    volume
        .saturating_add(prims.saturating_mul(pixels).saturating_mul(8))
        .saturating_add(threads.saturating_mul(per_thread))
        .saturating_add(PROCESS_BYTES)
}

/// An upper bound of the memory of a run that hands its slices on ([`voxelize_slabs`])
/// instead of assembling a volume (docs/memory.md): no volume, but `held` bytes kept by
/// whoever takes the slices (a Zarr store's chunk row, `crates/zarr`), the per-pixel slab
/// ranges of every primitive and their per-slab toggles (8 bytes a pixel each), per thread a
/// slab's masks and labels and the slices of its chunk in hand (at most 8: one batch of
/// [`voxelize_slabs`] is held until the sink has taken it), and the process itself. Unlike
/// [`memory_estimate`] it does not grow with the grid's depth.
pub fn memory_estimate_rows(grid: &Grid, prims: usize, threads: usize, held: u64) -> u64 {
    let [nx, ny, nz] = grid.dims.map(|d| d as u64);
    let pixels = nx.saturating_mul(ny);
    let (prims, threads) = (prims as u64, threads as u64);
    let chunk = (nz / (4 * threads.max(1))).clamp(1, 8);
    let per_thread = pixels.saturating_mul((prims / 8 + 1 + 8).saturating_add(chunk));
    held.saturating_add(prims.saturating_mul(pixels).saturating_mul(16))
        .saturating_add(threads.saturating_mul(per_thread))
        .saturating_add(PROCESS_BYTES)
}

/// [`voxelize`] handing each slice's colour codes to `sink` in order of k (0, 1, …) instead of
/// assembling a volume, for stores built slice by slice (seed 000 §4.3.4; `src/octree`).
/// Slabs are voxelized in parallel a batch at a time (a few slabs per thread), so at most a
/// batch of slices is held; the slices, and the returned [`Work`], are those of [`voxelize`]
/// (tested). `sink` may stop the run with an error of its own type, returned as it is; the
/// run's own errors are returned as `E` too.
pub fn voxelize_streaming<E: From<crate::Error>>(
    slicer: &Slicer,
    route: Route,
    set: EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    sink: &mut SliceSink<E>,
) -> Result<Work, E> {
    let nz = slicer.grid.dims[2];
    voxelize_slabs(slicer, route, set, eval, tick, 0..nz, sink)
}

/// [`voxelize_streaming`] over the slabs `slabs` of the grid only (k0..k1, k1 ≤ NZ): the
/// slices handed to `sink` (with their k in the whole grid) are those of the whole run, and
/// [`Work`] counts these slabs' frames alone. What one task of a run split by slab ranges
/// does (docs/scale-out.md); the masks of slab k0 are built from their source directly, so
/// no slab before it is computed.
pub fn voxelize_slabs<E: From<crate::Error>>(
    slicer: &Slicer,
    route: Route,
    set: EquationSet,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    slabs: std::ops::Range<usize>,
    sink: &mut SliceSink<E>,
) -> Result<Work, E> {
    use rayon::prelude::*;
    let nz = slicer.grid.dims[2];
    if slabs.start > slabs.end || slabs.end > nz {
        return Err(crate::Error::SlabRange {
            start: slabs.start,
            end: slabs.end,
            slabs: nz,
        }
        .into());
    }
    let mut work = counted_work(slicer, slabs.len())?;
    if let Route::Runs { float } = route {
        if crate::runs::applies(slicer) {
            return crate::runs::sweep_slices(slicer, float, eval, tick, slabs, sink, work);
        }
    }
    let source = source_for(slicer, route.by_slab(), &set)?;
    let threads = rayon::current_num_threads();
    let chunk = (slabs.len() / (4 * threads)).clamp(1, 8);
    let batch = chunk * threads;
    for start in slabs.clone().step_by(batch) {
        let end = (start + batch).min(slabs.end);
        let chunks: Vec<Chunk> = (start..end)
            .step_by(chunk)
            .collect::<Vec<_>>()
            .into_par_iter()
            .map(|a| slab_chunk(slicer, &source, eval, tick, a, (a + chunk).min(end)))
            .collect::<Result<_>>()?;
        let slices = chunks.into_iter().flat_map(|(s, sim)| {
            work.simulated_pixel_clocks += sim;
            s
        });
        for (k, (colours, counts)) in (start..).zip(slices) {
            work.ops += counts;
            work.filled += colours.iter().filter(|&&v| v != 0).count();
            sink(k, &colours)?;
        }
    }
    Ok(work)
}

/// Where a run's per-slab masks come from, by route.
fn source_for(slicer: &Slicer, route: Route, set: &EquationSet) -> Result<Source> {
    let [w, h, nz] = slicer.grid.dims;
    let sampled = slicer
        .sampled
        .iter()
        .enumerate()
        .map(|(j, s)| {
            match sampled_runs_in(slicer, &s.shape, Window { x0: 0, y0: 0, w, h }, &|| ()) {
                Some(runs) => {
                    let toggles = runs.toggles(nz);
                    SampledSource::Runs(runs, toggles)
                }
                None => SampledSource::Dataset(j),
            }
        })
        .collect();
    Ok(Source {
        convex: convex_source(slicer, route, set)?,
        sampled,
    })
}

fn convex_source(slicer: &Slicer, route: Route, set: &EquationSet) -> Result<ConvexSource> {
    use rayon::prelude::*;
    let (prims, nz) = (slicer.lists.len(), slicer.grid.dims[2]);
    Ok(match route {
        Route::Array { cycle } => ConvexSource::Array {
            cycle,
            set: set.clone(),
            footprints: match slicer.panel {
                Some(_) => Some(footprints(slicer)?),
                None => None,
            },
        },
        Route::Intervals | Route::Runs { float: false } => ConvexSource::ranges(
            (0..prims)
                .into_par_iter()
                .map(|p| word_ranges(slicer, p))
                .collect::<Result<_, _>>()?,
            nz,
        ),
        Route::Float | Route::Runs { float: true } => ConvexSource::ranges(
            (0..prims)
                .into_par_iter()
                .map(|p| float_ranges(slicer, p))
                .collect(),
            nz,
        ),
    })
}

/// The clocks and frames of a run over `slabs` slabs, counted from the programs: the same on
/// every route. Primitives are counted in parallel; an error is the first primitive's.
pub fn counted_work(slicer: &Slicer, slabs: usize) -> Result<Work> {
    use rayon::prelude::*;
    let cfg = slicer.config();
    let [nx, ny, _] = slicer.grid.dims;
    let (prims, nz) = (slicer.lists.len(), slabs);
    let each: Vec<Result<u64>> = (0..prims)
        .into_par_iter()
        .map(|p| {
            Ok(rtl_model::array::program_cycles(
                &cfg,
                &slice_ops(slicer, p, 0)?,
            ))
        })
        .collect();
    let mut cycles = 0;
    for c in each {
        cycles += c? * nz as u64;
    }
    Ok(Work {
        cycles,
        frames: (prims * nz) as u64,
        full_pixel_clocks: cycles * (nx * ny) as u64,
        ..Work::default()
    })
}

/// A slice's colour codes from its labels: the winner's colour code, or with
/// [`Slicer::grey`] a winning dataset's grey value at the voxel (§4.5), as [`grey_code`].
fn label_colours(slicer: &Slicer, k: usize, labels: &[u32]) -> Vec<u8> {
    let nx = slicer.grid.dims[0];
    labels
        .iter()
        .enumerate()
        .map(|(i, &l)| match l {
            0 => 0,
            l => {
                let p = l as usize - 1;
                let grey = match slicer.dataset(p) {
                    Some(s) if slicer.grey => {
                        s.grey(slicer.grid.centre(i % nx, i / nx, k)).map(grey_code)
                    }
                    _ => None,
                };
                grey.unwrap_or(slicer.colours[p])
            }
        })
        .collect()
}

/// First value [`Slicer::grey`] gives a dataset's grey levels: 1..=15 stay the palette's codes.
pub const GREY_BASE: u8 = 16;

/// A grey level 1..=255 as a voxel value GREY_BASE..=255 beside the colour codes.
pub fn grey_code(g: u8) -> u8 {
    let span = (255 - GREY_BASE) as u32;
    GREY_BASE + ((g.max(1) - 1) as u32 * span / 254) as u8
}

/// Every primitive's grey slice for the blending operators ([`crate::blend`]): 0 outside;
/// inside, a dataset's grey value, a solid's or mesh's [`crate::blend::SOLID`].
fn grey_slices(slicer: &Slicer, k: usize, masks: &[Mask]) -> Vec<Vec<u8>> {
    let nx = slicer.grid.dims[0];
    masks
        .iter()
        .enumerate()
        .map(|(p, m)| {
            let level = crate::blend::SOLID;
            let dataset = slicer.dataset(p);
            (0..m.len())
                .map(|i| match (m.get(i), dataset) {
                    (false, _) => 0,
                    (true, Some(s)) => s
                        .grey(slicer.grid.centre(i % nx, i / nx, k))
                        .unwrap_or(level),
                    (true, None) => level,
                })
                .collect()
        })
        .collect()
}

/// Slabs a..b: colour codes and counts of each, and the pixel-clocks simulated.
fn slab_chunk(
    slicer: &Slicer,
    source: &Source,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    a: usize,
    b: usize,
) -> Result<Chunk> {
    let (mut out, mut simulated) = (vec![], 0);
    source.sweep(slicer, a, b, &mut simulated, &mut |k, masks| {
        let mut counts = OpCounts::default();
        let colours = match &slicer.blend {
            Some(b) => b.blend(&grey_slices(slicer, k, masks), slicer.grid.slice_len()),
            None => label_colours(slicer, k, &eval.eval(masks, &mut counts)),
        };
        tick();
        out.push((colours, counts));
    })?;
    Ok((out, simulated))
}
