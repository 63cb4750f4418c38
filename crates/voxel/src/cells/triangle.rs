//! A closed mesh's triangles as the walk tests them: whether a segment crosses one (the
//! parity that carries a point's side down the walk), and whether a box may meet one.

use glam::DVec3;

/// Whether the segment p → q crosses the triangle: once, not at all, or too near an edge, a
/// vertex or its plane to tell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Crossing {
    Once,
    No,
    Unsure,
}

pub(super) fn crosses(t: &[DVec3; 3], p: DVec3, q: DVec3) -> Crossing {
    let lo = t[0].min(t[1]).min(t[2]);
    let hi = t[0].max(t[1]).max(t[2]);
    let (slo, shi) = (p.min(q), p.max(q));
    if (0..3).any(|a| lo[a] > shi[a] + 1e-9 || hi[a] < slo[a] - 1e-9) {
        return Crossing::No;
    }
    // Signed volumes, each against a tolerance of its own scale.
    let vol = |a: DVec3, b: DVec3, c: DVec3, d: DVec3| {
        let (u, v, w) = (b - a, c - a, d - a);
        let x = u.cross(v).dot(w);
        let tol = 1e-9 * u.length() * v.length() * w.length() + 1e-300;
        if x > tol {
            1
        } else if x < -tol {
            -1
        } else {
            0
        }
    };
    let (sp, sq) = (vol(t[0], t[1], t[2], p), vol(t[0], t[1], t[2], q));
    if sp != 0 && sp == sq {
        return Crossing::No;
    }
    let edges = [
        vol(p, q, t[0], t[1]),
        vol(p, q, t[1], t[2]),
        vol(p, q, t[2], t[0]),
    ];
    if edges.contains(&1) && edges.contains(&-1) {
        return Crossing::No;
    }
    if sp == 0 || sq == 0 || edges.contains(&0) {
        return Crossing::Unsure;
    }
    Crossing::Once
}

/// Does the box (centre c, half sizes h) perhaps meet the triangle? The separating axis
/// test (the box's axes, the triangle's normal, and the 9 products of their edges), each
/// axis given a little slack.
pub(super) fn meets_triangle(t: &[DVec3; 3], c: DVec3, h: DVec3) -> bool {
    let lo = t[0].min(t[1]).min(t[2]);
    let hi = t[0].max(t[1]).max(t[2]);
    if (0..3).any(|a| lo[a] > c[a] + h[a] || hi[a] < c[a] - h[a]) {
        return false;
    }
    let v = t.map(|p| p - c);
    let e = [v[1] - v[0], v[2] - v[1], v[0] - v[2]];
    let separates = |axis: DVec3| {
        let r = axis.abs().dot(h);
        let p = v.map(|q| axis.dot(q));
        let (mn, mx) = (p[0].min(p[1]).min(p[2]), p[0].max(p[1]).max(p[2]));
        let slack = 1e-9 * (axis.length() * (r.abs() + mx.abs().max(mn.abs())) + 1e-12);
        mn > r + slack || mx < -r - slack
    };
    if separates(e[0].cross(e[1])) {
        return false;
    }
    for edge in e {
        for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
            let a = axis.cross(edge);
            if a != DVec3::ZERO && separates(a) {
                return false;
            }
        }
    }
    true
}
