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

/// Samples across the span (a pixel, or the distance between two layers' samples) in which
/// a cut side lies, in each pass that looks for it.
const FINE: usize = 32;

/// At most this many samples along a cut side in [`Probe::window`]'s pass.
const ALONG: usize = 4096;

impl PrintJob {
    /// The box of what the voxelizer lights, for a tree whose box may be larger than the
    /// part (a difference or intersection can cut its top or sides away): one pass on the
    /// printer's pixels and layers within `part`, and `part` cut to what it lit
    /// ([`PrintJob::cut_box`]).
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

    /// `part` cut to what `lit` lit when placed `at` with `k`×`k` samples a pixel: each side
    /// whose last unlit sample before the lit ones lies inside `part` ([`Lit::sides`]) found
    /// by [`Probe::side`], the top set for PrusaSlicer's layer count over the new floor
    /// ([`PrintJob::top`]). Elsewhere the side stays: the part reaches it, as far as the
    /// samples can tell.
    pub(super) fn cut_box(
        &self,
        (vjob, loaded): (&VoxelizeJob, &Loaded),
        part: Box3,
        (at, k): (&place::Placement, usize),
        lit: &Lit,
    ) -> crate::Result<Box3> {
        let (mut lo, mut hi) = part;
        let probe = Probe {
            job: self,
            vjob,
            loaded,
            at,
            k,
            lit,
        };
        for side in lit.sides(part, at, &self.printer, k) {
            let edge = probe.side(&side)?;
            match side.low {
                true => lo[side.axis] = edge,
                false => hi[side.axis] = edge,
            }
        }
        if let Some((_, l1)) = lit.l.filter(|l| l.1 + 1 < at.layers) {
            hi.z = self.top(vjob, loaded, at, l1, lo.z)?;
        }
        Ok((lo, hi))
    }

    /// The top of a part whose highest lit layer was `l1` when placed `at`, for a part
    /// standing on `floor`: the top of the highest layer over `floor` that the part reaches
    /// (PrusaSlicer counts the layers from the part's height, a top thinner than a layer
    /// not printed). The part's top lies below layer `l1 + 1`'s sample, which it did not
    /// reach; one slab just below the highest layer top under that says whether it
    /// reaches it, else it reaches the one below (it reached layer `l1`'s sample).
    fn top(
        &self,
        vjob: &VoxelizeJob,
        loaded: &Loaded,
        at: &place::Placement,
        l1: usize,
        floor: f64,
    ) -> crate::Result<f64> {
        let p = &self.printer;
        let above = at.floor + place::sample_height(p, l1 + 1);
        let layer_top = |l: f64| floor + p.initial_layer_height + l * p.layer_height;
        let l = ((above - layer_top(0.0)) / p.layer_height).floor().max(0.0);
        if self.lit_at(vjob, loaded, at, layer_top(l) - 1e-6 * p.layer_height)? {
            return Ok(layer_top(l));
        }
        // Below the first layer's top: one layer, whatever the height.
        Ok((layer_top(l - 1.0)).max(floor + p.initial_layer_height / 2.0))
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

    /// The sides of `part` the samples lit when placed `at` stop short of, each with the
    /// span it lies in: from the last unlit sample, inside `part`, to the first lit one
    /// (along X and Y the pixel's samples, `k` a pixel; along Z the floor only: the top is
    /// [`PrintJob::top`]'s).
    fn sides(&self, (lo, hi): Box3, at: &place::Placement, p: &Printer, k: usize) -> Vec<Side> {
        let (Some(i), Some(j), Some(l)) = (self.i, self.j, self.l) else {
            return vec![];
        };
        let [fw, fh] = at.pixels();
        let [px, py] = p.pitch();
        let x = |i: usize| (f64::from(at.i.0) + i as f64) * px - at.shift.x;
        let y = |j: usize| (f64::from(at.j.0) + j as f64) * py - at.shift.y;
        let (hx, hy) = (px / (2 * k) as f64, py / (2 * k) as f64);
        let sample = |l: usize| at.floor + place::sample_height(p, l);
        let mut spans = vec![];
        if i.0 > 0 {
            spans.push((0, true, (x(i.0) - hx, x(i.0 + 1) - hx)));
        }
        if i.1 + 1 < fw {
            spans.push((0, false, (x(i.1) + hx, x(i.1 + 1) + hx)));
        }
        if j.0 > 0 {
            spans.push((1, true, (y(j.0) - hy, y(j.0 + 1) - hy)));
        }
        if j.1 + 1 < fh {
            spans.push((1, false, (y(j.1) + hy, y(j.1 + 1) + hy)));
        }
        if l.0 > 0 {
            spans.push((2, true, (sample(l.0 - 1), sample(l.0))));
        }
        spans
            .into_iter()
            .filter(|&(axis, low, (a, b))| match low {
                true => a > lo[axis],
                false => b < hi[axis],
            })
            .map(|(axis, low, span)| Side { axis, low, span })
            .collect()
    }
}

/// A side of the part's box that the samples stop short of: its axis (0, 1, 2: X, Y, Z),
/// whether it is the low one, and the span it lies in, from the unlit sample to the lit
/// one.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Side {
    axis: usize,
    low: bool,
    span: (f64, f64),
}

/// What a pass over a side's span needs: the print, the scene, the placement and samples
/// a pixel that found the side, and what they lit.
struct Probe<'a> {
    job: &'a PrintJob,
    vjob: &'a VoxelizeJob,
    loaded: &'a Loaded,
    at: &'a place::Placement,
    k: usize,
    lit: &'a Lit,
}

impl Probe<'_> {
    /// Where `side` lies. A first pass puts [`FINE`] samples across its span, along the
    /// other axes the samples and layers that were lit, and narrows the span to two
    /// neighbouring samples, one unlit and one lit. Where the side is a corner or a tip
    /// (a gear's tooth, a hexagon's corner) it may lie between the samples along, up to
    /// half a sample further out: a second pass ([`Probe::window`]) looks again, finer,
    /// around where the first saw it. The side is the middle of the last span.
    fn side(&self, side: &Side) -> crate::Result<f64> {
        let grids = self.grids(side.axis);
        let Some((span, along)) = self.pass(side, side.span, &grids)? else {
            return Ok((side.span.0 + side.span.1) / 2.0);
        };
        let Some(window) = along.and_then(|r| self.window(side, span, r, &grids)) else {
            return Ok((span.0 + span.1) / 2.0);
        };
        let (a, b) = match self.pass(side, window.0, &window.1)? {
            Some((span, _)) => span,
            None => span,
        };
        Ok((a + b) / 2.0)
    }

    /// The second look at a side along X or Y that the first pass narrowed to `span` and
    /// saw lit at the samples `r` along (of `grids`): a pixel across, out from the lit
    /// sample, by [`FINE`] samples along for each of the first pass's, over the samples `r`
    /// and one either side (at most [`ALONG`]).
    fn window(
        &self,
        side: &Side,
        span: (f64, f64),
        r: (usize, usize),
        grids: &[GridBox],
    ) -> Option<((f64, f64), Vec<GridBox>)> {
        let axis = side.axis;
        if axis > 1 {
            return None;
        }
        let along = 1 - axis;
        let pitch = self.job.printer.pitch()[axis];
        let across = match side.low {
            true => (span.1 - pitch, span.1),
            false => (span.0, span.0 + pitch),
        };
        let grids = grids
            .iter()
            .map(|&(mut lo, mut hi, mut dims)| {
                let step = (hi[along] - lo[along]) / dims[along] as f64;
                let first = lo[along] + (r.0 as f64 - 0.5) * step;
                hi[along] = lo[along] + (r.1 as f64 + 1.5) * step;
                lo[along] = first;
                dims[along] = (FINE * (r.1 - r.0 + 2)).min(ALONG);
                (lo, hi, dims)
            })
            .collect();
        Some((across, grids))
    }

    /// One pass over `span` across `side` with [`FINE`] samples, the other axes as in
    /// `grids`: the span narrowed to the two neighbouring samples the side lies between
    /// (the span's ends count as samples: unlit at the low side's start, lit at its end,
    /// the other way round for a high side) and the samples along that lit the first lit
    /// one; None when a plane of the scene does not fit the depth word on these grids.
    fn pass(
        &self,
        side: &Side,
        (a, b): (f64, f64),
        grids: &[GridBox],
    ) -> crate::Result<Option<Narrowed>> {
        let mut seen: Vec<Option<(usize, usize)>> = vec![None; FINE];
        for &(lo, hi, dims) in grids {
            let (mut lo, mut hi, mut dims) = (lo, hi, dims);
            (lo[side.axis], hi[side.axis], dims[side.axis]) = (a, b, FINE);
            let grid =
                Grid::new(dims, lo, hi).map_err(|e| Error::from(csgpix_voxel::Error::from(e)))?;
            let Some(lit) = self.lit_along(side.axis, grid)? else {
                return Ok(None);
            };
            for (s, l) in seen.iter_mut().zip(lit) {
                if let Some((r0, r1)) = l {
                    *s = widen(*s, r0, r1);
                }
            }
        }
        let n = FINE as i64;
        let d = (b - a) / FINE as f64;
        let at = |q: i64| match q {
            -1 => a,
            q if q == n => b,
            q => a + (q as f64 + 0.5) * d,
        };
        let lit = |q: i64| seen.get(q as usize).copied().flatten();
        let q = match side.low {
            true => seen
                .iter()
                .position(Option::is_some)
                .map_or(n, |q| q as i64),
            false => seen
                .iter()
                .rposition(Option::is_some)
                .map_or(-1, |q| q as i64),
        };
        let span = match side.low {
            true => (at(q - 1), at(q)),
            false => (at(q), at(q + 1)),
        };
        Ok(Some((span, (0..n).contains(&q).then(|| lit(q)).flatten())))
    }

    /// The boxes and samples of the lit pixels (`k` a pixel) and layers, one per run of
    /// evenly spaced layers (the first is one of its own when it is not as high); along Z
    /// one slab when `axis` is Z (the caller sets that axis).
    fn grids(&self, axis: usize) -> Vec<GridBox> {
        let (Some(i), Some(j), Some(l)) = (self.lit.i, self.lit.j, self.lit.l) else {
            return vec![];
        };
        let p = &self.job.printer;
        let [px, py] = p.pitch();
        let at = self.at;
        let x = |i: usize| (f64::from(at.i.0) + i as f64) * px - at.shift.x;
        let y = |j: usize| (f64::from(at.j.0) + j as f64) * py - at.shift.y;
        let dims = |n: usize| [(i.1 + 1 - i.0) * self.k, (j.1 + 1 - j.0) * self.k, n];
        let box_at = |z0: f64, z1: f64| {
            (
                DVec3::new(x(i.0), y(j.0), z0),
                DVec3::new(x(i.1 + 1), y(j.1 + 1), z1),
            )
        };
        if axis == 2 {
            let (lo, hi) = box_at(0.0, 1.0);
            return vec![(lo, hi, dims(1))];
        }
        super::layer_runs(p, l.0..l.1 + 1)
            .into_iter()
            .map(|layers| {
                let [lo, hi] = at.grid(p, layers.clone());
                let (lo, hi) = box_at(lo.z, hi.z);
                (lo, hi, dims(layers.len()))
            })
            .collect()
    }

    /// For each sample across (along `axis`) of `grid`, the first and last samples along
    /// (the other axis of X and Y) that the part lights there, in the exact float model
    /// (as [`PrintJob::lit_at`]); None when a plane of the scene does not fit the depth
    /// word on a grid that fine or placed there.
    fn lit_along(&self, axis: usize, grid: Grid) -> crate::Result<Option<Vec<Lit1>>> {
        match self.sweep_lit(axis, grid) {
            Ok(seen) => Ok(Some(seen)),
            Err(Error::Voxel(
                csgpix_voxel::Error::Plane { .. }
                | csgpix_voxel::Error::Draw(csgpix_draw::Error::Solid { .. }),
            )) => Ok(None),
            Err(e) => Err(e),
        }
    }

    fn sweep_lit(&self, axis: usize, grid: Grid) -> crate::Result<Vec<Lit1>> {
        let [w, _, slabs] = grid.dims;
        let mut exact = self.vjob.clone();
        exact.voxels.model = csgpix_draw::Model::Float;
        let plan = exact.plan_on(self.loaded, grid)??;
        let need = plan.budget(self.vjob, &self.loaded.scene)?.need;
        self.job
            .max_memory
            .check(need, "this print", "raise --max-memory")?;
        let mut seen: Vec<Lit1> = vec![None; grid.dims[axis]];
        sweep_plan(self.vjob, &plan, 0..slabs, |z: usize, s: &[u8]| {
            for (r, row) in s.chunks_exact(w).enumerate() {
                let Some(a) = row.iter().position(|&v| v != 0) else {
                    continue;
                };
                let b = row.iter().rposition(|&v| v != 0).unwrap_or(a);
                match axis {
                    0 => (a..=b)
                        .filter(|&x| row[x] != 0)
                        .for_each(|x| seen[x] = widen(seen[x], r, r)),
                    1 => seen[r] = widen(seen[r], a, b),
                    _ => seen[z] = widen(seen[z], 0, 0),
                }
            }
            Ok::<(), csgpix_voxel::Error>(())
        })?;
        Ok(seen)
    }
}

/// A voxelizer grid's box and samples along X, Y and Z.
type GridBox = (DVec3, DVec3, [usize; 3]);

/// A span narrowed by a pass, and the samples along that lit its side.
type Narrowed = ((f64, f64), Option<(usize, usize)>);

/// The first and last samples lit along a line of samples, if any.
type Lit1 = Option<(usize, usize)>;

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
