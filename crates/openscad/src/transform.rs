//! `multmatrix` and `color`: transforms and colours the solids below a node inherit.

use crate::{lex::*, linalg::*, node::*, value::*};

/// `multmatrix(m)`: 3 or 4 rows of 4 numbers, the last row `[0, 0, 0, w]` with the matrix
/// divided by `w` as OpenSCAD does; a singular linear part is refused.
pub(crate) fn matrix(params: &Params) -> Result<Option<Mat4>, Fail> {
    let Some(value) = params.get("m") else {
        return Ok(None);
    };
    let rows = value.list("`m`")?;
    if !(3..=4).contains(&rows.len()) {
        return fail(value.pos, "`m` must have 4 rows of 4 numbers");
    }
    let mut m = IDENTITY;
    for (row, cells) in m.iter_mut().zip(rows) {
        let [a, b, c, d] = cells.list("a row of `m`")? else {
            return fail(cells.pos, "a row of `m` must have 4 numbers");
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

/// Divides by `m[3][3]` and checks the matrix is affine and invertible.
pub(crate) fn normalise(mut m: Mat4, pos: Pos) -> Result<Mat4, Fail> {
    if m[3][..3].iter().any(|&v| v != 0.0) {
        return fail(
            pos,
            "projective matrices are not supported: the last row of `m` must be [0, 0, 0, w]",
        );
    }
    let w = m[3][3];
    if w == 0.0 {
        return fail(pos, "the last entry of `m` must not be 0");
    }
    if w != 1.0 {
        m = m.map(|row| row.map(|v| v / w));
    }
    let size = m[..3]
        .iter()
        .flat_map(|row| &row[..3])
        .fold(0.0_f64, |a, v| a.max(v.abs()));
    let det = det3(&m);
    let invertible = det.abs() > 1e-12 * size * size * size;
    if !invertible {
        return fail(
            pos,
            format!("singular matrix (determinant {det:e}): it flattens the solids"),
        );
    }
    Ok(m)
}

/// `color(c, alpha)`: `c` is `[r, g, b]` or `[r, g, b, a]` (alpha 1 if missing, as in
/// OpenSCAD's `builtin_color`), components in 0..1; `alpha` overrides the fourth.
pub(crate) fn colour(params: &Params) -> Result<[f64; 4], Fail> {
    let c = params.require("c", "a colour [r, g, b, a]")?;
    let items = match &c.kind {
        Kind::Str(name) => {
            let msg = format!(
                "colour \"{name}\" is not supported: give it as color([r, g, b, a]), \
                 as OpenSCAD's CSG export writes it"
            );
            return fail(c.pos, msg);
        }
        Kind::List(items) if (3..=4).contains(&items.len()) => items,
        _ => return fail(c.pos, "`c` must be [r, g, b] or [r, g, b, a]"),
    };
    let mut rgba = [1.0; 4];
    for (slot, item) in rgba.iter_mut().zip(items) {
        *slot = unit(item.number("a colour component")?, item.pos)?;
    }
    if let Some((alpha, pos)) = params.number("alpha")? {
        rgba[3] = unit(alpha, pos)?;
    }
    Ok(rgba)
}

pub(crate) fn unit(v: f64, pos: Pos) -> Result<f64, Fail> {
    if (0.0..=1.0).contains(&v) {
        Ok(v)
    } else {
        fail(
            pos,
            format!("colour components must be between 0 and 1, found {v}"),
        )
    }
}
