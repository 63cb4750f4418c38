//! The `float` model: exact f64 geometry of the same plane sets, by ray casting. Not hardware;
//! the reference `word` and `cycle` are measured against.
//!
//! Along the ray of pixel (x, y) (depth z from the screen, §2.3.1), a convex display list
//! (L = 0) is the intersection of its half-spaces: behind every front plane (z ≥ Z), in front
//! of every back plane (z ≤ Z), on the inner side of every perpendicular plane (K ≥ 0). A
//! concave list (L = 1) is a hole: the complement of the convex set its planes bound with
//! the roles of front and back exchanged (its front faces are the far side of the solid it
//! cuts away, §2.3.2). A scene is the union of its objects, or the clipping function over
//! them. The visible point is the first z ≥ 0 inside the scene, if below maxdepth: z = 0
//! (the screen, interior colour) when the ray starts inside.

use rtl_model::WordFormat;

use crate::clip_expr::Clip;
use crate::compile::INTERIOR_COLOUR;
use crate::display_list::DisplayList;

/// Which face bounds an interval: (object, plane), or none at ±infinity.
type Tag = Option<(usize, usize)>;

/// Disjoint, sorted intervals (lo, hi) of z, each end tagged with its face.
type Span = Vec<(f64, Tag, f64, Tag)>;

/// The float image and, per pixel, how close the hardware's decisions come to a tie.
#[derive(Clone, Debug)]
pub struct FloatImage {
    pub width: usize,
    pub height: usize,
    /// Visible depth, `None` for background.
    pub depth: Vec<Option<f64>>,
    pub colour: Vec<u32>,
    /// The smallest gap, in depth units, between any two plane values at this pixel, or
    /// between a plane value and 0 or maxdepth: below twice the rounding bound the word model
    /// may decide a comparison the other way.
    pub margin: Vec<f64>,
    /// A convex object has a back plane in front of the screen here: the thesis's rule
    /// "A < 0 ≤ B: Put 1" (§2.3.3) then keeps the object where the geometry has none.
    pub screen_rule: Vec<bool>,
}

fn value(p: &crate::display_list::DlPlane, x: f64, y: f64) -> f64 {
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

fn complement(s: &Span) -> Span {
    let mut out = vec![];
    let (mut lo, mut lo_t) = (f64::NEG_INFINITY, None);
    for &(a, at, b, bt) in s {
        if a > lo {
            out.push((lo, lo_t, a, at));
        }
        (lo, lo_t) = (b, bt);
    }
    if lo < f64::INFINITY {
        out.push((lo, lo_t, f64::INFINITY, None));
    }
    out
}

fn intersect(a: &Span, b: &Span) -> Span {
    let mut out = vec![];
    for &(a0, a0t, a1, a1t) in a {
        for &(b0, b0t, b1, b1t) in b {
            let (lo, lo_t) = if a0 >= b0 { (a0, a0t) } else { (b0, b0t) };
            let (hi, hi_t) = if a1 <= b1 { (a1, a1t) } else { (b1, b1t) };
            if lo < hi {
                out.push((lo, lo_t, hi, hi_t));
            }
        }
    }
    out.sort_by(|p, q| p.0.total_cmp(&q.0));
    out
}

fn union(a: &Span, b: &Span) -> Span {
    complement(&intersect(&complement(a), &complement(b)))
}

/// The region of one object along the ray.
fn object_span(dl: &DisplayList, obj: usize, x: f64, y: f64, rule: ScreenRule) -> Span {
    if dl.is_concave() {
        complement(&convex_span(dl, obj, x, y, true, ScreenRule::Exact))
    } else {
        convex_span(dl, obj, x, y, false, rule)
    }
}

fn eval(e: &Clip, spans: &[Span]) -> Span {
    match e {
        Clip::Obj(i) => spans[*i].clone(),
        Clip::Not(a) => complement(&eval(a, spans)),
        Clip::And(a, b) => intersect(&eval(a, spans), &eval(b, spans)),
        Clip::Or(a, b) => union(&eval(a, spans), &eval(b, spans)),
    }
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
    for i in 0..n {
        let (x, y) = ((i % width) as f64, (i / width) as f64);
        let spans: Vec<Span> = lists
            .iter()
            .enumerate()
            .map(|(o, dl)| object_span(dl, o, x, y, rule))
            .collect();
        let scene = match clip {
            Some(e) => eval(e, &spans),
            None => spans.iter().fold(vec![], |acc, s| union(&acc, s)),
        };
        if let Some(&(lo, lo_t, _, _)) = scene.iter().find(|s| s.2 > 0.0) {
            let (z, c) = match lo_t {
                Some((o, p)) if lo >= 0.0 => (lo, lists[o].planes[p].colour),
                _ => (0.0, INTERIOR_COLOUR),
            };
            if z < md {
                (img.depth[i], img.colour[i]) = (Some(z), c);
            }
        }
        let values: Vec<f64> = lists
            .iter()
            .flat_map(|dl| dl.planes.iter().map(|p| value(p, x, y)))
            .collect();
        img.margin[i] = margin(&values, md);
        img.screen_rule[i] = lists.iter().any(|dl| {
            !dl.is_concave()
                && dl
                    .planes
                    .iter()
                    .any(|p| !p.h && !p.y && value(p, x, y) < 0.0)
        });
    }
    img
}

fn margin(values: &[f64], md: f64) -> f64 {
    let mut m = f64::INFINITY;
    for (i, a) in values.iter().enumerate() {
        m = m.min(a.abs()).min((a - md).abs());
        for b in &values[i + 1..] {
            m = m.min((a - b).abs());
        }
    }
    m
}

/// The rounding bound of docs/depth-word.md at pixel (x, y): each of Z0, dZx, dZy is within
/// half a unit in the last place, so a plane's word is within 2^-(F+1)·(1 + x + y).
pub fn rounding_bound(fmt: &WordFormat, x: usize, y: usize) -> f64 {
    0.5 / (1u64 << fmt.frac) as f64 * (1 + x + y) as f64
}
