//! Slices: what the array's images become on the way to voxels (§3.4, §4.4).
//!
//! A slice is one slab of the volume, seen as a W×H image. For every primitive the slice
//! holds a [`Mask`], one bit per pixel: is this voxel inside the primitive? The evaluators
//! ([`SliceEval`]: the Blist of §4.5, the recursive tree of §4.2, the slice stack of §3.4.1)
//! turn those masks into the scene's own slice: per voxel, outside, or inside with the colour of
//! the primitive that the evaluator's rule picks.

use serde::Serialize;

/// One bit per pixel of a slice (pixel index y·W + x), 64 pixels to a `u64`, bit i of word
/// i / 64 for pixel i. Bits past `len` in the last word are always 0.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Mask {
    len: usize,
    words: Vec<u64>,
}

impl Mask {
    /// All pixels clear.
    pub fn new(len: usize) -> Mask {
        Mask {
            len,
            words: vec![0; len.div_ceil(64)],
        }
    }

    /// All pixels set.
    pub fn full(len: usize) -> Mask {
        let mut m = Mask {
            len,
            words: vec![!0; len.div_ceil(64)],
        };
        m.clear_tail();
        m
    }

    /// Pixels where `f(i)` holds.
    pub fn from_fn(len: usize, mut f: impl FnMut(usize) -> bool) -> Mask {
        let mut m = Mask::new(len);
        for i in 0..len {
            if f(i) {
                m.set(i, true);
            }
        }
        m
    }

    /// Pixels of the mask.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the mask has no pixel at all.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Whether pixel i is set.
    pub fn get(&self, i: usize) -> bool {
        self.words[i / 64] >> (i % 64) & 1 == 1
    }

    /// Set pixel i to `v`.
    pub fn set(&mut self, i: usize, v: bool) {
        let bit = 1u64 << (i % 64);
        if v {
            self.words[i / 64] |= bit;
        } else {
            self.words[i / 64] &= !bit;
        }
    }

    /// Set pixels `r` (a word at a time).
    pub fn set_range(&mut self, r: std::ops::Range<usize>) {
        let (mut i, end) = (r.start, r.end.min(self.len));
        while i < end {
            let (w, bit) = (i / 64, i % 64);
            let n = (64 - bit).min(end - i);
            let ones = if n == 64 {
                !0
            } else {
                ((1u64 << n) - 1) << bit
            };
            self.words[w] |= ones;
            i += n;
        }
    }

    /// Flip pixel i.
    pub fn toggle(&mut self, i: usize) {
        self.words[i / 64] ^= 1u64 << (i % 64);
    }

    /// Pixels set.
    pub fn count_ones(&self) -> usize {
        self.words.iter().map(|w| w.count_ones() as usize).sum()
    }

    /// The words, for evaluators that work 64 pixels at a time.
    pub fn words(&self) -> &[u64] {
        &self.words
    }

    /// The words, mutable; callers keep the bits past `len` clear (see [`Mask::clear_tail`]).
    pub fn words_mut(&mut self) -> &mut [u64] {
        &mut self.words
    }

    /// Clear the bits past `len` in the last word (after a NOT, for example).
    pub fn clear_tail(&mut self) {
        if !self.len.is_multiple_of(64) {
            if let Some(last) = self.words.last_mut() {
                *last &= (1u64 << (self.len % 64)) - 1;
            }
        }
    }

    /// Indices of the set pixels, in order.
    pub fn ones(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.len).filter(|&i| self.get(i))
    }
}

/// Work counted the way §5.5 counts it, summed over the voxels (or 64-voxel words, for the
/// bit-parallel stack sweep: see each evaluator) of a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct OpCounts {
    /// Voxel-primitive classifications looked at (Blist: label = name tests that pass; tree:
    /// leaves visited).
    pub comparisons: u64,
    /// Intermediate results pushed on a stack.
    pub pushes: u64,
    /// Intermediate results popped from a stack.
    pub pops: u64,
    /// Label register writes (Blist only).
    pub label_writes: u64,
}

impl std::ops::AddAssign for OpCounts {
    fn add_assign(&mut self, o: OpCounts) {
        self.comparisons += o.comparisons;
        self.pushes += o.pushes;
        self.pops += o.pops;
        self.label_writes += o.label_writes;
    }
}

/// Word `w` (voxels 64·w .. 64·w + 63) of primitive `p`'s mask in `prims`; a missing or short
/// mask contains nothing.
pub fn prim_word(prims: &[Mask], p: usize, w: usize) -> u64 {
    prims
        .get(p)
        .and_then(|m| m.words().get(w))
        .copied()
        .unwrap_or(0)
}

/// Pixels in the slice: the length of the longest primitive mask (0 when there is none). A
/// shorter mask contains nothing past its end, so a primitive absent from a slice can be an
/// empty mask that costs no allocation ([`crate::runs`]).
pub fn slice_len(prims: &[Mask]) -> usize {
    prims.iter().map(Mask::len).max().unwrap_or(0)
}

/// The scene's slice: per pixel, 0 when outside the scene, else 1 + the index of the
/// primitive whose colour the voxel takes.
pub type Labels = Vec<u32>;

/// An evaluator of one CSG tree over the primitive masks of a slice.
pub trait SliceEval: Sync {
    /// `prims[i]` is the mask of primitive i (the tree's `Solid(i)`); the slice is as long as
    /// the longest ([`slice_len`]), a shorter or missing mask contains nothing past its end.
    fn eval(&self, prims: &[Mask], counts: &mut OpCounts) -> Labels;

    /// Bytes of per-voxel intermediate state the evaluator keeps (label register, stack…),
    /// for a slice of `pixels` voxels.
    fn state_bytes(&self, pixels: usize) -> usize;
}

#[cfg(test)]
pub(crate) mod suite;

#[cfg(test)]
mod tests {
    use super::Mask;

    #[test]
    fn set_range_sets_exactly_the_range() {
        for len in [1, 63, 64, 65, 130] {
            for a in 0..len {
                for b in a..=len {
                    let mut m = Mask::new(len);
                    m.set_range(a..b);
                    let ok = (0..len).all(|i| m.get(i) == (a..b).contains(&i));
                    assert!(ok, "{len} {a}..{b}");
                    assert_eq!(m.count_ones(), b - a);
                }
            }
        }
    }
}
