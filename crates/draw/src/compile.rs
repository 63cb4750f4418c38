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

use csgpix_scene::clip_expr::Clip;
use csgpix_scene::display_list::{DisplayList, DlPlane};

/// The colour Put 0 writes when a front plane is clipped by the screen: the object's inside.
/// Code 7 is light grey in the palette (`src/palette.rs`).
pub const INTERIOR_COLOUR: u32 = 7;

/// A plane the array cannot take, located by plane index (0-based) and field (0-based: Z0,
/// dZx, dZy, colour) so the caller can point at the file position.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CompileError {
    /// Index of the plane in its display list (0-based).
    pub plane: usize,
    /// The field at fault, 0-based in the plane's row (0 Z0, 1 dZx, 2 dZy, 3 colour, …),
    /// or [`WHOLE_PROGRAM`].
    pub field: usize,
    /// What is wrong, one line.
    pub msg: String,
}

impl std::fmt::Display for CompileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.field {
            WHOLE_PROGRAM | WHOLE_LIST => f.write_str(&self.msg),
            _ => write!(f, "plane {}: {}", self.plane + 1, self.msg),
        }
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

/// Refuse a plane whose value leaves the word somewhere on a `width`×`height` window.
///
/// Each coefficient may fit the word while `Z0 + x·dZx + y·dZy` does not: DEPGEN's adders keep
/// N_D bits and wrap (docs/depth-word.md), so such a plane would reach the pixels with the
/// wrong sign, far beyond the display read as in front of the screen. The value is linear,
/// so its extremes are at the window's corners; they are computed from the quantized
/// coefficients, exactly as DEPGEN sums them. Errors name the list, the plane and the field
/// (Z0) of the offending plane.
pub fn check_window(
    lists: &[DisplayList],
    fmt: &WordFormat,
    width: usize,
    height: usize,
) -> Result<(), (usize, CompileError)> {
    let (xm, ym) = (
        width.saturating_sub(1) as i128,
        height.saturating_sub(1) as i128,
    );
    for (i, dl) in lists.iter().enumerate() {
        for (k, p) in dl.planes.iter().enumerate() {
            let c = coeffs(fmt, p.z0, p.dzx, p.dzy).map_err(|(field, msg)| {
                (
                    i,
                    CompileError {
                        plane: k,
                        field,
                        msg,
                    },
                )
            })?;
            for (x, y) in [(0, 0), (xm, 0), (0, ym), (xm, ym)] {
                let v = c.c0 as i128 + x * c.dx as i128 + y * c.dy as i128;
                if v < fmt.min_word() as i128 || v > fmt.max_word() as i128 {
                    let msg = format!(
                        "Z0 + x*dZx + y*dZy = {} at pixel ({x}, {y}) of the {width}x{height} \
                         window does not fit the depth word (range {} .. {}): DEPGEN would wrap",
                        v as f64 / (1u64 << fmt.frac) as f64,
                        fmt.to_real(fmt.min_word()),
                        fmt.to_real(fmt.max_word()),
                    );
                    return Err((
                        i,
                        CompileError {
                            plane: k,
                            field: 0,
                            msg,
                        },
                    ));
                }
            }
        }
    }
    Ok(())
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

/// The planes of an object, or of its complement: the complement of a convex object is a
/// concave hole whose front faces are the object's back faces, so H and L flip, and a
/// perpendicular plane's inside (K ≥ 0) becomes its outside (K negated).
fn planes(dl: &DisplayList, neg: bool) -> impl Iterator<Item = (usize, DlPlane)> + '_ {
    dl.planes
        .iter()
        .cloned()
        .enumerate()
        .map(move |(i, mut p)| {
            if neg {
                p.l = !p.l;
                if p.y {
                    (p.z0, p.dzx, p.dzy) = (-p.z0, -p.dzx, -p.dzy);
                } else {
                    p.h = !p.h;
                }
            }
            (i, p)
        })
}

/// Draw one literal of a clipping function into F (first stage and close).
fn literal_ops(
    dl: &DisplayList,
    neg: bool,
    fmt: &WordFormat,
    colour_bits: u32,
) -> Result<Vec<Op>, CompileError> {
    let mut flipped = DisplayList {
        planes: planes(dl, neg).map(|p| p.1).collect(),
        terminator: dl.terminator,
    };
    if neg {
        flipped.planes.insert(0, screen_plane(dl));
    }
    object_ops(&flipped, fmt, colour_bits).map_err(|mut e| {
        e.plane = e.plane.saturating_sub(neg as usize);
        e
    })
}

/// The first back plane of a complemented literal: the screen itself (Z = 0 everywhere). A
/// void cannot begin in front of the screen, so the geometry is unchanged; but the row "S = 1,
/// A < 0: Put 1" of the concave back-plane table (§2.3.3) would otherwise hide the whole void
/// wherever the first of the solid's front faces lies in front of the screen
/// (docs/rendering.md, "Where word may differ from float").
fn screen_plane(dl: &DisplayList) -> DlPlane {
    DlPlane {
        z0: 0.0,
        dzx: 0.0,
        dzy: 0.0,
        colour: dl.planes.first().map_or(1, |p| p.colour),
        h: false,
        y: false,
        l: true,
    }
}

/// Push "inside the literal's volume" on the clipping stack: the AND of its planes' partial
/// answers (a convex object is the intersection of its half-spaces), negated for a complement.
fn volume_ops(
    dl: &DisplayList,
    neg: bool,
    fmt: &WordFormat,
    ops: &mut Vec<Op>,
) -> Result<(), CompileError> {
    for (i, p) in dl.planes.iter().enumerate() {
        let coeffs = coeffs(fmt, p.z0, p.dzx, p.dzy).map_err(|(field, msg)| CompileError {
            plane: i,
            field,
            msg,
        })?;
        ops.push(Op::ClipPlane {
            coeffs,
            h: p.h,
            y: p.y,
            x: false,
        });
        if i > 0 {
            ops.push(Op::ClipAnd);
        }
    }
    if neg {
        ops.push(Op::ClipNot);
    }
    Ok(())
}

/// [`CompileError::field`] of an error about the whole program, not one plane.
pub const WHOLE_PROGRAM: usize = usize::MAX;

/// [`CompileError::field`] of an error about a whole list (the one the error names).
pub const WHOLE_LIST: usize = usize::MAX - 1;

/// The most operations a clipping program may have (about 40 bytes each, and as many
/// windows per pixel): beyond it the program's memory and time grow with the square of the
/// literals in a product, and it is refused before it is built.
pub const MAX_CLIP_OPS: u64 = 1 << 22;

/// An upper bound of [`clip_scene_ops`]'s length: a literal's own operations are at most
/// 2·planes + 2 (so are a volume's, with its AND), and each literal draws its product's
/// other volumes, applies and composes.
pub fn clip_ops_bound(lists: &[DisplayList], products: &[Vec<(usize, bool)>]) -> u64 {
    clip_ops_bound_by(&|o| lists[o].planes.len(), products)
}

/// [`clip_ops_bound`] with list `o` of `planes(o)` planes.
fn clip_ops_bound_by(planes: &dyn Fn(usize) -> usize, products: &[Vec<(usize, bool)>]) -> u64 {
    let per = |o: usize| 2 * planes(o) as u64 + 2;
    products
        .iter()
        .map(|prod| {
            let vol = prod
                .iter()
                .map(|&(o, _)| per(o))
                .fold(0, u64::saturating_add);
            (prod.len() as u64).saturating_mul(vol.saturating_add(3))
        })
        .fold(0, u64::saturating_add)
}

/// Refuse a clipping program whose bound of operations is over [`MAX_CLIP_OPS`]:
/// `bound` is an upper one (`"up to"`) or, before the lists are built, a lower one
/// (`"at least"`). The reason given is the one that holds: products of many literals (a
/// difference of many solids), or else solids of many planes.
fn check_clip_bound(
    bound: u64,
    which: &str,
    products: &[Vec<(usize, bool)>],
    planes: u64,
) -> Result<(), CompileError> {
    if bound <= MAX_CLIP_OPS {
        return Ok(());
    }
    let longest = products.iter().map(Vec::len).max().unwrap_or(0);
    let why = if longest > 2 {
        format!(
            "§5.2.1 draws every literal clipped by the rest of its product, so a difference \
             of n solids costs n² (here {longest} in one product; voxelize evaluates it in \
             Blist, linear in n)"
        )
    } else {
        format!(
            "its solids have {planes} planes, and the array draws each in about two \
             operations (a solid of fewer faces: in OpenSCAD a lower $fn, larger $fa or $fs)"
        )
    };
    let msg = format!(
        "the clipping program would have {which} {bound} operations, over {MAX_CLIP_OPS}: {why}"
    );
    Err(CompileError {
        plane: 0,
        field: WHOLE_PROGRAM,
        msg,
    })
}

/// Refuse `expr` before its lists are built when, even at one plane a list (every list has
/// one at least), its program would be over [`MAX_CLIP_OPS`]: projecting thousands of solids
/// onto a large screen costs seconds that a refusal should not wait for. The bound it gives
/// is that lower one; the compiler checks the full one.
pub fn check_clip_size(expr: &Clip) -> Result<(), CompileError> {
    let products = products_of(expr)?;
    let solids = products
        .iter()
        .flatten()
        .map(|&(o, _)| o + 1)
        .max()
        .unwrap_or(0);
    check_clip_bound(
        clip_ops_bound_by(&|_| 1, &products),
        "at least",
        &products,
        solids as u64,
    )
}

/// `expr`'s sum of products, or the refusal of a function with more than
/// [`csgpix_scene::clip_expr::MAX_PRODUCTS`].
fn products_of(expr: &Clip) -> Result<Vec<Vec<(usize, bool)>>, CompileError> {
    expr.products().map_err(|e| {
        let msg = format!(
            "{}: §5.2.1 draws a clipping function product by product, so write it with \
             fewer (voxelize evaluates a .csg tree in Blist, without products)",
            e.problem()
        );
        CompileError {
            plane: 0,
            field: WHOLE_PROGRAM,
            msg,
        }
    })
}

/// The thesis evaluation of a clipping function (§5.2.1): for every literal of every product
/// of its sum-of-products form, draw the literal, clip it by the other literals of the product
/// and compose it into the scene. Errors name the list they came from.
pub fn clip_scene_ops(
    lists: &[DisplayList],
    expr: &Clip,
    fmt: &WordFormat,
    colour_bits: u32,
) -> Result<Vec<Op>, (usize, CompileError)> {
    if let Some(i) = lists.iter().position(|l| l.is_concave()) {
        let msg = "a concave display list cannot be a clipping volume: leave it out of --clip \
                   (lists are composed without one) or split it into convex lists"
            .to_string();
        return Err((
            i,
            CompileError {
                plane: 0,
                field: WHOLE_LIST,
                msg,
            },
        ));
    }
    let products = products_of(expr).map_err(|e| (0, e))?;
    let planes = lists.iter().map(|l| l.planes.len() as u64).sum();
    check_clip_bound(clip_ops_bound(lists, &products), "up to", &products, planes)
        .map_err(|e| (0, e))?;
    let mut ops = vec![];
    for prod in &products {
        for (k, &(obj, neg)) in prod.iter().enumerate() {
            ops.extend(literal_ops(&lists[obj], neg, fmt, colour_bits).map_err(|e| (obj, e))?);
            let others: Vec<&(usize, bool)> = prod
                .iter()
                .enumerate()
                .filter(|(j, _)| *j != k)
                .map(|x| x.1)
                .collect();
            for (n, &&(o, ng)) in others.iter().enumerate() {
                volume_ops(&lists[o], ng, fmt, &mut ops).map_err(|e| (o, e))?;
                if n > 0 {
                    ops.push(Op::ClipAnd);
                }
            }
            if !others.is_empty() {
                ops.push(Op::ClipApply);
            }
            ops.push(Op::Compose { p: false });
        }
    }
    Ok(ops)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A function of too many products is refused before lists are built, with the
    /// compiler's own message (`render`, `requirements` and `throughput` waited minutes for
    /// the projection of a plate of 4,956 many-sided prisms before this refusal).
    #[test]
    fn too_many_products_are_refused_before_the_lists() {
        let pair = |i: usize| Clip::Or(Box::new(Clip::Obj(2 * i)), Box::new(Clip::Obj(2 * i + 1)));
        let and = |a, b| Clip::And(Box::new(a), Box::new(b));
        let twelve = (1..12).fold(pair(0), |e, i| and(e, pair(i)));
        assert!(check_clip_size(&twelve).is_ok(), "2^12 = 4096 products");
        let thirteen = and(twelve, pair(12));
        let e = check_clip_size(&thirteen).unwrap_err();
        assert_eq!(e.field, WHOLE_PROGRAM);
        let text = e.to_string();
        assert!(
            text.starts_with("the expression expands to more than 4096 products"),
            "{text}"
        );
        let lists = vec![
            DisplayList {
                planes: vec![],
                terminator: 0
            };
            26
        ];
        let compiled = clip_scene_ops(&lists, &thirteen, &WordFormat::default(), 4).unwrap_err();
        assert_eq!(compiled.1.to_string(), text);
    }

    /// A program too long for one solid's many planes is not blamed on a difference of many
    /// solids (a sphere of $fn = 3000 was); a whole-program error names no plane.
    #[test]
    fn a_long_program_names_its_cause() {
        let one = check_clip_bound(5_000_000, "up to", &[vec![(0, false)]], 2_500_000).unwrap_err();
        assert_eq!(one.field, WHOLE_PROGRAM);
        let text = one.to_string();
        assert!(
            text.starts_with("the clipping program would have up to 5000000"),
            "{text}"
        );
        assert!(text.contains("its solids have 2500000 planes"), "{text}");
        assert!(!text.contains("n²"), "{text}");
        let many = vec![(0, false), (1, true), (2, true), (3, true)];
        let text = check_clip_bound(5_000_000, "up to", &[many], 40)
            .unwrap_err()
            .to_string();
        assert!(
            text.contains("a difference of n solids costs n² (here 4 in one product"),
            "{text}"
        );
        assert!(check_clip_bound(MAX_CLIP_OPS, "up to", &[], 0).is_ok());
    }
}
