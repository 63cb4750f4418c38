//! The run route ([`Route::Runs`](crate::Route::Runs)): the volume column by column.
//!
//! Along pixel (x, y)'s ray every primitive fills a few runs of slabs: a convex solid one,
//! from the same depths the slab routes use (the array's plane words, or exact f64, reduced
//! by the same slab windows and sampling), a mesh one per pair of crossings, a dataset one per
//! stretch of samples at or above its threshold. Between the ends of those runs the membership
//! of every primitive is constant, so the CSG tree is evaluated once per *segment*, not once
//! per voxel, and the column is written as runs of one colour. The evaluator is the run's own
//! (the Blist of §4.5, the tree of §4.2, the slice stack of §3.4.1): the segments of a panel
//! of columns are laid side by side as one "slice" whose pixels are segments, so every
//! [`SliceEval`] works unchanged and gives the label the slab routes give each voxel of the
//! segment (point membership commutes with CSG; the colour rules are per voxel).
//!
//! Work by footprint: a primitive is visited only on the columns of its outline
//! ([`Slicer::outlines`]), panel by panel as the thesis's panels (§2.5) draw only the planes
//! that reach them; elsewhere its mask is empty and costs nothing. Memory is the runs, not
//! primitives × pixels.
//!
//! Writing: a row of columns (fixed y) is swept along z, its colours changing only where a
//! run starts, so each (y, z) row of the volume is one copy of X bytes, and all-empty rows
//! are left as allocated (zero).

use rayon::prelude::*;

use csgpix_scene::grid::Volume;
use csgpix_scene::trimesh::Window;

use csgpix_scene::dataset::Column;

use crate::dataset_runs::DatasetColumns;
use crate::error::Result;
use crate::pixel_box::PixelBox;
use crate::ranges::{sampled_runs_in, FloatPlanes, WordPlanes};
use crate::sampled::Shape;
use crate::slabs::SlabRuns;
use crate::slice::{Mask, OpCounts, SliceEval};
use crate::slicer::{Slicer, DEFAULT_PANEL};
use crate::work::{SliceSink, Work, PROCESS_BYTES};

/// One run of a column: from slab `k` on (to the next run's `k`, or the grid's end), voxels
/// take `colour` (0: empty).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Run {
    /// First slab of the run.
    pub k: u32,
    /// Colour code of its voxels.
    pub colour: u8,
}

/// The runs of every column of a rectangle of pixels, row-major: column c's runs are
/// `runs[start[c]..start[c + 1]]`, the first starting at slab 0, neighbours differing in
/// colour.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ColumnRuns {
    /// The columns.
    pub columns: PixelBox,
    /// Where each column's runs start in `runs` (one more entry than columns).
    pub start: Vec<usize>,
    /// The runs, column after column.
    pub runs: Vec<Run>,
}

impl ColumnRuns {
    /// Column (x, y)'s runs (x, y within [`ColumnRuns::columns`]).
    pub fn column(&self, x: usize, y: usize) -> &[Run] {
        let b = &self.columns;
        let c = (y - b.y0) * b.width() + (x - b.x0);
        &self.runs[self.start[c]..self.start[c + 1]]
    }

    /// Voxels of the columns within slabs `slabs` (its end at most the grid's) that are not
    /// empty.
    pub fn filled(&self, slabs: std::ops::Range<usize>) -> usize {
        self.start
            .windows(2)
            .map(|c| filled_between(&self.runs[c[0]..c[1]], slabs.clone()))
            .sum()
    }
}

impl ColumnRuns {
    /// The one colour every voxel of the columns of `b` (within [`ColumnRuns::columns`])
    /// has over `slabs`, if they have one: a chunk inside or outside every part, known from
    /// the runs without a voxel.
    pub fn uniform(&self, b: PixelBox, slabs: std::ops::Range<usize>) -> Option<u8> {
        let mut colour = None;
        for y in b.y0..b.y1 {
            for x in b.x0..b.x1 {
                let col = self.column(x, y);
                let at = col.partition_point(|r| (r.k as usize) <= slabs.start);
                let c = at.checked_sub(1).map_or(0, |a| col[a].colour);
                let changes = col.get(at).is_some_and(|r| (r.k as usize) < slabs.end);
                if changes || colour.is_some_and(|v| v != c) {
                    return None;
                }
                colour = Some(c);
            }
        }
        colour
    }
}

/// Non-empty voxels of one column's runs within slabs `slabs` (its end at most the grid's).
fn filled_between(runs: &[Run], slabs: std::ops::Range<usize>) -> usize {
    runs.iter()
        .enumerate()
        .filter(|(_, r)| r.colour != 0)
        .map(|(i, r)| {
            let end = runs.get(i + 1).map_or(slabs.end, |n| n.k as usize);
            let (a, b) = ((r.k as usize).max(slabs.start), end.min(slabs.end));
            b.saturating_sub(a)
        })
        .sum()
}

/// Whether the run route gives the volume of its slab route: not where voxels take a
/// dataset's grey value or a blend of grey values, which change voxel by voxel along a run.
pub fn applies(slicer: &Slicer) -> bool {
    let grey_datasets = slicer.grey && slicer.sampled.iter().any(|s| s.is_dataset());
    slicer.blend.is_none() && !grey_datasets
}

/// Where each primitive's runs come from along a column.
enum Depths<'a> {
    /// A convex solid's plane words (the array's depths), held when its outline meets more
    /// than [`HELD_PANELS`](crate::slicer::HELD_PANELS) panels, else compiled again from its display list in each panel
    /// it meets ([`Slicer::holds_planes`]).
    Word(Option<WordPlanes>),
    /// A convex solid's exact depths, held or not as the words are.
    Float(Option<FloatPlanes>),
    /// An import: a mesh or a dataset.
    Sampled(SampledDepths<'a>),
}

/// Solid `prim`'s words, compiled again where [`Columns::new`] compiled them without error
/// and did not keep them.
fn compiled(slicer: &Slicer, prim: usize) -> WordPlanes {
    WordPlanes::of(slicer, prim).expect("the same list compiled without error in Columns::new")
}

/// Where an import's runs come from along a column.
enum SampledDepths<'a> {
    /// A mesh's runs over its outline, computed once.
    Mesh(SlabRuns, PixelBox),
    /// A dataset, sampled at the voxel centres of the column ([`DatasetColumns`]).
    Dataset(DatasetColumns<'a>),
}

impl SampledDepths<'_> {
    /// The import's runs of slabs (first, last) along column (x, y), in order; `column` is
    /// a dataset's scratch space.
    fn slabs(&self, x: usize, y: usize, column: &mut Column, out: &mut Vec<(u32, u32)>) {
        match self {
            SampledDepths::Mesh(runs, b) => {
                if b.contains(x, y) {
                    out.extend_from_slice(runs.pixel((y - b.y0) * b.width() + (x - b.x0)));
                }
            }
            SampledDepths::Dataset(d) => d.runs(x, y, column, out),
        }
    }
}

/// A scene ready to be swept column by column.
pub struct Columns<'a> {
    slicer: &'a Slicer,
    depths: Vec<Depths<'a>>,
    /// Per panel (row-major over the array), the primitives whose outline meets it.
    panels: Vec<Vec<u32>>,
    panel: [usize; 2],
}

impl<'a> Columns<'a> {
    /// Every primitive's source of runs (a mesh's crossings over its outline, computed here,
    /// in parallel) and the primitives of each panel; `tick` once a row of each open mesh's
    /// outline as its winding numbers are done ([`open_mesh_ticks`]).
    pub fn new(slicer: &'a Slicer, float: bool, tick: &(dyn Fn() + Sync)) -> Result<Columns<'a>> {
        let solids = slicer.lists.len();
        // Every solid's words are compiled here, so a plane the word cannot hold is refused
        // before the run; only those of solids over many panels are kept.
        let mut depths: Vec<Depths> = (0..solids)
            .into_par_iter()
            .map(|p| {
                let held = slicer.holds_planes(p);
                match float {
                    true => Ok(Depths::Float(held.then(|| FloatPlanes::of(slicer, p)))),
                    false => Ok(Depths::Word(
                        Some(WordPlanes::of(slicer, p)?).filter(|_| held),
                    )),
                }
            })
            .collect::<Result<_>>()?;
        // Each mesh's crossings over its outline, the meshes in parallel (the estimate counts
        // every mesh's crossings as collected at once).
        let sampled: Vec<Depths> = (slicer.sampled.par_iter().enumerate())
            .map(|(j, s)| {
                let b = slicer.outlines[solids + j].unwrap_or(EMPTY_BOX);
                match sampled_runs_in(slicer, &s.shape, window(b), tick) {
                    Some(runs) => Depths::Sampled(SampledDepths::Mesh(runs, b)),
                    None => {
                        let d = DatasetColumns::new(s, &slicer.grid).expect("a dataset");
                        Depths::Sampled(SampledDepths::Dataset(d))
                    }
                }
            })
            .collect();
        depths.extend(sampled);
        let panel = slicer.panel.unwrap_or(DEFAULT_PANEL).map(|p| p.max(1));
        let panels = panel_lists(slicer, panel);
        Ok(Columns {
            slicer,
            depths,
            panels,
            panel,
        })
    }

    /// Panels across and down the array.
    fn panel_grid(&self) -> [usize; 2] {
        let [w, h, _] = self.slicer.grid.dims;
        [w.div_ceil(self.panel[0]), h.div_ceil(self.panel[1])]
    }

    /// The runs of every column of rows `y0..y1`, a panel at a time, and the evaluator's
    /// counts (one "slice" per panel, whose pixels are the panel's segments).
    pub fn rows(&self, eval: &dyn SliceEval, y0: usize, y1: usize) -> (ColumnRuns, OpCounts) {
        let w = self.slicer.grid.dims[0];
        self.columns(
            eval,
            PixelBox {
                x0: 0,
                y0,
                x1: w,
                y1,
            },
        )
    }

    /// The runs of the columns of `columns` (a brick's, within the array), panel by panel: a
    /// panel cut by the box computes only the columns inside it. A row of panels is made,
    /// then its columns are copied out row by row.
    pub fn columns(&self, eval: &dyn SliceEval, columns: PixelBox) -> (ColumnRuns, OpCounts) {
        let [pw, ph] = self.panel;
        let across = self.panel_grid()[0];
        let mut counts = OpCounts::default();
        let mut out = ColumnRuns {
            columns,
            start: Vec::with_capacity(columns.pixels() + 1),
            runs: vec![],
        };
        out.start.push(0);
        for py in columns.y0 / ph..columns.y1.div_ceil(ph) {
            let made: Vec<(PixelBox, ColumnRuns)> = (columns.x0 / pw..columns.x1.div_ceil(pw))
                .map(|px| {
                    let b = PixelBox {
                        x0: (px * pw).max(columns.x0),
                        y0: (py * ph).max(columns.y0),
                        x1: ((px + 1) * pw).min(columns.x1),
                        y1: ((py + 1) * ph).min(columns.y1),
                    };
                    let prims = &self.panels[py * across + px];
                    (b, self.panel_runs(eval, b, prims, &mut counts))
                })
                .collect();
            let Some((first, _)) = made.first() else {
                continue;
            };
            out.runs
                .reserve(made.iter().map(|(_, runs)| runs.runs.len()).sum());
            for y in first.y0..first.y1 {
                for (b, runs) in &made {
                    for x in b.x0..b.x1 {
                        out.runs.extend_from_slice(runs.column(x, y));
                        out.start.push(out.runs.len());
                    }
                }
            }
        }
        (out, counts)
    }

    /// The runs of the columns of box `b`, whose primitives are `prims`.
    fn panel_runs(
        &self,
        eval: &dyn SliceEval,
        b: PixelBox,
        prims: &[u32],
        counts: &mut OpCounts,
    ) -> ColumnRuns {
        let (seg, again) = self.panel_segments(b, prims);
        let masks = seg.masks(self.depths.len());
        let labels = eval.eval(&masks, counts);
        let mut out = ColumnRuns {
            columns: b,
            start: Vec::with_capacity(b.pixels() + 1),
            runs: Vec::with_capacity(seg.starts.len()),
        };
        out.start.push(0);
        let mut made = seg.columns();
        for same in again {
            let from = out.runs.len();
            match (same, out.start.len()) {
                (true, n) if n >= 2 => out.runs.extend_from_within(out.start[n - 2]..from),
                _ => {
                    let Some((starts, range)) = made.next() else {
                        break;
                    };
                    for (&k, i) in starts.iter().zip(range) {
                        // A scene without primitives has no labels: nothing is inside.
                        let colour = self.colour(labels.get(i).copied().unwrap_or(0));
                        let last = out.runs.last().filter(|_| out.runs.len() > from);
                        if last.is_none_or(|r| r.colour != colour) {
                            out.runs.push(Run { k, colour });
                        }
                    }
                }
            }
            out.start.push(out.runs.len());
        }
        out
    }

    /// The segments of the columns of box `b`, whose primitives are `prims`, and per column
    /// (row-major) whether its primitive runs are the column's before it in its row (its
    /// segments then not made again).
    fn panel_segments(&self, b: PixelBox, prims: &[u32]) -> (Segments, Vec<bool>) {
        let nz = self.slicer.grid.dims[2] as u32;
        let mut seg = Segments::default();
        let mut span = vec![];
        let mut column = Column::default();
        // Each primitive on the columns of its outline within the panel, its planes pruned
        // to those columns.
        let here: Vec<(u32, PixelBox, Tiles)> = prims
            .iter()
            .filter_map(|&p| {
                let o = self.slicer.outlines[p as usize].and_then(|o| o.intersect(b))?;
                let (slicer, prim) = (self.slicer, p as usize);
                let pruned = match &self.depths[prim] {
                    Depths::Word(Some(w)) => Pruned::Word(w.in_panel(slicer, o)?),
                    Depths::Word(None) => Pruned::Word(compiled(slicer, prim).in_panel(slicer, o)?),
                    Depths::Float(Some(f)) => Pruned::Float(f.in_panel(slicer, o)?),
                    Depths::Float(None) => {
                        Pruned::Float(FloatPlanes::of(slicer, prim).in_panel(slicer, o)?)
                    }
                    Depths::Sampled(d) => Pruned::Sampled(d),
                };
                let pruned = pruned.settled(slicer, o);
                Some((p, o, Tiles::of(self.slicer, pruned, o)))
            })
            .collect();
        // Each column's primitive runs (primitive, first, last); a column whose runs are
        // the column's before it in its row has its labels too (a label is a function of
        // which primitives hold a segment), so only its runs are copied. A solid's slabs
        // are made a row of its outline at a time ([`Tiles::row`]), an import's per column.
        let (mut held, mut before) = (vec![], vec![]);
        let mut rows: Vec<Vec<(u32, u32)>> = vec![vec![]; here.len()];
        let mut by_row = vec![false; here.len()];
        let mut again = Vec::with_capacity(b.pixels());
        for y in b.y0..b.y1 {
            for (k, (_, o, tiles)) in here.iter().enumerate() {
                let inside = (o.y0..o.y1).contains(&y);
                by_row[k] = inside && tiles.row(self.slicer, *o, y, &mut rows[k]);
            }
            for x in b.x0..b.x1 {
                held.clear();
                for (k, (p, o, tiles)) in here.iter().enumerate() {
                    if !o.contains(x, y) {
                        continue;
                    }
                    if by_row[k] {
                        let (first, last) = rows[k][x - o.x0];
                        if first <= last {
                            held.push((*p, first, last));
                        }
                        continue;
                    }
                    let Some(pruned) = tiles.at(*o, x, y) else {
                        continue;
                    };
                    span.clear();
                    pruned.slabs(self.slicer, x, y, &mut column, &mut span);
                    let runs = span.iter().filter(|(a, b)| a <= b);
                    held.extend(runs.map(|&(a, b)| (*p, a, b)));
                }
                let same = x > b.x0 && held == before;
                again.push(same);
                if !same {
                    seg.column(&held, nz);
                }
                std::mem::swap(&mut held, &mut before);
            }
        }
        (seg, again)
    }

    /// A label's colour code (0: outside), as the slab routes colour it.
    fn colour(&self, label: u32) -> u8 {
        match label {
            0 => 0,
            l => self.slicer.colours[l as usize - 1],
        }
    }
}

/// A primitive's source of runs in one panel: a solid's planes pruned to it, or an import's.
enum Pruned<'d, 'a> {
    Word(WordPlanes),
    Float(FloatPlanes),
    Sampled(&'d SampledDepths<'a>),
    /// The one run of slabs of every pixel, where the planes left are level
    /// ([`Pruned::settled`]).
    Level((u32, u32)),
}

impl Pruned<'_, '_> {
    /// Its planes pruned again to box `t` (None: the solid is nowhere in it); an import's
    /// runs as they are.
    fn in_box(&self, slicer: &Slicer, t: PixelBox) -> Option<Self> {
        let pruned = match self {
            Pruned::Word(w) => w.in_panel(slicer, t).map(Pruned::Word),
            Pruned::Float(f) => f.in_panel(slicer, t).map(Pruned::Float),
            Pruned::Sampled(d) => Some(Pruned::Sampled(d)),
            Pruned::Level(r) => Some(Pruned::Level(*r)),
        };
        pruned.map(|p| p.settled(slicer, t))
    }

    /// Where every plane left over box `b` is level (a prism's caps over the tiles inside
    /// its walls, a box's over its inside), the one run of slabs they give every pixel of
    /// it, found once; else itself.
    fn settled(self, slicer: &Slicer, b: PixelBox) -> Self {
        let level = match &self {
            Pruned::Word(w) => w.level(),
            Pruned::Float(f) => f.level(),
            Pruned::Sampled(_) | Pruned::Level(_) => false,
        };
        if !level {
            return self;
        }
        let mut run = vec![];
        self.slabs(slicer, b.x0, b.y0, &mut Column::default(), &mut run);
        match run[..] {
            [r] => Pruned::Level(r),
            _ => self,
        }
    }

    /// The slabs of columns `xs` of row `y`, one run each (`(1, 0)` where none), onto
    /// `out`; false (nothing pushed) for an import, whose columns can hold several runs.
    fn row(
        &self,
        slicer: &Slicer,
        y: usize,
        xs: std::ops::Range<usize>,
        out: &mut Vec<(u32, u32)>,
    ) -> bool {
        match self {
            Pruned::Word(w) => w.row_slabs(slicer, y as i64, xs, out),
            Pruned::Float(f) => out.extend(xs.map(|x| f.slabs(slicer, x, y))),
            Pruned::Level(r) => out.extend(xs.map(|_| *r)),
            Pruned::Sampled(_) => return false,
        }
        true
    }

    /// Planes left (0 for an import).
    fn planes(&self) -> usize {
        match self {
            Pruned::Word(w) => w.len(),
            Pruned::Float(f) => f.len(),
            Pruned::Sampled(_) | Pruned::Level(_) => 0,
        }
    }

    /// The primitive's runs of slabs (first, last) along column (x, y), in order; `column`
    /// is a dataset's scratch space.
    fn slabs(
        &self,
        slicer: &Slicer,
        x: usize,
        y: usize,
        column: &mut Column,
        out: &mut Vec<(u32, u32)>,
    ) {
        match self {
            Pruned::Word(w) => out.push(w.slabs(slicer, x as i64, y as i64)),
            Pruned::Float(f) => out.push(f.slabs(slicer, x, y)),
            Pruned::Sampled(d) => d.slabs(x, y, column, out),
            Pruned::Level(r) => out.push(*r),
        }
    }
}

/// Side of the tiles a panel's planes are pruned to again where many are left.
const TILE: usize = 8;

/// Planes left over a panel above which they are pruned again tile by tile.
const RETILE: usize = 8;

/// A primitive's planes over its outline `o` in a panel: pruned to it, and where many are
/// left (a solid of many faces, whose faces each decide only a few pixels) pruned again to
/// each TILE×TILE tile of it. Pruning a box's planes to a box inside it keeps what every
/// pixel of the smaller box is decided by ([`WordPlanes::in_panel`]), so a column's slabs are
/// the same from either; a pixel then evaluates its tile's few planes, not the panel's many.
enum Tiles<'d, 'a> {
    One(Pruned<'d, 'a>),
    /// Row-major over the tiles of `o` from its corner, `across` a row; None: nothing there.
    Grid {
        across: usize,
        tiles: Vec<Option<Pruned<'d, 'a>>>,
    },
}

impl<'d, 'a> Tiles<'d, 'a> {
    fn of(slicer: &Slicer, pruned: Pruned<'d, 'a>, o: PixelBox) -> Self {
        if pruned.planes() <= RETILE || o.width().max(o.height()) <= TILE {
            return Tiles::One(pruned);
        }
        let (across, down) = (o.width().div_ceil(TILE), o.height().div_ceil(TILE));
        let tiles = (0..across * down)
            .map(|i| {
                let (tx, ty) = (o.x0 + i % across * TILE, o.y0 + i / across * TILE);
                let t = PixelBox::new(tx, ty, (tx + TILE).min(o.x1), (ty + TILE).min(o.y1));
                pruned.in_box(slicer, t)
            })
            .collect();
        Tiles::Grid { across, tiles }
    }

    /// The slabs of row `y` of outline `o`, one run a column (`(1, 0)` where none), into
    /// `row`; false for an import's runs (several a column, taken column by column).
    fn row(&self, slicer: &Slicer, o: PixelBox, y: usize, row: &mut Vec<(u32, u32)>) -> bool {
        row.clear();
        match self {
            Tiles::One(p) => p.row(slicer, y, o.x0..o.x1, row),
            Tiles::Grid { across, tiles } => {
                let down = (y - o.y0) / TILE;
                for (k, tile) in tiles[down * across..][..*across].iter().enumerate() {
                    let x0 = o.x0 + k * TILE;
                    let xs = x0..(x0 + TILE).min(o.x1);
                    match tile {
                        None => row.extend(xs.map(|_| (1, 0))),
                        Some(p) => {
                            if !p.row(slicer, y, xs, row) {
                                return false;
                            }
                        }
                    }
                }
                true
            }
        }
    }

    /// The planes for pixel (x, y) of outline `o`; None where the solid is nowhere.
    fn at(&self, o: PixelBox, x: usize, y: usize) -> Option<&Pruned<'d, 'a>> {
        match self {
            Tiles::One(p) => Some(p),
            Tiles::Grid { across, tiles } => {
                let i = (y - o.y0) / TILE * across + (x - o.x0) / TILE;
                tiles[i].as_ref()
            }
        }
    }
}

const EMPTY_BOX: PixelBox = PixelBox {
    x0: 0,
    y0: 0,
    x1: 0,
    y1: 0,
};

fn window(b: PixelBox) -> Window {
    Window {
        x0: b.x0,
        y0: b.y0,
        w: b.width(),
        h: b.height(),
    }
}

/// Panel `i`'s columns (row-major over the array), cut by the grid's edges.
fn panel_box(slicer: &Slicer, [pw, ph]: [usize; 2], i: usize) -> PixelBox {
    let [nx, ny, _] = slicer.grid.dims;
    let (px, py) = (i % nx.div_ceil(pw), i / nx.div_ceil(pw));
    PixelBox {
        x0: px * pw,
        y0: py * ph,
        x1: ((px + 1) * pw).min(nx),
        y1: ((py + 1) * ph).min(ny),
    }
}

/// Per panel, the primitives whose outline meets it, in index order.
fn panel_lists(slicer: &Slicer, [pw, ph]: [usize; 2]) -> Vec<Vec<u32>> {
    let [w, h, _] = slicer.grid.dims;
    let (nx, ny) = (w.div_ceil(pw), h.div_ceil(ph));
    let mut lists = vec![vec![]; nx * ny];
    for (p, b) in slicer.outlines.iter().enumerate() {
        let Some(b) = b else { continue };
        for py in b.y0 / ph..b.y1.div_ceil(ph).min(ny) {
            for px in b.x0 / pw..b.x1.div_ceil(pw).min(nx) {
                lists[py * nx + px].push(p as u32);
            }
        }
    }
    lists
}

/// The segments of a panel's columns: where, along each column, some primitive's membership
/// changes, and which primitives hold each segment.
#[derive(Default)]
struct Segments {
    /// First slab of every segment, column after column.
    starts: Vec<u32>,
    /// Where each column's segments start in `starts`.
    column: Vec<usize>,
    /// Every primitive run: (primitive, column, first slab, last slab).
    held: Vec<(u32, u32, u32, u32)>,
}

impl Segments {
    /// A column whose primitives fill runs `held` (primitive, first slab, last slab), on a
    /// grid `nz` slabs deep.
    fn column(&mut self, held: &[(u32, u32, u32)], nz: u32) {
        let at = self.starts.len();
        let c = self.column.len() as u32;
        self.column.push(at);
        self.starts.push(0);
        for &(p, a, b) in held {
            self.starts.push(a);
            if b + 1 < nz {
                self.starts.push(b + 1);
            }
            self.held.push((p, c, a, b));
        }
        let col = &mut self.starts[at..];
        col.sort_unstable();
        let n = dedup_sorted(col);
        self.starts.truncate(at + n);
    }

    /// One mask per primitive over every segment of the panel: set where it holds the
    /// segment; empty (no allocation) for primitives with no run here.
    fn masks(&self, prims: usize) -> Vec<Mask> {
        let len = self.starts.len();
        let mut masks: Vec<Mask> = (0..prims).map(|_| Mask::new(0)).collect();
        if let Some(m) = masks.first_mut() {
            *m = Mask::new(len); // the slice's length, whoever holds a run
        }
        for &(p, c, a, b) in &self.held {
            let m = &mut masks[p as usize];
            if m.len() != len {
                *m = Mask::new(len);
            }
            let (from, to) = self.range(c as usize);
            let col = &self.starts[from..to];
            let first = from + col.partition_point(|&k| k < a);
            let end = from + col.partition_point(|&k| k <= b);
            m.set_range(first..end);
        }
        masks
    }

    /// Column c's segments: indices into `starts`.
    fn range(&self, c: usize) -> (usize, usize) {
        let to = self.column.get(c + 1).copied().unwrap_or(self.starts.len());
        (self.column[c], to)
    }

    /// Each column's segment starts and their range of indices.
    fn columns(&self) -> impl Iterator<Item = (&[u32], std::ops::Range<usize>)> + '_ {
        (0..self.column.len()).map(|c| {
            let (a, b) = self.range(c);
            (&self.starts[a..b], a..b)
        })
    }
}

/// Removes repeats from a sorted slice in place; returns the length kept.
fn dedup_sorted(v: &mut [u32]) -> usize {
    let mut n = 0;
    for i in 0..v.len() {
        if n == 0 || v[i] != v[n - 1] {
            v[n] = v[i];
            n += 1;
        }
    }
    n
}

/// Bands of rows the run route works in: one panel row each, so a band's primitives are
/// those of its panels.
fn bands(slicer: &Slicer) -> Vec<(usize, usize)> {
    let h = slicer.grid.dims[1];
    let ph = slicer.panel.unwrap_or(DEFAULT_PANEL)[1].max(1);
    (0..h.div_ceil(ph))
        .map(|b| (b * ph, ((b + 1) * ph).min(h)))
        .collect()
}

/// Ticks [`voxelize_runs`] and [`sweep_slices`] make: one per band of rows, and one per row
/// of each open mesh's outline ([`open_mesh_ticks`]).
pub fn ticks(slicer: &Slicer) -> usize {
    bands(slicer).len() + open_mesh_ticks(slicer)
}

/// The rows of the open meshes' outlines: [`Columns::new`] ticks once for each as its
/// winding numbers are done.
pub fn open_mesh_ticks(slicer: &Slicer) -> usize {
    open_mesh_outlines(slicer).map(|(b, _)| b.height()).sum()
}

/// The boundary edges an open mesh's winding number sums, times the voxels of its outline's
/// columns, over every open mesh: how much work the winding numbers may be (the soup's
/// order, docs/volume-scenes.md, "Open and non-manifold meshes").
pub fn open_mesh_work(slicer: &Slicer) -> u64 {
    let nz = slicer.grid.dims[2] as u64;
    let each = open_mesh_outlines(slicer).map(|(b, edges)| b.pixels() as u64 * nz * edges as u64);
    each.fold(0, u64::saturating_add)
}

/// Each open mesh's outline and boundary edges.
fn open_mesh_outlines(slicer: &Slicer) -> impl Iterator<Item = (PixelBox, usize)> + '_ {
    let solids = slicer.lists.len();
    slicer
        .sampled
        .iter()
        .enumerate()
        .filter_map(move |(j, s)| match &s.shape {
            Shape::OpenMesh(m, _) => {
                let b = slicer.outlines[solids + j].unwrap_or(EMPTY_BOX);
                Some((b, m.boundary_edges()))
            }
            _ => None,
        })
}

/// The whole volume by the run route, bands of rows in parallel, each band's runs written
/// row by row ([`write_rows`]); `tick` once per band. The work counts are [`Work`]'s except
/// `ops`, which counts the evaluator's work per segment, and `simulated_pixel_clocks` (0).
pub fn voxelize_runs(
    slicer: &Slicer,
    float: bool,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    mut work: Work,
) -> Result<(Volume, Work)> {
    let [nx, ny, nz] = slicer.grid.dims;
    let columns = Columns::new(slicer, float, tick)?;
    let bands = bands(slicer);
    let mut voxels = csgpix_output::try_zeroed(nx * ny * nz)?;
    // Every (y, z) row of the volume, grouped by band: band b owns rows y0..y1 of every slab.
    let mut owned: Vec<Vec<&mut [u8]>> = bands.iter().map(|_| vec![]).collect();
    let band_of = |y: usize| y / slicer.panel.unwrap_or(DEFAULT_PANEL)[1].max(1);
    for (r, row) in voxels.chunks_mut(nx.max(1)).enumerate() {
        owned[band_of(r % ny)].push(row);
    }
    let counted: Vec<(usize, OpCounts)> = owned
        .into_par_iter()
        .zip(bands)
        .map(|(mut rows, (y0, y1))| {
            let (runs, ops) = columns.rows(eval, y0, y1);
            // Every page touched here, in parallel, as the band's own: a zeroed allocation's
            // pages are mapped on first touch, and left to the file's write they are mapped
            // one at a time on one thread (×3-5 the time at 512³, measured).
            rows.iter_mut().for_each(|r| r.fill(0));
            write_rows(&runs, 0..nz, &mut rows);
            tick();
            (runs.filled(0..nz), ops)
        })
        .collect();
    for (filled, ops) in counted {
        work.filled += filled;
        work.ops += ops;
    }
    Ok((
        Volume {
            dims: slicer.grid.dims,
            voxels,
        },
        work,
    ))
}

/// Writes the runs of `runs`' columns over slabs `slabs` into `rows`: one row of the columns'
/// width per (slab, y), slab-major (`rows[(k − k0)·h + (y − y0)]`), left as they are (zero)
/// where a row is empty.
pub fn write_rows(runs: &ColumnRuns, slabs: std::ops::Range<usize>, rows: &mut [&mut [u8]]) {
    let b = runs.columns;
    let (w, h) = (b.width(), b.height());
    let mut cur = vec![0u8; w];
    for y in 0..h {
        // Colour changes along z as (k, x, colour), in order of k.
        let mut changes: Vec<(u32, u32, u8)> = vec![];
        for (x, c) in cur.iter_mut().enumerate() {
            let col = runs.column(b.x0 + x, b.y0 + y);
            let at = col.partition_point(|r| (r.k as usize) <= slabs.start);
            *c = at.checked_sub(1).map_or(0, |a| col[a].colour);
            let later = col[at..].iter().take_while(|r| (r.k as usize) < slabs.end);
            changes.extend(later.map(|r| (r.k, x as u32, r.colour)));
        }
        changes.sort_unstable_by_key(|c| c.0);
        let mut filled = cur.iter().filter(|&&c| c != 0).count();
        let mut next = changes.iter().peekable();
        for k in slabs.clone() {
            while let Some(&(_, x, c)) = next.next_if(|c| c.0 as usize == k) {
                let old = std::mem::replace(&mut cur[x as usize], c);
                filled = filled + usize::from(c != 0) - usize::from(old != 0);
            }
            if filled > 0 {
                rows[(k - slabs.start) * h + y].copy_from_slice(&cur);
            }
        }
    }
}

/// One brick of the volume: the columns of `columns` over slabs `slabs`, as the whole run
/// gives them, in the volume's order within the brick (X fastest, then Y, then Z), and the
/// voxels filled in it. What one task of a run split into bricks computes (docs/scale-out.md):
/// only the brick's columns are evaluated, so its memory is the brick's voxels and its
/// columns' runs (and each mesh primitive's crossings over its outline), not a whole slice's.
pub fn voxelize_brick(
    slicer: &Slicer,
    float: bool,
    eval: &dyn SliceEval,
    columns: PixelBox,
    slabs: std::ops::Range<usize>,
) -> Result<(Vec<u8>, usize)> {
    let [nx, ny, nz] = slicer.grid.dims;
    if columns.x1 > nx || columns.y1 > ny || slabs.end > nz || slabs.start > slabs.end {
        return Err(crate::Error::BrickRange {
            columns,
            slabs,
            dims: [nx, ny, nz],
        });
    }
    let runs = Columns::new(slicer, float, &|| ())?.brick(eval, columns);
    let filled = runs.filled(slabs.clone());
    let mut voxels = vec![0u8; columns.pixels() * slabs.len()];
    runs.write(slabs, &mut voxels);
    Ok((voxels, filled))
}

/// A brick's columns' runs, a band of panel rows each (computed in parallel): what
/// `csgpix_zarr::ZarrVolume::write_brick` writes slab range after slab range, and the
/// evaluator's counts.
pub struct BrickRuns {
    /// The brick's columns.
    pub columns: PixelBox,
    /// Its bands' runs, top to bottom, each the brick's width.
    pub bands: Vec<ColumnRuns>,
    /// The evaluator's work.
    pub ops: OpCounts,
}

impl Columns<'_> {
    /// The runs of the columns of `b`, bands of panel rows in parallel.
    pub fn brick(&self, eval: &dyn SliceEval, b: PixelBox) -> BrickRuns {
        let ph = self.panel[1];
        let bands: Vec<PixelBox> = (b.y0 / ph..b.y1.div_ceil(ph))
            .map(|p| PixelBox::new(b.x0, (p * ph).max(b.y0), b.x1, ((p + 1) * ph).min(b.y1)))
            .collect();
        let done: Vec<(ColumnRuns, OpCounts)> = bands
            .into_par_iter()
            .map(|band| self.columns(eval, band))
            .collect();
        let mut ops = OpCounts::default();
        let bands = done
            .into_iter()
            .map(|(r, o)| {
                ops += o;
                r
            })
            .collect();
        BrickRuns {
            columns: b,
            bands,
            ops,
        }
    }
}

impl BrickRuns {
    /// Voxels filled within `slabs`.
    pub fn filled(&self, slabs: std::ops::Range<usize>) -> usize {
        self.bands.iter().map(|b| b.filled(slabs.clone())).sum()
    }

    /// The one colour of the columns of `b` (within the brick) over `slabs`, if any
    /// ([`ColumnRuns::uniform`]).
    pub fn uniform(&self, b: PixelBox, slabs: std::ops::Range<usize>) -> Option<u8> {
        let mut colour = None;
        for band in &self.bands {
            let Some(part) = band.columns.intersect(b) else {
                continue;
            };
            let c = band.uniform(part, slabs.clone())?;
            if colour.is_some_and(|v| v != c) {
                return None;
            }
            colour = Some(c);
        }
        colour
    }

    /// The brick's voxels over `slabs` into `voxels` (zeroed; X fastest, then Y, then Z,
    /// the brick's width and height), bands in parallel.
    pub fn write(&self, slabs: std::ops::Range<usize>, voxels: &mut [u8]) {
        let b = self.columns;
        let (w, h) = (b.width().max(1), b.height());
        let mut owned: Vec<Vec<&mut [u8]>> = self.bands.iter().map(|_| vec![]).collect();
        let band_of = |y: usize| self.bands.partition_point(|r| r.columns.y1 <= b.y0 + y);
        for (r, row) in voxels.chunks_mut(w).enumerate() {
            owned[band_of(r % h)].push(row);
        }
        owned
            .into_par_iter()
            .zip(&self.bands)
            .for_each(|(mut rows, runs)| write_rows(runs, slabs.clone(), &mut rows));
    }
}

/// Slices `slabs` of the run route handed to `sink` in order of k, as
/// [`crate::voxelize_slabs`] does for the slab routes: the runs of every column computed
/// and turned into the first slab's colours and each later slab's changes band by band, in
/// parallel; then the changes applied slab by slab.
pub fn sweep_slices<E: From<crate::Error>>(
    slicer: &Slicer,
    float: bool,
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    slabs: std::ops::Range<usize>,
    sink: &mut SliceSink<E>,
    mut work: Work,
) -> Result<Work, E> {
    let [nx, ny, _] = slicer.grid.dims;
    let columns = Columns::new(slicer, float, tick)?;
    let mut cur = vec![0u8; nx * ny];
    let bands = bands(slicer);
    // The bands are whole panels of rows, so each writes its own rows of `cur`.
    let rows = bands.first().map_or(1, |&(y0, y1)| y1 - y0).max(1);
    let swept: Vec<BandSweep> = bands
        .into_par_iter()
        .zip(cur.par_chunks_mut((rows * nx).max(1)))
        .map(|((y0, y1), first)| {
            let runs = columns.rows(eval, y0, y1);
            tick();
            BandSweep::of(runs, first, slabs.clone())
        })
        .collect();
    for band in &swept {
        work.ops += band.ops;
        work.filled += band.filled;
    }
    for (k, at) in slabs.clone().zip(0..) {
        for band in &swept {
            for &(i, c) in &band.changes[at] {
                cur[i as usize] = c;
            }
        }
        sink(k, &cur)?;
    }
    Ok(work)
}

/// A band of rows ready to sweep: its columns' colours at the first slab written, and per
/// later slab the pixels (indices into the whole slice) whose colour changes there.
struct BandSweep {
    changes: Vec<Vec<(u32, u8)>>,
    ops: OpCounts,
    filled: usize,
}

impl BandSweep {
    /// Band `runs` (its [`OpCounts`] beside) over `slabs`, its first slab's colours written
    /// to `first` (the band's rows of the slice).
    fn of(
        (runs, ops): (ColumnRuns, OpCounts),
        first: &mut [u8],
        slabs: std::ops::Range<usize>,
    ) -> Self {
        // A band spans whole rows: its width is the slice's.
        let nx = runs.columns.width();
        let b = runs.columns;
        // Each slab's changes counted first, so none of the lists grows by copying.
        let mut count = vec![0usize; slabs.len()];
        for r in &runs.runs {
            // A run from the first slab on is in `first`, not a change.
            let at = (r.k as usize).checked_sub(slabs.start).filter(|&i| i > 0);
            if let Some(c) = at.and_then(|i| count.get_mut(i)) {
                *c += 1;
            }
        }
        let mut changes: Vec<Vec<(u32, u8)>> = count.into_iter().map(Vec::with_capacity).collect();
        for y in b.y0..b.y1 {
            for x in b.x0..b.x1 {
                let col = runs.column(x, y);
                let at = col.partition_point(|r| (r.k as usize) <= slabs.start);
                first[(y - b.y0) * nx + x - b.x0] = at.checked_sub(1).map_or(0, |a| col[a].colour);
                let i = (y * nx + x) as u32;
                for r in col[at..].iter().take_while(|r| (r.k as usize) < slabs.end) {
                    changes[r.k as usize - slabs.start].push((i, r.colour));
                }
            }
        }
        BandSweep {
            changes,
            ops,
            filled: runs.filled(slabs),
        }
    }
}

/// Segments the columns of panel `i` can have: per column one, plus two per primitive run
/// ([`primitive_runs`]), never more than the slabs.
fn segments_bound(slicer: &Slicer, prims: &[u32], counts: &DatasetCounts, i: usize) -> u64 {
    let [pw, ph] = counts.panel.map(|p| p as u64);
    let (columns, nz) = (pw.saturating_mul(ph), slicer.grid.dims[2] as u64);
    let runs = primitive_runs(slicer, prims, counts, i);
    columns
        .saturating_add(runs.saturating_mul(2))
        .min(columns.saturating_mul(nz.max(1)))
}

/// The primitive runs the columns of panel `i` can hold: a primitive has runs only on the
/// columns of its outline ([`Columns::panel_runs`] visits no others), a convex solid one
/// there, a mesh about one per two crossings (taken as [`MESH_RUNS`], as
/// [`crate::sampled::Sampled::memory_estimate`] takes two crossings), a dataset as many as
/// the slabs unless `counts` counted its runs, then those.
fn primitive_runs(slicer: &Slicer, prims: &[u32], counts: &DatasetCounts, i: usize) -> u64 {
    let nz = slicer.grid.dims[2] as u64;
    let solids = slicer.lists.len();
    let b = panel_box(slicer, counts.panel, i);
    let bounded: u64 = prims
        .iter()
        .map(|&p| {
            let j = (p as usize).wrapping_sub(solids);
            let per_column = match slicer.sampled.get(j) {
                None => 1,
                Some(_) if counts.counted[j] => 0,
                Some(s) if s.is_dataset() => nz,
                Some(_) => MESH_RUNS,
            };
            let covered = slicer.outlines[p as usize].and_then(|o| o.intersect(b));
            per_column.saturating_mul(covered.map_or(0, |o| o.pixels() as u64))
        })
        .fold(0u64, u64::saturating_add);
    bounded.saturating_add(counts.per_panel[i])
}

/// The runs of the datasets that go a lattice cell at a time ([`DatasetColumns::by_cells`]),
/// counted panel by panel by walking their columns (nothing is kept): a dataset's runs
/// follow its surface, which no bound from the scene sees, and counting costs a fraction of
/// the voxelization (the per-voxel datasets keep the slabs as their bound).
struct DatasetCounts {
    panel: [usize; 2],
    /// Per import, whether its runs are counted.
    counted: Vec<bool>,
    /// Per panel (row-major), the counted runs on its columns.
    per_panel: Vec<u64>,
}

impl DatasetCounts {
    fn of(slicer: &Slicer, panel: [usize; 2], lists: &[Vec<u32>]) -> DatasetCounts {
        let datasets: Vec<Option<DatasetColumns>> = (slicer.sampled.iter())
            .map(|s| DatasetColumns::new(s, &slicer.grid).filter(DatasetColumns::by_cells))
            .collect();
        let counted: Vec<bool> = datasets.iter().map(Option::is_some).collect();
        let per_panel = match counted.contains(&true) {
            false => vec![0; lists.len()],
            true => (lists.par_iter().enumerate())
                .map(|(i, l)| count_panel(slicer, panel, i, l, &datasets))
                .collect(),
        };
        DatasetCounts {
            panel,
            counted,
            per_panel,
        }
    }
}

/// The runs `datasets` give on the columns of panel `i`, whose primitives are `prims`, as
/// [`Columns::panel_runs`] takes them.
fn count_panel(
    slicer: &Slicer,
    [pw, ph]: [usize; 2],
    i: usize,
    prims: &[u32],
    datasets: &[Option<DatasetColumns>],
) -> u64 {
    let b = panel_box(slicer, [pw, ph], i);
    let (mut column, mut span, mut n) = (Column::default(), vec![], 0u64);
    for &p in prims {
        let j = (p as usize).wrapping_sub(slicer.lists.len());
        let Some(Some(d)) = datasets.get(j) else {
            continue;
        };
        let Some(o) = slicer.outlines[p as usize].and_then(|o| o.intersect(b)) else {
            continue;
        };
        for y in o.y0..o.y1 {
            for x in o.x0..o.x1 {
                span.clear();
                d.runs(x, y, &mut column, &mut span);
                n += span.iter().filter(|(a, b)| a <= b).count() as u64;
            }
        }
    }
    n
}

/// Runs assumed per column for a mesh primitive in the memory estimate.
pub const MESH_RUNS: u64 = 2;

/// An upper bound of the memory of a run-route run (docs/memory.md): the volume (`volume`;
/// else the slices' runs of the whole grid, held to be swept along z), the rows' handles,
/// each mesh's runs over its outline, and per thread a band's runs and its panel's segments,
/// masks (only the panel's primitives hold bits) and evaluator state. It follows the
/// primitives' footprints: a primitive costs where its outline is, not on every pixel.
pub fn memory_estimate(slicer: &Slicer, eval: &dyn SliceEval, threads: usize, volume: bool) -> u64 {
    memory_estimates(slicer, eval, threads)[usize::from(volume)]
}

/// [`memory_estimate`] both ways, the panels' bytes counted once: without the volume (the
/// runs swept slice by slice) and with it.
pub fn memory_estimates(slicer: &Slicer, eval: &dyn SliceEval, threads: usize) -> [u64; 2] {
    let [nx, ny, nz] = slicer.grid.dims.map(|d| d as u64);
    let panels = PanelBytes::of(slicer, eval, None);
    let volume = nx
        .saturating_mul(ny)
        .saturating_mul(nz)
        .saturating_add(nz.saturating_mul(ny).saturating_mul(16));
    let swept = panels
        .kept
        .iter()
        .fold(0u64, |a, &k| a.saturating_add(k))
        .saturating_mul(2)
        .saturating_add(nx.saturating_mul(ny));
    [swept, volume].map(|held| panels.total(slicer, threads, held))
}

/// [`memory_estimate`] of a run by bricks of `tile` columns (X, Y; tiles start at its
/// multiples), one brick at a time: the largest tile's runs instead of the grid's (the
/// brick's voxels are the writer's to count). `within`: the columns of the tiles the run
/// computes (a task's), if not all: only their panels are counted.
pub fn memory_estimate_bricks(
    slicer: &Slicer,
    eval: &dyn SliceEval,
    threads: usize,
    tile: [usize; 2],
    within: Option<PixelBox>,
) -> u64 {
    let [nx, ny, _] = slicer.grid.dims;
    let panels = PanelBytes::of(slicer, eval, within);
    let [pw, ph] = panels.panel;
    let across = nx.div_ceil(pw);
    let [tx, ty] = tile.map(|t| t.max(1));
    let mut per_tile = vec![0u64; nx.div_ceil(tx) * ny.div_ceil(ty)];
    for (i, &k) in panels.kept.iter().enumerate() {
        // A panel's runs are held by every tile its columns meet.
        let (px, py) = (i % across, i / across);
        for ty_ in (py * ph) / ty..((py + 1) * ph).min(ny).div_ceil(ty) {
            for tx_ in (px * pw) / tx..((px + 1) * pw).min(nx).div_ceil(tx) {
                let t = &mut per_tile[ty_ * nx.div_ceil(tx) + tx_];
                *t = t.saturating_add(k);
            }
        }
    }
    let held = per_tile.into_iter().max().unwrap_or(0);
    panels.total(slicer, threads, held)
}

/// What each panel of a run-route run holds: its runs, kept while its band's slices are
/// written, and the largest band's transient state; where `within` is given, the panels
/// that do not meet it are taken as empty (their datasets' runs not counted).
struct PanelBytes {
    panel: [usize; 2],
    /// Per panel (row-major), its columns' runs and their handles.
    kept: Vec<u64>,
    /// The largest band's runs and working state.
    band: u64,
}

impl PanelBytes {
    fn of(slicer: &Slicer, eval: &dyn SliceEval, within: Option<PixelBox>) -> PanelBytes {
        let nx = slicer.grid.dims[0] as u64;
        let panel = slicer.panel.unwrap_or(DEFAULT_PANEL).map(|p| p.max(1));
        let mut lists = panel_lists(slicer, panel);
        if let Some(w) = within {
            for (i, l) in lists.iter_mut().enumerate() {
                if panel_box(slicer, panel, i).intersect(w).is_none() {
                    *l = vec![];
                }
            }
        }
        let counts = DatasetCounts::of(slicer, panel, &lists);
        let [pw, ph] = panel.map(|p| p as u64);
        let across = nx.div_ceil(pw) as usize;
        let prims = slicer.primitive_count() as u64;
        let (mut bands, mut band) = (0u64, 0u64);
        let mut kept_all = Vec::with_capacity(lists.len());
        for (i, l) in lists.iter().enumerate() {
            let columns = pw.saturating_mul(ph);
            let segs = segments_bound(slicer, l, &counts, i);
            // Segments (4 bytes), their labels (4) and runs (8), the runs' handles (24 a
            // column), the primitive runs held (16 each), the masks (32 a primitive, a bit a
            // segment for the panel's own) and the evaluator's state.
            let transient = segs
                .saturating_mul(16)
                .saturating_add(columns.saturating_mul(16 * l.len() as u64))
                .saturating_add(prims.saturating_mul(32))
                .saturating_add((l.len() as u64).saturating_mul(segs / 8 + 8))
                .saturating_add(eval.state_bytes(segs as usize) as u64);
            let kept = segs
                .saturating_mul(8)
                .saturating_add(columns.saturating_mul(24));
            band = band.saturating_add(kept).saturating_add(transient);
            kept_all.push(kept);
            if (i + 1) % across == 0 {
                bands = bands.max(band);
                band = 0;
            }
        }
        PanelBytes {
            panel,
            kept: kept_all,
            band: bands,
        }
    }

    /// `held` with each mesh's runs over its outline, a band per thread and the process.
    fn total(&self, slicer: &Slicer, threads: usize, held: u64) -> u64 {
        let meshes: u64 = slicer
            .sampled
            .iter()
            .zip(&slicer.outlines[slicer.lists.len()..])
            .map(|(s, b)| s.memory_estimate_over(b.map_or(0, |b| b.pixels() as u64)))
            .sum();
        held.saturating_add(meshes)
            .saturating_add((threads as u64).saturating_mul(self.band))
            .saturating_add(PROCESS_BYTES)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ranges::tests::{slicer_and_box, solid};
    use crate::slicer::SlicerOptions;
    use csgpix_scene::grid::Grid;
    use proptest::prelude::*;

    /// Column (x, y)'s runs of slabs from `p`, empty ones dropped.
    fn slabs(p: &Pruned, slicer: &Slicer, x: usize, y: usize) -> Vec<(u32, u32)> {
        let mut out = vec![];
        p.slabs(slicer, x, y, &mut Column::default(), &mut out);
        out.retain(|(a, b)| a <= b);
        out
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// A solid's planes pruned to a box, then again tile by tile, give every pixel of the
        /// box the slabs all its planes give, in the word and in f64, pixel by pixel and a
        /// row at a time.
        #[test]
        fn planes_pruned_tile_by_tile_decide_as_all_do(
            text in solid(),
            n in 8usize..80,
            at in prop::array::uniform2(0usize..80),
            size in prop::array::uniform2(1usize..40),
        ) {
            let (slicer, b) = slicer_and_box(&text, n, at, size);
            let word = Pruned::Word(WordPlanes::of(&slicer, 0).unwrap());
            let float = Pruned::Float(FloatPlanes::of(&slicer, 0));
            for all in [word, float] {
                let tiles = all.in_box(&slicer, b).map(|p| Tiles::of(&slicer, p, b));
                let mut row = vec![];
                for y in b.y0..b.y1 {
                    let by_row = tiles.as_ref().is_some_and(|t| t.row(&slicer, b, y, &mut row));
                    prop_assert!(by_row || tiles.is_none());
                    for x in b.x0..b.x1 {
                        let got = tiles
                            .as_ref()
                            .and_then(|t| t.at(b, x, y))
                            .map_or(vec![], |p| slabs(p, &slicer, x, y));
                        let want = slabs(&all, &slicer, x, y);
                        prop_assert_eq!(&got, &want, "pixel {},{}", x, y);
                        // The row's run, made a plane at a time, is the pixel's.
                        if by_row {
                            let (first, last) = row[x - b.x0];
                            let got: Vec<_> = [(first, last)].into_iter().filter(|(a, b)| a <= b).collect();
                            prop_assert_eq!(got, want, "row pixel {},{}", x, y);
                        }
                    }
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// The estimate's bounds hold every panel's primitive runs and segments: each
        /// primitive counted on the columns of its outline only.
        #[test]
        fn a_panel_holds_no_more_runs_and_segments_than_its_bounds(
            text in csgpix_testkit::random_scene(),
            dims in prop::array::uniform3(1usize..40),
            panel in prop::array::uniform2(1usize..12),
        ) {
            let scene = csgpix_openscad::parse_csg(&text, "random").unwrap();
            let grid = Grid::of_scene(&scene, dims).unwrap();
            let opts = SlicerOptions { panel: Some(panel), ..SlicerOptions::default() };
            let slicer = Slicer::new(&scene, grid, opts).unwrap();
            let columns = Columns::new(&slicer, false, &|| ()).unwrap();
            let lists = panel_lists(&slicer, panel);
            let counts = DatasetCounts::of(&slicer, panel, &lists);
            for (i, l) in lists.iter().enumerate() {
                let (seg, _) = columns.panel_segments(panel_box(&slicer, panel, i), l);
                let (runs, segs) = (seg.held.len() as u64, seg.starts.len() as u64);
                prop_assert!(runs <= primitive_runs(&slicer, l, &counts, i), "panel {}", i);
                prop_assert!(segs <= segments_bound(&slicer, l, &counts, i), "panel {}", i);
            }
        }
    }

    /// The test above reaches the tiles: a sphere of many faces over a panel is tiled, and
    /// its tiles hold fewer planes than the panel.
    #[test]
    fn a_many_faced_solid_is_pruned_tile_by_tile() {
        let scene = csgpix_openscad::parse_csg("sphere($fn = 40, r = 9);", "s.csg").unwrap();
        let lo = glam::DVec3::splat(-10.0);
        let grid = Grid::new([64, 64, 64], lo, -lo).unwrap();
        let slicer = Slicer::new(&scene, grid, SlicerOptions::default()).unwrap();
        let b = PixelBox::new(0, 0, 32, 32);
        let panel = Pruned::Word(WordPlanes::of(&slicer, 0).unwrap())
            .in_box(&slicer, b)
            .unwrap();
        let most = panel.planes();
        let Tiles::Grid { tiles, .. } = Tiles::of(&slicer, panel, b) else {
            panic!("{most} planes over the panel, not tiled");
        };
        let fewest = tiles.iter().flatten().map(Pruned::planes).min().unwrap();
        assert!(fewest < most, "{fewest} of {most}");
    }
}
