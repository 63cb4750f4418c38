//! `import("x.svg")`: an SVG file read as OpenSCAD 2021.01 reads it (`src/import_svg.cc` and
//! its `libsvg`), into 2D shapes. `roxmltree` reads the XML; everything after it is
//! OpenSCAD's own rules, quirks included:
//!
//! * the elements `path`, `rect`, `circle`, `ellipse`, `line`, `polyline`, `polygon`, under
//!   `g` groups (their `transform`s compose); everything inside `defs` is skipped, `text` draws
//!   nothing, other elements (`use`, `image`, `symbol`, …) are ignored but their children are
//!   read, with the transform of the nearest group;
//! * curves at fixed step counts, whatever `$fn`: 20 segments per cubic or quadratic Bézier,
//!   `|sweep°|·10/180 + 4` per elliptical arc, 40 per circle or ellipse;
//! * fill and stroke styles are not read: every closed outline is filled, every open one (a
//!   path's subpath whose ends are more than 0.1 apart, a `line`, a `polyline`) is replaced by
//!   its stroke, Clipper's open offset of half the stroke width (`stroke-width` attribute or
//!   style; a plain number, else 1) with its `stroke-linecap` (square unless butt or round)
//!   and `stroke-linejoin` (miter, limit 2, unless bevel or round);
//! * the outlines of one element combine by the even-odd rule, elements by union;
//! * the size: `width`/`height` in mm (`px` 96 dpi, `pt`, `pc`, `in`, `cm`; plain numbers at
//!   the import's `dpi`, 72 by default) over the `viewBox` with `preserveAspectRatio` (default
//!   xMidYMid meet); without a viewBox user units are mm. SVG's y axis points down: y is
//!   flipped about the page height, or the shapes' box is centred with `center = true`.

use csgpix_scene::Error;
use std::cell::Cell;
use std::path::Path;

use glam::DVec2;

use crate::extrude::Poly2;
use crate::linalg::{cos_degrees, sin_degrees};

/// An affine map `[a, b, c, d, e, f]`: x' = a·x + c·y + e, y' = b·x + d·y + f.
type Affine = [f64; 6];

const IDENTITY: Affine = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];

fn compose(m: &Affine, n: &Affine) -> Affine {
    // m · n
    [
        m[0] * n[0] + m[2] * n[1],
        m[1] * n[0] + m[3] * n[1],
        m[0] * n[2] + m[2] * n[3],
        m[1] * n[2] + m[3] * n[3],
        m[0] * n[4] + m[2] * n[5] + m[4],
        m[1] * n[4] + m[3] * n[5] + m[5],
    ]
}

fn apply(m: &Affine, p: DVec2) -> DVec2 {
    DVec2::new(
        m[0] * p.x + m[2] * p.y + m[4],
        m[1] * p.x + m[3] * p.y + m[5],
    )
}

/// The SVG file `path` as OpenSCAD's `import(file, dpi, center)` draws it: one even-odd shape
/// per SVG element, their union. Err is one line.
pub(crate) fn read(
    path: &Path,
    dpi: f64,
    center: bool,
    max_vertices: usize,
) -> csgpix_scene::Result<Vec<Poly2>> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io("cannot read it", &e))?;
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
    parse(
        &text,
        name.as_deref().unwrap_or("svg"),
        dpi,
        center,
        max_vertices,
    )
}

/// [`read`] of the file's text (`file` names it in errors). Elements nested deeper than
/// [`csgpix_scene::MAX_XML_DEPTH`] (libxml2's limit, so OpenSCAD's too) and more than
/// [`csgpix_scene::MAX_XML_NODES`] nodes (entities included) are refused in one line, before
/// roxmltree and [`walk`], which recurse once per level. The outlines may have at most
/// `max_vertices` points in all: a stroke is refused before its outline is made when its
/// round joins and caps would pass what is left (a width of 10¹⁶ has 10²⁰ arc steps).
pub(crate) fn parse(
    text: &str,
    file: &str,
    dpi: f64,
    center: bool,
    max_vertices: usize,
) -> csgpix_scene::Result<Vec<Poly2>> {
    csgpix_scene::check_xml_nesting(text, file)?;
    let opts = roxmltree::ParsingOptions {
        allow_dtd: true,
        nodes_limit: csgpix_scene::MAX_XML_NODES,
    };
    let doc = roxmltree::Document::parse_with_options(text, opts).map_err(|e| Error::BadSvg {
        reason: e.to_string(),
    })?;
    let root = doc.root_element();
    if root.tag_name().name() != "svg" {
        return Err(Error::NotSvg {
            root: root.tag_name().name().to_string(),
        });
    }
    let page = Page::read(&root)?;
    let mut shapes = vec![];
    let left = Cell::new(max_vertices);
    for child in root.children() {
        walk(child, &IDENTITY, &mut shapes, 1, &left)?;
    }
    place(&page, shapes, dpi, center)
}

/// The `<svg>` element's size, viewBox and alignment.
struct Page {
    width: Length,
    height: Length,
    viewbox: Option<[f64; 4]>,
    /// (x, y) alignment, `None` for `preserveAspectRatio="none"`; and meet (or slice).
    align: Option<(Align, Align)>,
    meet: bool,
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Align {
    Min,
    Mid,
    Max,
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Unit {
    Undefined,
    None,
    Px,
    Pt,
    Pc,
    In,
    Cm,
    Mm,
    /// `%`, `em`, `ex`: the viewBox size, as OpenSCAD.
    Other,
}

#[derive(Clone, Copy, Debug)]
struct Length {
    number: f64,
    unit: Unit,
}

impl Page {
    fn read(node: &roxmltree::Node) -> csgpix_scene::Result<Page> {
        let attr = |n: &str| node.attribute(n).unwrap_or("");
        let viewbox = parse_viewbox(attr("viewBox"));
        if let Some(v) = viewbox {
            if v[2] == 0.0 || v[3] == 0.0 {
                return Err(Error::EmptyViewBox {
                    view_box: attr("viewBox").to_string(),
                });
            }
        }
        let (align, meet) = parse_alignment(attr("preserveAspectRatio"));
        Ok(Page {
            width: parse_length(attr("width")),
            height: parse_length(attr("height")),
            viewbox,
            align,
            meet,
        })
    }
}

/// OpenSCAD's `to_mm` of a page length.
fn to_mm(l: Length, viewbox: Option<f64>, dpi: f64) -> f64 {
    const INCH: f64 = 25.4;
    match l.unit {
        Unit::None => INCH * l.number / dpi,
        Unit::Px => INCH * l.number / 96.0,
        Unit::Pt => INCH * l.number / 72.0,
        Unit::Pc => INCH * l.number / 6.0,
        Unit::In => INCH * l.number,
        Unit::Cm => 10.0 * l.number,
        Unit::Mm => l.number,
        Unit::Undefined => viewbox.map_or(0.0, |v| INCH * v / dpi),
        Unit::Other => viewbox.unwrap_or(0.0),
    }
}

/// The shapes (each element's outlines in its user units, transformed) placed in mm as
/// `import_svg` does.
fn place(
    page: &Page,
    shapes: Vec<Vec<Vec<DVec2>>>,
    dpi: f64,
    center: bool,
) -> csgpix_scene::Result<Vec<Poly2>> {
    let width_mm = to_mm(page.width, page.viewbox.map(|v| v[2]), dpi);
    let height_mm = to_mm(page.height, page.viewbox.map(|v| v[3]), dpi);
    let mut scale = DVec2::ONE;
    let mut align = DVec2::ZERO;
    let mut origin = DVec2::ZERO;
    if let Some(v) = page.viewbox {
        origin = DVec2::new(v[0], v[1]);
        scale = DVec2::new(width_mm / v[2], height_mm / v[3]);
        if let Some((ax, ay)) = page.align {
            let s = if page.meet {
                scale.x.min(scale.y)
            } else {
                scale.x.max(scale.y)
            };
            scale = DVec2::splat(s);
            let at = |a: Align, page_mm: f64, s: f64, vb: f64| match a {
                Align::Min => 0.0,
                Align::Mid => page_mm / 2.0 - s * vb / 2.0,
                Align::Max => page_mm - s * vb,
            };
            align = DVec2::new(at(ax, width_mm, s, v[2]), at(ay, height_mm, s, v[3]));
        }
    }
    let (mut lo, mut hi) = (DVec2::splat(f64::MAX), DVec2::splat(f64::MIN));
    for p in shapes.iter().flatten().flatten() {
        if !p.is_finite() {
            return Err(Error::NonFiniteCoordinate);
        }
        lo = lo.min(scale * *p);
        hi = hi.max(scale * *p);
    }
    let c = if center {
        (lo + hi) / 2.0
    } else {
        DVec2::new(-align.x, height_mm - align.y)
    };
    let c = if center && lo.x > hi.x {
        DVec2::ZERO
    } else {
        c
    };
    let mut out = vec![];
    for shape in shapes {
        let paths: Vec<Vec<[f64; 2]>> = shape
            .iter()
            .map(|p| {
                p.iter()
                    .map(|v| {
                        [
                            scale.x * (-origin.x + v.x) - c.x,
                            scale.y * (-origin.y - v.y) + c.y,
                        ]
                    })
                    .collect()
            })
            .collect();
        // OpenSCAD's sanitize: the element's outlines by the even-odd rule.
        let poly = clean(&paths, Fill::EvenOdd);
        if !poly.paths.is_empty() {
            out.push(poly);
        }
    }
    Ok(out)
}

#[derive(Clone, Copy)]
enum Fill {
    EvenOdd,
    Positive,
}

/// Outlines combined by a fill rule into clean outer outlines and holes.
fn clean(paths: &[Vec<[f64; 2]>], fill: Fill) -> Poly2 {
    use i_overlay::core::fill_rule::FillRule;
    use i_overlay::core::overlay_rule::OverlayRule;
    use i_overlay::float::single::SingleFloatOverlay;
    let subj: Vec<Vec<[f64; 2]>> = paths.iter().filter(|p| p.len() >= 3).cloned().collect();
    let none: Vec<Vec<[f64; 2]>> = vec![];
    let rule = match fill {
        Fill::EvenOdd => FillRule::EvenOdd,
        Fill::Positive => FillRule::Positive,
    };
    let shapes = if subj.is_empty() {
        vec![]
    } else {
        subj.overlay(&none, OverlayRule::Subject, rule)
    };
    Poly2 {
        paths: shapes
            .into_iter()
            .flatten()
            .filter(|c| c.len() >= 3)
            .map(|c| c.into_iter().map(DVec2::from).collect())
            .collect(),
    }
}

/// The elements under `node` (a child of a container whose transform is `m`), in document
/// order: each drawing element's outlines, transformed.
/// `left` counts down the outline points the file may still make.
fn walk(
    node: roxmltree::Node,
    m: &Affine,
    out: &mut Vec<Vec<Vec<DVec2>>>,
    depth: usize,
    left: &Cell<usize>,
) -> csgpix_scene::Result<()> {
    if !node.is_element() {
        return Ok(());
    }
    // The text is checked before parsing, but an entity of the DTD may nest more.
    if depth > csgpix_scene::MAX_XML_DEPTH {
        return Err(Error::TooDeep {
            limit: csgpix_scene::MAX_XML_DEPTH,
        });
    }
    let ns = node.tag_name().namespace();
    let svg_ns = ns.is_none() || ns == Some("http://www.w3.org/2000/svg");
    let name = if svg_ns { node.tag_name().name() } else { "" };
    match name {
        // libsvg skips everything inside <defs>.
        "defs" => return Ok(()),
        "svg" => return Err(Error::NestedSvg),
        _ => {}
    }
    let attr = |n: &str| at(node, n);
    let own = || compose(m, &parse_transform(attr("transform")));
    let style = Style {
        element: name,
        width: attr("stroke-width"),
        cap: attr("stroke-linecap"),
        join: attr("stroke-linejoin"),
        style: attr("style"),
        left,
    };
    if let "g" | "text" | "tspan" = name {
        let m = own();
        for child in node.children() {
            walk(child, &m, out, depth + 1, left)?;
        }
        return Ok(());
    }
    let before = left.get();
    let paths = shape_outlines(node, name, &style)?;
    if let Some(paths) = paths {
        // Strokes took their points as they were drawn.
        let stroked = before - left.get();
        style.spend(
            paths
                .iter()
                .map(Vec::len)
                .sum::<usize>()
                .saturating_sub(stroked),
        )?;
        let own = own();
        out.push(
            paths
                .into_iter()
                .map(|p| p.into_iter().map(|v| apply(&own, v)).collect())
                .collect(),
        );
    }
    // Children of a drawing element or of an element libsvg does not know are read with the
    // nearest group's transform.
    for child in node.children() {
        walk(child, m, out, depth + 1, left)?;
    }
    Ok(())
}

/// libsvg's shapes: the outlines of drawing element `node` (named `name`) in its own
/// coordinates, or `None` when it is not one (SVG 1.1 §8 `path`, §9 basic shapes).
fn shape_outlines(
    node: roxmltree::Node,
    name: &str,
    style: &Style,
) -> csgpix_scene::Result<Option<Vec<Vec<DVec2>>>> {
    let attr = |n: &str| at(node, n);
    Ok(Some(match name {
        "path" => path_outlines(attr("d"), style)?,
        "rect" => rect(node, style)?,
        "circle" => {
            let r = parse_double(attr("r"));
            let c = [parse_double(attr("cx")), parse_double(attr("cy"))];
            vec![ellipse(c, r, r)]
        }
        "ellipse" => {
            let (rx, ry) = (parse_double(attr("rx")), parse_double(attr("ry")));
            let c = [parse_double(attr("cx")), parse_double(attr("cy"))];
            vec![ellipse(c, rx, ry)]
        }
        "line" => {
            let a = DVec2::new(parse_double(attr("x1")), parse_double(attr("y1")));
            let b = DVec2::new(parse_double(attr("x2")), parse_double(attr("y2")));
            style.stroke(&[a, b])?
        }
        "polygon" => {
            let mut pts = points(attr("points"));
            if let Some(&first) = pts.first() {
                pts.push(first);
            }
            vec![pts]
        }
        "polyline" => style.stroke(&points(attr("points")))?,
        _ => return Ok(None),
    }))
}

/// An attribute's value ("" when missing, as libsvg's attribute map gives it).
fn at<'a>(node: roxmltree::Node<'a, '_>, name: &str) -> &'a str {
    node.attribute(name).unwrap_or("")
}

/// libsvg's `parse_double`: the whole string a number, else 0.
fn parse_double(s: &str) -> f64 {
    let t = s;
    if t.is_empty() {
        return 0.0;
    }
    t.parse::<f64>().unwrap_or(0.0)
}

/// The longest prefix of `s` that is a decimal number (sign, digits, point, exponent).
fn number_prefix(s: &str) -> Option<(f64, &str)> {
    let b = s.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let digits = |i: &mut usize| {
        let s = *i;
        while *i < b.len() && b[*i].is_ascii_digit() {
            *i += 1;
        }
        *i - s
    };
    let mut n = digits(&mut i);
    if i < b.len() && b[i] == b'.' {
        i += 1;
        n += digits(&mut i);
    }
    if n == 0 {
        return None;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        if digits(&mut j) > 0 {
            i = j;
        }
    }
    Some((s[..i].parse().ok()?, &s[i..]))
}

/// libsvg's `parse_length`: a number and an optional unit, nothing else.
fn parse_length(s: &str) -> Length {
    let undefined = Length {
        number: 0.0,
        unit: Unit::Undefined,
    };
    let Some((number, rest)) = number_prefix(s.trim()) else {
        return undefined;
    };
    let unit = match rest.trim() {
        "" => Unit::None,
        "px" => Unit::Px,
        "pt" => Unit::Pt,
        "pc" => Unit::Pc,
        "in" => Unit::In,
        "cm" => Unit::Cm,
        "mm" => Unit::Mm,
        "%" | "em" | "ex" => Unit::Other,
        _ => return undefined,
    };
    Length { number, unit }
}

/// libsvg's `parse_viewbox`: four numbers apart by spaces or one comma, sizes not negative.
fn parse_viewbox(s: &str) -> Option<[f64; 4]> {
    let mut rest = s.trim_start();
    let mut v = [0.0; 4];
    for (k, slot) in v.iter_mut().enumerate() {
        if k > 0 {
            rest = rest.trim_start();
            if let Some(r) = rest.strip_prefix(',') {
                rest = r.trim_start();
            }
        }
        let (n, r) = number_prefix(rest)?;
        *slot = n;
        rest = r;
    }
    (rest.trim().is_empty() && v[2] >= 0.0 && v[3] >= 0.0).then_some(v)
}

/// libsvg's `parse_alignment`: `[defer] <align> [meet | slice]`, xMidYMid meet if unreadable.
fn parse_alignment(s: &str) -> (Option<(Align, Align)>, bool) {
    let default = (Some((Align::Mid, Align::Mid)), true);
    let mut words: Vec<&str> = s.split_whitespace().collect();
    if words.first() == Some(&"defer") {
        words.remove(0);
    }
    let Some(first) = words.first() else {
        return default;
    };
    let align = if *first == "none" {
        None
    } else {
        let a = |t: &str| match t {
            "Min" => Some(Align::Min),
            "Mid" => Some(Align::Mid),
            "Max" => Some(Align::Max),
            _ => None,
        };
        let (Some(x), Some(y)) = (
            first
                .get(1..4)
                .filter(|_| first.starts_with('x'))
                .and_then(a),
            first
                .get(5..8)
                .filter(|_| first.get(4..5) == Some("Y"))
                .and_then(a),
        ) else {
            return default;
        };
        if first.len() != 8 {
            return default;
        }
        Some((x, y))
    };
    let meet = match words.get(1) {
        None => true,
        Some(&"meet") => true,
        Some(&"slice") => false,
        Some(_) => return default,
    };
    if words.len() > 2 {
        return default;
    }
    (align, meet)
}

/// libsvg's `transform` attribute: `matrix`, `translate`, `scale`, `rotate`, `skewX`, `skewY`
/// (an operation with the wrong number of arguments is the identity).
fn parse_transform(s: &str) -> Affine {
    let s = s
        .replace("matrix", "m")
        .replace("translate", "t")
        .replace("scale", "s")
        .replace("rotate", "r")
        .replace("skewX", "x")
        .replace("skewY", "y");
    let mut ops: Vec<(char, Vec<f64>)> = vec![];
    for tok in tokens(&s, |c| c.is_whitespace() || ",()".contains(c), "mtsrxy") {
        let mut cs = tok.chars();
        match (cs.next(), cs.next()) {
            (Some(c), None) if "mtsrxy".contains(c) => ops.push((c, vec![])),
            _ => {
                if let Some(op) = ops.last_mut() {
                    op.1.push(parse_double(tok));
                }
            }
        }
    }
    let mut m = IDENTITY;
    for (op, a) in ops {
        let t = match (op, a.len()) {
            ('m', 6) => [a[0], a[1], a[2], a[3], a[4], a[5]],
            ('t', 1 | 2) => [1.0, 0.0, 0.0, 1.0, a[0], a.get(1).copied().unwrap_or(0.0)],
            ('s', 1 | 2) => [a[0], 0.0, 0.0, a.get(1).copied().unwrap_or(a[0]), 0.0, 0.0],
            ('r', 1 | 3) => {
                let (s, c) = (sin_degrees(a[0]), cos_degrees(a[0]));
                let r = [c, s, -s, c, 0.0, 0.0];
                if a.len() == 3 {
                    let to = [1.0, 0.0, 0.0, 1.0, a[1], a[2]];
                    let back = [1.0, 0.0, 0.0, 1.0, -a[1], -a[2]];
                    compose(&compose(&to, &r), &back)
                } else {
                    r
                }
            }
            ('x', 1) => [1.0, 0.0, a[0].to_radians().tan(), 1.0, 0.0, 0.0],
            ('y', 1) => [1.0, a[0].to_radians().tan(), 0.0, 1.0, 0.0, 0.0],
            _ => IDENTITY,
        };
        m = compose(&m, &t);
    }
    m
}

/// Boost's `char_separator`: pieces between dropped separators, and each kept delimiter alone.
fn tokens<'a>(s: &'a str, dropped: impl Fn(char) -> bool, kept: &str) -> Vec<&'a str> {
    let mut out = vec![];
    let mut start = 0;
    for (i, c) in s.char_indices() {
        if dropped(c) || kept.contains(c) {
            if i > start {
                out.push(&s[start..i]);
            }
            if kept.contains(c) {
                out.push(&s[i..i + c.len_utf8()]);
            }
            start = i + c.len_utf8();
        }
    }
    if start < s.len() {
        out.push(&s[start..]);
    }
    out
}

/// `points` of a polygon or polyline: x, y pairs (an odd last number is dropped).
fn points(s: &str) -> Vec<DVec2> {
    let nums: Vec<f64> = tokens(s, |c| c.is_whitespace() || c == ',', "")
        .into_iter()
        .map(parse_double)
        .collect();
    nums.chunks_exact(2)
        .map(|c| DVec2::new(c[0], c[1]))
        .collect()
}

/// libsvg's `draw_ellipse`: 40 points from the bottom (y + ry), x = rx·sin, y = ry·cos.
fn ellipse(c: [f64; 2], rx: f64, ry: f64) -> Vec<DVec2> {
    (1..=40)
        .map(|i| {
            let a = i as f64 * 360.0 / 40.0;
            DVec2::new(rx * sin_degrees(a) + c[0], ry * cos_degrees(a) + c[1])
        })
        .collect()
}

/// A `rect`: four corners, or with `rx`/`ry` the path libsvg writes for it (its numbers
/// printed to 6 significant digits, as boost::format does).
fn rect(node: roxmltree::Node, style: &Style) -> csgpix_scene::Result<Vec<Vec<DVec2>>> {
    let attr = |n: &str| at(node, n);
    let (x, y) = (parse_double(attr("x")), parse_double(attr("y")));
    let (w, h) = (parse_double(attr("width")), parse_double(attr("height")));
    let (mut rx, mut ry) = (parse_double(attr("rx")), parse_double(attr("ry")));
    let (has_rx, has_ry) = (rx.abs() >= 1e-8, ry.abs() >= 1e-8);
    if !(has_rx || has_ry) {
        let p = |a: f64, b: f64| DVec2::new(a, b);
        return Ok(vec![vec![
            p(x, y),
            p(x + w, y),
            p(x + w, y + h),
            p(x, y + h),
            p(x, y),
        ]]);
    }
    if !has_rx {
        rx = ry;
    } else if !has_ry {
        ry = rx;
    }
    rx = rx.min(w / 2.0);
    ry = ry.min(h / 2.0);
    let g = g6;
    let d = format!(
        "M {},{} H {} A {},{} 0 0,1 {},{} V {} A {},{} 0 0,1 {},{} H {} A {},{} 0 0,1 {},{} V {} A {},{} 0 0,1 {},{} z",
        g(x + rx), g(y),
        g(x + w - rx),
        g(rx), g(ry), g(x + w), g(y + ry),
        g(y + h - ry),
        g(rx), g(ry), g(x + w - rx), g(y + h),
        g(x + rx),
        g(rx), g(ry), g(x), g(y + h - ry),
        g(y + ry),
        g(rx), g(ry), g(x + rx), g(y),
    );
    path_outlines(&d, style)
}

/// A number as C++'s `ostream` prints it by default (`%g`, 6 significant digits).
fn g6(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v == 0.0 { "0".into() } else { format!("{v}") };
    }
    let sci = format!("{v:.5e}");
    let (mant, exp) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    let strip = |s: String| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    };
    if !(-4..6).contains(&exp) {
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", strip(mant.to_string()), exp.abs())
    } else {
        let decimals = (5 - exp).max(0) as usize;
        strip(format!("{v:.decimals$}"))
    }
}

/// The stroke attributes of an element, its name, and the outline points the file has left.
struct Style<'a> {
    element: &'a str,
    width: &'a str,
    cap: &'a str,
    join: &'a str,
    style: &'a str,
    left: &'a Cell<usize>,
}

#[derive(Clone, Copy, PartialEq)]
enum Cap {
    Butt,
    Square,
    Round,
}

#[derive(Clone, Copy, PartialEq)]
enum Join {
    Miter,
    Square,
    Round,
}

impl Style<'_> {
    /// A property of the `style` attribute (`name:value` between semicolons, verbatim).
    fn property(&self, name: &str) -> &str {
        for s in self.style.split(';') {
            let parts: Vec<&str> = s.split(':').collect();
            if parts.len() == 2 && parts[0] == name {
                return parts[1];
            }
        }
        ""
    }

    fn pick<'b>(&'b self, attr: &'b str, name: &str) -> &'b str {
        if attr.is_empty() {
            self.property(name)
        } else {
            attr
        }
    }

    /// `n` outline points taken from what the file has left, or the one-line refusal.
    fn spend(&self, n: usize) -> csgpix_scene::Result<()> {
        let left = self.left.get();
        if n > left {
            return Err(self.refuse(n as f64));
        }
        self.left.set(left - n);
        Ok(())
    }

    /// The error for an element whose outline needs `vertices` points, past those left.
    fn refuse(&self, vertices: f64) -> Error {
        Error::SvgVertexLimit {
            element: self.element.to_string(),
            vertices,
            left: self.left.get(),
        }
    }

    /// The outline of an open polyline's stroke (libsvg's `offset_path`), refused before it
    /// is made when its points could pass what the file has left.
    fn stroke(&self, path: &[DVec2]) -> csgpix_scene::Result<Vec<Vec<DVec2>>> {
        let w = parse_double(self.pick(self.width, "stroke-width"));
        let w = if w < 0.01 { 1.0 } else { w };
        let cap = match self.pick(self.cap, "stroke-linecap") {
            "butt" => Cap::Butt,
            "round" => Cap::Round,
            _ => Cap::Square,
        };
        let join = match self.pick(self.join, "stroke-linejoin") {
            "bevel" => Join::Square,
            "round" => Join::Round,
            _ => Join::Miter,
        };
        let bound = outline_bound(path.len(), w * 5000.0, cap, join);
        if bound > self.left.get() as f64 {
            return Err(self.refuse(bound));
        }
        let outline = open_offset(path, w, cap, join);
        self.spend(outline.iter().map(Vec::len).sum())?;
        Ok(outline)
    }
}

/// Clipper's round half away from zero.
fn round(v: f64) -> f64 {
    if v < 0.0 {
        (v - 0.5).trunc()
    } else {
        (v + 0.5).trunc()
    }
}

/// The most points [`ClipperOffset`] draws for an open path of `len` points offset by
/// `delta` (Clipper's units): at each point on each side a round join or cap's arc (at most
/// half a turn of [`ClipperOffset::new`]'s steps, plus its ends), or at most three points; a
/// single point's round outline is a whole turn.
fn outline_bound(len: usize, delta: f64, cap: Cap, join: Join) -> f64 {
    let round = cap == Cap::Round || join == Join::Round;
    let per = if round {
        (ClipperOffset::arc_steps(delta) / 2.0 + 3.0).max(3.0)
    } else {
        3.0
    };
    if len == 1 {
        return 2.0 * per;
    }
    2.0 * len as f64 * per
}

/// Clipper 6.4's `ClipperOffset` of one open path by half the stroke width, as libsvg calls
/// it: points scaled by 10⁴ and truncated to integers, the default miter limit (2) and arc
/// tolerance (0.25), then the union of the outline by the positive winding rule.
fn open_offset(path: &[DVec2], width: f64, cap: Cap, join: Join) -> Vec<Vec<DVec2>> {
    const SCALE: f64 = 10000.0;
    let mut src: Vec<DVec2> = path.iter().map(|v| (*v * SCALE).trunc()).collect();
    src.dedup();
    if src.is_empty() {
        return vec![];
    }
    let mut offset = ClipperOffset::new(&src, width * 5000.0, join);
    if src.len() == 1 {
        offset.point_outline();
    } else {
        offset.polyline_outline(cap);
    }
    let outline: Vec<[f64; 2]> = offset.dest.iter().map(|v| v.to_array()).collect();
    clean(&[outline], Fill::Positive)
        .paths
        .into_iter()
        .map(|p| p.into_iter().map(|v| v / SCALE).collect())
        .collect()
}

/// Point `p` moved by `d` along unit vector `n`, rounded to Clipper's integer grid.
fn offset_pt(p: DVec2, n: DVec2, d: f64) -> DVec2 {
    DVec2::new(round(p.x + n.x * d), round(p.y + n.y * d))
}

/// Clipper's `ClipperOffset::DoOffset` state for one open path: the scaled points, the
/// offset `delta`, the arc steps its arc tolerance gives, and the outline so far.
struct ClipperOffset<'a> {
    src: &'a [DVec2],
    delta: f64,
    join: Join,
    /// Steps in a full circle, and the sine and cosine of one step.
    steps: f64,
    m_sin: f64,
    m_cos: f64,
    steps_per_rad: f64,
    dest: Vec<DVec2>,
}

impl<'a> ClipperOffset<'a> {
    /// The steps in a full turn of an arc of radius `delta`, with arc tolerance 0.25 (at
    /// most one per unit of arc).
    fn arc_steps(delta: f64) -> f64 {
        let y = 0.25f64.min(delta.abs() * 0.25);
        let steps = std::f64::consts::PI / (1.0 - y / delta.abs()).acos();
        steps.min(delta.abs() * std::f64::consts::PI)
    }

    /// The offset state for `delta`, its arc steps from [`Self::arc_steps`].
    fn new(src: &'a [DVec2], delta: f64, join: Join) -> Self {
        let two_pi = std::f64::consts::TAU;
        let steps = Self::arc_steps(delta);
        ClipperOffset {
            src,
            delta,
            join,
            steps,
            m_sin: (two_pi / steps).sin(),
            m_cos: (two_pi / steps).cos(),
            steps_per_rad: steps / two_pi,
            dest: vec![],
        }
    }

    /// A single point's outline: a circle for round joins, else a square.
    fn point_outline(&mut self) {
        let (p, delta) = (self.src[0], self.delta);
        if self.join == Join::Round {
            let (mut x, mut yy) = (1.0, 0.0);
            let mut j = 1.0;
            while j <= self.steps {
                self.dest.push(offset_pt(p, DVec2::new(x, yy), delta));
                let x2 = x;
                x = x * self.m_cos - self.m_sin * yy;
                yy = x2 * self.m_sin + yy * self.m_cos;
                j += 1.0;
            }
        } else {
            for (x, yy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                self.dest.push(offset_pt(p, DVec2::new(x, yy), delta));
            }
        }
    }

    /// A polyline's outline: along one side, around the far end's cap, back along the
    /// other side (the normals reversed), and around the near end's cap.
    fn polyline_outline(&mut self, cap: Cap) {
        let (src, delta) = (self.src, self.delta);
        let len = src.len();
        let unit_normal = |a: DVec2, b: DVec2| {
            let d = b - a;
            if d == DVec2::ZERO {
                DVec2::ZERO
            } else {
                DVec2::new(d.y, -d.x) / d.length()
            }
        };
        let mut normals: Vec<DVec2> = (0..len - 1)
            .map(|j| unit_normal(src[j], src[j + 1]))
            .collect();
        normals.push(normals[len - 2]);
        let mut k = 0;
        for j in 1..len - 1 {
            self.offset_point(&normals, j, &mut k);
        }
        let j = len - 1;
        if cap == Cap::Butt {
            self.dest.push(offset_pt(src[j], normals[j], delta));
            self.dest.push(offset_pt(src[j], normals[j], -delta));
        } else {
            normals[j] = -normals[j];
            self.cap(cap, &normals, j, len - 2);
        }
        for j in (1..len).rev() {
            normals[j] = -normals[j - 1];
        }
        normals[0] = -normals[1];
        k = len - 1;
        for j in (1..len - 1).rev() {
            self.offset_point(&normals, j, &mut k);
        }
        if cap == Cap::Butt {
            self.dest.push(offset_pt(src[0], normals[0], -delta));
            self.dest.push(offset_pt(src[0], normals[0], delta));
        } else {
            self.cap(cap, &normals, 0, 1);
        }
    }

    /// A square or round cap at end `j` (`k` its neighbour), as Clipper draws it with
    /// `sinA` 0.
    fn cap(&mut self, cap: Cap, n: &[DVec2], j: usize, k: usize) {
        if cap == Cap::Square {
            self.do_square(n, j, k, 0.0);
        } else {
            self.do_round(n, j, k, 0.0);
        }
    }

    /// Clipper's `DoSquare`: the corner at point `j` cut square at distance `delta`.
    fn do_square(&mut self, n: &[DVec2], j: usize, k: usize, sin_a: f64) {
        let delta = self.delta;
        let dx = (sin_a.atan2(n[k].dot(n[j])) / 4.0).tan();
        let p = self.src[j];
        self.dest.push(DVec2::new(
            round(p.x + delta * (n[k].x - n[k].y * dx)),
            round(p.y + delta * (n[k].y + n[k].x * dx)),
        ));
        self.dest.push(DVec2::new(
            round(p.x + delta * (n[j].x + n[j].y * dx)),
            round(p.y + delta * (n[j].y - n[j].x * dx)),
        ));
    }

    /// Clipper's `DoRound`: an arc around point `j` from normal `k` to normal `j`.
    fn do_round(&mut self, n: &[DVec2], j: usize, k: usize, sin_a: f64) {
        let a = sin_a.atan2(n[k].dot(n[j]));
        let steps = (round(self.steps_per_rad * a.abs()) as i64).max(1);
        let (mut x, mut yy) = (n[k].x, n[k].y);
        for _ in 0..steps {
            self.dest
                .push(offset_pt(self.src[j], DVec2::new(x, yy), self.delta));
            let x2 = x;
            x = x * self.m_cos - self.m_sin * yy;
            yy = x2 * self.m_sin + yy * self.m_cos;
        }
        self.dest.push(offset_pt(self.src[j], n[j], self.delta));
    }

    /// Clipper's `OffsetPoint`: the join at point `j` between the edges with normals `k`
    /// and `j` (`k` becomes `j` unless the point is skipped).
    fn offset_point(&mut self, n: &[DVec2], j: usize, k: &mut usize) {
        let (src, delta) = (self.src, self.delta);
        let mut sin_a = n[*k].x * n[j].y - n[j].x * n[*k].y;
        if (sin_a * delta).abs() < 1.0 {
            if n[*k].dot(n[j]) > 0.0 {
                self.dest.push(offset_pt(src[j], n[*k], delta));
                return;
            }
        } else {
            sin_a = sin_a.clamp(-1.0, 1.0);
        }
        if sin_a * delta < 0.0 {
            self.dest.push(offset_pt(src[j], n[*k], delta));
            self.dest.push(src[j]);
            self.dest.push(offset_pt(src[j], n[j], delta));
        } else {
            match self.join {
                Join::Miter => {
                    const MITER_LIM: f64 = 0.5;
                    let r = 1.0 + n[j].dot(n[*k]);
                    if r >= MITER_LIM {
                        let q = delta / r;
                        self.dest.push(DVec2::new(
                            round(src[j].x + (n[*k].x + n[j].x) * q),
                            round(src[j].y + (n[*k].y + n[j].y) * q),
                        ));
                    } else {
                        self.do_square(n, j, *k, sin_a);
                    }
                }
                Join::Square => self.do_square(n, j, *k, sin_a),
                Join::Round => self.do_round(n, j, *k, sin_a),
            }
        }
        *k = j;
    }
}

/// libsvg's `path`: its `d` read token by token as libsvg does (boost tokens apart by spaces
/// and commas, each command letter and `-` a token of its own), each subpath a list of
/// points; open subpaths become their strokes.
fn path_outlines(d: &str, style: &Style) -> csgpix_scene::Result<Vec<Vec<DVec2>>> {
    let mut toks: Vec<String> = vec![];
    for t in tokens(d, |c| c.is_whitespace() || c == ',', PATH_COMMANDS) {
        toks.extend(split_dots(t));
    }
    let mut list: Vec<Vec<DVec2>> = vec![vec![]];
    let mut pen = PathPen::new();
    let mut number = PathNumber::default();
    for v in &toks {
        let p = if v.len() == 1 && PATH_COMMANDS.contains(v.as_str()) {
            if v == "-" {
                number.negate = true;
                continue;
            }
            pen.point = -1;
            pen.cmd = v.chars().next().unwrap_or(' ');
            0.0
        } else {
            match number.read(v) {
                Some(p) => p,
                None => continue,
            }
        };
        pen.step(&mut list, style, p)?;
    }
    while list.last().is_some_and(|p| p.is_empty()) {
        list.pop();
    }
    if !pen.closed {
        if let Some(last) = list.last() {
            if subpath_is_open(last) {
                let open = list.pop().expect("the last subpath");
                list.extend(style.stroke(&open)?);
            }
        }
    }
    Ok(list)
}

/// The tokens of a path's `d` that are tokens of their own: the command letters and `-`.
const PATH_COMMANDS: &str = "-zmlcqahvstZMLCQAHVST";

/// Whether a subpath is open in libsvg's sense: its ends more than 0.1 apart.
fn subpath_is_open(p: &[DVec2]) -> bool {
    p[0].distance(p[p.len() - 1]) > 0.1
}

/// libsvg's reading of a number token: a `-` token before it negates it, and a token ending
/// in `e` is an exponent's mantissa that is glued to the next number token.
#[derive(Default)]
struct PathNumber {
    /// A `-` token came last.
    negate: bool,
    /// The pending mantissa (with its sign) of a number written with an exponent.
    exp: String,
}

impl PathNumber {
    /// The value of number token `v`, or `None` when `v` is a mantissa awaiting its
    /// exponent.
    fn read(&mut self, v: &str) -> Option<f64> {
        if v.ends_with('e') {
            self.exp = if self.negate {
                format!("-{v}")
            } else {
                v.to_string()
            };
            self.negate = false;
            return None;
        }
        let p = if self.exp.is_empty() {
            let p = parse_double(v);
            if self.negate {
                -p
            } else {
                p
            }
        } else {
            let sign = if self.negate { "-" } else { "" };
            let p = parse_double(&format!("{}{sign}{v}", self.exp));
            self.exp.clear();
            p
        };
        self.negate = false;
        Some(p)
    }
}

/// libsvg's path reader between tokens: the command in force, which of its parameters comes
/// next, the parameters read so far and the current point.
struct PathPen {
    /// The command in force (a repeated command needs no new letter).
    cmd: char,
    /// The index of the command's next parameter.
    point: i32,
    /// The current point.
    x: f64,
    y: f64,
    /// The end point's x, read before its y.
    xx: f64,
    /// An arc's radii, rotation and flags.
    rx: f64,
    ry: f64,
    angle: f64,
    large: bool,
    sweep: bool,
    /// A Bézier's control points.
    cx1: f64,
    cy1: f64,
    cx2: f64,
    cy2: f64,
    /// Whether the last segment was a cubic or a quadratic (for `s` and `t` reflections).
    last_cubic: bool,
    last_quad: bool,
    /// A `z` was read.
    closed: bool,
}

impl PathPen {
    fn new() -> Self {
        PathPen {
            cmd: ' ',
            point: 0,
            x: 0.0,
            y: 0.0,
            xx: 0.0,
            rx: 0.0,
            ry: 0.0,
            angle: 0.0,
            large: false,
            sweep: false,
            cx1: 0.0,
            cy1: 0.0,
            cx2: 0.0,
            cy2: 0.0,
            last_cubic: false,
            last_quad: false,
            closed: false,
        }
    }

    /// Parameter `p` of the command in force (0 for a command letter itself), applied to
    /// the subpaths `list` (whose last is the current one).
    fn step(
        &mut self,
        list: &mut Vec<Vec<DVec2>>,
        style: &Style,
        p: f64,
    ) -> csgpix_scene::Result<()> {
        let rel = self.cmd.is_ascii_lowercase();
        let back = list.last_mut().expect("a current subpath");
        match self.cmd.to_ascii_lowercase() {
            'a' => self.arc(back, rel, p)?,
            'l' => self.line(back, rel, p),
            'c' => self.cubic(back, rel, p),
            's' => self.smooth_cubic(back, rel, p),
            'q' => self.quadratic(back, rel, p),
            't' => self.smooth_quadratic(back, rel, p),
            'm' => self.move_to(list, style, rel, p)?,
            'v' if self.point == 0 => {
                self.y = if rel { self.y + p } else { p };
                back.push(DVec2::new(self.x, self.y));
                self.end_segment(self.x, self.y, false, false);
            }
            'h' if self.point == 0 => {
                self.x = if rel { self.x + p } else { p };
                back.push(DVec2::new(self.x, self.y));
                self.end_segment(self.x, self.y, false, false);
            }
            'z' => self.close(list),
            _ => {}
        }
        self.point += 1;
        Ok(())
    }

    /// The absolute x of coordinate `p`.
    fn abs_x(&self, rel: bool, p: f64) -> f64 {
        if rel {
            self.x + p
        } else {
            p
        }
    }

    /// The absolute y of coordinate `p`.
    fn abs_y(&self, rel: bool, p: f64) -> f64 {
        if rel {
            self.y + p
        } else {
            p
        }
    }

    /// A segment drawn: the pen moves to its end and the command may repeat.
    fn end_segment(&mut self, x: f64, y: f64, cubic: bool, quad: bool) {
        (self.x, self.y) = (x, y);
        self.point = -1;
        (self.last_cubic, self.last_quad) = (cubic, quad);
    }

    /// `A rx ry angle large sweep x y`: an elliptical arc.
    fn arc(&mut self, back: &mut Vec<DVec2>, rel: bool, p: f64) -> csgpix_scene::Result<()> {
        match self.point {
            0 => self.rx = p.abs(),
            1 => self.ry = p.abs(),
            2 => self.angle = p,
            3 => self.large = p > 0.5,
            4 => self.sweep = p > 0.5,
            5 => self.xx = self.abs_x(rel, p),
            6 => {
                let yy = self.abs_y(rel, p);
                if self.rx == 0.0 || self.ry == 0.0 {
                    return Err(Error::ZeroRadiusArc);
                }
                let (x, y, xx) = (self.x, self.y, self.xx);
                let (large, sweep) = (self.large, self.sweep);
                arc_to(
                    back,
                    [x, y],
                    self.rx,
                    self.ry,
                    [xx, yy],
                    self.angle,
                    large,
                    sweep,
                );
                self.end_segment(xx, yy, false, false);
            }
            _ => {}
        }
        Ok(())
    }

    /// `L x y`: a straight line.
    fn line(&mut self, back: &mut Vec<DVec2>, rel: bool, p: f64) {
        match self.point {
            0 => self.xx = self.abs_x(rel, p),
            1 => {
                let yy = self.abs_y(rel, p);
                back.push(DVec2::new(self.xx, yy));
                self.end_segment(self.xx, yy, false, false);
            }
            _ => {}
        }
    }

    /// `C x1 y1 x2 y2 x y`: a cubic Bézier.
    fn cubic(&mut self, back: &mut Vec<DVec2>, rel: bool, p: f64) {
        match self.point {
            0 => self.cx1 = p,
            1 => self.cy1 = p,
            2 => self.cx2 = p,
            3 => self.cy2 = p,
            4 => self.xx = self.abs_x(rel, p),
            5 => {
                let yy = self.abs_y(rel, p);
                let (x, y) = (self.x, self.y);
                if rel {
                    (self.cx1, self.cy1) = (x + self.cx1, y + self.cy1);
                    (self.cx2, self.cy2) = (x + self.cx2, y + self.cy2);
                }
                let (c1, c2) = ([self.cx1, self.cy1], [self.cx2, self.cy2]);
                cubic(back, [x, y], c1, c2, [self.xx, yy]);
                self.end_segment(self.xx, yy, true, false);
            }
            _ => {}
        }
    }

    /// `S x2 y2 x y`: a cubic Bézier whose first control point mirrors the last cubic's
    /// second (or is the current point).
    fn smooth_cubic(&mut self, back: &mut Vec<DVec2>, rel: bool, p: f64) {
        let (x, y) = (self.x, self.y);
        match self.point {
            0 => {
                if self.last_cubic {
                    (self.cx1, self.cy1) = (2.0 * x - self.cx2, 2.0 * y - self.cy2);
                } else {
                    (self.cx1, self.cy1) = (x, y);
                }
                self.cx2 = p;
            }
            1 => self.cy2 = p,
            2 => self.xx = self.abs_x(rel, p),
            3 => {
                let yy = self.abs_y(rel, p);
                if rel {
                    (self.cx2, self.cy2) = (x + self.cx2, y + self.cy2);
                }
                let (c1, c2) = ([self.cx1, self.cy1], [self.cx2, self.cy2]);
                cubic(back, [x, y], c1, c2, [self.xx, yy]);
                self.end_segment(self.xx, yy, true, false);
            }
            _ => {}
        }
    }

    /// `Q x1 y1 x y`: a quadratic Bézier.
    fn quadratic(&mut self, back: &mut Vec<DVec2>, rel: bool, p: f64) {
        match self.point {
            0 => self.cx1 = p,
            1 => self.cy1 = p,
            2 => self.xx = self.abs_x(rel, p),
            3 => {
                let yy = self.abs_y(rel, p);
                let (x, y) = (self.x, self.y);
                if rel {
                    (self.cx1, self.cy1) = (x + self.cx1, y + self.cy1);
                }
                quadratic(back, [x, y], [self.cx1, self.cy1], [self.xx, yy]);
                self.end_segment(self.xx, yy, false, true);
            }
            _ => {}
        }
    }

    /// `T x y`: a quadratic Bézier whose control point mirrors the last quadratic's (or is
    /// the current point).
    fn smooth_quadratic(&mut self, back: &mut Vec<DVec2>, rel: bool, p: f64) {
        let (x, y) = (self.x, self.y);
        match self.point {
            0 => {
                if self.last_quad {
                    (self.cx1, self.cy1) = (2.0 * x - self.cx1, 2.0 * y - self.cy1);
                } else {
                    (self.cx1, self.cy1) = (x, y);
                }
                self.xx = self.abs_x(rel, p);
            }
            1 => {
                let yy = self.abs_y(rel, p);
                quadratic(back, [x, y], [self.cx1, self.cy1], [self.xx, yy]);
                self.end_segment(self.xx, yy, false, true);
            }
            _ => {}
        }
    }

    /// `M x y`: a new subpath (the current one, if open, replaced by its stroke); further
    /// pairs are lines.
    fn move_to(
        &mut self,
        list: &mut Vec<Vec<DVec2>>,
        style: &Style,
        rel: bool,
        p: f64,
    ) -> csgpix_scene::Result<()> {
        match self.point {
            0 => self.xx = self.abs_x(rel, p),
            1 => {
                let yy = self.abs_y(rel, p);
                self.cmd = if rel { 'l' } else { 'L' };
                let back = list.last().expect("a current subpath");
                if !back.is_empty() {
                    if subpath_is_open(back) {
                        let open = list.pop().expect("the current subpath");
                        list.extend(style.stroke(&open)?);
                    }
                    list.push(vec![]);
                }
                list.last_mut()
                    .expect("a current subpath")
                    .push(DVec2::new(self.xx, yy));
                self.end_segment(self.xx, yy, false, false);
            }
            _ => {}
        }
        Ok(())
    }

    /// `Z`: the current subpath closed back to its start, and a new one begun.
    fn close(&mut self, list: &mut Vec<Vec<DVec2>>) {
        let back = list.last_mut().expect("a current subpath");
        if let Some(&first) = back.first() {
            back.push(first);
            (self.x, self.y) = (first.x, first.y);
        }
        list.push(vec![]);
        self.closed = true;
        (self.last_cubic, self.last_quad) = (false, false);
    }
}

/// libsvg's `split_dots`: a token with two or more points split before each further point
/// ("0.5.5" is 0.5 and .5).
fn split_dots(s: &str) -> Vec<String> {
    if s.matches('.').count() < 2 {
        return vec![s.to_string()];
    }
    let mut out = vec![];
    let mut text = String::new();
    let mut dot_seen = false;
    for t in tokens(s, |_| false, ".") {
        text.push_str(t);
        if t == "." {
            dot_seen = true;
        } else if dot_seen {
            out.push(std::mem::take(&mut text));
        }
    }
    out
}

/// 20 segments of a cubic Bézier (the start point left out).
fn cubic(out: &mut Vec<DVec2>, p0: [f64; 2], p1: [f64; 2], p2: [f64; 2], p3: [f64; 2]) {
    for i in 1..=20u32 {
        let a = f64::from(i) * (1.0 / 20.0);
        let t = |e: i32| (1.0 - a).powi(e);
        let f = |k: usize| {
            p0[k] * t(3) + p1[k] * 3.0 * t(2) * a + p2[k] * 3.0 * t(1) * a * a + p3[k] * a * a * a
        };
        out.push(DVec2::new(f(0), f(1)));
    }
}

/// 20 segments of a quadratic Bézier (the start point left out).
fn quadratic(out: &mut Vec<DVec2>, p0: [f64; 2], p1: [f64; 2], p2: [f64; 2]) {
    for i in 1..=20u32 {
        let a = f64::from(i) * (1.0 / 20.0);
        let t = |e: i32| (1.0 - a).powi(e);
        let f = |k: usize| p0[k] * t(2) + p1[k] * 2.0 * t(1) * a + p2[k] * a * a;
        out.push(DVec2::new(f(0), f(1)));
    }
}

/// The angle from u to v in degrees, in [0, 360).
fn vector_angle(u: DVec2, v: DVec2) -> f64 {
    let a = v.y.atan2(v.x).to_degrees() - u.y.atan2(u.x).to_degrees();
    if a < 0.0 {
        a + 360.0
    } else {
        a
    }
}

/// libsvg's `arc_to` (SVG's implementation notes F.6.5), `|Δθ|·10/180 + 4` segments, the
/// start point included.
#[allow(clippy::too_many_arguments)]
fn arc_to(
    out: &mut Vec<DVec2>,
    p1: [f64; 2],
    mut rx: f64,
    mut ry: f64,
    p2: [f64; 2],
    angle: f64,
    large: bool,
    sweep: bool,
) {
    let (cos_r, sin_r) = (cos_degrees(angle), sin_degrees(angle));
    let (dx, dy) = ((p1[0] - p2[0]) / 2.0, (p1[1] - p2[1]) / 2.0);
    let x1_ = cos_r * dx + sin_r * dy;
    let y1_ = -sin_r * dx + cos_r * dy;
    let d = (x1_ * x1_) / (rx * rx) + (y1_ * y1_) / (ry * ry);
    if d > 1.0 {
        rx = (d.sqrt() * rx).abs();
        ry = (d.sqrt() * ry).abs();
    }
    let mut t1 = rx * rx * ry * ry - rx * rx * y1_ * y1_ - ry * ry * x1_ * x1_;
    let t2 = rx * rx * y1_ * y1_ + ry * ry * x1_ * x1_;
    if t1 < 0.0 {
        t1 = 0.0;
    }
    let mut t3 = (t1 / t2).sqrt();
    if large == sweep {
        t3 = -t3;
    }
    let cx_ = t3 * rx * y1_ / ry;
    let cy_ = t3 * -ry * x1_ / rx;
    let cx = cos_r * cx_ - sin_r * cy_ + (p1[0] + p2[0]) / 2.0;
    let cy = sin_r * cx_ + cos_r * cy_ + (p1[1] + p2[1]) / 2.0;
    let u = DVec2::new((x1_ - cx_) / rx, (y1_ - cy_) / ry);
    let v = DVec2::new((-x1_ - cx_) / rx, (-y1_ - cy_) / ry);
    let theta = vector_angle(DVec2::X, u);
    let mut delta = vector_angle(u, v);
    if !sweep {
        delta -= 360.0;
    }
    let steps = (delta.abs() * 10.0 / 180.0 + 4.0) as i32;
    for a in 0..=steps {
        let phi = theta + delta * f64::from(a) / f64::from(steps);
        let xx = cos_r * cos_degrees(phi) * rx - sin_r * sin_degrees(phi) * ry;
        let yy = sin_r * cos_degrees(phi) * rx + cos_r * sin_degrees(phi) * ry;
        out.push(DVec2::new(xx + cx, yy + cy));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(p: &Poly2) -> f64 {
        p.paths
            .iter()
            .map(|c| crate::extrude::signed_area(c).abs())
            .sum::<f64>()
    }

    #[test]
    fn libsvg_number_quirks() {
        assert_eq!(split_dots("0.5.25"), vec!["0.5", ".25"]);
        assert_eq!(split_dots("1.5"), vec!["1.5"]);
        assert_eq!(g6(10.123456789), "10.1235");
        assert_eq!(g6(1234567.0), "1.23457e+06");
        assert_eq!(g6(0.00001), "1e-05");
        assert_eq!(g6(-2.5), "-2.5");
        assert_eq!(parse_double("1px"), 0.0);
        let l = parse_length(" 210mm ");
        assert_eq!((l.number, l.unit), (210.0, Unit::Mm));
        assert_eq!(parse_length("3furlongs").unit, Unit::Undefined);
        assert_eq!(
            parse_viewbox("0,0, 210 297"),
            Some([0.0, 0.0, 210.0, 297.0])
        );
        assert_eq!(parse_viewbox("0 0 -1 2"), None);
        assert_eq!(
            parse_alignment("xMaxYMin slice"),
            (Some((Align::Max, Align::Min)), false)
        );
        assert_eq!(parse_alignment("none").0, None);
        assert_eq!(
            parse_alignment("bogus"),
            (Some((Align::Mid, Align::Mid)), true)
        );
    }

    #[test]
    fn transforms_compose_as_svg() {
        let m = parse_transform("translate(10,20) rotate(90) scale(2)");
        let p = apply(&m, DVec2::new(1.0, 0.0));
        assert!((p - DVec2::new(10.0, 22.0)).length() < 1e-12, "{p}");
        let r = parse_transform("rotate(90, 5, 5)");
        assert!((apply(&r, DVec2::new(10.0, 5.0)) - DVec2::new(5.0, 10.0)).length() < 1e-12);
        // A wrong number of arguments is the identity, as in libsvg.
        assert_eq!(parse_transform("translate(1,2,3)"), IDENTITY);
    }

    #[test]
    fn path_tokens_as_libsvg() {
        let left = Cell::new(1 << 20);
        let style = Style {
            element: "path",
            width: "",
            cap: "",
            join: "",
            style: "",
            left: &left,
        };
        // Relative numbers glued by minus signs and dots, an exponent split by the tokenizer.
        let p = path_outlines("m1-1h1e1v.5.5l-10-1z", &style).unwrap();
        assert_eq!(
            p[0],
            vec![
                DVec2::new(1.0, -1.0),
                DVec2::new(11.0, -1.0),
                DVec2::new(11.0, -0.5),
                DVec2::new(11.0, 0.0),
                DVec2::new(1.0, -1.0),
                DVec2::new(1.0, -1.0),
            ]
        );
        // An open path is its stroke: width 1 and square caps by default.
        let s = path_outlines("M 0,0 L 10,0", &style).unwrap();
        let a = area(&Poly2 { paths: s });
        assert!((a - 11.0).abs() < 1e-3, "{a}");
    }

    /// 10,000 nested groups overflowed the stack (roxmltree and `walk` recurse per level):
    /// refused at the first group past 256, as libxml2 refuses them for OpenSCAD; 250 are read.
    /// Groups nested through a DTD entity, which the scan of the text does not see, are
    /// refused by `walk`.
    #[test]
    fn deep_nesting_is_one_line_not_a_stack_overflow() {
        let nested = |n: usize| {
            format!(
                "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">{}<rect \
                 width=\"5\" height=\"5\"/>{}</svg>",
                "<g>".repeat(n),
                "</g>".repeat(n)
            )
        };
        assert_eq!(
            parse(&nested(250), "t.svg", 72.0, false, 1 << 20)
                .unwrap()
                .len(),
            1
        );
        let e = parse(&nested(10_000), "t.svg", 72.0, false, 1 << 20)
            .unwrap_err()
            .to_string();
        // The <svg> start tag is level 1: the 256th <g> is the first too deep.
        let col = e.split(':').nth(2).unwrap().parse::<usize>().unwrap();
        assert!(
            e.starts_with("t.svg:1:") && e.contains("nested more than 256"),
            "{e}"
        );
        assert_eq!(col, nested(0).find("<rect").unwrap() + 1 + 255 * 3);
        assert_eq!(e.lines().count(), 1);
        let g = "<g>".repeat(200) + &"</g>".repeat(200);
        let dtd = format!(
            "<!DOCTYPE svg [<!ENTITY deep \"{g}\">]><svg xmlns=\"http://www.w3.org/2000/svg\">\
             {}&deep;{}</svg>",
            "<g>".repeat(200),
            "</g>".repeat(200)
        );
        let e = parse(&dtd, "t.svg", 72.0, false, 1 << 20)
            .unwrap_err()
            .to_string();
        assert!(e.contains("nested more than 256"), "{e}");
    }

    #[test]
    fn page_scale_and_flip() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="20mm" height="10mm"
            viewBox="0 0 200 100"><rect x="10" y="10" width="50" height="20"/></svg>"#;
        let shapes = parse(svg, "t.svg", 72.0, false, 1 << 20).unwrap();
        let pts: Vec<DVec2> = shapes[0].points().collect();
        let lo = pts.iter().fold(DVec2::MAX, |a, b| a.min(*b));
        let hi = pts.iter().fold(DVec2::MIN, |a, b| a.max(*b));
        assert!((lo - DVec2::new(1.0, 7.0)).length() < 1e-9, "{lo}");
        assert!((hi - DVec2::new(6.0, 9.0)).length() < 1e-9, "{hi}");
        let c = parse(svg, "t.svg", 72.0, true, 1 << 20).unwrap();
        let lo = c[0].points().fold(DVec2::MAX, |a, b| a.min(b));
        assert!((lo - DVec2::new(-2.5, -1.0)).length() < 1e-9, "{lo}");
        assert!(parse("<svg><svg/></svg>", "t.svg", 72.0, false, 1 << 20).is_err());
        assert!(parse("<svg viewBox='0 0 0 10'/>", "t.svg", 72.0, false, 1 << 20).is_err());
    }

    /// A stroke so wide that its round joins have more arc steps than memory holds is
    /// refused before its outline is made (the svg fuzz target's input: 2.8·10¹⁶ wide, 10²⁰
    /// steps a turn); the points the file may make are counted across its elements.
    #[test]
    fn outlines_past_the_vertex_limit_are_refused_before_they_are_made() {
        let svg = |body: &str| format!(r#"<svg xmlns="http://www.w3.org/2000/svg">{body}</svg>"#);
        let wide = svg(
            r#"<polyline points="10,25 30,40 50,25" stroke-width="27777777777777777.5"
            stroke-linejoin="round"/>"#,
        );
        let e = parse(&wide, "t.svg", 72.0, false, 1 << 20)
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("the <polyline> element's outline would have"),
            "{e}"
        );
        assert!(e.contains("(1048576 left"), "{e}");
        assert_eq!(e.lines().count(), 1);
        // A round-joined stroke 20 wide draws (its bound is above what it draws) ...
        let line = r#"<polyline points="0,0 30,40 60,0" stroke-width="20" stroke-linejoin="round"
            stroke-linecap="round"/>"#;
        let one = parse(&svg(line), "t.svg", 72.0, false, 1 << 20).unwrap();
        let drawn: usize = one[0].points().count();
        let bound = outline_bound(3, 20.0 * 5000.0, Cap::Round, Join::Round);
        assert!(
            drawn as f64 <= bound && drawn > 100,
            "{drawn} points, bound {bound}"
        );
        // ... and is refused when the budget is below that bound, even if above what it draws.
        let e = parse(&svg(line), "t.svg", 72.0, false, drawn).unwrap_err();
        assert!(e.to_string().contains("<polyline>"), "{e}");
        // Plain shapes count too: three circles of 40 points in a budget of 100.
        let circles = svg(&r#"<circle cx="0" cy="0" r="5"/>"#.repeat(3));
        assert_eq!(parse(&circles, "t.svg", 72.0, false, 120).unwrap().len(), 3);
        let e = parse(&circles, "t.svg", 72.0, false, 100)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("the <circle> element's outline would have 40 points")
                && e.contains("(20 left"),
            "{e}"
        );
    }
}
