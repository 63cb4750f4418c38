//! The arithmetic every node family shares: points, `multmatrix` matrices, triangles, the
//! signed area of an outline and OpenSCAD's degree trigonometry (exact at multiples of 30° and
//! 45°, as `src/utils/degree_trig.cc`). It depends on nothing else in the crate.

use glam::{DVec2, DVec3};
use std::f64::consts::FRAC_1_SQRT_2;

/// A point or direction in scene units.
pub(crate) type Vec3 = [f64; 3];

/// A `multmatrix` matrix, row-major; the last row is `[0, 0, 0, 1]` once normalised.
pub(crate) type Mat4 = [[f64; 4]; 4];

/// The matrix that leaves every point where it is.
pub(crate) const IDENTITY: Mat4 = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// `a · b`: `b` applied first.
pub(crate) fn mat_mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut out = [[0.0; 4]; 4];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    out
}

/// The determinant of the linear part: negative for a mirror.
pub(crate) fn det3(m: &Mat4) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// `m` applied to the point `p`.
pub(crate) fn transform_point(m: &Mat4, p: Vec3) -> Vec3 {
    let row = |r: &[f64; 4]| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3];
    [row(&m[0]), row(&m[1]), row(&m[2])]
}

/// The plane part (x, y) of a transform, for 2D shapes.
pub(crate) fn plane_part(m: Option<&Mat4>) -> [[f64; 3]; 2] {
    let m = m.unwrap_or(&IDENTITY);
    [[m[0][0], m[0][1], m[0][3]], [m[1][0], m[1][1], m[1][3]]]
}

/// The cross product `a × b`.
pub(crate) fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a − b`.
pub(crate) fn sub(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a · b`.
pub(crate) fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The length of `a`.
pub(crate) fn norm(a: Vec3) -> f64 {
    dot(a, a).sqrt()
}

// ---------------------------------------------------------------------------------------------
// Trigonometry in degrees, as OpenSCAD's `src/utils/degree_trig.cc`

/// `sqrt(3) / 2`, OpenSCAD's `M_SQRT3_4`.
pub(crate) const SQRT3_4: f64 = 0.866_025_403_784_438_6;

/// Reduces to `[0, 360)`.
pub(crate) fn reduce_degrees(x: f64) -> f64 {
    if (0.0..360.0).contains(&x) {
        x
    } else {
        x - 360.0 * (x / 360.0).floor()
    }
}

/// `sin_degrees`: exact at multiples of 30° and 45°.
pub(crate) fn sin_degrees(x: f64) -> f64 {
    let mut x = reduce_degrees(x);
    let oppose = x >= 180.0;
    if oppose {
        x -= 180.0;
    }
    if x > 90.0 {
        x = 180.0 - x;
    }
    let s = if x < 45.0 {
        if x == 30.0 {
            0.5
        } else {
            x.to_radians().sin()
        }
    } else if x == 45.0 {
        FRAC_1_SQRT_2
    } else if x == 60.0 {
        SQRT3_4
    } else {
        (90.0 - x).to_radians().cos()
    };
    if oppose {
        -s
    } else {
        s
    }
}

/// `cos_degrees`: exact at multiples of 30° and 45°.
pub(crate) fn cos_degrees(x: f64) -> f64 {
    let mut x = reduce_degrees(x);
    let mut oppose = x >= 180.0;
    if oppose {
        x -= 180.0;
    }
    if x > 90.0 {
        x = 180.0 - x;
        oppose = !oppose;
    }
    let c = if x > 45.0 {
        if x == 60.0 {
            0.5
        } else {
            (90.0 - x).to_radians().sin()
        }
    } else if x == 45.0 {
        FRAC_1_SQRT_2
    } else if x == 30.0 {
        SQRT3_4
    } else {
        x.to_radians().cos()
    };
    if oppose {
        -c
    } else {
        c
    }
}

/// `sin_degrees` and `cos_degrees` of an angle.
pub(crate) fn sin_cos_degrees(a: f64) -> (f64, f64) {
    (sin_degrees(a), cos_degrees(a))
}

/// A triangle in scene units.
pub type Tri3 = [DVec3; 3];

/// The signed area of an outline (positive counter-clockwise).
pub fn signed_area(p: &[DVec2]) -> f64 {
    (0..p.len())
        .map(|i| p[i].perp_dot(p[(i + 1) % p.len()]))
        .sum::<f64>()
        / 2.0
}
