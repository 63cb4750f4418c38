//! Dual cells (seed 000 §3.1.1.5, Figs. 3.16-3.18).
//!
//! Marching Cubes needs values at cube corners, so every voxel value is moved to the
//! right-top-back corner of a cell of the same size: cell (x, y, z) has the eight voxels
//! x−1..x, y−1..y, z−1..z as corners, and holds them packed into one byte, bit i for corner
//! Vi, which is exactly the Marching Cubes case index. Voxels outside the grid read as empty.
//! The stored cell grid has as many cells as the voxel grid (cells 0..side−1 on every axis),
//! as the thesis has it (Table 7.1's node counts need exactly this). No stored cell has voxel
//! side−1 as its minimum corner, so Marching Cubes also visits the cells just past the far
//! faces (a coordinate equal to side): they are not stored, their bytes come from the stored
//! cell they border ([`beyond`]), and with them every mesh is closed.

/// Corner offsets (dx, dy, dz) of bit i, from the cell's minimum corner voxel (x−1, y−1, z−1):
/// the order of Fig. 3.18, which is Lorensen's and Bourke's with y up.
pub const CORNERS: [[u8; 3]; 8] = [
    [0, 0, 0],
    [1, 0, 0],
    [1, 0, 1],
    [0, 0, 1],
    [0, 1, 0],
    [1, 1, 0],
    [1, 1, 1],
    [0, 1, 1],
];

/// Corners of edge e (Bourke's numbering: e0 = V0-V1 … e11 = V3-V7).
pub const EDGES: [[u8; 2]; 12] = [
    [0, 1],
    [1, 2],
    [2, 3],
    [3, 0],
    [4, 5],
    [5, 6],
    [6, 7],
    [7, 4],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
];

/// The bit of the voxel (x, y, z) itself in cell (x, y, z): corner (1, 1, 1) = V6.
pub const SELF_BIT: u8 = 6;

/// The case byte of corners V0..V7 (true = filled).
pub fn case_of(corners: [bool; 8]) -> u8 {
    (0..8).fold(0, |a, i| a | u8::from(corners[i]) << i)
}

/// The edges a case cuts: those whose two corners differ (Bourke's `edgeTable`).
pub fn cut_edges(case: u8) -> u16 {
    (0..12).fold(0, |a, e| {
        let [p, q] = EDGES[e];
        a | u16::from((case >> p ^ case >> q) & 1 == 1) << e
    })
}

/// The byte of a cell past the grid's far faces, from the stored cell it borders: the cell at
/// coordinate side on the axes of `far` (bit a for axis a) and the stored cell `v` at
/// side−1 on those axes, the same elsewhere. Its corners past the grid (offset 1 on a far
/// axis) are empty; the others are the stored cell's corners at offset 1 on the far axes.
pub const fn beyond(v: u8, far: u8) -> u8 {
    let mut out = 0u8;
    let mut i = 0;
    while i < 8 {
        let c = CORNERS[i];
        let mut src = c;
        let mut outside = false;
        let mut a = 0;
        while a < 3 {
            if far >> a & 1 == 1 {
                outside |= c[a] == 1;
                src[a] = 1;
            }
            a += 1;
        }
        if !outside {
            let mut j = 0;
            while j < 8 {
                let d = CORNERS[j];
                if d[0] == src[0] && d[1] == src[1] && d[2] == src[2] {
                    out |= (v >> j & 1) << i;
                }
                j += 1;
            }
        }
        i += 1;
    }
    out
}

/// [`beyond`] for every byte and set of far axes: `BEYOND[far][v]`.
pub const BEYOND: [[u8; 256]; 8] = {
    let mut t = [[0u8; 256]; 8];
    let mut far = 1;
    while far < 8 {
        let mut v = 0;
        while v < 256 {
            t[far][v] = beyond(v as u8, far as u8);
            v += 1;
        }
        far += 1;
    }
    t
};

/// The cells past the far faces of a grid of `side` cells that a leaf borders, with their
/// bytes when they have a surface: the leaf at cell `p`, `size` cells a side, of byte `v` (a
/// coarse leaf's is 0 or 255). Nothing unless the leaf reaches a far face and is not empty.
#[inline]
pub fn beyond_leaf(p: [u32; 3], size: u32, v: u8, side: u32, f: &mut impl FnMut([u32; 3], u8)) {
    if v == 0 {
        return;
    }
    let far = (0..3).fold(0u8, |m, a| m | u8::from(p[a] + size == side) << a);
    if far == 0 {
        return;
    }
    for b in 1..8u8 {
        let w = BEYOND[b as usize][v as usize];
        if b & !far != 0 || w == 0 {
            continue;
        }
        let span = |a: usize| {
            if b >> a & 1 == 1 {
                side..side + 1
            } else {
                p[a]..p[a] + size
            }
        };
        for z in span(2) {
            for y in span(1) {
                for x in span(0) {
                    f([x, y, z], w);
                }
            }
        }
    }
}

/// Corners at offset 1 on each axis: `FAR_CORNERS[a]` has bit i when corner Vi's a is 1.
pub const FAR_CORNERS: [u8; 3] = {
    let mut t = [0u8; 3];
    let mut i = 0;
    while i < 8 {
        let mut a = 0;
        while a < 3 {
            t[a] |= CORNERS[i][a] << i;
            a += 1;
        }
        i += 1;
    }
    t
};

/// Does deepest cell `c` of byte `v` border a cell past a far face with a surface (a filled
/// corner on that face)? Cheap, so that traversals call [`beyond_node`] only then.
#[inline]
pub fn borders_far_cells(c: [u32; 3], v: u8, side: u32) -> bool {
    let on = |a: usize| (c[a] == side - 1) & (v & FAR_CORNERS[a] != 0);
    on(0) | on(1) | on(2)
}

/// [`beyond_leaf`] out of line, for the traversals' rare calls.
#[cold]
#[inline(never)]
pub fn beyond_leaf_cold(
    p: [u32; 3],
    size: u32,
    v: u8,
    side: u32,
    f: &mut impl FnMut([u32; 3], u8),
) {
    beyond_leaf(p, size, v, side, f);
}

/// [`beyond_leaf`] of the leaf with key `k` in a tree of `depth` levels, out of line: the
/// traversals call it only for the few leaves on a far face.
#[cold]
#[inline(never)]
pub fn beyond_node(k: super::key::Key, depth: u32, v: u8, f: &mut impl FnMut([u32; 3], u8)) {
    let (l, c) = super::key::coords(k);
    let s = depth - l;
    beyond_leaf(c.map(|c| c << s), 1 << s, v, 1 << depth, f);
}

/// One stored leaf of a hashed store (key `k`, byte `v`) to the surface traversal: a deepest
/// surface cell to `f`, then the cells past the far faces it or a full leaf there borders.
#[inline(always)]
pub fn hashed_leaf(k: super::key::Key, v: u8, depth: u32, f: &mut impl FnMut([u32; 3], u8)) {
    if v.wrapping_sub(1) < 254 {
        let c = super::key::coords(k).1;
        f(c, v);
        if borders_far_cells(c, v, 1 << depth) {
            beyond_node(k, depth, v, f);
        }
    } else if v == 255 && super::key::reaches_far_face(k) {
        beyond_node(k, depth, v, f);
    }
}

/// One leaf of a pointer tree at `level` and cell `p` (in its level's units) to the surface
/// traversal, as [`hashed_leaf`].
#[inline(always)]
pub fn tree_leaf(p: [u32; 3], level: u32, depth: u32, v: u8, f: &mut impl FnMut([u32; 3], u8)) {
    let (s, side) = (depth - level, 1 << depth);
    if s == 0 && v != 0 && v != 255 {
        f(p, v);
        if borders_far_cells(p, v, side) {
            beyond_leaf_cold(p, 1, v, side, f);
        }
    } else if v == 255 && p.iter().any(|&c| (c + 1) << s == side) {
        beyond_leaf_cold(p.map(|c| c << s), 1 << s, v, side, f);
    }
}

/// The byte of cell (x, y, z) with `voxel(i, j, k)` giving occupancy; cells read voxels
/// x−1..x etc., so `voxel` must answer false outside the grid (including −1).
pub fn cell_of(voxel: impl Fn(i64, i64, i64) -> bool, x: i64, y: i64, z: i64) -> u8 {
    let c = CORNERS.map(|[dx, dy, dz]| {
        voxel(
            x - 1 + i64::from(dx),
            y - 1 + i64::from(dy),
            z - 1 + i64::from(dz),
        )
    });
    case_of(c)
}

/// `SPREAD[b]` has byte i equal to bit i of b: eight cells' bits of one corner, moved to
/// their bytes.
const SPREAD: [u64; 256] = {
    let mut t = [0u64; 256];
    let mut b = 0;
    while b < 256 {
        let mut i = 0;
        while i < 8 {
            t[b] |= ((b as u64 >> i) & 1) << (8 * i);
            i += 1;
        }
        b += 1;
    }
    t
};

/// Bit i set when byte i of `v` is not 0.
fn nonzero_bits(v: u64) -> u64 {
    let mut t = v | v >> 4;
    t |= t >> 2;
    t |= t >> 1;
    (t & 0x0101_0101_0101_0101).wrapping_mul(0x0102_0408_1020_4080) >> 56
}

/// Turns voxel slices, in order of z, into cell layers (seed 000 §3.1.1.5 done slice by
/// slice): cell layer z needs only voxel slices z−1 and z, so it keeps the occupancy of one
/// slice, a bit per voxel. A cell's byte gathers 8 corner bits (rows y−1 and y of slices
/// z−1 and z, columns x−1 and x); 64 cells are done a word at a time, and 8 of them with one
/// table lookup per corner.
pub struct CellLayers {
    side: usize,
    /// 64-bit words per voxel row.
    words: usize,
    /// Occupancy bits of the previous slice and of this one, `words` per row.
    prev: Vec<u64>,
    cur: Vec<u64>,
    /// Rows with no voxel, in `prev` and `cur`.
    prev_zero: Vec<bool>,
    cur_zero: Vec<bool>,
    layer: Vec<u8>,
}

/// The 8 corner planes of 64 cells: for each corner Vi, bit j is that corner of cell 64k + j.
/// `rows` are the words of voxel rows (slice z−1, y−1), (z−1, y), (z, y−1), (z, y) at cell x
/// and `left` the same rows' words one voxel to the left (x − 1).
fn corner_planes(rows: [u64; 4], left: [u64; 4]) -> [u64; 8] {
    let [a, b, c, d] = rows;
    let [al, bl, cl, dl] = left;
    // V0..V7 (CORNERS): (0,0,0) (1,0,0) (1,0,1) (0,0,1) (0,1,0) (1,1,0) (1,1,1) (0,1,1).
    [al, a, c, cl, bl, b, d, dl]
}

impl CellLayers {
    /// Layers of `side`×`side` cells.
    pub fn new(side: usize) -> CellLayers {
        let words = side.div_ceil(64);
        CellLayers {
            side,
            words,
            prev: vec![0; side * words],
            cur: vec![0; side * words],
            prev_zero: vec![true; side],
            cur_zero: vec![true; side],
            layer: vec![0; side * side],
        }
    }

    /// Bytes it holds.
    pub fn bytes(side: usize) -> u64 {
        let side = side as u64;
        side * side + 2 * side * side.div_ceil(64) * 8 + 2 * side
    }

    /// The next cell layer from the next voxel slice: colour codes (0 = empty), `w` per row,
    /// X fastest (a [`csgpix_scene::grid::Volume`] slice). Voxels beyond `w` or the slice's rows
    /// are empty; slices wider than the side are cut. Rows with no voxel in this slice nor
    /// the previous one are cleared without looking at each cell.
    pub fn next(&mut self, slice: &[u8], w: usize) -> &[u8] {
        std::mem::swap(&mut self.prev, &mut self.cur);
        std::mem::swap(&mut self.prev_zero, &mut self.cur_zero);
        let h = slice.len().checked_div(w).unwrap_or(0);
        for y in 0..self.side {
            let row = if y < h {
                &slice[y * w..(y + 1) * w]
            } else {
                &[]
            };
            self.cur_zero[y] = self.occupancy(y, row);
        }
        for y in 0..self.side {
            self.cell_row(y);
        }
        &self.layer
    }

    /// Voxel row y of this slice into bits; true when it has no voxel.
    fn occupancy(&mut self, y: usize, row: &[u8]) -> bool {
        let out = &mut self.cur[y * self.words..(y + 1) * self.words];
        let row = &row[..row.len().min(self.side)];
        let mut any = 0;
        for (k, o) in out.iter_mut().enumerate() {
            let part = row.get(64 * k..row.len().min(64 * k + 64)).unwrap_or(&[]);
            let mut bits = 0u64;
            for (g, chunk) in part.chunks(8).enumerate() {
                let mut b = [0u8; 8];
                b[..chunk.len()].copy_from_slice(chunk);
                bits |= nonzero_bits(u64::from_le_bytes(b)) << (8 * g);
            }
            *o = bits;
            any |= bits;
        }
        any == 0
    }

    /// Cell row y of the layer from voxel rows y − 1 and y of the two slices.
    fn cell_row(&mut self, y: usize) {
        let (s, nw) = (self.side, self.words);
        let out = &mut self.layer[y * s..(y + 1) * s];
        let below = y.checked_sub(1);
        let zero = |z: &[bool]| z[y] && below.filter(|&b| !z[b]).is_none();
        if zero(&self.prev_zero) && zero(&self.cur_zero) {
            out.fill(0);
            return;
        }
        let word = |v: &[u64], r: Option<usize>, k: usize| r.map_or(0, |r| v[r * nw + k]);
        let mut carry = [0u64; 4];
        for (k, cells) in out.chunks_mut(64).enumerate() {
            let rows = [
                word(&self.prev, below, k),
                word(&self.prev, Some(y), k),
                word(&self.cur, below, k),
                word(&self.cur, Some(y), k),
            ];
            let left: [u64; 4] = std::array::from_fn(|i| rows[i] << 1 | carry[i] >> 63);
            carry = rows;
            write_cells(corner_planes(rows, left), cells);
        }
    }

    /// The layer after the last slice (an empty slice), for grids shorter than the side.
    pub fn next_empty(&mut self) -> &[u8] {
        self.next(&[], 0)
    }
}

/// Up to 64 cell bytes from their corner planes.
fn write_cells(planes: [u64; 8], cells: &mut [u8]) {
    if planes.iter().all(|&p| p == 0) {
        cells.fill(0);
        return;
    }
    if cells.len() == 64 && planes.iter().all(|&p| p == u64::MAX) {
        cells.fill(255);
        return;
    }
    for (g, out) in cells.chunks_mut(8).enumerate() {
        let mut v = 0u64;
        for (i, p) in planes.iter().enumerate() {
            v |= SPREAD[(p >> (8 * g) & 0xff) as usize] << i;
        }
        out.copy_from_slice(&v.to_le_bytes()[..out.len()]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Cell layers of random slices `w` wide and `h` high, against [`cell_of`] on every cell.
    fn check_layers(side: usize, w: usize, h: usize, slices: usize) {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64 ^ (side * 31 + w) as u64;
        let mut vox = vec![0u8; w * h * slices];
        for v in &mut vox {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            // Mostly runs of one value, so whole words are empty or full too.
            *v = if seed % 16 < 7 {
                (seed >> 8) as u8 | 1
            } else {
                0
            };
        }
        for row in vox.chunks_mut(w).step_by(3) {
            row.fill(1);
        }
        let filled = |x: i64, y: i64, z: i64| {
            let (x, y, z) = (x as usize, y as usize, z as usize);
            x < w.min(side) && y < h && z < slices && vox[(z * h + y) * w + x] != 0
        };
        let inside = |x: i64, y: i64, z: i64| x >= 0 && y >= 0 && z >= 0 && filled(x, y, z);
        let mut layers = CellLayers::new(side);
        for z in 0..=slices {
            let layer = match vox.chunks(w * h).nth(z) {
                Some(s) => layers.next(s, w).to_vec(),
                None => layers.next_empty().to_vec(),
            };
            for y in 0..side {
                for x in 0..side {
                    let want = cell_of(inside, x as i64, y as i64, z as i64);
                    assert_eq!(layer[y * side + x], want, "side {side} w {w} ({x},{y},{z})");
                }
            }
        }
    }

    #[test]
    fn cells_past_the_far_faces_read_the_voxels_they_border() {
        // Random 3³ volumes in a 2³-voxel grid (side 2): every cell with a coordinate 2 from
        // `beyond_leaf` of the cells, against `cell_of` with the voxels past the grid empty.
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..200 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let bits = seed as u8;
            let voxel = |x: i64, y: i64, z: i64| {
                (0..2).contains(&x)
                    && (0..2).contains(&y)
                    && (0..2).contains(&z)
                    && bits >> (z * 4 + y * 2 + x) & 1 == 1
            };
            let mut got = std::collections::BTreeMap::new();
            for z in 0..2u32 {
                for y in 0..2u32 {
                    for x in 0..2u32 {
                        let v = cell_of(voxel, x.into(), y.into(), z.into());
                        beyond_leaf([x, y, z], 1, v, 2, &mut |p, w| {
                            assert!(got.insert(p, w).is_none(), "{p:?} twice");
                        });
                    }
                }
            }
            for z in 0..3u32 {
                for y in 0..3u32 {
                    for x in 0..3u32 {
                        if ![x, y, z].contains(&2) {
                            continue;
                        }
                        let want = cell_of(voxel, x.into(), y.into(), z.into());
                        let have = got.get(&[x, y, z]).copied().unwrap_or(0);
                        assert_eq!(have, want, "{bits:08b} cell {:?}", [x, y, z]);
                    }
                }
            }
        }
        // A full coarse leaf of 2³ cells on the far corner of a 4³ grid: 3·4 + 3·2 + 1 cells.
        let mut n = 0;
        beyond_leaf([2, 2, 2], 2, 255, 4, &mut |_, _| n += 1);
        assert_eq!(n, 19);
    }

    #[test]
    fn cell_layers_from_bits_equal_the_dual_cells() {
        check_layers(128, 100, 90, 3);
        check_layers(64, 64, 64, 2);
        check_layers(64, 70, 10, 2); // rows wider than the side are cut
        check_layers(8, 5, 8, 3);
        check_layers(2, 1, 1, 1);
    }
}
