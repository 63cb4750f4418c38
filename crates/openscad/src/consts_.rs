//! Limits and OpenSCAD constants.

/// Deepest nesting of statements accepted: a top-level statement is at depth 1, so a cube may
/// sit inside at most 999 groups.
pub const MAX_NESTING: usize = 1_000;

/// Deepest nesting of vectors accepted (matrices, points and faces need 2).
pub const MAX_VECTOR_NESTING: usize = 64;

/// Most fragments (points on a circle) a sphere or cylinder may have.
pub const MAX_FRAGMENTS: usize = 10_000;

/// Most vertices a whole scene may have: a guard against a file that would exhaust memory
/// while it is read (20 million vertices hold about 0.5 GB with their faces); designs such as
/// a `$fn = 1080` pulley, past the million once kept here, are read.
pub const MAX_SCENE_VERTICES: usize = 20_000_000;

/// Scene vertices a point of a `text()` outline is charged while the text is drawn: the
/// glyph outlines, their union and the cap's triangulation hold about 1,200 bytes a point with
/// the point itself (voxelize peaks of 40 and 63 MB at 500 and 1,000 characters of about 38
/// points each, 2026-11-29), and a scene vertex stands for [`crate::BYTES_PER_SCENE_VERTEX`]
/// (64) bytes. Charged 1 (before), 3,000 characters passed `--max-memory 50` at a 138 MiB
/// peak; charged 10, 1,000 characters at 61 MiB. The budget a text is drawn in leaves out
/// the process's own [`crate::PROCESS_BYTES`]. The charge is also the run's estimate of the
/// text ([`csgpix_scene::solid::CsgScene::reading_bytes`]): charged 20 (1,280 bytes), sculpt
/// of 1,000 characters peaked at 63 MiB against an estimate of 62; 24 leaves a quarter over
/// the 1,200 measured.
pub const TEXT_POINT_VERTICES: usize = 24;

/// Most points a polyhedron may have (its convexity check takes points × faces steps).
pub const MAX_POLYHEDRON_POINTS: usize = 10_000;

/// Largest absolute coordinate of a placed solid, so that areas and volumes stay finite.
pub const MAX_COORDINATE: f64 = 1e12;

/// Smallest positive side of a placed solid's bounding box (a side of 0, a flat shape, is
/// another matter): the smallest side of a grid ([`csgpix_scene::grid::MIN_EXTENT`]), the
/// counterpart of [`MAX_COORDINATE`].
pub const MIN_EXTENT: f64 = csgpix_scene::grid::MIN_EXTENT;

/// OpenSCAD's `GRID_FINE` (`src/geometry/Grid.h`): below this radius a circle has 3 fragments.
pub(crate) const GRID_FINE: f64 = 0.000_000_953_674_316_406_25;

/// OpenSCAD's `F_MINIMUM` (`src/core/primitives.cc`): `$fa` and `$fs` are clamped up to it.
pub(crate) const F_MINIMUM: f64 = 0.01;

/// How far (relative to the largest coordinate) a polyhedron point may lie outside a face
/// plane. OpenSCAD writes polyhedron coordinates with 6 significant digits, so faces of a
/// convex polyhedron can be that far from flat in an exported file.
pub(crate) const CONVEXITY_TOLERANCE: f64 = 1e-5;
