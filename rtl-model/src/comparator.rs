//! The bit-serial comparator ("compare" module of Figure 2.9, flags of §2.3.2).
//!
//! Two depth words arrive one bit per clock, LSB first: the incoming word on the A side (A, or
//! B at stage position 3, or F at position 4) and the stored word of the register it meets
//! (F, B or C). Four flip-flops per pixel summarise the comparison so far:
//!
//! * `lt`: A < R on the bits seen (a later differing bit overrides an earlier one, and at the
//!   sign bit the order is reversed: a 1 there means negative);
//! * `eq`: no bit has differed;
//! * `ovf`: an overflow bit of A was 1;
//! * `sign`: the sign bit of A.
//!
//! After the last bit the internal variables are N = sign, J = lt | eq (A ≤ R), T = eq (A = R)
//! and M = ovf & !sign (A ≥ maxdepth). Each flip-flop is one bit per pixel; here a `u64` carries
//! 64 pixels, so one call to [`Comparator::step`] is one clock for 64 pixels.

use crate::depth_word::WordFormat;

/// What role bit `k` of the word plays, which decides how the comparator treats it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BitRole {
    /// Fraction or integer bit.
    Plain,
    /// One of the overflow bits (F+I .. F+I+O).
    Overflow,
    /// The sign, streamed last.
    Sign,
}

impl BitRole {
    /// The role of bit `k` in `fmt`.
    pub fn of(fmt: &WordFormat, k: u32) -> BitRole {
        if k == fmt.sign_bit() {
            BitRole::Sign
        } else if fmt.overflow_bits().contains(&k) {
            BitRole::Overflow
        } else {
            BitRole::Plain
        }
    }
}

/// The comparator flip-flops of 64 pixels, one bit per lane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Comparator {
    /// A < R on the bits seen so far.
    pub lt: u64,
    /// No bit has differed so far (A = R on the bits seen).
    pub eq: u64,
    /// An overflow bit of A was 1.
    pub ovf: u64,
    /// The sign bit of A (valid after the last bit).
    pub sign: u64,
}

/// The internal variables N, J, T, M of 64 pixels, one bit per lane (§2.3.2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Flags {
    /// N = sign: A < 0.
    pub n: u64,
    /// J = lt | eq: A ≤ R.
    pub j: u64,
    /// T = eq: A = R.
    pub t: u64,
    /// M = ovf & !sign: A ≥ maxdepth.
    pub m: u64,
}

impl Default for Comparator {
    fn default() -> Self {
        Comparator::RESET
    }
}

impl Comparator {
    /// State before the first bit of a word: equal so far, nothing seen.
    pub const RESET: Comparator = Comparator {
        lt: 0,
        eq: !0,
        ovf: 0,
        sign: 0,
    };

    /// One clock: bit `a` of the incoming word against bit `r` of the stored word.
    #[inline(always)]
    pub fn step(&mut self, a: u64, r: u64, role: BitRole) {
        let diff = a ^ r;
        // Below the sign a differing bit decides "A < R" when R has the 1; at the sign it is
        // the other way round, since a 1 there is negative.
        let a_smaller = if role == BitRole::Sign { a } else { r };
        self.lt = (diff & a_smaller) | (!diff & self.lt);
        self.eq &= !diff;
        match role {
            BitRole::Overflow => self.ovf |= a,
            BitRole::Sign => self.sign = a,
            BitRole::Plain => {}
        }
    }

    /// The flags after the last bit.
    #[inline(always)]
    pub fn flags(&self) -> Flags {
        Flags {
            n: self.sign,
            j: self.lt | self.eq,
            t: self.eq,
            m: self.ovf & !self.sign,
        }
    }
}

/// Scalar flags of one comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
pub struct FlagBits {
    /// N: A < 0.
    pub n: bool,
    /// J: A ≤ R.
    pub j: bool,
    /// T: A = R.
    pub t: bool,
    /// M: A ≥ maxdepth.
    pub m: bool,
}

/// Compare two raw words by streaming them bit by bit through the serial comparator (lane 0).
pub fn compare_serial(fmt: &WordFormat, a: i64, r: i64) -> FlagBits {
    let mut c = Comparator::RESET;
    for k in 0..fmt.bits() {
        let bit = |w: i64| ((w >> k) & 1) as u64;
        c.step(bit(a), bit(r), BitRole::of(fmt, k));
    }
    let f = c.flags();
    FlagBits {
        n: f.n & 1 == 1,
        j: f.j & 1 == 1,
        t: f.t & 1 == 1,
        m: f.m & 1 == 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serial_comparison_equals_integer_comparison_exhaustively() {
        let fmt = WordFormat::new(1, 2, 2).unwrap();
        for a in fmt.min_word()..=fmt.max_word() {
            for r in fmt.min_word()..=fmt.max_word() {
                let f = compare_serial(&fmt, a, r);
                let want = FlagBits {
                    n: fmt.n(a),
                    j: a <= r,
                    t: a == r,
                    m: fmt.m(a),
                };
                assert_eq!(f, want, "a={a} r={r}");
            }
        }
    }

    #[test]
    fn thesis_word_extremes() {
        let fmt = WordFormat::THESIS;
        let cases = [
            (fmt.min_word(), fmt.max_word()),
            (fmt.max_word(), fmt.min_word()),
            (-1, 0),
            (0, -1),
            (fmt.maxdepth(), fmt.maxdepth() - 1),
            (fmt.max_word(), fmt.max_word()),
        ];
        for (a, r) in cases {
            let f = compare_serial(&fmt, a, r);
            assert_eq!(
                (f.j, f.t, f.n, f.m),
                (a <= r, a == r, a < 0, a >= fmt.maxdepth())
            );
        }
    }
}
