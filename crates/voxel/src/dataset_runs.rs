//! A dataset import's runs along a pixel column without sampling every voxel: exactly the
//! voxels [`Sampled::inside`] gives at the voxel centres, in a few samples per lattice cell
//! where the import's placement allows it, voxel by voxel otherwise.
//!
//! Voxel (x, y, k)'s membership is computed as centre c = `grid.centre(x, y, k)` → file
//! point f = `to_file.transform_point3(c)` → offset d = f − origin → index q = `inverse · d`
//! ([`Dataset::index_of`]) → a lattice cell per axis → the trilinear value, inside when at or
//! above the threshold ([`Dataset::sample`]). Along a column only c.z moves. When the
//! placement keeps index x and y off c.z ([`ColumnMap::of`]), the x and y steps of the
//! interpolation are done once per column ([`Dataset::fill_column`]) and only index z is
//! computed per voxel, by `index_of` itself. Index z then moves one way along the column, so
//! the voxels of one lattice z-cell are consecutive: a cell whose two plane values lie clearly
//! on one side of the threshold (`side`) is filled or skipped whole, together with the cells
//! after it on the same side, their end found by a search ([`first_true`]); in the other
//! cells, which the threshold crosses, a search finds the voxels near the crossing, and only
//! those are sampled one by one (`Walk::crossing`).

use std::ops::Range;

use glam::{DMat3, DMat4, DVec3};

use crate::sampled::{Sampled, Shape};
use csgpix_scene::dataset::{cell, Cell, Column, Dataset};
use csgpix_scene::grid::Grid;

/// How index z moves along every pixel column of a grid, for a placement whose index x and y
/// do not move along it: the condition of the column-at-a-time path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ColumnMap {
    /// 1 when index z never decreases as k grows, −1 when it never increases.
    dir: i64,
}

impl ColumnMap {
    /// The column map of a dataset placed by scene → file map `to_file`, with axis-step
    /// inverse `inverse`, on `grid`; `None` when index x or y may differ between two voxels
    /// of a column, or index z may move both ways along one.
    ///
    /// The operations, in order (glam 0.30's `transform_point3` and `DMat3 * DVec3`, no fused
    /// multiply-add), X, Y, Z, W being `to_file`'s columns and I_s `inverse`'s:
    /// c.z = min.z + (k + ½)·v.z; f_s = W_s + (Z_s·c.z + (Y_s·c.y + X_s·c.x)); d_s = f_s − o_s;
    /// q_r = (I_0r·d_0 + I_1r·d_1) + I_2r·d_2. Only c.z depends on k. Hence, with every
    /// entry and c.z finite:
    ///
    /// * where Z_s = ±0, Z_s·c.z = ±0, and adding ±0 leaves a value unchanged (only a zero
    ///   sum's sign may differ; inf and NaN stay): f_s and d_s keep one value ("fixed" s);
    /// * where I_sx = I_sy = ±0 for every moving s (Z_s ≠ 0), and d_s is finite, the moving
    ///   terms of q_x and q_y are ±0: q_x and q_y keep one value;
    /// * the later steps (`cell`: comparisons, clamp, floor, a subtraction; `lerp`: −, ·, +)
    ///   give equal values for equal inputs (again up to a zero's sign, which no comparison
    ///   sees), so every voxel of the column is sampled with the same x and y cells;
    /// * rounding is monotone, so c.z never decreases with k, a moving d_s moves the way of
    ///   sign(Z_s), and q_z moves one way when every moving term I_sz·d_s does: `dir`.
    ///
    /// A moving d_s that is not finite somewhere makes q_z there not finite (its term is ±inf
    /// or NaN): [`DatasetColumns`] checks q at both ends of each column, and d_s is monotone
    /// in between.
    pub fn of(grid: &Grid, to_file: &DMat4, inverse: &DMat3) -> Option<ColumnMap> {
        let nz = grid.dims[2];
        // c.z does not depend on (x, y), and is monotone in k: its ends bound it.
        let ends = [grid.centre(0, 0, 0).z, grid.centre(0, 0, nz - 1).z];
        if !(to_file.is_finite() && inverse.is_finite() && ends.iter().all(|c| c.is_finite())) {
            return None;
        }
        let moving = to_file.z_axis.truncate().to_array();
        let steps = [inverse.x_axis, inverse.y_axis, inverse.z_axis];
        let mut dir = 0;
        for (z, i) in moving.into_iter().zip(steps) {
            if z == 0.0 {
                continue;
            }
            if i.x != 0.0 || i.y != 0.0 {
                return None;
            }
            if i.z == 0.0 {
                continue;
            }
            let d = if (z > 0.0) == (i.z > 0.0) { 1 } else { -1 };
            if dir != 0 && d != dir {
                return None;
            }
            dir = d;
        }
        // No moving term: index z is the same all along; either way is one way.
        Some(ColumnMap {
            dir: if dir == 0 { 1 } else { dir },
        })
    }
}

/// A dataset import ready to give its runs of slabs along the columns of a grid.
pub struct DatasetColumns<'a> {
    sampled: &'a Sampled,
    data: &'a Dataset,
    threshold: f64,
    to_file: &'a DMat4,
    grid: &'a Grid,
    map: Option<ColumnMap>,
}

impl<'a> DatasetColumns<'a> {
    /// The dataset import `s` on `grid` (`None` for a mesh).
    pub fn new(s: &'a Sampled, grid: &'a Grid) -> Option<DatasetColumns<'a>> {
        let Shape::Dataset {
            data,
            threshold,
            to_file,
        } = &s.shape
        else {
            return None;
        };
        Some(DatasetColumns {
            sampled: s,
            data,
            threshold: *threshold,
            to_file,
            grid,
            map: ColumnMap::of(grid, to_file, data.inverse()),
        })
    }

    /// Whether columns go a lattice cell at a time ([`ColumnMap::of`]), not voxel by voxel.
    pub fn by_cells(&self) -> bool {
        self.map.is_some()
    }

    /// The runs of slabs (first, last) inside the dataset along column (x, y), in order,
    /// appended to `out`; `column` is scratch space.
    pub fn runs(&self, x: usize, y: usize, column: &mut Column, out: &mut Vec<(u32, u32)>) {
        match self.map {
            Some(map) => self.runs_by_cells(map, x, y, column, out),
            None => self.runs_by_voxels(x, y, out),
        }
    }

    /// [`DatasetColumns::runs`] from [`Sampled::inside`] at every voxel centre.
    pub fn runs_by_voxels(&self, x: usize, y: usize, out: &mut Vec<(u32, u32)>) {
        let start = out.len();
        for k in 0..self.grid.dims[2] {
            if self.sampled.inside(self.grid.centre(x, y, k)) {
                push_run(out, start, k, k);
            }
        }
    }

    /// Voxel (x, y, k)'s index coordinates, as [`Sampled::sample`] computes them.
    fn index(&self, x: usize, y: usize, k: usize) -> DVec3 {
        let p = self.to_file.transform_point3(self.grid.centre(x, y, k));
        self.data.index_of(p)
    }

    /// [`DatasetColumns::runs`] a lattice cell at a time, under `map`.
    fn runs_by_cells(
        &self,
        map: ColumnMap,
        x: usize,
        y: usize,
        column: &mut Column,
        out: &mut Vec<(u32, u32)>,
    ) {
        let nz = self.grid.dims[2];
        let (first, last) = (self.index(x, y, 0), self.index(x, y, nz - 1));
        if !(first.is_finite() && last.is_finite()) {
            // Some offset overflows along the column (see `ColumnMap::of`).
            return self.runs_by_voxels(x, y, out);
        }
        // Index x and y are first's all along the column (`ColumnMap::of`).
        if !self.data.fill_column(first.x, first.y, column) {
            return;
        }
        let walk = Walk {
            columns: self,
            index: ColumnIndex::new(self, x, y),
            column,
            dir: map.dir,
            n: self.data.nrrd.sizes[2],
            start: first.z,
            slope: (last.z - first.z) / (nz - 1).max(1) as f64,
        };
        walk.runs(out);
    }
}

/// Index z along one pixel column: [`DatasetColumns::index`]'s operations, in its order on
/// the same values, so the same bits, with what does not move along the column (c.x, c.y
/// and their terms, the voxel's size) done once. By [`ColumnMap::of`]'s listing:
/// c.z = min.z + (k + ½)·v.z; f = W + (Z·c.z + (Y·c.y + X·c.x)); d = f − o;
/// q_z = (I_0z·d_x + I_1z·d_y) + I_2z·d_z (glam 0.30's `transform_point3` adds each axis's
/// term to the sum so far, `mul_vec3` the sum so far to each axis's term; IEEE addition
/// commutes exactly).
struct ColumnIndex {
    /// Y·c.y + X·c.x.
    xy: DVec3,
    /// `to_file`'s Z and W columns.
    z: DVec3,
    w: DVec3,
    /// The lattice's origin.
    origin: DVec3,
    /// I_0z, I_1z, I_2z.
    row: DVec3,
    /// The grid's min.z and voxel size v.z.
    min_z: f64,
    step_z: f64,
}

impl ColumnIndex {
    fn new(columns: &DatasetColumns, x: usize, y: usize) -> ColumnIndex {
        let (m, i) = (columns.to_file, columns.data.inverse());
        let c = columns.grid.centre(x, y, 0);
        ColumnIndex {
            xy: m.y_axis.truncate() * c.y + m.x_axis.truncate() * c.x,
            z: m.z_axis.truncate(),
            w: m.w_axis.truncate(),
            origin: columns.data.nrrd.origin,
            row: DVec3::new(i.x_axis.z, i.y_axis.z, i.z_axis.z),
            min_z: columns.grid.min.z,
            step_z: columns.grid.voxel().z,
        }
    }

    /// Voxel k's index z.
    fn at(&self, k: usize) -> f64 {
        let cz = self.min_z + (k as f64 + 0.5) * self.step_z;
        let d = (self.w + (self.z * cz + self.xy)) - self.origin;
        (self.row.x * d.x + self.row.y * d.y) + self.row.z * d.z
    }
}

/// One column walked a lattice cell at a time.
struct Walk<'c, 'a> {
    columns: &'c DatasetColumns<'a>,
    index: ColumnIndex,
    column: &'c Column,
    /// [`ColumnMap`]'s direction.
    dir: i64,
    /// The dataset's z size.
    n: usize,
    /// Index z at k = 0 and its mean step per voxel: guesses only.
    start: f64,
    slope: f64,
}

impl Walk<'_, '_> {
    /// Voxel k's z-cell ([`cell`], exactly as [`Dataset::sample`] finds it) and its place
    /// along the lattice: the cell's first plane, −1 before plane 0, n past the last.
    fn position(&self, k: usize) -> (i64, Option<Cell>) {
        let qz = self.index.at(k);
        match cell(qz, self.n) {
            Some(c) => (c.0 as i64, Some(c)),
            // Index z is finite along the column: outside is below or above.
            None if qz < 0.0 => (-1, None),
            None => (self.n as i64, None),
        }
    }

    /// [`Walk::position`] oriented to never decrease as k grows.
    fn key(&self, k: usize) -> i64 {
        self.dir * self.position(k).0
    }

    /// The voxel where the line through index z's ends reaches index z `q`: a guess.
    fn guess(&self, q: f64) -> usize {
        let k = ((q - self.start) / self.slope).ceil();
        if k.is_finite() && k > 0.0 {
            k.min(usize::MAX as f64) as usize
        } else {
            0
        }
    }

    /// The runs of the column, appended to `out`.
    fn runs(&self, out: &mut Vec<(u32, u32)>) {
        let (nz, n) = (self.columns.grid.dims[2], self.n as i64);
        let start = out.len();
        // The lattice is entered at index z 0 going up, at its last plane going down.
        let (before, entry) = match self.dir > 0 {
            true => (-1, 0.0),
            false => (-n, (n - 1) as f64),
        };
        let mut k = first_true(0..nz, self.guess(entry), |k| self.key(k) > before);
        while k < nz {
            let (z0, Some(c)) = self.position(k) else {
                break; // past the lattice: index z does not come back
            };
            let (a, b) = (self.column.plane(c.0), self.column.plane(c.1));
            k = match side(a, b, self.columns.threshold) {
                Some(inside) => {
                    let end = self.cell_end(k, self.same_side(z0, inside));
                    if inside {
                        push_run(out, start, k, end - 1);
                    }
                    end
                }
                None => {
                    let end = self.cell_end(k, z0);
                    self.crossing(k..end, z0, (a, b), out, start);
                    end
                }
            };
        }
    }

    /// The last z-cell (first plane) from cell `z0` on, the column's way, before a cell whose
    /// planes are not all on side `inside` ([`side`]): the voxels of those cells, consecutive
    /// (index z is monotone), all take that side, and one search finds where they end.
    fn same_side(&self, z0: i64, inside: bool) -> i64 {
        let top = self.n.saturating_sub(2) as i64; // the last cell's first plane
        let mut last = z0;
        while (0..=top).contains(&(last + self.dir)) {
            let next = (last + self.dir) as usize;
            let (a, b) = (self.column.plane(next), self.column.plane(next + 1));
            if side(a, b, self.columns.threshold) != Some(inside) {
                break;
            }
            last = next as i64;
        }
        last
    }

    /// The voxel after the last of z-cell `z0` (plane), voxel `k` being in it or in a cell
    /// before: where index z reaches the next cell's plane.
    fn cell_end(&self, k: usize, z0: i64) -> usize {
        let next = (z0 + i64::from(self.dir > 0)) as f64;
        let key = self.dir * z0;
        let nz = self.columns.grid.dims[2];
        first_true(k + 1..nz, self.guess(next), |j| self.key(j) > key)
    }

    /// Voxel k's value as [`Dataset::sample`] gives it (NaN outside the lattice, which
    /// `voxels` of one cell never are).
    fn value(&self, k: usize) -> f64 {
        self.position(k)
            .1
            .map_or(f64::NAN, |c| self.column.value_in(c))
    }

    /// Voxels `voxels` evaluated one by one, their runs appended to `out[start..]`.
    fn each(&self, voxels: Range<usize>, out: &mut Vec<(u32, u32)>, start: usize) {
        for k in voxels {
            if self.value(k) >= self.columns.threshold {
                push_run(out, start, k, k);
            }
        }
    }

    /// The runs of `voxels`, all of z-cell `z0` (plane), whose plane values `a`, `b` are not
    /// clear of the threshold ([`side`]): a few voxels evaluated, the rest filled by side.
    ///
    /// Within the cell the value is v(t) = `lerp(a, b, t)`, t = index z − z0 from [`cell`],
    /// and t is monotone in k (index z is, rounding is, and z0 is fixed). The exact
    /// g(t) = (1 − t)·a + t·b is linear, so for voxels i ≤ j ≤ l, g(t_j) lies between g(t_i)
    /// and g(t_l). [`side`]'s argument gives |v(t) − g(t)| ≤ δ = 4.1·ε·M + 3·2⁻¹⁰⁷⁵,
    /// M = max(|a|, |b|) (ε = 2⁻⁵³), and v = a at t = 0, b at t = 1, exactly. Hence, if two
    /// values x = v(t_i) and y = v(t_l) (or a plane value for t = 0, 1) are both more than
    /// 2δ below the threshold, every voxel with t between t_i and t_l has v < threshold:
    /// outside; both more than 2δ above: inside. [`clear`] decides that with margin
    /// 8·`f64::EPSILON`·M + `f64::MIN_POSITIVE` = 16·ε·M + 2⁻¹⁰²², near twice 2δ, which also
    /// covers the rounding of its differences and of the margin itself.
    ///
    /// So: the voxels from the first to the last one found clear together with the plane the
    /// column enters the cell by (a search near where g reaches the threshold) take that
    /// side; the voxels from the first found clear with the plane it leaves by, to the end,
    /// take that one; the voxels between, where v may wiggle around the threshold, are
    /// evaluated one by one. Every voxel is thus either evaluated or covered by a [`clear`]
    /// verdict on values actually computed: exact whatever the searches find (they only
    /// assume the verdicts monotone for speed). Planes not finite: all one by one.
    fn crossing(
        &self,
        voxels: Range<usize>,
        z0: i64,
        (a, b): (f64, f64),
        out: &mut Vec<(u32, u32)>,
        start: usize,
    ) {
        if !(a.is_finite() && b.is_finite()) || voxels.len() <= SHORT_CELL {
            return self.each(voxels, out, start);
        }
        let threshold = self.columns.threshold;
        let margin = 8.0 * f64::EPSILON * a.abs().max(b.abs()) + f64::MIN_POSITIVE;
        let (enter, leave) = if self.dir > 0 { (a, b) } else { (b, a) };
        // Where the exact g reaches the threshold: a guess for both searches.
        let guess = self.guess(z0 as f64 + (threshold - a) / (b - a));
        let clear_with = |plane: f64| move |v: f64| clear(plane, v, threshold, margin);
        let head = self.last_clear(voxels.clone(), guess, clear_with(enter));
        let from = match head {
            Some((j, inside)) => {
                if inside {
                    push_run(out, start, voxels.start, j);
                }
                j + 1
            }
            None => voxels.start,
        };
        let tail = self.first_clear(from..voxels.end, guess, clear_with(leave));
        self.each(from..tail.map_or(voxels.end, |(j, _)| j), out, start);
        if let Some((j, true)) = tail {
            push_run(out, start, j, voxels.end - 1);
        }
    }

    /// The last voxel of `voxels` found by a search from `guess` whose value `verdict` finds
    /// clear of the threshold, and its side; `None` when none was found.
    fn last_clear(
        &self,
        voxels: Range<usize>,
        guess: usize,
        verdict: impl Fn(f64) -> Option<bool>,
    ) -> Option<(usize, bool)> {
        self.clear_end(voxels, guess, verdict, false)
    }

    /// The first voxel of `voxels` found by a search from `guess` whose value `verdict` finds
    /// clear of the threshold, and its side; `None` when none was found.
    fn first_clear(
        &self,
        voxels: Range<usize>,
        guess: usize,
        verdict: impl Fn(f64) -> Option<bool>,
    ) -> Option<(usize, bool)> {
        self.clear_end(voxels, guess, verdict, true)
    }

    /// [`Walk::first_clear`] (`first`) or [`Walk::last_clear`]: the search's predicate is
    /// "clear" for the first such voxel, "not clear" past the last one; the extreme voxel
    /// found clear is kept.
    fn clear_end(
        &self,
        voxels: Range<usize>,
        guess: usize,
        verdict: impl Fn(f64) -> Option<bool>,
        first: bool,
    ) -> Option<(usize, bool)> {
        let found = std::cell::Cell::new(None);
        first_true(voxels, guess, |j| match verdict(self.value(j)) {
            Some(inside) => {
                if found.get().is_none_or(|(f, _)| (j < f) == first) {
                    found.set(Some((j, inside)));
                }
                first
            }
            None => !first,
        });
        found.get()
    }
}

/// Crossing cells of at most this many voxels are evaluated voxel by voxel: their searches
/// would cost about as much.
const SHORT_CELL: usize = 6;

/// Whether every value the last interpolation step can give between plane values `a` and
/// `b`, `lerp(a, b, t)` = fl(fl(fl(1 − t)·a) + fl(t·b)) for t in [0, 1], is at or above
/// `threshold` (`Some(true)`) or below it (`Some(false)`); `None` when that is not certain.
///
/// With u = fl(1 − t) in [0, 1], |u − (1 − t)| ≤ ε (ε = 2⁻⁵³, unit roundoff) and
/// M = max(|a|, |b|): u·a + t·b lies within ε·M of (1 − t)·a + t·b, which lies in
/// [min(a, b), max(a, b)]; the two products and the sum each add a relative error of at most
/// ε, at most ε·(u·|a| + t·|b|)·(2 + ε) + 3·2⁻¹⁰⁷⁵ (subnormal results) in all, u + t ≤ 1 + ε.
/// So the rounded value is within 4.1·ε·M + 3·2⁻¹⁰⁷⁵ of [min(a, b), max(a, b)]. The margin,
/// 4·`f64::EPSILON`·M + `f64::MIN_POSITIVE` = 8·ε·M + 2⁻¹⁰²², is over twice that, which also
/// covers the rounding of the differences compared with it.
fn side(a: f64, b: f64, threshold: f64) -> Option<bool> {
    let margin = 4.0 * f64::EPSILON * a.abs().max(b.abs()) + f64::MIN_POSITIVE;
    clear(a, b, threshold, margin)
}

/// Whether `x` and `y` are both more than `margin` at or above `threshold` (`Some(true)`)
/// or below it (`Some(false)`), by computed differences; `None` otherwise, or when either is
/// not finite.
fn clear(x: f64, y: f64, threshold: f64, margin: f64) -> Option<bool> {
    if !(x.is_finite() && y.is_finite()) {
        return None;
    }
    if threshold - x.max(y) > margin {
        Some(false)
    } else if x.min(y) - threshold > margin {
        Some(true)
    } else {
        None
    }
}

/// The first index of `range` where `pred` holds (`range.end` when none does), for a `pred`
/// that, once true, stays true over `range`: tried next to `guess` first, then in steps
/// doubling away from it, then by halving.
pub fn first_true(range: Range<usize>, guess: usize, pred: impl Fn(usize) -> bool) -> usize {
    // The answer is in lo..=hi throughout.
    let (mut lo, mut hi) = (range.start, range.end.max(range.start));
    let g = guess.clamp(lo, hi);
    let mut step = 1;
    if g == hi || pred(g) {
        hi = g;
        while lo < hi {
            let m = hi.saturating_sub(step).max(lo);
            if !pred(m) {
                lo = m + 1;
                break;
            }
            hi = m;
            step *= 2;
        }
    } else {
        lo = g + 1;
        while lo < hi {
            let m = (lo + step - 1).min(hi - 1);
            if pred(m) {
                hi = m;
                break;
            }
            lo = m + 1;
            step *= 2;
        }
    }
    while lo < hi {
        let m = lo + (hi - lo) / 2;
        if pred(m) {
            hi = m;
        } else {
            lo = m + 1;
        }
    }
    lo
}

/// Add slabs `first..=last` to the runs `out[start..]`, joining the last when they touch.
fn push_run(out: &mut Vec<(u32, u32)>, start: usize, first: usize, last: usize) {
    match out[start..].last_mut() {
        Some(r) if r.1 as usize + 1 == first => r.1 = last as u32,
        _ => out.push((first as u32, last as u32)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`ColumnIndex::at`] gives [`DatasetColumns::index`]'s index z bit for bit, on
    /// placements with scales, swaps and translations of every kind and grids of any origin.
    #[test]
    fn column_index_is_the_voxels_index_to_the_bit() {
        use csgpix_scene::nrrd::{Nrrd, SampleType};
        use glam::DVec4;
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let mut compared = 0;
        for _ in 0..200 {
            // Index z may lean on file x and y (I_0z, I_1z), never index x or y on file z.
            let inverse = DMat3::from_cols(
                DVec3::new(next(), 0.0, next()),
                DVec3::new(0.0, next(), next()),
                DVec3::new(0.0, 0.0, next()),
            ) * 3.0;
            let origin = DVec3::new(next(), next(), next()) * 10.0;
            let steps = inverse.inverse();
            let nrrd = Nrrd::new([3, 4, 5], vec![0.0; 60], origin, steps, SampleType::Uint8);
            let Ok(data) = Dataset::new(nrrd.unwrap()) else {
                continue;
            };
            // Scene x and y reach every file axis; scene z file z alone.
            let mut r = [0.0; 10];
            r.iter_mut().for_each(|v| *v = next() * 2.0);
            let to_file = DMat4::from_cols(
                DVec4::new(r[0], r[1], r[2], 0.0),
                DVec4::new(r[3], r[4], r[5], 0.0),
                DVec4::new(0.0, 0.0, r[6], 0.0),
                DVec4::new(r[7], r[8], r[9], 1.0) * DVec4::new(4.0, 4.0, 4.0, 1.0),
            );
            let s = Sampled {
                shape: Shape::Dataset {
                    data: Box::new(data),
                    threshold: 0.5,
                    to_file,
                },
                colour: 1,
                file: "t.nrrd".into(),
            };
            let lo = DVec3::new(next(), next(), next()) * 9.0;
            let hi = lo + DVec3::new(next().abs(), next().abs(), next().abs()) * 20.0 + 0.1;
            let grid = Grid::new([7, 5, 33], lo, hi).unwrap();
            let columns = DatasetColumns::new(&s, &grid).unwrap();
            for (x, y) in [(0, 0), (3, 2), (6, 4)] {
                let index = ColumnIndex::new(&columns, x, y);
                for k in 0..33 {
                    let want = columns.index(x, y, k).z;
                    assert_eq!(
                        index.at(k).to_bits(),
                        want.to_bits(),
                        "voxel ({x}, {y}, {k})"
                    );
                    compared += 1;
                }
            }
        }
        assert!(compared > 10_000, "{compared} voxels compared");
    }

    #[test]
    fn first_true_finds_every_boundary_from_every_guess() {
        for len in 0..40 {
            for start in [0, 3] {
                let range = start..start + len;
                for answer in range.start..=range.end {
                    for guess in 0..start + len + 3 {
                        let calls = std::cell::Cell::new(0);
                        let pred = |i: usize| {
                            assert!(range.contains(&i), "probed {i} outside {range:?}");
                            calls.set(calls.get() + 1);
                            i >= answer
                        };
                        assert_eq!(first_true(range.clone(), guess, pred), answer);
                        if guess == answer && answer > start && answer < start + len {
                            assert_eq!(calls.get(), 2, "a right guess costs two probes");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn side_is_certain_only_clear_of_the_threshold() {
        assert_eq!(side(0.0, 100.0, 300.0), Some(false));
        assert_eq!(side(400.0, 1000.0, 300.0), Some(true));
        assert_eq!(side(200.0, 400.0, 300.0), None);
        assert_eq!(side(300.0, 400.0, 300.0), None, "a value on the threshold");
        assert_eq!(side(f64::NAN, 400.0, 300.0), None);
        let below = 300.0 - 2.0 * 300.0 * f64::EPSILON;
        assert_eq!(side(below, below, 300.0), None, "within the margin");
        // Exhaustive over t on a fine grid: what side promises, lerp keeps.
        let lerp = csgpix_scene::dataset::lerp;
        let near = [
            300.0 - 1e-12,
            300.0 * (1.0 + 1e-14),
            299.0,
            301.0,
            1e-300,
            -5.0,
        ];
        for &a in &near {
            for &b in &near {
                let Some(inside) = side(a, b, 300.0) else {
                    continue;
                };
                for i in 0..=1000 {
                    let t = i as f64 / 1000.0;
                    assert_eq!(lerp(a, b, t) >= 300.0, inside, "{a} {b} {t}");
                }
            }
        }
    }

    fn to_file(z: DVec3) -> DMat4 {
        let mut m = DMat4::from_scale(DVec3::new(2.0, -3.0, 0.5));
        m.w_axis = glam::DVec4::new(1.0, 2.0, 3.0, 1.0);
        m.z_axis = z.extend(0.0);
        m
    }

    #[test]
    fn column_map_needs_index_x_and_y_off_scene_z() {
        let grid = Grid::new([4, 4, 4], DVec3::ZERO, DVec3::ONE).unwrap();
        let diag = DMat3::from_diagonal(DVec3::new(0.5, 2.0, -0.25));
        let up = ColumnMap::of(&grid, &to_file(DVec3::Z), &DMat3::IDENTITY);
        assert_eq!(up, Some(ColumnMap { dir: 1 }));
        let down = ColumnMap::of(&grid, &to_file(DVec3::Z), &diag);
        assert_eq!(down, Some(ColumnMap { dir: -1 }));
        // -0.0 entries are zeros too.
        let signed = ColumnMap::of(&grid, &to_file(DVec3::new(-0.0, 0.0, 2.0)), &diag);
        assert_eq!(signed, Some(ColumnMap { dir: -1 }));
        // Scene z into file x: fine if index x and y do not read file x.
        let perm = DMat3::from_cols(DVec3::Z, DVec3::X, DVec3::Y);
        let swapped = ColumnMap::of(&grid, &to_file(DVec3::X), &perm);
        assert_eq!(swapped, Some(ColumnMap { dir: 1 }));
        assert_eq!(ColumnMap::of(&grid, &to_file(DVec3::X), &diag), None);
        // Any trace of scene z in file x or y, of file z in index x or y: voxel by voxel.
        let tilt = DVec3::new(1e-300, 0.0, 1.0);
        assert_eq!(ColumnMap::of(&grid, &to_file(tilt), &diag), None);
        let mut skew = diag;
        skew.z_axis.y = -1e-17;
        assert_eq!(ColumnMap::of(&grid, &to_file(DVec3::Z), &skew), None);
        // Both file x and z moving, index z reading them with opposite signs: not one way.
        // (Singular steps: an invertible inverse cannot keep two moving axes off index x, y.)
        let two = to_file(DVec3::new(1.0, 0.0, 1.0));
        let xy = DVec3::new(1.0, 1.0, 0.0);
        let mixed = DMat3::from_cols(DVec3::Z, xy, -DVec3::Z);
        assert_eq!(ColumnMap::of(&grid, &two, &mixed), None);
        let same = DMat3::from_cols(DVec3::Z, xy, DVec3::Z);
        assert_eq!(
            ColumnMap::of(&grid, &two, &same),
            Some(ColumnMap { dir: 1 })
        );
        let into_x = DMat3::from_cols(DVec3::X, xy, DVec3::Z);
        assert_eq!(
            ColumnMap::of(&grid, &two, &into_x),
            None,
            "file x feeds index x"
        );
        // Not finite.
        let mut inf = to_file(DVec3::Z);
        inf.w_axis.x = f64::INFINITY;
        assert_eq!(ColumnMap::of(&grid, &inf, &diag), None);
        assert_eq!(
            ColumnMap::of(&grid, &to_file(DVec3::Z), &(diag * f64::NAN)),
            None
        );
        let huge = Grid::new([4, 4, 4], DVec3::splat(-1e308), DVec3::splat(1e308)).unwrap();
        assert_eq!(ColumnMap::of(&huge, &to_file(DVec3::Z), &diag), None);
        // Scene z moving nothing: index z is fixed, one way.
        let flat = ColumnMap::of(&grid, &to_file(DVec3::ZERO), &diag);
        assert_eq!(flat, Some(ColumnMap { dir: 1 }));
    }
}
