//! `multmatrix` and `color`: transforms and colours the solids below a node inherit.

use csgpix_scene::error::{CsgError, Rule};

use crate::{lex::*, linalg::*, node::*, value::*};

/// `multmatrix(m)`: 3 or 4 rows of 4 numbers, the last row `[0, 0, 0, w]` with the matrix
/// divided by `w` as OpenSCAD does; a singular linear part is refused.
pub(crate) fn matrix(params: &Params) -> Result<Option<Mat4>, Fail> {
    let Some(value) = params.get("m") else {
        return Ok(None);
    };
    let rows = value.list("`m`")?;
    if !(3..=4).contains(&rows.len()) {
        return fail(value.pos, must("`m`", Rule::MatrixRows));
    }
    let mut m = IDENTITY;
    for (row, cells) in m.iter_mut().zip(rows) {
        let [a, b, c, d] = cells.list("a row of `m`")? else {
            return fail(cells.pos, must("a row of `m`", Rule::MatrixRow));
        };
        let entry = "an entry of `m`";
        *row = [
            a.number(entry)?,
            b.number(entry)?,
            c.number(entry)?,
            d.number(entry)?,
        ];
    }
    normalise(m, value.pos).map(Some)
}

/// Divides by `m[3][3]` and checks the matrix is affine. A singular matrix, or one holding an
/// infinity or NaN (`w = 0` gives those), is read: the objects it places are removed where
/// they are placed ([`removal_3d`], [`removal_2d`]), as OpenSCAD removes them.
pub(crate) fn normalise(mut m: Mat4, pos: Pos) -> Result<Mat4, Fail> {
    if m[3][..3].iter().any(|&v| v != 0.0) {
        return fail(pos, CsgError::ProjectiveMatrix);
    }
    let w = m[3][3];
    if w != 1.0 {
        m = m.map(|row| row.map(|v| v / w));
    }
    Ok(m)
}

/// Why OpenSCAD removes a 3D object placed by `m`, if it does: a matrix holding NaN or an
/// infinity (`GeometryEvaluator::visit(TransformNode)`), or a singular one, which flattens
/// the object (`CGAL_Nef_polyhedron::transform`). The messages are OpenSCAD's.
pub(crate) fn removal_3d(m: Option<&Mat4>) -> Option<&'static str> {
    let m = m?;
    if m.iter().flatten().any(|v| !v.is_finite()) {
        return Some(NOT_FINITE);
    }
    let rows = [0, 1, 2].map(|r| [m[r][0], m[r][1], m[r][2]]);
    singular(&rows).then_some("Scaling a 3D object with 0 - removing object")
}

/// [`removal_3d`] for a 2D object, placed by the plane part of `m` (`Polygon2d::transform`).
pub(crate) fn removal_2d(m: Option<&Mat4>) -> Option<&'static str> {
    let m = m?;
    let [[a, b, tx], [c, d, ty]] = plane_part(Some(m));
    if [a, b, tx, c, d, ty].iter().any(|v| !v.is_finite()) {
        return Some(NOT_FINITE);
    }
    let rows = [[a, b, 0.0], [c, d, 0.0], [0.0, 0.0, 1.0]];
    singular(&rows).then_some("Scaling a 2D object with 0 - removing object")
}

const NOT_FINITE: &str =
    "Transformation matrix contains Not-a-Number and/or Infinity - removing object.";

/// A determinant that is zero within rounding, relative to the matrix's largest entry.
fn singular(rows: &[[f64; 3]; 3]) -> bool {
    let size = rows.iter().flatten().fold(0.0_f64, |a, v| a.max(v.abs()));
    let m = [
        [rows[0][0], rows[0][1], rows[0][2], 0.0],
        [rows[1][0], rows[1][1], rows[1][2], 0.0],
        [rows[2][0], rows[2][1], rows[2][2], 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    det3(&m).abs() <= 1e-12 * size * size * size
}

/// `color(c, alpha)`: `c` is `[r, g, b]` or `[r, g, b, a]` (alpha 1 if missing, as in
/// OpenSCAD's `builtin_color`), components in 0..1; `alpha` overrides the fourth. A component
/// out of range is OpenSCAD's warning (`ColorModule::instantiate`) and is clamped to 0..1 for
/// the colour code; the geometry does not change.
pub(crate) fn colour(params: &Params, warnings: &mut Vec<(Pos, String)>) -> Result<[f64; 4], Fail> {
    let c = params.require("c", "a colour [r, g, b, a]")?;
    let items = match &c.kind {
        Kind::Str(name) => {
            let name = name.clone();
            return fail(c.pos, CsgError::NamedColour { name });
        }
        Kind::List(items) if (3..=4).contains(&items.len()) => items,
        _ => return fail(c.pos, must("`c`", Rule::Rgba)),
    };
    let mut rgba = [1.0; 4];
    for (slot, item) in rgba.iter_mut().zip(items) {
        *slot = unit(item.number("a colour component")?, item.pos, warnings);
    }
    if let Some((alpha, pos)) = params.number("alpha")? {
        rgba[3] = unit(alpha, pos, warnings);
    }
    Ok(rgba)
}

/// A colour component clamped to 0..1, with OpenSCAD's warning when it was not in range.
pub(crate) fn unit(v: f64, pos: Pos, warnings: &mut Vec<(Pos, String)>) -> f64 {
    if (0.0..=1.0).contains(&v) {
        return v;
    }
    let msg = format!(
        "color() expects numbers between 0.0 and 1.0. Value of {v:?} is out of range (taken as {})",
        if v > 1.0 { 1 } else { 0 }
    );
    warnings.push((pos, msg));
    if v > 1.0 {
        1.0
    } else {
        0.0
    }
}
