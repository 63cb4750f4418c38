//! AMF meshes as OpenSCAD 2021.01 imports them (`import_amf.cc`, `AmfImporter::read` and
//! `AmfImporterZIP::createXmlReader`).
//!
//! OpenSCAD follows element paths: each `/amf/object` is one PolySet; every
//! `object/mesh/vertices/vertex/coordinates` with its `x`, `y`, `z` appends a vertex to the
//! object's list, and every `object/mesh/volume/triangle` with its `v1`, `v2`, `v3` a triangle
//! of the vertices listed so far, so the volumes of an object are one surface (volumes that
//! share a face cross it twice, which parity reads as their union). Several objects are
//! united ([`crate::meshfile::unite`]). Other elements (metadata, colours, materials,
//! constellations) are ignored, and so is the `unit` attribute: 2021.01 never scales, and
//! csgpix records a warning for a unit other than millimetres.
//!
//! A file that starts as a zip archive is read from it, as OpenSCAD's build with libzip
//! does: the entry named as the file itself (directories ignored), or else the only entry,
//! with OpenSCAD's warning. Where OpenSCAD stops reading at a malformed number or indexes
//! past its vertex list, csgpix refuses with the place.

use crate::meshfile::{finite, utf8, Objects, Soup, Xml};
use crate::zipped::{is_zip, Archive};
use crate::{Error, Result};

/// Parses an AMF file, plain or zipped; `file` is its path as named in errors, whose last
/// component names the zip entry to read.
pub(crate) fn parse(bytes: &[u8], file: &str) -> Result<Objects> {
    if !is_zip(bytes) {
        return parse_xml(bytes, file, vec![]);
    }
    let mut zip = Archive::open(bytes, file)?;
    let names = zip.names();
    let base = file.rsplit(['/', '\\']).next().unwrap_or(file);
    let mut warnings = vec![];
    let entry = match names.iter().find(|n| n.rsplit('/').next() == Some(base)) {
        Some(n) => n.clone(),
        None if names.len() == 1 => {
            let guessed = Error::AmfEntryGuessed {
                expected: base.to_string(),
                read: names[0].clone(),
            };
            warnings.push(guessed.context(file));
            names[0].clone()
        }
        None => {
            return Err(Error::AmfEntryMissing {
                entries: names.len(),
                expected: base.to_string(),
            }
            .context(file))
        }
    };
    let xml = zip.read(&entry)?.unwrap_or_default();
    parse_xml(&xml, &format!("{file}[{entry}]"), warnings)
}

/// The XML document: its objects.
fn parse_xml(bytes: &[u8], file: &str, warnings: Vec<Error>) -> Result<Objects> {
    let x = Xml::parse(utf8(bytes, file)?, file)?;
    let root = x.doc.root_element();
    if root.tag_name().name() != "amf" {
        let msg = Error::WrongRootElement {
            what: "an AMF file",
            root: root.tag_name().name().to_string(),
            want: "amf",
        };
        return Err(x.error(root, msg));
    }
    let mut out = Objects {
        parts: vec![],
        warnings,
    };
    if let Some(u) = root.attribute("unit") {
        if !u.eq_ignore_ascii_case("millimeter") {
            let msg = Error::UnitIgnored {
                unit: u.to_string(),
                format: "AMF",
                whatever: true,
            };
            out.warnings.push(x.error(root, msg));
        }
    }
    for object in children(root, "object") {
        out.parts.push(object_soup(&x, object)?);
    }
    Ok(out)
}

fn children<'a, 'b>(
    n: roxmltree::Node<'a, 'b>,
    name: &'static str,
) -> impl Iterator<Item = roxmltree::Node<'a, 'b>> {
    n.children()
        .filter(move |c| c.is_element() && c.tag_name().name() == name)
}

/// One object's triangles, its vertices and triangles in document order.
fn object_soup(x: &Xml, object: roxmltree::Node) -> Result<Soup> {
    let mut vs: Vec<[f64; 3]> = vec![];
    let mut soup = Soup::new();
    for mesh in children(object, "mesh") {
        for part in mesh.children().filter(|c| c.is_element()) {
            match part.tag_name().name() {
                "vertices" => {
                    for v in children(part, "vertex") {
                        for c in children(v, "coordinates") {
                            vs.push(coordinates(x, c)?);
                        }
                    }
                }
                "volume" => {
                    for t in children(part, "triangle") {
                        soup.push(triangle(x, t, &vs)?);
                    }
                }
                _ => {}
            }
        }
    }
    Ok(soup)
}

/// `<coordinates><x>…</x><y>…</y><z>…</z></coordinates>`.
fn coordinates(x: &Xml, c: roxmltree::Node) -> Result<[f64; 3]> {
    let mut p = [0.0; 3];
    for (k, name) in ["x", "y", "z"].into_iter().enumerate() {
        let Some(e) = children(c, name).last() else {
            let msg = Error::NoChildElement {
                parent: "a vertex's <coordinates>",
                child: name,
            };
            return Err(x.error(c, msg));
        };
        let text = e.text().unwrap_or_default();
        p[k] = finite(text).ok_or_else(|| {
            x.error(
                e,
                Error::NotFiniteElement {
                    element: name,
                    text: text.trim().to_string(),
                },
            )
        })?;
    }
    Ok(p)
}

/// `<triangle><v1>…</v1><v2>…</v2><v3>…</v3></triangle>`: indices into the vertices so far.
fn triangle(x: &Xml, t: roxmltree::Node, vs: &[[f64; 3]]) -> Result<[[f64; 3]; 3]> {
    let mut tri = [[0.0; 3]; 3];
    for (k, name) in ["v1", "v2", "v3"].into_iter().enumerate() {
        let Some(e) = children(t, name).last() else {
            let msg = Error::NoChildElement {
                parent: "a <triangle>",
                child: name,
            };
            return Err(x.error(t, msg));
        };
        let text = e.text().unwrap_or_default().trim();
        let i = text.parse::<usize>().ok().filter(|&i| i < vs.len());
        tri[k] = vs[i.ok_or_else(|| {
            x.error(
                e,
                Error::ElementVertexIndex {
                    element: name,
                    count: vs.len(),
                    text: text.to_string(),
                },
            )
        })?];
    }
    Ok(tri)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::meshfile::unite;

    /// A tetrahedron in AMF, `extra` inserted in its object.
    fn tetra(extra: &str) -> String {
        let v = |x, y, z| {
            format!("<vertex><coordinates><x>{x}</x><y>{y}</y><z>{z}</z></coordinates></vertex>")
        };
        let t = |a, b, c| format!("<triangle><v1>{a}</v1><v2>{b}</v2><v3>{c}</v3></triangle>");
        format!(
            "<?xml version=\"1.0\"?>\n<amf unit=\"millimeter\">\n<object id=\"0\"><mesh>\n\
             <vertices>{}{}{}{}</vertices>\n<volume>{}{}{}{}</volume>{extra}\n</mesh></object>\n</amf>\n",
            v(0, 0, 0),
            v(1, 0, 0),
            v(0, 1, 0),
            v(0, 0, 1),
            t(0, 2, 1),
            t(0, 1, 3),
            t(0, 3, 2),
            t(1, 2, 3)
        )
    }

    fn err(text: &str) -> String {
        let e = parse(text.as_bytes(), "t.amf")
            .err()
            .expect("accepted")
            .to_string();
        assert_eq!(e.lines().count(), 1, "{e}");
        e
    }

    #[test]
    fn a_tetrahedron_reads_closed() {
        let o = parse(tetra("").as_bytes(), "t.amf").unwrap();
        assert!(o.warnings.is_empty());
        let m = unite(o.parts, "t.amf").unwrap();
        assert_eq!((m.vertices.len(), m.triangles.len()), (4, 4));
        m.check_closed("t.amf").unwrap();
        // Zipped under its own name, or as the only entry (with OpenSCAD's warning).
        let text = tetra("");
        let z = crate::zipped::testing::archive(&[("d/t.amf", text.as_bytes())]);
        let o = parse(&z, "dir/t.amf").unwrap();
        assert!(o.warnings.is_empty());
        assert_eq!(unite(o.parts, "").unwrap(), m);
        let o = parse(&z, "other.amf").unwrap();
        assert!(o.warnings[0]
            .to_string()
            .contains("its only entry `d/t.amf` is read"));
        // An entry's name is the archive's text: quoted on one line (a fuzzer's find).
        let z = crate::zipped::testing::archive(&[("d/t.\namf", text.as_bytes())]);
        let w = parse(&z, "other.amf").unwrap().warnings[0].to_string();
        assert!(w.contains("its only entry `d/t.\\namf` is read"), "{w}");
        let z2 = crate::zipped::testing::archive(&[("a", b""), ("b", b"")]);
        assert!(parse(&z2, "t.amf")
            .err()
            .unwrap()
            .to_string()
            .contains("none is named `t.amf`"));
    }

    #[test]
    fn malformed_files_are_one_line_at_their_place() {
        let e = err("<amf><object>");
        assert!(
            e.starts_with("t.amf:1:1: not well-formed XML: the root node was opened"),
            "{e}"
        );
        assert!(err("<stl/>").starts_with("t.amf:1:1: not an AMF file"));
        let e = err(&tetra("").replacen("<x>1</x>", "<x>1,5</x>", 1));
        assert!(
            e.starts_with("t.amf:4:") && e.contains("<x> must be a finite number, found \"1,5\""),
            "{e}"
        );
        let e = err(&tetra("").replacen("<z>1</z>", "", 1));
        assert!(e.contains("has no <z>"), "{e}");
        let e = err(&tetra("").replacen("<v3>3</v3>", "<v3>4</v3>", 1));
        assert!(
            e.contains("<v3> must index the 4 vertices listed so far (from 0), found \"4\""),
            "{e}"
        );
        let e = err(&tetra("").replacen("<v1>1</v1>", "<v1>-1</v1>", 1));
        assert!(e.contains("found \"-1\""), "{e}");
        let e = parse(b"<amf>\xff</amf>", "t.amf")
            .err()
            .unwrap()
            .to_string();
        assert!(e.starts_with("t.amf:1:6: not UTF-8"), "{e}");
    }

    #[test]
    fn deep_nesting_is_no_recursion() {
        // A million nested elements (roxmltree would recurse once per level): refused before
        // parsing, at the first start tag too deep.
        let n = 1_000_000;
        let text = format!("<amf>{}{}</amf>", "<a>".repeat(n), "</a>".repeat(n));
        let e = err(&text);
        assert!(
            e.starts_with("t.amf:1:771: elements nested more than 256 deep"),
            "{e}"
        );
        let e = err(&format!("<amf>{}</amf>", "<a b='>'>".repeat(n)));
        assert!(e.contains("nested more than 256 deep"), "{e}");
        // 255 levels, self-closing tags, comments and CDATA do not count.
        let ok = format!(
            "<amf>{}<a/><!--<a>--><![CDATA[<a>]]>{}</amf>",
            "<a>".repeat(254),
            "</a>".repeat(254)
        );
        assert!(parse(ok.as_bytes(), "t.amf").unwrap().parts.is_empty());
        // A DTD (whose entities could nest elements unseen) is refused.
        let e = err("<!DOCTYPE amf [<!ENTITY e \"<a/>\">]><amf>&e;</amf>");
        assert!(
            e.starts_with("t.amf:1:1: not well-formed XML: XML with DTD detected"),
            "{e}"
        );
    }

    #[test]
    fn units_and_several_objects() {
        let inch = tetra("").replacen("millimeter", "inch", 1);
        let o = parse(inch.as_bytes(), "t.amf").unwrap();
        let w = o.warnings[0].to_string();
        assert!(w.starts_with("t.amf:2:1: unit \"inch\" is ignored"), "{w}");
        // Two overlapping tetrahedra: united, not XOR'd.
        let text = tetra("");
        let obj = &text[text.find("<object").unwrap()..text.find("</amf>").unwrap()];
        let moved = obj
            .replace("<x>0</x>", "<x>0.25</x>")
            .replace("<x>1</x>", "<x>1.25</x>");
        // Facing inward (v2 and v3 swapped): united as a solid all the same, as by CGAL.
        let moved = moved
            .replace("v2>", "vX>")
            .replace("v3>", "v2>")
            .replace("vX>", "v3>");
        let two = text.replacen("</amf>", &format!("{moved}</amf>"), 1);
        let o = parse(two.as_bytes(), "t.amf").unwrap();
        assert_eq!(o.parts.len(), 2);
        let m = unite(o.parts, "t.amf").unwrap();
        m.check_closed("t.amf").unwrap();
        let (lo, hi) = m.bounds();
        assert_eq!((lo.x, hi.x), (0.0, 1.25));
        // The union's volume (divergence theorem): two tetrahedra of 1/6 overlapping in one
        // scaled by 3/4.
        let vol: f64 = m
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| m.vertices[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum();
        let want = 2.0 / 6.0 - 0.75f64.powi(3) / 6.0;
        assert!((vol - want).abs() < 1e-9, "{vol} for {want}");
    }
}
