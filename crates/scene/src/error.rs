//! The error of every scene reader and writer: one line, located in its input where it has a
//! place there (`FILE:LINE:COL: message`), never naming a command-line flag (the CLI adds
//! those). The place, the file that could not be read and the context are fields
//! ([`Error::location`], [`Error::io_kind`]), so a caller need not parse the message.

use std::fmt;

mod csg;

pub use csg::{CsgError, ImportArgument, Rule};

/// Where in an input a problem is: 1-based line and column (in characters). Binary inputs
/// are located by byte offset instead, as line 0 and column = offset + 1.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// The input's name as the user gave it (a path, or a name such as `<expr>`).
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column, in characters.
    pub col: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", OneLine(&self.file), self.line, self.col)
    }
}

pub use csgpix_output::{IoError, OneLine};

/// A scene error: what went wrong and, for bad input, where.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// Bad input at a place in it (a `.csg`, `.dl` or mesh file, an expression, an NRRD
    /// header): `at: problem`.
    #[error("{at}: {problem}")]
    At {
        /// Where.
        at: Location,
        /// What is wrong there.
        problem: Box<Error>,
    },
    /// A problem about `what` (a path, a primitive, an output's name): `what: source`.
    #[error("{}: {source}", OneLine(what))]
    Context {
        /// What the problem concerns, as the user would name it.
        what: String,
        /// The problem.
        source: Box<Error>,
    },
    /// A file or directory could not be read, written or created: the system's error. The
    /// path is in an enclosing [`Error::Context`] (`path: system message`, see [`Error::io`])
    /// or [`Error::At`].
    #[error(transparent)]
    Io(IoError),
    /// A grid was asked over a scene with no solids, so it has no bounds of its own: the
    /// caller has to give a box.
    #[error("the scene has no solids: give the grid's bounds")]
    NeedsBounds,
    /// A grid resolution with a side of 0 voxels.
    #[error("resolution {dims:?}: every side needs at least one voxel")]
    EmptyResolution {
        /// The resolution asked for, X, Y, Z.
        dims: [usize; 3],
    },
    /// A grid (padding included) with more voxels along an axis than csgpix allows.
    #[error("a grid of {dims:?} voxels: at most {limit} per axis")]
    GridTooLarge {
        /// The grid's voxels, X, Y, Z.
        dims: [usize; 3],
        /// The most voxels along an axis ([`crate::grid::MAX_GRID_SIDE`]).
        limit: usize,
    },
    /// An output that cannot be written (a writer's path, refused or failed).
    #[error(transparent)]
    Output(#[from] csgpix_output::Error),
    /// A program csgpix runs (openscad) did not finish within its time limit: it was
    /// killed. The caller names the setting that raises the limit.
    #[error("{program} did not finish within {} s", Seconds(*limit))]
    TimedOut {
        /// The program.
        program: String,
        /// The limit it was given.
        limit: std::time::Duration,
    },
    // --- Syntax and text -------------------------------------------------------------------
    /// Input that is not what its format allows at this point: what was expected there and
    /// what was found (as the message shows it: `` `word` ``, `the end of the file`, …).
    #[error("expected {expected}, found {}", OneLine(found))]
    Expected {
        /// What the format allows here (`a finite number`, `` `endfacet` ``).
        expected: String,
        /// What the input holds instead, quoted as shown.
        found: String,
    },
    /// Something that needs a number of parts was given another number: `what needs
    /// needs, found found` (a vertex of 2 coordinates, a face of 2 vertices).
    #[error("{what} needs {needs}, found {found}")]
    Needs {
        /// What is incomplete (`a vertex`).
        what: &'static str,
        /// What it needs (`3 coordinates`).
        needs: &'static str,
        /// How many parts it has.
        found: usize,
    },
    /// A text that should be a number is not one.
    #[error("{:?} is not a number", text)]
    NotANumber {
        /// The text, as found.
        text: String,
    },
    /// A number that should be finite is infinite or NaN (`text` as found).
    #[error("{:?} is not a finite number", text)]
    NotFinite {
        /// The text, as found.
        text: String,
    },
    /// A text input that is not UTF-8: the first bad byte (its place in an enclosing
    /// [`Error::At`]).
    #[error("invalid UTF-8 (byte 0x{byte:02X}): text inputs are UTF-8")]
    BadUtf8 {
        /// The first byte that is not UTF-8.
        byte: u8,
    },
    /// A text part of a file format (an XML document) that is not UTF-8.
    #[error("not UTF-8 text")]
    NotUtf8Text,
    /// A line longer than a reader accepts; `format` names the format the file is probably
    /// not (`DXF`), when the length says so.
    #[error("a line longer than {limit} bytes{}", NotA(*format))]
    LineTooLong {
        /// The longest line accepted, in bytes.
        limit: usize,
        /// The format such a line suggests the file is not.
        format: Option<&'static str>,
    },
    /// XML elements nested deeper than csgpix reads ([`crate::MAX_XML_DEPTH`]).
    #[error("elements nested more than {limit} deep: csgpix refuses them")]
    TooDeep {
        /// The deepest nesting read.
        limit: usize,
    },
    /// An XML file of more nodes than csgpix reads ([`crate::MAX_XML_NODES`]).
    #[error("more than {limit} XML nodes: csgpix refuses larger files")]
    TooManyXmlNodes {
        /// The most nodes read.
        limit: u32,
    },
    /// A file that is not well-formed XML: the parser's reason.
    #[error("not well-formed XML: {}", OneLine(reason))]
    NotWellFormedXml {
        /// The parser's message.
        reason: String,
    },
    /// An expression of more nested parentheses and `!` than csgpix reads.
    #[error("expression nested deeper than {limit}")]
    ExpressionTooDeep {
        /// The deepest nesting read.
        limit: usize,
    },
    /// An expression that ends with a `(` still open: where it opened, when the message
    /// says so (`expected ')'` otherwise).
    #[error("expected ')'{}", match open {
        Some(col) => format!(" to close the '(' at column {col}"),
        None => String::new(),
    })]
    Unclosed {
        /// The column of the `(` still open.
        open: Option<usize>,
    },
    /// A `)` with no `(` open.
    #[error("')' without a matching '('")]
    Unmatched,
    /// A colour code too large for its type.
    #[error("colour `{}` is out of range", OneLine(text))]
    ColourOutOfRange {
        /// The code, as written.
        text: String,
    },
    /// A display list whose terminating entry comes before any plane (the list is empty).
    #[error("terminating entry found before any plane")]
    TerminatorFirst,
    /// A name of a CSG expression that the scene does not have.
    #[error("unknown object {name:?}; the scene names {}", known.join(", "))]
    UnknownObject {
        /// The name given.
        name: String,
        /// The names the scene has.
        known: Vec<String>,
    },
    /// A clip expression whose sum-of-products form has more products than csgpix builds.
    #[error("the expression expands to more than {limit} products")]
    TooManyProducts {
        /// The most products.
        limit: usize,
    },
    /// A JSON value of a store's metadata that does not decode: the decoder's reason (the
    /// key is in an enclosing [`Error::Context`]).
    #[error("{}", OneLine(reason))]
    Json {
        /// serde_json's message.
        reason: String,
    },

    // --- Grids -----------------------------------------------------------------------------
    /// Grid bounds that are not finite or have a side that is not positive.
    #[error("bounds {min} .. {max} must be finite with every side positive")]
    BadBounds {
        /// The lower corner given.
        min: glam::DVec3,
        /// The upper corner given.
        max: glam::DVec3,
    },
    /// Grid bounds too thin to divide into voxels.
    #[error("degenerate extent: the bounds are {side:e} across, under {min:e}")]
    DegenerateExtent {
        /// The bounds' shortest side.
        side: f64,
        /// The shortest side accepted ([`crate::grid::MIN_EXTENT`]).
        min: f64,
    },
    /// A grid given both as a resolution and as a voxel size.
    #[error("give the grid as a resolution or a voxel size, not both")]
    ResolutionAndVoxelSize,
    /// A voxel size that is not a positive number.
    #[error("voxel size {size}: must be a positive number")]
    BadVoxelSize {
        /// The size given.
        size: f64,
    },
    /// A voxel size so small that an axis would have more voxels than csgpix allows.
    #[error("voxel size {size} over an extent of {extent}: more than {limit} voxels per axis")]
    VoxelSizeTooSmall {
        /// The size given.
        size: f64,
        /// The extent of the axis that overflows.
        extent: f64,
        /// The most voxels per axis.
        limit: usize,
    },

    // --- Volumes ---------------------------------------------------------------------------
    /// A volume whose number of samples does not match its sizes.
    #[error("{samples} samples for sizes {}", Sizes(sizes))]
    SampleCount {
        /// The samples there are.
        samples: usize,
        /// The sizes, X, Y, Z.
        sizes: [usize; 3],
    },
    /// A volume written with another number of samples than its sizes (`[x, y, z]`).
    #[error("{samples} samples for sizes {sizes:?}")]
    WriteSampleCount {
        /// The samples there are.
        samples: usize,
        /// The sizes, X, Y, Z.
        sizes: [usize; 3],
    },
    /// A volume whose raw data has another number of bytes than its sizes need.
    #[error("{bytes} data bytes for {}x{}x{}", sizes[0], sizes[1], sizes[2])]
    DataLength {
        /// The data bytes there are.
        bytes: usize,
        /// The sizes, X, Y, Z.
        sizes: [usize; 3],
    },
    /// A sample that is not a finite value.
    #[error("sample {index} is {value}: expected finite values")]
    NonFiniteSample {
        /// The sample's index.
        index: usize,
        /// Its value.
        value: f32,
    },
    /// A volume file larger than any volume csgpix reads could be.
    #[error("{len} bytes: larger than any volume of {limit} samples")]
    VolumeFileTooLarge {
        /// The file's length.
        len: u64,
        /// The most samples of a volume.
        limit: usize,
    },
    /// A volume whose space origin or directions are not finite.
    #[error("space origin and directions must be finite")]
    NonFiniteFrame,
    /// A field a header must have is missing (`no sizes field`).
    #[error("no {field} field")]
    MissingField {
        /// The field's name.
        field: &'static str,
    },
    /// A NRRD header that does not end in a blank line.
    #[error("no blank line after the NRRD header")]
    NoNrrdHeaderEnd,
    /// A file that does not start with the NRRD magic.
    #[error("not a NRRD file")]
    NotNrrd,
    /// A number of a header that does not parse: the parser's reason (the field is in an
    /// enclosing [`Error::Context`]).
    #[error("{reason}")]
    BadInteger {
        /// The parser's message (`invalid digit found in string`).
        reason: std::num::ParseIntError,
    },

    /// A header that is not UTF-8: the decoder's reason.
    #[error("{reason}")]
    Utf8 {
        /// Where the first bad byte is.
        reason: std::str::Utf8Error,
    },

    // --- Meshes ----------------------------------------------------------------------------
    /// A mesh whose surface has holes or fins: what is open (its edges), and how to mend it.
    #[error(
        "mesh is not closed: {open}; close the holes and remove the fins (e.g. with MeshLab's \
         or Blender's mesh repair) so that every edge is shared by an even number of \
         triangles and the surface bounds a solid"
    )]
    NotClosed {
        /// The open edges, as [`crate::trimesh::TriMesh::open_edges_summary`] words them.
        open: String,
    },
    /// A triangle that refers to a vertex the mesh does not have.
    #[error("triangle {triangle} refers to vertex {vertex}, but the mesh has {count} vertices")]
    NoSuchVertex {
        /// The triangle's index.
        triangle: usize,
        /// The vertex it names.
        vertex: u32,
        /// The vertices there are.
        count: usize,
    },
    /// A mesh file's vertex reference out of the vertices defined before it.
    #[error("vertex index {index} is out of range: {defined} vertices are defined so far")]
    VertexIndex {
        /// The reference, as written (1-based, or negative from the last).
        index: i64,
        /// The vertices defined so far.
        defined: usize,
    },
    /// A mesh without a proper triangle.
    #[error(
        "mesh has no triangles (after dropping {degenerate} degenerate ones); a solid needs a \
         closed surface"
    )]
    NoTriangles {
        /// The degenerate triangles dropped.
        degenerate: usize,
    },
    /// A mesh with more distinct vertices than a `u32` indexes.
    #[error("more than 2^32 distinct vertices")]
    TooManyVertices,
    /// An ASCII STL facet of other than 3 vertices.
    #[error("this facet has {vertices} vertices; an STL facet has 3")]
    FacetVertices {
        /// The vertices it has.
        vertices: usize,
    },
    /// A binary STL shorter than its 84-byte header.
    #[error("binary STL truncated at byte offset {len}: the header needs 84 bytes")]
    StlHeaderTruncated {
        /// The file's length.
        len: u64,
    },
    /// A binary STL shorter than the triangles its header promises.
    #[error(
        "binary STL truncated at byte offset {len}: the header promises {triangles} triangles \
         ({needs} bytes), triangle {incomplete} starts at byte offset {offset} and is incomplete"
    )]
    StlTruncated {
        /// The file's length.
        len: u64,
        /// The triangles the header promises.
        triangles: u64,
        /// The bytes they need.
        needs: u64,
        /// The first incomplete triangle.
        incomplete: u64,
        /// Where it starts.
        offset: u64,
    },
    /// A binary STL triangle with a coordinate that is infinite or NaN.
    #[error(
        "triangle {triangle} (byte offset {offset}) has a coordinate that is not a finite number"
    )]
    NonFiniteTriangle {
        /// The triangle's index.
        triangle: usize,
        /// Where it starts.
        offset: usize,
    },
    /// An empty OFF file.
    #[error("empty file: an OFF file starts with `OFF`")]
    EmptyOff,
    /// An OFF file of no vertices.
    #[error("the file has no vertices")]
    NoVertices,
    /// A SKEL file (OFF's skeleton format) where a surface is needed.
    #[error("a SKEL file has no surface: csgpix reads OFF")]
    SkelFile,
    /// A binary OFF file.
    #[error("binary OFF is not read: write the mesh as text OFF, STL or OBJ")]
    BinaryOff,
    /// An nOFF file of a dimension other than 3.
    #[error("an OFF file of dimension {dimension}: csgpix reads 3D meshes")]
    OffDimension {
        /// The dimension it declares.
        dimension: usize,
    },
    /// A homogeneous coordinate that makes its vertex infinite.
    #[error("this w makes the vertex infinite")]
    InfiniteVertex,
    /// An OFF facet of fewer than 3 vertices.
    #[error("facet {facet} has {vertices} vertices: a facet needs at least 3")]
    FacetTooSmall {
        /// The facet's index.
        facet: usize,
        /// The vertices it lists.
        vertices: usize,
    },
    /// An OFF facet that refers to a vertex the file does not have.
    #[error(
        "facet {facet} refers to vertex {vertex}, but the file has {count} vertices (numbered \
         from 0)"
    )]
    FacetVertex {
        /// The facet's index.
        facet: usize,
        /// The vertex it names.
        vertex: usize,
        /// The vertices there are.
        count: usize,
    },
    /// A path whose extension names no mesh format csgpix writes.
    #[error("the mesh format comes from the extension: .stl, .obj or .ply")]
    MeshWriteExtension,
    /// A path whose extension names no mesh format csgpix reads.
    #[error("a mesh is read from .stl, .obj, .off, .amf or .3mf (the extension names the format)")]
    MeshReadExtension,
    /// A mesh format name csgpix does not read.
    #[error("no mesh format `{}`: one of {known:?}", OneLine(format))]
    UnknownMeshFormat {
        /// The name given.
        format: String,
        /// The formats csgpix reads.
        known: &'static [&'static str],
    },
    /// A file of several objects whose union failed: the mesh library's reason.
    #[error(
        "the union of its {objects} objects failed ({}); OpenSCAD unites them as solids, so each \
         must be a closed surface",
        OneLine(reason)
    )]
    UnionFailed {
        /// The objects.
        objects: usize,
        /// The library's message.
        reason: String,
    },
    /// A zipped AMF whose entry named as the archive is missing, its only entry read instead
    /// (a warning).
    #[error(
        "the zipped AMF has no entry `{}`: its only entry `{}` is read, as OpenSCAD 2021.01 \
         does",
        OneLine(expected),
        OneLine(read)
    )]
    AmfEntryGuessed {
        /// The entry looked for (the archive's name).
        expected: String,
        /// The entry read.
        read: String,
    },
    /// A zipped AMF of several entries, none named as the archive.
    #[error(
        "the zipped AMF has {entries} entries and none is named `{}`: OpenSCAD reads the \
         entry named as the archive",
        OneLine(expected)
    )]
    AmfEntryMissing {
        /// The entries there are.
        entries: usize,
        /// The entry looked for.
        expected: String,
    },
    /// A 3MF package without the model part it names.
    #[error("the 3MF package has no model part `{}`", OneLine(part))]
    No3mfModel {
        /// The part's path.
        part: String,
    },

    // --- Archives --------------------------------------------------------------------------
    /// A file that is no readable zip archive: its length and the zip library's reason.
    #[error("not a readable zip archive ({bytes} bytes): {}", OneLine(reason))]
    NotZip {
        /// The file's length.
        bytes: usize,
        /// The library's message.
        reason: String,
    },
    /// A zip entry that cannot be read: the zip library's reason (the entry is in an
    /// enclosing [`Error::Context`]).
    #[error("{}", OneLine(reason))]
    ZipEntry {
        /// The library's message.
        reason: String,
    },
    /// A zip entry that inflates past what csgpix allows for its archive's size.
    #[error(
        "inflates past {left} bytes, more than csgpix allows for an archive of this size \
         ({ratio} times, at least {min}, at most {max} bytes): a zip bomb or a damaged archive"
    )]
    ZipBomb {
        /// The bytes left to inflate.
        left: u64,
        /// The allowed ratio of inflated to archive bytes.
        ratio: u64,
        /// The least allowed.
        min: u64,
        /// The most allowed.
        max: u64,
    },

    // --- Scenes ----------------------------------------------------------------------------
    /// A scene with imported primitives given to a command that draws convex solids only.
    #[error(
        "{}: {command} draws convex solids only; datasets and meshes are voxelized \
         (`csgpix voxelize`)",
        OneLine(primitive)
    )]
    ConvexOnly {
        /// The first imported primitive, as the message names it.
        primitive: String,
        /// The command.
        command: String,
    },
    /// An OpenSCAD node without an argument it needs.
    #[error("`{node}` needs {usage}")]
    NeedsArgument {
        /// The node's name.
        node: String,
        /// What it needs (`` `size` ``).
        usage: String,
    },
    /// An imported file that does not exist: the file as given, and where it was looked for.
    #[error("`import(\"{}\")`: no such file {}", OneLine(file), OneLine(.path.display()))]
    NoSuchImport {
        /// The file as given.
        file: String,
        /// Where it was looked for.
        path: std::path::PathBuf,
    },
    /// An imported mesh that is not closed, voxelized by its winding number (a warning).
    #[error(
        "`{}`: mesh is not closed: {open}; voxelized by its generalized winding number \
         (inside where at least 1/2, within the mesh's box), where OpenSCAD's render drops it",
        OneLine(file)
    )]
    OpenMeshVoxelized {
        /// The mesh file.
        file: String,
        /// The open edges, as [`crate::trimesh::TriMesh::open_edges_summary`] words them.
        open: String,
    },
    /// An operation on an imported file that csgpix does not do.
    #[error(
        "{operation} of `import(\"{}\")` is not supported (csgpix loads imported files only \
         to voxelize)",
        OneLine(file)
    )]
    ImportNotSupported {
        /// The operation (`projection(cut = true)`).
        operation: &'static str,
        /// The imported file.
        file: String,
    },
    /// An import whose geometry is not read with the scene (a dataset or mesh file).
    #[error(
        "`import(\"{}\")` has no geometry while the scene is read (a dataset or mesh file)",
        OneLine(file)
    )]
    ImportWithoutGeometry {
        /// The imported file.
        file: String,
    },
    /// The geometry of a complement asked for: it is unbounded.
    #[error("the geometry of a complement is unbounded")]
    UnboundedComplement,
    /// A mesh boolean operation that failed: the library's reason.
    #[error("mesh boolean failed: {}", OneLine(reason))]
    BooleanFailed {
        /// The library's message.
        reason: String,
    },
    /// Triangles that are not a closed manifold mesh: the library's reason.
    #[error("not a closed manifold mesh: {}", OneLine(reason))]
    NotManifold {
        /// The library's message.
        reason: String,
    },
    /// A Minkowski sum that would pass the scene's vertex limit.
    #[error(
        "the Minkowski sum would pass the scene's vertex limit (the limit follows the memory \
         limit, e.g. --max-memory)"
    )]
    MinkowskiTooLarge,
    /// A `surface()` grid of heights that would pass the scene's vertex limit.
    #[error(
        "a grid of {lines} × {columns} heights would pass the scene's vertex limit: {vertices} \
         more vertices, {left} left (the limit follows the memory limit, e.g. --max-memory)"
    )]
    SurfaceTooLarge {
        /// Lines of heights.
        lines: usize,
        /// Columns of heights.
        columns: usize,
        /// The vertices its mesh needs.
        vertices: usize,
        /// The vertices the scene has left.
        left: usize,
    },
    /// An image whose size is refused: the size and why.
    #[error("a {width}×{height} image: {problem}")]
    ImageSize {
        /// Its width, in pixels.
        width: usize,
        /// Its height, in pixels.
        height: usize,
        /// What is wrong with that size.
        problem: Box<Error>,
    },
    /// A PNG the decoder refuses: its reason.
    #[error("PNG decoder: {}", OneLine(reason))]
    Png {
        /// The decoder's message.
        reason: String,
    },
    /// A `surface()` height that is infinite or NaN.
    #[error("a height of `{}`: csgpix needs finite heights", OneLine(token))]
    NonFiniteHeight {
        /// The height, as written.
        token: String,
    },
    /// A `hull()` of fewer than two distinct points.
    #[error("hull() of fewer than two distinct points")]
    HullTooFewPoints,
    /// A `hull()` of points on one plane.
    #[error("hull() of points on one plane: no volume")]
    FlatHull,
    /// A `rotate_extrude()` of a shape on both sides of the axis.
    #[error("all points for rotate_extrude() must have the same X coordinate sign")]
    MixedXSign,
    /// A polyhedron whose faces wind inward or enclose no volume.
    #[error(
        "the faces wind the wrong way round (OpenSCAD lists each face clockwise seen from \
         outside) or enclose no volume"
    )]
    WrongWinding,
    /// A polyhedron that is not convex: a point outside a face's plane.
    #[error("not convex: point {point} lies {distance:.3e} outside the plane of face {face}")]
    NotConvex {
        /// The point.
        point: usize,
        /// How far outside.
        distance: f64,
        /// The face.
        face: usize,
    },
    /// A polyhedron face of no area.
    #[error("face {face} has no area")]
    FaceWithoutArea {
        /// The face.
        face: usize,
    },
    /// A polyhedron edge run the same way by two faces.
    #[error(
        "faces {first} and {second} both run from point {from} to point {to} (the surface is \
         not closed and consistently wound)"
    )]
    EdgeTwice {
        /// The first face.
        first: usize,
        /// The second face.
        second: usize,
        /// The edge's start.
        from: usize,
        /// The edge's end.
        to: usize,
    },
    /// A polyhedron edge with no neighbouring face.
    #[error(
        "not closed: the edge between points {a} and {b} of face {face} has no neighbouring face"
    )]
    OpenEdge {
        /// One end.
        a: usize,
        /// The other.
        b: usize,
        /// The face.
        face: usize,
    },
    /// A broken invariant of csgpix itself (a bug): what was missing.
    #[error("internal: {0}")]
    Internal(&'static str),
    /// A broken invariant of csgpix itself: a primitive index with no primitive.
    #[error("internal: no {kind} {index}")]
    NoPrimitive {
        /// `solid` or `import`.
        kind: &'static str,
        /// The index.
        index: usize,
    },

    // --- OpenSCAD --------------------------------------------------------------------------
    /// `openscad` is needed but not on `PATH`; `scad` when it was to read a `.scad` file.
    #[error("{}", if *scad { NO_OPENSCAD_SCAD } else { NO_OPENSCAD })]
    NoOpenscad {
        /// Whether it was to read a `.scad` file (the message then offers the export).
        scad: bool,
    },
    /// `openscad` failed: what it was to do and the line of its output that says why.
    #[error("openscad could not {action} it: {}", OneLine(why))]
    OpenscadFailed {
        /// `mesh` or `export`.
        action: &'static str,
        /// Its error line.
        why: String,
    },

    // --- Fonts and text --------------------------------------------------------------------
    /// A font weight csgpix does not read (the font is in an enclosing [`Error::Context`]).
    #[error("unsupported weight `{}`", OneLine(weight))]
    UnsupportedFontWeight {
        /// The weight, as written.
        weight: String,
    },
    /// A font property csgpix does not read.
    #[error(
        "unsupported property `{}` (csgpix reads `Family:style=Style`)",
        OneLine(property)
    )]
    UnsupportedFontProperty {
        /// The property, as written.
        property: String,
    },
    /// A font family without the style asked for.
    #[error("family `{}` has no such style", OneLine(family))]
    NoSuchStyle {
        /// The family.
        family: String,
    },
    /// A font csgpix does not find; `scene` when the scene's own font files were searched.
    #[error(
        "font `{}` not found (searched {}CSGPIX_FONT_PATH, the bundled fonts and the system \
         fonts)",
        OneLine(font),
        if *scene { "the scene's font files, " } else { "" }
    )]
    FontNotFound {
        /// The font's name.
        font: String,
        /// Whether the scene's font files were searched.
        scene: bool,
    },
    /// A font file that could not be read (`parsed` false) or parsed.
    #[error("font `{}` could not be {}", OneLine(font), if *parsed { "parsed" } else { "read" })]
    FontUnreadable {
        /// The font's name.
        font: String,
        /// Whether it was read but not parsed.
        parsed: bool,
    },
    /// A text alignment that is not one of its values.
    #[error("unknown {axis} `{}` ({allowed})", OneLine(value))]
    UnknownAlignment {
        /// `halign` or `valign`.
        axis: &'static str,
        /// The value given.
        value: String,
        /// The values allowed.
        allowed: &'static str,
    },
    /// A text whose outline has more points than csgpix accepts.
    #[error(
        "the text's outline has more than the {limit} points csgpix accepts (lower $fn or the \
         size)"
    )]
    TextTooDetailed {
        /// The most points.
        limit: usize,
    },

    // --- SVG -------------------------------------------------------------------------------
    /// A file that is not well-formed SVG: the XML parser's reason.
    #[error("not a valid SVG file: {}", OneLine(reason))]
    BadSvg {
        /// The parser's message.
        reason: String,
    },
    /// An XML file whose root element is not `<svg>`.
    #[error("not an SVG file: its root element is <{}>, not <svg>", OneLine(root))]
    NotSvg {
        /// The root element's name.
        root: String,
    },
    /// An SVG `viewBox` of no area.
    #[error("the viewBox \"{}\" is empty", OneLine(view_box))]
    EmptyViewBox {
        /// The attribute, as written.
        view_box: String,
    },
    /// An SVG coordinate that is infinite or NaN.
    #[error("a coordinate is not a finite number")]
    NonFiniteCoordinate,
    /// An `<svg>` inside the `<svg>`.
    #[error("an <svg> inside the <svg> is not supported")]
    NestedSvg,
    /// An SVG element whose outline (a stroke's, before it is drawn) would pass the scene's
    /// vertex limit.
    #[error(
        "the <{}> element's outline would have {vertices:.0} points, past the scene's vertex \
         limit ({left} left; the limit follows the memory limit, e.g. --max-memory)",
        OneLine(element)
    )]
    SvgVertexLimit {
        /// The element's name (at most as written).
        element: String,
        /// The points it would have (an upper bound for a stroke; it may be past `u64`).
        vertices: f64,
        /// The points left.
        left: usize,
    },
    /// An SVG path arc of radius 0.
    #[error("a path has an arc of radius 0")]
    ZeroRadiusArc,

    // --- AMF and 3MF ------------------------------------------------------------------------
    /// An XML mesh file whose root element is not the format's.
    #[error("not {what}: its root element is <{}>, not <{want}>", OneLine(root))]
    WrongRootElement {
        /// What the file is not (`an AMF file`, `a 3MF model`).
        what: &'static str,
        /// The root element's name.
        root: String,
        /// The root element the format has.
        want: &'static str,
    },
    /// A warning: a unit other than millimetres, which OpenSCAD ignores; `whatever` when the
    /// message adds that it does so whatever the unit (AMF).
    #[error(
        "unit \"{}\" is ignored: OpenSCAD 2021.01 reads {format} coordinates as millimetres{}",
        OneLine(unit),
        if *whatever { ", whatever the unit" } else { "" }
    )]
    UnitIgnored {
        /// The unit, as written.
        unit: String,
        /// `AMF` or `3MF`.
        format: &'static str,
        /// Whether to add ", whatever the unit".
        whatever: bool,
    },
    /// A warning: part of a 3MF file OpenSCAD does not apply (`what` is its subject, with
    /// its verb: `components are`).
    #[error(
        "{what} not applied: OpenSCAD 2021.01 imports each mesh object once, where it is defined"
    )]
    NotApplied {
        /// What is not applied, with its verb.
        what: &'static str,
    },
    /// An AMF element without a child element it needs.
    #[error("{parent} has no <{child}>")]
    NoChildElement {
        /// The element, as the message names it (`a <triangle>`).
        parent: &'static str,
        /// The child's name.
        child: &'static str,
    },
    /// An AMF coordinate element that is not a finite number.
    #[error("<{element}> must be a finite number, found \"{}\"", OneLine(text))]
    NotFiniteElement {
        /// The element's name.
        element: &'static str,
        /// Its text, trimmed.
        text: String,
    },
    /// An AMF triangle corner that is not the index of a vertex listed so far.
    #[error(
        "<{element}> must index the {count} vertices listed so far (from 0), found \"{}\"",
        OneLine(text)
    )]
    ElementVertexIndex {
        /// The element's name (`v1`).
        element: &'static str,
        /// The vertices listed so far.
        count: usize,
        /// Its text, trimmed.
        text: String,
    },
    /// A 3MF package whose relationships name no 3D model part.
    #[error("no relationship names the 3D model part")]
    No3mfModelRelationship,
    /// A 3MF build item naming an object the resources do not define.
    #[error(
        "the build item names object \"{}\", which the resources do not define",
        OneLine(id)
    )]
    UndefinedObject {
        /// The object's id, as written.
        id: String,
    },
    /// An XML element without an attribute it needs.
    #[error("a <{element}> needs its attribute {attribute}")]
    MissingAttribute {
        /// The element's name.
        element: &'static str,
        /// The attribute's name.
        attribute: &'static str,
    },
    /// A 3MF vertex coordinate that is not a finite 32-bit number.
    #[error("{attribute}=\"{}\" is not a finite 32-bit number", OneLine(text))]
    NotFiniteAttribute {
        /// The attribute's name.
        attribute: &'static str,
        /// Its value, as written.
        text: String,
    },
    /// A 3MF triangle corner that is not the index of one of the mesh's vertices.
    #[error(
        "{attribute}=\"{}\" must index the mesh's {count} vertices (from 0)",
        OneLine(text)
    )]
    AttributeVertexIndex {
        /// The attribute's name (`v1`).
        attribute: &'static str,
        /// Its value, as written.
        text: String,
        /// The mesh's vertices.
        count: usize,
    },

    // --- NRRD headers ----------------------------------------------------------------------
    /// Input that is not what its format allows at this point, where nothing in particular is
    /// found instead (a line of no field, a missing field, too few bytes to skip).
    #[error("expected {expected}")]
    ExpectedHere {
        /// What the format allows here.
        expected: String,
    },
    /// A NRRD header field the format does not have.
    #[error("unknown field `{}`", OneLine(name))]
    UnknownField {
        /// The field's name, as written.
        name: String,
    },
    /// A header field given a second time.
    #[error("`{}` given twice (first on line {first_line})", OneLine(name))]
    DuplicateField {
        /// The field's name, as written the second time.
        name: String,
        /// The line of its first occurrence.
        first_line: usize,
    },
    /// A NRRD encoding of the format that csgpix does not read (text, hex, bzip2).
    #[error(
        "expected encoding raw or gzip (`{}` is not supported)",
        OneLine(encoding)
    )]
    UnsupportedEncoding {
        /// The encoding, as written (lowercased).
        encoding: String,
    },
    /// A multi-byte NRRD sample type without an `endian:` field.
    #[error("the {bytes}-byte type {ty} needs an `endian:` field")]
    NeedsEndian {
        /// The bytes of a sample.
        bytes: usize,
        /// The type's name (`uint16`).
        ty: &'static str,
    },
    /// A volume with more samples than the limit.
    #[error(
        "sizes {}×{}×{} exceed the limit of {limit} samples{}",
        sizes[0],
        sizes[1],
        sizes[2],
        match set_by { Some(s) => format!(" ({s})"), None => String::new() }
    )]
    TooManySamples {
        /// The sizes, X, Y, Z.
        sizes: [usize; 3],
        /// The most samples.
        limit: usize,
        /// What sets a limit lower than csgpix's own, when one does.
        set_by: Option<&'static str>,
    },
    /// NRRD data that could not be read: `gzip` when it was to be decompressed, the reason.
    #[error("expected {} data: {}", if *gzip { "gzip" } else { "readable" }, OneLine(reason))]
    UnreadableData {
        /// Whether the data are gzip.
        gzip: bool,
        /// The system's or decoder's message.
        reason: String,
    },
    /// NRRD data of another number of bytes than the sizes and type need: `found` the bytes
    /// there are when fewer, `None` when more.
    #[error(
        "sizes {}×{}×{} of {ty} need {bytes} data bytes{}, found {}",
        sizes[0],
        sizes[1],
        sizes[2],
        if *gzip { " after decompression" } else { "" },
        match found { Some(n) => format!("only {n}"), None => "more".to_string() }
    )]
    DataBytes {
        /// The sizes, X, Y, Z.
        sizes: [usize; 3],
        /// The sample type's name.
        ty: &'static str,
        /// The bytes needed.
        bytes: usize,
        /// Whether they are counted after decompression.
        gzip: bool,
        /// The bytes there are, when fewer.
        found: Option<u64>,
    },

    // --- Other crates' errors --------------------------------------------------------------
    /// A display list or clip program that does not compile: the draw compiler's reason
    /// (`CompileError::msg`; its plane and field place it in an enclosing [`Error::At`] or
    /// [`Error::Context`]).
    #[error("{}", OneLine(reason))]
    Compile {
        /// What is wrong, as the compiler words it.
        reason: String,
    },
    /// A `.pla` file of golden vectors that does not parse: the parser's reason (`PlaError::
    /// msg`; its line and column in an enclosing [`Error::At`]).
    #[error("{}", OneLine(reason))]
    Pla {
        /// What is wrong, as the parser words it.
        reason: String,
    },
    /// A warning of the OpenSCAD reader (OpenSCAD's own wording where it warns too, or that
    /// of the mesh, DXF or font reader it called), located in an enclosing [`Error::At`].
    #[error("{}", OneLine(message))]
    Warning {
        /// The warning, one line.
        message: String,
    },

    // --- DXF -------------------------------------------------------------------------------
    /// A DXF entity whose fragments would pass the scene's vertex limit.
    #[error(
        "the {} entity would pass the scene's vertex limit ({left} vertices left; the limit \
         follows the memory limit, e.g. --max-memory)",
        OneLine(entity)
    )]
    DxfVertexLimit {
        /// The entity's type, as written (at most 40 characters).
        entity: String,
        /// The vertices left.
        left: usize,
    },
    /// A DXF arc or ellipse whose end angle is more whole turns below its start than csgpix
    /// unwinds.
    #[error(
        "the {} entity's end angle is more than {turns:e} turns below its start",
        OneLine(entity)
    )]
    DxfAngleTurns {
        /// The entity's type, as written.
        entity: String,
        /// The most turns unwound.
        turns: f64,
    },
    /// A DXF entity with a point that is not finite or is past csgpix's coordinate limit.
    #[error(
        "the {} entity has a point beyond csgpix's coordinate limit {limit:e}",
        OneLine(entity)
    )]
    DxfCoordinateLimit {
        /// The entity's type, as written.
        entity: String,
        /// The largest coordinate accepted.
        limit: f64,
    },

    // --- The OpenSCAD reader ---------------------------------------------------------------
    /// A token, statement or argument the OpenSCAD `.csg` reader refuses (the place is in an
    /// enclosing [`Error::At`]).
    #[error(transparent)]
    Csg(#[from] CsgError),
}

/// The cases of [`Error`] a caller may need to tell apart (to name its own option, say).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Kind {
    /// Any other problem: the message says it all.
    #[default]
    Other,
    /// A grid was asked over a scene with no solids ([`Error::NeedsBounds`]).
    NeedsBounds,
    /// A program did not finish within its time limit ([`Error::TimedOut`]).
    TimedOut,
}

/// A scene result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// A time limit in seconds: `300`, or `0.5` when not whole.
struct Seconds(std::time::Duration);

impl fmt::Display for Seconds {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.subsec_nanos() {
            0 => write!(f, "{}", self.0.as_secs()),
            _ => write!(f, "{}", self.0.as_secs_f64()),
        }
    }
}

/// " (not a DXF file?)" after a too long line, when the format is named.
struct NotA(Option<&'static str>);

impl fmt::Display for NotA {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Some(format) => write!(f, " (not a {format} file?)"),
            None => Ok(()),
        }
    }
}

/// A volume's sizes, `X×Y×Z`.
struct Sizes<'a>(&'a [usize; 3]);

impl fmt::Display for Sizes<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [x, y, z] = self.0;
        write!(f, "{x}×{y}×{z}")
    }
}

const NO_OPENSCAD: &str = "needs openscad on PATH (Debian: apt-get install openscad)";
const NO_OPENSCAD_SCAD: &str = "reading .scad needs openscad on PATH (Debian: apt-get install \
                                openscad); or export File → Export → Export as CSG and give the \
                                .csg";

impl Error {
    /// `problem` at `file:line:col`.
    ///
    /// ```
    /// use csgpix_scene::Error;
    ///
    /// let expected = |what: &str, found: &str| Error::Expected {
    ///     expected: what.into(),
    ///     found: found.into(),
    /// };
    /// let e = Error::at("a.dl", 3, 7, expected("a number", "`x`"));
    /// assert_eq!(e.to_string(), "a.dl:3:7: expected a number, found `x`");
    /// assert_eq!(e.in_file("b.dl").to_string(), "b.dl:3:7: expected a number, found `x`");
    /// ```
    pub fn at(file: impl Into<String>, line: usize, col: usize, problem: Error) -> Self {
        problem.located(file, line, col)
    }

    /// This error at `file:line:col`.
    pub fn located(self, file: impl Into<String>, line: usize, col: usize) -> Self {
        let file = file.into();
        Error::At {
            at: Location { file, line, col },
            problem: Box::new(self),
        }
    }

    /// A failure of the system on `path`: `path: system message`.
    pub fn io(path: impl fmt::Display, e: &std::io::Error) -> Self {
        Error::Io(e.into()).context(path)
    }

    /// Which case it is, for callers that word [`Kind::NeedsBounds`] or [`Kind::TimedOut`]
    /// their own way.
    pub fn kind(&self) -> Kind {
        match self {
            Error::NeedsBounds => Kind::NeedsBounds,
            Error::TimedOut { .. } => Kind::TimedOut,
            Error::Context { source: e, .. } | Error::At { problem: e, .. } => e.kind(),
            _ => Kind::Other,
        }
    }

    /// Where in its input the problem is, when it has a place there.
    ///
    /// ```
    /// use csgpix_scene::Error;
    ///
    /// let e = Error::at("a.dl", 3, 7, Error::NotANumber { text: "x".into() }).context("plane 2");
    /// assert_eq!(e.to_string(), "a.dl:3:7: plane 2: \"x\" is not a number");
    /// assert_eq!(e.location().map(|l| l.line), Some(3));
    /// ```
    pub fn location(&self) -> Option<&Location> {
        match self {
            Error::At { at, .. } => Some(at),
            Error::Context { source, .. } => source.location(),
            _ => None,
        }
    }

    /// The problem without its place: for [`Error::At`] what is wrong there, else the whole
    /// error.
    pub fn problem(&self) -> &Error {
        match self {
            Error::At { problem, .. } => problem,
            e => e,
        }
    }

    /// The system's kind of failure, when a file could not be read or written.
    ///
    /// ```
    /// use csgpix_scene::Error;
    /// use std::io::ErrorKind;
    ///
    /// let e = csgpix_scene::input::read_text("no/such.csg".as_ref()).unwrap_err();
    /// assert_eq!(e.io_kind(), Some(ErrorKind::NotFound));
    /// assert!(e.to_string().starts_with("no/such.csg: "));
    /// ```
    pub fn io_kind(&self) -> Option<std::io::ErrorKind> {
        match self {
            Error::Io(e) => Some(e.kind),
            Error::Output(e) => e.io_kind(),
            Error::At { problem: e, .. } | Error::Context { source: e, .. } => e.io_kind(),
            _ => None,
        }
    }

    /// The same error located in `file` instead (the caller's name for the input, e.g. the
    /// option an expression came from); unchanged when it has no location.
    pub fn in_file(self, file: impl Into<String>) -> Self {
        match self {
            Error::At { mut at, problem } => {
                at.file = file.into();
                Error::At { at, problem }
            }
            Error::Context { what, source } => Error::Context {
                what,
                source: Box::new(source.in_file(file)),
            },
            e => e,
        }
    }

    /// The same error, its problem after `what: ` (e.g. the primitive it concerns), the
    /// place, if any, still first.
    pub fn context(self, what: impl fmt::Display) -> Self {
        match self {
            Error::At { at, problem } => Error::At {
                at,
                problem: Box::new(problem.context(what)),
            },
            e => Error::Context {
                what: what.to_string(),
                source: Box::new(e),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_syntax_error_reads_expected_then_found_at_its_place() {
        let e = Error::Expected {
            expected: "`endfacet`".into(),
            found: "the end of the file".into(),
        };
        let e = Error::at("a.stl", 9, 1, e);
        assert_eq!(
            e.to_string(),
            "a.stl:9:1: expected `endfacet`, found the end of the file"
        );
        assert!(matches!(e.problem(), Error::Expected { .. }));
        assert_eq!(e.kind(), Kind::Other);
    }

    #[test]
    fn counts_and_limits_show_their_numbers() {
        let e = Error::SampleCount {
            samples: 5,
            sizes: [2, 2, 2],
        };
        assert_eq!(
            e.context("dataset").to_string(),
            "dataset: 5 samples for sizes 2×2×2"
        );
        let e = Error::WriteSampleCount {
            samples: 5,
            sizes: [2, 2, 2],
        };
        assert_eq!(e.to_string(), "5 samples for sizes [2, 2, 2]");
        let e = Error::Needs {
            what: "a face",
            needs: "at least 3 vertices",
            found: 2,
        };
        assert_eq!(e.to_string(), "a face needs at least 3 vertices, found 2");
        let e = Error::VoxelSizeTooSmall {
            size: 0.001,
            extent: 100.0,
            limit: 65536,
        };
        assert_eq!(
            e.to_string(),
            "voxel size 0.001 over an extent of 100: more than 65536 voxels per axis"
        );
    }

    #[test]
    fn a_line_too_long_names_the_format_only_when_given() {
        let dxf = Error::LineTooLong {
            limit: 4096,
            format: Some("DXF"),
        };
        assert_eq!(
            dxf.context("a.dxf:7").to_string(),
            "a.dxf:7: a line longer than 4096 bytes (not a DXF file?)"
        );
        let dat = Error::LineTooLong {
            limit: 100,
            format: None,
        };
        assert_eq!(dat.to_string(), "a line longer than 100 bytes");
    }

    #[test]
    fn an_open_mesh_says_how_to_mend_it() {
        let e = Error::NotClosed {
            open: "3 edges belong to one triangle".into(),
        }
        .context("m.stl");
        assert_eq!(
            e.to_string(),
            "m.stl: mesh is not closed: 3 edges belong to one triangle; close the holes and \
             remove the fins (e.g. with MeshLab's or Blender's mesh repair) so that every edge \
             is shared by an even number of triangles and the surface bounds a solid"
        );
    }

    #[test]
    fn fonts_and_openscad_word_their_cases() {
        let font = |scene| Error::FontNotFound {
            font: "Nope".into(),
            scene,
        };
        assert_eq!(
            font(true).to_string(),
            "font `Nope` not found (searched the scene's font files, CSGPIX_FONT_PATH, the \
             bundled fonts and the system fonts)"
        );
        assert_eq!(
            font(false).to_string(),
            "font `Nope` not found (searched CSGPIX_FONT_PATH, the bundled fonts and the system \
             fonts)"
        );
        let unread = Error::FontUnreadable {
            font: "X".into(),
            parsed: true,
        };
        assert_eq!(unread.to_string(), "font `X` could not be parsed");
        assert_eq!(
            Error::NoOpenscad { scad: true }
                .context("p.scad")
                .to_string(),
            "p.scad: reading .scad needs openscad on PATH (Debian: apt-get install openscad); or \
             export File → Export → Export as CSG and give the .csg"
        );
        let failed = Error::OpenscadFailed {
            action: "mesh",
            why: "ERROR: Parser error\nin file".into(),
        };
        assert_eq!(
            failed.to_string(),
            format!(
                "openscad could not mesh it: {}",
                OneLine("ERROR: Parser error\nin file")
            ),
            "a library's or program's text stays one line"
        );
    }

    #[test]
    fn an_image_size_wraps_why_that_size_is_refused() {
        let e = Error::ImageSize {
            width: 3,
            height: 2,
            problem: Box::new(Error::SurfaceTooLarge {
                lines: 2,
                columns: 3,
                vertices: 20,
                left: 10,
            }),
        };
        assert_eq!(
            Error::at("h.png", 0, 17, e).to_string(),
            "h.png:0:17: a 3×2 image: a grid of 2 × 3 heights would pass the scene's vertex \
             limit: 20 more vertices, 10 left (the limit follows the memory limit, e.g. \
             --max-memory)"
        );
    }
    #[test]
    fn nrrd_header_variants_keep_their_messages() {
        let e = Error::DuplicateField {
            name: "sizes".into(),
            first_line: 3,
        };
        assert_eq!(
            Error::at("v.nrrd", 5, 1, e).to_string(),
            "v.nrrd:5:1: `sizes` given twice (first on line 3)"
        );
        let e = Error::UnsupportedEncoding {
            encoding: "bzip2".into(),
        };
        assert_eq!(
            e.to_string(),
            "expected encoding raw or gzip (`bzip2` is not supported)"
        );
        let e = Error::TooManySamples {
            sizes: [2, 3, 4],
            limit: 10,
            set_by: Some("--max-memory"),
        };
        assert_eq!(
            e.to_string(),
            "sizes 2×3×4 exceed the limit of 10 samples (--max-memory)"
        );
        let e = Error::DataBytes {
            sizes: [2, 2, 2],
            ty: "uint16",
            bytes: 16,
            gzip: true,
            found: Some(3),
        };
        assert_eq!(
            e.to_string(),
            "sizes 2×2×2 of uint16 need 16 data bytes after decompression, found only 3"
        );
        let e = Error::ExpectedHere {
            expected: "`(x,y,z)` or `none`".into(),
        };
        assert_eq!(e.to_string(), "expected `(x,y,z)` or `none`");
    }

    #[test]
    fn xml_mesh_and_dxf_variants_keep_their_messages() {
        let e = Error::UnitIgnored {
            unit: "inch".into(),
            format: "AMF",
            whatever: true,
        };
        assert_eq!(
            e.to_string(),
            "unit \"inch\" is ignored: OpenSCAD 2021.01 reads AMF coordinates as millimetres, \
             whatever the unit"
        );
        let e = Error::NotApplied {
            what: "components are",
        };
        assert_eq!(
            e.to_string(),
            "components are not applied: OpenSCAD 2021.01 imports each mesh object once, where \
             it is defined"
        );
        let e = Error::AttributeVertexIndex {
            attribute: "v2",
            text: "9".into(),
            count: 4,
        };
        assert_eq!(
            e.to_string(),
            "v2=\"9\" must index the mesh's 4 vertices (from 0)"
        );
        let e = Error::DxfAngleTurns {
            entity: "ARC".into(),
            turns: 1e6,
        };
        assert_eq!(
            e.to_string(),
            "the ARC entity's end angle is more than 1e6 turns below its start"
        );
        let e = Error::Compile {
            reason: "bad\ncolour".into(),
        };
        assert_eq!(e.to_string(), OneLine("bad\ncolour").to_string());
    }
}
