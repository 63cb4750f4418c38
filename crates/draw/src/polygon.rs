//! Polygons and lines (§5.3.1): a plane clipped by perpendicular planes. An N-sided convex
//! polygon is N + 1 planes: the plane it lies in, then one perpendicular plane per edge whose
//! K is the signed distance in pixels from the edge (K ≥ 0 inside). A line is a thin
//! rectangle: four perpendicular planes around the segment.

use csgpix_scene::display_list::{DisplayList, DlPlane};

use crate::{Error, Result};

/// The plane a polygon lies in: depth Z0 + x·dZx + y·dZy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Support {
    /// Depth at pixel (0, 0).
    pub z0: f64,
    /// Depth step per pixel along x.
    pub dzx: f64,
    /// Depth step per pixel along y.
    pub dzy: f64,
}

fn perpendicular(a: (f64, f64), b: (f64, f64), inside_left: bool) -> Option<DlPlane> {
    let (ex, ey) = (b.0 - a.0, b.1 - a.1);
    let len = (ex * ex + ey * ey).sqrt();
    if len < 1e-12 {
        return None;
    }
    // Left normal of the edge (screen y points down, the formula is the same).
    let s = if inside_left { 1.0 } else { -1.0 };
    let (nx, ny) = (-ey / len * s, ex / len * s);
    Some(DlPlane {
        z0: -(nx * a.0 + ny * a.1),
        dzx: nx,
        dzy: ny,
        colour: 0,
        h: false,
        y: true,
        l: false,
    })
}

/// A convex polygon with vertices in pixel coordinates, in either winding.
pub fn polygon(support: Support, colour: u32, vertices: &[(f64, f64)]) -> Result<DisplayList> {
    if vertices.len() < 3 {
        return Err(Error::TooFewVertices {
            got: vertices.len(),
        });
    }
    let n = vertices.len();
    let cross = |i: usize| {
        let (a, b, c) = (vertices[i], vertices[(i + 1) % n], vertices[(i + 2) % n]);
        (b.0 - a.0) * (c.1 - b.1) - (b.1 - a.1) * (c.0 - b.0)
    };
    let turns: Vec<f64> = (0..n).map(cross).collect();
    let left = turns.iter().any(|t| *t > 0.0);
    if turns.iter().any(|t| *t > 0.0) && turns.iter().any(|t| *t < 0.0) {
        return Err(Error::NotConvex);
    }
    let mut planes = vec![DlPlane {
        z0: support.z0,
        dzx: support.dzx,
        dzy: support.dzy,
        colour,
        h: true,
        y: false,
        l: false,
    }];
    planes.extend((0..n).filter_map(|i| perpendicular(vertices[i], vertices[(i + 1) % n], left)));
    if planes.len() < 4 {
        return Err(Error::NoArea);
    }
    Ok(DisplayList {
        planes,
        terminator: 1234,
    })
}

/// A line from `a` to `b`, `width` pixels wide, as a thin rectangle in the support plane.
pub fn line(
    support: Support,
    colour: u32,
    a: (f64, f64),
    b: (f64, f64),
    width: f64,
) -> Result<DisplayList> {
    let (ex, ey) = (b.0 - a.0, b.1 - a.1);
    let len = (ex * ex + ey * ey).sqrt();
    if len < 1e-12 || width <= 0.0 {
        return Err(Error::BadLine);
    }
    let (nx, ny) = (-ey / len * width / 2.0, ex / len * width / 2.0);
    let corners = [
        (a.0 + nx, a.1 + ny),
        (b.0 + nx, b.1 + ny),
        (b.0 - nx, b.1 - ny),
        (a.0 - nx, a.1 - ny),
    ];
    polygon(support, colour, &corners)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_is_four_planes_inside_positive() {
        let s = Support {
            z0: 10.0,
            dzx: 0.1,
            dzy: 0.0,
        };
        for verts in [
            [(0.0, 0.0), (10.0, 0.0), (0.0, 10.0)],
            [(0.0, 0.0), (0.0, 10.0), (10.0, 0.0)],
        ] {
            let dl = polygon(s, 2, &verts).unwrap();
            assert_eq!(dl.planes.len(), 4);
            let inside = |x: f64, y: f64| {
                dl.planes[1..]
                    .iter()
                    .all(|p| p.z0 + x * p.dzx + y * p.dzy >= 0.0)
            };
            assert!(inside(2.0, 2.0) && inside(0.0, 0.0) && inside(5.0, 5.0));
            assert!(
                !inside(20.0, 20.0)
                    && !inside(-1.0, 3.0)
                    && !inside(3.0, -1.0)
                    && !inside(6.0, 6.0)
            );
        }
        assert!(polygon(s, 2, &[(0.0, 0.0), (10.0, 0.0), (2.0, 2.0), (0.0, 10.0)]).is_err());
        assert!(polygon(s, 2, &[(0.0, 0.0), (1.0, 0.0)]).is_err());
    }
}
