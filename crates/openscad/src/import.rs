//! `import()` of meshes and datasets.

use crate::{lex::*, node::*, reader::*, value::*};
use csgpix_scene::solid::Import;

/// have one. `scale` other than 1 is refused (OpenSCAD applies it to 2D files only).
/// `import(file = "x.stl" | "x.obj" | "x.nrrd", threshold = t)`: a mesh or a dataset named by
/// the scene, loaded later (`csgpix_voxel::sampled`). A dataset needs `threshold`; a mesh must not
pub(crate) fn import(head: &Head, ctx: &Ctx) -> Result<Import, Fail> {
    let p = &head.params;
    let file = p.require("file", "a file name, e.g. import(\"part.stl\")")?;
    let Kind::Str(name) = &file.kind else {
        return fail(file.pos, "`file` must be a string");
    };
    let threshold = p.number("threshold")?;
    let lower = name.to_ascii_lowercase();
    let dataset = lower.ends_with(".nrrd") || lower.ends_with(".nhdr");
    if !(dataset || lower.ends_with(".stl") || lower.ends_with(".obj")) {
        return fail(
            file.pos,
            format!("`import(\"{name}\")`: csgpix imports .stl and .obj meshes and .nrrd datasets (not 2D files such as .dxf or .svg)"),
        );
    }
    match (dataset, threshold) {
        (true, None) => {
            return fail(
                head.pos,
                format!("`import(\"{name}\")` is a dataset: give its iso value, `threshold = t`"),
            )
        }
        (false, Some((_, at))) => return fail(at, "`threshold` applies to datasets (.nrrd) only"),
        _ => {}
    }
    if let Some((s, at)) = p.number("scale")? {
        if s != 1.0 {
            return fail(
                at,
                "`scale` is not supported for 3D imports (use multmatrix)",
            );
        }
    }
    if let Some((t, at)) = threshold {
        if !t.is_finite() {
            return fail(at, "`threshold` must be a finite number");
        }
    }
    Ok(Import {
        file: name.clone(),
        threshold: threshold.map(|t| t.0),
        matrix: ctx.matrix,
        colour: ctx.colour,
        line: head.pos.line,
        col: head.pos.col,
        mesh: None,
    })
}
