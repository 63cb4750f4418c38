//! The voxel grid laid over a scene and the volumes voxelized on it (§4.4).

use glam::DVec3;

use crate::solid::CsgScene;
use crate::{Error, Result};

/// The voxel grid: `dims` voxels spanning the box `min`..`max` in scene units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Voxels along X, Y and Z.
    pub dims: [usize; 3],
    /// The box's low corner.
    pub min: DVec3,
    /// The box's high corner.
    pub max: DVec3,
}

impl Grid {
    /// A grid over the scene's bounds (every solid's vertices, so subtracted solids count).
    /// A scene without solids has none: the error is then [`Error::NeedsBounds`].
    pub fn of_scene(scene: &CsgScene, dims: [usize; 3]) -> Result<Grid> {
        let (min, max) = Grid::scene_bounds(scene)?;
        Grid::new(dims, min, max)
    }

    /// The box around every solid's vertices; [`Error::NeedsBounds`] when there is none.
    pub fn scene_bounds(scene: &CsgScene) -> Result<(DVec3, DVec3)> {
        let pts = scene.solids.iter().flat_map(|s| s.vertices.iter());
        let (min, max) = pts.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), p| {
            (a.min(DVec3::from(*p)), b.max(DVec3::from(*p)))
        });
        if !min.is_finite() {
            return Err(Error::NeedsBounds);
        }
        Ok((min, max))
    }

    /// A grid over an explicit box, every side at least [`MIN_EXTENT`].
    pub fn new(dims: [usize; 3], min: DVec3, max: DVec3) -> Result<Grid> {
        if dims.contains(&0) {
            return Err(Error::EmptyResolution { dims });
        }
        if !(min.is_finite() && max.is_finite()) || (max - min).min_element() <= 0.0 {
            return Err(Error::BadBounds { min, max });
        }
        let side = (max - min).min_element();
        if side < MIN_EXTENT {
            return Err(Error::DegenerateExtent {
                side,
                min: MIN_EXTENT,
            });
        }
        Ok(Grid { dims, min, max })
    }

    /// Size of one voxel in scene units.
    pub fn voxel(&self) -> DVec3 {
        (self.max - self.min)
            / DVec3::new(
                self.dims[0] as f64,
                self.dims[1] as f64,
                self.dims[2] as f64,
            )
    }

    /// Centre of voxel (i, j, k) in scene units.
    pub fn centre(&self, i: usize, j: usize, k: usize) -> DVec3 {
        self.min + (DVec3::new(i as f64, j as f64, k as f64) + 0.5) * self.voxel()
    }

    /// Voxels in one slice.
    pub fn slice_len(&self) -> usize {
        self.dims[0] * self.dims[1]
    }
}

/// Smallest side of a grid's box (and of a solid the `.csg` reader places). A grid's voxels
/// are its sides over at most [`MAX_GRID_SIDE`] voxels each: a box a few 1e-308 across has
/// voxels no f64 can invert, and the planes drawn on it came out NaN.
pub const MIN_EXTENT: f64 = 1e-12;

/// Most voxels a grid may have along one axis (a `--voxel` size far below the scene's extent
/// is refused here rather than by the memory estimate's arithmetic).
pub const MAX_GRID_SIDE: usize = 1 << 20;

/// How a grid is laid over a region: voxels per axis (`res`), a cubic voxel size (`voxel`,
/// the grid centred on the region with whole voxels covering it) or a number of cubic voxels
/// along the region's longest side (`longest`, as binvox, OpenVDB and trimesh take a
/// resolution), then `pad` empty voxels added on every side. One of the three is given.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GridSpec {
    /// Voxels along X, Y and Z.
    pub res: Option<[usize; 3]>,
    /// Side of a cubic voxel, in scene units.
    pub voxel: Option<f64>,
    /// Cubic voxels along the longest side (the others as many as cover theirs).
    pub longest: Option<usize>,
    /// Empty voxels added on every side.
    pub pad: usize,
}

impl GridSpec {
    /// The grid over the box `lo`..`hi`.
    pub fn grid(&self, lo: DVec3, hi: DVec3) -> Result<Grid> {
        let inner = match (self.res, self.voxel, self.longest) {
            (Some(dims), None, None) => Grid::new(dims, lo, hi)?,
            (None, Some(size), None) => Self::cubic(size, lo, hi)?,
            (None, None, Some(n)) => Self::longest(n, lo, hi)?,
            _ => return Err(Error::ResolutionAndVoxelSize),
        };
        let v = inner.voxel();
        let pad = self.pad.min(MAX_GRID_SIDE);
        let dims = inner.dims.map(|d| d.saturating_add(2 * pad));
        if dims.iter().any(|&d| d > MAX_GRID_SIDE) {
            return Err(Error::GridTooLarge {
                dims,
                limit: MAX_GRID_SIDE,
            });
        }
        let margin = v * pad as f64;
        Grid::new(dims, inner.min - margin, inner.max + margin)
    }

    /// `n` cubic voxels along the box's longest side, the others covered by as many as they
    /// need, centred. A cube gets exactly `n` a side over the box itself.
    fn longest(n: usize, lo: DVec3, hi: DVec3) -> Result<Grid> {
        let extent = hi - lo;
        if extent.x == extent.y && extent.y == extent.z {
            return Grid::new([n; 3], lo, hi);
        }
        if n == 0 {
            return Grid::new([0; 3], lo, hi);
        }
        Self::cubic(extent.max_element() / n as f64, lo, hi)
    }

    /// Cubic voxels of side `size`: as many as cover each side of the box, centred on it.
    fn cubic(size: f64, lo: DVec3, hi: DVec3) -> Result<Grid> {
        if !(size.is_finite() && size > 0.0) {
            return Err(Error::BadVoxelSize { size });
        }
        let extent = hi - lo;
        let mut dims = [0usize; 3];
        for (d, e) in dims.iter_mut().zip(extent.to_array()) {
            // A side that is a whole number of voxels (to rounding) gets exactly that many.
            let n = (e / size * (1.0 - 1e-12)).ceil().max(1.0);
            if n.is_nan() || n > MAX_GRID_SIDE as f64 {
                return Err(Error::VoxelSizeTooSmall {
                    size,
                    extent: e,
                    limit: MAX_GRID_SIDE,
                });
            }
            *d = n as usize;
        }
        let side = DVec3::new(dims[0] as f64, dims[1] as f64, dims[2] as f64) * size;
        let centre = (lo + hi) / 2.0;
        Grid::new(dims, centre - side / 2.0, centre + side / 2.0)
    }
}

/// A voxelized scene: colour codes, X fastest, then Y, then Z; 0 is empty.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Volume {
    /// Voxels along X, Y and Z.
    pub dims: [usize; 3],
    /// One colour code a voxel, `(k·ny + j)·nx + i` for voxel (i, j, k).
    pub voxels: Vec<u8>,
}

/// The filled voxels on the volume's surface: those with an empty 6-neighbour or on the
/// grid's border.
pub fn surface_voxels(v: &Volume) -> u64 {
    let [nx, ny, nz] = v.dims;
    let at = |i: usize, j: usize, k: usize| v.voxels[(k * ny + j) * nx + i] != 0;
    let open = |i: usize, j: usize, k: usize| {
        i == 0 || j == 0 || k == 0 || i + 1 == nx || j + 1 == ny || k + 1 == nz || {
            !(at(i - 1, j, k)
                && at(i + 1, j, k)
                && at(i, j - 1, k)
                && at(i, j + 1, k)
                && at(i, j, k - 1)
                && at(i, j, k + 1))
        }
    };
    let mut n = 0;
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                n += u64::from(at(i, j, k) && open(i, j, k));
            }
        }
    }
    n
}

#[cfg(test)]
mod grid_tests {
    use super::*;

    fn spec(res: Option<[usize; 3]>, voxel: Option<f64>, pad: usize) -> GridSpec {
        GridSpec {
            res,
            voxel,
            longest: None,
            pad,
        }
    }

    #[test]
    fn the_longest_side_gets_n_cubic_voxels() {
        let longest = |n, lo: [f64; 3], hi: [f64; 3]| {
            let spec = GridSpec {
                longest: Some(n),
                ..GridSpec::default()
            };
            spec.grid(DVec3::from(lo), DVec3::from(hi)).unwrap()
        };
        // 28 / 64 a voxel: 22.8 needs 52.2 → 53 voxels, centred; the longest side exactly 64.
        let g = longest(64, [-11.4, -11.4, -14.0], [11.4, 11.4, 14.0]);
        assert_eq!(g.dims, [53, 53, 64]);
        let v = g.voxel();
        assert!(
            (v.x - v.z).abs() < 1e-12 && (v.y - v.z).abs() < 1e-12,
            "{v}"
        );
        assert_eq!((g.min.z, g.max.z), (-14.0, 14.0));
        assert!((g.min.x + g.max.x).abs() < 1e-12 && g.max.x >= 11.4);
        // A side that is a whole number of voxels gets exactly that many.
        assert_eq!(longest(64, [0.0; 3], [32.0, 16.0, 8.0]).dims, [64, 32, 16]);
        // A cube is the box itself, as --res N×N×N lays it.
        let cube = longest(10, [-1.0; 3], [2.0; 3]);
        assert_eq!(
            cube,
            Grid::new([10; 3], DVec3::splat(-1.0), DVec3::splat(2.0)).unwrap()
        );
        let zero = GridSpec {
            longest: Some(0),
            ..GridSpec::default()
        };
        assert!(zero.grid(DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0)).is_err());
    }

    #[test]
    fn cubic_voxels_cover_the_bounds_centred() {
        let g = spec(None, Some(0.5), 0)
            .grid(DVec3::new(1.0, 2.0, 3.0), DVec3::new(63.0, 3.2, 4.0))
            .unwrap();
        // 62 / 0.5 = 124 exactly; 1.2 / 0.5 = 2.4 → 3 voxels, centred; 1 / 0.5 = 2.
        assert_eq!(g.dims, [124, 3, 2]);
        assert_eq!(g.voxel(), DVec3::splat(0.5));
        assert_eq!(g.min.x, 1.0);
        assert!((g.min.y - (2.6 - 0.75)).abs() < 1e-12);
        assert_eq!(g.max.z, 4.0);
    }

    #[test]
    fn padding_adds_empty_voxels_of_the_same_size() {
        let g = spec(Some([10, 20, 5]), None, 2)
            .grid(DVec3::ZERO, DVec3::new(10.0, 10.0, 10.0))
            .unwrap();
        assert_eq!(g.dims, [14, 24, 9]);
        assert_eq!(g.voxel(), DVec3::new(1.0, 0.5, 2.0));
        assert_eq!(g.min, DVec3::new(-2.0, -1.0, -4.0));
        assert_eq!(g.max, DVec3::new(12.0, 11.0, 14.0));
    }

    #[test]
    fn bad_grids_are_refused() {
        let (lo, hi) = (DVec3::ZERO, DVec3::ONE);
        assert!(spec(None, Some(0.0), 0).grid(lo, hi).is_err());
        assert!(spec(None, Some(f64::NAN), 0).grid(lo, hi).is_err());
        assert!(spec(None, Some(1e-9), 0).grid(lo, hi).is_err());
        assert!(spec(None, None, 0).grid(lo, hi).is_err());
        assert!(spec(Some([4; 3]), None, usize::MAX).grid(lo, hi).is_err());
        // A box 1e-307 across made voxels no f64 inverts (NaN planes).
        let e = Grid::new([8; 3], lo, DVec3::splat(1e-307)).unwrap_err();
        assert!(e.to_string().starts_with("degenerate extent: "), "{e}");
        assert!(Grid::new([8; 3], lo, DVec3::splat(MIN_EXTENT)).is_ok());
    }
}
