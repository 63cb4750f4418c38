//! The dense grid: one case byte per cell (seed 000 §3.1.1.5's `CellData[res³]`), the
//! baseline every octree is checked against.

use super::key::{self, Key};
use super::{Slices, StoreBuilder, StoreKind, SurfaceWalk, VoxelStore};
use crate::Result;

/// side³ cells, X fastest, then Y, then Z.
#[derive(Clone, Debug)]
pub struct DenseGrid {
    depth: u32,
    cells: Vec<u8>,
}

/// Cell layers appended as they come.
pub struct Builder {
    slices: Slices,
    cells: Vec<u8>,
}

impl Builder {
    /// A builder of a grid of side 2^depth from slices `width` voxels wide.
    pub fn new(depth: u32, width: usize) -> Builder {
        let side = 1usize << depth;
        Builder {
            slices: Slices::new(depth, width),
            cells: Vec::with_capacity(side * side * side),
        }
    }
}

impl StoreBuilder for Builder {
    fn push(&mut self, k: usize, slice: &[u8]) -> Result<()> {
        let layer = self.slices.push(k, slice)?;
        self.cells.extend_from_slice(layer);
        Ok(())
    }

    fn finish(mut self: Box<Self>) -> Result<Box<dyn VoxelStore>> {
        while let Some(layer) = self.slices.pad() {
            self.cells.extend_from_slice(layer);
        }
        Ok(Box::new(DenseGrid {
            depth: self.slices.depth(),
            cells: std::mem::take(&mut self.cells),
        }))
    }
}

impl DenseGrid {
    fn index(&self, x: u32, y: u32, z: u32) -> Option<usize> {
        let s = 1usize << self.depth;
        let (x, y, z) = (x as usize, y as usize, z as usize);
        (x < s && y < s && z < s).then_some((z * s + y) * s + x)
    }
}

impl VoxelStore for DenseGrid {
    fn kind(&self) -> StoreKind {
        StoreKind::Dense
    }

    fn depth(&self) -> u32 {
        self.depth
    }

    fn cell(&self, x: u32, y: u32, z: u32) -> u8 {
        self.index(x, y, z).map_or(0, |i| self.cells[i])
    }

    fn node_count(&self) -> usize {
        self.cells.len()
    }

    fn internal_count(&self) -> usize {
        0
    }

    fn bytes(&self) -> usize {
        self.cells.capacity()
    }

    fn for_each_leaf(&self, f: &mut dyn FnMut(Key, u8)) {
        let s = 1usize << self.depth;
        for (i, &v) in self.cells.iter().enumerate() {
            let (x, y, z) = (i % s, i / s % s, i / (s * s));
            f(key::key(x as u32, y as u32, z as u32, self.depth), v);
        }
    }
}

impl SurfaceWalk for DenseGrid {
    /// Every surface cell, scanning all cells in order.
    fn walk_surface<F: FnMut([u32; 3], u8)>(&self, mut f: F) {
        let s = 1usize << self.depth;
        for (i, &v) in self.cells.iter().enumerate() {
            if v != 0 && v != 255 {
                f(
                    [(i % s) as u32, (i / s % s) as u32, (i / (s * s)) as u32],
                    v,
                );
            }
        }
        // The cells past the far faces, from the cells on them.
        let side = s as u32;
        for z in 0..side {
            for y in 0..side {
                let row = (z as usize * s + y as usize) * s;
                let xs = if y + 1 == side || z + 1 == side {
                    0
                } else {
                    side - 1
                };
                for x in xs..side {
                    let v = self.cells[row + x as usize];
                    super::cell::beyond_leaf([x, y, z], 1, v, side, &mut f);
                }
            }
        }
    }
}

// The tests every store passes.
#[cfg(test)]
super::suite::voxel_store_suite!(tests, super::StoreKind::Dense);
