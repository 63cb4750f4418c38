//! The multiscale pyramid's downsample: a level's voxel from its ≤ 8 voxels of the level
//! below, by a rule that keeps labels (a colour code stays a colour code; no value is made
//! up by averaging).

use rayon::prelude::*;

/// The label of a coarse voxel from the values of the fine voxels it covers (8, or fewer at
/// a far edge the halving does not divide): the most frequent non-zero value, ties going to
/// the smallest such value; 0 only when every value is 0. So a thin part one voxel wide is
/// kept rather than lost to the empty space around it, and the result never depends on the
/// order of the values.
pub fn label_of(values: &[u8]) -> u8 {
    let Some(&first) = values.first() else {
        return 0;
    };
    if values.iter().all(|&v| v == first) {
        return first;
    }
    let (mut best, mut best_count) = (0u8, 0usize);
    for (n, &v) in values.iter().enumerate() {
        // Each value counted once, at its first occurrence.
        if v == 0 || values[..n].contains(&v) {
            continue;
        }
        let count = values[n..].iter().filter(|&&w| w == v).count();
        if count > best_count || (count == best_count && v < best) {
            (best, best_count) = (v, count);
        }
    }
    best
}

/// The next level of `n` slices of `nx × ny` values (X fastest, then Y, then slice), each
/// axis halved rounding up: `ceil(n/2)` slices of `ceil(nx/2) × ceil(ny/2)`, voxel (i, j, k)
/// [`label_of`] voxels (2i..2i+2, 2j..2j+2, 2k..2k+2) of `src` that exist.
pub fn downsample(src: &[u8], [nx, ny, n]: [usize; 3]) -> Vec<u8> {
    assert_eq!(src.len(), nx * ny * n, "downsample: {nx}x{ny}x{n}");
    let (mx, my, m) = (nx.div_ceil(2), ny.div_ceil(2), n.div_ceil(2));
    let mut out = vec![0u8; mx * my * m];
    if out.is_empty() {
        return out;
    }
    out.par_chunks_mut(mx * my)
        .enumerate()
        .for_each(|(k, slice)| {
            let ks = 2 * k..(2 * k + 2).min(n);
            for j in 0..my {
                let js = 2 * j..(2 * j + 2).min(ny);
                // The ≤ 4 fine lines (z, y) this coarse line is made from.
                let lines: Vec<&[u8]> = ks
                    .clone()
                    .flat_map(|z| js.clone().map(move |y| (z * ny + y) * nx))
                    .map(|row| &src[row..row + nx])
                    .collect();
                coarse_line(&lines, &mut slice[j * mx..(j + 1) * mx]);
            }
        });
    out
}

/// Coarse voxels made a block at a time: where every fine voxel of a block of
/// [`BLOCK`] coarse voxels holds one value (inside or outside a part, most of a volume),
/// that value ([`label_of`] of equal values), without sorting out each voxel's 8.
const BLOCK: usize = 32;

/// One coarse line `out` from its fine `lines` (each twice as long, rounding up).
fn coarse_line(lines: &[&[u8]], out: &mut [u8]) {
    let nx = lines[0].len();
    let mut values = [0u8; 8];
    for (b, block) in out.chunks_mut(BLOCK).enumerate() {
        let fine = 2 * b * BLOCK..(2 * (b + 1) * BLOCK).min(nx);
        let first = lines[0][fine.start];
        if lines.iter().all(|l| all_equal(&l[fine.clone()], first)) {
            block.fill(first);
            continue;
        }
        for (c, v) in block.iter_mut().enumerate() {
            let i = b * BLOCK + c;
            let mut len = 0;
            for l in lines {
                for &x in &l[2 * i..(2 * i + 2).min(nx)] {
                    values[len] = x;
                    len += 1;
                }
            }
            *v = label_of(&values[..len]);
        }
    }
}

/// Whether every byte of `s` is `v`: a whole block compared before looking at the result,
/// which the compiler turns into wide compares.
pub(crate) fn all_equal(s: &[u8], v: u8) -> bool {
    let mut blocks = s.chunks_exact(64);
    for c in &mut blocks {
        if c.iter().fold(0u8, |a, &b| a | (b ^ v)) != 0 {
            return false;
        }
    }
    blocks.remainder().iter().all(|&b| b == v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_most_frequent_non_zero_value_ties_to_the_smallest() {
        assert_eq!(label_of(&[0; 8]), 0);
        assert_eq!(label_of(&[7; 8]), 7);
        // One non-zero voxel among 7 empty ones wins: a part is never lost to emptiness.
        assert_eq!(label_of(&[0, 0, 0, 0, 0, 0, 0, 9]), 9);
        // Most frequent non-zero, whatever the zeros.
        assert_eq!(label_of(&[0, 0, 0, 3, 5, 5, 0, 0]), 5);
        assert_eq!(label_of(&[2, 4, 4, 4, 2, 0, 0, 0]), 4);
        // Ties to the smallest value, in any order.
        assert_eq!(label_of(&[0, 0, 9, 9, 3, 3, 0, 0]), 3);
        assert_eq!(label_of(&[3, 9, 3, 9, 0, 0, 0, 0]), 3);
        assert_eq!(label_of(&[200, 17, 1, 255, 0, 0, 0, 0]), 1);
        // Fewer voxels at a far edge; none at all is empty.
        assert_eq!(label_of(&[0, 6]), 6);
        assert_eq!(label_of(&[8]), 8);
        assert_eq!(label_of(&[]), 0);
        // Never an average: the result is one of the values.
        let v = [10, 20, 30, 40, 50, 60, 70, 80];
        assert_eq!(label_of(&v), 10);
    }

    /// The rule does not depend on the order of the values (every rotation and the reverse
    /// of a few sets).
    #[test]
    fn the_label_is_the_same_in_any_order() {
        for set in [
            [0u8, 1, 1, 2, 2, 3, 0, 0],
            [5, 5, 5, 0, 0, 0, 0, 4],
            [9, 8, 7, 9, 8, 7, 0, 1],
        ] {
            let want = label_of(&set);
            for r in 0..8 {
                let mut v = set;
                v.rotate_left(r);
                assert_eq!(label_of(&v), want, "{v:?}");
                v.reverse();
                assert_eq!(label_of(&v), want, "{v:?}");
            }
        }
    }

    /// Each coarse voxel [`label_of`] the fine voxels it covers, read one voxel at a time.
    fn naive(src: &[u8], [nx, ny, n]: [usize; 3]) -> Vec<u8> {
        let (mx, my) = (nx.div_ceil(2), ny.div_ceil(2));
        let mut out = vec![];
        for k in 0..n.div_ceil(2) {
            for j in 0..my {
                for i in 0..mx {
                    let mut v = vec![];
                    for z in 2 * k..(2 * k + 2).min(n) {
                        for y in 2 * j..(2 * j + 2).min(ny) {
                            for x in 2 * i..(2 * i + 2).min(nx) {
                                v.push(src[(z * ny + y) * nx + x]);
                            }
                        }
                    }
                    out.push(label_of(&v));
                }
            }
        }
        out
    }

    proptest::proptest! {
        /// Volumes mostly of long runs (where the block rule takes over) with voxels
        /// sprinkled in, at sides about the block's: the block rule changes no voxel.
        #[test]
        fn blocks_of_one_value_downsample_as_voxels_do(
            nx in 1usize..200, ny in 1usize..5, n in 1usize..5,
            runs in proptest::collection::vec((0u8..4, 1usize..150), 1..40),
            dots in proptest::collection::vec((0usize..4000, 0u8..6), 0..6),
        ) {
            let len = nx * ny * n;
            let mut src: Vec<u8> = runs.iter().flat_map(|&(v, r)| std::iter::repeat_n(v, r)).cycle().take(len).collect();
            for (at, v) in dots {
                if at < len {
                    src[at] = v;
                }
            }
            proptest::prop_assert_eq!(downsample(&src, [nx, ny, n]), naive(&src, [nx, ny, n]));
        }
    }

    /// Odd sides round up; each coarse voxel is the rule on the fine voxels it covers, read
    /// here one voxel at a time.
    #[test]
    fn downsample_halves_each_axis_rounding_up() {
        let [nx, ny, n] = [5, 3, 3];
        let src: Vec<u8> = (0..nx * ny * n).map(|v| (v * 7 % 5) as u8).collect();
        let out = downsample(&src, [nx, ny, n]);
        assert_eq!(out.len(), 3 * 2 * 2);
        for k in 0..2 {
            for j in 0..2 {
                for i in 0..3 {
                    let mut v = vec![];
                    for z in 2 * k..(2 * k + 2).min(n) {
                        for y in 2 * j..(2 * j + 2).min(ny) {
                            for x in 2 * i..(2 * i + 2).min(nx) {
                                v.push(src[(z * ny + y) * nx + x]);
                            }
                        }
                    }
                    assert_eq!(out[(k * 2 + j) * 3 + i], label_of(&v), "({i}, {j}, {k})");
                }
            }
        }
        // The corner voxel (2, 1, 1) covers one fine voxel: (4, 2, 2).
        assert_eq!(out[(2 + 1) * 3 + 2], src[(2 * ny + 2) * nx + 4]);
        assert!(downsample(&[], [0, 4, 4]).is_empty());
    }
}
