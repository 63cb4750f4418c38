//! §5.3.1: polygons and lines through the array, against the float model and their area.

use csgpix_draw::compile::scene_ops;
use csgpix_draw::float::{self, rounding_bound, ScreenRule};
use csgpix_draw::polygon::{line, polygon, Support};
use csgpix_scene::display_list::DisplayList;
use rtl_model::program::CReg;
use rtl_model::{Array, ArrayConfig, CycleArray, Equations, WordArray};

/// Lit pixels of the hardware and of float; every pixel where they differ is a near tie.
fn lit(lists: &[DisplayList], size: usize) -> (usize, usize) {
    let cfg = ArrayConfig::new(size, size);
    let ops = scene_ops(lists, &cfg.fmt, cfg.colour_bits).unwrap();
    let mut c = CycleArray::new(cfg, Equations::Derived.set());
    let mut w = WordArray::new(cfg, Equations::Derived.set());
    c.run(&ops).unwrap();
    w.run(&ops).unwrap();
    let st = w.state();
    assert_eq!(c.state(), st);
    let f = float::render(lists, None, size, size, &cfg.fmt, ScreenRule::Exact);
    for (i, p) in st.pixels.iter().enumerate() {
        let bound = 2.0 * rounding_bound(&cfg.fmt, i % size, i / size);
        let g = p.creg(CReg::G);
        assert!(
            g == f.colour[i] || f.margin[i] < bound,
            "pixel {i}: {g} vs {} margin {}",
            f.colour[i],
            f.margin[i]
        );
    }
    let hw = st.pixels.iter().filter(|p| p.creg(CReg::G) != 0).count();
    (hw, f.colour.iter().filter(|c| **c != 0).count())
}

#[test]
fn a_triangle_covers_its_area() {
    let s = Support {
        z0: 40.0,
        dzx: 0.25,
        dzy: -0.1,
    };
    let tri = polygon(s, 2, &[(4.5, 4.5), (60.5, 10.5), (20.5, 50.5)]).unwrap();
    let (hw, fl) = lit(&[tri], 64);
    // Shoelace area: 1/2 |56·46 - 16·6| = 1240 pixels, give or take the edge pixels.
    for n in [hw, fl] {
        assert!((n as f64 - 1240.0).abs() < 60.0, "{hw} {fl}");
    }
}

#[test]
fn a_one_pixel_line_is_one_pixel_wide() {
    let s = Support {
        z0: 10.0,
        dzx: 0.0,
        dzy: 0.0,
    };
    let l = line(s, 4, (5.0, 20.25), (55.0, 20.25), 1.0).unwrap();
    let (hw, fl) = lit(&[l], 64);
    assert_eq!((hw, fl), (51, 51));
}
