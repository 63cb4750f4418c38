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
    /// part (a difference or intersection can cut its top or sides away): what the print's
    /// samples (`k` a pixel) would light with the part placed on `part` ([`Scan::lit`]),
    /// and `part` cut to that ([`PrintJob::cut_box`]). Found before the print, so that the
    /// print is made once, where the part sits.
    pub(super) fn lit_box(
        &self,
        vjob: &VoxelizeJob,
        loaded: &Loaded,
        part: Box3,
        k: usize,
    ) -> crate::Result<Box3> {
        let placed = self.place(vjob, part)?;
        let scan = Scan {
            job: self,
            vjob,
            loaded,
            at: &placed,
            k,
        };
        let lit = scan.lit()?;
        self.cut_box((vjob, loaded), part, (&placed, k), &lit)
    }

    /// The voxelizer's plan on `grid` in the float model, within the memory limit: the
    /// looks at the part's box ask about the part itself (a side between two samples, a
    /// height below a layer's top), not about the depth word's rounding.
    fn float_plan(
        &self,
        vjob: &VoxelizeJob,
        loaded: &Loaded,
        grid: Grid,
    ) -> crate::Result<crate::voxelize::plan::Plan> {
        let mut exact = vjob.clone();
        exact.voxels.model = csgpix_draw::Model::Float;
        self.plan(&exact, loaded, grid)
    }

    /// `vjob`'s plan on `grid`, within the memory limit.
    fn plan(
        &self,
        vjob: &VoxelizeJob,
        loaded: &Loaded,
        grid: Grid,
    ) -> crate::Result<crate::voxelize::plan::Plan> {
        let plan = vjob.plan_on(loaded, grid)??;
        let need = plan.budget(vjob, &loaded.scene)?.need;
        self.max_memory
            .check(need, "this print", "raise --max-memory")?;
        Ok(plan)
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
        let plan = self.float_plan(vjob, loaded, grid)?;
        let mut any = false;
        sweep_plan(vjob, &plan, 0..1, |_: usize, s: &[u8]| {
            any |= s.iter().any(|&v| v != 0);
            Ok::<(), csgpix_voxel::Error>(())
        })?;
        Ok(any)
    }
}

/// Whether the tree's box ([`part_box`]) is the part's: no difference, intersection or
/// complement can cut it, in the tree or in a footprint's 2D tree.
pub(super) fn exact_box(loaded: &Loaded) -> bool {
    let solids = loaded.scene.solids.len();
    let leaf = |i: usize| {
        i < solids
            || loaded
                .sampled
                .get(i - solids)
                .is_none_or(|s| s.set_bounds_exact())
    };
    exact_node(&loaded.scene.root, &leaf)
}

fn exact_node(n: &CsgNode, leaf: &dyn Fn(usize) -> bool) -> bool {
    match n {
        CsgNode::Solid(i) => leaf(*i),
        CsgNode::Empty => true,
        CsgNode::Union(c) => c.iter().all(|c| exact_node(c, leaf)),
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
    /// Layer `l`'s samples `s`, rows `w` wide, whose first is column `x0` and row `y0`
    /// and which lie `step` columns and rows apart.
    fn add(&mut self, l: usize, s: &[u8], w: usize, (x0, y0, step): (usize, usize, usize)) {
        for (r, row) in s.chunks_exact(w.max(1)).enumerate() {
            let first = row.iter().position(|&v| v != 0);
            if let Some(a) = first {
                let b = row.iter().rposition(|&v| v != 0).unwrap_or(a);
                self.i = widen(self.i, x0 + a * step, x0 + b * step);
                self.j = widen(self.j, y0 + r * step, y0 + r * step);
                self.l = widen(self.l, l, l);
            }
        }
    }

    /// What either lit.
    fn join(&mut self, o: Lit) {
        let pairs = [(&mut self.i, o.i), (&mut self.j, o.j), (&mut self.l, o.l)];
        for (r, o) in pairs {
            if let Some((a, b)) = o {
                *r = widen(*r, a, b);
            }
        }
    }

    /// The pixels of samples lit `k` a pixel side.
    fn pixels(self, k: usize) -> Lit {
        let px = |r: Option<(usize, usize)>| r.map(|(a, b)| (a / k, b / k));
        Lit {
            i: px(self.i),
            j: px(self.j),
            l: self.l,
        }
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
        let x = |i: usize| at.edge(p, 0, i);
        let y = |j: usize| at.edge(p, 1, j);
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
        let at = self.at;
        let x = |i: usize| at.edge(p, 0, i);
        let y = |j: usize| at.edge(p, 1, j);
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
        fits(self.sweep_lit(axis, grid))
    }

    fn sweep_lit(&self, axis: usize, grid: Grid) -> crate::Result<Vec<Lit1>> {
        let [w, _, slabs] = grid.dims;
        let plan = self.job.float_plan(self.vjob, self.loaded, grid)?;
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

/// Samples apart, along X and Y, of [`Scan::lit`]'s first look.
const COARSE: usize = 8;

/// A look, before a print, at what its samples would light: the print's placement and
/// samples a pixel side, the scene.
struct Scan<'a> {
    job: &'a PrintJob,
    vjob: &'a VoxelizeJob,
    loaded: &'a Loaded,
    at: &'a place::Placement,
    k: usize,
}

/// Some of a print's samples: every `step`-th of the columns `x` and rows `y` (samples,
/// `k` a pixel side) in the layers `layers`.
#[derive(Clone, Debug)]
struct Region {
    x: std::ops::Range<usize>,
    y: std::ops::Range<usize>,
    layers: std::ops::Range<usize>,
    step: usize,
}

impl Region {
    fn is_empty(&self) -> bool {
        self.x.is_empty() || self.y.is_empty() || self.layers.is_empty()
    }

    /// Every `step`-th of its samples along X and Y, from the middle of the first `step`.
    fn every(&self, step: usize) -> Region {
        let from = |r: &std::ops::Range<usize>| r.start + (step / 2).min(r.len().saturating_sub(1));
        Region {
            x: from(&self.x)..self.x.end,
            y: from(&self.y)..self.y.end,
            layers: self.layers.clone(),
            step,
        }
    }

    /// Its samples along X and Y.
    fn dims(&self) -> [usize; 2] {
        [self.x.len(), self.y.len()].map(|n| n.div_ceil(self.step))
    }
}

impl Scan<'_> {
    /// The pixels and layers the print's samples light, in the float model. A first look
    /// takes every [`COARSE`]-th sample along X and Y, in every layer. What it lit can
    /// reach further out only by a feature that fits between its samples, so then every
    /// sample is looked at between each side of the box and the first look's outermost
    /// lit one, along X and along Y in every layer; along Z, in the layers below and above
    /// those lit so far, every second sample and then, in the layers still unlit beyond
    /// what that lit, every sample. The part's surface costs the first look a sample in 64
    /// and the strips along X and Y what the box holds outside the part; the layers along
    /// Z cost a look at the whole footprint, where the first look lit none of them (a
    /// chamfered or rounded bottom or top, a cut floor or top). Where the first look lit
    /// nothing, or a plane does not fit the depth word on a look's grid, every sample is
    /// looked at.
    fn lit(&self) -> crate::Result<Lit> {
        let [fw, fh] = self.at.pixels();
        let all = Region {
            x: 0..fw * self.k,
            y: 0..fh * self.k,
            layers: 0..self.at.layers,
            step: 1,
        };
        match self.sides_lit(&all)? {
            Some(lit) => Ok(lit.pixels(self.k)),
            None => self.everything(all),
        }
    }

    /// [`Scan::lit`]'s looks, in samples along X and Y; None when the first look lit
    /// nothing or a look's grid does not fit the word.
    fn sides_lit(&self, all: &Region) -> crate::Result<Option<Lit>> {
        let float = csgpix_draw::Model::Float;
        let Some(mut lit) = self.look(&all.every(COARSE), float)? else {
            return Ok(None);
        };
        let (Some(i), Some(j)) = (lit.i, lit.j) else {
            return Ok(None);
        };
        let (w, h) = (all.x.end, all.y.end);
        let strips = [
            Region {
                x: 0..i.0,
                ..all.clone()
            },
            Region {
                x: i.1 + 1..w,
                ..all.clone()
            },
            Region {
                y: 0..j.0,
                ..all.clone()
            },
            Region {
                y: j.1 + 1..h,
                ..all.clone()
            },
        ];
        for r in strips.iter().filter(|r| !r.is_empty()) {
            let Some(seen) = self.look(r, float)? else {
                return Ok(None);
            };
            lit.join(seen);
        }
        let Some(l) = lit.l else {
            return Ok(None);
        };
        for (low, mut rest) in [(true, 0..l.0), (false, l.1 + 1..all.layers.end)] {
            for step in [2, 1] {
                if rest.is_empty() {
                    break;
                }
                let r = Region {
                    layers: rest.clone(),
                    ..all.clone()
                };
                let Some(seen) = self.look(&r.every(step), float)? else {
                    return Ok(None);
                };
                lit.join(seen);
                if let Some((a, b)) = seen.l {
                    rest = match low {
                        true => rest.start..a,
                        false => b + 1..rest.end,
                    };
                }
            }
        }
        Ok(Some(lit))
    }

    /// Every sample's look, in the float model, or where a plane does not fit the word on
    /// that grid, in the print's own.
    fn everything(&self, all: Region) -> crate::Result<Lit> {
        let lit = match self.look(&all, csgpix_draw::Model::Float)? {
            Some(lit) => lit,
            None => self.look(&all, self.vjob.voxels.model)?.unwrap_or_default(),
        };
        Ok(lit.pixels(self.k))
    }

    /// What the samples of `r` light in `model`: sample indices along X and Y, layers
    /// along Z; None when a plane of the scene does not fit the depth word on its grid.
    fn look(&self, r: &Region, model: csgpix_draw::Model) -> crate::Result<Option<Lit>> {
        let p = &self.job.printer;
        let [fw, fh] = self.at.pixels();
        let [nx, ny] = r.dims();
        let mut vjob = self.vjob.clone();
        vjob.voxels.model = model;
        let mut lit = Lit::default();
        for layers in super::layer_runs(p, r.layers.clone()) {
            let [lo, hi] = self.at.grid(p, layers.clone());
            // The samples of X's `q`-th column and Y's row (of `fw`·k and `fh`·k) are
            // at lo + (q + ½)·d: a grid of every `step`-th from the range's start has
            // its cells `step`·d wide, the first centred on it.
            let axis = |lo: f64, hi: f64, n: usize, q: &std::ops::Range<usize>, m: usize| {
                let d = (hi - lo) / n as f64;
                let a = lo + (q.start as f64 + 0.5 - 0.5 * r.step as f64) * d;
                (a, a + (m * r.step) as f64 * d)
            };
            let (x0, x1) = axis(lo.x, hi.x, fw * self.k, &r.x, nx);
            let (y0, y1) = axis(lo.y, hi.y, fh * self.k, &r.y, ny);
            let grid = Grid::new(
                [nx, ny, layers.len()],
                DVec3::new(x0, y0, lo.z),
                DVec3::new(x1, y1, hi.z),
            )
            .map_err(|e| Error::from(csgpix_voxel::Error::from(e)))?;
            let swept = self.job.plan(&vjob, self.loaded, grid).and_then(|plan| {
                sweep_plan(&vjob, &plan, 0..layers.len(), |z: usize, s: &[u8]| {
                    lit.add(layers.start + z, s, nx, (r.x.start, r.y.start, r.step));
                    Ok::<(), Error>(())
                })
                .map(|_| ())
            });
            if fits(swept)?.is_none() {
                return Ok(None);
            }
        }
        Ok(Some(lit))
    }
}

/// `r`, or None when it failed because a plane does not fit the depth word on that grid.
fn fits<T>(r: crate::Result<T>) -> crate::Result<Option<T>> {
    match r {
        Ok(t) => Ok(Some(t)),
        Err(Error::Voxel(
            csgpix_voxel::Error::Plane { .. }
            | csgpix_voxel::Error::Draw(csgpix_draw::Error::Solid { .. }),
        )) => Ok(None),
        Err(e) => Err(e),
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
/// a primitive's its vertices' (an import's, its bounds; a footprint's, its 2D tree's).
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
                .map(|s| s.set_bounds()),
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
