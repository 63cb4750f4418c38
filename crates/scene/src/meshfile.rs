//! What the OFF, AMF and 3MF readers (modules `off`, `amf`, `threemf`)
//! share: a file's objects united into one [`TriMesh`] as OpenSCAD 2021.01 unites them, its
//! warnings, and XML documents whose errors are located `FILE:LINE:COL`.

use boolmesh::prelude::{compute_boolean, Manifold, OpType};
use glam::DVec3;

use crate::trimesh::TriMesh;
use crate::{Error, Result};

/// A triangle soup: one object of a mesh file.
pub(crate) type Soup = Vec<[[f64; 3]; 3]>;

/// What a reader found in a file: its objects (each a triangle soup) and what it noticed but
/// read anyway, as OpenSCAD goes on after a warning (each a located one-line [`Error`]).
#[derive(Default)]
pub(crate) struct Objects {
    pub(crate) parts: Vec<Soup>,
    pub(crate) warnings: Vec<Error>,
}

/// The most nodes (elements, texts, comments) an XML mesh file may have: a DOM takes about
/// 100 bytes per node, so this bounds the document at about 1.6 GB (an AMF of some two
/// million triangles, a 3MF of some eight million).
pub const MAX_XML_NODES: u32 = 1 << 24;

/// The union of the objects, as OpenSCAD 2021.01 forms it when a file has several
/// (`import_amf.cc`, `AmfImporter::read`, and `import_3mf.cc`, `import_3mf`: a CGAL Nef union
/// of one PolySet per object). Objects whose bounding boxes share no interior are united by
/// putting their triangles together (parity then gives the union exactly); overlapping ones
/// through boolmesh, which needs each to be a closed manifold. Empty objects add nothing.
pub(crate) fn unite(parts: Vec<Soup>, file: &str) -> Result<TriMesh> {
    let parts: Vec<Soup> = parts.into_iter().filter(|p| !p.is_empty()).collect();
    let boxes: Vec<(DVec3, DVec3)> = parts.iter().map(bounds).collect();
    let overlap = boxes.iter().enumerate().any(|(i, a)| {
        boxes[..i]
            .iter()
            .any(|b| a.0.cmplt(b.1).all() && b.0.cmplt(a.1).all())
    });
    if !overlap {
        return Ok(TriMesh::from_f64(&parts.concat()));
    }
    let fail = |e: String| {
        let e = Error::UnionFailed {
            objects: parts.len(),
            reason: e,
        };
        e.context(file)
    };
    let mut acc: Option<Manifold> = None;
    for p in &parts {
        // Outward, as CGAL's Nef polyhedron takes a closed surface whichever way it faces;
        // boolmesh reads an inward surface as a hole and its union goes wrong.
        let inward = signed_volume(p) < 0.0;
        let pos: Vec<f64> = p
            .iter()
            .flat_map(|&[a, b, c]| if inward { [a, c, b] } else { [a, b, c] })
            .flatten()
            .collect();
        let idx: Vec<usize> = (0..p.len() * 3).collect();
        let m = Manifold::new(&pos, &idx).map_err(fail)?;
        acc = Some(match acc {
            None => m,
            Some(a) => compute_boolean(&a, &m, OpType::Add).map_err(fail)?,
        });
    }
    let Some(m) = acc else {
        return Ok(TriMesh::default());
    };
    let p = |i: usize| {
        let q = m.ps[i];
        [q.x, q.y, q.z]
    };
    let tris: Soup =
        m.hs.chunks_exact(3)
            .map(|h| [p(h[0].tail), p(h[1].tail), p(h[2].tail)])
            .collect();
    Ok(TriMesh::from_f64(&tris))
}

/// The volume a closed surface bounds, negative when its triangles face inward (the
/// divergence theorem over the triangles' cones from the origin).
fn signed_volume(p: &Soup) -> f64 {
    p.iter()
        .map(|t| {
            let [a, b, c] = t.map(DVec3::from);
            a.dot(b.cross(c)) / 6.0
        })
        .sum()
}

fn bounds(p: &Soup) -> (DVec3, DVec3) {
    p.iter()
        .flatten()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(DVec3::from(v)), hi.max(DVec3::from(v)))
        })
}

/// An XML document of a mesh file, named `file` in its errors.
pub(crate) struct Xml<'a> {
    pub(crate) doc: roxmltree::Document<'a>,
    pub(crate) file: &'a str,
}

impl<'a> Xml<'a> {
    /// Parses `text`; a syntax error, more than [`MAX_XML_NODES`] nodes or elements nested
    /// deeper than [`MAX_XML_DEPTH`] is one line at its place. roxmltree's tokenizer recurses
    /// once per nested element, so the depth is measured first ([`nesting`]); a DTD is
    /// refused, since its entities could hold nesting that scan does not see (mesh files
    /// have none).
    pub(crate) fn parse(text: &'a str, file: &'a str) -> Result<Xml<'a>> {
        check_xml_nesting(text, file)?;
        let opts = roxmltree::ParsingOptions {
            allow_dtd: false,
            nodes_limit: MAX_XML_NODES,
        };
        let doc = roxmltree::Document::parse_with_options(text, opts).map_err(|e| {
            let p = e.pos();
            let problem = match e {
                roxmltree::Error::NodesLimitReached => Error::TooManyXmlNodes {
                    limit: MAX_XML_NODES,
                },
                e => Error::NotWellFormedXml {
                    reason: e.to_string(),
                },
            };
            Error::at(file, p.row as usize, p.col as usize, problem)
        })?;
        Ok(Xml { doc, file })
    }

    /// `problem` at the start of `node`.
    pub(crate) fn error(&self, node: roxmltree::Node, problem: Error) -> Error {
        let p = self.doc.text_pos_at(node.range().start);
        Error::at(self.file, p.row as usize, p.col as usize, problem)
    }
}

/// How deep XML elements may nest (an AMF mesh needs 7; libxml2, OpenSCAD's SVG parser,
/// refuses deeper than 256 too: "Excessive depth in document").
pub const MAX_XML_DEPTH: usize = 256;

/// Elements nested deeper than [`MAX_XML_DEPTH`] in the XML `text` (named `file`) are one line
/// at the first such start tag. roxmltree's tokenizer recurses once per nested element (10,000
/// levels overflow the stack), so every XML reader measures the depth first.
pub fn check_xml_nesting(text: &str, file: &str) -> Result<()> {
    let Some(at) = nesting(text.as_bytes(), MAX_XML_DEPTH) else {
        return Ok(());
    };
    let good = &text.as_bytes()[..at];
    let line = good.iter().filter(|&&b| b == b'\n').count() + 1;
    let last = good.rsplit(|&b| b == b'\n').next().unwrap_or_default();
    let col = String::from_utf8_lossy(last).chars().count() + 1;
    let problem = Error::TooDeep {
        limit: MAX_XML_DEPTH,
    };
    Err(Error::at(file, line, col, problem))
}

/// The byte offset of the first start tag nested deeper than `max`, if any. Comments, CDATA,
/// processing instructions and quoted attribute values are skipped as XML reads them, so on a
/// well-formed prefix the depth is the parser's.
fn nesting(b: &[u8], max: usize) -> Option<usize> {
    let find = |from: usize, pat: &[u8]| {
        b[from..]
            .windows(pat.len())
            .position(|w| w == pat)
            .map_or(b.len(), |i| from + i + pat.len())
    };
    let (mut i, mut depth) = (0, 0usize);
    while i < b.len() {
        if b[i] != b'<' {
            i += 1;
            continue;
        }
        let rest = &b[i..];
        if rest.starts_with(b"<!--") {
            i = find(i + 4, b"-->");
        } else if rest.starts_with(b"<![CDATA[") {
            i = find(i + 9, b"]]>");
        } else if rest.starts_with(b"<?") {
            i = find(i + 2, b"?>");
        } else if rest.starts_with(b"</") {
            depth = depth.saturating_sub(1);
            i = find(i + 2, b">");
        } else {
            let start = i;
            let mut quote = None;
            i += 1;
            while i < b.len() && !(quote.is_none() && b[i] == b'>') {
                match (quote, b[i]) {
                    (None, q @ (b'"' | b'\'')) => quote = Some(q),
                    (Some(q), c) if c == q => quote = None,
                    _ => {}
                }
                i += 1;
            }
            if b.get(i.wrapping_sub(1)) != Some(&b'/') {
                depth += 1;
                if depth > max {
                    return Some(start);
                }
            }
            i += 1;
        }
    }
    None
}

/// `bytes` as UTF-8 text (a byte-order mark dropped; OFF files are ASCII, XML ones UTF-8); an invalid byte is one line at its
/// line and column.
pub(crate) fn utf8<'a>(bytes: &'a [u8], file: &str) -> Result<&'a str> {
    let bytes = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes);
    std::str::from_utf8(bytes).map_err(|e| {
        let good = &bytes[..e.valid_up_to()];
        let line = good.iter().filter(|&&b| b == b'\n').count() + 1;
        let last = good.rsplit(|&b| b == b'\n').next().unwrap_or_default();
        // Valid UTF-8 up to here: its characters are the column.
        let col = String::from_utf8_lossy(last).chars().count() + 1;
        Error::at(file, line, col, Error::NotUtf8Text)
    })
}

/// The number a text spells (surrounding blanks allowed), if finite.
pub(crate) fn finite(s: &str) -> Option<f64> {
    s.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}
