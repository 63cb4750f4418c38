//! `--fallback openscad`: a subtree csgpix does not draw (a 2D import, a node it does not
//! know) meshed by openscad itself and drawn as a closed mesh primitive.

use csgpix_scene::Error;
use std::path::Path;

use glam::DVec3;

use csgpix_scene::trimesh::TriMesh;

use crate::extrude::Region;
use crate::subprocess::Ran;
use crate::ReadOptions;

/// OpenSCAD's outline of one 2D statement (an SVG or DXF import): the section at z = 0 of
/// its mesh of `linear_extrude(height = 2, center = true) { statement }`.
pub(crate) fn outline(statement: &str, options: &ReadOptions) -> csgpix_scene::Result<Region> {
    let wrapped = format!("linear_extrude(height = 2, center = true) {{\n{statement}\n}}\n");
    let tris = mesh(&wrapped, options)?;
    let tris: Vec<[[f64; 3]; 3]> = tris.iter().map(|t| t.map(|v| v.to_array())).collect();
    Ok(crate::project::mesh_section(&tris))
}

/// OpenSCAD's mesh of one statement of `.csg` text (its children included), in the
/// statement's own coordinates: `openscad -o sub.stl .csgpix-fallback.XXXX.csg`, the
/// statement written into the scene's directory (`options.dir`) so its relative file names
/// are found, openscad given `options.openscad_timeout`. Err is one line: openscad missing,
/// its own error, past its time, or a 2D result (which has no mesh).
pub(crate) fn mesh(
    statement: &str,
    options: &ReadOptions,
) -> csgpix_scene::Result<Vec<[DVec3; 3]>> {
    // openscad resolves a file name in a .csg relative to that file: the statement is
    // written beside the scene (a hidden file, removed after) where it can be.
    let beside = options
        .dir
        .as_deref()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let hidden = tempfile::Builder::new()
        .prefix(".csgpix-fallback.")
        .suffix(".csg")
        .tempfile_in(beside)
        .or_else(|_| tempfile::Builder::new().suffix(".csg").tempfile())
        .map_err(|e| Error::io("a temporary file", &e))?;
    let tmp = tempfile::tempdir().map_err(|e| Error::io("a temporary directory", &e))?;
    // A signal that ends the run removes both (csgpix_output::scratch).
    let _scratch = [hidden.path(), tmp.path()].map(csgpix_output::scratch);
    let (csg, stl) = (hidden.path().to_path_buf(), tmp.path().join("sub.stl"));
    std::fs::write(&csg, statement)
        .map_err(|e| Error::io(format_args!("writing {}", csg.display()), &e))?;
    let mut cmd = std::process::Command::new("openscad");
    cmd.arg("-o").arg(&stl).arg(&csg);
    let (status, stderr) = match crate::subprocess::run(&mut cmd, options.openscad_timeout) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(Error::NoOpenscad { scad: false })
        }
        Err(e) => return Err(Error::io("running openscad", &e)),
        Ok(Ran::TimedOut) => return Err(crate::export::timed_out(options.openscad_timeout)),
        Ok(Ran::Done { status, stderr }) => (status, stderr),
    };
    if !(status.success() && stl.is_file()) {
        let why = stderr
            .lines()
            .find(|l| l.contains("ERROR") || l.contains("not a 3D object"))
            .or_else(|| stderr.lines().rfind(|l| !l.trim().is_empty()))
            .unwrap_or("no output");
        return Err(Error::OpenscadFailed {
            action: "mesh",
            why: why.trim().to_string(),
        });
    }
    let m = TriMesh::read(&stl)?;
    m.check_closed("openscad's mesh")?;
    Ok(m.triangles
        .iter()
        .map(|t| t.map(|i| m.vertices[i as usize]))
        .collect())
}
