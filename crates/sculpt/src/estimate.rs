//! The memory of a sculpting run (docs/memory.md, "sculpt"), bounded before the store is
//! built: the optimized octree of the volume ([`crate::octree::estimate`]), the per-cell
//! mesh of [`Sculptor`](crate::Sculptor), what the tool's path adds to both, and the mesh
//! written at the end with the closedness check of the report.

use glam::DVec3;

use crate::octree::cell::CORNERS;
use crate::octree::estimate::{
    hashed_entries, map_buckets, map_bytes, table_bytes, vec_capacity, CellCounts, Corner,
    ENTRY_BYTES,
};
use crate::octree::key::MAX_DEPTH;
use crate::octree::{depth_for, mc};
use crate::Result;
use csgpix_voxel::cells::corners_of;

/// Bytes of a triangle (three `f32` corners).
const TRI_BYTES: u64 = std::mem::size_of::<mc::Tri>() as u64;

/// Bytes of an entry of [`crate::CellMesh`]'s map (a key and its run).
const CELL_ENTRY_BYTES: u64 = std::mem::size_of::<(u64, (u32, u8))>() as u64;

/// The Marching Cubes case of a cell whose corner k ([`corner_code`](csgpix_voxel::cells::corner_code)'s order) is filled
/// when bit k of `filled` is set.
fn case_of(filled: u8) -> u8 {
    let mut case = 0u8;
    for (i, c) in CORNERS.iter().enumerate() {
        let k = c[0] | c[1] << 1 | c[2] << 2;
        case |= (filled >> k & 1) << i;
    }
    case
}

/// The most triangles a cell with the corners `code` ([`corner_code`](csgpix_voxel::cells::corner_code)) has: the most of any
/// filling of its unknown corners.
pub fn cell_triangles(code: usize) -> u64 {
    let t = mc::table();
    let c = corners_of(code);
    let known = (0..8).fold(0u8, |a, k| a | u8::from(c[k] == Corner::In) << k);
    let unknown = (0..8).fold(0u8, |a, k| a | u8::from(c[k] == Corner::Unknown) << k);
    // Every subset of the unknown corners.
    let mut sub = unknown;
    let mut most = 0;
    loop {
        most = most.max(t.count(case_of(known | sub)) as u64);
        if sub == 0 {
            break;
        }
        sub = (sub - 1) & unknown;
    }
    most
}

/// The triangles Marching Cubes makes at most over the cells `counts` bounds.
pub fn triangles(counts: &CellCounts) -> u64 {
    counts
        .corners
        .iter()
        .enumerate()
        .filter(|(_, &n)| n > 0)
        .fold(0u64, |a, (code, &n)| {
            a.saturating_add(n.saturating_mul(cell_triangles(code)))
        })
}

/// The most triangles one cell has.
pub fn most_cell_triangles() -> u64 {
    (0..=255u8)
        .map(|c| mc::table().count(c) as u64)
        .max()
        .unwrap_or(0)
}

/// What the tool's path reaches: per level the nodes whose voxels it may change (level l <
/// depth; a split makes such a node internal), the cells whose byte it may change (the
/// deepest level, the cells past the far faces included), and the voxels it may flip.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Reach {
    /// Per level l < depth, nodes holding a voxel within the tool of some step.
    pub nodes: Vec<u64>,
    /// Cells with such a voxel as a corner.
    pub cells: u64,
    /// Voxels within the tool of some step, inside the editable region.
    pub voxels: u64,
    /// Pairs (step, cell) where the cell has a corner voxel within the tool at that step but
    /// not at the step before: a cell's byte changes only at such a step (a voxel flips at
    /// most once, the first time the tool covers it, and the step before covered every voxel
    /// within it).
    pub changes: u64,
}

/// Nodes walked by [`reach`] before it gives up and counts every node of the levels left.
const REACH_BUDGET: u64 = 16_000_000;

/// [`Reach`] of a tool of radius `radius` voxels at the centres `path` (voxel units) over a
/// volume of `dims` (the editable region: voxels 0..dims on each axis, within the store's
/// side), by walking the octree from the root: a node is kept when its box of voxel centres,
/// clipped to the region, is within the radius of a step's centre.
pub fn reach(path: &[DVec3], radius: f64, dims: [usize; 3]) -> Result<Reach> {
    let depth = depth_for(dims)?;
    let side = 1u64 << depth;
    let limit = dims.map(|d| (d as u64).min(side));
    let mut r = Reach {
        nodes: vec![0; depth as usize],
        ..Reach::default()
    };
    // Every step, the non-finite ones (which change nothing) kept out of the lists.
    let mut w = ReachWalk {
        centres: path,
        path,
        r2: radius * radius * (1.0 + 1e-9) + 1e-9,
        inner2: radius * radius * (1.0 - 1e-9) - 1e-9,
        limit,
        side,
        depth,
        lists: vec![vec![]; depth as usize + 3],
        reach: &mut r,
        visits: 0,
    };
    w.lists[0] = (0..path.len() as u32)
        .filter(|&i| path[i as usize].is_finite())
        .collect();
    if w.visit(0, [0; 3]).is_err() {
        // Every node of every level may be reached.
        for (l, n) in r.nodes.iter_mut().enumerate() {
            *n = 1u64 << (3 * l as u32).min(63);
        }
        let cells = limit.map(|l| l + 1);
        r.cells = cells.iter().product();
        r.voxels = limit.iter().product();
        r.changes = r.voxels.saturating_mul(8);
    }
    Ok(r)
}

struct ReachWalk<'a> {
    centres: &'a [DVec3],
    /// The path as given: the step before a centre is the one before it here.
    path: &'a [DVec3],
    r2: f64,
    /// A squared distance surely within the tool (rounding kept out).
    inner2: f64,
    limit: [u64; 3],
    side: u64,
    depth: u32,
    lists: Vec<Vec<u32>>,
    reach: &'a mut Reach,
    visits: u64,
}

impl ReachWalk<'_> {
    /// Node `pos` at virtual level `vl` (a root of twice the side, so that the cells past the
    /// far faces are walked), the steps near its parent in `lists[vl]`.
    fn visit(&mut self, vl: u32, pos: [u64; 3]) -> std::result::Result<(), ()> {
        self.visits += 1;
        if self.visits > REACH_BUDGET {
            return Err(());
        }
        let s = (2 * self.side) >> vl;
        // Voxel centres of the node, clipped to the editable region.
        let mut lo = DVec3::ZERO;
        let mut hi = DVec3::ZERO;
        for a in 0..3 {
            let l = (pos[a] * s).saturating_sub(1);
            let h = (pos[a] * s + s - 1).min(self.limit[a].saturating_sub(1));
            if self.limit[a] == 0 || l > h {
                return Ok(());
            }
            (lo[a], hi[a]) = (l as f64, h as f64);
        }
        let (parent, rest) = self.lists.split_at_mut(vl as usize + 1);
        let out = &mut rest[0];
        out.clear();
        for &i in &parent[vl as usize] {
            let c = self.centres[i as usize];
            let d = c.clamp(lo, hi) - c;
            if d.length_squared() <= self.r2 {
                out.push(i);
            }
        }
        if out.is_empty() {
            return Ok(());
        }
        match vl.checked_sub(1) {
            Some(l) if l == self.depth => {
                self.reach.cells += 1;
                let v = DVec3::from(pos.map(|p| p as f64));
                let inside = (0..3).all(|a| pos[a] < self.limit[a]);
                let near = out.iter().any(|&i| {
                    let c = self.centres[i as usize];
                    (v - c).length_squared() <= self.r2
                });
                self.reach.voxels += u64::from(inside && near);
                // Steps at which a corner (in the region) is newly within the tool.
                let corners: Vec<DVec3> = (0..8)
                    .map(|k| v - DVec3::new((k & 1) as f64, (k >> 1 & 1) as f64, (k >> 2) as f64))
                    .filter(|q| (0..3).all(|a| q[a] >= 0.0 && q[a] < self.limit[a] as f64))
                    .collect();
                for &i in out.iter() {
                    let c = self.centres[i as usize];
                    let before = (i as usize)
                        .checked_sub(1)
                        .and_then(|j| self.path.get(j))
                        .filter(|p| p.is_finite());
                    let new = corners.iter().any(|&q| {
                        let covered =
                            before.is_some_and(|&b| (q - b).length_squared() < self.inner2);
                        (q - c).length_squared() <= self.r2 && !covered
                    });
                    self.reach.changes += u64::from(new);
                }
                return Ok(());
            }
            Some(l) if pos.iter().all(|&p| p < 1 << l) => self.reach.nodes[l as usize] += 1,
            _ => {}
        }
        for ch in 0..8u64 {
            let p = [
                2 * pos[0] + (ch & 1),
                2 * pos[1] + (ch >> 1 & 1),
                2 * pos[2] + (ch >> 2),
            ];
            let child = s / 2;
            if p.iter().any(|&q| q * child > self.side) {
                continue;
            }
            self.visit(vl + 1, p)?;
        }
        Ok(())
    }
}

/// A sculpting run, for [`memory_estimate`].
#[derive(Clone, Copy, Debug)]
pub struct Plan<'a> {
    /// The volume's voxels along X, Y, Z.
    pub dims: [usize; 3],
    /// Bounds of the store's nodes and of the surface ([`csgpix_voxel::cells::cell_counts`]
    /// for a scene, [`crate::octree::estimate::volume_counts`] for a volume).
    pub counts: &'a CellCounts,
    /// The tool's centres, voxel units.
    pub path: &'a [DVec3],
    /// The tool's radius, voxels.
    pub radius: f64,
}

/// Bytes a sculpting run holds once the store is built (its build is
/// [`crate::octree::estimate::store_bytes`]): the optimized octree, grown by the path, the
/// per-cell mesh, the steps, and at the end the mesh in scene units and its copy welded by
/// the report's open-edge count (every format; the OBJ and PLY writers weld one as large,
/// freed before):
///
/// - the store: 1 + 7 entries an internal node before, 7 more for every node the path may
///   make internal (a split), the entries' vector at most twice that (reserved a quarter
///   ahead, then doubled), a bucket head each of the buckets it was built with;
/// - the mesh: a map entry (and control byte) for every cell that may have a surface, before
///   or after the path, and the old table while it grows; a pool of triangles holding the
///   triangles of every cell before the path and, at most, a new run for every change of a
///   cell's byte (each voxel flips at most once, changing its 8 cells), the pool's capacity
///   twice that; the free runs' indices;
/// - the end: the triangles (at most those of every cell that may have a surface, capped by
///   the pool), a map of their vertices (at most 3 per 4 triangles: every vertex is on a cut
///   lattice edge, whose 4 cells each give it a triangle) and the faces, and the map of
///   edges (3 per 2 triangles: the mesh is closed).
pub fn memory_estimate(p: &Plan) -> Result<u64> {
    let depth = depth_for(p.dims)?;
    if depth > MAX_DEPTH {
        return Ok(u64::MAX);
    }
    let reach = reach(p.path, p.radius, p.dims)?;
    let tmax = most_cell_triangles();
    // The store.
    let before = hashed_entries(crate::octree::StoreKind::Octree, p.counts.internal());
    let split = reach.nodes.iter().fold(0u64, |a, &n| a.saturating_add(n));
    let after = before.saturating_add(split.saturating_mul(7));
    // Sealed with no spare room, reserved a quarter more (the vector doubles), then doubling.
    let mut cap = before.saturating_mul(2);
    while cap < after {
        cap = cap.saturating_mul(2);
    }
    let store =
        table_bytes(before).saturating_add(cap.saturating_sub(before).saturating_mul(ENTRY_BYTES));
    // The mesh.
    let cells = p.counts.surface_cells();
    let live_cells = cells.saturating_add(reach.cells).max(cells + cells / 4);
    let buckets = map_buckets(live_cells);
    let map = map_bytes(buckets, CELL_ENTRY_BYTES)
        .saturating_add(map_bytes(buckets / 2, CELL_ENTRY_BYTES));
    let tris = triangles(p.counts);
    let changes = reach.voxels.saturating_mul(8).min(reach.changes);
    let pool_len = tris.saturating_add(changes.saturating_mul(tmax));
    let pool_cap = vec_capacity(pool_len.max(tris.saturating_add(cells / 2)));
    let free = vec_capacity(changes).saturating_mul(4);
    let mesh = map
        .saturating_add(pool_cap.saturating_mul(TRI_BYTES))
        .saturating_add(free);
    // The steps: the path, its steps and their times, one step's voxels and masks.
    let steps = (p.path.len() as u64)
        .saturating_mul(2 * 24 + std::mem::size_of::<crate::Step>() as u64 + 16);
    let box_side = 2.0 * p.radius.max(0.0) + 3.0;
    let ball = 4.0 / 3.0 * std::f64::consts::PI * (p.radius + 1.0).powi(3);
    let step = (box_side.powi(3) + 24.0 * ball) as u64;
    // The end.
    let out = pool_len.min(tris.saturating_add(reach.cells.saturating_mul(tmax)));
    let scene = out.saturating_mul(TRI_BYTES);
    let welded = map_bytes(map_buckets(out), 16)
        .saturating_add(out.saturating_add(6).saturating_mul(12))
        .saturating_add(out.saturating_mul(12));
    let edges = map_bytes(map_buckets(out.saturating_mul(3) / 2), 12);
    let end = scene.saturating_add(welded).saturating_add(edges);
    Ok(store
        .saturating_add(mesh)
        .saturating_add(steps)
        .saturating_add(step)
        .saturating_add(end))
}
