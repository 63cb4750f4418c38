//! Helpers shared by csgpix-draw's integration tests: random `.csg` scenes.
// Each test crate uses only some of these.
#![allow(dead_code)]

use proptest::prelude::*;
use std::f64::consts::PI;

/// A primitive of the `.csg` subset, placed by a random rotation and shift.
pub fn primitive() -> impl Strategy<Value = String> {
    let shape = prop_oneof![
        (2.0..12.0f64, 2.0..12.0f64, 2.0..12.0f64)
            .prop_map(|(a, b, c)| format!("cube(size = [{a:.3}, {b:.3}, {c:.3}], center = true);")),
        (3usize..14, 1.0..6.0f64).prop_map(|(n, r)| format!("sphere($fn = {n}, r = {r:.3});")),
        (3usize..14, 2.0..10.0f64, 0.0..5.0f64, 1.0..5.0f64).prop_map(|(n, h, r1, r2)| format!(
            "cylinder($fn = {n}, h = {h:.3}, r1 = {r1:.3}, r2 = {r2:.3}, center = true);"
        )),
    ];
    (shape, -PI..PI, -PI..PI, prop::array::uniform3(-4.0..4.0f64)).prop_map(|(shape, a, b, t)| {
        // Rotation about z by a, then about x by b.
        let (ca, sa, cb, sb) = (a.cos(), a.sin(), b.cos(), b.sin());
        let m = [
            [ca, -sa, 0.0, t[0]],
            [sa * cb, ca * cb, -sb, t[1]],
            [sa * sb, ca * sb, cb, t[2]],
        ];
        let row = |r: [f64; 4]| format!("[{:.6}, {:.6}, {:.6}, {:.6}]", r[0], r[1], r[2], r[3]);
        format!(
            "multmatrix([{}, {}, {}, [0, 0, 0, 1]]) {{ {shape} }}",
            row(m[0]),
            row(m[1]),
            row(m[2])
        )
    })
}

pub fn random_scene() -> impl Strategy<Value = String> {
    let op = prop_oneof![Just("union"), Just("difference"), Just("intersection")];
    (op, prop::collection::vec(primitive(), 1..4))
        .prop_map(|(op, kids)| format!("{op}() {{\n{}\n}}\n", kids.join("\n")))
}
