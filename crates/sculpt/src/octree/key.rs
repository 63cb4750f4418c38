//! Location keys of the hash-based octrees (seed 000 §4.3.3.1, Eqs. 4.1-4.7).
//!
//! A node at level `l` (root = level 0) with integer coordinates (x, y, z) at that level's
//! resolution has the key `1 ‖ z_{l-1} y_{l-1} x_{l-1} … z_0 y_0 x_0`: a leading 1 followed by
//! the Morton code, three bits per level, x the least significant bit of each triplet (the
//! "(z)yx" order of Fig. 4.1). The child of `k` with location code `c` is `k << 3 | c`, the
//! parent is `k >> 3`, and the level is `(bit_length(k) - 1) / 3`.

/// A node key (seed 000 §4.3.3.1). 3·l + 1 bits at level l.
pub type Key = u64;

/// Deepest level a key may have: 3·21 + 1 = 64 bits would not leave room, 20 levels use 61.
pub const MAX_DEPTH: u32 = 20;

/// The root's key.
pub const ROOT: Key = 1;

/// `v` with two zero bits inserted between its bits (DIL of Eq. 4.1, 3D); `v` < 2^21.
pub fn dilate3(v: u32) -> u64 {
    let mut x = u64::from(v) & 0x1f_ffff;
    x = (x | x << 32) & 0x001f_0000_0000_ffff;
    x = (x | x << 16) & 0x001f_0000_ff00_00ff;
    x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
    x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
    (x | x << 2) & 0x1249_2492_4924_9249
}

/// The inverse of [`dilate3`]: every third bit of `d`, starting at bit 0.
#[inline]
pub fn undilate3(d: u64) -> u32 {
    let mut x = d & 0x1249_2492_4924_9249;
    x = (x | x >> 2) & 0x10c3_0c30_c30c_30c3;
    x = (x | x >> 4) & 0x100f_00f0_0f00_f00f;
    x = (x | x >> 8) & 0x001f_0000_ff00_00ff;
    x = (x | x >> 16) & 0x001f_0000_0000_ffff;
    x = (x | x >> 32) & 0x1f_ffff;
    x as u32
}

/// INT(x, y, z) = DIL(z) << 2 | DIL(y) << 1 | DIL(x) (Eq. 4.5: the OCR's "<<4", "<<2" are
/// damaged; the bit pattern z y x of each triplet needs shifts of 2 and 1).
pub fn interleave(x: u32, y: u32, z: u32) -> u64 {
    dilate3(z) << 2 | dilate3(y) << 1 | dilate3(x)
}

/// KEY = 1 ‖ INT (Eq. 4.7): the key of node (x, y, z) at `level`.
pub fn key(x: u32, y: u32, z: u32, level: u32) -> Key {
    1 << (3 * level) | interleave(x, y, z)
}

/// The parent's key (seed 000 §4.3.4: no parent pointers, `key >> 3`).
pub fn parent(k: Key) -> Key {
    k >> 3
}

/// The child of `k` with location code `c` = z·4 + y·2 + x (Fig. 4.1).
pub fn child(k: Key, c: u8) -> Key {
    k << 3 | Key::from(c & 7)
}

/// The level of a key: (bit length − 1) / 3. Key 0 is not a key; it gets level 0.
#[inline]
pub fn level(k: Key) -> u32 {
    (63 - k.max(1).leading_zeros()) / 3
}

/// Level and coordinates of a key (the inverse of [`key`]).
#[inline]
pub fn coords(k: Key) -> (u32, [u32; 3]) {
    let l = level(k);
    let int = k & !(1 << (3 * l));
    (
        l,
        [undilate3(int), undilate3(int >> 1), undilate3(int >> 2)],
    )
}

/// Does the node of key `k` reach a far face of the grid (a coordinate all ones at its
/// level)? The root does.
#[inline]
pub fn reaches_far_face(k: Key) -> bool {
    let ones = X_ONES[level(k) as usize];
    k & ones == ones || k >> 1 & ones == ones || k >> 2 & ones == ones
}

/// `X_ONES[l]`: the x bits of a key at level l (every third bit below bit 3·l).
const X_ONES: [u64; 22] = {
    let mut t = [0u64; 22];
    let mut l = 1;
    while l < 22 {
        t[l] = t[l - 1] | 1 << (3 * (l - 1));
        l += 1;
    }
    t
};

/// The quadtree key of pixel (x, y) at `level` (the 2D examples of seed 000 Figs. 4.7, 5.1):
/// 1 followed by y x bit pairs, x the least significant.
pub fn key2(x: u32, y: u32, level: u32) -> Key {
    let dil = |v: u32| (0..level).fold(0u64, |a, b| a | u64::from(v >> b & 1) << (2 * b));
    1 << (2 * level) | dil(y) << 1 | dil(x)
}

/// Pixel (x, y) and level of a quadtree key (the inverse of [`key2`]).
#[inline]
pub fn coords2(k: Key) -> (u32, [u32; 2]) {
    let l = (63 - k.max(1).leading_zeros()) / 2;
    let pick = |s: u32| (0..l).fold(0u32, |a, b| a | ((k >> (2 * b + s) & 1) as u32) << b);
    (l, [pick(0), pick(1)])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn naive_dilate(v: u32) -> u64 {
        (0..21).fold(0, |a, b| a | u64::from(v >> b & 1) << (3 * b))
    }

    #[test]
    fn dilation_matches_the_bit_by_bit_definition() {
        for v in [0, 1, 2, 3, 5, 255, 511, 1023, 0x1f_ffff, 0x15_5555, 123_456] {
            assert_eq!(dilate3(v), naive_dilate(v), "{v}");
            assert_eq!(undilate3(dilate3(v)), v);
        }
    }

    #[test]
    fn key_of_a_voxel_by_hand() {
        // (x, y, z) = (1, 0, 1) at level 1: code z y x = 101, key 1101 = 13.
        assert_eq!(key(1, 0, 1, 1), 0b1101);
        // (3, 1, 2) at level 2: x = 11, y = 01, z = 10: triplets (z1 y1 x1)(z0 y0 x0) =
        // (1 0 1)(0 1 1): key 1 101 011 = 0b1101011 = 107.
        assert_eq!(key(3, 1, 2, 2), 107);
        assert_eq!(coords(107), (2, [3, 1, 2]));
        assert_eq!(parent(107), 0b1101);
        assert_eq!(child(0b1101, 0b011), 107);
        assert_eq!(level(ROOT), 0);
        assert_eq!(level(107), 2);
    }

    #[test]
    fn far_faces_are_reached_by_coordinates_all_ones() {
        for l in 0..=3u32 {
            let n = 1u32 << l;
            for z in 0..n {
                for y in 0..n {
                    for x in 0..n {
                        let want = [x, y, z].contains(&(n - 1));
                        assert_eq!(reaches_far_face(key(x, y, z, l)), want, "{l} {x} {y} {z}");
                    }
                }
            }
        }
        let top = (1 << 20) - 1;
        assert!(reaches_far_face(key(3, top, 5, 20)));
        assert!(!reaches_far_face(key(3, top - 1, 5, 20)));
    }
}
