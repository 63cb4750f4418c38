//! 3MF meshes as OpenSCAD 2021.01 imports them (`import_3mf.cc`, `import_3mf`, through
//! lib3mf 1.8): every mesh object of the model's resources is taken once, as defined, and
//! several are united ([`crate::meshfile::unite`]).
//!
//! A 3MF file is a zip archive ([`crate::zipped`]); its model is the part `_rels/.rels` names
//! with the 3D-model relationship (`3D/3dmodel.model` when there is no `.rels`). In it,
//! `<resources><object><mesh><vertices><vertex x y z/>…<triangles><triangle v1 v2 v3/>` are the
//! meshes. lib3mf keeps coordinates as 32-bit floats, so they are rounded to `f32` here too.
//!
//! What OpenSCAD 2021.01 leaves out, csgpix leaves out too, with a warning where the geometry
//! would differ from the file's intent: the `<build>` (its items' `transform`s are not
//! applied, and an object is imported once whether the build places it never or many times),
//! component objects (`<components>`, whose meshes are imported where their own objects define
//! them), and the model's `unit` (never scaled to millimetres). Where lib3mf refuses the
//! file (an index past the vertices, a build item naming no object), OpenSCAD imports nothing
//! and csgpix refuses with the place.

use std::collections::HashSet;

use crate::meshfile::{finite, utf8, Objects, Soup, Xml};
use crate::zipped::Archive;
use crate::{Error, Result};

/// The relationship type of a 3MF package's model part.
const MODEL_REL: &str = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";

/// Parses a 3MF package.
pub(crate) fn parse(bytes: &[u8], file: &str) -> Result<Objects> {
    let mut zip = Archive::open(bytes, file)?;
    let path = match zip.read("_rels/.rels")? {
        Some(rels) => model_path(&rels, &format!("{file}[_rels/.rels]"))?,
        None => "3D/3dmodel.model".to_string(),
    };
    let Some(model) = zip.read(&path)? else {
        return Err(Error::No3mfModel { part: path }.context(file));
    };
    parse_model(&model, &format!("{file}[{path}]"))
}

/// The model part `_rels/.rels` names (without its leading `/`).
fn model_path(rels: &[u8], file: &str) -> Result<String> {
    let x = Xml::parse(utf8(rels, file)?, file)?;
    x.doc
        .descendants()
        .filter(|n| n.tag_name().name() == "Relationship")
        .find(|n| n.attribute("Type") == Some(MODEL_REL))
        .and_then(|n| n.attribute("Target"))
        .map(|t| t.trim_start_matches('/').to_string())
        .ok_or_else(|| {
            let root = x.doc.root_element();
            x.error(root, Error::No3mfModelRelationship)
        })
}

/// The model document: its mesh objects, and warnings for what OpenSCAD leaves out.
pub(crate) fn parse_model(bytes: &[u8], file: &str) -> Result<Objects> {
    let x = Xml::parse(utf8(bytes, file)?, file)?;
    let root = x.doc.root_element();
    if root.tag_name().name() != "model" {
        let msg = Error::WrongRootElement {
            what: "a 3MF model",
            root: root.tag_name().name().to_string(),
            want: "model",
        };
        return Err(x.error(root, msg));
    }
    let mut out = Objects::default();
    if let Some(u) = root.attribute("unit").filter(|u| *u != "millimeter") {
        let msg = Error::UnitIgnored {
            unit: u.to_string(),
            format: "3MF",
            whatever: false,
        };
        out.warnings.push(x.error(root, msg));
    }
    let mut ids = HashSet::new();
    let mut component = None;
    for res in children(root, "resources") {
        for object in children(res, "object") {
            ids.insert(object.attribute("id").unwrap_or_default());
            for mesh in children(object, "mesh") {
                out.parts.push(mesh_soup(&x, mesh)?);
            }
            component = component.or(children(object, "components").next());
        }
    }
    if let Some(c) = component {
        let msg = Error::NotApplied {
            what: "components are",
        };
        out.warnings.push(x.error(c, msg));
    }
    build(&x, root, &ids, &mut out.warnings)?;
    Ok(out)
}

fn children<'a, 'b>(
    n: roxmltree::Node<'a, 'b>,
    name: &'static str,
) -> impl Iterator<Item = roxmltree::Node<'a, 'b>> {
    n.children()
        .filter(move |c| c.is_element() && c.tag_name().name() == name)
}

/// The build's items must name objects (lib3mf refuses the file otherwise); a transform other
/// than the identity gets a warning, since OpenSCAD does not apply it.
fn build(
    x: &Xml,
    root: roxmltree::Node,
    ids: &HashSet<&str>,
    warnings: &mut Vec<Error>,
) -> Result<()> {
    let mut moved = None;
    for item in children(root, "build").flat_map(|b| children(b, "item")) {
        let id = item.attribute("objectid").unwrap_or_default();
        if !ids.contains(id) {
            let msg = Error::UndefinedObject { id: id.to_string() };
            return Err(x.error(item, msg));
        }
        let identity = "1 0 0 0 1 0 0 0 1 0 0 0";
        let t = item.attribute("transform").unwrap_or(identity);
        let numbers: Vec<Option<f64>> = t.split_whitespace().map(finite).collect();
        let same = numbers.len() == 12
            && numbers
                .iter()
                .zip(identity.split(' ').map(finite))
                .all(|(a, b)| *a == b);
        if !same && moved.is_none() {
            moved = Some(item);
        }
    }
    if let Some(item) = moved {
        let msg = Error::NotApplied {
            what: "the build item's transform is",
        };
        warnings.push(x.error(item, msg));
    }
    Ok(())
}

/// One `<mesh>`: its triangles.
fn mesh_soup(x: &Xml, mesh: roxmltree::Node) -> Result<Soup> {
    let mut vs: Vec<[f64; 3]> = vec![];
    for v in children(mesh, "vertices").flat_map(|n| children(n, "vertex")) {
        let mut p = [0.0; 3];
        for (c, name) in p.iter_mut().zip(["x", "y", "z"]) {
            let text = v.attribute(name).ok_or_else(|| {
                let msg = Error::MissingAttribute {
                    element: "vertex",
                    attribute: name,
                };
                x.error(v, msg)
            })?;
            // lib3mf's vertices are 32-bit floats.
            *c = finite(text)
                .map(|f| f64::from(f as f32))
                .filter(|f| f.is_finite())
                .ok_or_else(|| {
                    x.error(
                        v,
                        Error::NotFiniteAttribute {
                            attribute: name,
                            text: text.to_string(),
                        },
                    )
                })?;
        }
        vs.push(p);
    }
    let mut soup = Soup::new();
    for t in children(mesh, "triangles").flat_map(|n| children(n, "triangle")) {
        let mut tri = [[0.0; 3]; 3];
        for (c, name) in tri.iter_mut().zip(["v1", "v2", "v3"]) {
            let text = t.attribute(name).unwrap_or_default();
            let i = text.trim().parse::<usize>().ok().filter(|&i| i < vs.len());
            *c = vs[i.ok_or_else(|| {
                let n = vs.len();
                x.error(
                    t,
                    Error::AttributeVertexIndex {
                        attribute: name,
                        text: text.to_string(),
                        count: n,
                    },
                )
            })?];
        }
        soup.push(tri);
    }
    Ok(soup)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::meshfile::unite;
    use crate::zipped::testing::archive;

    const RELS: &str = "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">\
        <Relationship Target=\"/3D/m.model\" Id=\"r\" Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/>\
        </Relationships>";

    fn model(extra: &str, build: &str) -> String {
        format!(
            "<?xml version=\"1.0\"?>\n<model unit=\"millimeter\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n\
             <resources>\n<object id=\"1\" type=\"model\"><mesh><vertices>\n\
             <vertex x=\"0\" y=\"0\" z=\"0\"/><vertex x=\"0.1\" y=\"0\" z=\"0\"/>\n\
             <vertex x=\"0\" y=\"1\" z=\"0\"/><vertex x=\"0\" y=\"0\" z=\"1\"/>\n\
             </vertices><triangles>\n\
             <triangle v1=\"0\" v2=\"2\" v3=\"1\"/><triangle v1=\"0\" v2=\"1\" v3=\"3\"/>\n\
             <triangle v1=\"0\" v2=\"3\" v3=\"2\"/><triangle v1=\"1\" v2=\"2\" v3=\"3\"/>\n\
             </triangles></mesh></object>{extra}\n</resources>\n<build>{build}</build>\n</model>\n"
        )
    }

    fn err(text: &str) -> String {
        let e = parse_model(text.as_bytes(), "t.3mf[m]")
            .err()
            .expect("accepted")
            .to_string();
        assert_eq!(e.lines().count(), 1, "{e}");
        e
    }

    #[test]
    fn a_package_reads_its_model_part() {
        let m = model("", "<item objectid=\"1\"/>");
        let z = archive(&[
            ("_rels/.rels", RELS.as_bytes()),
            ("3D/m.model", m.as_bytes()),
        ]);
        let o = parse(&z, "t.3mf").unwrap();
        assert!(o.warnings.is_empty());
        let mesh = unite(o.parts, "t.3mf").unwrap();
        mesh.check_closed("t.3mf").unwrap();
        // lib3mf's 32-bit floats.
        assert!(mesh.vertices.iter().any(|v| v.x == f64::from(0.1f32)));
        // Without .rels, the usual part; without either, one line.
        let z = archive(&[("3D/3dmodel.model", m.as_bytes())]);
        assert_eq!(unite(parse(&z, "t.3mf").unwrap().parts, "").unwrap(), mesh);
        let z = archive(&[("_rels/.rels", RELS.as_bytes())]);
        let e = parse(&z, "t.3mf").err().unwrap().to_string();
        assert_eq!(e, "t.3mf: the 3MF package has no model part `3D/m.model`");
        let z = archive(&[("_rels/.rels", b"<Relationships/>")]);
        let e = parse(&z, "t.3mf").err().unwrap().to_string();
        assert!(
            e.starts_with("t.3mf[_rels/.rels]:1:1: no relationship"),
            "{e}"
        );
        let e = parse(b"solid x", "t.3mf").err().unwrap().to_string();
        assert!(e.starts_with("t.3mf: not a readable zip archive"), "{e}");
    }

    #[test]
    fn what_openscad_leaves_out_is_a_warning() {
        let comp = "<object id=\"2\"><components><component objectid=\"1\"/></components></object>";
        let m = model(
            comp,
            "<item objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 5 0 0\"/><item objectid=\"2\"/>",
        );
        let o = parse_model(m.replacen("millimeter", "inch", 1).as_bytes(), "t.3mf[m]").unwrap();
        let w: Vec<String> = o.warnings.iter().map(|w| w.to_string()).collect();
        assert!(
            w[0].starts_with("t.3mf[m]:2:1: unit \"inch\" is ignored"),
            "{w:?}"
        );
        assert!(
            w[1].starts_with("t.3mf[m]:10:44: components are not applied"),
            "{w:?}"
        );
        assert!(
            w[2].starts_with("t.3mf[m]:12:8: the build item's transform"),
            "{w:?}"
        );
        assert_eq!(o.parts.len(), 1);
        // An identity transform, written out, is no warning.
        let m = model(
            "",
            "<item objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 0 0 0\"/>",
        );
        assert!(parse_model(m.as_bytes(), "t").unwrap().warnings.is_empty());
    }

    #[test]
    fn malformed_models_are_one_line_at_their_place() {
        let good = model("", "<item objectid=\"1\"/>");
        assert!(err("<model>").starts_with("t.3mf[m]:1:1: not well-formed XML"));
        assert!(err("<amf/>").starts_with("t.3mf[m]:1:1: not a 3MF model"));
        let e = err(&good.replacen("v3=\"3\"", "v3=\"4\"", 1));
        assert!(
            e.starts_with("t.3mf[m]:8:33: ")
                && e.contains("v3=\"4\" must index the mesh's 4 vertices"),
            "{e}"
        );
        let e = err(&good.replacen("x=\"0.1\"", "x=\"1e39\"", 1));
        assert!(
            e.starts_with("t.3mf[m]:5:") && e.contains("not a finite 32-bit number"),
            "{e}"
        );
        let e = err(&good.replacen(" z=\"1\"", "", 1));
        assert!(e.contains("needs its attribute z"), "{e}");
        let e = err(&good.replacen("objectid=\"1\"", "objectid=\"7\"", 1));
        assert!(
            e.starts_with("t.3mf[m]:12:8: the build item names object \"7\""),
            "{e}"
        );
    }
}
