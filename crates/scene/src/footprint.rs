//! A straight extrusion kept as its footprint: a `linear_extrude` without twist or scale of a
//! large 2D tree, as the tree itself (its shapes' outlines and its operations) and a height,
//! instead of one convex prism or mesh per shape.
//!
//! Seen along its axis such a solid is the same 2D set at every height, so a voxel column is
//! inside it over one depth interval or not at all: its pixels are found once, by evaluating
//! the 2D tree over the pixel centres, and every slab follows (`csgpix_voxel`'s runs). The
//! tree is evaluated in one raster pass per operation: each shape's pixels by scan lines over
//! its own box, each operation's by combining its children's boxes, so the cost follows the
//! shapes' edges and the boxes they cover, not shapes × pixels, and nothing is held per plane.
//!
//! A shape is its outlines under the even-odd rule (a point is inside when a ray from it
//! crosses its outlines an odd number of times), as OpenSCAD cleans up a polygon and as
//! `csgpix_openscad::extrude` orients a shape's outlines. Pixel (x, y) is sampled at the
//! integer point (x, y) of pixel coordinates, as the meshes' raster
//! ([`crate::trimesh::TriMesh::crossings_flat_in`]); an outline's edge counts for the rows from
//! its lower end up to, not including, its upper end.

use glam::{DMat4, DVec2, DVec3};

use crate::trimesh::Window;

const EMPTY_BOX: (DVec2, DVec2) = (DVec2::INFINITY, DVec2::NEG_INFINITY);

/// A 2D boolean operation of the footprint's tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// Everything in any operand.
    Union,
    /// Everything in every operand.
    Intersection,
    /// The first operand minus the others.
    Difference,
}

/// One step of the tree in postfix order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Step {
    /// The next shape.
    Shape,
    /// An operation on the last `n` results.
    Op(Op, usize),
}

/// A 2D tree extruded straight along the Z axis of its plane, placed in the scene.
///
/// Invariants (kept by [`Footprint::push_shape`], [`Footprint::push_op`] and checked by
/// [`Footprint::is_complete`]): `path_ends` and `shape_ends` are non-decreasing and end at
/// the lengths of `points` and `path_ends`; the steps leave exactly one result.
#[derive(Clone, Debug, PartialEq)]
pub struct Footprint {
    /// Every outline point in the plane, path after path.
    points: Vec<DVec2>,
    /// Where each path ends in `points`.
    path_ends: Vec<usize>,
    /// Where each shape's paths end in `path_ends`.
    shape_ends: Vec<usize>,
    /// The tree, postfix.
    steps: Vec<Step>,
    /// While the tree is built, the scene XY box of each result on its stack: a shape's
    /// placed points, a union's operands together, an intersection's overlap, a difference's
    /// first operand (lo > hi for an empty one). The last is the tree's box.
    boxes: Vec<(DVec2, DVec2)>,
    /// The scene XY box of every placed outline point, subtracted shapes' too.
    points_box: (DVec2, DVec2),
    /// Bottom and top of the extrusion in its plane's frame (bottom ≤ top).
    pub z: [f64; 2],
    /// Scene ← plane, row-major 4×4 (affine). It keeps the Z axis: the plane's X and Y map
    /// into the scene's XY plane and its Z onto the scene's Z ([`keeps_z`]).
    pub matrix: [[f64; 4]; 4],
}

/// Whether row-major affine `m` maps the XY plane into itself and Z onto Z (a footprint's
/// placement): rotations about Z, mirrors, scales and translations.
pub fn keeps_z(m: &[[f64; 4]; 4]) -> bool {
    m[0][2] == 0.0 && m[1][2] == 0.0 && m[2][0] == 0.0 && m[2][1] == 0.0 && m[2][2] != 0.0
}

/// Pixels inside, over a box of pixels (absolute pixel coordinates).
#[derive(Clone, Debug, Default)]
struct Mask {
    x0: i64,
    y0: i64,
    w: usize,
    h: usize,
    bits: Vec<bool>,
}

impl Mask {
    fn empty() -> Mask {
        Mask::default()
    }

    fn zeros(x0: i64, y0: i64, x1: i64, y1: i64) -> Mask {
        if x1 < x0 || y1 < y0 {
            return Mask::empty();
        }
        let (w, h) = ((x1 - x0 + 1) as usize, (y1 - y0 + 1) as usize);
        Mask {
            x0,
            y0,
            w,
            h,
            bits: vec![false; w * h],
        }
    }

    fn is_empty(&self) -> bool {
        self.w == 0 || self.h == 0
    }

    /// Last column and row (inclusive).
    fn hi(&self) -> (i64, i64) {
        (self.x0 + self.w as i64 - 1, self.y0 + self.h as i64 - 1)
    }

    fn get(&self, x: i64, y: i64) -> bool {
        let (x1, y1) = self.hi();
        if self.is_empty() || x < self.x0 || y < self.y0 || x > x1 || y > y1 {
            return false;
        }
        self.bits[(y - self.y0) as usize * self.w + (x - self.x0) as usize]
    }

    /// Itself, or the empty mask when no pixel is set.
    fn trimmed(self) -> Mask {
        match self.bits.iter().any(|&b| b) {
            true => self,
            false => Mask::empty(),
        }
    }
}

impl Footprint {
    /// An empty tree over heights `z` (in any order), placed by `matrix` (which must keep
    /// the Z axis, [`keeps_z`]).
    pub fn new(z: [f64; 2], matrix: [[f64; 4]; 4]) -> Footprint {
        debug_assert!(keeps_z(&matrix));
        Footprint {
            points: vec![],
            path_ends: vec![],
            shape_ends: vec![],
            steps: vec![],
            boxes: vec![],
            points_box: EMPTY_BOX,
            z: [z[0].min(z[1]), z[0].max(z[1])],
            matrix,
        }
    }

    /// Adds a shape (its outlines, even-odd) as the next leaf.
    pub fn push_shape<'a>(&mut self, paths: impl IntoIterator<Item = &'a [DVec2]>) {
        let mut b = EMPTY_BOX;
        let m = self.matrix;
        // Placed as the reader places a prism's vertices (row · (x, y, z, 1), the Z term
        // zero), so the boxes are those of the prisms' vertices to the bit.
        let row = |r: &[f64; 4], q: DVec2| r[0] * q.x + r[1] * q.y + r[2] * self.z[0] + r[3];
        for p in paths {
            for &q in p {
                let s = DVec2::new(row(&m[0], q), row(&m[1], q));
                b = (b.0.min(s), b.1.max(s));
            }
            self.points.extend_from_slice(p);
            self.path_ends.push(self.points.len());
        }
        self.boxes.push(b);
        self.points_box = (self.points_box.0.min(b.0), self.points_box.1.max(b.1));
        self.shape_ends.push(self.path_ends.len());
        self.steps.push(Step::Shape);
    }

    /// Combines the last `n` results (shapes or operations, in the order they were pushed).
    pub fn push_op(&mut self, op: Op, n: usize) {
        self.steps.push(Step::Op(op, n));
        let parts = self.boxes.split_off(self.boxes.len().saturating_sub(n));
        let mut it = parts.into_iter();
        let first = it.next().unwrap_or(EMPTY_BOX);
        self.boxes.push(match op {
            Op::Union => it.fold(first, |a, b| (a.0.min(b.0), a.1.max(b.1))),
            Op::Intersection => {
                let (lo, hi) = it.fold(first, |a, b| (a.0.max(b.0), a.1.min(b.1)));
                // An empty overlap is the empty box, which a union then leaves out.
                match lo.x <= hi.x && lo.y <= hi.y {
                    true => (lo, hi),
                    false => EMPTY_BOX,
                }
            }
            Op::Difference => first,
        });
    }

    /// Whether the steps leave exactly one result.
    pub fn is_complete(&self) -> bool {
        let mut depth = 0usize;
        for s in &self.steps {
            match *s {
                Step::Shape => depth += 1,
                Step::Op(_, n) if n <= depth => depth = depth - n + 1,
                Step::Op(..) => return false,
            }
        }
        depth == 1
    }

    /// Outline points.
    pub fn points(&self) -> usize {
        self.points.len()
    }

    /// Bytes it holds.
    pub fn bytes(&self) -> u64 {
        (self.points.capacity() * 16
            + (self.path_ends.capacity() + self.shape_ends.capacity()) * 8
            + self.steps.capacity() * 16) as u64
    }

    /// Scene ← plane as a matrix.
    pub fn to_scene(&self) -> DMat4 {
        DMat4::from_cols_array_2d(&self.matrix).transpose()
    }

    /// The placed heights of the bottom and the top, in order.
    fn scene_z(&self) -> [f64; 2] {
        let r = &self.matrix[2];
        let z = self.z.map(|z| r[0] * 0.0 + r[1] * 0.0 + r[2] * z + r[3]);
        [z[0].min(z[1]), z[0].max(z[1])]
    }

    /// Scene box around every placed outline point (subtracted shapes' too, as a scene's
    /// box counts every primitive), the same as the box of its shapes' prisms.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        self.at_heights(self.points_box)
    }

    /// Scene box around the tree's set: a union's operands' boxes together, an
    /// intersection's overlap, a difference's first operand (what is cut away does not widen
    /// it). Empty (lo > hi, infinite) when the set is empty by its boxes.
    pub fn set_bounds(&self) -> (DVec3, DVec3) {
        self.at_heights(self.boxes.last().copied().unwrap_or(EMPTY_BOX))
    }

    /// Whether [`Footprint::set_bounds`] is the set's own box: no intersection or difference
    /// can cut the set inside it (a union's and a shape's boxes are their points').
    pub fn set_bounds_exact(&self) -> bool {
        self.steps
            .iter()
            .all(|s| matches!(s, Step::Shape | Step::Op(Op::Union, _)))
    }

    fn at_heights(&self, (lo, hi): (DVec2, DVec2)) -> (DVec3, DVec3) {
        if !(lo.x <= hi.x && lo.y <= hi.y) {
            return (DVec3::INFINITY, DVec3::NEG_INFINITY);
        }
        let [z0, z1] = self.scene_z();
        (lo.extend(z0), hi.extend(z1))
    }

    /// Per pixel of `win` (index `(y − y0)·w + (x − x0)`), whether the 2D tree holds the
    /// pixel's centre; `to_pixel` maps a point of the plane to pixel coordinates (an affine
    /// map). One scan-line raster per shape over its own box, one pass per operation over
    /// its operands' boxes (module documentation).
    pub fn mask_in(&self, to_pixel: impl Fn(DVec2) -> DVec2, win: Window) -> Vec<bool> {
        let mut out = vec![false; win.w.saturating_mul(win.h)];
        let Some(m) = self.evaluate(&to_pixel, win) else {
            return out;
        };
        for y in 0..win.h {
            for x in 0..win.w {
                out[y * win.w + x] = m.get((win.x0 + x) as i64, (win.y0 + y) as i64);
            }
        }
        out
    }

    /// The tree's result over `win`, None when the steps are not complete.
    fn evaluate(&self, to_pixel: &dyn Fn(DVec2) -> DVec2, win: Window) -> Option<Mask> {
        let mut stack: Vec<Mask> = vec![];
        let mut shape = 0;
        let mut scratch = Scan::default();
        for s in &self.steps {
            match *s {
                Step::Shape => {
                    stack.push(self.shape_mask(shape, to_pixel, win, &mut scratch));
                    shape += 1;
                }
                Step::Op(op, n) => {
                    let parts = stack.split_off(stack.len().checked_sub(n)?);
                    stack.push(combine(op, parts));
                }
            }
        }
        (stack.len() == 1).then(|| stack.pop()).flatten()
    }

    /// Shape `s`'s pixels within `win`, by scan lines.
    fn shape_mask(
        &self,
        s: usize,
        to_pixel: &dyn Fn(DVec2) -> DVec2,
        win: Window,
        scan: &mut Scan,
    ) -> Mask {
        let paths = match s {
            0 => 0..self.shape_ends[0],
            _ => self.shape_ends[s - 1]..self.shape_ends[s],
        };
        scan.clear();
        let mut from = if paths.start == 0 {
            0
        } else {
            self.path_ends[paths.start - 1]
        };
        for &end in &self.path_ends[paths] {
            scan.path(self.points[from..end].iter().map(|&p| to_pixel(p)));
            from = end;
        }
        scan.fill(win)
    }
}

/// One shape's scan conversion: its edges in pixel coordinates, then their crossings of the
/// pixel rows.
#[derive(Default)]
struct Scan {
    /// Edges, lower end first.
    edges: Vec<(DVec2, DVec2)>,
    /// (row, x) of every crossing.
    hits: Vec<(i64, f64)>,
}

impl Scan {
    fn clear(&mut self) {
        self.edges.clear();
        self.hits.clear();
    }

    /// A closed outline (the last point joins the first); horizontal edges cross no row.
    fn path(&mut self, points: impl Iterator<Item = DVec2>) {
        let start = self.edges.len();
        let mut first = None;
        let mut last: Option<DVec2> = None;
        for p in points {
            first.get_or_insert(p);
            if let Some(a) = last {
                self.edge(a, p);
            }
            last = Some(p);
        }
        if let (Some(a), Some(b)) = (last, first) {
            if self.edges.len() > start || a != b {
                self.edge(a, b);
            }
        }
    }

    fn edge(&mut self, a: DVec2, b: DVec2) {
        if a.y != b.y {
            self.edges.push(if a.y < b.y { (a, b) } else { (b, a) });
        }
    }

    /// The pixels whose centres lie inside by the even-odd rule, clipped to `win`.
    fn fill(&mut self, win: Window) -> Mask {
        let (wx1, wy1) = (
            win.x0 as i64 + win.w as i64 - 1,
            win.y0 as i64 + win.h as i64 - 1,
        );
        let (mut lo, mut hi) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        for &(a, b) in &self.edges {
            lo = lo.min(a.min(b));
            hi = hi.max(a.max(b));
        }
        if !(lo.x <= hi.x && lo.y <= hi.y) {
            return Mask::empty();
        }
        // Rows from the lowest centre at or above lo.y to the last below hi.y, in the window.
        let y0 = clamp_i64(lo.y.ceil()).max(win.y0 as i64);
        let y1 = (clamp_i64(hi.y.ceil()) - 1).min(wy1);
        let x0 = clamp_i64(lo.x.ceil()).max(win.x0 as i64);
        let x1 = clamp_i64(hi.x.floor()).min(wx1);
        let mut mask = Mask::zeros(x0, y0, x1, y1);
        if mask.is_empty() {
            return Mask::empty();
        }
        for &(a, b) in &self.edges {
            // Rows y with a.y <= y < b.y.
            let r0 = clamp_i64(a.y.ceil()).max(y0);
            let r1 = (clamp_i64(b.y.ceil()) - 1).min(y1);
            let slope = (b.x - a.x) / (b.y - a.y);
            for y in r0..=r1 {
                self.hits.push((y, a.x + (y as f64 - a.y) * slope));
            }
        }
        self.hits
            .sort_unstable_by(|p, q| p.0.cmp(&q.0).then(p.1.total_cmp(&q.1)));
        for row in self.hits.chunk_by(|p, q| p.0 == q.0) {
            let base = (row[0].0 - y0) as usize * mask.w;
            // Inside from each even crossing to the next odd one: x in [c0, c1).
            for pair in row.chunks_exact(2) {
                let from = clamp_i64(pair[0].1.ceil()).max(x0);
                let to = (clamp_i64(pair[1].1.ceil()) - 1).min(x1);
                for x in from..=to {
                    mask.bits[base + (x - x0) as usize] = true;
                }
            }
        }
        mask.trimmed()
    }
}

/// A float's whole value as an i64, saturating (NaN as 0).
fn clamp_i64(v: f64) -> i64 {
    v.clamp(-(1i64 << 52) as f64, (1i64 << 52) as f64) as i64
}

/// One operation over its operands' masks.
fn combine(op: Op, parts: Vec<Mask>) -> Mask {
    let mut it = parts.into_iter();
    let Some(first) = it.next() else {
        return Mask::empty();
    };
    match op {
        Op::Union => {
            let rest: Vec<Mask> = it.filter(|m| !m.is_empty()).collect();
            let boxes = std::iter::once(&first)
                .chain(&rest)
                .filter(|m| !m.is_empty());
            let (mut x0, mut y0, mut x1, mut y1) = (i64::MAX, i64::MAX, i64::MIN, i64::MIN);
            for m in boxes {
                let (hx, hy) = m.hi();
                (x0, y0, x1, y1) = (x0.min(m.x0), y0.min(m.y0), x1.max(hx), y1.max(hy));
            }
            if rest.is_empty() {
                return first;
            }
            let mut out = Mask::zeros(x0, y0, x1, y1);
            for m in std::iter::once(&first).chain(&rest) {
                or_into(&mut out, m);
            }
            out
        }
        Op::Intersection => {
            let mut acc = first;
            for m in it {
                acc = and(&acc, &m);
            }
            acc
        }
        Op::Difference => {
            let mut acc = first;
            for m in it {
                if acc.is_empty() {
                    break;
                }
                clear_where(&mut acc, &m);
            }
            acc.trimmed()
        }
    }
}

fn or_into(out: &mut Mask, m: &Mask) {
    if m.is_empty() {
        return;
    }
    for y in 0..m.h {
        let from = (m.y0 + y as i64 - out.y0) as usize * out.w + (m.x0 - out.x0) as usize;
        let row = &m.bits[y * m.w..(y + 1) * m.w];
        for (o, &b) in out.bits[from..from + m.w].iter_mut().zip(row) {
            *o |= b;
        }
    }
}

fn and(a: &Mask, b: &Mask) -> Mask {
    if a.is_empty() || b.is_empty() {
        return Mask::empty();
    }
    let ((ax1, ay1), (bx1, by1)) = (a.hi(), b.hi());
    let (x0, y0) = (a.x0.max(b.x0), a.y0.max(b.y0));
    let (x1, y1) = (ax1.min(bx1), ay1.min(by1));
    let mut out = Mask::zeros(x0, y0, x1, y1);
    if out.is_empty() {
        return out;
    }
    for y in y0..=y1 {
        for x in x0..=x1 {
            if a.get(x, y) && b.get(x, y) {
                out.bits[(y - y0) as usize * out.w + (x - x0) as usize] = true;
            }
        }
    }
    out.trimmed()
}

fn clear_where(acc: &mut Mask, m: &Mask) {
    if m.is_empty() {
        return;
    }
    let ((ax1, ay1), (mx1, my1)) = (acc.hi(), m.hi());
    for y in acc.y0.max(m.y0)..=ay1.min(my1) {
        for x in acc.x0.max(m.x0)..=ax1.min(mx1) {
            if m.get(x, y) {
                acc.bits[(y - acc.y0) as usize * acc.w + (x - acc.x0) as usize] = false;
            }
        }
    }
}

#[cfg(test)]
mod tests;
