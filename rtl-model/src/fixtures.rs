//! Programs the unit tests of several blocks run.

use crate::program::Coeffs;
use crate::Op;

/// A front and a back plane, a clipping plane with NOT and apply, close and compose.
pub fn program() -> Vec<Op> {
    let plane = |c0, dx, dy, colour, h| Op::Plane {
        coeffs: Coeffs { c0, dx, dy },
        colour,
        interior: 5,
        l: false,
        s: true,
        h,
        y: false,
    };
    vec![
        plane(40 << 10, 300, -200, 2, true),
        plane(90 << 10, -100, 400, 3, false),
        Op::Close { l: false },
        Op::ClipPlane {
            coeffs: Coeffs {
                c0: 60 << 10,
                dx: 500,
                dy: 0,
            },
            h: true,
            y: false,
            x: false,
        },
        Op::ClipNot,
        Op::ClipApply,
        Op::Compose { p: true },
    ]
}
