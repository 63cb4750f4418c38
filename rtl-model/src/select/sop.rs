//! Sum-of-products equations over named Boolean variables.
//!
//! The select logic of §2.3.3-2.3.5 is a handful of two-level equations. A [`Sop`] is one of
//! them: an OR of [`Cube`]s (AND terms), optionally complemented (the thesis prints S1', S2' and
//! a primed name is the complement). Variables are numbered by their position in the
//! equations' variable list.

/// One product term. Bit `i` of `care` says whether variable `i` appears; bit `i` of `value`
/// gives its polarity (1 = plain, 0 = primed). Bits of `value` outside `care` are zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Cube {
    /// Bit `i` set: variable `i` appears in the term.
    pub care: u32,
    /// Bit `i`: polarity of variable `i` (1 plain, 0 primed); zero outside `care`.
    pub value: u32,
}

impl Cube {
    /// The cube that is true for exactly one minterm of `n` variables.
    pub fn minterm(n: usize, m: u32) -> Cube {
        let care = if n >= 32 { u32::MAX } else { (1u32 << n) - 1 };
        Cube {
            care,
            value: m & care,
        }
    }

    /// True when the minterm `m` (bit `i` = variable `i`) lies inside the cube.
    pub fn contains(&self, m: u32) -> bool {
        m & self.care == self.value
    }

    /// Number of literals in the term.
    pub fn literals(&self) -> u32 {
        self.care.count_ones()
    }
}

/// The Boolean variables of §2.3.2-2.3.5, in the bit order used by every [`Cube`] of an
/// equation: externals L S H Y X P, then the comparator's internals N J T M.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[repr(u8)]
pub enum Var {
    /// External: 1 for a concave object, 0 for a convex one (§2.3.3).
    L,
    /// External: 1 for the first plane that writes its register (F or B) in the object.
    S,
    /// External: 1 for a front-facing plane, 0 for a back-facing one.
    H,
    /// External: 1 for a plane perpendicular to the screen (its word is K, not Z).
    Y,
    /// External of a clipping plane: at A = F, 0 if the surface is kept, 1 if not (§2.3.4).
    X,
    /// External of the second stage: 1 initialises C (§2.3.5).
    P,
    /// Internal: the sign of the A-side word, A < 0 (§2.3.2).
    N,
    /// Internal: A ≤ R, the A side against the stored register (§2.3.2).
    J,
    /// Internal: A = R (§2.3.2).
    T,
    /// Internal: A ≥ maxdepth, an overflow bit set on a non-negative word (§2.3.2).
    M,
}

impl Var {
    /// Every variable, in cube bit order.
    pub const ALL: [Var; 10] = [
        Var::L,
        Var::S,
        Var::H,
        Var::Y,
        Var::X,
        Var::P,
        Var::N,
        Var::J,
        Var::T,
        Var::M,
    ];

    /// The single-letter name the thesis uses.
    pub fn name(self) -> char {
        b"LSHYXPNJTM"[self as usize] as char
    }

    /// The variable a letter names, if any.
    pub fn from_name(c: char) -> Option<Var> {
        Var::ALL.into_iter().find(|v| v.name() == c)
    }

    /// Bit of this variable in a cube.
    pub fn bit(self) -> u32 {
        1 << self as u32
    }
}

/// One equation: `out = OR(cubes)`, or its complement when `primed` (a printed `S1' = …`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sop {
    /// The product terms, ORed; none is the constant 0.
    pub cubes: Vec<Cube>,
    /// The equation defines the complement of the signal (`S1' = …`).
    pub primed: bool,
}

impl Sop {
    /// Evaluate on 64 lanes at once; `vars[v]` holds variable `v` for every lane.
    #[inline]
    pub fn eval(&self, vars: &[u64; 10]) -> u64 {
        let mut out = 0u64;
        for c in &self.cubes {
            let mut term = !0u64;
            for v in Var::ALL {
                if c.care & v.bit() != 0 {
                    let x = vars[v as usize];
                    term &= if c.value & v.bit() != 0 { x } else { !x };
                }
            }
            out |= term;
        }
        if self.primed {
            !out
        } else {
            out
        }
    }

    /// Evaluate on one set of scalar values.
    pub fn eval_bits(&self, vars: &[bool; 10]) -> bool {
        let lanes = vars.map(|b| if b { !0u64 } else { 0 });
        self.eval(&lanes) & 1 == 1
    }

    /// Substitute constants for the variables in `fixed` (mask) with values `value`: cubes that
    /// the constants falsify vanish, literals they satisfy drop out. The array does this once
    /// per plane, since the externals are the same for every pixel.
    pub fn specialize(&self, fixed: u32, value: u32) -> Sop {
        let cubes = self
            .cubes
            .iter()
            .filter(|c| (c.value ^ value) & c.care & fixed == 0)
            .map(|c| Cube {
                care: c.care & !fixed,
                value: c.value & !fixed,
            })
            .collect();
        Sop {
            cubes,
            primed: self.primed,
        }
    }

    /// The thesis notation: `L'Y'S'N + Y'N'M'`; `0` and `1` for the constants.
    pub fn to_text(&self) -> String {
        if self.cubes.is_empty() {
            return "0".into();
        }
        let terms: Vec<String> = self
            .cubes
            .iter()
            .map(|c| {
                if c.care == 0 {
                    return "1".into();
                }
                let mut t = String::new();
                for v in Var::ALL.into_iter().filter(|v| c.care & v.bit() != 0) {
                    t.push(v.name());
                    if c.value & v.bit() == 0 {
                        t.push('\'');
                    }
                }
                t
            })
            .collect();
        terms.join(" + ")
    }
}

/// Why an equation text was refused, with the 1-based column.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SopError {
    /// 1-based column in the right-hand side.
    pub col: usize,
    /// What is wrong.
    pub msg: String,
}

/// Parse a right-hand side in the thesis notation: products of letters, `'` for complement,
/// optional `.` between letters, `+` between products, `0`/`1` constants. `alias` maps letters
/// the text uses without defining them to the variable they are read as (see `printed.rs`).
pub fn parse_sop(text: &str, alias: &[(char, Var)]) -> Result<Vec<Cube>, SopError> {
    let mut cubes = Vec::new();
    let mut cur = Cube { care: 0, value: 0 };
    let mut empty = true;
    let mut last: Option<Var> = None;
    for (i, ch) in text.chars().enumerate() {
        let col = i + 1;
        let err = |msg: String| Err(SopError { col, msg });
        match ch {
            ' ' | '\t' | '.' => {}
            '+' => {
                if empty {
                    return err("expected a product term before '+'".into());
                }
                cubes.push(cur);
                cur = Cube { care: 0, value: 0 };
                empty = true;
                last = None;
            }
            '\'' => match last.take() {
                Some(v) => cur.value &= !v.bit(),
                None => return err("expected a variable before '".into()),
            },
            '1' if empty => empty = false,
            '0' if empty => {
                empty = false;
                cur = Cube { care: 0, value: 1 }; // marker: falsified term
            }
            c => {
                let v = Var::from_name(c)
                    .or_else(|| alias.iter().find(|a| a.0 == c).map(|a| a.1))
                    .ok_or(SopError {
                        col,
                        msg: format!("expected one of LSHYXPNJTM, found {c:?}"),
                    })?;
                if cur.care & v.bit() != 0 {
                    return err(format!("variable {} twice in one term", v.name()));
                }
                cur.care |= v.bit();
                cur.value |= v.bit();
                last = Some(v);
                empty = false;
            }
        }
    }
    if empty {
        return Err(SopError {
            col: text.chars().count() + 1,
            msg: "expected a product term".into(),
        });
    }
    cubes.push(cur);
    // A "0" term was marked with value outside care: it never holds, drop it.
    Ok(cubes
        .into_iter()
        .filter(|c| c.value & !c.care == 0)
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_print_round_trip() {
        let c = parse_sop("L'Y'S'N + Y'.N'.M' + 1", &[]).unwrap();
        let s = Sop {
            cubes: c,
            primed: false,
        };
        assert_eq!(s.to_text(), "L'S'Y'N + Y'N'M' + 1");
        let again = parse_sop(&s.to_text(), &[]).unwrap();
        assert_eq!(again, s.cubes);
    }

    #[test]
    fn parse_errors_name_the_column() {
        assert_eq!(parse_sop("LQ", &[]).unwrap_err().col, 2);
        assert_eq!(parse_sop("L + + S", &[]).unwrap_err().col, 5);
        assert_eq!(parse_sop("'L", &[]).unwrap_err().col, 1);
        assert_eq!(parse_sop("LL", &[]).unwrap_err().col, 2);
    }

    #[test]
    fn specialize_agrees_with_eval() {
        let s = Sop {
            cubes: parse_sop("L'S N + Y'N'M' + L J T'", &[]).unwrap(),
            primed: true,
        };
        let fixed = Var::L.bit() | Var::S.bit() | Var::Y.bit();
        for m in 0u32..1024 {
            let vars: [bool; 10] = std::array::from_fn(|i| m >> i & 1 == 1);
            let sp = s.specialize(fixed, m & fixed);
            assert_eq!(s.eval_bits(&vars), sp.eval_bits(&vars), "minterm {m}");
        }
    }
}
