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
            let mut values = [0u8; 8];
            for j in 0..my {
                let js = 2 * j..(2 * j + 2).min(ny);
                for i in 0..mx {
                    let is = 2 * i..(2 * i + 2).min(nx);
                    let mut len = 0;
                    for z in ks.clone() {
                        for y in js.clone() {
                            let row = (z * ny + y) * nx;
                            for x in is.clone() {
                                values[len] = src[row + x];
                                len += 1;
                            }
                        }
                    }
                    slice[j * mx + i] = label_of(&values[..len]);
                }
            }
        });
    out
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
