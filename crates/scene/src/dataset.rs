//! Volumetric DATASET primitives (§3.3, Figure 3.1; §5.4, Figure 5.6): a sampled scalar
//! volume such as a CT head, placed in the scene by its NRRD geometry and sampled
//! trilinearly, plus [`phantom`], a CT-head-like test volume the project makes itself.
//!
//! A sample lattice point (i, j, k) lies at `origin + directions · (i, j, k)` in the scene
//! (NRRD format spec, §4 "space origin" and "space directions"); between lattice points the
//! volume is interpolated trilinearly, outside the lattice it is undefined.

use glam::{DMat3, DVec3};

use crate::nrrd::{invertible, Nrrd, SampleType};
pub use crate::nrrd::{write_nrrd, Encoding};
use crate::{Error, Result};

/// Lattice tolerance, in index units: points this close outside the lattice still sample.
pub const INDEX_TOLERANCE: f64 = 1e-9;

/// A volume ready to sample: the NRRD and the inverse of its axis steps.
#[derive(Clone, Debug, PartialEq)]
pub struct Dataset {
    /// The volume and its lattice.
    pub nrrd: Nrrd,
    inverse: DMat3,
}

impl Dataset {
    /// The dataset of `nrrd`, whose axis steps must span 3D (be invertible) and whose
    /// samples must fill its sizes.
    pub fn new(nrrd: Nrrd) -> Result<Dataset> {
        let count = nrrd.sizes.iter().try_fold(1usize, |a, &n| a.checked_mul(n));
        if count != Some(nrrd.samples.len()) || nrrd.samples.is_empty() {
            let e = Error::SampleCount {
                samples: nrrd.samples.len(),
                sizes: nrrd.sizes,
            };
            return Err(e.context("dataset"));
        }
        if !invertible(&nrrd.directions) || !nrrd.origin.is_finite() {
            let e = Error::Expected {
                expected: "a finite origin and 3 independent axis steps".into(),
                found: format!("{:?}", nrrd.directions),
            };
            return Err(e.context("dataset"));
        }
        let inverse = nrrd.directions.inverse();
        Ok(Dataset { nrrd, inverse })
    }

    /// The inverse of the axis steps: scene offsets from the origin → index coordinates.
    pub fn inverse(&self) -> &DMat3 {
        &self.inverse
    }

    /// The continuous index coordinates of scene point `p`.
    pub fn index_of(&self, p: DVec3) -> DVec3 {
        self.inverse * (p - self.nrrd.origin)
    }

    /// The trilinearly interpolated value at scene point `p`; `None` outside the lattice
    /// (index coordinate below 0 or above size − 1 on some axis, past [`INDEX_TOLERANCE`]).
    /// On a size-1 axis only that index plane samples.
    pub fn sample(&self, p: DVec3) -> Option<f64> {
        let q = self.index_of(p);
        let [nx, ny, nz] = self.nrrd.sizes;
        let (xc, yc) = (cell(q.x, nx)?, cell(q.y, ny)?);
        let (z0, z1, tz) = cell(q.z, nz)?;
        Some(lerp(self.plane(xc, yc, z0), self.plane(xc, yc, z1), tz))
    }

    /// The value interpolated in x, then y, at lattice z-plane `k`, for the x and y cells
    /// of [`cell`]: the two inner steps of [`Dataset::sample`]'s trilinear interpolation.
    fn plane(&self, (x0, x1, tx): Cell, (y0, y1, ty): Cell, k: usize) -> f64 {
        let v = |i, j| f64::from(self.nrrd.at(i, j, k));
        let row = |j| lerp(v(x0, j), v(x1, j), tx);
        lerp(row(y0), row(y1), ty)
    }

    /// The lattice column at index coordinates (`qx`, `qy`): every z-plane's value there,
    /// interpolated as [`Dataset::sample`] does; `None` outside the lattice in x or y.
    /// [`Column::value_at`] then gives `sample` at any index z of the column.
    pub fn column(&self, qx: f64, qy: f64) -> Option<Column> {
        let mut c = Column { planes: vec![] };
        self.fill_column(qx, qy, &mut c).then_some(c)
    }

    /// [`Dataset::column`] into `c`, reusing its storage; false (and `c` unchanged) outside
    /// the lattice.
    pub fn fill_column(&self, qx: f64, qy: f64, c: &mut Column) -> bool {
        let [nx, ny, nz] = self.nrrd.sizes;
        let (Some(xc), Some(yc)) = (cell(qx, nx), cell(qy, ny)) else {
            return false;
        };
        c.planes.clear();
        // `plane` at every k, its four samples found by offsets from plane 0 (the same
        // samples, the same operations).
        let [sx, sy, _] = self.nrrd.sizes;
        let ((x0, x1, tx), (y0, y1, ty)) = (xc, yc);
        let corners = [x0 + sx * y0, x1 + sx * y0, x0 + sx * y1, x1 + sx * y1];
        let planes = self.nrrd.samples.chunks_exact(sx * sy).take(nz);
        c.planes.extend(planes.map(|p| {
            let v = corners.map(|i| f64::from(p[i]));
            lerp(lerp(v[0], v[1], tx), lerp(v[2], v[3], tx), ty)
        }));
        true
    }

    /// The scene-space box around the lattice's 8 corners (sample centres, not voxel faces).
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let top = DVec3::from(self.nrrd.sizes.map(|n| (n - 1) as f64));
        (0..8)
            .map(|c| {
                let pick = DVec3::new((c & 1) as f64, ((c >> 1) & 1) as f64, (c >> 2) as f64);
                self.nrrd.origin + self.nrrd.directions * (pick * top)
            })
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p), hi.max(p))
            })
    }

    /// The voxel grey for value `v`: `range` mapped linearly onto 1..=255, clamped (255 when
    /// the range is one value). Never 0, which means empty.
    pub fn grey(&self, v: f64) -> u8 {
        let (lo, hi) = self.nrrd.range;
        let (lo, hi) = (f64::from(lo), f64::from(hi));
        if hi <= lo {
            return 255;
        }
        let t = ((v - lo) / (hi - lo)).clamp(0.0, 1.0);
        if t.is_nan() {
            return 1;
        }
        (1.0 + (t * 254.0).round()) as u8
    }
}

/// The values of one lattice column of a dataset at fixed index x and y: per lattice z-plane
/// the value interpolated in x and y ([`Dataset::column`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Column {
    planes: Vec<f64>,
}

impl Column {
    /// The value at lattice z-plane `k` (below the dataset's z size).
    pub fn plane(&self, k: usize) -> f64 {
        self.planes[k]
    }

    /// The value at index z `qz`, as [`Dataset::sample`] gives it at index (qx, qy, qz) (the
    /// same operations on the same values); `None` outside the lattice.
    pub fn value_at(&self, qz: f64) -> Option<f64> {
        cell(qz, self.planes.len()).map(|c| self.value_in(c))
    }

    /// The value in z-cell `(z0, z1, tz)` (from [`cell`]).
    pub fn value_in(&self, (z0, z1, tz): Cell) -> f64 {
        lerp(self.planes[z0], self.planes[z1], tz)
    }
}

/// A lattice cell on one axis: the two samples and the weight of the second ([`cell`]).
pub type Cell = (usize, usize, f64);

/// The lattice cell of index coordinate `q` on an axis of `n` samples: the two samples and
/// the weight of the second; `None` outside [0, n − 1].
pub fn cell(q: f64, n: usize) -> Option<Cell> {
    let top = (n - 1) as f64;
    if !(q >= -INDEX_TOLERANCE && q <= top + INDEX_TOLERANCE) {
        return None;
    }
    let q = q.clamp(0.0, top);
    // q ≥ 0 (or −0): truncation is its floor, without a call to libm's `floor` where the
    // target has no rounding instruction (x86-64 before SSE4.1).
    let i0 = (q as usize).min(n.saturating_sub(2));
    let i1 = (i0 + 1).min(n - 1);
    Some((i0, i1, q - i0 as f64))
}

/// `a` at t = 0, `b` at t = 1, exactly.
pub fn lerp(a: f64, b: f64, t: f64) -> f64 {
    (1.0 - t) * a + t * b
}

// --- The phantom -------------------------------------------------------------------------------

/// Skull bone, soft tissue, ventricle fluid and the dense inclusion, in CT-like units.
const SKULL: f64 = 1000.0;
const TISSUE: f64 = 400.0;
const VENTRICLE: f64 = 100.0;
const DENSE: f64 = 1200.0;

/// Half the phantom's box: it spans −10..10 scene units on each axis.
pub const PHANTOM_HALF: f64 = 10.0;

/// An ellipsoid: centre and radii, in scene units.
struct Ellipsoid {
    centre: DVec3,
    radii: DVec3,
}

impl Ellipsoid {
    const fn new(centre: [f64; 3], radii: [f64; 3]) -> Ellipsoid {
        Ellipsoid {
            centre: DVec3::from_array(centre),
            radii: DVec3::from_array(radii),
        }
    }

    /// How much of a sample at `p` lies inside: 1 inside, 0 outside, a linear ramp one
    /// sample step `h` wide across the surface. The signed distance is the first-order
    /// estimate (f − 1)/|∇f| of f = |(p − c)/r|, exact enough near the surface.
    fn fill(&self, p: DVec3, h: f64) -> f64 {
        let u = (p - self.centre) / self.radii;
        let f = u.length();
        if f == 0.0 {
            return 1.0;
        }
        let d = (f - 1.0) * f / (u / self.radii).length();
        (0.5 - d / h).clamp(0.0, 1.0)
    }
}

/// The head: skull outside and inside surfaces, the two ventricles, the dense sphere. X is
/// left–right, Y back–front, Z up.
const SKULL_OUT: Ellipsoid = Ellipsoid::new([0.0, 0.0, 0.0], [7.2, 9.0, 8.4]);
const SKULL_IN: Ellipsoid = Ellipsoid::new([0.0, 0.0, 0.0], [6.3, 8.1, 7.5]);
const VENTRICLES: [Ellipsoid; 2] = [
    Ellipsoid::new([-1.5, 0.8, 1.2], [0.9, 2.8, 1.5]),
    Ellipsoid::new([1.5, 0.8, 1.2], [0.9, 2.8, 1.5]),
];
const INCLUSION: Ellipsoid = Ellipsoid::new([0.0, -4.0, -2.0], [1.2, 1.2, 1.2]);

/// The phantom's value at scene point `p`, for sample step `h`.
fn head_value(p: DVec3, h: f64) -> f64 {
    let ventricles: f64 = VENTRICLES.iter().map(|e| e.fill(p, h)).sum();
    SKULL * SKULL_OUT.fill(p, h)
        + (TISSUE - SKULL) * SKULL_IN.fill(p, h)
        + (VENTRICLE - TISSUE) * ventricles
        + (DENSE - TISSUE) * INCLUSION.fill(p, h)
}

/// An n³ `uint16` CT-head phantom after the thesis's CT head (§5.4, Figure 5.6; §3.3,
/// Figure 3.1): an ellipsoidal skull shell (1000) around soft tissue (400) holding two
/// ventricle ellipsoids (100) and a small dense sphere (1200), 0 outside. Values are analytic
/// with a one-sample linear ramp across each surface, so trilinear sampling is smooth.
///
/// The samples are the centres of an n³ grid of cells over −10..10 on each axis: sample
/// (0, 0, 0) is at −10 + h/2 with step h = 20/n. `n` below 1 is taken as 1. Deterministic.
pub fn phantom(n: usize) -> Nrrd {
    let n = n.max(1);
    let h = 2.0 * PHANTOM_HALF / n as f64;
    let origin = DVec3::splat(-PHANTOM_HALF + h / 2.0);
    let mut samples = Vec::with_capacity(n * n * n);
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                let p = origin + h * DVec3::new(i as f64, j as f64, k as f64);
                samples.push(head_value(p, h).round().clamp(0.0, 65535.0) as f32);
            }
        }
    }
    let directions = DMat3::from_diagonal(DVec3::splat(h));
    // A CT head: its own frame is the patient's (right, anterior, superior).
    let mut nrrd = Nrrd::new([n; 3], samples, origin, directions, SampleType::Uint16)
        .expect("the phantom's samples fill its sizes and are finite");
    nrrd.space = Some("right-anterior-superior".into());
    nrrd
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nrrd::read_nrrd;

    /// Skewed, non-axis-aligned steps and an off-centre origin.
    fn skewed() -> (DVec3, DMat3) {
        let dirs = DMat3::from_cols(
            DVec3::new(0.8, 0.3, -0.2),
            DVec3::new(-0.25, 1.1, 0.4),
            DVec3::new(0.1, -0.3, 0.9),
        );
        (DVec3::new(1.5, -2.0, 0.25), dirs)
    }

    fn linear(q: DVec3) -> f64 {
        3.0 * q.x - 2.0 * q.y + 5.0 * q.z + 7.0
    }

    /// f = 3i − 2j + 5k + 7 on a 5×4×6 lattice, stored as float.
    fn linear_dataset() -> Dataset {
        let sizes = [5, 4, 6];
        let mut samples = Vec::new();
        for k in 0..6 {
            for j in 0..4 {
                for i in 0..5 {
                    samples.push(linear(DVec3::new(i as f64, j as f64, k as f64)) as f32);
                }
            }
        }
        let (origin, dirs) = skewed();
        Dataset::new(Nrrd::new(sizes, samples, origin, dirs, SampleType::Float).unwrap()).unwrap()
    }

    /// A deterministic stream of numbers in [0, 1).
    fn unit_stream() -> impl FnMut() -> f64 {
        let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
        move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    #[test]
    fn trilinear_reproduces_a_linear_field() {
        let d = linear_dataset();
        let mut r = unit_stream();
        for _ in 0..2000 {
            let q = DVec3::new(4.0 * r(), 3.0 * r(), 5.0 * r());
            let p = d.nrrd.origin + d.nrrd.directions * q;
            let v = d.sample(p).unwrap();
            assert!((v - linear(q)).abs() < 1e-9, "{q}: {v} vs {}", linear(q));
        }
    }

    #[test]
    fn a_column_samples_as_sample_does_bit_for_bit() {
        let (d, phantom) = (linear_dataset(), Dataset::new(phantom(7)).unwrap());
        let mut r = unit_stream();
        for d in [d, phantom] {
            let (lo, hi) = d.bounds();
            for _ in 0..3000 {
                // Some points outside, some on lattice planes.
                let mut p = lo + (hi - lo) * DVec3::new(r(), r(), r()) * 1.2 - (hi - lo) * 0.1;
                if r() < 0.2 {
                    p = d.nrrd.origin + d.nrrd.directions * (d.index_of(p)).round();
                }
                let q = d.index_of(p);
                let by_column = d.column(q.x, q.y).and_then(|c| c.value_at(q.z));
                let bits = |v: Option<f64>| v.map(f64::to_bits);
                assert_eq!(bits(by_column), bits(d.sample(p)), "{p}");
            }
        }
    }

    #[test]
    fn corners_sample_exactly_and_just_outside_is_none() {
        let d = linear_dataset();
        let top = DVec3::new(4.0, 3.0, 5.0);
        for c in 0..8 {
            let pick = DVec3::new((c & 1) as f64, ((c >> 1) & 1) as f64, (c >> 2) as f64);
            let q = pick * top;
            let p = d.nrrd.origin + d.nrrd.directions * q;
            let v = d.sample(p).unwrap();
            assert!((v - linear(q)).abs() < 1e-9, "corner {q}: {v}");
            for axis in 0..3 {
                let mut out = q;
                out[axis] += if pick[axis] == 0.0 { -1e-6 } else { 1e-6 };
                let p = d.nrrd.origin + d.nrrd.directions * out;
                assert_eq!(d.sample(p), None, "outside {out}");
            }
        }
        assert_eq!(d.sample(DVec3::NAN), None);
    }

    #[test]
    fn a_size_one_axis_samples_only_its_plane() {
        let n = Nrrd::new(
            [2, 1, 1],
            vec![10.0, 20.0],
            DVec3::ZERO,
            DMat3::IDENTITY,
            SampleType::Uint8,
        )
        .unwrap();
        let d = Dataset::new(n).unwrap();
        assert_eq!(d.sample(DVec3::new(0.5, 0.0, 0.0)), Some(15.0));
        assert_eq!(d.sample(DVec3::new(0.5, 1e-10, -1e-10)), Some(15.0));
        assert_eq!(d.sample(DVec3::new(0.5, 1e-6, 0.0)), None);
        assert_eq!(d.sample(DVec3::new(0.5, 0.0, -1e-6)), None);
    }

    #[test]
    fn bounds_are_the_corners_box() {
        let d = linear_dataset();
        let (lo, hi) = d.bounds();
        let mut r = unit_stream();
        for _ in 0..500 {
            let q = DVec3::new(4.0 * r(), 3.0 * r(), 5.0 * r());
            let p = d.nrrd.origin + d.nrrd.directions * q;
            assert!(p.cmpge(lo - 1e-12).all() && p.cmple(hi + 1e-12).all());
        }
        let top = d.nrrd.origin + d.nrrd.directions * DVec3::new(4.0, 3.0, 5.0);
        assert!(top.cmple(hi).all() && d.nrrd.origin.cmpge(lo).all());
        let h = 20.0 / 8.0;
        let p = Dataset::new(phantom(8)).unwrap().bounds();
        assert_eq!(
            p,
            (DVec3::splat(-10.0 + h / 2.0), DVec3::splat(10.0 - h / 2.0))
        );
    }

    #[test]
    fn grey_maps_the_range_onto_1_to_255() {
        let d = linear_dataset();
        let (lo, hi) = d.nrrd.range;
        assert_eq!((lo, hi), (1.0, 44.0));
        assert_eq!(d.grey(1.0), 1);
        assert_eq!(d.grey(44.0), 255);
        assert_eq!(d.grey(22.5), 128);
        assert_eq!((d.grey(-100.0), d.grey(1e9), d.grey(f64::NAN)), (1, 255, 1));
        let flat = Nrrd::new(
            [1, 1, 1],
            vec![3.0],
            DVec3::ZERO,
            DMat3::IDENTITY,
            SampleType::Uint8,
        );
        let flat = Dataset::new(flat.unwrap()).unwrap();
        assert_eq!((flat.grey(3.0), flat.grey(-1.0)), (255, 255));
    }

    #[test]
    fn new_refuses_singular_steps_and_short_samples() {
        let mut n = linear_dataset().nrrd;
        n.directions.z_axis = n.directions.x_axis * 2.0 - n.directions.y_axis;
        assert!(Dataset::new(n.clone())
            .unwrap_err()
            .to_string()
            .contains("independent axis steps"));
        n.directions = DMat3::IDENTITY;
        n.samples.pop();
        assert!(Dataset::new(n)
            .unwrap_err()
            .to_string()
            .contains("119 samples for sizes 5×4×6"));
    }

    #[test]
    fn phantom_is_a_head() {
        let n = 64;
        let d = Dataset::new(phantom(n)).unwrap();
        assert_eq!(d.nrrd, phantom(n), "deterministic");
        assert_eq!(d.nrrd.sample_type, SampleType::Uint16);
        assert!(d.nrrd.samples.iter().all(|v| v.fract() == 0.0));
        assert_eq!(d.nrrd.range, (0.0, DENSE as f32));
        let at = |x, y, z| d.sample(DVec3::new(x, y, z)).unwrap();
        let near = |p: [f64; 3], want: f64| {
            let v = at(p[0], p[1], p[2]);
            assert!((v - want).abs() <= 2.0, "{p:?}: {v}, expected {want}");
        };
        near([0.0, 0.0, -5.0], TISSUE);
        near([0.0, 0.0, 7.95], SKULL);
        near([0.0, -8.55, 0.0], SKULL);
        near([6.75, 0.0, 0.0], SKULL);
        near([1.5, 0.8, 1.2], VENTRICLE);
        near([-1.5, 0.8, 1.2], VENTRICLE);
        near([0.0, -4.0, -2.0], DENSE);
        near([9.0, 9.0, 9.0], 0.0);
        near([0.0, 0.0, 9.5], 0.0);
        // One-sample ramps: across the skull's outer surface the value climbs within 3 steps.
        let h = 20.0 / n as f64;
        near([0.0, 0.0, 8.4 + 1.5 * h], 0.0);
        near([0.0, 0.0, 8.4 - 1.5 * h], SKULL);
        assert!(d.grey(at(0.0, 0.0, 9.5)) == 1 && d.grey(at(0.0, -4.0, -2.0)) == 255);
    }

    #[test]
    fn phantom_round_trips_through_gzip_deterministically() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.nrrd"), dir.path().join("b.nrrd"));
        let head = phantom(24);
        write_nrrd(&a, &head, Encoding::Gzip, "phantom").unwrap();
        write_nrrd(&b, &head, Encoding::Gzip, "phantom").unwrap();
        assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
        assert_eq!(read_nrrd(&a).unwrap(), head);
        write_nrrd(&a, &head, Encoding::Raw, "phantom").unwrap();
        let back = Dataset::new(read_nrrd(&a).unwrap()).unwrap();
        assert_eq!(
            back.sample(DVec3::new(0.3, -1.1, 2.2)),
            Dataset::new(head)
                .unwrap()
                .sample(DVec3::new(0.3, -1.1, 2.2))
        );
    }
}
