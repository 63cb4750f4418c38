//! Building the octrees bottom-up, slice by slice (seed 000 §4.2 bottom-up, §4.3.4).
//!
//! Voxel slices arrive in order of z. Each one completes a layer of cells (a cell needs
//! voxel slices z−1 and z, [`super::cell::CellLayers`]). Every two layers of nodes at level l
//! make one layer at level l − 1: each parent looks at its 8 children, and is a homogeneous
//! leaf when all of them are homogeneous leaves of the same value (0 or 255), else an internal
//! node whose children are the tree's nodes. A level keeps at most two layers, so the whole
//! pyramid holds about 2·side² nodes at the deepest level plus a quarter of that above: the
//! dense volume is never built. What happens to a decided node is the store's business
//! ([`Merge`]): the optimized hash octree keeps only the leaves, the plain one every node, the
//! pointer octree links children to parents.

use super::key::{self, Key};
use crate::{Error, Result};

/// What a store does with the nodes the pyramid decides.
///
/// A store says how it makes and reads a leaf ([`Merge::leaf`], [`Merge::leaf_value`]) and
/// what it keeps of an internal node ([`Merge::internal`]); cells, the homogeneous test and
/// leaf merging are the same for every store and are the default methods, so that the rule
/// "homogeneous is a leaf of 0 or 255" is written once ([`homogeneous`]).
pub trait Merge {
    /// A node being built (a value, or a subtree).
    type Node: Default;
    /// Does every cell become a node before parents are decided (seed 000 §4.2.2, the
    /// thesis's pointer octree)? When false, a homogeneous 2×2×2 block of cells goes straight
    /// to a leaf parent without a node per cell.
    const EVERY_CELL: bool = false;
    /// A leaf of byte v: a deepest-level cell's case byte, or a homogeneous node's 0 or 255.
    fn leaf(&mut self, v: u8) -> Self::Node;
    /// The byte of a leaf node (None for an internal one).
    fn leaf_value(n: &Self::Node) -> Option<u8>;
    /// A parent with key `key` whose children (location codes 0..8) are nodes of the tree.
    fn internal(&mut self, key: Key, children: [Self::Node; 8]) -> Result<Self::Node>;
    /// A deepest-level cell with its case byte: a leaf in every store.
    fn cell(&mut self, v: u8) -> Self::Node {
        self.leaf(v)
    }
    /// `Some(v)` when the node is a homogeneous leaf of value v (0 or 255).
    fn homogeneous(n: &Self::Node) -> Option<u8> {
        Self::leaf_value(n).and_then(homogeneous)
    }
    /// A parent whose 8 children are homogeneous leaves of value v becomes that leaf, given
    /// the children to merge (a store may reuse one of them for the leaf).
    fn merge_leaf(&mut self, v: u8, kids: [Self::Node; 8]) -> Self::Node {
        drop(kids);
        self.leaf(v)
    }
}

/// `Some(v)` when a cell's case byte v is homogeneous: every corner outside (0) or every
/// corner inside (255); any other byte is a surface cell.
pub fn homogeneous(v: u8) -> Option<u8> {
    (v == 0 || v == 255).then_some(v)
}

/// One level's pending layers.
struct Level<N> {
    /// Nodes per side.
    n: usize,
    buf: Vec<N>,
    /// Layers held (0 or 1; at 2 they are joined).
    filled: usize,
    /// Layers of the level above completed so far (the z of the next parent layer).
    z: u32,
}

/// The bottom-up builder: cell layers in, decided nodes out to `merge`.
pub struct Pyramid<M: Merge> {
    depth: u32,
    /// Levels 0..depth of nodes; the deepest level is kept as bytes in `cells`.
    levels: Vec<Level<M::Node>>,
    /// Two layers of cell bytes (side² each).
    cells: Vec<u8>,
    cells_filled: usize,
    /// Parent layers made from cell layers so far.
    cells_z: u32,
    /// The store's side of the build: what it keeps of each decided node.
    pub merge: M,
    /// Cell layers received.
    layers: usize,
    root: Option<M::Node>,
    /// Internal nodes decided (the root included).
    pub internal: u64,
}

impl<M: Merge> Pyramid<M> {
    /// A pyramid over a side of 2^depth cells.
    pub fn new(depth: u32, merge: M) -> Pyramid<M> {
        let side = 1usize << depth;
        let levels = (0..depth)
            .map(|l| {
                let n = 1usize << l;
                Level {
                    n,
                    buf: std::iter::repeat_with(M::Node::default)
                        .take(if l == 0 { 1 } else { 2 * n * n })
                        .collect(),
                    filled: 0,
                    z: 0,
                }
            })
            .collect();
        Pyramid {
            depth,
            levels,
            cells: vec![0; 2 * side * side],
            cells_filled: 0,
            cells_z: 0,
            merge,
            layers: 0,
            root: None,
            internal: 0,
        }
    }

    /// Bytes the pyramid holds for a side of 2^depth cells with nodes of `node` bytes.
    pub fn bytes(depth: u32, node: usize) -> u64 {
        let s = 1u64 << depth;
        2 * s * s + (2 * s * s / 3 + 1) * node as u64
    }

    /// The next layer of cells (side² case bytes, X fastest).
    pub fn push_cells(&mut self, cells: &[u8]) -> Result<()> {
        let d = self.depth as usize;
        let n2 = 1usize << (2 * d);
        if self.layers >= 1 << d || cells.len() < n2 {
            return Err(Error::BadLayer {
                layer: self.layers,
                cells: cells.len(),
            });
        }
        self.layers += 1;
        if d == 0 {
            self.root = Some(self.merge.cell(cells[0]));
            return Ok(());
        }
        let at = self.cells_filled * n2;
        self.cells[at..at + n2].copy_from_slice(&cells[..n2]);
        self.cells_filled += 1;
        if self.cells_filled < 2 {
            return Ok(());
        }
        self.cells_filled = 0;
        let par = &mut self.levels[d - 1];
        let base = par.filled * par.n * par.n;
        let out = &mut par.buf[base..base + par.n * par.n];
        join_cells(
            &mut self.merge,
            &mut self.internal,
            &self.cells,
            d,
            self.cells_z,
            out,
        )?;
        self.cells_z += 1;
        self.layer_done(d - 1)
    }

    /// Level l has one more layer: at two, join them into a layer of level l − 1.
    fn layer_done(&mut self, l: usize) -> Result<()> {
        if l == 0 {
            self.root = Some(std::mem::take(&mut self.levels[0].buf[0]));
            return Ok(());
        }
        self.levels[l].filled += 1;
        if self.levels[l].filled < 2 {
            return Ok(());
        }
        self.join(l)?;
        self.levels[l].filled = 0;
        self.levels[l].z += 1;
        self.layer_done(l - 1)
    }

    /// Parents at level l − 1 of the two layers held at level l.
    fn join(&mut self, l: usize) -> Result<()> {
        let (upper, lower) = self.levels.split_at_mut(l);
        let (child, par) = (&mut lower[0], &mut upper[l - 1]);
        let (n, np) = (child.n, par.n);
        let base = par.filled * np * np;
        let pz = child.z;
        for py in 0..np {
            for px in 0..np {
                let kids: [M::Node; 8] = std::array::from_fn(|c| {
                    let (dx, dy, dz) = (c & 1, c >> 1 & 1, c >> 2);
                    std::mem::take(&mut child.buf[dz * n * n + (2 * py + dy) * n + 2 * px + dx])
                });
                par.buf[base + py * np + px] = decide(
                    &mut self.merge,
                    &mut self.internal,
                    l - 1,
                    [px, py, pz as usize],
                    kids,
                )?;
            }
        }
        Ok(())
    }

    /// The root, once every layer is in.
    pub fn finish(self) -> Result<(M, M::Node, u64)> {
        match self.root {
            Some(r) => Ok((self.merge, r, self.internal)),
            None => Err(Error::MissingLayers {
                got: self.layers,
                want: 1usize << self.depth,
            }),
        }
    }
}

/// A parent at `level`: a homogeneous leaf, or an internal node (counted in `internal`).
fn decide<M: Merge>(
    merge: &mut M,
    internal: &mut u64,
    level: usize,
    p: [usize; 3],
    kids: [M::Node; 8],
) -> Result<M::Node> {
    let first = M::homogeneous(&kids[0]);
    if let Some(v) = first {
        if kids[1..].iter().all(|k| M::homogeneous(k) == first) {
            return Ok(merge.merge_leaf(v, kids));
        }
    }
    *internal += 1;
    let k = key::key(p[0] as u32, p[1] as u32, p[2] as u32, level as u32);
    merge.internal(k, kids)
}

/// Parents at level d − 1 of the two cell layers in `cells` (layer pz of parents), into
/// `out`. Runs of 8 cells equal to 0 or to 255 on all four rows make 4 leaves at once.
fn join_cells<M: Merge>(
    merge: &mut M,
    internal: &mut u64,
    cells: &[u8],
    d: usize,
    pz: u32,
    out: &mut [M::Node],
) -> Result<()> {
    let s = 1usize << d;
    let np = s / 2;
    let word = |at: usize| {
        let mut b = [0u8; 8];
        b.copy_from_slice(&cells[at..at + 8]);
        u64::from_le_bytes(b)
    };
    for py in 0..np {
        // Rows of child codes dz·2 + dy.
        let rows = [
            2 * py * s,
            (2 * py + 1) * s,
            (2 * py + s) * s,
            (2 * py + 1 + s) * s,
        ];
        let mut px = 0;
        while px < np {
            if !M::EVERY_CELL && px + 4 <= np {
                let w = word(rows[0] + 2 * px);
                if (w == 0 || w == u64::MAX) && rows[1..].iter().all(|&r| word(r + 2 * px) == w) {
                    for o in &mut out[py * np + px..py * np + px + 4] {
                        *o = merge.leaf(w as u8);
                    }
                    px += 4;
                    continue;
                }
            }
            let v: [u8; 8] = std::array::from_fn(|c| cells[rows[c >> 1] + 2 * px + (c & 1)]);
            out[py * np + px] = if M::EVERY_CELL {
                let kids = v.map(|x| merge.cell(x));
                let p = [px, py, pz as usize];
                decide(merge, internal, d - 1, p, kids)?
            } else if homogeneous(v[0]).is_some() && v.iter().all(|&x| x == v[0]) {
                merge.leaf(v[0])
            } else {
                *internal += 1;
                let kids = v.map(|x| merge.cell(x));
                merge.internal(key::key(px as u32, py as u32, pz, d as u32 - 1), kids)?
            };
            px += 1;
        }
    }
    Ok(())
}
