//! How many octree nodes a voxelization can make, bounded from the scene before it is
//! voxelized (docs/memory.md, "Octree nodes").
//!
//! A node of an octree over the cell grid (`csgpix_sculpt::octree`) is internal exactly when
//! the voxels its cells have as corners are not all alike: node (X, Y, Z) at level l covers
//! the cells X..X + S − 1 (S = 2^(depth − l)) on each axis, whose corners are the voxel
//! centres X − 1 ..= X + S − 1. [`cell_counts`] walks that tree from the root without
//! voxelizing. At each node it classifies every primitive on the node's box of voxel centres
//! as wholly inside, wholly outside, constant but of unknown value, or mixed, the box grown by
//! how far the voxelizer may draw the primitive's boundary from where it is ([`Tolerance`]):
//!
//! - a convex solid by its face planes (outside one: outside; inside all: inside);
//! - a closed mesh by the triangles that may meet the box (the separating axis test); a box
//!   meeting none is on one side of the surface, which side carried down the walk by the
//!   parity of the triangles a segment from the parent's centre crosses;
//! - a dataset by the range of its trilinear interpolant over the box (exact over a few
//!   cells, bounded by blocks of samples over more), and on nodes of up to 3 voxels a side by
//!   its samples at the voxel centres themselves.
//!
//! It then evaluates the scene's CSG tree in that logic, intersected with the grid (voxels
//! outside it are empty). A node whose tree is not mixed has voxels all alike, and is neither
//! counted nor descended into; every internal node is counted. At the level above the
//! deepest, a node's 27 voxel centres are classified one by one (filled, empty, or either),
//! and each of its 8 cells counts unless its 8 corners are known to be alike; the histogram
//! of what is known of the corners bounds the triangles Marching Cubes makes
//! (`csgpix_sculpt::estimate::triangles`). Every test is conservative, so the counts are
//! upper bounds, and the walk visits only what it counts (and 8 children of each): the
//! scene's surface, not the grid. Subtrees below the root's grandchildren are walked in
//! parallel; past [`VISIT_BUDGET`] visits the walk stops a level higher and bounds the
//! levels below by 8 children a node.

use std::sync::atomic::{AtomicU64, Ordering};

use glam::{DMat3, DVec3};
use rayon::prelude::*;

use csgpix_scene::dataset::{cell, Dataset};
use csgpix_scene::solid::{ConvexSolid, CsgNode, CsgScene};

use crate::sampled::Shape;
use crate::slicer::{Sampling, Slicer};

mod lattice;
mod prims;
mod triangle;

use lattice::Lattice;
use prims::{grid_planes, planes, sampled_prim};
use triangle::{crosses, meets_triangle, Crossing};

/// Codes of a cell's corners ([`corner_code`]): 3^8.
pub const CORNER_CODES: usize = 6561;

/// What is known of a corner voxel: empty, filled, or either.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Corner {
    /// Empty.
    Out = 0,
    /// Filled.
    In = 1,
    /// Either.
    Unknown = 2,
}

/// The code of a cell's corners: corner k (voxel (x − 1 + (k & 1), y − 1 + (k >> 1 & 1),
/// z − 1 + (k >> 2)) of cell (x, y, z)) is digit k in base 3.
pub fn corner_code(corners: [Corner; 8]) -> usize {
    corners.iter().rev().fold(0, |a, &c| a * 3 + c as usize)
}

/// The corners of a code ([`corner_code`]'s inverse).
pub fn corners_of(code: usize) -> [Corner; 8] {
    let mut c = code;
    std::array::from_fn(|_| {
        let d = c % 3;
        c /= 3;
        [Corner::Out, Corner::In, Corner::Unknown][d]
    })
}

/// Visits [`cell_counts`] makes before it stops one level higher (the levels below are then
/// bounded by 8 children a node): a few seconds' work, past any grid a run fits in memory.
pub const VISIT_BUDGET: u64 = 160_000_000;

/// Upper bounds of an octree's nodes by level, over a cell grid of side 2^depth.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CellCounts {
    /// Levels below the root.
    pub depth: u32,
    /// Per level l = 0..=depth (the root's first): at l < depth the nodes whose corner voxels
    /// may differ (the internal nodes, the root included); at l = depth the cells that may
    /// have a surface, the cells just past the grid's far faces (a coordinate equal to the
    /// side, which Marching Cubes meshes) included.
    pub nonuniform: Vec<u64>,
    /// The cells counted at the deepest level by what is known of their corners:
    /// `corners[corner_code(c)]` cells have corners `c` ([`CORNER_CODES`] entries).
    pub corners: Vec<u64>,
}

impl CellCounts {
    /// The internal nodes: every level but the deepest.
    pub fn internal(&self) -> u64 {
        let d = self.depth as usize;
        self.nonuniform[..d.min(self.nonuniform.len())]
            .iter()
            .fold(0u64, |a, &n| a.saturating_add(n))
    }

    /// The cells that may have a surface (the deepest level's count).
    pub fn surface_cells(&self) -> u64 {
        self.nonuniform.last().copied().unwrap_or(0)
    }
}

/// How far from a primitive's boundary the voxelizer may classify a voxel centre wrongly
/// (docs/voxelization.md, "word against float", "Steep faces"), in voxels:
///
/// - a sloped plane's word is within 2^-(F+1)·(1 + x + y) depth units of its value at pixel
///   (x, y), so a sample depth within twice that (plus the one least unit of centre
///   sampling's Vz) of the face may fall either way: (W + H + 2) raw units, over the slab's
///   `slab_raw`, along Z;
/// - a face steeper than the slope limit is drawn as a perpendicular plane through its trace
///   at depth 0, which moves it across by at most maxdepth / slope pixels (and along its
///   normal by no more than the depth range times its normal's Z);
/// - a perpendicular plane's K is exact to 1.5e-5 pixel;
/// - slab sampling takes the voxel's segment along Z, half a voxel each way.
///
/// Along a plane's unit normal (a, b, c) that is |c|·(word error + half) for a sloped plane,
/// plus the steep move when the plane may be steep ([`Tolerance::plane`]). Meshes are taken
/// to move by the word error along Z and a thousandth of a voxel across; datasets are sampled
/// exactly at the centres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// Raw depth units a voxel along Z (the slab).
    pub slab_raw: f64,
    /// Pixels along X and Y of the array (voxels of the grid).
    pub pixels: [f64; 2],
    /// Voxels along Z a sample stands for beyond its centre: half a voxel under slab
    /// sampling, none under centre sampling.
    pub half: f64,
    /// Pixels across that a steep face moves.
    pub steep: f64,
    /// The depth range in voxels along Z.
    pub range: f64,
    /// The slope limit in voxels along Z per pixel.
    pub slope: f64,
}

impl Tolerance {
    /// The tolerance of `slicer`'s convex solids and meshes.
    pub fn of(slicer: &Slicer) -> Tolerance {
        let [w, h, _] = slicer.grid.dims.map(|d| d as f64);
        let slab_raw = slicer.slab_raw.max(1) as f64;
        let q = slicer.fmt.to_real(slicer.slab_raw.max(1));
        let maxdepth = slicer.fmt.to_real(slicer.fmt.maxdepth());
        let steep = if slicer.slope_limit > 0.0 {
            maxdepth / slicer.slope_limit + 0.01
        } else {
            f64::INFINITY
        };
        let half = match slicer.sampling {
            Sampling::Slab => 0.5,
            Sampling::Centre => 0.0,
        };
        Tolerance {
            slab_raw,
            pixels: [w, h],
            half,
            steep,
            range: maxdepth / q,
            slope: slicer.slope_limit / q,
        }
    }

    /// Voxels along Z that a plane of slopes `dz` (voxels along Z per pixel along X, Y) may
    /// be drawn off: its word at pixel (x, y) is Z0 + x·dZx + y·dZy with each coefficient
    /// rounded to the word (half a least unit at most, nothing for a coefficient the word
    /// holds exactly, as 0 for a face parallel to an axis), twice that as the interval's
    /// bound, the least unit of centre sampling's Vz, and the half voxel of slab sampling.
    pub fn word(&self, dz: [f64; 2]) -> f64 {
        let rounding = |v: f64| {
            let raw = (v * self.slab_raw).abs();
            ((raw - raw.round()).abs() + 1e-9 * (1.0 + raw)).min(0.5)
        };
        let [w, h] = self.pixels;
        let raw = 2.0
            * (0.5 + (w - 1.0).max(0.0) * rounding(dz[0]) + (h - 1.0).max(0.0) * rounding(dz[1]))
            + 1.0;
        raw / self.slab_raw + self.half + 1e-4
    }

    /// How far along its unit normal `n` (voxel coordinates) a convex solid's face may be
    /// drawn from where it is: the word's error along Z ([`Tolerance::word`]) times the
    /// normal's Z, and the steep move where the face may be drawn as a perpendicular plane
    /// (its slope, in the array's depth units per pixel, within a factor of 2 of the limit or
    /// above), within the depth range.
    pub fn plane(&self, n: DVec3) -> f64 {
        let c = n.z.abs();
        let mut t = 1e-4;
        if c > 0.0 {
            t += c * self.word([n.x / n.z, n.y / n.z]);
        }
        if 2.0 * n.x.abs().max(n.y.abs()) > self.slope * c {
            let across = (n.x * n.x + n.y * n.y).sqrt();
            t += (self.steep * across).min(self.range * c);
        }
        t
    }

    /// How far a mesh's crossings may be moved, voxels along X, Y, Z: the word's error of a
    /// plane of any slope along Z, a thousandth of a voxel across.
    fn mesh(&self) -> DVec3 {
        DVec3::new(1e-3, 1e-3, self.word([0.5 / self.slab_raw; 2]))
    }
}

/// A primitive's share of a node: wholly outside, wholly inside, constant on the node but
/// unknown (a mesh that does not meet it), or perhaps both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Class {
    Out,
    In,
    Unif,
    Mixed,
}

impl Class {
    fn or(self, b: Class) -> Class {
        use Class::*;
        match (self, b) {
            (In, _) | (_, In) => In,
            (Out, x) | (x, Out) => x,
            (Mixed, _) | (_, Mixed) => Mixed,
            _ => Unif,
        }
    }

    fn and(self, b: Class) -> Class {
        use Class::*;
        match (self, b) {
            (Out, _) | (_, Out) => Out,
            (In, x) | (x, In) => x,
            (Mixed, _) | (_, Mixed) => Mixed,
            _ => Unif,
        }
    }

    fn not(self) -> Class {
        match self {
            Class::In => Class::Out,
            Class::Out => Class::In,
            c => c,
        }
    }
}

/// The CSG tree in postfix.
#[derive(Clone, Copy, Debug)]
enum Op {
    Leaf(u32),
    Union(u32),
    Inter(u32),
    Diff(u32),
    Not,
    Empty,
}

fn postfix(n: &CsgNode, out: &mut Vec<Op>) {
    let (ch, op): (&[CsgNode], fn(u32) -> Op) = match n {
        CsgNode::Solid(i) => {
            out.push(Op::Leaf(*i as u32));
            return;
        }
        CsgNode::Empty => {
            out.push(Op::Empty);
            return;
        }
        CsgNode::Complement(c) => {
            postfix(c, out);
            out.push(Op::Not);
            return;
        }
        CsgNode::Union(c) => (c, Op::Union),
        CsgNode::Intersection(c) => (c, Op::Inter),
        CsgNode::Difference(c) => (c, Op::Diff),
    };
    for c in ch {
        postfix(c, out);
    }
    out.push(op(ch.len() as u32));
}

/// Trees with more leaves than this are not evaluated per node: a node is taken as mixed when
/// any primitive is (the union of their boundaries), which costs nothing per node; so are
/// blended scenes, whose values are not the tree's Boolean.
const TREE_LEAVES: usize = 64;

/// A primitive in voxel coordinates (voxel (i, j, k)'s centre at (i, j, k)).
enum Prim<'a> {
    /// A convex solid: n·x ≤ d for every plane, drawn within t of it: (n, d, t).
    Planes(Vec<(DVec3, f64, f64)>),
    /// A closed mesh and its box.
    Tris(Vec<[DVec3; 3]>, DVec3, DVec3),
    /// A dataset and its iso value.
    Lattice(Lattice<'a>),
    /// A mesh that is not closed, by its box: outside beyond it, anything within (its
    /// winding number's level set is not bounded here).
    Unknown(DVec3, DVec3),
    /// Nothing.
    Empty,
}

/// A mixed primitive of a node, and its planes or triangles that may meet the node
/// (`arena[start..start + len]` of its depth).
///
/// A mesh's entry carries a point and what is known of it (filled, empty, or unknown):
/// every other point's membership follows by the parity of the triangles crossed on the way
/// (the mesh is closed), and only the node's triangles can cross a segment within its box.
#[derive(Clone, Copy, Debug)]
struct Entry {
    prim: u32,
    start: u32,
    len: u32,
    at: DVec3,
    known: Class,
}

struct Walk<'p, 'a> {
    prims: &'p [Prim<'a>],
    /// Per primitive, how far its boundary may move (voxels along X, Y, Z).
    grow: &'p [DVec3],
    ops: Option<&'p [Op]>,
    grid: u32,
    class: Vec<Class>,
    lists: Vec<Vec<Entry>>,
    arena: Vec<Vec<u32>>,
    undo: Vec<Vec<(u32, Class)>>,
    stack: Vec<Class>,
    side: u64,
    depth: u32,
    /// The deepest level walked; below it, 8 children a node.
    last: u32,
    counts: Vec<u64>,
    corners: Vec<u64>,
    /// Visits not yet added to `spent`.
    visits: u64,
    /// Visits of every walk of this bound.
    spent: &'p AtomicU64,
    /// Nodes at this virtual level are put in `tasks` rather than walked.
    split: Option<u32>,
    tasks: Vec<Task>,
}

/// A node left for a walk of its own: its virtual level and place, the classes there and
/// its parent's mixed primitives.
struct Task {
    vl: u32,
    pos: [u64; 3],
    class: Vec<Class>,
    list: Vec<Entry>,
    arena: Vec<u32>,
}

/// A convex solid's class on the box (centre `c`, half sizes `hg`, grown by its drawing
/// tolerance) from its `active` planes: out when the box lies beyond one plane (by more
/// than its slack), else in when within all, else mixed; the planes the box meets pushed
/// to `dst` (none when out).
fn classify_planes(
    planes: &[(DVec3, f64, f64)],
    active: &[u32],
    c: DVec3,
    hg: DVec3,
    dst: &mut Vec<u32>,
) -> Class {
    let start = dst.len();
    for &j in active {
        let (n, d, t) = planes[j as usize];
        let s = n.dot(c) - d;
        let r = n.abs().dot(hg);
        let slack = t + 1e-9 * (1.0 + d.abs());
        if s - r > slack {
            dst.truncate(start);
            return Class::Out;
        }
        if s + r >= -slack {
            dst.push(j);
        }
    }
    if dst.len() == start {
        Class::In
    } else {
        Class::Mixed
    }
}

/// A closed mesh's `active` triangles on the box (centre `c`, half sizes `hg`): those it
/// meets pushed to `dst`, and the box centre's class carried from the parent's point
/// `e.at` by the triangles the segment between them crosses ([`Class::Unif`] when a
/// crossing is unsure or the parent's was unknown).
fn centre_class(
    tris: &[[DVec3; 3]],
    active: &[u32],
    e: &Entry,
    c: DVec3,
    hg: DVec3,
    dst: &mut Vec<u32>,
) -> Class {
    let mut known = e.known;
    for &j in active {
        let t = &tris[j as usize];
        if known != Class::Unif {
            match crosses(t, e.at, c) {
                Crossing::Once => known = known.not(),
                Crossing::No => {}
                Crossing::Unsure => known = Class::Unif,
            }
        }
        if meets_triangle(t, c, hg) {
            dst.push(j);
        }
    }
    known
}

/// Visits added to the shared count at a time.
const VISIT_BATCH: u64 = 1 << 14;

/// Ran out of [`VISIT_BUDGET`].
struct Spent;

impl Walk<'_, '_> {
    /// Classifies the mixed primitives of `lists[i]` on the box (centre c, half sizes h), into
    /// `lists[i + 1]`, and evaluates the tree there. The classes changed are in `undo[i + 1]`.
    fn step(&mut self, i: usize, c: DVec3, h: DVec3) -> Class {
        let any_mixed = self.classify(i, c, h);
        self.evaluate(any_mixed)
    }

    /// The classifying half of [`Walk::step`]: whether any primitive is mixed.
    fn classify(&mut self, i: usize, c: DVec3, h: DVec3) -> bool {
        let (lists_lo, lists_hi) = self.lists.split_at_mut(i + 1);
        let (parent, out) = (&lists_lo[i], &mut lists_hi[0]);
        let (arena_lo, arena_hi) = self.arena.split_at_mut(i + 1);
        let (items, dst) = (&arena_lo[i], &mut arena_hi[0]);
        out.clear();
        dst.clear();
        let undo = &mut self.undo[i + 1];
        undo.clear();
        let mut any_mixed = false;
        for e in parent {
            let hg = h + self.grow[e.prim as usize];
            let start = dst.len();
            let mut known = Class::Unif;
            let active = &items[e.start as usize..(e.start + e.len) as usize];
            let class = match &self.prims[e.prim as usize] {
                Prim::Planes(planes) => classify_planes(planes, active, c, hg, dst),
                Prim::Tris(tris, lo, hi) => {
                    if (0..3).any(|a| lo[a] > c[a] + hg[a] || hi[a] < c[a] - hg[a]) {
                        Class::Out
                    } else {
                        // The centre's membership, from the parent's point.
                        known = centre_class(tris, active, e, c, hg, dst);
                        if dst.len() == start {
                            known
                        } else {
                            Class::Mixed
                        }
                    }
                }
                Prim::Lattice(l) => l.classify(c, hg),
                Prim::Unknown(lo, hi) => {
                    match (0..3).any(|a| lo[a] > c[a] + hg[a] || hi[a] < c[a] - hg[a]) {
                        true => Class::Out,
                        false => Class::Mixed,
                    }
                }
                Prim::Empty => Class::Out,
            };
            let len = dst.len() - start;
            if class == Class::Mixed {
                any_mixed = true;
                out.push(Entry {
                    prim: e.prim,
                    start: start as u32,
                    len: len as u32,
                    at: c,
                    known,
                });
            }
            undo.push((e.prim, self.class[e.prim as usize]));
            self.class[e.prim as usize] = class;
        }
        any_mixed
    }

    /// The evaluating half of [`Walk::step`]: the tree over the classes as they are.
    fn evaluate(&mut self, any_mixed: bool) -> Class {
        let grid = self.class[self.grid as usize];
        match self.ops {
            None => match (grid, any_mixed) {
                (Class::Out, _) => Class::Out,
                (_, true) => Class::Mixed,
                _ => Class::Unif,
            },
            Some(ops) => {
                let s = &mut self.stack;
                s.clear();
                for op in ops {
                    let v = match *op {
                        Op::Leaf(p) => self.class[p as usize],
                        Op::Empty => Class::Out,
                        Op::Not => {
                            let v = s.pop().unwrap_or(Class::Out);
                            v.not()
                        }
                        Op::Union(n) | Op::Inter(n) | Op::Diff(n) => {
                            let at = s.len() - n as usize;
                            let v = match *op {
                                Op::Union(_) => s[at..].iter().fold(Class::Out, |a, &b| a.or(b)),
                                Op::Inter(_) => match n {
                                    0 => Class::Out,
                                    _ => s[at..].iter().fold(Class::In, |a, &b| a.and(b)),
                                },
                                _ => match n {
                                    0 => Class::Out,
                                    _ => s[at + 1..].iter().fold(s[at], |a, &b| a.and(b.not())),
                                },
                            };
                            s.truncate(at);
                            v
                        }
                    };
                    s.push(v);
                }
                s.pop().unwrap_or(Class::Out).and(grid)
            }
        }
    }

    /// Puts back the classes `step(i, …)` changed.
    fn restore(&mut self, i: usize) {
        for &(p, c) in self.undo[i + 1].iter().rev() {
            self.class[p as usize] = c;
        }
    }

    /// Node `pos` (in units of its side) at virtual level `vl` (0: a root of twice the side,
    /// so that the cells past the far faces are walked too), whose parent's mixed primitives
    /// are `lists[vl]`.
    fn visit(&mut self, vl: u32, pos: [u64; 3]) -> Result<(), Spent> {
        if self.split == Some(vl) {
            self.tasks.push(Task {
                vl,
                pos,
                class: self.class.clone(),
                list: self.lists[vl as usize].clone(),
                arena: self.arena[vl as usize].clone(),
            });
            return Ok(());
        }
        self.visits += 1;
        if self.visits >= VISIT_BATCH {
            let spent = self.spent.fetch_add(self.visits, Ordering::Relaxed) + self.visits;
            self.visits = 0;
            if spent > VISIT_BUDGET {
                return Err(Spent);
            }
        }
        let side2 = 2 * self.side;
        let s = side2 >> vl;
        let lo = pos.map(|p| (p * s) as f64 - 1.0);
        let h = DVec3::splat(s as f64 / 2.0);
        let c = DVec3::from(lo) + h;
        let i = vl as usize;
        let class = self.step(i, c, h);
        if class != Class::Mixed {
            self.restore(i);
            return Ok(());
        }
        // Level l of the real tree is virtual level l + 1.
        let level = vl.checked_sub(1);
        match level {
            Some(l) if l == self.depth => self.cell(i, lo, pos),
            Some(l) => {
                let inside = pos.iter().all(|&p| p < 1 << l);
                if inside {
                    self.counts[l as usize] += 1;
                }
                if l + 1 == self.depth && self.last == self.depth {
                    self.cells(i, lo, pos);
                } else if l < self.last {
                    self.children(vl, pos)?;
                }
            }
            None => self.children(vl, pos)?,
        }
        self.restore(i);
        Ok(())
    }

    fn children(&mut self, vl: u32, pos: [u64; 3]) -> Result<(), Spent> {
        for ch in 0..8u64 {
            let p = [
                2 * pos[0] + (ch & 1),
                2 * pos[1] + (ch >> 1 & 1),
                2 * pos[2] + (ch >> 2),
            ];
            // Past the far faces only the first cell layer has corners in the grid.
            if p.iter()
                .any(|&q| (q << (self.depth + 1 - (vl + 1))) > self.side)
            {
                continue;
            }
            self.visit(vl + 1, p)?;
        }
        Ok(())
    }

    /// The 8 cells of a node of the level above the deepest (its box's low corner `lo`, index
    /// `pos`) whose box is mixed, with its primitives in `lists[i + 1]`: its 27 voxels, one by
    /// one, are the corners of its cells.
    fn cells(&mut self, i: usize, lo: [f64; 3], pos: [u64; 3]) {
        // With one or two mixed primitives, the tree's value for each of their classes, once.
        const CLASSES: [Class; 4] = [Class::Out, Class::In, Class::Unif, Class::Mixed];
        let mixed: Vec<u32> = self.lists[i + 1].iter().map(|e| e.prim).collect();
        let table: Option<Vec<Class>> = (mixed.len() <= 2).then(|| {
            let saved: Vec<Class> = mixed.iter().map(|&p| self.class[p as usize]).collect();
            let n = 1 << (2 * mixed.len());
            let t = (0..n)
                .map(|code| {
                    for (j, &p) in mixed.iter().enumerate() {
                        self.class[p as usize] = CLASSES[code >> (2 * j) & 3];
                    }
                    let any = (0..mixed.len()).any(|j| code >> (2 * j) & 3 == 3);
                    self.evaluate(any)
                })
                .collect();
            for (&p, &c) in mixed.iter().zip(&saved) {
                self.class[p as usize] = c;
            }
            t
        });
        let mut point = [Corner::Out; 27];
        for (k, cl) in point.iter_mut().enumerate() {
            let q = DVec3::new(
                lo[0] + (k % 3) as f64,
                lo[1] + (k / 3 % 3) as f64,
                lo[2] + (k / 9) as f64,
            );
            let any = self.classify(i + 1, q, DVec3::ZERO);
            let class = match &table {
                Some(t) => {
                    let code = mixed.iter().enumerate().fold(0, |a, (j, &p)| {
                        let c = self.class[p as usize];
                        a | (CLASSES.iter().position(|&x| x == c).unwrap_or(3) << (2 * j))
                    });
                    t[code]
                }
                None => self.evaluate(any),
            };
            *cl = match class {
                Class::In => Corner::In,
                Class::Out => Corner::Out,
                _ => Corner::Unknown,
            };
            self.restore(i + 1);
        }
        self.visits += 27;
        for ch in 0..8usize {
            let d = [ch & 1, ch >> 1 & 1, ch >> 2];
            if (0..3).any(|a| 2 * pos[a] + d[a] as u64 > self.side) {
                continue;
            }
            let corner: [Corner; 8] = std::array::from_fn(|k| {
                let (x, y, z) = (d[0] + (k & 1), d[1] + (k >> 1 & 1), d[2] + (k >> 2));
                point[x + 3 * y + 9 * z]
            });
            let alike = corner
                .iter()
                .all(|&c| c == corner[0] && c != Corner::Unknown);
            if !alike {
                self.counts[self.depth as usize] += 1;
                self.corners[corner_code(corner)] += 1;
            }
        }
    }

    /// A deepest-level cell (its box's low corner `lo`, index `pos`) whose box is mixed, with
    /// its primitives in `lists[i + 1]`: its 8 corner voxels, one by one.
    fn cell(&mut self, i: usize, lo: [f64; 3], pos: [u64; 3]) {
        if pos.iter().any(|&p| p > self.side) {
            return;
        }
        let mut corner = [Corner::Out; 8];
        for (k, cl) in corner.iter_mut().enumerate() {
            let q = DVec3::new(
                lo[0] + (k & 1) as f64,
                lo[1] + (k >> 1 & 1) as f64,
                lo[2] + (k >> 2) as f64,
            );
            *cl = match self.step(i + 1, q, DVec3::ZERO) {
                Class::In => Corner::In,
                Class::Out => Corner::Out,
                _ => Corner::Unknown,
            };
            self.restore(i + 1);
            self.visits += 1;
        }
        let alike = corner
            .iter()
            .all(|&c| c == corner[0] && c != Corner::Unknown);
        if !alike {
            self.counts[self.depth as usize] += 1;
            self.corners[corner_code(corner)] += 1;
        }
    }
}

/// Upper bounds of the internal nodes of every level of an octree of side 2^depth over
/// `slicer`'s voxelization of `scene`, and of the cells with a surface (module docs).
pub fn cell_counts(scene: &CsgScene, slicer: &Slicer, depth: u32) -> CellCounts {
    let grid = &slicer.grid;
    let voxel = grid.voxel();
    let to_voxel = |p: DVec3| (p - grid.min) / voxel - DVec3::splat(0.5);
    let tol = Tolerance::of(slicer);
    let mut prims: Vec<Prim> = vec![];
    let mut grow = vec![];
    for s in &scene.solids {
        let p = planes(s, to_voxel, &tol);
        prims.push(if p.is_empty() {
            Prim::Empty
        } else {
            Prim::Planes(p)
        });
        grow.push(DVec3::ZERO);
    }
    for s in &slicer.sampled {
        let (prim, g) = sampled_prim(&s.shape, slicer, &to_voxel, &tol);
        prims.push(prim);
        grow.push(g);
    }
    let grid_prim = prims.len() as u32;
    prims.push(grid_planes(grid.dims));
    grow.push(DVec3::ZERO);
    let ops = tree_ops(&scene.root, grid_prim, slicer);
    walk(&prims, &grow, ops.as_deref(), grid_prim, depth)
}

/// The CSG tree in postfix, when the walk may evaluate it: few enough leaves, all of them
/// primitives before the grid's (`grid_prim`), and boolean. Blending (`--blend`) combines
/// grey values, not memberships: only that the volume is a function of what each primitive
/// holds is used then.
fn tree_ops(root: &CsgNode, grid_prim: u32, slicer: &Slicer) -> Option<Vec<Op>> {
    let mut ops = vec![];
    postfix(root, &mut ops);
    let leaves = ops.iter().filter(|o| matches!(o, Op::Leaf(_))).count();
    let known = ops
        .iter()
        .all(|o| !matches!(o, Op::Leaf(p) if *p as usize >= grid_prim as usize));
    let boolean = slicer.blend.is_none();
    (leaves <= TREE_LEAVES && known && boolean).then_some(ops)
}

fn walk(prims: &[Prim], grow: &[DVec3], ops: Option<&[Op]>, grid: u32, depth: u32) -> CellCounts {
    let levels = depth as usize + 4;
    let mut last = depth;
    loop {
        let spent = AtomicU64::new(0);
        let fresh = |split| Walk {
            prims,
            grow,
            ops,
            grid,
            class: vec![Class::Mixed; prims.len()],
            lists: vec![vec![]; levels],
            arena: vec![vec![]; levels],
            undo: vec![vec![]; levels],
            stack: vec![],
            side: 1 << depth,
            depth,
            last,
            counts: vec![0; depth as usize + 1],
            corners: vec![0; CORNER_CODES],
            visits: 0,
            spent: &spent,
            split,
            tasks: vec![],
        };
        // The top levels here, the subtrees below them in parallel.
        let mut w = fresh(Some(SPLIT));
        w.seed_root();
        let top = w.visit(0, [0; 3]);
        let tasks = std::mem::take(&mut w.tasks);
        let subtrees: Result<Vec<_>, Spent> = top.and_then(|()| {
            tasks
                .into_par_iter()
                .map(|t| {
                    let mut s = fresh(None);
                    s.class = t.class;
                    s.lists[t.vl as usize] = t.list;
                    s.arena[t.vl as usize] = t.arena;
                    s.visit(t.vl, t.pos)?;
                    Ok((s.counts, s.corners))
                })
                .collect()
        });
        match subtrees {
            Ok(parts) => {
                for (counts, corners) in parts {
                    w.add(&counts, &corners);
                }
                return w.finish();
            }
            Err(Spent) if last > 0 => last -= 1,
            Err(Spent) => return w.finish_unwalked(),
        }
    }
}

/// The virtual level whose nodes are walked in parallel: the real root's grandchildren.
const SPLIT: u32 = 3;

/// Nodes of level l, the cells past the far faces counted at the deepest.
fn cap(depth: u32, l: u32) -> u64 {
    let n = (1u64 << l) + u64::from(l == depth);
    n.saturating_mul(n).saturating_mul(n)
}

impl Walk<'_, '_> {
    /// Level 0's list: every primitive with all its planes or triangles active, a mesh's
    /// known point outside its box (a point outside the mesh's box is outside the mesh).
    fn seed_root(&mut self) {
        for (p, prim) in self.prims.iter().enumerate() {
            let (n, at) = match prim {
                Prim::Planes(v) => (v.len(), DVec3::ZERO),
                Prim::Tris(t, lo, hi) => (t.len(), *lo - (*hi - *lo) - DVec3::ONE),
                _ => (0, DVec3::ZERO),
            };
            let start = self.arena[0].len() as u32;
            self.arena[0].extend(0..n as u32);
            self.lists[0].push(Entry {
                prim: p as u32,
                start,
                len: n as u32,
                at,
                known: Class::Out,
            });
        }
    }

    /// A subtree's counts and corner codes added to these.
    fn add(&mut self, counts: &[u64], corners: &[u64]) {
        for (a, b) in self.counts.iter_mut().zip(counts) {
            *a += b;
        }
        for (a, b) in self.corners.iter_mut().zip(corners) {
            *a += b;
        }
    }

    /// The counts when not even the root fits the budget: every node may be internal.
    fn finish_unwalked(self) -> CellCounts {
        let depth = self.depth;
        let mut c = self.finish();
        c.nonuniform = (0..=depth).map(|l| cap(depth, l)).collect();
        c.corners = vec![0; CORNER_CODES];
        c.corners[CORNER_CODES - 1] = c.nonuniform[depth as usize];
        c
    }

    fn finish(self) -> CellCounts {
        let mut nonuniform = self.counts;
        let mut corners = self.corners;
        // Levels below the last walked: at most 8 children a node.
        for l in self.last + 1..=self.depth {
            let up = nonuniform[l as usize - 1].saturating_mul(8);
            nonuniform[l as usize] = up.min(cap(self.depth, l));
        }
        if self.last < self.depth {
            // Nothing is known of the corners of cells not walked.
            corners = vec![0; CORNER_CODES];
            corners[CORNER_CODES - 1] = nonuniform[self.depth as usize];
        }
        CellCounts {
            depth: self.depth,
            nonuniform,
            corners,
        }
    }
}

#[cfg(test)]
mod tests;
