//! `import()` of meshes and datasets.

use crate::{frame::*, lex::*, node::*, value::*};
use csgpix_scene::error::{CsgError, ImportArgument, Rule};
use csgpix_scene::solid::Import;

/// `import(file = "x.stl" | "x.obj" | "x.off" | "x.amf" | "x.3mf" | "x.nrrd", threshold = t)`:
/// a mesh or a dataset named by the scene, loaded later (`csgpix_voxel::sampled`, through
/// `csgpix_scene::trimesh::TriMesh::read` for meshes). A dataset needs `threshold`; a mesh must
/// not have one. `scale` other than 1 is refused (OpenSCAD applies it to 2D files only).
pub(crate) fn import(head: &Head, ctx: &Ctx) -> Result<Import, Fail> {
    let p = &head.params;
    let file = p.require("file", "a file name, e.g. import(\"part.stl\")")?;
    let Kind::Str(name) = &file.kind else {
        return fail(file.pos, must("`file`", Rule::Text));
    };
    let threshold = p.number("threshold")?;
    let lower = name.to_ascii_lowercase();
    let dataset = lower.ends_with(".nrrd") || lower.ends_with(".nhdr");
    let mesh = csgpix_scene::trimesh::READ_EXTENSIONS
        .iter()
        .any(|e| lower.rsplit_once('.').is_some_and(|(_, x)| x == *e));
    if !(dataset || mesh) {
        let problem = CsgError::UnknownImportFormat { file: name.clone() };
        return fail(file.pos, problem);
    }
    match (dataset, threshold) {
        (true, None) => {
            let file = name.clone();
            return fail(head.pos, CsgError::NeedsThreshold { file });
        }
        (false, Some((_, at))) => return fail(at, refused(ImportArgument::Threshold)),
        _ => {}
    }
    if let Some((s, at)) = p.number("scale")? {
        if s != 1.0 {
            return fail(at, refused(ImportArgument::Scale));
        }
    }
    if let Some((t, at)) = threshold {
        if !t.is_finite() {
            return fail(at, must("`threshold`", Rule::FiniteNumber));
        }
    }
    Ok(Import {
        file: name.clone(),
        threshold: threshold.map(|t| t.0),
        matrix: ctx.matrix,
        colour: ctx.colour,
        line: head.pos.line,
        col: head.pos.col,
        footprint: None,
        mesh: None,
    })
}

/// An `import()` argument refused for the file's kind.
fn refused(argument: ImportArgument) -> CsgError {
    CsgError::ImportArgument(argument)
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
        return fail(file.pos, must("`file`", Rule::Text));
    };
    if let Some(v) = p.get("id") {
        return fail(v.pos, refused(ImportArgument::SvgId));
    }
    if let Some(v) = p.get("layer") {
        if !matches!(&v.kind, Kind::Str(l) if l.is_empty()) {
            return fail(v.pos, refused(ImportArgument::SvgLayer));
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

/// The formats `import()` reads, by extension: 3D meshes and datasets, then 2D drawings.
const MESHES: [&str; 7] = ["stl", "obj", "off", "amf", "3mf", "nrrd", "nhdr"];
const DRAWINGS: [&str; 2] = ["svg", "dxf"];

/// An `import()` OpenSCAD gives no geometry for, going on with the rest of the scene
/// (`ImportNode::createGeometry` in src/import.cc): an empty name or an unknown format
/// ("Unsupported file format", logged as an error that does not stop the render), or a file
/// that cannot be opened ("Can't open import file"). The message, and whether the import
/// was of a 2D drawing. `dir` is where a relative name starts; without one (a scene read
/// from text, not from a file) files are not looked for here but when they are loaded.
pub(crate) fn unreadable(head: &Head, dir: Option<&std::path::Path>) -> Option<(String, bool)> {
    let Some(Kind::Str(name)) = head.params.get("file").map(|v| &v.kind) else {
        return None; // `file` missing or not a string: import() says so.
    };
    let ext = std::path::Path::new(name)
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    let flat = DRAWINGS.contains(&ext.as_str());
    if name.is_empty() || !(flat || MESHES.contains(&ext.as_str())) {
        let msg = format!(
            "Unsupported file format while trying to import file '{name}': nothing imported"
        );
        return Some((msg, false));
    }
    let path = dir?.join(name);
    if path.is_file() {
        return None;
    }
    let what = match std::fs::metadata(&path) {
        Ok(m) if m.is_dir() => "it is a directory",
        Ok(_) => "it is not a regular file",
        Err(_) => "no such file",
    };
    let msg = format!(
        "Can't open import file '{}' ({what}): nothing imported",
        path.display()
    );
    Some((msg, flat))
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
        return fail(file.pos, must("`file`", Rule::Text));
    };
    let layer = match p.get("layer").map(|v| (&v.kind, v.pos)) {
        None => String::new(),
        Some((Kind::Str(l), _)) => l.clone(),
        Some((_, at)) => return fail(at, must("`layer`", Rule::LayerName)),
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
                return fail(v.pos, must("`origin`", Rule::Finite))
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
        Some((Kind::Num(s), at)) if !s.is_finite() => {
            return fail(at, must("`scale`", Rule::Finite))
        }
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
