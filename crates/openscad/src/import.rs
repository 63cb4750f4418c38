//! `import()` of meshes and datasets.

use crate::{frame::*, lex::*, node::*, value::*};
use csgpix_scene::solid::Import;

/// `import(file = "x.stl" | "x.obj" | "x.off" | "x.amf" | "x.3mf" | "x.nrrd", threshold = t)`:
/// a mesh or a dataset named by the scene, loaded later (`csgpix_voxel::sampled`, through
/// `csgpix_scene::trimesh::TriMesh::read` for meshes). A dataset needs `threshold`; a mesh must
/// not have one. `scale` other than 1 is refused (OpenSCAD applies it to 2D files only).
pub(crate) fn import(head: &Head, ctx: &Ctx) -> Result<Import, Fail> {
    let p = &head.params;
    let file = p.require("file", "a file name, e.g. import(\"part.stl\")")?;
    let Kind::Str(name) = &file.kind else {
        return fail(file.pos, "`file` must be a string");
    };
    let threshold = p.number("threshold")?;
    let lower = name.to_ascii_lowercase();
    let dataset = lower.ends_with(".nrrd") || lower.ends_with(".nhdr");
    let mesh = csgpix_scene::trimesh::READ_EXTENSIONS
        .iter()
        .any(|e| lower.rsplit_once('.').is_some_and(|(_, x)| x == *e));
    if !(dataset || mesh) {
        return fail(
            file.pos,
            format!("`import(\"{name}\")`: csgpix imports .stl, .obj, .off, .amf and .3mf meshes, .nrrd datasets and .svg drawings (not .dxf files)"),
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

/// An `import` of an SVG file (a 2D shape, module [`crate::svg`]).
pub(crate) fn is_svg(head: &Head) -> bool {
    head.kind == NodeKind::Import
        && matches!(&head.params.get("file").map(|v| &v.kind),
            Some(Kind::Str(f)) if f.to_ascii_lowercase().ends_with(".svg"))
}

/// `import(file = "x.svg", dpi, center)` as OpenSCAD 2021.01 reads it: `dpi` a number of at
/// least 0.001 (else 72, with OpenSCAD's warning), `center` true or false (anything else is
/// false); `origin`, `scale` and `convexity` ignored, as 2021.01 ignores them for SVG. `id`
/// (a later OpenSCAD's choice of one element) and a `layer` are refused: 2021.01 draws the
/// whole file.
pub(crate) struct SvgArgs {
    pub(crate) file: String,
    pub(crate) dpi: f64,
    pub(crate) center: bool,
    pub(crate) warning: Option<(Pos, String)>,
}

pub(crate) fn svg_args(head: &Head) -> Result<SvgArgs, Fail> {
    let p = &head.params;
    let file = p.require("file", "a file name")?;
    let Kind::Str(name) = &file.kind else {
        return fail(file.pos, "`file` must be a string");
    };
    if let Some(v) = p.get("id") {
        return fail(
            v.pos,
            "`id` (one element of an SVG file) is not supported: OpenSCAD 2021.01 imports the whole file",
        );
    }
    if let Some(v) = p.get("layer") {
        if !matches!(&v.kind, Kind::Str(l) if l.is_empty()) {
            return fail(v.pos, "`layer` applies to DXF files, not SVG");
        }
    }
    let mut dpi = 72.0;
    let mut warning = None;
    if let Some((d, at)) = p.number("dpi")? {
        if d >= 0.001 {
            dpi = d;
        } else {
            let msg = "Invalid dpi value giving, using default of 72 dpi. Value must be positive and >= 0.001";
            warning = Some((at, msg.to_string()));
        }
    }
    let center = matches!(p.get("center").map(|v| &v.kind), Some(Kind::Bool(true)));
    Ok(SvgArgs {
        file: name.clone(),
        dpi,
        center,
        warning,
    })
}
