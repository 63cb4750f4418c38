//! Slices of primitives (§4.4): the processor's P·Vz images (`cycle` and `word`) against the
//! interval route that shortcuts them, voxel for voxel, and against exact f64 intervals.

use csgpix_openscad::parse_csg;
use csgpix_testkit::random_scene;
use csgpix_voxel::{array_mask, float_ranges, word_ranges, Grid, Sampling, Slicer, SlicerOptions};
use proptest::prelude::*;
use rtl_model::Equations;

/// Mismatches (slab, primitive, pixel) between the array and the interval route, and voxels
/// where the interval route differs from float.
fn compare(
    text: &str,
    dims: [usize; 3],
    cycle_too: bool,
    sampling: Sampling,
) -> (Vec<(usize, usize, usize)>, usize) {
    let scene = parse_csg(text, "scene.csg").unwrap();
    let grid = Grid::of_scene(&scene, dims).unwrap();
    let slicer = Slicer::new(
        &scene,
        grid,
        SlicerOptions {
            sampling,
            ..SlicerOptions::default()
        },
    )
    .unwrap();
    let mut bad = vec![];
    let mut vs_float = 0;
    for prim in 0..scene.solids.len() {
        let fast = word_ranges(&slicer, prim).unwrap();
        let exact = float_ranges(&slicer, prim);
        for k in 0..dims[2] {
            let (word, _) = array_mask(&slicer, prim, k, false, Equations::Derived.set()).unwrap();
            if cycle_too {
                let (cyc, _) =
                    array_mask(&slicer, prim, k, true, Equations::Derived.set()).unwrap();
                assert_eq!(cyc, word, "cycle and word slices differ");
            }
            let m = fast.mask(k);
            bad.extend(
                (0..m.len())
                    .filter(|&i| m.get(i) != word.get(i))
                    .map(|i| (k, prim, i)),
            );
            let f = exact.mask(k);
            vs_float += (0..m.len()).filter(|&i| m.get(i) != f.get(i)).count();
        }
    }
    (bad, vs_float)
}

#[test]
fn cube_minus_cylinder_slices_match_the_array() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../vectors/scenes/cube-minus-cylinder.csg"
    ))
    .unwrap();
    for sampling in [Sampling::Centre, Sampling::Slab] {
        let (bad, vs_float) = compare(&text, [24, 24, 24], true, sampling);
        println!(
            "cube-minus-cylinder 24^3 ({sampling:?}): {} mismatches, {vs_float} voxels differ from float",
            bad.len()
        );
        assert!(bad.is_empty(), "{:?}", &bad[..bad.len().min(20)]);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn interval_route_gives_the_processors_slices(text in random_scene(), n in 6usize..14) {
        for sampling in [Sampling::Centre, Sampling::Slab] {
            let (bad, _) = compare(&text, [n, n + 1, n], false, sampling);
            prop_assert!(bad.is_empty(), "{sampling:?} {:?}\n{text}", &bad[..bad.len().min(20)]);
        }
    }
}
