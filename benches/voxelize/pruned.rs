//! The pruned peer: fidget evaluating the expression as its own renderers do, by recursive
//! subdivision with interval arithmetic and tape simplification, instead of every clause at
//! every voxel (the dense peer).
//!
//! The grid is cut into cells of `cells[0]` voxels a side (the grid's far faces cut the
//! last ones short). Each cell is evaluated once with fidget's interval evaluator over the box
//! of its voxel centres: an interval entirely <= 0 fills the cell as inside, one entirely > 0
//! leaves it outside (the volume starts empty), with no point evaluated. Otherwise the tape is
//! simplified with that evaluation's trace (the min/max branches the box never takes are
//! dropped) and the cell's children, of the next side in `cells`, are evaluated with the
//! simplified tape. A leaf cell (`cells`' last side) is evaluated in bulk at its voxel
//! centres with its simplified tape. Top-level cells are spread over rayon's pool.
//!
//! The simplification goes through fidget's own `RenderHandle`, as its renderers do: it
//! keeps the last simplified tape per level and reuses it while the trace repeats, and it
//! keeps the parent's tape when simplifying does not shorten it.

use std::marker::PhantomData;

use csgpix::scene::grid::Grid;
use fidget::eval::Function;
use fidget::jit::{JitFloatSliceEval, JitFunction, JitIntervalEval, JitShape};
use fidget::render::RenderHandle;
use fidget::shape::{ShapeBulkEval, ShapeTracingEval};
use fidget::types::Interval;
use rayon::prelude::*;

/// Cell sides in voxels, top level first (the bench's `--cells` replaces them); each divides
/// the one before it. 64 → 16 → 4 splits by 4 per axis (64 children) per level; the 4³ leaves
/// are evaluated in bulk, 64 points a call. Other choices timed within the run-to-run spread
/// of this shared machine (docs/voxelize-bench.md), so none replaced it.
pub const CELLS: [usize; 3] = [64, 16, 4];

type Handle = RenderHandle<JitFunction>;

/// Membership (1 inside, 0 outside) at every voxel centre of `g`, by recursive subdivision
/// into cells of the sides `cells`, top level first.
pub fn pruned_eval(shape: &JitShape, g: &Grid, cells: &[usize]) -> Vec<u8> {
    assert!(
        !cells.is_empty() && cells.windows(2).all(|w| w[1] > 0 && w[0] % w[1] == 0),
        "cell sides {cells:?}: each must divide the one before it"
    );
    let [nx, ny, nz] = g.dims;
    let mut voxels = vec![0u8; nx * ny * nz];
    // Every page touched now, in parallel, as the run route does: cells proven outside are
    // never written, and a zeroed allocation's untouched pages would be mapped one at a time
    // by the file's write instead.
    voxels
        .par_chunks_mut((nx * ny).max(1))
        .for_each(|s| s.fill(0));
    let job = Job {
        axes: Axes::of(g),
        out: Out::new(&mut voxels, g.dims),
        cells,
    };
    let mut root = Handle::new(shape.clone());
    // Compiled once here; every worker's clone shares it (the JIT code sits behind an Arc).
    root.i_tape(&mut vec![]);
    let top: Vec<Cell> = Cell::whole(g.dims).split(cells[0]).collect();
    top.into_par_iter().for_each_init(
        || (Worker::default(), root.clone()),
        |(w, h), c| w.cell(h, c, 0, &job),
    );
    voxels
}

/// What every cell of one evaluation shares.
struct Job<'a> {
    axes: Axes,
    out: Out<'a>,
    cells: &'a [usize],
}

/// The voxel centres' coordinates along X, Y and Z, in f32 as the dense peer passes them.
struct Axes([Vec<f32>; 3]);

impl Axes {
    fn of(g: &Grid) -> Axes {
        let along = |a: usize| {
            (0..g.dims[a])
                .map(|i| {
                    let mut ijk = [0; 3];
                    ijk[a] = i;
                    g.centre(ijk[0], ijk[1], ijk[2])[a] as f32
                })
                .collect()
        };
        Axes([along(0), along(1), along(2)])
    }

    /// The interval of the centres `lo..hi` along axis `a` (centres increase with the index).
    fn span(&self, a: usize, lo: usize, hi: usize) -> Interval {
        Interval::new(self.0[a][lo], self.0[a][hi - 1])
    }
}

/// A box of voxels, `lo..hi` along each axis.
#[derive(Clone, Copy, Debug)]
struct Cell {
    lo: [usize; 3],
    hi: [usize; 3],
}

impl Cell {
    fn whole(dims: [usize; 3]) -> Cell {
        Cell {
            lo: [0; 3],
            hi: dims,
        }
    }

    /// The cell cut into cells of `side` voxels, X fastest; the last along each axis may be
    /// shorter.
    fn split(self, side: usize) -> impl Iterator<Item = Cell> {
        let starts = move |a: usize| (self.lo[a]..self.hi[a]).step_by(side);
        starts(2).flat_map(move |k| {
            starts(1).flat_map(move |j| {
                starts(0).map(move |i| {
                    let lo = [i, j, k];
                    Cell {
                        lo,
                        hi: std::array::from_fn(|a| (lo[a] + side).min(self.hi[a])),
                    }
                })
            })
        })
    }

    fn len(&self, a: usize) -> usize {
        self.hi[a] - self.lo[a]
    }
}

/// The volume, written cell by cell from several threads at once.
struct Out<'a> {
    ptr: *mut u8,
    dims: [usize; 3],
    _volume: PhantomData<&'a mut [u8]>,
}

// SAFETY: the only writes are `put` and `fill`, each within one cell; the top-level cells
// are disjoint and each is handed to one task only, and their children lie inside them, so
// no byte is written by two threads (nor read while written).
unsafe impl Sync for Out<'_> {}

impl<'a> Out<'a> {
    fn new(voxels: &'a mut [u8], dims: [usize; 3]) -> Out<'a> {
        assert_eq!(voxels.len(), dims.iter().product::<usize>());
        Out {
            ptr: voxels.as_mut_ptr(),
            dims,
            _volume: PhantomData,
        }
    }

    /// Index of voxel (i, j, k).
    fn at(&self, i: usize, j: usize, k: usize) -> usize {
        (k * self.dims[1] + j) * self.dims[0] + i
    }

    /// `row` written from voxel (i, j, k) along X.
    fn put(&self, [i, j, k]: [usize; 3], row: &[u8]) {
        assert!(i + row.len() <= self.dims[0] && j < self.dims[1] && k < self.dims[2]);
        // SAFETY: in bounds (asserted), and only this task writes this cell (see `Sync`).
        unsafe {
            std::ptr::copy_nonoverlapping(row.as_ptr(), self.ptr.add(self.at(i, j, k)), row.len())
        }
    }

    /// Every voxel of `c` set to `v`.
    fn fill(&self, c: Cell, v: u8) {
        assert!((0..3).all(|a| c.hi[a] <= self.dims[a]));
        for k in c.lo[2]..c.hi[2] {
            for j in c.lo[1]..c.hi[1] {
                // SAFETY: as in `put`.
                unsafe { std::ptr::write_bytes(self.ptr.add(self.at(c.lo[0], j, k)), v, c.len(0)) }
            }
        }
    }
}

/// One thread's evaluators and scratch, kept across the cells it takes.
#[derive(Default)]
struct Worker {
    interval: ShapeTracingEval<JitIntervalEval>,
    float: ShapeBulkEval<JitFloatSliceEval>,
    workspace: <JitFunction as Function>::Workspace,
    shapes: Vec<<JitFunction as Function>::Storage>,
    tapes: Vec<<JitFunction as Function>::TapeStorage>,
    /// A leaf's voxel centres, X, Y and Z, and a row of its membership.
    pts: [Vec<f32>; 3],
    row: Vec<u8>,
}

impl Worker {
    /// Cell `c` of side `job.cells[level]` (or less at the grid's far faces) with tape `h`.
    fn cell(&mut self, h: &mut Handle, c: Cell, level: usize, job: &Job) {
        let [x, y, z] = std::array::from_fn(|a| job.axes.span(a, c.lo[a], c.hi[a]));
        let (v, trace) = self
            .interval
            .eval(h.i_tape(&mut self.tapes), x, y, z)
            .expect("interval eval");
        // A NaN bound fails both tests and the cell is subdivided.
        if v.upper() <= 0.0 {
            return job.out.fill(c, 1);
        }
        if v.lower() > 0.0 {
            return;
        }
        let sub = match trace {
            Some(t) => h.simplify(t, &mut self.workspace, &mut self.shapes, &mut self.tapes),
            None => h,
        };
        match job.cells.get(level + 1) {
            Some(&side) => {
                for child in c.split(side) {
                    self.cell(sub, child, level + 1, job);
                }
            }
            None => self.leaf(sub, c, job),
        }
    }

    /// A leaf: every voxel centre of `c` in one bulk call of `h`'s float tape.
    fn leaf(&mut self, h: &mut Handle, c: Cell, job: &Job) {
        for p in &mut self.pts {
            p.clear();
        }
        for k in c.lo[2]..c.hi[2] {
            for j in c.lo[1]..c.hi[1] {
                for i in c.lo[0]..c.hi[0] {
                    for (a, at) in [i, j, k].into_iter().enumerate() {
                        self.pts[a].push(job.axes.0[a][at]);
                    }
                }
            }
        }
        let [xs, ys, zs] = &self.pts;
        let values = self
            .float
            .eval(h.f_tape(&mut self.tapes), xs, ys, zs)
            .expect("float eval");
        let (w, rows) = (c.len(0), c.len(1));
        for (r, vals) in values.chunks(w).enumerate() {
            self.row.clear();
            self.row.extend(vals.iter().map(|&v| u8::from(v <= 0.0)));
            job.out
                .put([c.lo[0], c.lo[1] + r % rows, c.lo[2] + r / rows], &self.row);
        }
    }
}
