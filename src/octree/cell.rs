//! Dual cells (seed 000 §3.1.1.5, Figs. 3.16-3.18).
//!
//! Marching Cubes needs values at cube corners, so every voxel value is moved to the
//! right-top-back corner of a cell of the same size: cell (x, y, z) has the eight voxels
//! x−1..x, y−1..y, z−1..z as corners, and holds them packed into one byte, bit i for corner
//! Vi, which is exactly the Marching Cubes case index. Voxels outside the grid read as empty.
//! The cell grid has as many cells as the voxel grid (cells 0..side−1 on every axis), so no
//! cell has voxel side−1 as its minimum corner: a solid touching the grid's far faces gives
//! an open mesh there (the thesis's own convention, which Table 7.1 needs).

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

/// Bits of the cell byte contributed by a 2×2 voxel block of the slice z−1 (`LOW`) or of the
/// slice z (`HIGH`), indexed by the block code q = v(x−1,y−1) | v(x,y−1)<<1 | v(x−1,y)<<2 |
/// v(x,y)<<3.
const fn block_lut(high: bool) -> [u8; 16] {
    // (dx, dy) -> bit: dz = 0: (0,0) V0, (1,0) V1, (0,1) V4, (1,1) V5;
    // dz = 1: (0,0) V3, (1,0) V2, (0,1) V7, (1,1) V6.
    let bits: [u8; 4] = if high { [3, 2, 7, 6] } else { [0, 1, 4, 5] };
    let mut t = [0u8; 16];
    let mut q = 0;
    while q < 16 {
        let mut b = 0;
        while b < 4 {
            if q >> b & 1 == 1 {
                t[q] |= 1 << bits[b];
            }
            b += 1;
        }
        q += 1;
    }
    t
}

const LOW: [u8; 16] = block_lut(false);
const HIGH: [u8; 16] = block_lut(true);

/// Turns voxel slices, in order of z, into cell layers (seed 000 §3.1.1.5 done slice by
/// slice): cell layer z needs only voxel slices z−1 and z, so it keeps one slice of block
/// codes.
pub struct CellLayers {
    side: usize,
    /// Block codes of the previous slice (all 0 before slice 0).
    prev: Vec<u8>,
    cur: Vec<u8>,
    /// Rows whose block codes are all 0, in `prev` and `cur`.
    prev_zero: Vec<bool>,
    cur_zero: Vec<bool>,
    layer: Vec<u8>,
}

/// Voxel row y of a slice as 0/1 into `out` (empty past the slice); true when all empty.
fn occupancy_row(slice: &[u8], w: usize, h: usize, y: usize, out: &mut [u8]) -> bool {
    out.fill(0);
    if y >= h {
        return true;
    }
    let row = &slice[y * w..y * w + w.min(out.len())];
    let mut any = 0u8;
    for (o, &v) in out.iter_mut().zip(row) {
        *o = u8::from(v != 0);
        any |= v;
    }
    any == 0
}

impl CellLayers {
    /// Layers of `side`×`side` cells.
    pub fn new(side: usize) -> CellLayers {
        let n = side * side;
        CellLayers {
            side,
            prev: vec![0; n],
            cur: vec![0; n],
            prev_zero: vec![true; side],
            cur_zero: vec![true; side],
            layer: vec![0; n],
        }
    }

    /// Bytes it holds.
    pub fn bytes(side: usize) -> u64 {
        3 * (side as u64) * (side as u64)
    }

    /// The next cell layer from the next voxel slice: colour codes (0 = empty), `w` per row,
    /// X fastest (a [`crate::voxelize::Volume`] slice). Voxels beyond `w` or the slice's rows
    /// are empty; slices wider than the side are cut. Rows with no voxel in this slice nor
    /// the previous one are cleared without looking at each cell.
    pub fn next(&mut self, slice: &[u8], w: usize) -> &[u8] {
        let s = self.side;
        std::mem::swap(&mut self.prev, &mut self.cur);
        std::mem::swap(&mut self.prev_zero, &mut self.cur_zero);
        let h = slice.len().checked_div(w).unwrap_or(0);
        let (mut below, mut here) = (vec![0u8; s], vec![0u8; s]);
        let mut below_zero = true;
        for y in 0..s {
            std::mem::swap(&mut below, &mut here);
            let here_zero = occupancy_row(slice, w, h, y, &mut here);
            let at = y * s..(y + 1) * s;
            if here_zero && below_zero {
                self.cur[at.clone()].fill(0);
                self.cur_zero[y] = true;
                if self.prev_zero[y] {
                    self.layer[at].fill(0);
                } else {
                    for (c, &p) in self.layer[at.clone()].iter_mut().zip(&self.prev[at]) {
                        *c = LOW[p as usize];
                    }
                }
            } else {
                self.cur_zero[y] = false;
                self.mixed_row(y, &below, &here);
            }
            below_zero = here_zero;
        }
        &self.layer
    }

    /// Block codes and cell bytes of row y from the voxel rows y−1 (`below`) and y.
    fn mixed_row(&mut self, y: usize, below: &[u8], here: &[u8]) {
        let s = self.side;
        let cur = &mut self.cur[y * s..(y + 1) * s];
        let prev = &self.prev[y * s..(y + 1) * s];
        let out = &mut self.layer[y * s..(y + 1) * s];
        let mut left = 0u8;
        for x in 0..s {
            let right = below[x] | here[x] << 1;
            let q = Self::code(left, right);
            cur[x] = q;
            out[x] = LOW[prev[x] as usize] | HIGH[q as usize];
            left = right;
        }
    }

    /// The layer after the last slice (an empty slice), for grids shorter than the side.
    pub fn next_empty(&mut self) -> &[u8] {
        self.next(&[], 0)
    }

    /// Block code from the column pairs (x−1: `left`, x: `right`), each `v(y−1) | v(y) << 1`.
    fn code(left: u8, right: u8) -> u8 {
        (left & 1) | (right & 1) << 1 | (left >> 1) << 2 | (right >> 1) << 3
    }
}
