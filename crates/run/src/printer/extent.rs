//! The part's box, on which it is placed: the tree's ([`part_box`]) where nothing can cut
//! it, else the box of what the voxelizer lights. A slicer centres a part on its mesh's box
//! and counts its layers from the mesh's height, so a side that a difference or
//! intersection cuts is found to a fraction of a pixel (of a layer along Z), not to the
//! pixel: a side off by a pixel moves the whole part by half of one.

use csgpix_scene::solid::CsgNode;
use csgpix_voxel::sampled::Loaded;
use csgpix_voxel::Grid;
use glam::DVec3;

use super::{place, sweep_plan, PrintJob, Printer};
use crate::voxelize::VoxelizeJob;
use crate::Error;

impl PrintJob {
    /// The box of what the voxelizer lights, for a tree whose box may be larger than the
    /// part (a difference or intersection can cut its top or sides away): one pass on the
    /// printer's pixels and layers within `part`, and `part` cut to the pixels and layers
    /// lit. Where the part reaches a side of `part` that side stays exact; elsewhere it is
    /// known to a pixel (a layer along Z).
    pub(super) fn lit_box(
        &self,
        vjob: &VoxelizeJob,
        loaded: &Loaded,
        part: Box3,
    ) -> crate::Result<Box3> {
        let placed = self.place(vjob, part)?;
        let passes = self.passes(vjob, loaded, &placed, 1)?;
        let need = passes.iter().map(|p| p.1).max().unwrap_or(0);
        self.max_memory
            .check(need, "this print", "raise --max-memory")?;
        let [fw, _] = placed.pixels();
        let mut lit = Lit::default();
        for (plan, _, layers) in &passes {
            sweep_plan(vjob, plan, 0..layers.len(), |k: usize, s: &[u8]| {
                lit.add(layers.start + k, s, fw);
                Ok::<(), csgpix_voxel::Error>(())
            })?;
        }
        self.cut_box((vjob, loaded), part, (&placed, 1), &lit)
    }

    /// `part` cut to the pixels and layers `lit` lit when placed `at`; its top a layer
    /// lower when the part does not reach the top layer's top (PrusaSlicer's count): one
    /// slab just below that top says whether it does.
    pub(super) fn cut_box(
        &self,
        (vjob, loaded): (&VoxelizeJob, &Loaded),
        part: Box3,
        (at, k): (&place::Placement, usize),
        lit: &Lit,
    ) -> crate::Result<Box3> {
        let (lo, mut hi) = lit.cut(part, at, &self.printer, k);
        let reach = hi.z - 1e-6 * self.printer.layer_height;
        if hi.z < part.1.z && !self.lit_at(vjob, loaded, at, reach)? {
            hi.z -= self.printer.layer_height;
        }
        Ok((lo, hi))
    }

    /// Whether anything of the part is at height `z` (scene units) over its placed pixels.
    fn lit_at(
        &self,
        vjob: &VoxelizeJob,
        loaded: &Loaded,
        placed: &place::Placement,
        z: f64,
    ) -> crate::Result<bool> {
        let [lo, hi] = placed.grid(&self.printer, 0..1);
        // One slab a layer high whose centre, where it samples, is at z.
        let half = self.printer.layer_height / 2.0;
        let (lo, hi) = (lo.with_z(z - half), hi.with_z(z + half));
        let grid = Grid::new([placed.pixels()[0], placed.pixels()[1], 1], lo, hi)
            .map_err(|e| Error::from(csgpix_voxel::Error::from(e)))?;
        // The float model: the word's depths are a 1/1024 of the slab apart, coarser
        // than the step below the top that this asks about.
        let mut exact = vjob.clone();
        exact.voxels.model = csgpix_draw::Model::Float;
        let plan = exact.plan_on(loaded, grid).map_err(Error::from)??;
        let mut any = false;
        sweep_plan(vjob, &plan, 0..1, |_: usize, s: &[u8]| {
            any |= s.iter().any(|&v| v != 0);
            Ok::<(), csgpix_voxel::Error>(())
        })?;
        Ok(any)
    }
}

/// Whether the tree's box ([`part_box`]) is the part's: no difference, intersection or
/// complement can cut it.
pub(super) fn exact_box(n: &CsgNode) -> bool {
    match n {
        CsgNode::Solid(_) | CsgNode::Empty => true,
        CsgNode::Union(c) => c.iter().all(exact_box),
        _ => false,
    }
}

/// The pixels and layers lit in a pass: first and last along X, Y and Z.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Lit {
    i: Option<(usize, usize)>,
    j: Option<(usize, usize)>,
    l: Option<(usize, usize)>,
}

fn widen(r: Option<(usize, usize)>, a: usize, b: usize) -> Option<(usize, usize)> {
    Some(r.map_or((a, b), |(x, y)| (x.min(a), y.max(b))))
}

impl Lit {
    /// Layer `l`'s samples `s`, rows `fw` wide.
    pub fn add(&mut self, l: usize, s: &[u8], fw: usize) {
        for (j, row) in s.chunks_exact(fw.max(1)).enumerate() {
            let first = row.iter().position(|&v| v != 0);
            if let Some(a) = first {
                let b = row.iter().rposition(|&v| v != 0).unwrap_or(a);
                self.i = widen(self.i, a, b);
                self.j = widen(self.j, j, j);
                self.l = widen(self.l, l, l);
            }
        }
    }

    /// Layer `l`, lit where the layer before it was.
    pub fn add_layer(&mut self, l: usize) {
        self.l = widen(self.l, l, l);
    }

    /// `part` cut to what was lit with `k`×`k` samples a pixel when placed `at`. A side the
    /// lit pixels reach to within a pixel of stays as it is: the part reaches it, as far as
    /// the samples can tell. A side they stop short of moves in to the last unlit sample
    /// before them (the part does not reach that far), half a sample outside the lit pixels:
    /// there the box is known to that half sample, along Z to a layer.
    fn cut(&self, (lo, hi): Box3, at: &place::Placement, p: &Printer, k: usize) -> Box3 {
        let (Some(i), Some(j), Some(l)) = (self.i, self.j, self.l) else {
            return (lo, hi);
        };
        let [fw, fh] = at.pixels();
        let [px, py] = p.pitch();
        let x = |i: usize| (f64::from(at.i.0) + i as f64) * px - at.shift.x;
        let y = |j: usize| (f64::from(at.j.0) + j as f64) * py - at.shift.y;
        let (hx, hy) = (px / (2 * k) as f64, py / (2 * k) as f64);
        let low = |first: usize, at: f64| if first <= 1 { f64::NEG_INFINITY } else { at };
        let high = |last: usize, n: usize, at: f64| if last + 2 >= n { f64::INFINITY } else { at };
        let sample = |l: usize| at.floor + place::sample_height(p, l);
        let a = DVec3::new(
            low(i.0, x(i.0) - hx),
            low(j.0, y(j.0) - hy),
            if l.0 == 0 {
                f64::NEG_INFINITY
            } else {
                sample(l.0 - 1)
            },
        );
        let top = at.floor + p.initial_layer_height + l.1 as f64 * p.layer_height;
        let b = DVec3::new(
            high(i.1, fw, x(i.1 + 1) + hx),
            high(j.1, fh, y(j.1 + 1) + hy),
            if l.1 + 1 >= at.layers {
                f64::INFINITY
            } else {
                top
            },
        );
        (lo.max(a), hi.min(b))
    }
}

/// The box of the part itself: a union's is its children's together, an intersection's
/// their overlap, a difference's its first child's (what is cut away cannot widen it);
/// a primitive's its vertices' (an import's, its bounds).
pub fn part_box(loaded: &Loaded) -> Result<(DVec3, DVec3), String> {
    let scene = &loaded.scene;
    let leaf = |i: usize| -> Option<(DVec3, DVec3)> {
        match scene.solids.get(i) {
            Some(s) => s.vertices.iter().fold(None, |b, v| {
                let v = DVec3::from(*v);
                Some(b.map_or((v, v), |(a, c): (DVec3, DVec3)| (a.min(v), c.max(v))))
            }),
            None => loaded
                .sampled
                .get(i - scene.solids.len())
                .map(|s| s.bounds()),
        }
    };
    match node_box(&scene.root, &leaf) {
        Some((lo, hi)) if lo.is_finite() && hi.is_finite() && (hi - lo).min_element() > 0.0 => {
            Ok((lo, hi))
        }
        _ => Err("the scene has no solid to print".into()),
    }
}

/// A box, scene units: its lowest and highest corners.
pub(super) type Box3 = (DVec3, DVec3);

fn node_box(n: &CsgNode, leaf: &dyn Fn(usize) -> Option<Box3>) -> Option<Box3> {
    let join = |a: Option<Box3>, b: Option<Box3>| match (a, b) {
        (Some(a), Some(b)) => Some((a.0.min(b.0), a.1.max(b.1))),
        (a, b) => a.or(b),
    };
    match n {
        CsgNode::Solid(i) => leaf(*i),
        CsgNode::Union(c) => c.iter().fold(None, |b, c| join(b, node_box(c, leaf))),
        CsgNode::Intersection(c) => {
            let mut it = c.iter().map(|c| node_box(c, leaf));
            let first = it.next()??;
            it.try_fold(first, |a, b| {
                let b = b?;
                let (lo, hi) = (a.0.max(b.0), a.1.min(b.1));
                (lo.cmple(hi).all()).then_some((lo, hi))
            })
        }
        CsgNode::Difference(c) => c.first().and_then(|c| node_box(c, leaf)),
        // Everything outside a solid has no box; the voxel grid cannot hold it.
        CsgNode::Complement(_) | CsgNode::Empty => None,
    }
}
