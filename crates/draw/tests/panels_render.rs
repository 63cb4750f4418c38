//! Rendering on panels (§2.5) gives the whole screen's image: every panel runs only the solids
//! binned to it, moved to its origin, and panels no solid touches are not simulated at all.

use csgpix_draw::compile::clip_scene_ops;
use csgpix_draw::panels::{render_on_panels, PanelScene};
use csgpix_draw::project::{project, View};
use csgpix_openscad::parse_csg;
use csgpix_scene::solid::CsgScene;
use csgpix_testkit::random_scene;
use proptest::prelude::*;
use rtl_model::program::{CReg, Reg};
use rtl_model::{Array, ArrayConfig, CycleArray, Equations, WordArray, WordFormat};

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn scene(name: &str) -> CsgScene {
    let path = format!("{ROOT}/vectors/scenes/{name}.csg");
    parse_csg(&std::fs::read_to_string(path).unwrap(), name).unwrap()
}

/// What `render` draws: the projected scene's program on one screen-sized array.
fn whole(s: &CsgScene, view: View, screen: (usize, usize), cycle: bool) -> (Vec<u32>, Vec<i64>) {
    let fmt = WordFormat::THESIS;
    let cfg = ArrayConfig {
        fmt,
        ..ArrayConfig::new(screen.0, screen.1)
    };
    let p = project(s, view, screen.0, screen.1, &fmt).unwrap();
    let ops = match &p.clip {
        Some(clip) => clip_scene_ops(&p.lists, clip, &fmt, cfg.colour_bits).unwrap(),
        None => vec![],
    };
    let set = Equations::Derived.set();
    let mut arr: Box<dyn Array> = if cycle {
        Box::new(CycleArray::new(cfg, set))
    } else {
        Box::new(WordArray::new(cfg, set))
    };
    arr.run(&ops).unwrap();
    let st = arr.state();
    (
        st.pixels.iter().map(|p| p.creg(CReg::G)).collect(),
        st.pixels.iter().map(|p| p.reg(Reg::C)).collect(),
    )
}

/// Panels against the whole screen; returns the share of pixel-clocks simulated.
fn check(
    s: &CsgScene,
    view: View,
    screen: (usize, usize),
    panel: (usize, usize),
    cycle: bool,
) -> f64 {
    let ps = PanelScene::new(s, view, screen, WordFormat::THESIS).unwrap();
    let img = render_on_panels(&ps, panel, cycle, &Equations::Derived.set()).unwrap();
    let (colour, depth) = whole(s, view, screen, cycle);
    let differ = (0..colour.len())
        .filter(|&i| (img.colour[i], img.depth[i]) != (colour[i], depth[i]))
        .count();
    assert_eq!(
        differ, 0,
        "{view:?} {screen:?} {panel:?}: {differ} pixels differ"
    );
    let cfg = ps.panel_config(screen);
    let full =
        rtl_model::array::program_cycles(&cfg, &ps.frame_ops(&vec![true; ps.lists.len()]).unwrap())
            * cfg.pixels() as u64;
    img.simulated_pixel_clocks as f64 / full.max(1) as f64
}

#[test]
fn every_example_on_panels_is_the_whole_screen() {
    for name in [
        "figure-5.2",
        "hollow-cube",
        "cube-minus-cylinder",
        "twelve",
        "csg-logo",
    ] {
        let s = scene(name);
        for view in [View::Top, View::Front, View::Iso] {
            for panel in [(16, 16), (24, 10)] {
                let share = check(&s, view, (64, 48), panel, false);
                println!("{name} {view:?} 64x48 on {panel:?} panels: {share:.3} of the whole screen's pixel-clocks");
            }
        }
    }
    // The cycle model too, once per scene.
    for name in ["figure-5.2", "twelve"] {
        check(&scene(name), View::Iso, (40, 40), (16, 16), true);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn random_scenes_on_panels_are_the_whole_screen(
        text in random_scene(),
        view in 0..3usize,
        pw in 4usize..24,
        ph in 4usize..24,
    ) {
        let s = parse_csg(&text, "random").unwrap();
        let view = [View::Top, View::Front, View::Iso][view];
        check(&s, view, (40, 36), (pw, ph), false);
    }
}
