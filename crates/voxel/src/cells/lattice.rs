//! A dataset as the walk classifies it: the range of its trilinear interpolant over a box
//! of voxel centres (exact over a few cells, bounded by blocks of samples over more), and
//! its samples at the voxel centres themselves.

use super::*;

/// One level of a dataset's blocks: each block's least and greatest sample, and how many
/// blocks there are along each axis.
type Blocks = (Vec<(f32, f32)>, [usize; 3]);

/// A dataset seen from voxel coordinates.
pub(super) struct Lattice<'a> {
    /// Voxel coordinates → continuous lattice index: `a·v + b`.
    a: DMat3,
    abs_a: DMat3,
    b: DVec3,
    data: &'a Dataset,
    threshold: f64,
    eps: f64,
    /// Under `--blend` a voxel inside takes the dataset's grey value, which varies: only
    /// outside is known.
    graded: bool,
    /// Least and greatest sample of blocks of 4^… cells: `mip[m]` has blocks of 2^(m + 2)
    /// cells a side, `dims[m]` of them.
    mip: Vec<Blocks>,
}

/// Cells a range is read over piece by piece (the exact range of the interpolant) before
/// their samples bound it.
const PIECES: usize = 27;

/// Cells whose samples a range reads before blocks of samples bound it.
const SAMPLES: usize = 512;

impl<'a> Lattice<'a> {
    pub(super) fn new(
        a: DMat3,
        b: DVec3,
        data: &'a Dataset,
        threshold: f64,
        graded: bool,
    ) -> Lattice<'a> {
        let abs_a = DMat3::from_cols(a.x_axis.abs(), a.y_axis.abs(), a.z_axis.abs());
        let (lo, hi) = data.nrrd.range;
        let scale = 1.0 + f64::from(lo).abs().max(f64::from(hi).abs()) + threshold.abs();
        let mut l = Lattice {
            a,
            abs_a,
            b,
            data,
            threshold,
            eps: 1e-9 * scale,
            graded,
            mip: vec![],
        };
        l.build_mip();
        l
    }

    /// Cells along each axis (a lattice of one sample along an axis has one cell there).
    fn cells(&self) -> [usize; 3] {
        self.data.nrrd.sizes.map(|n| n.saturating_sub(1).max(1))
    }

    fn at(&self, i: usize, j: usize, k: usize) -> f64 {
        f64::from(self.data.nrrd.at(i, j, k))
    }

    fn build_mip(&mut self) {
        let cells = self.cells();
        let sizes = self.data.nrrd.sizes;
        // Blocks of 4 cells: their samples read once (the samples on a block's faces twice).
        let dims = cells.map(|c| c.div_ceil(4));
        let mut first = Vec::with_capacity(dims.iter().product());
        for bz in 0..dims[2] {
            for by in 0..dims[1] {
                for bx in 0..dims[0] {
                    let b = [bx, by, bz];
                    let r = |a: usize| 4 * b[a]..=(4 * b[a] + 4).min(sizes[a] - 1);
                    let (mut mn, mut mx) = (f32::INFINITY, f32::NEG_INFINITY);
                    for k in r(2) {
                        for j in r(1) {
                            for i in r(0) {
                                let v = self.data.nrrd.at(i, j, k);
                                (mn, mx) = (mn.min(v), mx.max(v));
                            }
                        }
                    }
                    first.push((mn, mx));
                }
            }
        }
        self.mip.push((first, dims));
        while self
            .mip
            .last()
            .is_some_and(|(_, d)| d.iter().any(|&n| n > 1))
        {
            let (below, d) = self.mip.last().expect("a level");
            let dims = d.map(|n| n.div_ceil(2));
            let mut up = Vec::with_capacity(dims.iter().product());
            for bz in 0..dims[2] {
                for by in 0..dims[1] {
                    for bx in 0..dims[0] {
                        let (mut mn, mut mx) = (f32::INFINITY, f32::NEG_INFINITY);
                        for c in 0..8 {
                            let q = [2 * bx + (c & 1), 2 * by + (c >> 1 & 1), 2 * bz + (c >> 2)];
                            if (0..3).all(|a| q[a] < d[a]) {
                                let (lo, hi) = below[(q[2] * d[1] + q[1]) * d[0] + q[0]];
                                (mn, mx) = (mn.min(lo), mx.max(hi));
                            }
                        }
                        up.push((mn, mx));
                    }
                }
            }
            self.mip.push((up, dims));
        }
    }

    /// The trilinear value at index point q, inside the lattice cell `c` (lower corner).
    fn trilinear(&self, c: [usize; 3], q: DVec3) -> f64 {
        let sizes = self.data.nrrd.sizes;
        let hi = |a: usize| (c[a] + 1).min(sizes[a] - 1);
        let t = |a: usize| (q[a] - c[a] as f64).clamp(0.0, 1.0);
        let (tx, ty, tz) = (t(0), t(1), t(2));
        let l = |a: f64, b: f64, t: f64| (1.0 - t) * a + t * b;
        let row = |j, k| l(self.at(c[0], j, k), self.at(hi(0), j, k), tx);
        let plane = |k| l(row(c[1], k), row(hi(1), k), ty);
        l(plane(c[2]), plane(hi(2)), tz)
    }

    /// The least and greatest value over the index box [lo, hi] (inside the lattice): exact
    /// over a few cells (the interpolant is multilinear in each, its extremes at the corners
    /// of the box's piece there), else bounded by the samples of blocks covering the box.
    fn range(&self, lo: DVec3, hi: DVec3) -> (f64, f64) {
        let cells = self.cells();
        let cell = |a: usize, q: f64| (q.floor().max(0.0) as usize).min(cells[a] - 1);
        let c0 = [0, 1, 2].map(|a| cell(a, lo[a]));
        // A box ending on a lattice plane stays in the cell below it.
        let c1 =
            [0, 1, 2].map(|a| ((hi[a].ceil() - 1.0).max(0.0) as usize).clamp(c0[a], cells[a] - 1));
        let n: usize = (0..3).map(|a| c1[a] - c0[a] + 1).product();
        let (mut mn, mut mx) = (f64::INFINITY, f64::NEG_INFINITY);
        if n <= PIECES {
            for z in c0[2]..=c1[2] {
                for y in c0[1]..=c1[1] {
                    for x in c0[0]..=c1[0] {
                        let c = [x, y, z];
                        let plo = DVec3::from(c.map(|v| v as f64)).max(lo);
                        let phi = DVec3::from(c.map(|v| v as f64 + 1.0)).min(hi).max(plo);
                        for k in 0..8 {
                            let q = DVec3::new(
                                if k & 1 == 0 { plo.x } else { phi.x },
                                if k & 2 == 0 { plo.y } else { phi.y },
                                if k & 4 == 0 { plo.z } else { phi.z },
                            );
                            let v = self.trilinear(c, q);
                            (mn, mx) = (mn.min(v), mx.max(v));
                        }
                    }
                }
            }
            return (mn, mx);
        }
        if n <= SAMPLES {
            let top = self.data.nrrd.sizes.map(|s| s - 1);
            for z in c0[2]..=(c1[2] + 1).min(top[2]) {
                for y in c0[1]..=(c1[1] + 1).min(top[1]) {
                    for x in c0[0]..=(c1[0] + 1).min(top[0]) {
                        let v = self.at(x, y, z);
                        (mn, mx) = (mn.min(v), mx.max(v));
                    }
                }
            }
            return (mn, mx);
        }
        // The first level whose blocks the box spans at most two of along each axis.
        let mut m = 0;
        while m + 1 < self.mip.len() && (0..3).any(|a| (c1[a] >> (m + 2)) - (c0[a] >> (m + 2)) > 1)
        {
            m += 1;
        }
        let (blocks, d) = &self.mip[m];
        let b0 = c0.map(|c| c >> (m + 2));
        let b1 = [0, 1, 2].map(|a| (c1[a] >> (m + 2)).min(d[a] - 1));
        for z in b0[2]..=b1[2] {
            for y in b0[1]..=b1[1] {
                for x in b0[0]..=b1[0] {
                    let (lo, hi) = blocks[(z * d[1] + y) * d[0] + x];
                    (mn, mx) = (mn.min(f64::from(lo)), mx.max(f64::from(hi)));
                }
            }
        }
        (mn, mx)
    }

    /// A dataset voxel is filled when the sample at its centre is at or above the threshold:
    /// filled, empty, or too close to tell (or past the lattice by its tolerance).
    fn point(&self, v: DVec3) -> Class {
        let q = self.a * v + self.b;
        let [nx, ny, nz] = self.data.nrrd.sizes;
        let tol = 1e-6;
        let (Some(x), Some(y), Some(z)) = (cell(q.x, nx), cell(q.y, ny), cell(q.z, nz)) else {
            let top = DVec3::from(self.data.nrrd.sizes.map(|n| (n - 1) as f64));
            let far = (0..3).any(|a| q[a] < -tol || q[a] > top[a] + tol);
            return if far { Class::Out } else { Class::Mixed };
        };
        let c = [x.0, y.0, z.0];
        let v = self.trilinear(c, q);
        let near = (0..3).any(|a| {
            let top = (self.data.nrrd.sizes[a] - 1) as f64;
            q[a] < tol || q[a] > top - tol
        });
        if v < self.threshold - self.eps {
            Class::Out
        } else if v >= self.threshold + self.eps && !near {
            Class::In
        } else {
            Class::Mixed
        }
    }

    pub(super) fn classify(&self, c: DVec3, h: DVec3) -> Class {
        match self.membership(c, h) {
            Class::In if self.graded => Class::Mixed,
            c => c,
        }
    }

    /// Whether the voxel centres of the box (centre c, half sizes h) are inside.
    fn membership(&self, c: DVec3, h: DVec3) -> Class {
        // A node of up to 3 voxels a side: its voxel centres one by one.
        if h.max_element() <= 1.0 {
            let n = [h.x, h.y, h.z].map(|x| x.round() as i64);
            let mut seen = None;
            for k in -n[2]..=n[2] {
                for j in -n[1]..=n[1] {
                    for i in -n[0]..=n[0] {
                        let v = c + DVec3::new(i as f64, j as f64, k as f64);
                        let p = self.point(v);
                        match (seen, p) {
                            (_, Class::Mixed) => return Class::Mixed,
                            (None, p) => seen = Some(p),
                            (Some(s), p) if s != p => return Class::Mixed,
                            _ => {}
                        }
                    }
                }
            }
            return seen.unwrap_or(Class::Out);
        }
        let ci = self.a * c + self.b;
        let hi = self.abs_a * h + DVec3::splat(1e-9);
        let (lo, hi) = (ci - hi, ci + hi);
        let tol = csgpix_scene::dataset::INDEX_TOLERANCE;
        let top = DVec3::from(self.data.nrrd.sizes.map(|n| (n - 1) as f64));
        if (0..3).any(|a| lo[a] > top[a] + tol || hi[a] < -tol) {
            return Class::Out;
        }
        let partial = (0..3).any(|a| lo[a] < -tol || hi[a] > top[a] + tol);
        let (lo, hi) = (lo.clamp(DVec3::ZERO, top), hi.clamp(DVec3::ZERO, top));
        let (mn, mx) = self.range(lo, hi);
        if mx < self.threshold - self.eps {
            Class::Out
        } else if !partial && mn >= self.threshold + self.eps {
            Class::In
        } else {
            Class::Mixed
        }
    }
}
