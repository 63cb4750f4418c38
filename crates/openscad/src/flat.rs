//! 2D shapes and the nodes over them: `square`, `circle`, `polygon`, `hull` and `offset` of
//! 2D children, extrusion parameters.

use csgpix_scene::error::{CsgError, Rule};
use csgpix_scene::Error;
use glam::DVec2;

use crate::extrude::{default_slices, offset, region_points, Linear, Offset, Poly2, Region};
use crate::value::must;
use crate::{consts_::*, frame::*, lex::*, linalg::*, node::*, primitives::*};

/// A finished `hull()` of 2D shapes: the convex hull of their vertices.
pub(crate) fn hull_flat(frame: Frame) -> Result<Option<Item>, Fail> {
    let pos = frame.pos;
    let at = frame.first_flat.unwrap_or(pos);
    let mut pts = vec![];
    for r in &frame.flats {
        region_points(r, &mut pts).map_err(|problem| Fail { pos, problem })?;
    }
    let h = crate::hull::hull2(&pts);
    if h.len() < 3 {
        return Ok(None);
    }
    Ok(Some(Item::Flat(Region::Poly(Poly2 { paths: vec![h] }), at)))
}

/// A finished `offset()`, in its own coordinates (the caller places it): the outline and
/// where its first 2D child stands.
pub(crate) fn offset_flat(frame: Frame) -> Result<Option<(Region, Pos)>, Fail> {
    let pos = frame.pos;
    if !frame.children.is_empty() {
        let node = "offset";
        return fail(pos, CsgError::ChildDimension { node, flat: true });
    }
    if frame.flats.is_empty() {
        return Ok(None);
    }
    let Spec::Offset(o) = frame.spec else {
        return fail(pos, Error::Internal("an offset without its parameters"));
    };
    let at = frame.first_flat.unwrap_or(pos);
    let region = region_of(Op::Union, frame.flats);
    let r = offset(&region, o, &sin_cos_degrees).map_err(|problem| Fail { pos, problem })?;
    Ok(Some((r, at)))
}

/// The 2D tree an operation makes of its 2D children.
pub(crate) fn region_of(op: Op, mut parts: Vec<Region>) -> Region {
    if parts.len() == 1 && op == Op::Union {
        return parts.pop().unwrap_or(Region::Union(vec![]));
    }
    match op {
        Op::Union => Region::Union(parts),
        Op::Intersection => Region::Intersection(parts),
        Op::Difference => Region::Difference(parts),
    }
}

/// Every vertex of every shape of a 2D tree, to `f` (for the slice and fragment counts).
pub(crate) fn for_each_point(r: &Region, f: &mut impl FnMut(DVec2)) {
    let mut stack = vec![r];
    while let Some(r) = stack.pop() {
        match r {
            Region::Poly(p) => p.points().for_each(&mut *f),
            Region::Union(c) | Region::Intersection(c) | Region::Difference(c) => {
                stack.extend(c.iter())
            }
        }
    }
}

/// `linear_extrude`'s slices: as given, or OpenSCAD 2021.01's count from the outlines.
pub(crate) fn linear_slices(a: LinearArgs, region: &Region) -> Linear {
    let mut l = a.linear;
    l.slices = match a.slices {
        Some(n) => n,
        // Straight walls: one slice (`default_slices`), without a walk over the points.
        None if l.twist == 0.0 && l.scale[0] == l.scale[1] => 1,
        None => {
            let ds = DVec2::new(l.scale[0] - 1.0, l.scale[1] - 1.0);
            let (mut r, mut delta) = (0.0f64, 0.0f64);
            for_each_point(region, &mut |p| {
                r = r.max(p.length());
                delta = delta.max((p * ds).length());
            });
            let (fn_, fa, fs) = a.res;
            default_slices(&l, r, fn_, fa, fs, delta).min(MAX_FRAGMENTS as f64) as usize
        }
    };
    l
}

/// The parameters of an extrusion or offset, read when the statement opens.
pub(crate) fn flat_spec(head: &Head) -> Result<Spec, Fail> {
    let p = &head.params;
    let res = || -> Result<(f64, f64, f64), Fail> {
        let r = Resolution::read(p)?;
        Ok((r.fn_, r.fa, r.fs))
    };
    Ok(match head.kind {
        NodeKind::LinearExtrude => Spec::Linear(linear_args(p, res()?)?),
        NodeKind::RotateExtrude => {
            let mut angle = p.number("angle")?.map_or(360.0, |a| a.0);
            // OpenSCAD 2021.01: an angle outside (-360, 360] is a full turn.
            if !(angle > -360.0 && angle <= 360.0) {
                angle = 360.0;
            }
            if angle == 0.0 {
                return fail(head.pos, CsgError::ZeroAngle);
            }
            Spec::Rotate { angle, res: res()? }
        }
        NodeKind::Offset => {
            let r = Resolution::read(p)?;
            let o = match (p.number("r")?, p.number("delta")?) {
                (Some((r_, at)), _) => {
                    finite(r_, at, "`r`")?;
                    Offset::Round {
                        r: r_,
                        fragments: r.fragments(r_.abs(), at)?,
                    }
                }
                (None, Some((d, at))) => Offset::Delta {
                    delta: finite(d, at, "`delta`")?,
                    chamfer: p.boolean("chamfer")?,
                },
                (None, None) => Offset::Delta {
                    delta: 1.0,
                    chamfer: p.boolean("chamfer")?,
                },
            };
            Spec::Offset(o)
        }
        NodeKind::Projection => Spec::Projection {
            cut: p.boolean("cut")?,
        },
        NodeKind::Resize => {
            let (newsize, auto) = resize_args(p)?;
            Spec::Resize { newsize, auto }
        }
        _ => Spec::None,
    })
}

pub(crate) fn finite(v: f64, at: Pos, what: &str) -> Result<f64, Fail> {
    if v.is_finite() && v.abs() <= MAX_COORDINATE {
        Ok(v)
    } else {
        fail(at, must(what, Rule::FiniteNumber))
    }
}

/// `what` past the coordinate limit.
fn past_limit(what: &'static str) -> CsgError {
    CsgError::CoordinateLimit {
        what,
        resized: false,
    }
}

/// `linear_extrude(height, center, convexity, twist, slices, scale)`.
pub(crate) fn linear_args(p: &Params, res: (f64, f64, f64)) -> Result<LinearArgs, Fail> {
    let height = match p.number("height")? {
        Some((h, at)) => finite(h, at, "`height`")?,
        None => 100.0,
    };
    let twist = match p.number("twist")? {
        Some((t, at)) => finite(t, at, "`twist`")?,
        None => 0.0,
    };
    let slices = match p.number("slices")? {
        Some((n, at)) => {
            if !(n.is_finite() && n < MAX_FRAGMENTS as f64) {
                return fail(at, must("`slices`", Rule::Below(MAX_FRAGMENTS)));
            }
            Some((n.max(1.0)) as usize)
        }
        None => None,
    };
    let scale = match p.get("scale") {
        None => [1.0, 1.0],
        Some(v) => {
            let s = v.pair("`scale`")?;
            if s.iter().any(|c| !(c.is_finite() && *c >= 0.0)) {
                return fail(v.pos, must("`scale`", Rule::NotNegative));
            }
            s
        }
    };
    Ok(LinearArgs {
        linear: Linear {
            height,
            center: p.boolean("center")?,
            twist,
            slices: 1,
            scale,
        },
        slices,
        res,
    })
}

/// `square`, `circle`, `polygon` or `text` as a shape in its own plane; `None` for a zero
/// or negative size, which OpenSCAD draws as nothing.
pub(crate) fn flat_shape<'f>(
    p: &Params,
    fonts: impl FnOnce() -> &'f crate::text::Fonts,
    budget: usize,
    notes: &mut Vec<String>,
    drawn: &mut crate::text::Drawn,
) -> Result<Option<Poly2>, Fail> {
    match p.node {
        NodeKind::Square => {
            let size = match p.get("size") {
                None => [1.0, 1.0],
                Some(v) => {
                    let s = v.pair("`size`")?;
                    if s.iter().any(|c| !(*c > 0.0 && c.is_finite())) {
                        return Ok(None);
                    }
                    if s.iter().any(|c| c.is_nan() || *c > MAX_COORDINATE) {
                        return fail(v.pos, past_limit("`size`"));
                    }
                    s
                }
            };
            Ok(Some(Poly2::square(size[0], size[1], p.boolean("center")?)))
        }
        NodeKind::Circle => {
            let r = match radius(p, "d", "r")? {
                Some((r, _)) if !(r > 0.0 && r.is_finite()) => return Ok(None),
                Some((r, _)) => r,
                None => 1.0,
            };
            let n = Resolution::read(p)?.fragments(r, p.pos)?;
            check_budget(n, budget, p.pos)?;
            Ok(Some(unit_circle(n, |unit| Poly2::circle_of(r, unit))))
        }
        NodeKind::Text => crate::text::text_shape(p, fonts(), budget, notes, drawn).map(Some),
        _ => polygon(p, budget).map(Some),
    }
}

/// `f` of the sines and cosines of `circle()`'s `n` fragment angles (360°·i/n), computed
/// once for a run of circles of the same `n`: a plate of thousands of circles of a thousand
/// fragments each computed millions.
fn unit_circle<T>(n: usize, f: impl FnOnce(&[(f64, f64)]) -> T) -> T {
    thread_local! {
        static LAST: std::cell::RefCell<Vec<(f64, f64)>> = const { std::cell::RefCell::new(Vec::new()) };
    }
    LAST.with_borrow_mut(|unit| {
        if unit.len() != n {
            unit.clear();
            unit.extend((0..n).map(|i| sin_cos_degrees(360.0 * i as f64 / n as f64)));
        }
        f(unit)
    })
}

/// `polygon(points, paths)`: one outline of all points, or one per path (even-odd fill).
pub(crate) fn polygon(p: &Params, budget: usize) -> Result<Poly2, Fail> {
    let pts = p.require("points", "points = [[x, y], …]")?;
    let pts = pts
        .list("`points`")?
        .iter()
        .map(|v| match v.list("a point")? {
            [x, y] | [x, y, _] => {
                let q = DVec2::new(x.number("a point")?, y.number("a point")?);
                if q.abs().max_element() > MAX_COORDINATE || !q.is_finite() {
                    return fail(v.pos, past_limit("a point"));
                }
                Ok(q)
            }
            _ => fail(v.pos, must("a point", Rule::Xy)),
        })
        .collect::<Result<Vec<_>, _>>()?;
    check_budget(pts.len(), budget, p.pos)?;
    let paths = match p.get("paths") {
        None => vec![pts],
        Some(v) => v
            .list("`paths`")?
            .iter()
            .map(|path| {
                path.list("a path")?
                    .iter()
                    .map(|i| {
                        let k = i.number("a point index")?;
                        if k.fract() != 0.0 || k < 0.0 || k >= pts.len() as f64 {
                            let count = pts.len();
                            return fail(i.pos, CsgError::PointIndex { index: k, count });
                        }
                        Ok(pts[k as usize])
                    })
                    .collect::<Result<Vec<_>, _>>()
            })
            .collect::<Result<Vec<_>, _>>()?,
    };
    Ok(Poly2 {
        paths: paths.into_iter().filter(|p| p.len() >= 3).collect(),
    })
}

/// `resize(newsize, auto)`'s arguments: up to three sizes (missing ones 0), `auto` a boolean or
/// a vector of them (numbers count as booleans, as the CSG export writes `[0, 1, 0]`).
pub(crate) fn resize_args(p: &Params) -> Result<([f64; 3], [bool; 3]), Fail> {
    let mut newsize = [0.0; 3];
    if let Some(v) = p.get("newsize") {
        let items = v.list("`newsize`")?;
        if items.len() > 3 {
            return fail(v.pos, must("`newsize`", Rule::Xyz));
        }
        for (slot, item) in newsize.iter_mut().zip(items) {
            let s = finite(
                item.number("an entry of `newsize`")?,
                item.pos,
                "an entry of `newsize`",
            )?;
            *slot = s;
        }
    }
    let truth = |v: &crate::value::Value| -> Result<bool, Fail> {
        match &v.kind {
            crate::value::Kind::Bool(b) => Ok(*b),
            crate::value::Kind::Undef => Ok(false),
            _ => Ok(v.number("an entry of `auto`")? != 0.0),
        }
    };
    let mut auto = [false; 3];
    if let Some(v) = p.get("auto") {
        match &v.kind {
            crate::value::Kind::List(items) => {
                for (slot, item) in auto.iter_mut().zip(items) {
                    *slot = truth(item)?;
                }
            }
            _ => auto = [truth(v)?; 3],
        }
    }
    Ok((newsize, auto))
}
