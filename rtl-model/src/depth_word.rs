//! The depth word of §2.4.1 (Figure 2.10).
//!
//! A depth is an `N_D`-bit two's-complement fixed-point word, streamed LSB first:
//! bits `0..F` fraction, `F..F+I` integer, `F+I..F+I+O` overflow, bit `N_D-1` sign.
//! The thesis uses F = 10, I = 10, O = 11: 32 bits, so 32 clocks per plane.
//!
//! Invariants of [`WordFormat`]: `F + I + O + 1 = N_D <= 63`, `I >= 1`, `O >= 1`. Raw words are
//! carried in an `i64` holding the sign-extended `N_D`-bit value, so every raw word `w` obeys
//! `min_word() <= w <= max_word()`.

use serde::Serialize;

/// Field widths of the depth word: fraction, integer and overflow bits (sign is one more).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub struct WordFormat {
    /// F: fraction bits (depth units are 2^F raw steps).
    pub frac: u32,
    /// I: integer bits (maxdepth = 2^I depth units); at least 1.
    pub int: u32,
    /// O: overflow bits, the guard band between maxdepth and the sign; at least 1.
    pub ovf: u32,
}

impl Default for WordFormat {
    /// The thesis word: 10 fraction, 10 integer, 11 overflow bits and the sign (§2.4.1).
    fn default() -> Self {
        WordFormat::THESIS
    }
}

/// Why a [`WordFormat`] or a coefficient was refused.
#[derive(Clone, Debug, PartialEq)]
pub enum FormatError {
    /// N_D must lie in 3..=63 and every field but the fraction must be at least one bit.
    BadWidths {
        /// Fraction bits asked for.
        frac: u32,
        /// Integer bits asked for.
        int: u32,
        /// Overflow bits asked for.
        ovf: u32,
    },
    /// A real coefficient does not fit the word once scaled by 2^F.
    OutOfRange {
        /// The coefficient, in depth units per pixel.
        value: f64,
        /// Smallest real the word holds (the most negative word).
        min: f64,
        /// Largest real the word holds (the Put-1 word).
        max: f64,
    },
}

impl std::fmt::Display for FormatError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FormatError::BadWidths { frac, int, ovf } => write!(
                f,
                "depth word {frac}/{int}/{ovf}: need integer >= 1, overflow >= 1 and \
                 fraction+integer+overflow+1 <= 63 bits"
            ),
            FormatError::OutOfRange { value, min, max } => write!(
                f,
                "coefficient {value} does not fit the depth word (range {min} .. {max})"
            ),
        }
    }
}

impl std::error::Error for FormatError {}

impl WordFormat {
    /// The thesis format, 10/10/11 + sign = 32 bits.
    pub const THESIS: WordFormat = WordFormat {
        frac: 10,
        int: 10,
        ovf: 11,
    };

    /// A checked format.
    pub fn new(frac: u32, int: u32, ovf: u32) -> Result<WordFormat, FormatError> {
        let n = frac as u64 + int as u64 + ovf as u64 + 1;
        if int == 0 || ovf == 0 || n > 63 {
            return Err(FormatError::BadWidths { frac, int, ovf });
        }
        Ok(WordFormat { frac, int, ovf })
    }

    /// N_D: bits per word, which is also clocks per plane (eq. 2.3).
    pub fn bits(&self) -> u32 {
        self.frac + self.int + self.ovf + 1
    }

    /// Index of the sign bit (the last bit streamed).
    pub fn sign_bit(&self) -> u32 {
        self.bits() - 1
    }

    /// Bit positions of the overflow field (M is their OR on a non-negative word).
    pub fn overflow_bits(&self) -> std::ops::Range<u32> {
        self.frac + self.int..self.sign_bit()
    }

    /// Mask of the low `N_D` bits.
    pub fn mask(&self) -> u64 {
        (1u64 << self.bits()) - 1
    }

    /// maxdepth = 2^I depth units: the first value with an overflow bit set.
    pub fn maxdepth(&self) -> i64 {
        1i64 << (self.frac + self.int)
    }

    /// The word "Put 1" writes: the largest positive word, 0111…1 (also the reset value).
    pub fn max_word(&self) -> i64 {
        (1i64 << self.sign_bit()) - 1
    }

    /// The most negative word, 1000…0.
    pub fn min_word(&self) -> i64 {
        -(1i64 << self.sign_bit())
    }

    /// Reduce any integer to the `N_D`-bit two's-complement word the bit-serial adders leave:
    /// the adders keep the low `N_D` bits and drop the carry out (wrap-around).
    pub fn wrap(&self, raw: i64) -> i64 {
        let shift = 64 - self.bits();
        (raw << shift) >> shift
    }

    /// Bit `k` of a raw word (k < N_D).
    pub fn bit(&self, raw: i64, k: u32) -> bool {
        (raw >> k) & 1 == 1
    }

    /// Raw word from real depth units, rounded to nearest (ties to even), refused out of range.
    pub fn quantize(&self, value: f64) -> Result<i64, FormatError> {
        let scaled = (value * (1u64 << self.frac) as f64).round_ties_even();
        let (min, max) = (self.min_word() as f64, self.max_word() as f64);
        if !scaled.is_finite() || scaled < min || scaled > max {
            return Err(FormatError::OutOfRange {
                value,
                min: self.to_real(self.min_word()),
                max: self.to_real(self.max_word()),
            });
        }
        Ok(scaled as i64)
    }

    /// The real value of a raw word, in depth units.
    pub fn to_real(&self, raw: i64) -> f64 {
        raw as f64 / (1u64 << self.frac) as f64
    }

    /// N: the sign of the word (§2.3.2).
    pub fn n(&self, raw: i64) -> bool {
        raw < 0
    }

    /// M: an overflow bit is set on a non-negative word, i.e. `raw >= maxdepth` (§2.3.2).
    pub fn m(&self, raw: i64) -> bool {
        raw >= self.maxdepth()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thesis_word_is_32_bits_with_maxdepth_1024() {
        let f = WordFormat::THESIS;
        assert_eq!(f.bits(), 32);
        assert_eq!(f.overflow_bits(), 20..31);
        assert_eq!(f.to_real(f.maxdepth()), 1024.0);
        assert_eq!(f.max_word(), i32::MAX as i64);
        assert_eq!(f.min_word(), i32::MIN as i64);
    }

    #[test]
    fn wrap_matches_twos_complement_truncation() {
        let f = WordFormat::THESIS;
        assert_eq!(f.wrap(i32::MAX as i64 + 1), i32::MIN as i64);
        assert_eq!(f.wrap(-1), -1);
        assert_eq!(f.wrap(0x1_2345_6789), 0x2345_6789);
    }

    #[test]
    fn m_is_an_overflow_bit_on_a_non_negative_word() {
        let f = WordFormat::new(1, 2, 2).unwrap();
        for raw in f.min_word()..=f.max_word() {
            let any_ovf = f.overflow_bits().any(|k| f.bit(raw, k));
            assert_eq!(f.m(raw), any_ovf && !f.n(raw), "raw {raw}");
        }
    }

    #[test]
    fn quantize_rounds_to_nearest_and_refuses_out_of_range() {
        let f = WordFormat::THESIS;
        assert_eq!(f.quantize(46.06).unwrap(), 47165); // 46.06 * 1024 = 47165.44
        assert_eq!(f.quantize(-1.0).unwrap(), -1024);
        assert_eq!(f.quantize(0.5 / 1024.0).unwrap(), 0); // tie to even
        assert!(f.quantize(3.0e6).is_err());
        assert!(f.quantize(f64::NAN).is_err());
    }

    #[test]
    fn bad_widths_are_refused() {
        assert!(WordFormat::new(10, 0, 11).is_err());
        assert!(WordFormat::new(30, 20, 20).is_err());
        assert!(WordFormat::new(0, 1, 1).is_ok());
    }
}
