//! From a display list (§5.2) to the operations the array runs.
//!
//! An object is its planes in file order, then the close stage (position 3) when it has back
//! planes, then the second stage (position 4) composing it into the scene in C. S, the "first
//! plane" external, is set on the first plane that writes each register: the first front or
//! perpendicular plane (F) and the first back plane (B). The thesis's S=1 rows exist exactly so
//! that a register's reset word (maxdepth) never takes part in a comparison; an object whose
//! back planes came after a front plane would otherwise keep maxdepth in B (docs/decisions.md).

use rtl_model::program::{Coeffs, Op};
use rtl_model::WordFormat;

use crate::display_list::DisplayList;

/// The colour Put 0 writes when a front plane is clipped by the screen: the object's inside.
/// Code 7 is light grey in the palette (`src/palette.rs`).
pub const INTERIOR_COLOUR: u32 = 7;

/// A plane the array cannot take, located by plane index (0-based) and field (0-based: Z0,
/// dZx, dZy, colour) so the caller can point at the file position.
#[derive(Clone, Debug, PartialEq)]
pub struct CompileError {
    pub plane: usize,
    pub field: usize,
    pub msg: String,
}

impl std::fmt::Display for CompileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "plane {}: {}", self.plane + 1, self.msg)
    }
}

/// Quantize one plane's coefficients to raw depth words; `Err` names the field (0, 1, 2).
pub fn coeffs(fmt: &WordFormat, z0: f64, dzx: f64, dzy: f64) -> Result<Coeffs, (usize, String)> {
    let names = ["Z0", "dZx", "dZy"];
    let q = |i: usize, v: f64| {
        fmt.quantize(v)
            .map_err(|e| (i, format!("{}: {e}", names[i])))
    };
    Ok(Coeffs {
        c0: q(0, z0)?,
        dx: q(1, dzx)?,
        dy: q(2, dzy)?,
    })
}

/// The operations that draw one object into F (not yet composed).
pub fn object_ops(
    dl: &DisplayList,
    fmt: &WordFormat,
    colour_bits: u32,
) -> Result<Vec<Op>, CompileError> {
    let max_colour = (1u64 << colour_bits) - 1;
    let (mut front_seen, mut back_seen) = (false, false);
    let mut ops = Vec::with_capacity(dl.planes.len() + 1);
    for (i, p) in dl.planes.iter().enumerate() {
        if p.colour as u64 > max_colour {
            return Err(CompileError {
                plane: i,
                field: 3,
                msg: format!(
                    "colour {} does not fit {colour_bits}-bit colour registers",
                    p.colour
                ),
            });
        }
        let front = p.h || p.y;
        let seen = if front {
            &mut front_seen
        } else {
            &mut back_seen
        };
        let s = !*seen;
        *seen = true;
        ops.push(Op::Plane {
            coeffs: coeffs(fmt, p.z0, p.dzx, p.dzy).map_err(|(field, msg)| CompileError {
                plane: i,
                field,
                msg,
            })?,
            colour: p.colour,
            interior: INTERIOR_COLOUR,
            l: p.l,
            s,
            h: p.h,
            y: p.y,
        });
    }
    if back_seen {
        ops.push(Op::Close { l: dl.is_concave() });
    }
    Ok(ops)
}

/// Draw every object and compose each into the scene (second stage, P = 0). An error names
/// the list it came from.
pub fn scene_ops(
    lists: &[DisplayList],
    fmt: &WordFormat,
    colour_bits: u32,
) -> Result<Vec<Op>, (usize, CompileError)> {
    let mut ops = vec![];
    for (i, dl) in lists.iter().enumerate() {
        ops.extend(object_ops(dl, fmt, colour_bits).map_err(|e| (i, e))?);
        ops.push(Op::Compose { p: false });
    }
    Ok(ops)
}
