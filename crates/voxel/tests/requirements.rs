//! Modelling only what a scene requires changes nothing: the array route simulating only the
//! panels and slabs each primitive touches gives the volume of simulating the whole array for
//! every frame, bit for bit, on every example scene and on random ones, for both models.

use csgpix_openscad::parse_csg;
use csgpix_scene::solid::CsgScene;
use csgpix_testkit::random_scene;
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::footprints;
use csgpix_voxel::{voxelize, Grid, Route, Slicer, SlicerOptions, Volume, Work};
use proptest::prelude::*;
use rtl_model::Equations;

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn scene(name: &str) -> CsgScene {
    let path = format!("{ROOT}/vectors/scenes/{name}.csg");
    parse_csg(&std::fs::read_to_string(path).unwrap(), name).unwrap()
}

fn run(s: &CsgScene, dims: [usize; 3], cycle: bool, panel: Option<[usize; 2]>) -> (Volume, Work) {
    let opts = SlicerOptions {
        panel,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(s, Grid::of_scene(s, dims).unwrap(), opts).unwrap();
    let eval = BlistEval::new(&s.root);
    voxelize(
        &slicer,
        Route::Array { cycle },
        Equations::Derived.set(),
        &eval,
        &|| {},
    )
    .unwrap()
}

#[test]
fn pruned_and_whole_arrays_give_the_same_volume_on_every_example() {
    for name in ["figure-5.2", "hollow-cube", "cube-minus-cylinder", "twelve"] {
        let s = scene(name);
        for panel in [[4, 4], [8, 16]] {
            let (whole, w) = run(&s, [20, 18, 12], false, None);
            let (pruned, p) = run(&s, [20, 18, 12], false, Some(panel));
            assert_eq!(whole, pruned, "{name} {panel:?}");
            assert_eq!(w.simulated_pixel_clocks, w.full_pixel_clocks, "{name}");
            assert_eq!(
                (p.cycles, p.full_pixel_clocks),
                (w.cycles, w.full_pixel_clocks)
            );
            assert!(
                p.simulated_pixel_clocks < w.simulated_pixel_clocks,
                "{name} {panel:?}"
            );
            println!(
                "{name} 20x18x12, {panel:?} panels: simulated {:.3} of the whole array's pixel-clocks",
                p.simulated_pixel_clocks as f64 / w.simulated_pixel_clocks as f64
            );
        }
    }
}

#[test]
fn the_cycle_model_prunes_the_same_way() {
    let s = scene("twelve");
    let (whole, _) = run(&s, [16, 16, 10], true, None);
    let (pruned, _) = run(&s, [16, 16, 10], true, Some([4, 4]));
    assert_eq!(whole, pruned);
}

/// A primitive in one corner of a larger grid touches only the corner panels and slabs.
#[test]
fn a_corner_primitive_touches_the_corner_only() {
    let text = "union() {\n  cube(size = [1, 1, 1]);\n  \
                multmatrix([[1, 0, 0, 9], [0, 1, 0, 9], [0, 0, 1, 9], [0, 0, 0, 1]]) {\n    \
                cube(size = [1, 1, 1]);\n  }\n}\n";
    let s = parse_csg(text, "corner").unwrap();
    let slicer = Slicer::new(
        &s,
        Grid::of_scene(&s, [20, 20, 20]).unwrap(),
        SlicerOptions::default(),
    )
    .unwrap();
    let f = footprints(&slicer).unwrap();
    // Each unit cube covers 2 of the 20 voxels along each axis (the scene spans 10 units).
    let a = f[0].pixels.unwrap();
    assert!(a.x0 == 0 && a.y0 == 0 && a.x1 <= 3 && a.y1 <= 3, "{a:?}");
    let (k0, k1) = f[0].slabs.unwrap();
    assert!(k0 == 0 && k1 <= 2, "{k0}..={k1}");
    let b = f[1].pixels.unwrap();
    assert!(
        b.x1 == 20 && b.y1 == 20 && b.x0 >= 17 && b.y0 >= 17,
        "{b:?}"
    );
    assert!(f[1].slabs.unwrap().0 >= 17);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random rotated cubes, spheres, cylinders and cones under random trees.
    #[test]
    fn pruning_never_changes_a_voxel(text in random_scene(), n in 6usize..14, p in 1usize..6) {
        let s = parse_csg(&text, "random").unwrap();
        let (whole, _) = run(&s, [n, n + 1, n], false, None);
        let (pruned, _) = run(&s, [n, n + 1, n], false, Some([p, p + 1]));
        prop_assert_eq!(whole, pruned);
    }
}
