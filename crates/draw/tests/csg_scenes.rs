//! OpenSCAD `.csg` scenes through all three models: projected in each view, drawn the thesis
//! way (§5.2.1) by `cycle` and `word` (identical in every register), and compared with exact
//! ray casting (`float`), where every differing pixel must be explained (docs/rendering.md).

use csgpix_draw::compile::clip_scene_ops;
use csgpix_draw::float::agreement;
use csgpix_draw::project::{project, View};
use csgpix_openscad::parse_csg;
use csgpix_testkit::random_scene;
use proptest::prelude::*;
use rtl_model::program::CReg;
use rtl_model::{Array, ArrayConfig, CycleArray, Equations, WordArray};

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn scene(name: &str) -> String {
    let path = format!("{ROOT}/vectors/scenes/{name}");
    std::fs::read_to_string(path).unwrap()
}

/// Render `text` in `view` on a `size`² array; the number of pixels that differ from float,
/// after asserting cycle = word and that every difference is explained.
fn check(text: &str, view: View, size: usize) -> usize {
    check_drawn(text, view, size, true)
}

fn check_drawn(text: &str, view: View, size: usize, must_draw: bool) -> usize {
    let scene = parse_csg(text, "scene.csg").unwrap();
    let cfg = ArrayConfig::new(size, size);
    let p = project(&scene, view, size, size, &cfg.fmt).unwrap();
    let Some(clip) = p.clip else {
        assert!(!must_draw, "the scene draws nothing");
        return 0;
    };
    let ops = clip_scene_ops(&p.lists, &clip, &cfg.fmt, cfg.colour_bits).unwrap();
    let mut cyc = CycleArray::new(cfg, Equations::Derived.set());
    let mut wrd = WordArray::new(cfg, Equations::Derived.set());
    cyc.run(&ops).unwrap();
    wrd.run(&ops).unwrap();
    assert_eq!(
        cyc.state(),
        wrd.state(),
        "cycle and word differ in {view:?}"
    );
    let colours: Vec<u32> = wrd.state().pixels.iter().map(|p| p.creg(CReg::G)).collect();
    let drawn = colours.iter().filter(|&&c| c != 0).count();
    assert!(
        !must_draw || drawn > size * size / 10,
        "{view:?}: only {drawn} pixels drawn"
    );
    let a = agreement(&colours, &p.lists, Some(&clip), size, size, &cfg.fmt);
    println!(
        "{view:?}: {} of {} pixels differ from float ({} near a tie, {} screen rule)",
        a.differ(),
        size * size,
        a.near_tie,
        a.screen_rule
    );
    assert!(
        a.unexplained.is_empty(),
        "{view:?}: {:?}",
        &a.unexplained[..a.unexplained.len().min(10)]
    );
    a.differ()
}

#[test]
fn cube_minus_cylinder_in_every_view() {
    let text = scene("cube-minus-cylinder.csg");
    for view in [View::Top, View::Front, View::Iso] {
        let differ = check(&text, view, 250);
        // The projection keeps the scene behind the screen, so differences are rare.
        assert!(differ < 250 * 250 / 100, "{view:?}: {differ}");
    }
}

#[test]
fn sphere_union_and_intersection() {
    let text = "union() {\n\
        sphere($fn = 16, $fa = 12, $fs = 2, r = 10);\n\
        intersection() {\n\
          multmatrix([[1, 0, 0, 15], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = [12, 12, 12], center = true);\n\
          multmatrix([[1, 0, 0, 15], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere($fn = 12, r = 8);\n\
        }\n\
      }\n";
    for view in [View::Top, View::Iso] {
        check(text, view, 96);
    }
}

#[test]
fn openscad_csg_logo() {
    // One product of five literals (cube, sphere, three complemented cylinders): 566 faces,
    // and outline planes where the screen rule would draw a solid beside itself.
    let differ = check(&scene("csg-logo.csg"), View::Iso, 128);
    assert!(differ < 128 * 128 / 100, "{differ}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn random_csg_scenes_agree_in_three_models(text in random_scene(), view in 0..3usize) {
        let view = [View::Top, View::Front, View::Iso][view];
        check_drawn(&text, view, 40, false);
    }
}
