//! Reader for the OpenSCAD `.csg` subset csgpix draws and voxelizes: solids, 2D shapes under
//! extrusions, hulls and offsets under CSG operations, as OpenSCAD writes them with File →
//! Export → Export as CSG.
//!
//! # What is read
//!
//! Statements `name(args);`, `name(args) child` and `name(args) { children }`, `//` and `/* */`
//! comments, numbers, `true`, `false`, `undef`, strings and (nested) vectors, positional and
//! named arguments (`$fn = 0`). The nodes:
//!
//! * `group()`, `union()` → [`CsgNode::Union`]; `render(convexity = …)` is read as a group
//!   (it only asks OpenSCAD to cache the geometry, so ignoring it is harmless).
//! * `intersection()` → [`CsgNode::Intersection`], `difference()` → [`CsgNode::Difference`]
//!   (the first child minus the others).
//! * `multmatrix(m = 4×4)` transforms the solids below it (nested transforms compose). As in
//!   OpenSCAD's `multmatrix` module (`src/core/TransformNode.cc`) a matrix whose `m[3][3]` is
//!   not 1 is divided by it; a projective matrix is refused; a singular one, or one holding
//!   `inf` or `nan`, removes the objects it places with OpenSCAD's warning. A matrix with a
//!   negative determinant (a mirror) reverses the winding of every face so faces stay outward.
//! * `color([r, g, b, a])` / `color(c = [r, g, b], alpha = a)` colours the solids below it,
//!   the innermost colour winning; a component out of 0..1 is OpenSCAD's warning and is
//!   clamped. Named and hex colours (`color("red")`) are refused: the CSG
//!   export always writes the vector form.
//! * `cube`, `sphere`, `cylinder` are tessellated exactly as OpenSCAD does (see below), and
//!   `polyhedron` is a convex solid when it is closed and convex, else a mesh primitive; one
//!   that is not closed (its corners welded) is kept with a warning and voxelized by its
//!   generalized winding number (`csgpix_scene::winding`), where OpenSCAD's render drops it.
//! * The modifiers `%` (background) and `*` (disable) drop the statement, as OpenSCAD leaves
//!   such nodes out of the rendered result; `#` (highlight) is ignored; `!` is refused.
//! * `import(file = "x.stl" | "x.obj" | "x.off" | "x.amf" | "x.3mf" | "x.nrrd", threshold = t)`
//!   names a mesh or a dataset primitive ([`Import`], loaded by `csgpix_voxel::sampled`;
//!   OFF, AMF and 3MF read as OpenSCAD 2021.01 imports them: 3MF build transforms, components
//!   and units not applied, several objects united; `csgpix_scene::trimesh::TriMesh::read`);
//!   `threshold` (ours, not OpenSCAD's) is a dataset's iso value.
//!
//! * 2D shapes `square`, `circle`, `polygon(points, paths)` (several paths filled even-odd:
//!   holes) under 2D `multmatrix`/`color`/`group`/`union`/`difference`/`intersection`, inside
//!   `linear_extrude(height, center, twist, slices, scale)` or `rotate_extrude(angle)`; a 2D
//!   shape outside an extrusion, or an operation mixing 2D and 3D children, is refused.
//!   Extrusions follow OpenSCAD 2021.01's layout ([`crate::extrude`]): an untwisted, evenly
//!   scaled extrusion of one convex outline is a convex solid; anything else is a closed mesh
//!   primitive (an [`Import`] holding its triangles), and a 2D boolean becomes the same boolean
//!   of the extruded shapes, except under a twist or uneven scale, where it is taken in the
//!   plane first.
//! * `hull()` of solids (one convex solid over their vertices; the solids leave the scene) or
//!   of 2D shapes (a convex outline); of a difference or intersection, over the vertices of
//!   its computed geometry (module `geom`: a mesh boolean, or the 2D boolean).
//! * `minkowski(convexity)` of solids or 2D shapes, all children left to right: a union of
//!   convex solids (hulls of vertex sums) and closed mesh primitives, exact for non-convex
//!   operands (the boundary formula and its proof are in module `geom`).
//! * `offset(r | delta, chamfer)` of one convex outline, or outward of a union of them.
//! * `projection(cut)` of solids, a 2D shape (so `linear_extrude(…) projection(…) …` reads):
//!   with `cut = true` the section at z = 0, every leaf sectioned and the CSG tree kept as a 2D
//!   tree; otherwise the shadow on z = 0 (see `project.rs`). The solids below leave the scene.
//! * `resize(newsize, auto)` of solids or 2D shapes: a scale about the origin from the exact
//!   bounding box, with OpenSCAD 2021.01's rules for zero entries and `auto`; a negative size
//!   (with a warning) is ignored for one primitive and mirrors a boolean's result, as
//!   OpenSCAD's `PolySet::resize` and `CGAL_Nef_polyhedron::resize` do. The shadow of a difference or intersection, and its box, need the mesh of
//!   `geom::mesh_of`.
//! * `text(text, size, font, halign, valign, spacing, direction, language, script)`: a 2D
//!   shape, the glyph outlines shaped and flattened as OpenSCAD 2021.01 does
//!   ([`crate::text`]); a font that is not found is fontconfig's match, with a warning.
//!
//! * `import(file = "x.svg", dpi, center)` and `import(file = "x.dxf", layer, origin, scale,
//!   $fn, $fa, $fs)`: 2D shapes read as OpenSCAD 2021.01 reads them (modules `svg` and `dxf`:
//!   a DXF file's LINE, LWPOLYLINE, CIRCLE, ARC, ELLIPSE and block INSERTs, its segments
//!   joined on OpenSCAD's 1/1024 grid and filled even-odd; other entities are OpenSCAD's
//!   warnings), errors one line naming the file's line; [`read_dxf`] reads DXF bytes alone.
//!
//! * `surface(file, center, invert)`: the heights of a `.dat` grid or a PNG image closed into
//!   a solid as OpenSCAD 2021.01 does it ([`surface`]), a closed mesh primitive.
//!
//! Where OpenSCAD warns and goes on (a colour out of range, a malformed polyhedron, an import
//! of a missing file, a child of the other dimension, …: docs/volume-scenes.md lists them),
//! so does the reader, into [`CsgScene::warnings`]; [`ReadOptions::strict`] refuses the
//! first instead.
//!
//! Anything else (nodes of later releases, …) is refused with an error naming the node, its
//! line and column, or with [`Fallback::Openscad`] meshed by openscad. [`scene_text`] turns a `.scad` file into
//! this CSG text by running `openscad`. Every openscad run is killed when it takes longer
//! than [`ReadOptions::openscad_timeout`] ([`DEFAULT_OPENSCAD_TIMEOUT`] by default).
//!
//! The tree is simplified without changing the solid it describes: a union or group with one
//! child is that child, unions inside unions (and intersections inside intersections) are
//! flattened, empty children are dropped from unions and from the subtracted part of a
//! difference, and an intersection with an empty child, or a difference whose first child is
//! empty, is [`CsgNode::Empty`]. This is the meaning OpenSCAD gives empty children when it
//! renders (F6); its preview (F5) skips empty children of an intersection instead.
//!
//! # Following OpenSCAD
//!
//! The tessellation follows OpenSCAD's source (read, not copied):
//!
//! * fragment count: `Calc::get_fragments_from_r` in `src/utils/calc.cc`, with `GRID_FINE`
//!   from `src/geometry/Grid.h` and the clamping of `$fa`/`$fs` to `F_MINIMUM = 0.01` from
//!   `set_fragments` in `src/core/primitives.cc`;
//! * vertex and face layout: `CubeNode::createGeometry`, `SphereNode::createGeometry`,
//!   `CylinderNode::createGeometry` and `generate_circle` in `src/core/primitives.cc` (the
//!   current layout with quads between sphere rings and a single apex for cones);
//! * angles: `sin_degrees`/`cos_degrees` in `src/utils/degree_trig.cc`, which are exact at
//!   multiples of 30° and 45°.
//!
//! OpenSCAD versions differ in details, and this reader picks one:
//!
//! * a fractional `$fn` is truncated (`get_fragments_from_r`, release 2021.01); the newer
//!   `CurveDiscretizer::getCircularSegmentCount` (`src/core/CurveDiscretizer.cc`) rounds it
//!   up instead;
//! * release 2021.01 splits the band between two sphere rings into triangles where newer
//!   versions use one quad per fragment, as here; the vertices are the same;
//! * away from multiples of 30° and 45°, angles are converted as `x * (π / 180)`; 2021.01
//!   computes `x * π / 180`, which can differ in the last bit.
//!
//! # Limits
//!
//! Every error names the line and column (1-based, counted in characters) of the offending
//! token. Statements nest at most [`MAX_NESTING`] deep and vectors [`MAX_VECTOR_NESTING`]
//! deep, so neither the reader nor code walking the tree recursively can overflow the stack;
//! a circle has at most [`MAX_FRAGMENTS`] fragments, a polyhedron at most
//! [`MAX_POLYHEDRON_POINTS`] points, a scene at most [`MAX_SCENE_VERTICES`] vertices, and no
//! coordinate may exceed [`MAX_COORDINATE`] in size.

#![warn(missing_docs)]

mod cap;
mod clip;
mod consts_;
mod dxf;
mod export;
pub mod extrude;
mod fallback;
mod flat;
mod fontscan;
mod frame;
mod geom;
pub mod hull;
mod import;
mod lex;
mod linalg;
mod memo;
mod node;
mod pieces;
mod primitives;
mod project;
mod reader;
mod subprocess;
pub mod surface;
mod svg;
#[cfg(test)]
mod tests;
pub mod text;
mod transform;
mod tree;
mod value;

pub use consts_::{
    MAX_COORDINATE, MAX_FRAGMENTS, MAX_NESTING, MAX_POLYHEDRON_POINTS, MAX_SCENE_VERTICES,
    MAX_VECTOR_NESTING, MIN_EXTENT, TEXT_POINT_VERTICES,
};
pub use export::{in_scad, read_scene, read_scene_with, scene_text, scene_text_with};
pub use subprocess::DEFAULT_OPENSCAD_TIMEOUT;

use csgpix_scene::solid::CsgScene;
// The crate documentation names these nodes.
#[cfg(doc)]
use csgpix_scene::solid::{CsgNode, Import};
use csgpix_scene::Error;
use reader::Reader;

/// # Errors
///
/// The first problem, at its line and column in `file`.
///
/// # Examples
///
/// ```
/// use csgpix_openscad::parse_csg;
/// use csgpix_scene::solid::CsgNode;
///
/// let text = "difference() {\n  cube(size = [2, 2, 2], center = true);\n  \
///             sphere($fn = 8, r = 1.2);\n}\n";
/// let scene = parse_csg(text, "scene.csg")?;
/// assert_eq!(scene.solids.len(), 2);
/// assert!(matches!(scene.root, CsgNode::Difference(ref c) if c.len() == 2));
///
/// let err = parse_csg("cube(size = [1, 1]);", "bad.csg").unwrap_err();
/// assert!(err.to_string().starts_with("bad.csg:1:"));
/// # Ok::<(), csgpix_scene::Error>(())
/// ```
/// Reads a `.csg` file's text into a scene; `file` is only used in error messages.
///
pub fn parse_csg(text: &str, file: &str) -> csgpix_scene::Result<CsgScene> {
    parse_csg_with(text, file, &ReadOptions::default())
}

/// How a scene is read beyond the language itself.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReadOptions {
    /// What becomes of a node csgpix does not draw.
    pub fallback: Fallback,
    /// Where the scene's relative file names start (its file's directory; [`read_scene_with`]
    /// sets it), for the subtrees openscad meshes.
    pub dir: Option<std::path::PathBuf>,
    /// Font files `text()` looks in before the standard fonts ([`text::Fonts::standard`]), in
    /// this order. [`read_scene_with`] adds the scene's own: those a `.scad` file (or a file
    /// it includes or uses) names in `use <x.ttf>` / `use <x.otf>`, as OpenSCAD registers
    /// them; for a `.csg` file, which has lost its `use` lines, the `*.ttf` and `*.otf` files
    /// in the `.csg` file's own directory.
    pub fonts: Vec<std::path::PathBuf>,
    /// The most vertices the scene may have while it is read (`None`:
    /// [`MAX_SCENE_VERTICES`]); [`ReadOptions::max_vertices_for`] turns a memory limit into it.
    pub max_vertices: Option<usize>,
    /// The most samples an imported dataset may have (`import("x.nrrd", …)`), from the
    /// caller's memory limit; [`SampleLimit::NONE`](csgpix_scene::nrrd::SampleLimit::NONE)
    /// by default.
    pub samples: csgpix_scene::nrrd::SampleLimit,
    /// How long each openscad run (a `.scad` export, a `--fallback openscad` mesh) may take
    /// before it is killed and the read fails with [`Error::TimedOut`]; None: no limit.
    /// [`DEFAULT_OPENSCAD_TIMEOUT`] by default.
    pub openscad_timeout: Option<std::time::Duration>,
    /// `--strict`: the first warning ([`CsgScene::warnings`]) is a refusal instead, as csgpix
    /// read scenes before it followed OpenSCAD's leniency. False by default: where OpenSCAD
    /// warns and goes on, so does the reader.
    pub strict: bool,
    /// A straight `linear_extrude` (no twist, no scale) of more outline points than this is
    /// one footprint primitive (its 2D tree and height, [`csgpix_scene::footprint`]) instead
    /// of a convex prism or mesh per shape; None: never. [`DEFAULT_FOOTPRINT_POINTS`] by
    /// default. A footprint is sampled, not drawn by the array (`render`, `requirements` and
    /// `throughput` refuse it, as a mesh).
    pub footprints: Option<usize>,
    /// Also read as a footprint every straight extrusion with a shape that is not convex
    /// (one that would be a mesh), whatever its points, when [`ReadOptions::footprints`] is
    /// not None. False by default: each such shape is a mesh primitive of its own colour
    /// code; `print`, whose layers carry no codes, sets it (docs/printer.md, "Concave
    /// outlines are footprints").
    pub concave_footprints: bool,
}

/// Outline points past which a straight extrusion is read as a footprint
/// ([`ReadOptions::footprints`]).
pub const DEFAULT_FOOTPRINT_POINTS: usize = 100_000;

impl Default for ReadOptions {
    fn default() -> ReadOptions {
        ReadOptions {
            fallback: Fallback::default(),
            dir: None,
            fonts: vec![],
            max_vertices: None,
            samples: Default::default(),
            openscad_timeout: Some(DEFAULT_OPENSCAD_TIMEOUT),
            strict: false,
            footprints: Some(DEFAULT_FOOTPRINT_POINTS),
            concave_footprints: false,
        }
    }
}

impl ReadOptions {
    /// These options for a scene the array draws (`render`, `requirements`, `throughput`,
    /// `study`): every extrusion as convex prisms and meshes, never a footprint, which the
    /// array cannot draw.
    pub fn for_the_array(self) -> ReadOptions {
        ReadOptions {
            footprints: None,
            ..self
        }
    }
}

/// What one vertex of a scene costs while it is read, in bytes, with its share of faces and
/// triangles (a mesh primitive's triangles as f32 corners, a convex solid's f64 vertices and
/// face lists, the copies a boolean or hull makes); measured scenes stay below it.
pub const BYTES_PER_SCENE_VERTEX: u64 = 64;

/// What the process holds before it reads a scene (its code, the allocator's arenas, the
/// standard library): 11 MB measured, as the run layer's estimates count it. A `text()` is
/// drawn within the vertex budget less this ([`TEXT_POINT_VERTICES`]).
pub const PROCESS_BYTES: u64 = 16 << 20;

impl ReadOptions {
    /// The vertex limit a memory limit of `bytes` allows ([`BYTES_PER_SCENE_VERTEX`] each).
    pub fn max_vertices_for(bytes: u64) -> usize {
        usize::try_from(bytes / BYTES_PER_SCENE_VERTEX).unwrap_or(usize::MAX)
    }
}

/// What becomes of a node csgpix does not draw (a 2D import, a node it does not know).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Fallback {
    /// Refused, with its line and column (the default: csgpix draws what it reads itself).
    #[default]
    Refuse,
    /// Meshed by openscad, that subtree alone, and drawn as a closed mesh primitive; each
    /// such subtree is reported as a warning (stderr, `--json`).
    Openscad,
}

/// The DXF file `bytes` (called `file` in messages) drawn as `import(file)` draws it with
/// OpenSCAD's default `$fn`, `$fa`, `$fs` (module `dxf`), at most `max_vertices` vertices:
/// the number of outline points and of warnings. The entry point of the DXF fuzz target.
///
/// # Errors
///
/// A file csgpix refuses, one line naming `file` and the line.
pub fn read_dxf(
    bytes: &[u8],
    file: &str,
    max_vertices: usize,
) -> csgpix_scene::Result<(usize, usize)> {
    let settings = dxf::Settings {
        layer: String::new(),
        origin: [0.0, 0.0],
        scale: 1.0,
        res: primitives::Resolution {
            fn_: 0.0,
            fa: 12.0,
            fs: 2.0,
        },
    };
    let d = dxf::parse(bytes, file, &settings, max_vertices)?;
    Ok((d.shape.points().count(), d.warnings.len()))
}

/// The SVG file `text` (called `file` in messages) drawn as `import(file)` draws it at 72 dpi
/// (module `svg`), its outlines at most `max_vertices` points: the number of its shapes. The
/// entry point of the SVG fuzz target.
///
/// # Errors
///
/// A file csgpix refuses, one line.
pub fn read_svg(text: &str, file: &str, max_vertices: usize) -> csgpix_scene::Result<usize> {
    svg::parse(text, file, 72.0, false, max_vertices).map(|s| s.len())
}

/// [`parse_csg`] with [`ReadOptions`].
pub fn parse_csg_with(
    text: &str,
    file: &str,
    options: &ReadOptions,
) -> csgpix_scene::Result<CsgScene> {
    let mut scene = Reader::new(text, options)
        .run()
        .map_err(|fail| fail.problem.located(file, fail.pos.line, fail.pos.col))?;
    for w in &mut scene.warnings {
        *w = std::mem::replace(w, Error::NeedsBounds).in_file(file);
    }
    match scene.warnings.first() {
        Some(first) if options.strict => Err(first.clone()),
        _ => Ok(scene),
    }
}
