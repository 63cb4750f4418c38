//! Mesh files read by their extension: STL and OBJ ([`TriMesh::parse`]), and OFF, AMF and 3MF
//! as OpenSCAD 2021.01 imports them (modules `off`, `amf`, `threemf`, their objects united by
//! `meshfile`). Kept apart from `trimesh` so that the mesh type does not depend on the
//! readers that make it.

use std::path::Path;

use crate::trimesh::{TriMesh, READ_EXTENSIONS};
use crate::{Error, Result};

impl TriMesh {
    /// Reads a mesh file, its format named by the extension (any case): `.stl` and `.obj`
    /// ([`TriMesh::parse`]), `.off`, `.amf` and `.3mf` as OpenSCAD 2021.01 imports them
    /// (crates/scene/src/off.rs, amf.rs, threemf.rs). Errors are one line starting with the
    /// path. What OpenSCAD would warn about, or leave out of a file, is dropped here: see
    /// [`TriMesh::read_with_warnings`].
    pub fn read(path: &Path) -> Result<TriMesh> {
        TriMesh::read_with_warnings(path).map(|(m, _)| m)
    }

    /// [`TriMesh::read`] and the warnings of the reading, each one located line (for an AMF
    /// or 3MF file: a `unit` that is not applied, a 3MF build transform or components that
    /// OpenSCAD 2021.01 does not apply, a zipped AMF's entry read by its position).
    pub fn read_with_warnings(path: &Path) -> Result<(TriMesh, Vec<Error>)> {
        let file = path.display().to_string();
        let ext = path.extension().and_then(|e| e.to_str());
        let ext = ext.map(str::to_ascii_lowercase).unwrap_or_default();
        if !READ_EXTENSIONS.contains(&ext.as_str()) {
            return Err(Error::MeshReadExtension.context(file));
        }
        let bytes = std::fs::read(path).map_err(|e| Error::io("cannot read", &e).context(&file))?;
        TriMesh::parse_format(&bytes, &file, &ext)
    }

    /// Parses the bytes of a mesh file of format `ext` (one of [`READ_EXTENSIONS`]; `file`
    /// names it in errors and warnings, and its last component names the entry of a zipped
    /// AMF), as [`TriMesh::read_with_warnings`] does.
    pub fn parse_format(bytes: &[u8], file: &str, ext: &str) -> Result<(TriMesh, Vec<Error>)> {
        let objects = match ext {
            "off" => crate::off::parse(bytes, file)?,
            "amf" => crate::amf::parse(bytes, file)?,
            "3mf" => crate::threemf::parse(bytes, file)?,
            "stl" | "obj" => return Ok((TriMesh::parse(bytes, file, ext == "obj")?, vec![])),
            _ => {
                let e = Error::UnknownMeshFormat {
                    format: ext.to_string(),
                    known: &READ_EXTENSIONS,
                };
                return Err(e.context(file));
            }
        };
        let mesh = crate::meshfile::unite(objects.parts, file)?;
        Ok((mesh, objects.warnings))
    }
}
