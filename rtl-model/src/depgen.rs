//! DEPGEN, the tree-structured depth generator (§2.4, after Pixel-Planes).
//!
//! It delivers `c0 + x·dx + y·dy` to every pixel, one bit per clock, LSB first. Two trees of
//! bit-serial adders run side by side: the x tree puts `x·dx` on every column line and the y
//! tree puts `c0 + y·dy` on every row line; each pixel adds its column and row bits with its
//! own one-bit serial adder. Level `j` of a tree adds the coefficient delayed by `j` clocks
//! (that is, shifted left by `j`) on the branches whose coordinate has bit `j` set, so a line
//! receives the sum over the set bits of its coordinate. Every adder keeps its carry between
//! clocks and drops the carry out of bit N_D-1: all sums are modulo 2^N_D, as the word model's
//! `WordFormat::wrap` says.
//!
//! Pipeline: each level is a registered adder, so a bit reaches the pixel
//! [`ArrayConfig::depgen_latency`] clocks after the controller presented it at the root. In a
//! stream of planes that is paid once; this model computes each clock's tree outputs directly
//! and the array adds the latency to its clock count. The Verilog trees
//! (`crate::verilog::depgen`, `rtl-model/verilog/depgen.v`) are the pipelined version, and
//! the co-simulation checks that the two put the same bits into A in the same clocks.
//!
//! [`ArrayConfig::depgen_latency`]: crate::state::ArrayConfig::depgen_latency

use crate::depth_word::WordFormat;
use crate::program::Coeffs;

/// The two trees, bit-sliced over lines: 64 column (or row) lines per `u64`.
#[derive(Clone, Debug)]
pub struct DepGen {
    fmt: WordFormat,
    cols: Tree,
    rows: Tree,
}

#[derive(Clone, Debug)]
struct Tree {
    words: usize,
    /// `mask[j * words + i]`: the lines of word `i` whose coordinate has bit `j` set.
    mask: Vec<u64>,
    levels: usize,
}

/// One plane's bits on every line: `col[k * col_words + i]`, `row[k * row_words + i]`.
#[derive(Clone, Debug, Default)]
pub struct LineBits {
    /// Bit k of `x·dx` on every column line: `col[k * col_words + i]` holds lines 64i..64i+63.
    pub col: Vec<u64>,
    /// Bit k of `c0 + y·dy` on every row line: `row[k * row_words + i]` holds lines 64i..64i+63.
    pub row: Vec<u64>,
    /// Words per clock of `col`: ceil(width / 64).
    pub col_words: usize,
    /// Words per clock of `row`: ceil(height / 64).
    pub row_words: usize,
}

impl LineBits {
    /// The row line of row `y` at clock `k`, as a mask for all 64 lanes of a pixel word.
    #[inline(always)]
    pub fn row_mask(&self, k: usize, y: usize) -> u64 {
        0u64.wrapping_sub(self.row[k * self.row_words + y / 64] >> (y % 64) & 1)
    }
}

impl Tree {
    fn new(lines: usize) -> Tree {
        let words = lines.div_ceil(64);
        let levels = (usize::BITS - (lines.max(1) - 1).leading_zeros()) as usize;
        let mut mask = vec![0u64; levels * words];
        for j in 0..levels {
            for line in 0..words * 64 {
                if line >> j & 1 == 1 {
                    mask[j * words + line / 64] |= 1 << (line % 64);
                }
            }
        }
        Tree {
            words,
            mask,
            levels,
        }
    }

    /// Run the tree for N_D clocks: root value `root`, coefficient `d` added at every level.
    fn stream(&self, fmt: &WordFormat, root: i64, d: i64) -> Vec<u64> {
        let nd = fmt.bits() as usize;
        let mut out = vec![0u64; nd * self.words];
        let mut carry = vec![0u64; self.levels * self.words];
        let bcast = |w: i64, k: usize| 0u64.wrapping_sub((w >> k & 1) as u64);
        for k in 0..nd {
            for i in 0..self.words {
                let mut v = bcast(root, k);
                for j in 0..self.levels {
                    let add =
                        if k >= j { bcast(d, k - j) } else { 0 } & self.mask[j * self.words + i];
                    let c = &mut carry[j * self.words + i];
                    let s = v ^ add ^ *c;
                    *c = (v & add) | (*c & (v ^ add));
                    v = s;
                }
                out[k * self.words + i] = v;
            }
        }
        out
    }
}

impl DepGen {
    /// The x tree over `width` column lines and the y tree over `height` row lines, for words
    /// of format `fmt`.
    pub fn new(width: usize, height: usize, fmt: WordFormat) -> DepGen {
        DepGen {
            fmt,
            cols: Tree::new(width),
            rows: Tree::new(height),
        }
    }

    /// The column and row line bits of one plane, clock by clock.
    pub fn stream(&self, c: &Coeffs) -> LineBits {
        LineBits {
            col: self.cols.stream(&self.fmt, 0, c.dx),
            row: self.rows.stream(&self.fmt, c.c0, c.dy),
            col_words: self.cols.words,
            row_words: self.rows.words,
        }
    }
}

/// The pixel's one-bit serial adder: sum bit out, carry kept.
#[inline(always)]
pub fn pixel_add(col: u64, row: u64, carry: &mut u64) -> u64 {
    let s = col ^ row ^ *carry;
    *carry = (col & row) | (*carry & (col ^ row));
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_pixel_receives_its_plane_value_modulo_2_to_the_nd() {
        let fmt = WordFormat::new(3, 4, 2).unwrap();
        let (w, h) = (70, 5);
        let g = DepGen::new(w, h, fmt);
        for c in [
            Coeffs {
                c0: 5,
                dx: 3,
                dy: -7,
            },
            Coeffs {
                c0: fmt.min_word(),
                dx: fmt.max_word(),
                dy: 1,
            },
            Coeffs {
                c0: -1,
                dx: -1,
                dy: fmt.min_word(),
            },
        ] {
            let lines = g.stream(&c);
            for y in 0..h {
                for x in 0..w {
                    let mut carry = 0;
                    let mut v = 0i64;
                    for k in 0..fmt.bits() as usize {
                        let col = lines.col[k * lines.col_words + x / 64] >> (x % 64) & 1;
                        let row = lines.row_mask(k, y) & 1;
                        v |= (pixel_add(col, row, &mut carry) as i64 & 1) << k;
                    }
                    let want = fmt.wrap(c.c0 + x as i64 * c.dx + y as i64 * c.dy);
                    assert_eq!(fmt.wrap(v), want, "x={x} y={y} {c:?}");
                }
            }
        }
    }
}
