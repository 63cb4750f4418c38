//! Grey-valued scenes: the volumetric Boolean operations as blending functions (§3.3),
//! evaluated per slice on a slice stack (§3.4.1's pseudocode).
//!
//! Every primitive contributes a grey slice: 0 outside; inside, a dataset's own grey value
//! (its interpolated sample, scaled to 1..=255) and [`SOLID`] (255) for a solid or a mesh. With C_d the value already in
//! the frame buffer (the operator's first operand) and C_s the incoming one:
//!
//! | operator | §3.3 | here |
//! |---|---|---|
//! | union | C = max(C_s, C_d), or C = k_s·C_s + k_d·C_d | the same; the sum rounded and clamped to 255 |
//! | intersection | C = min(C_s, C_d) | the same |
//! | difference | C = min(C_d − C_s, 0), "where C is equal to 0 if C_d − C_s < 0" | max(C_d − C_s, 0) |
//! | complement (`!`, CSG expressions only) | — | 255 − C |
//!
//! The difference as printed, min(C_d − C_s, 0), is never positive, so every difference
//! would be empty; the sentence under it says what is meant: C_d − C_s, and 0 where that is
//! negative. That reading is implemented.

use crate::evaluate::{Compile, Op, Postfix};
use csgpix_scene::solid::CsgNode;

/// How a union blends (§3.3 gives both).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Union {
    /// C = max(C_s, C_d).
    Max,
    /// C = k_s·C_s + k_d·C_d.
    Sum {
        /// k_s, the factor of the source (the right operand).
        ks: f64,
        /// k_d, the factor of the destination (the left operand).
        kd: f64,
    },
}

/// A tree as blending operations on grey slices.
#[derive(Clone, Debug, PartialEq)]
pub struct BlendEval {
    program: Postfix,
    union: Union,
}

impl BlendEval {
    /// The blending program of `tree`, its unions blending by `union`.
    pub fn new(tree: &CsgNode, union: Union) -> BlendEval {
        BlendEval {
            program: Postfix::compile(tree, Compile::default()),
            union,
        }
    }

    /// Grey slices of every primitive (`prims[i]` for leaf i, all of one length; a missing
    /// one is all 0) in, the scene's grey slice out.
    pub fn blend(&self, prims: &[Vec<u8>], len: usize) -> Vec<u8> {
        let mut stack: Vec<Vec<u8>> = Vec::with_capacity(self.program.peak_depth());
        for op in self.program.ops() {
            match *op {
                Op::Leaf(i) => stack.push(prims.get(i).cloned().unwrap_or_else(|| vec![0; len])),
                Op::Const(_) => stack.push(vec![0; len]),
                Op::Not => {
                    if let Some(top) = stack.last_mut() {
                        top.iter_mut().for_each(|c| *c = 255 - *c);
                    }
                }
                Op::And | Op::Or | Op::AndNot => {
                    let (Some(s), Some(mut d)) = (stack.pop(), stack.pop()) else {
                        return vec![0; len];
                    };
                    for (d, s) in d.iter_mut().zip(&s) {
                        *d = self.binary(*op, *d, *s);
                    }
                    stack.push(d);
                }
                Op::Guard { .. } => {}
            }
        }
        stack.pop().unwrap_or_else(|| vec![0; len])
    }

    /// One blending function, C from C_d (in the buffer) and C_s (incoming).
    pub fn binary(&self, op: Op, d: u8, s: u8) -> u8 {
        match op {
            Op::And => d.min(s),
            Op::AndNot => d.saturating_sub(s),
            Op::Or => match self.union {
                Union::Max => d.max(s),
                Union::Sum { ks, kd } => {
                    (ks * s as f64 + kd * d as f64).round().clamp(0.0, 255.0) as u8
                }
            },
            _ => d,
        }
    }
}

/// The value of a solid's or a mesh's inside: they are binary volumes (0 or 255), so that
/// blending them alone is their Boolean operation (tested) and subtracting one removes
/// whatever it covers.
pub const SOLID: u8 = 255;

#[cfg(test)]
mod tests {
    use super::*;
    use csgpix_scene::csg_expr::parse;

    fn blend(expr: &str, union: Union, prims: &[u8]) -> u8 {
        let e = parse(expr).unwrap();
        let slices: Vec<Vec<u8>> = prims.iter().map(|&v| vec![v]).collect();
        BlendEval::new(&e.root, union).blend(&slices, 1)[0]
    }

    #[test]
    fn the_operators_of_section_3_3() {
        let m = Union::Max;
        assert_eq!(blend("A+B", m, &[40, 200]), 200);
        assert_eq!(blend("A.B", m, &[40, 200]), 40);
        assert_eq!(blend("A-B", m, &[200, 40]), 160);
        assert_eq!(blend("A-B", m, &[40, 200]), 0, "negative differences are 0");
        assert_eq!(blend("!A", m, &[40]), 215);
        let sum = Union::Sum { ks: 0.5, kd: 0.25 };
        // d = A = 100 is in the buffer, s = B = 200 comes in: 0.5·200 + 0.25·100.
        assert_eq!(blend("A+B", sum, &[100, 200]), 125);
        let big = Union::Sum { ks: 1.0, kd: 1.0 };
        assert_eq!(blend("A+B", big, &[200, 200]), 255, "sums clamp");
    }

    #[test]
    fn chains_fold_left_and_nest() {
        let m = Union::Max;
        // (A − B) − C: 250 − 100 − 100.
        assert_eq!(blend("A-B-C", m, &[250, 100, 100]), 50);
        // A − (B − C): 250 − (150 − 100).
        assert_eq!(blend("A-(B-C)", m, &[250, 150, 100]), 200);
        assert_eq!(blend("(A+B).C", m, &[10, 90, 50]), 50);
    }

    #[test]
    fn binary_volumes_blend_as_boolean_sets() {
        // With values 0 and 255 only, the blends are the Boolean operators.
        for expr in ["A+B", "A.B", "A-B", "!A.B", "(A-B)+(B-A)"] {
            let e = parse(expr).unwrap();
            for bits in 0..4u8 {
                let v = [bits & 1, bits >> 1 & 1];
                let got = blend(expr, Union::Max, &v.map(|b| b * 255));
                let want = crate::evaluate::direct(&e.root, |i| v[i] == 1);
                assert_eq!(got == 255, want, "{expr} {v:?}");
                assert!(got == 0 || got == 255);
            }
        }
    }
}
