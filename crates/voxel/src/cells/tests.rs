use super::*;
use proptest::prelude::*;

#[test]
fn the_logic_keeps_unknown_constants_and_mixtures_apart() {
    use Class::*;
    // A constant of unknown value stays constant under every operator…
    for c in [Out, In, Unif] {
        assert_ne!(Unif.or(c), Mixed);
        assert_ne!(Unif.and(c), Mixed);
    }
    // …but may not hide a mixed primitive, which an In (or an Out) does.
    assert_eq!(Unif.or(Mixed), Mixed);
    assert_eq!(In.or(Mixed), In);
    assert_eq!(Out.and(Mixed), Out);
    assert_eq!(Mixed.not(), Mixed);
    assert_eq!(In.not(), Out);
}

#[test]
fn a_segment_crosses_a_triangle_once_misses_it_or_is_unsure_on_its_edge() {
    let t = [DVec3::ZERO, DVec3::X * 4.0, DVec3::Y * 4.0];
    let through = crosses(&t, DVec3::new(1.0, 1.0, -1.0), DVec3::new(1.0, 1.0, 1.0));
    assert_eq!(through, Crossing::Once);
    let beside = crosses(&t, DVec3::new(3.0, 3.0, -1.0), DVec3::new(3.0, 3.0, 1.0));
    assert_eq!(beside, Crossing::No);
    let short = crosses(&t, DVec3::new(1.0, 1.0, 0.5), DVec3::new(1.0, 1.0, 1.0));
    assert_eq!(short, Crossing::No);
    let edge = crosses(&t, DVec3::new(2.0, 0.0, -1.0), DVec3::new(2.0, 0.0, 1.0));
    assert_eq!(edge, Crossing::Unsure);
}

#[test]
fn faces_along_z_are_exact_and_level_faces_move_by_the_words_rounding() {
    let t = Tolerance {
        slab_raw: 2048.0,
        pixels: [512.0, 512.0],
        half: 0.0,
        steep: 0.5,
        range: 512.0,
        slope: 1000.0,
    };
    assert!(t.plane(DVec3::X) < 1e-3);
    assert!(t.plane(DVec3::new(0.6, 0.8, 0.0)) < 1e-3);
    // A level face: its slopes are 0, held exactly; Z0 rounds, Vz is one unit.
    let level = t.plane(DVec3::Z);
    assert!(level > 2.0 / 2048.0 && level < 1e-2, "{level}");
    // A sloped face: its slopes round too, by up to half a unit each, across the array.
    let sloped = t.plane(DVec3::new(0.3, 0.2, 0.9).normalize());
    assert!(sloped > level && sloped < 1.0, "{sloped}");
}

proptest! {
    /// Whatever point of a triangle lies in a box, the box is taken to meet it.
    #[test]
    fn a_box_holding_a_point_of_a_triangle_meets_it(
        t in prop::array::uniform3(prop::array::uniform3(-4.0..4.0f64)),
        c in prop::array::uniform3(-4.0..4.0f64),
        h in prop::array::uniform3(0.0..2.0f64),
        w in prop::array::uniform3(0.0..1.0f64),
    ) {
        let t = t.map(DVec3::from);
        let (c, h) = (DVec3::from(c), DVec3::from(h));
        let s = w[0] + w[1] + w[2] + 1e-9;
        let p = (t[0] * w[0] + t[1] * w[1] + t[2] * w[2]) / s;
        let inside = (0..3).all(|a| (p[a] - c[a]).abs() <= h[a]);
        prop_assert!(!inside || meets_triangle(&t, c, h));
    }
}
