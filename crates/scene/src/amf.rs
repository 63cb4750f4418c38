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
            let msg = format!(
                "the zipped AMF has no entry `{base}`: its only entry `{}` is read, as \
                 OpenSCAD 2021.01 does",
                names[0]
            );
            warnings.push(Error::invalid(msg).context(file));
            names[0].clone()
        }
        None => {
            return Err(Error::invalid(format!(
                "{file}: the zipped AMF has {} entries and none is named `{base}`: OpenSCAD \
                 reads the entry named as the archive",
                names.len()
            )))
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
        let msg = format!(
            "not an AMF file: its root element is <{}>, not <amf>",
            root.tag_name().name()
        );
        return Err(x.error(root, msg));
    }
    let mut out = Objects {
        parts: vec![],
        warnings,
    };
    if let Some(u) = root.attribute("unit") {
        if !u.eq_ignore_ascii_case("millimeter") {
            let msg = format!(
                "unit \"{u}\" is ignored: OpenSCAD 2021.01 reads AMF coordinates as \
                 millimetres, whatever the unit"
            );
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
            return Err(x.error(c, format!("a vertex's <coordinates> has no <{name}>")));
        };
        let text = e.text().unwrap_or_default();
        p[k] = finite(text).ok_or_else(|| {
            x.error(e, format!("<{name}> must be a finite number, found \"{}\"", text.trim()))
        })?;
    }
    Ok(p)
}

/// `<triangle><v1>…</v1><v2>…</v2><v3>…</v3></triangle>`: indices into the vertices so far.
fn triangle(x: &Xml, t: roxmltree::Node, vs: &[[f64; 3]]) -> Result<[[f64; 3]; 3]> {
    let mut tri = [[0.0; 3]; 3];
    for (k, name) in ["v1", "v2", "v3"].into_iter().enumerate() {
        let Some(e) = children(t, name).last() else {
            return Err(x.error(t, format!("a <triangle> has no <{name}>")));
        };
        let text = e.text().unwrap_or_default().trim();
        let i = text.parse::<usize>().ok().filter(|&i| i < vs.len());
        tri[k] = vs[i.ok_or_else(|| {
            x.error(
                e,
                format!(
                    "<{name}> must index the {} vertices listed so far (from 0), found \"{text}\"",
                    vs.len()
                ),
            )
        })?];
    }
    Ok(tri)
}
