//! The controller's view: what the array is told to do, one operation at a time, and what the
//! stage selector (§2.4) connects for each.
//!
//! An [`Op`] that streams (a plane, a clipping plane, closing an object, composing it) takes one
//! window of N_D clocks. During a window the comparator sees the A-side word against a stored
//! register; at its end SGENE latches a 2-bit select code per pixel. That code is carried out
//! by TRANSD/TRANSC during the *next* window, bit k at clock k, in lockstep with the next
//! comparison (Figure 2.11: "the selector has decided … while the next plane is ready to be
//! downloaded"). [`Window::of`] is the one place that maps an operation to this wiring; both
//! models follow it.

use serde::Serialize;

use crate::select::sop::{Sop, Var};
use crate::select::{EquationSet, Signal};

/// Plane coefficients as raw depth words: value at pixel (x, y) = `c0 + x·dx + y·dy`, modulo
/// 2^N_D (eq. 2.1 for Z, eq. 2.2 for K). Each is an N_D-bit two's-complement word with F
/// fraction bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Coeffs {
    /// Value at pixel (0, 0): Z0 (or K0), raw N_D-bit word.
    pub c0: i64,
    /// Increment per pixel in x (one column to the right): dZx (or dKx), raw word.
    pub dx: i64,
    /// Increment per pixel in y (one row down): dZy (or dKy), raw word.
    pub dy: i64,
}

/// Move a program to an array whose pixel (0, 0) is pixel (x0, y0) of a larger one (a panel,
/// §2.5, or the part of the screen a primitive touches): every plane's Z0 becomes
/// Z0 + x0·dZx + y0·dZy. DEPGEN's sums are taken modulo 2^N_D, so the smaller array's pixel
/// (x, y) receives exactly the word the larger one's pixel (x0 + x, y0 + y) does; pixels share
/// nothing else, so their registers evolve the same.
pub fn translate(ops: &mut [Op], x0: usize, y0: usize) {
    let (x0, y0) = (x0 as i64, y0 as i64);
    for op in ops {
        if let Op::Plane { coeffs, .. } | Op::ClipPlane { coeffs, .. } = op {
            coeffs.c0 = coeffs
                .c0
                .wrapping_add(x0.wrapping_mul(coeffs.dx))
                .wrapping_add(y0.wrapping_mul(coeffs.dy));
        }
    }
}

/// One instruction of the array.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub enum Op {
    /// A plane of an object: stage position 1 when front or perpendicular (H or Y), else 2.
    /// `interior` is the object's internal colour, written by Put 0.
    Plane {
        /// The plane's Z (or K, when `y`) coefficients, streamed by DEPGEN into A.
        coeffs: Coeffs,
        /// The plane's colour code, loaded by MEM D into D (used by front planes only).
        colour: u32,
        /// The object's internal colour, written into E by Put 0.
        interior: u32,
        /// External L: 1 for a concave object, 0 for a convex one (§2.3.3).
        l: bool,
        /// External S: 1 for the first plane that writes its register (F or B) in this object.
        s: bool,
        /// External H: 1 for a front-facing plane, 0 for a back-facing one.
        h: bool,
        /// External Y: 1 for a plane perpendicular to the screen (`coeffs` give K, not Z).
        y: bool,
    },
    /// Stage position 3: compare B with F and keep the visible part of the object in F.
    Close {
        /// External L: 1 for a concave object, 0 for a convex one.
        l: bool,
    },
    /// A clipping plane (§2.3.4): LL of A against F is pushed on every pixel's stack.
    ClipPlane {
        /// The clipping plane's Z (or K, when `y`) coefficients, streamed into A.
        coeffs: Coeffs,
        /// External H: 1 for a front-facing clipping plane, 0 for a back-facing one.
        h: bool,
        /// External Y: 1 for a clipping plane perpendicular to the screen.
        y: bool,
        /// External X: at A = F, 0 if the surface is kept and 1 if not (LL = X').
        x: bool,
    },
    /// Postfix AND (`.`) on the clipping stack: pop two, push their AND; one clock.
    ClipAnd,
    /// Postfix OR (`+`) on the clipping stack: pop two, push their OR; one clock.
    ClipOr,
    /// Postfix NOT (`!`) on the clipping stack: complement the top; one clock.
    ClipNot,
    /// Pop LL' (one clock): the next window keeps F where LL' = 1 and puts 1 where LL' = 0.
    ClipApply,
    /// Stage position 4 (§2.3.5): compose F (colour E) into C (colour G); P = 1 initialises C.
    Compose {
        /// External P: 1 initialises C (Put 1 in every pixel: maxdepth, background colour)
        /// instead of composing F; 0 composes F into C.
        p: bool,
    },
}

/// Depth registers of a pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Reg {
    /// The incoming plane (Z, or K when perpendicular), written by DEPGEN.
    A = 0,
    /// The object's front envelope, then the visible part of the object.
    F = 1,
    /// The object's back envelope.
    B = 2,
    /// The scene so far (second stage).
    C = 3,
}

/// Colour registers of a pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum CReg {
    /// The incoming plane's colour, from MEM D.
    D = 0,
    /// The colour of F.
    E = 1,
    /// The colour of C: the image.
    G = 2,
}

/// How a latched 2-bit code is read by TRANSD/TRANSC.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decode {
    /// Positions 1-3 and the clipping result: (S1,S2) 00 Put A, 10 Put 0, 01 Keep, 11 Put 1.
    Sel,
    /// Position 4: (S3,S4) 00 Put 1, 01 Put F, 1- Keep C.
    Compose,
}

/// Per-pixel action masks a code decodes to (each a bit per lane).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ActionMasks {
    /// Lanes that take the source register (Put A, or Put F at position 4).
    pub put_src: u64,
    /// Lanes that take 0 (the screen) and the internal colour.
    pub put0: u64,
    /// Lanes that keep the destination register and its colour.
    pub keep: u64,
    /// Lanes that take the Put-1 word (maxdepth) and the background colour.
    pub put1: u64,
}

impl Decode {
    /// Decode the latched code (`hi` = S1 or S3, `lo` = S2 or S4) of 64 lanes.
    #[inline(always)]
    pub fn masks(self, hi: u64, lo: u64) -> ActionMasks {
        match self {
            Decode::Sel => ActionMasks {
                put_src: !hi & !lo,
                put0: hi & !lo,
                keep: !hi & lo,
                put1: hi & lo,
            },
            Decode::Compose => ActionMasks {
                put_src: !hi & lo,
                put0: 0,
                keep: hi,
                put1: !hi & !lo,
            },
        }
    }
}

/// What the latched code will do to the registers in the next window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Transfer {
    /// Depth register TRANSD writes.
    pub dst: Reg,
    /// Depth register that Put A / Put F copies into `dst`.
    pub src: Reg,
    /// Colour register written and its source (none for back planes).
    pub colour: Option<(CReg, CReg)>,
    /// How the latched code is read (TRANSD positions 1-3 or TRANSC position 4).
    pub decode: Decode,
    /// Colour that Put 0 writes (the object's internal colour).
    pub interior: u32,
}

/// What SGENE produces at the end of a window.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Decide {
    /// Latch (hi, lo) as the select code, equations already specialized to the externals.
    Latch(Sop, Sop),
    /// Push LL on the clipping stack.
    Push(Sop),
}

/// The wiring of one streaming window (the stage selector position and what flows where).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Window {
    /// Stage selector position 1-4.
    pub position: u8,
    /// Coefficients DEPGEN streams into A, and the colour MEM D loads into D, if any.
    pub stream: Option<(Coeffs, Option<u32>)>,
    /// Comparator operand on the A side (streamed in, or re-read at positions 3 and 4).
    pub lhs: Reg,
    /// Comparator operand on the stored side.
    pub rhs: Reg,
    /// What SGENE does with the flags at the window's end.
    pub decide: Decide,
    /// What the code latched at the end of this window does in the next one.
    pub transfer: Option<Transfer>,
}

fn spec(set: &EquationSet, s: Signal, ext: &[(Var, bool)]) -> Sop {
    let fixed = ext.iter().fold(0, |m, (v, _)| m | v.bit());
    let value = ext.iter().fold(0, |m, (v, b)| m | ((*b as u32) * v.bit()));
    set.sop(s).specialize(fixed, value)
}

/// What of a window its clocks depend on: whether DEPGEN streams in it, whether it leaves a
/// transfer pending ([`Window::stream`] and [`Window::transfer`] are `Some`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shape {
    /// DEPGEN streams coefficients into A.
    pub streams: bool,
    /// The code latched at its end transfers in the next window.
    pub transfers: bool,
}

impl Window {
    /// [`Window::of`]'s shape without its select equations (which a clock count does not
    /// read), or `None` for the one-clock stack operations.
    pub fn shape(op: &Op) -> Option<Shape> {
        let (streams, transfers) = match op {
            Op::Plane { .. } => (true, true),
            Op::ClipPlane { .. } => (true, false),
            Op::Close { .. } | Op::Compose { .. } => (false, true),
            Op::ClipAnd | Op::ClipOr | Op::ClipNot | Op::ClipApply => return None,
        };
        Some(Shape { streams, transfers })
    }

    /// The window of a streaming op, or `None` for the one-clock stack operations.
    pub fn of(op: &Op, set: &EquationSet) -> Option<Window> {
        use Signal::*;
        let sel =
            |hi, lo, ext: &[(Var, bool)]| Decide::Latch(spec(set, hi, ext), spec(set, lo, ext));
        Some(match *op {
            Op::Plane {
                coeffs,
                colour,
                interior,
                l,
                s,
                h,
                y,
            } if h || y => Window {
                position: 1,
                stream: Some((coeffs, Some(colour))),
                lhs: Reg::A,
                rhs: Reg::F,
                decide: sel(FrontS1, FrontS2, &[(Var::L, l), (Var::S, s), (Var::Y, y)]),
                transfer: Some(Transfer {
                    dst: Reg::F,
                    src: Reg::A,
                    colour: Some((CReg::E, CReg::D)),
                    decode: Decode::Sel,
                    interior,
                }),
            },
            Op::Plane { coeffs, l, s, .. } => Window {
                position: 2,
                stream: Some((coeffs, None)),
                lhs: Reg::A,
                rhs: Reg::B,
                decide: sel(BackS1, BackS2, &[(Var::L, l), (Var::S, s)]),
                transfer: Some(Transfer {
                    dst: Reg::B,
                    src: Reg::A,
                    colour: None,
                    decode: Decode::Sel,
                    interior: 0,
                }),
            },
            Op::Close { l } => Window {
                position: 3,
                stream: None,
                lhs: Reg::B,
                rhs: Reg::F,
                decide: sel(CloseS1, CloseS2, &[(Var::L, l)]),
                transfer: Some(Transfer::clip_apply()),
            },
            Op::ClipPlane { coeffs, h, y, x } => Window {
                position: 1,
                stream: Some((coeffs, None)),
                lhs: Reg::A,
                rhs: Reg::F,
                decide: Decide::Push(spec(set, LL, &[(Var::H, h), (Var::Y, y), (Var::X, x)])),
                transfer: None,
            },
            Op::Compose { p } => Window {
                position: 4,
                stream: None,
                lhs: Reg::F,
                rhs: Reg::C,
                decide: sel(S3, S4, &[(Var::P, p)]),
                transfer: Some(Transfer {
                    dst: Reg::C,
                    src: Reg::F,
                    colour: Some((CReg::G, CReg::E)),
                    decode: Decode::Compose,
                    interior: 0,
                }),
            },
            Op::ClipAnd | Op::ClipOr | Op::ClipNot | Op::ClipApply => return None,
        })
    }
}

impl Transfer {
    /// Keep F or put 1 into it (stage 3 and the clipping result), colour kept or background.
    pub fn clip_apply() -> Transfer {
        Transfer {
            dst: Reg::F,
            src: Reg::B,
            colour: Some((CReg::E, CReg::D)),
            decode: Decode::Sel,
            interior: 0,
        }
    }
}

/// The stack effect of an operation: (pops, pushes).
pub fn stack_effect(op: &Op) -> (usize, usize) {
    match op {
        Op::ClipPlane { .. } => (0, 1),
        Op::ClipAnd | Op::ClipOr => (2, 1),
        Op::ClipNot => (1, 1),
        Op::ClipApply => (1, 0),
        _ => (0, 0),
    }
}

/// Why a program cannot run on an array.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ProgramError {
    /// Operation `op` would push beyond the clipping stack's `depth` levels.
    StackOverflow {
        /// Index of the operation in the program.
        op: usize,
        /// Levels of the clipping stack.
        depth: usize,
    },
    /// Operation `op` pops more levels than the clipping stack holds.
    StackUnderflow {
        /// Index of the operation in the program.
        op: usize,
    },
    /// `ClipApply` right after a window whose select code has not been carried out yet.
    LatchBusy {
        /// Index of the operation in the program.
        op: usize,
    },
}

impl std::fmt::Display for ProgramError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ProgramError::StackOverflow { op, depth } => write!(
                f,
                "operation {op} needs more than the {depth} levels of the clipping stack \
                 (raise --stack-depth)"
            ),
            ProgramError::StackUnderflow { op } => {
                write!(f, "operation {op} pops an empty clipping stack")
            }
            ProgramError::LatchBusy { op } => write!(
                f,
                "operation {op} (apply clipping) must follow a clipping plane: the select code \
                 of the window before it has not been carried out"
            ),
        }
    }
}

impl std::error::Error for ProgramError {}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Equations;

    /// Every kind of operation with every external that changes its window.
    fn every_op() -> Vec<Op> {
        let coeffs = Coeffs {
            c0: 5,
            dx: -1,
            dy: 2,
        };
        let mut ops = vec![Op::ClipAnd, Op::ClipOr, Op::ClipNot, Op::ClipApply];
        for bits in 0..16u8 {
            let [l, s, h, y] = [0, 1, 2, 3].map(|i| bits >> i & 1 == 1);
            ops.push(Op::Plane {
                coeffs,
                colour: 3,
                interior: 2,
                l,
                s,
                h,
                y,
            });
            ops.push(Op::ClipPlane { coeffs, h, y, x: l });
            ops.push(Op::Close { l });
            ops.push(Op::Compose { p: s });
        }
        ops
    }

    /// A clock count reads a window's shape alone; it is the shape of the window itself.
    #[test]
    fn a_windows_shape_is_the_window_s() {
        for eq in [Equations::Derived, Equations::Printed] {
            let set = eq.set();
            for op in every_op() {
                let whole = Window::of(&op, &set).map(|w| Shape {
                    streams: w.stream.is_some(),
                    transfers: w.transfer.is_some(),
                });
                assert_eq!(Window::shape(&op), whole, "{op:?}");
            }
        }
    }
}
