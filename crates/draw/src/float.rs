//! The `float` model: exact f64 geometry of the same plane sets, by ray casting. Not hardware;
//! the reference `word` and `cycle` are measured against.
//!
//! Along the ray of pixel (x, y) (depth z from the screen, §2.3.1), a convex display list
//! (L = 0) is the intersection of its half-spaces: behind every front plane (z ≥ Z), in front
//! of every back plane (z ≤ Z), on the inner side of every perpendicular plane (K ≥ 0). A
//! concave list (L = 1) is a void: the convex set its planes bound with the roles of front and
//! back exchanged, and what the array draws of it is its far wall, where the void ends in
//! material (§2.3.2, Figure 2.3). Objects are composed as the second stage does: the nearest
//! surface wins. A clipping function is evaluated as §5.2.1 defines its image, in exact
//! arithmetic: each literal's surface, kept inside the rest of its product, nearest wins. A
//! convex solid that contains the screen shows the screen (z = 0, interior colour). Nothing at
//! or beyond maxdepth is shown.

use rtl_model::WordFormat;

use crate::compile::INTERIOR_COLOUR;
use csgpix_scene::clip_expr::{Clip, Literal};
use csgpix_scene::display_list::DisplayList;

/// Which face bounds an interval: (object, plane), or none at ±infinity.
type Tag = Option<(usize, usize)>;

/// Disjoint, sorted intervals (lo, hi) of z, each end tagged with its face.
type Span = Vec<(f64, Tag, f64, Tag)>;

/// The float image and, per pixel, how close the hardware's decisions come to a tie.
#[derive(Clone, Debug)]
pub struct FloatImage {
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Visible depth, `None` for background.
    pub depth: Vec<Option<f64>>,
    /// Colour code per pixel (row-major), 0 for background.
    pub colour: Vec<u32>,
    /// The smallest gap, in depth units, between any two plane values at this pixel, or
    /// between a plane value and 0 or maxdepth: below twice the rounding bound the word model
    /// may decide a comparison the other way.
    pub margin: Vec<f64>,
    /// A face plane lies in front of the screen (Z < 0) here, so the rows of §2.3.3 for
    /// A < 0 decide. Some of them differ from the geometry: "A < 0 ≤ B: Put 1" on a convex
    /// back plane keeps the object where it has none, and a first back plane of a concave
    /// object (a complemented literal's front face) at Z < 0 puts 1 and hides the void.
    pub screen_rule: Vec<bool>,
}

fn value(p: &csgpix_scene::display_list::DlPlane, x: f64, y: f64) -> f64 {
    p.z0 + x * p.dzx + y * p.dzy
}

/// How a back plane in front of the screen (Z < 0) is treated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ScreenRule {
    /// Geometry: the solid ends there, so nothing of it lies behind the screen.
    Exact,
    /// §2.3.3 as printed: "A < 0 ≤ B: Put 1" puts maxdepth into B, so the back envelope is
    /// the smallest back plane after the last negative one in list order (infinite if none).
    Thesis,
}

/// The convex set a list's planes bound along one ray, with H flipped when `flip`.
fn convex_span(dl: &DisplayList, obj: usize, x: f64, y: f64, flip: bool, rule: ScreenRule) -> Span {
    let (mut lo, mut lo_t, mut hi, mut hi_t) = (f64::NEG_INFINITY, None, f64::INFINITY, None);
    for (i, p) in dl.planes.iter().enumerate() {
        let v = value(p, x, y);
        if p.y {
            // Inside a perpendicular plane is K >= 0; the flipped set keeps K <= 0.
            let inside = if flip { v <= 0.0 } else { v >= 0.0 };
            if !inside {
                return vec![];
            }
        } else if p.h != flip {
            if v > lo {
                (lo, lo_t) = (v, Some((obj, i)));
            }
        } else if rule == ScreenRule::Thesis && v < 0.0 {
            (hi, hi_t) = (f64::INFINITY, None);
        } else if v < hi {
            (hi, hi_t) = (v, Some((obj, i)));
        }
    }
    if lo < hi {
        vec![(lo, lo_t, hi, hi_t)]
    } else {
        vec![]
    }
}

/// The first point at or behind the screen inside a region: its depth and face (none when the
/// ray starts inside, at the screen).
fn first_inside(region: &Span) -> Option<(f64, Tag)> {
    let &(lo, lo_t, _, _) = region.iter().find(|s| s.2 > 0.0)?;
    Some(if lo >= 0.0 { (lo, lo_t) } else { (0.0, None) })
}

/// The surface the array draws for one object: a convex solid's first point behind the
/// screen; a concave list (a void, §2.3.2) its far wall, where the void ends in material.
fn surface(dl: &DisplayList, obj: usize, x: f64, y: f64, rule: ScreenRule) -> Option<(f64, Tag)> {
    if dl.is_concave() {
        let &(_, _, hi, hi_t) = convex_span(dl, obj, x, y, true, ScreenRule::Exact).first()?;
        (hi >= 0.0).then_some((hi, hi_t))
    } else {
        first_inside(&convex_span(dl, obj, x, y, false, rule))
    }
}

/// Is the point at depth `z` inside list `dl`'s convex solid (on a face counts as inside, as
/// the clipping test keeps ties with X = 0, §2.3.4)?
fn inside(dl: &DisplayList, x: f64, y: f64, z: f64) -> bool {
    dl.planes.iter().all(|p| {
        let v = value(p, x, y);
        match (p.y, p.h) {
            (true, _) => v >= 0.0,
            (false, true) => z >= v,
            (false, false) => z <= v,
        }
    })
}

/// A clipping function the thesis way (§5.2.1), in exact arithmetic: every literal's surface
/// (a complemented convex object is drawn as the void it leaves, whose far wall is the
/// object's back), kept where it lies inside the other literals of its product; the nearest
/// kept surface wins.
fn clipped_surface(
    lists: &[DisplayList],
    prods: &[Vec<Literal>],
    x: f64,
    y: f64,
    rule: ScreenRule,
) -> Option<(f64, Tag)> {
    let mut best: Option<(f64, Tag)> = None;
    for prod in prods {
        for (k, &(o, neg)) in prod.iter().enumerate() {
            let span = convex_span(
                &lists[o],
                o,
                x,
                y,
                false,
                if neg { ScreenRule::Exact } else { rule },
            );
            let s = match neg {
                false => first_inside(&span),
                true => span
                    .first()
                    .and_then(|&(_, _, hi, hi_t)| (hi >= 0.0).then_some((hi, hi_t))),
            };
            let Some(s) = s else { continue };
            let kept = prod
                .iter()
                .enumerate()
                .all(|(j, &(m, ng))| j == k || inside(&lists[m], x, y, s.0) != ng);
            if kept && best.is_none_or(|b| s.0 <= b.0) {
                best = Some(s);
            }
        }
    }
    best
}

/// Objects composed by the second stage: the nearest surface wins, a later object on a tie.
fn nearest_surface(lists: &[DisplayList], x: f64, y: f64, rule: ScreenRule) -> Option<(f64, Tag)> {
    let mut best: Option<(f64, Tag)> = None;
    for (o, dl) in lists.iter().enumerate() {
        if let Some(s) = surface(dl, o, x, y, rule) {
            if best.is_none_or(|b| s.0 <= b.0) {
                best = Some(s);
            }
        }
    }
    best
}

/// Ray-cast the scene on a `width`×`height` window.
pub fn render(
    lists: &[DisplayList],
    clip: Option<&Clip>,
    width: usize,
    height: usize,
    fmt: &WordFormat,
    rule: ScreenRule,
) -> FloatImage {
    let md = fmt.to_real(fmt.maxdepth());
    let n = width * height;
    let mut img = FloatImage {
        width,
        height,
        depth: vec![None; n],
        colour: vec![0; n],
        margin: vec![f64::INFINITY; n],
        screen_rule: vec![false; n],
    };
    let products = clip.map(|e| e.products().unwrap_or_default());
    for i in 0..n {
        let (x, y) = ((i % width) as f64, (i / width) as f64);
        let visible = match &products {
            Some(prods) => clipped_surface(lists, prods, x, y, rule),
            None => nearest_surface(lists, x, y, rule),
        };
        if let Some((z, tag)) = visible.filter(|v| v.0 < md) {
            let c = tag.map_or(INTERIOR_COLOUR, |(o, p)| lists[o].planes[p].colour);
            (img.depth[i], img.colour[i]) = (Some(z), c);
        }
        let values: Vec<f64> = lists
            .iter()
            .flat_map(|dl| dl.planes.iter().map(|p| value(p, x, y)))
            .collect();
        img.margin[i] = margin(&values, md);
        img.screen_rule[i] = lists
            .iter()
            .any(|dl| dl.planes.iter().any(|p| !p.y && value(p, x, y) < 0.0));
    }
    img
}

/// Why an array pixel's colour is what it is, measured against the float model.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The same colour as the exact float model.
    Equal,
    /// Different, but two quantities the array compares are closer than twice the rounding
    /// bound ([`rounding_bound`]), so the word model may decide either way.
    NearTie,
    /// Different where a face lies in front of the screen and the thesis's rows for A < 0
    /// decide: the float model with [`ScreenRule::Thesis`] gives the array's colour (or is
    /// itself near a tie), or, under a clipping function, the rule acts on a literal.
    ScreenRule,
    /// Different, and neither explains it: a fault.
    Unexplained,
}

/// Counts of each [`Verdict`] over an image, and the unexplained pixels (index y·W + x).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Agreement {
    /// Pixels where both models show the same.
    pub equal: usize,
    /// Pixels that differ where a decision is within rounding of a tie ([`Verdict::NearTie`]).
    pub near_tie: usize,
    /// Pixels that differ by the thesis's rule for back planes in front of the screen ([`Verdict::ScreenRule`]).
    pub screen_rule: usize,
    /// Pixels that differ with no explanation (index y·W + x).
    pub unexplained: Vec<usize>,
}

impl Agreement {
    /// Pixels whose colour differs from the exact float model.
    pub fn differ(&self) -> usize {
        self.near_tie + self.screen_rule + self.unexplained.len()
    }
}

/// Compare an array's colours (G of every pixel) with the float model of the same scene.
pub fn agreement(
    colours: &[u32],
    lists: &[DisplayList],
    clip: Option<&Clip>,
    width: usize,
    height: usize,
    fmt: &WordFormat,
) -> Agreement {
    let exact = render(lists, clip, width, height, fmt, ScreenRule::Exact);
    let thesis = render(lists, clip, width, height, fmt, ScreenRule::Thesis);
    let mut a = Agreement::default();
    for (i, &g) in colours.iter().enumerate() {
        let bound = 2.0 * rounding_bound(fmt, i % width, i / width);
        let verdict = if g == exact.colour[i] {
            Verdict::Equal
        } else if exact.margin[i] < bound {
            Verdict::NearTie
        } else if exact.screen_rule[i]
            && (clip.is_some() || g == thesis.colour[i] || thesis.margin[i] < bound)
        {
            Verdict::ScreenRule
        } else {
            Verdict::Unexplained
        };
        match verdict {
            Verdict::Equal => a.equal += 1,
            Verdict::NearTie => a.near_tie += 1,
            Verdict::ScreenRule => a.screen_rule += 1,
            Verdict::Unexplained => a.unexplained.push(i),
        }
    }
    a
}

/// The smallest gap between any two plane values, or between one and 0 or maxdepth: the
/// smallest gap of the sorted values, so O(n log n) for lists of hundreds of faces.
fn margin(values: &[f64], md: f64) -> f64 {
    // (value, is a plane value): the gap between 0 and maxdepth themselves does not count.
    let mut v: Vec<(f64, bool)> = values.iter().map(|&x| (x, true)).collect();
    v.extend([(0.0, false), (md, false)]);
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    v.windows(2)
        .filter(|w| w[0].1 || w[1].1)
        .map(|w| w[1].0 - w[0].0)
        .fold(f64::INFINITY, f64::min)
}

/// The rounding bound of docs/depth-word.md at pixel (x, y): each of Z0, dZx, dZy is within
/// half a unit in the last place, so a plane's word is within 2^-(F+1)·(1 + x + y).
pub fn rounding_bound(fmt: &WordFormat, x: usize, y: usize) -> f64 {
    0.5 / (1u64 << fmt.frac) as f64 * (1 + x + y) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Every pair, directly: the definition [`margin`] must match.
    fn margin_pairs(values: &[f64], md: f64) -> f64 {
        let mut m = f64::INFINITY;
        for (i, a) in values.iter().enumerate() {
            m = m.min(a.abs()).min((a - md).abs());
            for b in &values[i + 1..] {
                m = m.min((a - b).abs());
            }
        }
        m
    }

    proptest! {
        #[test]
        fn margin_is_the_smallest_pairwise_gap(
            values in prop::collection::vec(-3000.0..3000.0f64, 0..40),
        ) {
            prop_assert_eq!(margin(&values, 1024.0), margin_pairs(&values, 1024.0));
        }
    }
}
