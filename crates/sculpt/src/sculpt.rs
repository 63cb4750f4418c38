//! Haptic sculpting on the optimized hash-based octree (seed 000 Ch. 5, Ch. 6, §5.2; digest
//! `notes/seed000.md` §2.9-§2.10): a spherical tool moves along a path; each step finds the
//! voxels under the tool by key lookup with ancestor fallback, removes them (or adds them),
//! rewrites the case bytes of every dual cell having a changed voxel as a corner (splitting
//! coarse leaves along the path only), re-meshes exactly those cells with their old triangles
//! removed, and computes the spring force F = k·ΔX. See `docs/sculpting.md`.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::time::Instant;

use glam::DVec3;
use serde::Serialize;

use crate::octree::cell::{BEYOND, CORNERS};
use crate::octree::key::{self, Key};
use crate::octree::{mc, OptimizedOctree, SurfaceWalk, VoxelStore};
use csgpix_scene::mesh::Tri;
use csgpix_scene::Error as SceneError;

use crate::{Error, Result, ToolProblem};

/// Largest tool radius, in voxels: a step then touches at most (2·128 + 2)³ cells.
pub const MAX_RADIUS: f64 = 128.0;

/// Where voxels sit in the scene: voxel (i, j, k)'s centre is `origin + (i, j, k) ⊙ voxel`.
/// Marching Cubes works in voxel units with the same origin (`octree::mc`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Scene position of voxel (0, 0, 0)'s centre.
    pub origin: DVec3,
    /// Size of a voxel along each axis, in scene units.
    pub voxel: DVec3,
}

impl Frame {
    /// The frame of a voxelization grid.
    pub fn of_grid(g: &csgpix_scene::grid::Grid) -> Frame {
        Frame {
            origin: g.centre(0, 0, 0),
            voxel: g.voxel(),
        }
    }

    /// Voxel units (voxel centres at whole numbers) of a scene point.
    pub fn to_voxel(&self, p: DVec3) -> DVec3 {
        (p - self.origin) / self.voxel
    }

    /// Scene units of a point in voxel units.
    pub fn to_scene(&self, v: [f32; 3]) -> [f32; 3] {
        let p = self.origin + DVec3::new(v[0].into(), v[1].into(), v[2].into()) * self.voxel;
        [p.x as f32, p.y as f32, p.z as f32]
    }
}

/// A multiply-shift hasher for octree keys (Morton codes: the low bits already spread).
#[derive(Clone, Copy, Debug, Default)]
pub struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u64(&mut self, k: u64) {
        let h = (self.0 ^ k).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        self.0 = h ^ h >> 29;
    }
}

type KeyMap<V> = HashMap<Key, V, BuildHasherDefault<KeyHasher>>;

/// Most triangles one cell's case emits (a table row holds 5).
const CELL_TRIS: usize = 5;

/// The mesh kept per cell (seed 000 §5.2: "delete the triangles generated from the node's old
/// value, append those of its new value"): every surface cell owns a run of triangles in one
/// pool; a freed run goes to a free list by length and is reused by the next cell with as
/// many triangles. Vertices in voxel units.
#[derive(Clone, Debug, Default)]
pub struct CellMesh {
    pool: Vec<Tri>,
    cells: KeyMap<(u32, u8)>,
    free: [Vec<u32>; CELL_TRIS + 1],
    live: usize,
}

impl CellMesh {
    /// The mesh of every surface cell of `store` (global Marching Cubes, §3.1.2, per cell,
    /// the cells past the grid's far faces included).
    pub fn of_store(store: &OptimizedOctree) -> CellMesh {
        let mut m = CellMesh::default();
        let mut scratch = Vec::with_capacity(CELL_TRIS);
        store.walk_surface(|p, v| m.set(p, v, &mut scratch));
        m
    }

    /// The map's key of cell `p`: a key one level below the deepest a store may have, so
    /// that the cells past the far faces (a coordinate equal to the side) have keys too.
    fn slot(p: [u32; 3]) -> Key {
        key::key(p[0], p[1], p[2], key::MAX_DEPTH + 1)
    }

    /// Replaces cell `p`'s triangles by those of byte `v`.
    pub fn set(&mut self, p: [u32; 3], v: u8, scratch: &mut Vec<Tri>) {
        let k = Self::slot(p);
        self.remove(k);
        scratch.clear();
        mc::cell_triangles(p, v, scratch);
        let n = scratch.len().min(CELL_TRIS);
        if n == 0 {
            return;
        }
        let at = match self.free[n].pop() {
            Some(at) => {
                self.pool[at as usize..at as usize + n].copy_from_slice(&scratch[..n]);
                at
            }
            None => {
                self.pool.extend_from_slice(&scratch[..n]);
                (self.pool.len() - n) as u32
            }
        };
        self.cells.insert(k, (at, n as u8));
        self.live += n;
    }

    /// Drops cell `k`'s triangles.
    fn remove(&mut self, k: Key) {
        if let Some((at, n)) = self.cells.remove(&k) {
            self.free[n as usize].push(at);
            self.live -= n as usize;
        }
    }

    /// Room for `more` surface cells (and 2 triangles each) without reallocating.
    pub fn reserve(&mut self, more: usize) {
        self.cells.reserve(more);
        self.pool.reserve(2 * more);
    }

    /// Live triangles.
    pub fn len(&self) -> usize {
        self.live
    }

    /// No triangle?
    pub fn is_empty(&self) -> bool {
        self.live == 0
    }

    /// Cells with triangles.
    pub fn cells(&self) -> usize {
        self.cells.len()
    }

    /// Every live triangle (voxel units), cell by cell in no particular order.
    pub fn triangles(&self) -> Vec<Tri> {
        let mut out = Vec::with_capacity(self.live);
        for &(at, n) in self.cells.values() {
            out.extend_from_slice(&self.pool[at as usize..at as usize + n as usize]);
        }
        out
    }
}

/// What one step did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Step {
    /// The tool touched material (a filled voxel centre inside the sphere) before the update.
    pub contact: bool,
    /// Voxels removed (or added).
    pub voxels: u32,
    /// Cells whose byte changed, each re-meshed.
    pub cells: u32,
    /// Nodes the octree gained by splitting coarse leaves.
    pub nodes_added: u64,
    /// ΔX = P_s − P_c in scene units (seed 000 Eq. 6.1-6.2), zero without contact.
    pub displacement: [f64; 3],
    /// F = k·ΔX.
    pub force: [f64; 3],
    /// Wall time of the step: collision, update, local re-mesh and force.
    pub seconds: f64,
}

/// The tool and the force model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tool {
    /// Sphere radius in voxels, in (0, [`MAX_RADIUS`]].
    pub radius: f64,
    /// Add material instead of removing it.
    pub add: bool,
    /// k of F = k·ΔX, force per scene unit.
    pub stiffness: f64,
}

/// `sphere:R` (R in voxels).
pub fn parse_tool(s: &str) -> Result<f64> {
    let bad = |reason: ToolProblem| Error::BadTool {
        spec: s.to_string(),
        reason,
    };
    let r = s
        .strip_prefix("sphere:")
        .ok_or_else(|| bad(ToolProblem::NotSphere))?;
    let r: f64 = r.trim().parse().map_err(|e| bad(ToolProblem::Radius(e)))?;
    check_radius(r).map_err(bad)
}

/// The radius if it is in (0, [`MAX_RADIUS`]], else why not.
fn check_radius(r: f64) -> Result<f64, ToolProblem> {
    if r.is_finite() && r > 0.0 && r <= MAX_RADIUS {
        Ok(r)
    } else {
        Err(ToolProblem::RadiusRange)
    }
}

/// The sculpting state: the store, its per-cell mesh and the haptic contact.
pub struct Sculptor {
    /// The optimized octree being sculpted (§4.3.4).
    pub store: OptimizedOctree,
    /// Its mesh, one entry per surface cell (local Marching Cubes, §5.2).
    pub mesh: CellMesh,
    /// Where the voxels sit in the scene.
    pub frame: Frame,
    tool: Tool,
    /// Voxels the tool may change: 0..limit on each axis.
    limit: [u32; 3],
    /// P_s: the HIP where the current contact began (seed 000 Eq. 6.2).
    touch: Option<DVec3>,
    /// The previous HIP.
    prev: Option<DVec3>,
    /// Voxels to change this step, and the box of voxels the tool covers.
    flips: Vec<[u32; 3]>,
    boxed: ([u32; 3], [u32; 3]),
    masks: Vec<u8>,
    scratch: Vec<Tri>,
}

/// Bit of cell c = v + d for voxel v: v's corner in c is (1 − d) from c's minimum corner.
const BIT_OF: [u8; 8] = bits_of();

const fn bits_of() -> [u8; 8] {
    let mut t = [0u8; 8];
    let mut d = 0;
    while d < 8 {
        let want = [
            1 - (d & 1) as u8,
            1 - (d >> 1 & 1) as u8,
            1 - (d >> 2 & 1) as u8,
        ];
        let mut i = 0;
        while i < 8 {
            let c = CORNERS[i];
            if c[0] == want[0] && c[1] == want[1] && c[2] == want[2] {
                t[d] = i as u8;
            }
            i += 1;
        }
        d += 1;
    }
    t
}

impl Sculptor {
    /// A sculptor over `store` (a volume of `dims` voxels placed by `frame`): the tool may
    /// touch every voxel of the volume, removing or adding.
    pub fn new(
        mut store: OptimizedOctree,
        frame: Frame,
        dims: [usize; 3],
        tool: Tool,
    ) -> Result<Sculptor> {
        check_radius(tool.radius).map_err(Error::Tool)?;
        if !(tool.stiffness.is_finite() && tool.stiffness >= 0.0) {
            return Err(Error::BadStiffness);
        }
        let side = store.side() as u32;
        let limit = dims.map(|d| (d.min(u32::MAX as usize) as u32).min(side));
        let mut mesh = CellMesh::of_store(&store);
        // Headroom so that early steps do not stall on a reallocation or a rehash (the
        // structures still grow, with a stall, past it).
        store.reserve(store.node_count() / 4);
        mesh.reserve(mesh.cells() / 4);
        Ok(Sculptor {
            store,
            mesh,
            frame,
            tool,
            limit,
            touch: None,
            prev: None,
            flips: Vec::new(),
            boxed: ([0; 3], [0; 3]),
            masks: Vec::new(),
            scratch: Vec::with_capacity(CELL_TRIS),
        })
    }

    /// One haptic step with the tool's centre (the HIP) at `hip`, in scene units.
    pub fn step(&mut self, hip: DVec3) -> Result<Step> {
        let t0 = Instant::now();
        let nodes = self.store.node_count();
        let contact = self.collide(self.frame.to_voxel(hip));
        let cells = self.update()?;
        let (dx, f) = self.force(hip, contact);
        Ok(Step {
            contact,
            voxels: self.flips.len() as u32,
            cells,
            nodes_added: self.store.node_count().saturating_sub(nodes) as u64,
            displacement: dx.to_array(),
            force: f.to_array(),
            seconds: t0.elapsed().as_secs_f64(),
        })
    }

    /// The box of voxels within the tool's reach, clipped to the editable region; None when
    /// the tool is wholly outside it.
    fn reach(&self, c: DVec3) -> Option<([u32; 3], [u32; 3])> {
        if !c.is_finite() {
            return None;
        }
        let r = self.tool.radius;
        let mut lo = [0u32; 3];
        let mut hi = [0u32; 3];
        for a in 0..3 {
            let lim = f64::from(self.limit[a]);
            let (l, h) = (
                (c[a] - r).ceil().max(0.0),
                (c[a] + r).floor().min(lim - 1.0),
            );
            if l > h {
                return None;
            }
            (lo[a], hi[a]) = (l as u32, h as u32);
        }
        Some((lo, hi))
    }

    /// Collision (seed 000 §5.1): every voxel centre inside the tool is looked up by its key,
    /// falling back to the nearest stored ancestor (a coarse leaf answers for all the voxels
    /// it covers; the last one found is kept). Fills `flips` with the voxels to change; true
    /// when a filled voxel is inside the tool.
    fn collide(&mut self, c: DVec3) -> bool {
        self.flips.clear();
        let Some((lo, hi)) = self.reach(c) else {
            self.boxed = ([0; 3], [0; 3]);
            return false;
        };
        self.boxed = (lo, hi);
        let (r2, depth) = (self.tool.radius * self.tool.radius, self.store.depth());
        let mut cache: (Key, u32, u8) = (0, 0, 0);
        let mut contact = false;
        for z in lo[2]..=hi[2] {
            for y in lo[1]..=hi[1] {
                for x in lo[0]..=hi[0] {
                    let d = DVec3::new(x.into(), y.into(), z.into()) - c;
                    if d.length_squared() > r2 {
                        continue;
                    }
                    let filled = self.voxel(&mut cache, [x, y, z], depth);
                    contact |= filled;
                    if filled != self.tool.add {
                        self.flips.push([x, y, z]);
                    }
                }
            }
        }
        contact
    }

    /// Voxel p (bit 6 of its cell), through the last coarse leaf found when it covers p.
    fn voxel(&self, cache: &mut (Key, u32, u8), p: [u32; 3], depth: u32) -> bool {
        let k = key::key(p[0], p[1], p[2], depth);
        if k >> cache.1 != cache.0 {
            let (found, v) = self.store.find(p[0], p[1], p[2]).unwrap_or((0, 0));
            *cache = (found, 3 * (depth - key::level(found.max(1))), v);
        }
        cache.2 >> crate::octree::cell::SELF_BIT & 1 == 1
    }

    /// Rewrites the byte of every cell having a changed voxel as a corner (the changed voxels
    /// ⊕ {0, 1}³, seed 000 §5.2 and the digest's general rule) and re-meshes exactly the cells
    /// whose byte changed. Returns how many.
    fn update(&mut self) -> Result<u32> {
        if self.flips.is_empty() {
            return Ok(0);
        }
        let (lo, hi) = self.boxed;
        let n = [0, 1, 2].map(|a| (hi[a] - lo[a] + 2) as usize);
        self.masks.clear();
        self.masks.resize(n[0] * n[1] * n[2], 0);
        for v in &self.flips {
            for (d, &bit) in BIT_OF.iter().enumerate() {
                let o = [d & 1, d >> 1 & 1, d >> 2 & 1];
                let i = [0, 1, 2].map(|a| (v[a] - lo[a]) as usize + o[a]);
                self.masks[(i[2] * n[1] + i[1]) * n[0] + i[0]] ^= 1 << bit;
            }
        }
        self.apply_masks(lo, n)
    }

    /// Applies the corner flips of the mask box at `lo` (dims `n`) to the store and the mesh.
    /// The cells past the grid's far faces are not stored: once the stored cells are set,
    /// each is re-meshed with the byte read from the stored cell it borders.
    fn apply_masks(&mut self, lo: [u32; 3], n: [usize; 3]) -> Result<u32> {
        let side = self.store.side() as u32;
        let at = |i: usize| {
            [
                lo[0] + (i % n[0]) as u32,
                lo[1] + (i / n[0] % n[1]) as u32,
                lo[2] + (i / (n[0] * n[1])) as u32,
            ]
        };
        let mut changed = 0;
        let mut beyond = false;
        for (i, &m) in self.masks.iter().enumerate() {
            let p = at(i);
            if m == 0 || p.iter().any(|&c| c >= side) {
                beyond |= m != 0;
                continue;
            }
            let v = self.store.cell(p[0], p[1], p[2]) ^ m;
            self.store.set_cell(p[0], p[1], p[2], v)?;
            self.mesh.set(p, v, &mut self.scratch);
            changed += 1;
        }
        if beyond {
            for (i, &m) in self.masks.iter().enumerate() {
                let p = at(i);
                if m == 0 || p.iter().any(|&c| c > side) || !p.contains(&side) {
                    continue;
                }
                let far = (0..3).fold(0u8, |f, a| f | u8::from(p[a] == side) << a);
                let q = p.map(|c| c.min(side - 1));
                let v = BEYOND[far as usize][self.store.cell(q[0], q[1], q[2]) as usize];
                self.mesh.set(p, v, &mut self.scratch);
                changed += 1;
            }
        }
        Ok(changed)
    }

    /// The spring force of seed 000 §6 (Eq. 6.1, F = k·ΔX) with ΔX = P_s − P_c (Eq. 6.2 as the
    /// digest reads it, §2.10): P_c is the HIP now, P_s where the stylus touched the surface,
    /// taken as the last HIP before the current contact began (the first HIP if the path
    /// starts in contact). No contact: no force, and the next contact starts afresh.
    fn force(&mut self, hip: DVec3, contact: bool) -> (DVec3, DVec3) {
        let before = self.prev.replace(hip);
        if !contact {
            self.touch = None;
            return (DVec3::ZERO, DVec3::ZERO);
        }
        let ps = *self.touch.get_or_insert(before.unwrap_or(hip));
        let dx = ps - hip;
        (dx, dx * self.tool.stiffness)
    }

    /// The mesh in scene units.
    pub fn scene_triangles(&self) -> Vec<Tri> {
        let f = self.frame;
        let mut t = self.mesh.triangles();
        for tri in &mut t {
            *tri = tri.map(|v| f.to_scene(v));
        }
        t
    }
}

/// Tool positions from a CSV file's text: columns x, y, z in scene units, one row per
/// position; blank lines and `#` comments are skipped, and the first row may be a header
/// (no field of it a number). Errors read `file:line:col: message`.
pub fn parse_path(text: &str, file: &str) -> Result<Vec<DVec3>> {
    let mut out = Vec::new();
    let mut first = true;
    for (n, raw) in text.lines().enumerate() {
        let line = raw.strip_suffix('\r').unwrap_or(raw);
        if line.trim().is_empty() || line.trim_start().starts_with('#') {
            continue;
        }
        let fields = fields(line);
        let header = first && fields.iter().all(|(_, f)| f.trim().parse::<f64>().is_err());
        first = false;
        if header {
            continue;
        }
        out.push(parse_row(&fields, line.len(), file, n + 1)?);
    }
    if out.is_empty() {
        return Err(Error::NoToolPositions { file: file.into() });
    }
    Ok(out)
}

/// The comma-separated fields of a line with their 1-based start columns.
fn fields(line: &str) -> Vec<(usize, &str)> {
    let mut at = 1;
    line.split(',')
        .map(|f| {
            let col = at + (f.len() - f.trim_start().len());
            at += f.chars().count() + 1;
            (col, f)
        })
        .collect()
}

fn parse_row(fields: &[(usize, &str)], len: usize, file: &str, line: usize) -> Result<DVec3> {
    if fields.len() != 3 {
        let col = fields.get(3).map_or(len + 1, |f| f.0);
        let found = fields.len();
        let problem = SceneError::Expected {
            expected: "3 fields x,y,z".into(),
            found: found.to_string(),
        };
        return Err(Error::Scene(SceneError::at(file, line, col, problem)));
    }
    let mut v = [0.0; 3];
    for (i, (col, f)) in fields.iter().enumerate() {
        let f = f.trim();
        let text = f.to_string();
        let problem = match f.parse::<f64>() {
            Ok(x) if x.is_finite() => {
                v[i] = x;
                continue;
            }
            Ok(_) => SceneError::NotFinite { text },
            Err(_) => SceneError::NotANumber { text },
        };
        return Err(Error::Scene(SceneError::at(file, line, *col, problem)));
    }
    Ok(DVec3::from_array(v))
}

/// The frame of a NRRD volume read by [`csgpix_scene::nrrd::read_nrrd`] (`space origin`, and
/// `space directions` or `spacings`): the octree's cells are axis-aligned, so the steps must
/// be positive and along the axes.
pub fn nrrd_frame(n: &csgpix_scene::nrrd::Nrrd) -> Result<Frame> {
    let d = n.directions;
    let voxel = DVec3::new(d.x_axis.x, d.y_axis.y, d.z_axis.z);
    let off = [
        d.x_axis.y, d.x_axis.z, d.y_axis.x, d.y_axis.z, d.z_axis.x, d.z_axis.y,
    ];
    if off.iter().any(|&v| v != 0.0) || !voxel.is_finite() || voxel.min_element() <= 0.0 {
        return Err(Error::NotAxisAligned);
    }
    Ok(Frame {
        origin: n.origin,
        voxel,
    })
}

/// The filled voxels of a NRRD volume: samples at or above `threshold`, or, without one,
/// samples other than 0 (a volume `voxelize` wrote: 0 is empty, a colour code is filled).
pub fn nrrd_voxels(n: &csgpix_scene::nrrd::Nrrd, threshold: Option<f64>) -> Vec<u8> {
    let inside = |v: f32| match threshold {
        Some(t) => f64::from(v) >= t,
        None => v != 0.0,
    };
    n.samples.iter().map(|&v| u8::from(inside(v))).collect()
}

/// Step latency figures, microseconds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Latency {
    /// Steps timed.
    pub steps: usize,
    /// Median step, µs.
    pub median_us: f64,
    /// 99th percentile (nearest rank), µs.
    pub p99_us: f64,
    /// Slowest step, µs.
    pub max_us: f64,
    /// Mean step, µs.
    pub mean_us: f64,
}

impl Latency {
    /// Median, 99th percentile (nearest rank), max and mean of step times in seconds.
    pub fn of(seconds: &[f64]) -> Latency {
        let mut s: Vec<f64> = seconds.iter().map(|t| t * 1e6).collect();
        s.sort_by(f64::total_cmp);
        let n = s.len();
        if n == 0 {
            return Latency::default();
        }
        let rank = |q: f64| s[((q * n as f64).ceil() as usize).clamp(1, n) - 1];
        Latency {
            steps: n,
            median_us: if n % 2 == 1 {
                s[n / 2]
            } else {
                (s[n / 2 - 1] + s[n / 2]) / 2.0
            },
            p99_us: rank(0.99),
            max_us: s[n - 1],
            mean_us: s.iter().sum::<f64>() / n as f64,
        }
    }
}
