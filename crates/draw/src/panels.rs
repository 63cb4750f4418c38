//! A scene on panels (§2.5): what eq. 2.5's even-distribution assumption cannot give.
//!
//! The screen S_n × S_m is tiled by n × m panels, each its own pixel-processor array running
//! in parallel. A primitive goes to every panel its screen footprint touches (the bounding box
//! of its projected silhouette, clamped to the screen, §2.5: "Primitives that fall into more
//! than one region must be processed in the corresponding panels"). A panel's program is the
//! scene's program compiled from the primitives binned to it only (the CSG tree with every
//! other solid replaced by nothing, which is exact inside the panel), its coefficients moved
//! to the panel's origin; its clocks are counted by the rtl-model
//! ([`rtl_model::array::program_cycles`], equal to running it, tested), not by a formula.
//! The frame takes as long as the slowest panel.
//!
//! Slices (§5.5, eq. 5.1): one slice of the scene costs, on each panel, one P·Vz frame per
//! primitive binned there (§4.4, as `csgpix voxelize` draws them: the solid's faces and
//! silhouette planes, clipped by a slab), slices cut perpendicular to the view direction.

use std::collections::HashMap;

use rtl_model::array::program_cycles;
use rtl_model::program::Op;
use rtl_model::{ArrayConfig, EquationSet, WordFormat};
use serde::Serialize;

use crate::compile::clip_scene_ops;
use crate::project::{clip_of, closed_list, max_slope, project, Frame, View, DEPTH_MARGIN};
use csgpix_scene::clip_expr::Clip;
use csgpix_scene::display_list::DisplayList;
use csgpix_scene::solid::{CsgNode, CsgScene};

use crate::{Error, Result};

/// An inclusive pixel rectangle: x0, y0, x1, y1.
pub type Rect = (usize, usize, usize, usize);

/// A scene projected onto the whole screen, ready to be cut into panels.
pub struct PanelScene {
    /// The screen, S_n × S_m pixels (§2.5).
    pub screen: (usize, usize),
    /// The depth word of every panel.
    pub fmt: WordFormat,
    /// One display list per solid, in screen coordinates (as `render` draws them).
    pub lists: Vec<DisplayList>,
    /// The same with the silhouette planes `voxelize` adds, for P·Vz frames.
    pub slice_lists: Vec<DisplayList>,
    /// Each solid's footprint on the screen (None: it projects outside or to nothing).
    pub footprints: Vec<Option<Rect>>,
    root: CsgNode,
}

impl PanelScene {
    /// Project `scene` in `view` onto an S_n × S_m screen with depth word `fmt` (the scene's
    /// bounds fill the screen, as in `render`).
    pub fn new(
        scene: &CsgScene,
        view: View,
        screen: (usize, usize),
        fmt: WordFormat,
    ) -> Result<PanelScene> {
        let (w, h) = screen;
        // The lists `render` draws (with the outline planes projection adds where the screen
        // rule would draw a solid beside itself), and for slices the faces with every
        // silhouette plane, as `voxelize` draws them.
        let lists = project(scene, view, w, h, &fmt)?.lists;
        let frame = Frame::fit(scene, view, w, h)?;
        let slope = max_slope(&fmt, w, h);
        let slice_lists = (scene.solids.iter().enumerate())
            .map(|(i, s)| closed_list(&frame, i, s, slope))
            .collect();
        // A tree that simplifies to nothing (a difference from an empty solid) draws no
        // solid: no panel lists any.
        let footprints = match lists.is_empty() {
            true => vec![],
            false => scene
                .solids
                .iter()
                .map(|s| footprint(&frame, &s.vertices, screen))
                .collect(),
        };
        Ok(PanelScene {
            screen,
            fmt,
            lists,
            slice_lists,
            footprints,
            root: scene.root.clone(),
        })
    }

    /// Surfaces (planes) of every solid: the N_s of eq. 5.1 summed over the scene.
    pub fn surfaces(&self) -> usize {
        self.lists.iter().map(|l| l.planes.len()).sum()
    }

    /// The program drawing the solids in `present` (the rest are nothing), in screen
    /// coordinates; empty when the tree leaves nothing to draw.
    pub fn frame_ops(&self, present: &[bool]) -> Result<Vec<Op>> {
        let Some(clip) = clip_of(&restrict(&self.root, present)) else {
            return Ok(vec![]);
        };
        let colour_bits = colour_bits(&self.fmt);
        clip_scene_ops(&self.lists, &clip, &self.fmt, colour_bits).map_err(|(solid, error)| {
            match error.field {
                crate::compile::WHOLE_PROGRAM => Error::Clip(error),
                _ => Error::Solid { solid, error },
            }
        })
    }

    /// The P·Vz program of solid `prim` (§4.4, §5.2.1: @(P)·Vz + @(Vz)·P) for a slab one
    /// depth unit thick; every slab's program has the same operations, so the same clocks.
    pub fn slice_ops(&self, prim: usize) -> Result<Vec<Op>> {
        let colour = self.slice_lists[prim]
            .planes
            .first()
            .map_or(1, |p| p.colour);
        let lists = [
            self.slice_lists[prim].clone(),
            DisplayList::slab(DEPTH_MARGIN, DEPTH_MARGIN + 1.0, colour),
        ];
        let expr = Clip::And(Box::new(Clip::Obj(0)), Box::new(Clip::Obj(1)));
        clip_scene_ops(&lists, &expr, &self.fmt, colour_bits(&self.fmt))
            .map_err(|(_, error)| Error::Solid { solid: prim, error })
    }

    /// The configuration of one n × m panel's array.
    pub fn panel_config(&self, panel: (usize, usize)) -> ArrayConfig {
        let mut cfg = ArrayConfig::new(panel.0, panel.1);
        cfg.fmt = self.fmt;
        cfg.colour_bits = colour_bits(&self.fmt);
        cfg
    }
}

/// Colour register width for a word (as `ArrayArgs::config`: at most N_D).
fn colour_bits(fmt: &WordFormat) -> u32 {
    ArrayConfig::new(1, 1).colour_bits.min(fmt.bits())
}

/// The pixels the bounding box of the projected vertices covers, widened to whole pixels and
/// clamped to the screen (pixel centres at integer coordinates, as DEPGEN evaluates them).
pub fn footprint(frame: &Frame, vertices: &[[f64; 3]], screen: (usize, usize)) -> Option<Rect> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for v in vertices {
        let p = frame.to_pixel(glam::DVec3::from(*v));
        lo = [lo[0].min(p.x), lo[1].min(p.y)];
        hi = [hi[0].max(p.x), hi[1].max(p.y)];
    }
    let clamp = |lo: f64, hi: f64, n: usize| -> Option<(usize, usize)> {
        let (a, b) = (lo.floor().max(0.0), hi.ceil().min(n as f64 - 1.0));
        (lo.is_finite() && a <= b).then_some((a as usize, b as usize))
    };
    let (x0, x1) = clamp(lo[0], hi[0], screen.0)?;
    let (y0, y1) = clamp(lo[1], hi[1], screen.1)?;
    Some((x0, y0, x1, y1))
}

/// The CSG tree with every solid not in `present` replaced by nothing. Walks with an explicit
/// stack (no recursion), as [`clip_of`] does.
pub fn restrict(root: &CsgNode, present: &[bool]) -> CsgNode {
    enum Task<'a> {
        Visit(&'a CsgNode),
        Build(&'a CsgNode, usize),
    }
    let mut tasks = vec![Task::Visit(root)];
    let mut out: Vec<CsgNode> = vec![];
    while let Some(t) = tasks.pop() {
        match t {
            Task::Visit(CsgNode::Solid(i)) if present.get(*i) == Some(&true) => {
                out.push(CsgNode::Solid(*i))
            }
            Task::Visit(CsgNode::Solid(_) | CsgNode::Empty) => out.push(CsgNode::Empty),
            Task::Visit(n) => {
                let c = n.children();
                tasks.push(Task::Build(n, c.len()));
                tasks.extend(c.iter().rev().map(Task::Visit));
            }
            Task::Build(n, k) => {
                let kids = out.split_off(out.len() - k);
                out.push(match n {
                    CsgNode::Union(_) => CsgNode::Union(kids),
                    CsgNode::Intersection(_) => CsgNode::Intersection(kids),
                    CsgNode::Difference(_) => CsgNode::Difference(kids),
                    _ => CsgNode::Complement(Box::new(
                        kids.into_iter().next().unwrap_or(CsgNode::Empty),
                    )),
                });
            }
        }
    }
    out.pop().unwrap_or(CsgNode::Empty)
}

pub use rtl_model::program::translate;

/// One panel of the tiling and what it does for a frame and a slice.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PanelWork {
    /// Column and row of the panel in the tiling.
    pub col: usize,
    /// Row of the panel in the tiling (see `col`).
    pub row: usize,
    /// Solids binned to it (0-based, file order).
    pub prims: Vec<usize>,
    /// Clocks of its frame program.
    pub frame_cycles: u64,
    /// Clocks of one slice: the P·Vz frames of its solids.
    pub slice_cycles: u64,
}

/// n × m panels tiling the screen: columns, rows (the last ones may hang over the edge).
pub fn tiling(screen: (usize, usize), panel: (usize, usize)) -> (usize, usize) {
    (screen.0.div_ceil(panel.0), screen.1.div_ceil(panel.1))
}

/// A panel cut to the screen: at most the screen on each side.
pub fn clamp_panel(panel: (usize, usize), screen: (usize, usize)) -> (usize, usize) {
    (panel.0.min(screen.0), panel.1.min(screen.1))
}

/// The solids whose footprint touches each panel, row-major.
pub fn bins(
    footprints: &[Option<Rect>],
    screen: (usize, usize),
    panel: (usize, usize),
) -> Vec<Vec<usize>> {
    let (cols, rows) = tiling(screen, panel);
    let mut out = vec![vec![]; cols * rows];
    for (i, f) in footprints.iter().enumerate() {
        let Some((x0, y0, x1, y1)) = *f else { continue };
        for r in y0 / panel.1..=y1 / panel.1 {
            for c in x0 / panel.0..=x1 / panel.0 {
                out[r * cols + c].push(i);
            }
        }
    }
    out
}

/// Clocks of a program on an array, by a counter: [`program_cycles`] or a run of a model.
pub type Counter<'a> = dyn Fn(&ArrayConfig, &[Op]) -> Result<u64> + 'a;

/// The rtl-model's count of a program's clocks (equal to running it on either model, with
/// either equation set).
pub fn count_cycles(cfg: &ArrayConfig, ops: &[Op]) -> Result<u64> {
    Ok(program_cycles(cfg, ops))
}

/// The most panels a tiling may have (each holds a list of solids): 2^22.
pub const MAX_PANELS: usize = 1 << 22;

/// Every panel's work for n × m panels. Panels with the same solids share one compile and
/// one count (their programs differ only in Z0).
pub fn panel_work(
    ps: &PanelScene,
    panel: (usize, usize),
    count: &Counter,
) -> Result<Vec<PanelWork>> {
    let (cols, rows) = tiling(ps.screen, panel);
    if cols * rows > MAX_PANELS {
        return Err(Error::TooManyPanels {
            cols,
            rows,
            panel,
            limit: MAX_PANELS,
        });
    }
    let cfg = ps.panel_config(panel);
    let slice: Vec<u64> = (0..ps.lists.len())
        .map(|p| count(&cfg, &ps.slice_ops(p)?))
        .collect::<Result<_>>()?;
    let mut cache: HashMap<Vec<usize>, u64> = HashMap::new();
    let mut out = vec![];
    for (k, prims) in bins(&ps.footprints, ps.screen, panel)
        .into_iter()
        .enumerate()
    {
        let frame_cycles = match cache.get(&prims) {
            Some(&c) => c,
            None => {
                let c = count(&cfg, &ps.frame_ops(&presence(&prims, ps.lists.len()))?)?;
                *cache.entry(prims.clone()).or_insert(c)
            }
        };
        out.push(PanelWork {
            col: k % cols,
            row: k / cols,
            slice_cycles: prims.iter().map(|&p| slice[p]).sum(),
            prims,
            frame_cycles,
        });
    }
    Ok(out)
}

/// A membership vector of `n` solids from a list.
pub fn presence(prims: &[usize], n: usize) -> Vec<bool> {
    let mut v = vec![false; n];
    for &p in prims {
        v[p] = true;
    }
    v
}

/// A scene's frame and slice rates on n × m panels, measured and by the formula.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SceneEstimate {
    /// The panel, n × m pixels.
    pub panel: (usize, usize),
    /// Panels tiling the screen (columns × rows).
    pub panels: usize,
    /// Panels with at least one solid binned.
    pub touched: usize,
    /// Solids summed over panels: how often solids are processed, duplicates included.
    pub binned: usize,
    /// Most solids on one panel.
    pub max_solids: usize,
    /// Column and row of the slowest panel for a frame.
    pub slowest: (usize, usize),
    /// Clocks of the slowest panel's frame: the frame's clocks.
    pub frame_cycles: u64,
    /// Seconds of the frame at the clock period t (§2.5).
    pub frame_s: f64,
    /// Frames per second.
    pub fps: f64,
    /// Clocks of the slowest panel's slice.
    pub slice_cycles: u64,
    /// Slices per second (§4.4: one P·Vz program a slice).
    pub slices_per_s: f64,
    /// Eq. 2.5 (Table 2.1 reading): the scene's surfaces spread evenly over S_n·S_m/(n·m)
    /// panels at N_D clocks each.
    pub formula_frame_s: f64,
    /// Frames per second by eq. 2.5.
    pub formula_fps: f64,
    /// Eq. 5.1 with P_R = the panels' surfaces per second (eq. 2.5 × 1/t) and N_s = the
    /// scene's surfaces.
    pub formula_slices_per_s: f64,
    /// The whole screen's own program (one array, `one_array_cycles`) split evenly over the
    /// panels: eq. 2.5's assumption with the program's real clocks instead of N_D per surface.
    pub even_split_fps: f64,
}

/// Sum up `work` (from [`panel_work`]) against the formula for hardware `hw`;
/// `one_array_cycles` is the whole scene's program on one screen-sized array.
pub fn estimate(
    ps: &PanelScene,
    hw: &crate::throughput::Hardware,
    panel: (usize, usize),
    work: &[PanelWork],
    one_array_cycles: u64,
) -> SceneEstimate {
    use crate::throughput::{panel_ratio, slices_per_second, surfaces_per_second};
    let slowest = work
        .iter()
        .max_by_key(|w| (w.frame_cycles, std::cmp::Reverse((w.row, w.col))))
        .map_or((0, 0), |w| (w.col, w.row));
    let frame_cycles = work.iter().map(|w| w.frame_cycles).max().unwrap_or(0);
    let slice_cycles = work.iter().map(|w| w.slice_cycles).max().unwrap_or(0);
    let panels_per_screen = panel_ratio(ps.screen, panel);
    let surfaces = ps.surfaces() as f64;
    let formula_frame_s = surfaces * hw.bits as f64 * hw.period() / panels_per_screen;
    SceneEstimate {
        panel,
        panels: work.len(),
        touched: work.iter().filter(|w| !w.prims.is_empty()).count(),
        binned: work.iter().map(|w| w.prims.len()).sum(),
        max_solids: work.iter().map(|w| w.prims.len()).max().unwrap_or(0),
        slowest,
        frame_cycles,
        frame_s: frame_cycles as f64 * hw.period(),
        fps: hw.clock_hz / frame_cycles as f64,
        slice_cycles,
        slices_per_s: hw.clock_hz / slice_cycles as f64,
        formula_frame_s,
        formula_fps: 1.0 / formula_frame_s,
        formula_slices_per_s: slices_per_second(
            panels_per_screen * surfaces_per_second(hw),
            surfaces,
        ),
        even_split_fps: hw.clock_hz * panels_per_screen / one_array_cycles as f64,
    }
}

/// What the panels draw for a frame, stitched into the screen.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PanelImage {
    /// Per screen pixel, row-major: the colour code in G and the depth word in C.
    pub colour: Vec<u32>,
    /// Per screen pixel, row-major: the depth word in C.
    pub depth: Vec<i64>,
    /// Panels whose program draws anything, and so were simulated.
    pub simulated_panels: usize,
    /// Σ over simulated panels of the panel's pixels × its program's clocks.
    pub simulated_pixel_clocks: u64,
    /// The slowest panel's clocks: the frame on the panelled hardware.
    pub slowest_cycles: u64,
}

/// Draw a frame the panelled way: each panel runs its own program (only its binned solids,
/// moved to its origin, [`PanelScene::frame_ops`] and [`translate`]) on its own array of the
/// `cycle` or `word` model; a panel whose program is empty is left as reset. Equal to the
/// whole screen's image pixel for pixel (tests/panels_render.rs) while simulating only the
/// panels the scene touches. A panel wider or taller than the screen is cut to it: the
/// pixels past the screen are never shown, and would only cost memory and clocks.
pub fn render_on_panels(
    ps: &PanelScene,
    panel: (usize, usize),
    cycle: bool,
    set: &EquationSet,
) -> Result<PanelImage> {
    use rtl_model::program::{CReg, Reg};
    use rtl_model::{Array, CycleArray, WordArray};
    let (w, h) = ps.screen;
    let panel = clamp_panel(panel, ps.screen);
    let cfg = ps.panel_config(panel);
    let reset = CycleArray::new(ps.panel_config((1, 1)), set.clone())
        .state()
        .pixels[0];
    let mut img = PanelImage {
        colour: vec![reset.creg(CReg::G); w * h],
        depth: vec![reset.reg(Reg::C); w * h],
        simulated_panels: 0,
        simulated_pixel_clocks: 0,
        slowest_cycles: 0,
    };
    let (cols, _) = tiling(ps.screen, panel);
    // Panels with the same solids run the same program, moved: compile it once.
    let mut compiled: HashMap<Vec<usize>, Vec<Op>> = HashMap::new();
    for (k, prims) in bins(&ps.footprints, ps.screen, panel)
        .into_iter()
        .enumerate()
    {
        let (x0, y0) = (k % cols * panel.0, k / cols * panel.1);
        let mut ops = match compiled.get(&prims) {
            Some(ops) => ops.clone(),
            None => {
                let ops = ps.frame_ops(&presence(&prims, ps.lists.len()))?;
                compiled.entry(prims).or_insert(ops).clone()
            }
        };
        if ops.is_empty() {
            continue;
        }
        translate(&mut ops, x0, y0);
        let mut arr: Box<dyn Array> = if cycle {
            Box::new(CycleArray::new(cfg, set.clone()))
        } else {
            Box::new(WordArray::new(cfg, set.clone()))
        };
        arr.run(&ops)?;
        for y in 0..panel.1.min(h - y0) {
            for x in 0..panel.0.min(w - x0) {
                let p = arr.pixel(x, y);
                let i = (y0 + y) * w + x0 + x;
                (img.colour[i], img.depth[i]) = (p.creg(CReg::G), p.reg(Reg::C));
            }
        }
        img.simulated_panels += 1;
        img.simulated_pixel_clocks += arr.cycles() * cfg.pixels() as u64;
        img.slowest_cycles = img.slowest_cycles.max(arr.cycles());
    }
    Ok(img)
}
