//! A dataset's runs along a column a lattice cell at a time (`dataset_runs`) against the
//! same column sampled at every voxel centre (`Sampled::inside`): the same runs, column by
//! column, for random small datasets (sizes 1-9, u8 and u16 samples, thresholds on and
//! between sample values), placed axis-aligned (scales of either sign, axes swapped,
//! translations: the cell path) or not (the voxel path), on random grids around them; and
//! fine grids over datasets of 2-4 samples a side, so that many voxels share a lattice cell
//! the threshold crosses (`Walk::crossing`): thresholds on sample values, on a voxel's own
//! value, on the value midway between two samples, planes nearly or exactly equal (where
//! lerp's rounding wiggles around the threshold), either direction along index z.

use csgpix_scene::dataset::{Column, Dataset};
use csgpix_scene::grid::Grid;
use csgpix_scene::nrrd::{Nrrd, SampleType};
use csgpix_voxel::dataset_runs::DatasetColumns;
use csgpix_voxel::sampled::{Sampled, Shape};
use glam::{DMat3, DMat4, DVec3};
use proptest::prelude::*;

/// A random dataset: sizes 1-9 per axis, u8 or u16 samples.
fn samples() -> impl Strategy<Value = ([usize; 3], bool, Vec<u16>)> {
    ([1usize..=9, 1usize..=9, 1usize..=9], any::<bool>()).prop_flat_map(|(sizes, wide)| {
        let top = if wide { u16::MAX } else { u8::MAX as u16 };
        let n = sizes.iter().product::<usize>();
        // Few distinct values too, so that planes often tie with each other and the threshold.
        let values = prop_oneof![
            prop::collection::vec(0..=top, n),
            prop::collection::vec(prop::sample::select(vec![0, 7, 200]), n),
            prop::collection::vec(prop::sample::select(vec![7, 200]), n)
        ];
        (Just(sizes), Just(wide), values)
    })
}

/// A scale: a power of two (exact products, ties with planes) or any, either sign.
fn scale() -> impl Strategy<Value = f64> {
    let magnitude = prop_oneof![(-3i32..=3).prop_map(|e| 2f64.powi(e)), 0.05f64..20.0,];
    (magnitude, any::<bool>()).prop_map(|(m, neg)| if neg { -m } else { m })
}

fn offset() -> impl Strategy<Value = DVec3> {
    prop_oneof![
        (-8i32..=8, -8i32..=8, -8i32..=8)
            .prop_map(|(x, y, z)| DVec3::new(x as f64, y as f64, z as f64) * 0.5),
        (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0).prop_map(|(x, y, z)| DVec3::new(x, y, z)),
    ]
}

/// Any invertible-looking matrix: a random one, the test skips singular draws.
fn general3() -> impl Strategy<Value = DMat3> {
    prop::array::uniform9(-2.0f64..2.0).prop_map(|a| DMat3::from_cols_array(&a))
}

/// A placement: the dataset's steps and origin, the import's scene → file map.
#[derive(Clone, Debug)]
struct Placement {
    steps: DMat3,
    origin: DVec3,
    to_file: DMat4,
    /// Whether it is meant for the cell path.
    aligned: bool,
}

/// A placement that keeps index x and y off scene z, by one of four routes: scales on the
/// diagonals; the file's x and y swapped by the map and back by the steps; scene z along file
/// x, which the steps take to index z; any map and steps within x and y, (scene x, y) → file
/// z and (index x, y) → file z allowed.
fn aligned() -> impl Strategy<Value = Placement> {
    let scales = [scale(), scale(), scale()];
    let maps = [scale(), scale(), scale()];
    let block = prop::array::uniform4(-2.0f64..2.0);
    let (o, t) = (offset(), offset());
    (0usize..4, scales, maps, block, o, t, any::<bool>()).prop_map(
        |(route, [a, b, c], [sx, sy, sz], m, origin, t, negative_zero)| {
            let v = DVec3::new;
            let (steps, map) = match route {
                0 => (
                    DMat3::from_diagonal(v(a, b, c)),
                    DMat3::from_diagonal(v(sx, sy, sz)),
                ),
                1 => (
                    DMat3::from_cols(v(0.0, b, 0.0), v(a, 0.0, 0.0), v(0.0, 0.0, c)),
                    DMat3::from_cols(v(0.0, sx, 0.0), v(sy, 0.0, 0.0), v(0.0, 0.0, sz)),
                ),
                2 => (
                    DMat3::from_cols(v(0.0, a, 0.0), v(0.0, 0.0, b), v(c, 0.0, 0.0)),
                    DMat3::from_cols(v(0.0, sx, 0.0), v(0.0, 0.0, sy), v(sz, 0.0, 0.0)),
                ),
                _ => (
                    DMat3::from_cols(v(m[0], m[1], a), v(m[2], m[3], b), v(0.0, 0.0, c)),
                    DMat3::from_cols(v(m[3], m[0], sx), v(m[1], m[2], sy), v(0.0, 0.0, sz)),
                ),
            };
            let mut to_file = DMat4::from_mat3(map);
            to_file.w_axis = t.extend(1.0);
            if negative_zero {
                // -0.0 for the zeros that keep scene z out of file x and y.
                let z = &mut to_file.z_axis;
                for e in [&mut z.x, &mut z.y, &mut z.z] {
                    if *e == 0.0 {
                        *e = -0.0;
                    }
                }
            }
            Placement {
                steps,
                origin,
                to_file,
                aligned: true,
            }
        },
    )
}

fn skewed() -> impl Strategy<Value = Placement> {
    (general3(), offset(), general3(), offset(), any::<bool>()).prop_map(
        |(steps, origin, m, t, aligned_steps)| {
            // Half the time the steps are aligned and only the map mixes scene z in.
            let steps = if aligned_steps {
                let d = DVec3::new(steps.x_axis.x, steps.y_axis.y, steps.z_axis.z);
                DMat3::from_diagonal(d + DVec3::splat(0.5).copysign(d))
            } else {
                steps
            };
            let mut to_file = DMat4::from_mat3(m);
            to_file.w_axis = t.extend(1.0);
            Placement {
                steps,
                origin,
                to_file,
                aligned: false,
            }
        },
    )
}

/// A grid around the dataset's scene box: grown or shrunk, shifted, a few voxels a side.
fn grid_around(lo: DVec3, hi: DVec3, dims: [usize; 3], grow: [f64; 3], shift: [f64; 3]) -> Grid {
    let size = (hi - lo).max(DVec3::splat(0.25));
    let centre = (lo + hi) / 2.0 + DVec3::from(shift) * size;
    let half = size * DVec3::from(grow) / 2.0;
    Grid::new(dims, centre - half, centre + half).unwrap()
}

/// A grid of voxels `2^e` a side whose centres are multiples of `2^e`, from `back` voxels
/// below the box's low corner: with power-of-two scales and offsets in halves, voxel centres
/// fall on lattice planes exactly, and plane values tie with sample-value thresholds.
fn grid_snapped(lo: DVec3, dims: [usize; 3], e: i32, back: [usize; 3]) -> Grid {
    let v = 2f64.powi(e);
    let back = DVec3::from(back.map(|b| b as f64));
    let min = ((lo / v).floor() - back - 0.5) * v;
    let size = DVec3::from(dims.map(|d| d as f64)) * v;
    Grid::new(dims, min, min + size).unwrap()
}

fn dataset(sizes: [usize; 3], wide: bool, values: &[u16], p: &Placement) -> Option<Dataset> {
    let t = if wide {
        SampleType::Uint16
    } else {
        SampleType::Uint8
    };
    let samples = values.iter().map(|&v| v as f32).collect();
    Dataset::new(Nrrd::new(sizes, samples, p.origin, p.steps, t).ok()?).ok()
}

/// The dataset import of `data` at `threshold`.
fn import(data: Dataset, threshold: f64, to_file: DMat4) -> Sampled {
    Sampled {
        shape: Shape::Dataset {
            data: Box::new(data),
            threshold,
            to_file,
        },
        colour: 1,
        file: "random.nrrd".into(),
    }
}

/// Every column's runs, by cells and by voxels, equal; whether the cell path was taken.
fn check(s: &Sampled, grid: &Grid) -> Result<bool, TestCaseError> {
    let d = DatasetColumns::new(s, grid).unwrap();
    let mut column = Column::default();
    let (mut fast, mut slow) = (vec![], vec![]);
    for y in 0..grid.dims[1] {
        for x in 0..grid.dims[0] {
            fast.clear();
            slow.clear();
            // Something before: the runs are appended, not joined to it.
            fast.push((0, 0));
            slow.push((0, 0));
            d.runs(x, y, &mut column, &mut fast);
            d.runs_by_voxels(x, y, &mut slow);
            prop_assert_eq!(&fast, &slow, "column ({}, {})", x, y);
        }
    }
    Ok(d.by_cells())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    #[test]
    fn runs_by_cells_are_the_voxels_runs(
        (sizes, wide, values) in samples(),
        placement in prop_oneof![3 => aligned(), 1 => skewed()],
        dims in [1usize..=7, 1usize..=7, 1usize..=48],
        grow in [0.5f64..1.6, 0.5f64..1.6, 0.3f64..1.6],
        shift in [-0.4f64..0.4, -0.4f64..0.4, -0.4f64..0.4],
        snap in prop::option::of((-3i32..=1, [0usize..3, 0usize..3, 0usize..6])),
        pick in any::<prop::sample::Index>(),
        between in prop_oneof![Just(None), (-1.0f64..300.0).prop_map(Some)],
    ) {
        let Some(data) = dataset(sizes, wide, &values, &placement) else {
            return Ok(()); // singular steps
        };
        // A threshold on a sample value, or anywhere.
        let threshold = between.unwrap_or(f64::from(values[pick.index(values.len())]));
        let s = Sampled {
            shape: Shape::Dataset { data: Box::new(data), threshold, to_file: placement.to_file },
            colour: 1,
            file: "random.nrrd".into(),
        };
        let (lo, hi) = s.bounds();
        prop_assume!(lo.is_finite() && hi.is_finite());
        let grid = match snap {
            Some((e, back)) => grid_snapped(lo, dims, e, back),
            None => grid_around(lo, hi, dims, grow, shift),
        };
        let by_cells = check(&s, &grid)?;
        if placement.aligned {
            prop_assert!(by_cells, "an axis-aligned placement goes by cells");
        }
    }
}

/// The figure-5.6 placement (the phantom, identity map) on a fine grid, by cells.
#[test]
fn the_phantom_by_cells() {
    let data = Dataset::new(csgpix_scene::dataset::phantom(12)).unwrap();
    for threshold in [0.0, 100.0, 300.0, 400.0, 1000.0, 1200.0, 1201.0] {
        let s = Sampled {
            shape: Shape::Dataset {
                data: Box::new(data.clone()),
                threshold,
                to_file: DMat4::IDENTITY,
            },
            colour: 1,
            file: "phantom.nrrd".into(),
        };
        let grid = Grid::new([24, 20, 97], DVec3::splat(-11.0), DVec3::splat(11.0)).unwrap();
        assert!(check(&s, &grid).unwrap(), "by cells");
    }
}

/// A small dataset of float samples: 1-4 a side in x and y, 2-4 in z; integers, or values
/// within a few ulps of one float (plane values nearly equal: lerp's rounding decides).
fn small_samples() -> impl Strategy<Value = ([usize; 3], Vec<f32>)> {
    ([1usize..=4, 1usize..=4, 2usize..=4], 0.001f32..1000.0).prop_flat_map(|(sizes, base)| {
        let n = sizes.iter().product::<usize>();
        let near =
            (-3i32..=3).prop_map(move |d| f32::from_bits((base.to_bits() as i32 + d) as u32));
        let values = prop_oneof![
            prop::collection::vec((0u16..=255).prop_map(f32::from), n),
            prop::collection::vec(prop::sample::select(vec![0.0f32, 2.0, 7.0]), n),
            prop::collection::vec(near, n),
            prop::collection::vec(prop::sample::select(vec![base, base.next_up()]), n),
        ];
        (Just(sizes), values)
    })
}

/// The threshold of a case: a sample value, midway between two, a voxel's own value
/// (`Sampled::sample` there: it ties at that voxel), any value near the samples, or a sample
/// value moved by an ulp or so (equal planes then cross it by rounding alone).
#[derive(Clone, Debug)]
enum Threshold {
    Sample(prop::sample::Index),
    Midway(prop::sample::Index, prop::sample::Index),
    Voxel(
        prop::sample::Index,
        prop::sample::Index,
        prop::sample::Index,
    ),
    Within(f64),
    /// A sample value moved by this many ulps (of f64).
    Beside(prop::sample::Index, i8),
}

fn threshold() -> impl Strategy<Value = Threshold> {
    let i = any::<prop::sample::Index>;
    prop_oneof![
        1 => i().prop_map(Threshold::Sample),
        1 => (i(), i()).prop_map(|(a, b)| Threshold::Midway(a, b)),
        2 => (i(), i(), i()).prop_map(|(x, y, z)| Threshold::Voxel(x, y, z)),
        1 => (-0.1f64..1.1).prop_map(Threshold::Within),
        1 => (i(), -3i8..=3).prop_map(|(i, d)| Threshold::Beside(i, d)),
    ]
}

impl Threshold {
    fn value(&self, values: &[f32], s: &Sampled, grid: &Grid) -> f64 {
        let v = |i: &prop::sample::Index| f64::from(values[i.index(values.len())]);
        match self {
            Threshold::Sample(i) => v(i),
            Threshold::Midway(a, b) => (v(a) + v(b)) / 2.0,
            Threshold::Voxel(x, y, z) => {
                let [nx, ny, nz] = grid.dims;
                let c = grid.centre(x.index(nx), y.index(ny), z.index(nz));
                s.sample(c).unwrap_or(f64::NAN)
            }
            Threshold::Within(t) => {
                let (lo, hi) = values.iter().fold((f64::MAX, f64::MIN), |(lo, hi), &x| {
                    (lo.min(f64::from(x)), hi.max(f64::from(x)))
                });
                lo + t * (hi - lo)
            }
            Threshold::Beside(i, d) => {
                let step = |x: f64| if *d < 0 { x.next_down() } else { x.next_up() };
                (0..d.unsigned_abs()).fold(v(i), |x, _| step(x))
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    #[test]
    fn crossing_cells_of_many_voxels(
        (sizes, values) in small_samples(),
        placement in aligned(),
        dims in [1usize..=3, 1usize..=3, 20usize..=200],
        grow in [0.5f64..1.6, 0.5f64..1.6, 0.8f64..1.3],
        shift in [-0.4f64..0.4, -0.4f64..0.4, -0.1f64..0.1],
        snap in prop::option::of((-6i32..=-2, [0usize..3, 0usize..3, 0usize..6])),
        threshold in threshold(),
    ) {
        let nrrd = Nrrd::new(sizes, values.clone(), placement.origin, placement.steps, SampleType::Float);
        let Some(data) = nrrd.ok().and_then(|n| Dataset::new(n).ok()) else {
            return Ok(()); // singular steps
        };
        let s = import(data.clone(), 0.0, placement.to_file);
        let (lo, hi) = s.bounds();
        prop_assume!(lo.is_finite() && hi.is_finite());
        let grid = match snap {
            Some((e, back)) => grid_snapped(lo, dims, e, back),
            None => grid_around(lo, hi, dims, grow, shift),
        };
        let s = import(data, threshold.value(&values, &s, &grid), placement.to_file);
        prop_assert!(check(&s, &grid)?, "by cells");
    }
}

/// A 1×1×2 dataset of samples `z` along index z (step `step`, origin 0, identity map), on
/// 96 voxels of ¼ (⅛ with `eighths`) along scene z from −1 − ⅛ (mirrored for a negative
/// step): voxel centres at scene z −1 + ¼·i (⅛·i), index z that over `step`.
fn two_planes(z: [f32; 2], step: f64, threshold: f64, eighths: bool) -> (Sampled, Grid) {
    let steps = DMat3::from_diagonal(DVec3::new(1.0, 1.0, step));
    let nrrd = Nrrd::new([1, 1, 2], z.to_vec(), DVec3::ZERO, steps, SampleType::Float).unwrap();
    let s = import(Dataset::new(nrrd).unwrap(), threshold, DMat4::IDENTITY);
    let v = if eighths { 0.125 } else { 0.25 };
    let n = 96;
    let (lo, hi) = (-1.0 - v / 2.0, -1.0 - v / 2.0 + n as f64 * v);
    let (lo, hi) = if step > 0.0 { (lo, hi) } else { (-hi, -lo) };
    let grid = Grid::new(
        [1, 1, n],
        DVec3::new(-0.5, -0.5, lo),
        DVec3::new(0.5, 0.5, hi),
    )
    .unwrap();
    (s, grid)
}

/// g(t) meets the threshold exactly at a voxel centre: a = 0, b = 2, threshold 1 at t = ½;
/// a = 1, b = 5, threshold 2 at t = ¼; a = 0, b = 1, threshold ⅜ at t = ⅜ (on ⅛ voxels);
/// either way along index z, with the samples swapped.
#[test]
fn thresholds_met_exactly_at_a_voxel() {
    for (z, threshold) in [([0.0, 2.0], 1.0), ([1.0, 5.0], 2.0), ([0.0, 1.0], 0.375)] {
        for z in [z, [z[1], z[0]]] {
            for step in [1.0, -1.0, 0.5, -2.0] {
                for eighths in [false, true] {
                    let (s, grid) = two_planes(z, step, threshold, eighths);
                    let hit = (0..grid.dims[2])
                        .any(|k| s.sample(grid.centre(0, 0, k)) == Some(threshold));
                    let on = eighths && step.abs() == 1.0;
                    assert!(hit || !on, "{z:?} {step}: no voxel on the threshold");
                    assert!(check(&s, &grid).unwrap(), "by cells");
                }
            }
        }
    }
}

/// Equal planes on the threshold or an ulp or two (of f64) off it, and planes an ulp (of f32)
/// apart: lerp's rounding alone decides each voxel, in several runs per cell (the test checks there are some).
#[test]
fn equal_planes_wiggle_around_the_threshold() {
    let mut wiggles = 0;
    for a in [0.1f32, 1.0 / 3.0, 7.0, 300.7, 1e-30, 12345.678] {
        let (up, wide) = (a.next_up(), f64::from(a));
        let cases = [
            ([a, a], wide),
            ([a, a], wide.next_up()),
            ([a, a], wide.next_up().next_up()),
            ([a, a], wide.next_down()),
            ([a, up], f64::from(up)),
            ([up, a], wide),
        ];
        for (z, threshold) in cases {
            for step in [1.0, -1.0, 0.75, -3.0] {
                for eighths in [false, true] {
                    let (s, grid) = two_planes(z, step, threshold, eighths);
                    let mut runs = vec![];
                    DatasetColumns::new(&s, &grid)
                        .unwrap()
                        .runs_by_voxels(0, 0, &mut runs);
                    wiggles += usize::from(runs.len() > 1);
                    assert!(check(&s, &grid).unwrap(), "by cells");
                }
            }
        }
    }
    assert!(wiggles > 0, "no case where rounding splits a cell's runs");
}
