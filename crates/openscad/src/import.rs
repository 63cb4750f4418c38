//! `import()` of meshes and datasets.

use crate::{frame::*, lex::*, node::*, value::*};
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
            format!("`import(\"{name}\")`: csgpix imports .stl and .obj meshes, .nrrd datasets and .svg and .dxf drawings"),
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

/// An `import` of a DXF file (a 2D drawing, module [`crate::dxf`]).
pub(crate) fn is_dxf(head: &Head) -> bool {
    head.kind == NodeKind::Import
        && matches!(&head.params.get("file").map(|v| &v.kind),
            Some(Kind::Str(f)) if f.to_ascii_lowercase().ends_with(".dxf"))
}

/// `import(file = "x.dxf", layer, origin, scale, $fn, $fa, $fs)` as
/// `ImportModule::instantiate` (`src/import.cc`, 2021.01) reads it: `layer` a string (empty:
/// all layers), `origin` `[x, y]` (anything else is `[0, 0]` with OpenSCAD's warning),
/// `scale` a number, 1 when not positive; `convexity`, `center` and `dpi` play no part.
pub(crate) struct DxfArgs {
    pub(crate) file: String,
    pub(crate) settings: crate::dxf::Settings,
    pub(crate) warning: Option<(Pos, String)>,
}

pub(crate) fn dxf_args(head: &Head) -> Result<DxfArgs, Fail> {
    let p = &head.params;
    let file = p.require("file", "a file name")?;
    let Kind::Str(name) = &file.kind else {
        return fail(file.pos, "`file` must be a string");
    };
    let layer = match p.get("layer").map(|v| (&v.kind, v.pos)) {
        None => String::new(),
        Some((Kind::Str(l), _)) => l.clone(),
        Some((_, at)) => return fail(at, "`layer` must be a string (a DXF layer's name)"),
    };
    let mut origin = [0.0, 0.0];
    let mut warning = None;
    if let Some(v) = p.get("origin") {
        let pair = match &v.kind {
            Kind::List(xy) if xy.len() == 2 => match (&xy[0].kind, &xy[1].kind) {
                (Kind::Num(x), Kind::Num(y)) => Some([*x, *y]),
                _ => None,
            },
            _ => None,
        };
        match pair {
            Some(o) if !o.iter().all(|c| c.is_finite()) => {
                return fail(v.pos, "`origin` must be finite")
            }
            Some(o) => origin = o,
            None => warning = Some(v.pos),
        }
    }
    let warning = warning.map(|at| {
        // OpenSCAD's words, which name the wrong module.
        let msg = "linear_extrude(..., origin=...) could not be converted".to_string();
        (at, msg)
    });
    let scale = match p.get("scale").map(|v| (&v.kind, v.pos)) {
        Some((Kind::Num(s), at)) if !s.is_finite() => return fail(at, "`scale` must be finite"),
        Some((Kind::Num(s), _)) if *s > 0.0 => *s,
        _ => 1.0,
    };
    let res = crate::primitives::Resolution::read(p)?;
    Ok(DxfArgs {
        file: name.clone(),
        settings: crate::dxf::Settings {
            layer,
            origin,
            scale,
            res,
        },
        warning,
    })
}
