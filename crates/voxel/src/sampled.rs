//! Primitives sampled rather than drawn: volume datasets and closed triangle meshes beside the
//! convex solids (§3.2-3.3, Figure 5.6: the CT head among cubes and cylinders).
//!
//! The Blist (§4.3.2) and the other evaluators see only a mask per primitive per slab; what
//! differs is where the mask comes from:
//!
//! * a **dataset** (`import("head.nrrd", threshold = t)`): voxel v is inside when the sample
//!   at v's centre, trilinearly interpolated, is at or above t ([`csgpix_scene::dataset`]); the
//!   import's transform maps the dataset into the scene;
//! * a **mesh** (`import("part.stl")`, OBJ too): its triangles are polygons, each a plane cut
//!   by three planes perpendicular to the screen (§5.3.1); along every pixel's ray the depths
//!   where the ray crosses them are found exactly ([`csgpix_scene::trimesh`]), and the solid's
//!   interior is the odd parity of the crossings in front, the XOR of §3.4.2 (crossings in
//!   front of the first slab are the "0th slice"). The inside intervals then meet the slabs
//!   under the same sampling convention and depth-word quantization as the convex solids
//!   ([`crate::voxelize`]), so a mesh of a convex solid's own faces gives that solid's voxels.
//! * a mesh that is **not closed** (holes, fins, a soup): the voxel centres where its
//!   generalized winding number is at least 1/2 ([`csgpix_scene::winding`]), with a warning
//!   naming its open edges ([`Sampled::warning`]).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::{DMat4, DVec3};

use crate::error::{BindingProblem, BindingSyntax, Error, ExprError, Result};
// Here before crate::slabs took it: the public path stays.
pub use crate::slabs::SlabRuns;
use crate::slice::Mask;
use csgpix_draw::project::colour_code;
use csgpix_scene::dataset::Dataset;
use csgpix_scene::footprint::Footprint;
use csgpix_scene::grid::Grid;
use csgpix_scene::nrrd::{read_nrrd_limited, SampleLimit};
use csgpix_scene::solid::{CsgNode, CsgScene, Import, IMPORTED};
use csgpix_scene::trimesh::TriMesh;
use csgpix_scene::winding::OpenMesh;
use csgpix_scene::Location;

/// What a sampled primitive is.
#[derive(Clone)]
pub enum Shape {
    /// A dataset and its iso value; `to_file` maps scene points into the dataset's own space.
    Dataset {
        /// The samples.
        data: Box<Dataset>,
        /// The iso value: samples at or above it are inside.
        threshold: f64,
        /// Scene space → the dataset's own space.
        to_file: DMat4,
    },
    /// A closed mesh, in scene coordinates.
    Mesh(TriMesh),
    /// A mesh that is not closed (holes, fins, a soup of triangles), in scene coordinates:
    /// inside where its generalized winding number is at least 1/2
    /// ([`csgpix_scene::winding`]). With the warning that names its open edges, located
    /// where the scene or the command line names the file (None when the scene's reader
    /// warned of it already, as for a `polyhedron()`).
    OpenMesh(Box<OpenMesh>, Option<csgpix_scene::Error>),
    /// A straight extrusion of a large 2D tree, kept as its footprint (the 2D tree, its
    /// height and placement, [`csgpix_scene::footprint`]): a pixel is inside over the
    /// extrusion's depth range where the tree holds its centre.
    Footprint(Arc<Footprint>),
}

/// A loaded import.
#[derive(Clone)]
pub struct Sampled {
    /// What it is.
    pub shape: Shape,
    /// Palette code (1..=15) of its voxels, as for a convex solid.
    pub colour: u8,
    /// The file, as the scene names it.
    pub file: String,
}

impl Sampled {
    /// The `space` its dataset's file declared, if it is a dataset and declared one.
    pub fn space(&self) -> Option<&str> {
        match &self.shape {
            Shape::Dataset { data, .. } => data.nrrd.space.as_deref(),
            _ => None,
        }
    }

    /// Scene-space box around the primitive.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        match &self.shape {
            Shape::Mesh(m) => m.bounds(),
            Shape::OpenMesh(m, _) => m.mesh().bounds(),
            Shape::Footprint(f) => f.bounds(),
            Shape::Dataset { data, to_file, .. } => {
                let (lo, hi) = data.bounds();
                let to_scene = to_file.inverse();
                corners(lo, hi)
                    .map(|c| to_scene.transform_point3(c))
                    .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), p| {
                        (a.min(p), b.max(p))
                    })
            }
        }
    }

    /// Scene-space box around what it fills, as far as its own structure tells: a
    /// footprint's follows its 2D operations ([`Footprint::set_bounds`]); any other's is
    /// [`Sampled::bounds`].
    pub fn set_bounds(&self) -> (DVec3, DVec3) {
        match &self.shape {
            Shape::Footprint(f) => f.set_bounds(),
            _ => self.bounds(),
        }
    }

    /// Whether [`Sampled::set_bounds`] is the box of what it fills: false for a footprint
    /// whose 2D tree intersects or subtracts ([`Footprint::set_bounds_exact`]).
    pub fn set_bounds_exact(&self) -> bool {
        match &self.shape {
            Shape::Footprint(f) => f.set_bounds_exact(),
            _ => true,
        }
    }

    /// Datasets: the sample at scene point `p` (None outside the dataset's lattice).
    pub fn sample(&self, p: DVec3) -> Option<f64> {
        match &self.shape {
            Shape::Dataset { data, to_file, .. } => data.sample(to_file.transform_point3(p)),
            Shape::Mesh(_) | Shape::OpenMesh(..) | Shape::Footprint(_) => None,
        }
    }

    /// Datasets: InPrimitive at scene point `p`.
    pub fn inside(&self, p: DVec3) -> bool {
        match &self.shape {
            Shape::Dataset { threshold, .. } => self.sample(p).is_some_and(|v| v >= *threshold),
            Shape::Mesh(_) | Shape::OpenMesh(..) | Shape::Footprint(_) => false,
        }
    }

    /// Datasets: the grey colour (1..=255) of the sample at `p` (§4.5: the winner's colour).
    pub fn grey(&self, p: DVec3) -> Option<u8> {
        match &self.shape {
            Shape::Dataset { data, .. } => self.sample(p).map(|v| data.grey(v)),
            Shape::Mesh(_) | Shape::OpenMesh(..) | Shape::Footprint(_) => None,
        }
    }

    /// Bytes voxelizing it on `grid` needs beyond the solids' share: a mesh's crossings, one
    /// list per pixel (24 bytes) and about two crossings of 8 bytes each (plus as much while
    /// they are collected), and its slab runs and toggles; a dataset is resampled in place.
    pub fn memory_estimate(&self, grid: &Grid) -> u64 {
        self.memory_estimate_over(grid.slice_len() as u64)
    }

    /// [`Sampled::memory_estimate`] for a mesh whose crossings are kept over `pixels` pixels
    /// only (its outline, on the run route).
    pub fn memory_estimate_over(&self, pixels: u64) -> u64 {
        match &self.shape {
            Shape::Mesh(m) => pixels * (24 + 2 * 16 + 24 + 2 * 8) + m.triangles.len() as u64 * 64,
            // Signed crossings (24 bytes each while collected and kept) for the runs.
            Shape::OpenMesh(m, _) => {
                pixels * (24 + 2 * 24 + 24 + 2 * 8) + m.mesh().triangles.len() as u64 * 64
            }
            // The pixel mask (a byte each, and as much again while the tree's operands are
            // combined) and one slab run per pixel.
            Shape::Footprint(f) => pixels * (24 + 2 + 8) + f.bytes(),
            Shape::Dataset { .. } => 0,
        }
    }

    /// The warning a mesh that is not closed carries ([`Shape::OpenMesh`]).
    pub fn warning(&self) -> Option<&csgpix_scene::Error> {
        match &self.shape {
            Shape::OpenMesh(_, w) => w.as_ref(),
            _ => None,
        }
    }

    /// Whether it is a dataset (not a mesh).
    pub fn is_dataset(&self) -> bool {
        matches!(self.shape, Shape::Dataset { .. })
    }

    /// Datasets: the mask of slab k, from the samples at the voxel centres.
    pub fn dataset_mask(&self, grid: &Grid, k: usize) -> Mask {
        let nx = grid.dims[0];
        Mask::from_fn(grid.slice_len(), |i| {
            self.inside(grid.centre(i % nx, i / nx, k))
        })
    }
}

/// The eight corners of a box.
pub(crate) fn corners(lo: DVec3, hi: DVec3) -> impl Iterator<Item = DVec3> {
    (0..8).map(move |c| {
        DVec3::new(
            if c & 1 == 0 { lo.x } else { hi.x },
            if c & 2 == 0 { lo.y } else { hi.y },
            if c & 4 == 0 { lo.z } else { hi.z },
        )
    })
}

/// A scene and its loaded imports (`sampled[j]` is the primitive `solids.len() + j`).
#[derive(Clone)]
pub struct Loaded {
    /// The scene: its solids, its imports named, its tree.
    pub scene: CsgScene,
    /// Its imports, loaded, in the scene's order.
    pub sampled: Vec<Sampled>,
}

impl Loaded {
    /// A grid over every primitive's bounds (subtracted ones too).
    pub fn grid(&self, dims: [usize; 3]) -> Result<Grid> {
        let (lo, hi) = self.bounds()?;
        Ok(Grid::new(dims, lo, hi)?)
    }

    /// The grid `spec` over `bounds`, or over the scene's own box when none is given.
    pub fn grid_over(
        &self,
        spec: &csgpix_scene::grid::GridSpec,
        bounds: Option<(DVec3, DVec3)>,
    ) -> Result<Grid> {
        let (lo, hi) = match bounds {
            Some(b) => b,
            None => self.bounds()?,
        };
        Ok(spec.grid(lo, hi)?)
    }

    /// The box around every primitive (subtracted ones too); [`Error::NeedsBounds`] when
    /// there is no primitive.
    pub fn bounds(&self) -> Result<(DVec3, DVec3)> {
        let solid_pts = self.scene.solids.iter().flat_map(|s| s.vertices.iter());
        let mut lo = DVec3::INFINITY;
        let mut hi = DVec3::NEG_INFINITY;
        for p in solid_pts {
            lo = lo.min(DVec3::from(*p));
            hi = hi.max(DVec3::from(*p));
        }
        for s in &self.sampled {
            let (a, b) = s.bounds();
            lo = lo.min(a);
            hi = hi.max(b);
        }
        if !lo.is_finite() {
            return Err(Error::NeedsBounds);
        }
        Ok((lo, hi))
    }
}

/// Read a `.csg` scene and every file it imports (relative to the scene's directory).
pub fn load_scene(path: &Path) -> Result<Loaded> {
    load_scene_with(path, &csgpix_openscad::ReadOptions::default())
}

/// [`load_scene`] with the reader's options (`--fallback openscad`). The warnings of reading
/// the imported files (a mesh that is not closed, a 3MF transform OpenSCAD does not apply)
/// join the scene's; under [`ReadOptions::strict`](csgpix_openscad::ReadOptions::strict) the
/// first is the error instead.
pub fn load_scene_with(path: &Path, options: &csgpix_openscad::ReadOptions) -> Result<Loaded> {
    let name = path.display().to_string();
    let mut scene = csgpix_openscad::read_scene_with(path, options)?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let (sampled, warnings) = load_imports_warned(&scene, &name, &dir, options.samples)?;
    if let (Some(first), true) = (warnings.first(), options.strict) {
        return Err(first.clone().into());
    }
    scene.warnings.extend(warnings);
    Ok(Loaded { scene, sampled })
}

/// Load the scene's imports; `scene_file` names the scene in messages, `dir` is where
/// relative paths start.
pub fn load_imports(scene: &CsgScene, scene_file: &str, dir: &Path) -> Result<Vec<Sampled>> {
    load_imports_limited(scene, scene_file, dir, SampleLimit::NONE)
}

/// [`load_imports`], datasets of at most `samples` samples.
pub fn load_imports_limited(
    scene: &CsgScene,
    scene_file: &str,
    dir: &Path,
    samples: SampleLimit,
) -> Result<Vec<Sampled>> {
    load_imports_warned(scene, scene_file, dir, samples).map(|(s, _)| s)
}

/// [`load_imports_limited`] and the warnings of reading the mesh files (a 3MF build
/// transform OpenSCAD 2021.01 does not apply, say: `csgpix_scene::trimesh::TriMesh::read_with_warnings`).
pub fn load_imports_warned(
    scene: &CsgScene,
    scene_file: &str,
    dir: &Path,
    samples: SampleLimit,
) -> Result<(Vec<Sampled>, Vec<csgpix_scene::Error>)> {
    use rayon::prelude::*;
    let first = scene.solids.len();
    // The imports in parallel (a file's parse and weld, an extrusion's weld and closure
    // check), then taken in order: the first failing import's error, every warning in the
    // order the imports come, as when they were read one by one.
    let each: Vec<(Result<Sampled>, Vec<csgpix_scene::Error>)> = (scene.imports.par_iter())
        .enumerate()
        .map(|(j, imp)| {
            let at = Location {
                file: scene_file.to_string(),
                line: imp.line,
                col: imp.col,
            };
            let mut warnings = vec![];
            let origin = Origin::Scene(at);
            let r = load_import(imp, first + j, &origin, dir, samples, &mut warnings);
            (r, warnings)
        })
        .collect();
    let mut warnings = vec![];
    let mut sampled = Vec::with_capacity(each.len());
    for (r, w) in each {
        warnings.extend(w);
        sampled.push(r?);
    }
    Ok((sampled, warnings))
}

/// Where an import was named, for messages.
enum Origin<'a> {
    /// By `import(…)` in a scene file.
    Scene(Location),
    /// By a primitive name's binding ([`Binding`]).
    Binding(&'a str),
}

impl Origin<'_> {
    /// The import's file is missing.
    fn missing(&self, file: &str, path: PathBuf) -> Error {
        let file = file.to_string();
        match self {
            Origin::Scene(at) => {
                let problem = csgpix_scene::Error::NoSuchImport { file, path };
                csgpix_scene::Error::at(&at.file, at.line, at.col, problem).into()
            }
            Origin::Binding(name) => Error::Binding {
                name: name.to_string(),
                problem: BindingProblem::NoSuchFile { file, path },
            },
        }
    }
}

/// Load one import (primitive `index`); `origin` says where it was named.
fn load_import(
    imp: &Import,
    index: usize,
    origin: &Origin,
    dir: &Path,
    samples: SampleLimit,
    warnings: &mut Vec<csgpix_scene::Error>,
) -> Result<Sampled> {
    let colour = imp
        .colour
        .map_or(1 + (index % 6) as u32, colour_code)
        .min(255) as u8;
    if let Some(f) = &imp.footprint {
        return Ok(Sampled {
            shape: Shape::Footprint(f.clone()),
            colour,
            file: imp.file.clone(),
        });
    }
    if let Some(tris) = &imp.mesh {
        // A mesh the scene made itself (an extrusion): named by the node, not a file.
        let at = match origin {
            Origin::Scene(at) => at.to_string(),
            Origin::Binding(name) => name.to_string(),
        };
        let mesh = TriMesh::from_f64(tris);
        // Not closed: the reader warned of it (`polyhedron()`).
        let shape = mesh_shape(mesh, &format!("{at}: `{}`", imp.file), |_| None)?;
        return Ok(Sampled {
            shape,
            colour,
            file: imp.file.clone(),
        });
    }
    let path: PathBuf = dir.join(&imp.file);
    if !path.is_file() {
        return Err(origin.missing(&imp.file, path));
    }
    let to_scene = imp.matrix.map_or(DMat4::IDENTITY, |m| {
        DMat4::from_cols_array_2d(&m).transpose()
    });
    let shape = match imp.threshold {
        Some(threshold) => {
            let data = Box::new(read_nrrd_limited(&path, samples).and_then(Dataset::new)?);
            Shape::Dataset {
                data,
                threshold,
                to_file: to_scene.inverse(),
            }
        }
        None => {
            let (mesh, found) = TriMesh::read_with_warnings(&path)?;
            warnings.extend(found);
            // Closed or not as read: placing it keeps its triangles' indices. An open mesh's
            // warning joins the scene's, located at the import.
            let mesh = mesh.transformed(to_scene);
            let warn = |what: &str| Some(open_warning(origin, &imp.file, what));
            let mut shape = mesh_shape(mesh, &path.display().to_string(), warn)?;
            if let Shape::OpenMesh(_, w) = &mut shape {
                warnings.extend(w.take());
            }
            shape
        }
    };
    Ok(Sampled {
        shape,
        colour,
        file: imp.file.clone(),
    })
}

/// A mesh as a primitive: a closed one (every edge shared by an even number of triangles,
/// [`TriMesh::check_closed`]) sliced by parity as ever; any other by its winding number, with
/// `warn(what is open)` as its warning. Errors as [`TriMesh::check_closed`] for a mesh with no
/// proper triangle; `file` names it there.
fn mesh_shape(
    mesh: TriMesh,
    file: &str,
    warn: impl Fn(&str) -> Option<csgpix_scene::Error>,
) -> Result<Shape> {
    Ok(match mesh.open_edges_summary(file)? {
        None => Shape::Mesh(mesh),
        Some(what) => Shape::OpenMesh(Box::new(OpenMesh::new(&mesh)), warn(&what)),
    })
}

/// The warning for an imported mesh that is not closed, located where it is named.
fn open_warning(origin: &Origin, file: &str, what: &str) -> csgpix_scene::Error {
    let warning = csgpix_scene::Error::OpenMeshVoxelized {
        file: file.to_string(),
        open: what.to_string(),
    };
    match origin {
        Origin::Scene(at) => warning.located(&at.file, at.line, at.col),
        Origin::Binding(name) => warning.context(format_args!("--prim {name}")),
    }
}

/// A primitive name of a CSG expression bound to a file (`NAME=FILE[,threshold=T]`):
/// a `.csg` scene (its whole tree stands for the name), a dataset (`.nrrd`, with its
/// threshold) or a mesh (`.stl`, `.obj`, `.off`, `.amf`, `.3mf`).
#[derive(Clone, Debug, PartialEq)]
pub struct Binding {
    /// The primitive name (letters, digits, `_`; a letter first).
    pub name: String,
    /// The file it stands for.
    pub file: PathBuf,
    /// A dataset's iso value (§3.2): samples at or above it are inside.
    pub threshold: Option<f64>,
}

/// A binding from its text, `NAME=FILE[,threshold=T]`.
pub fn parse_binding(s: &str) -> Result<Binding> {
    let bad = |problem| Error::BadBinding {
        spec: s.to_string(),
        problem,
    };
    let (name, rest) = s
        .split_once('=')
        .ok_or_else(|| bad(BindingSyntax::NoEquals))?;
    let (file, threshold) = match rest.rsplit_once(",threshold=") {
        Some((f, t)) => {
            let t: f64 = t.trim().parse().map_err(|error| {
                let text = t.to_string();
                bad(BindingSyntax::Threshold { text, error })
            })?;
            if !t.is_finite() {
                return Err(bad(BindingSyntax::NotFinite));
            }
            (f, Some(t))
        }
        None => (rest, None),
    };
    let name = name.trim();
    let ok = name.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !ok {
        let name = name.to_string();
        return Err(bad(BindingSyntax::BadName { name }));
    }
    Ok(Binding {
        name: name.to_string(),
        file: PathBuf::from(file),
        threshold,
    })
}

/// The scene of a CSG expression (§4.3.2's "named primitives") whose names are bound to
/// files: [`Error::Expr`] when it does not parse, [`Error::Unbound`] for a name bound to no
/// file, [`Error::Binding`] for a binding that does not fit.
///
/// ```
/// use csgpix_voxel::sampled::scene_from_expr;
/// use csgpix_voxel::Error;
///
/// let unbound = scene_from_expr("A + B", &[]).err();
/// assert_eq!(unbound, Some(Error::Unbound { name: "A".into(), col: 1 }));
/// assert!(matches!(scene_from_expr("A +", &[]), Err(Error::Expr(_))));
/// ```
pub fn scene_from_expr(expr: &str, bindings: &[Binding]) -> Result<Loaded> {
    scene_from_expr_with(expr, bindings, &csgpix_openscad::ReadOptions::default())
}

/// [`scene_from_expr`] with the reader's options for the bound files (their datasets'
/// sample limit, the scenes' fallback).
pub fn scene_from_expr_with(
    expr: &str,
    bindings: &[Binding],
    options: &csgpix_openscad::ReadOptions,
) -> Result<Loaded> {
    let e = csgpix_scene::csg_expr::parse(expr).map_err(|error| {
        // The expression is one line: its column is the place to name.
        let col = error.location().map_or(1, |at| at.col);
        Error::Expr(ExprError { col, error })
    })?;
    if let Some(b) = bindings.iter().find(|b| !e.names.contains(&b.name)) {
        return Err(binding(b, BindingProblem::NotInExpression));
    }
    // Every name bound before any file is read.
    let unbound = |i: usize| Error::Unbound {
        name: e.names[i].clone(),
        col: e.columns[i],
    };
    if let Some(i) = (0..e.names.len()).find(|&i| !bindings.iter().any(|b| b.name == e.names[i])) {
        return Err(unbound(i));
    }
    let mut scene = CsgScene::convex(vec![], CsgNode::Empty);
    let mut sampled = vec![];
    let mut parts = vec![];
    for (i, name) in e.names.iter().enumerate() {
        let b = bindings
            .iter()
            .find(|b| &b.name == name)
            .ok_or_else(|| unbound(i))?;
        parts.push(add_part(&mut scene, &mut sampled, b, options)?);
    }
    let mut root = e.root.clone();
    // Every name stands for its part's tree.
    root.for_each_leaf_mut(|n| {
        if let CsgNode::Solid(i) = n {
            *n = parts.get(*i).cloned().unwrap_or(CsgNode::Empty);
        }
    });
    root.number_imports_after(scene.solids.len());
    scene.root = root;
    Ok(Loaded { scene, sampled })
}

/// Add one bound file's primitives to `scene`; its tree, with solids numbered in `scene` and
/// imports as `IMPORTED + j`.
fn add_part(
    scene: &mut CsgScene,
    sampled: &mut Vec<Sampled>,
    b: &Binding,
    options: &csgpix_openscad::ReadOptions,
) -> Result<CsgNode> {
    let is_csg = b
        .file
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("csg"));
    if is_csg {
        if b.threshold.is_some() {
            return Err(binding(b, BindingProblem::ThresholdOnScene));
        }
        let part = load_scene_with(&b.file, options)?;
        let (so, io) = (scene.solids.len(), scene.imports.len());
        let n = part.scene.solids.len();
        let mut tree = part.scene.root.clone();
        tree.for_each_leaf_mut(|leaf| {
            if let CsgNode::Solid(i) = leaf {
                *i = if *i < n {
                    so + *i
                } else {
                    IMPORTED + io + *i - n
                };
            }
        });
        scene.solids.extend(part.scene.solids);
        scene.imports.extend(part.scene.imports);
        sampled.extend(part.sampled);
        return Ok(tree);
    }
    let ext = b.file.extension().map(|x| x.to_ascii_lowercase());
    let ext = ext.as_ref().and_then(|x| x.to_str()).unwrap_or("");
    let mesh = csgpix_scene::trimesh::READ_EXTENSIONS.contains(&ext);
    if !(mesh || ext == "nrrd" || ext == "nhdr") {
        return Err(binding(b, BindingProblem::UnknownFormat(b.file.clone())));
    }
    let dataset = ext == "nrrd" || ext == "nhdr";
    if dataset != b.threshold.is_some() {
        let problem = match dataset {
            true => BindingProblem::NeedsThreshold,
            false => BindingProblem::ThresholdOnMesh,
        };
        return Err(binding(b, problem));
    }
    let import = Import {
        file: b.file.display().to_string(),
        threshold: b.threshold,
        matrix: None,
        colour: None,
        line: 1,
        col: 1,
        footprint: None,
        mesh: None,
    };
    let index = IMPORTED + scene.imports.len();
    let loaded = load_import(
        &import,
        scene.solids.len() + scene.imports.len(),
        &Origin::Binding(&b.name),
        Path::new(""),
        options.samples,
        &mut scene.warnings,
    )?;
    scene.imports.push(import);
    sampled.push(loaded);
    Ok(CsgNode::Solid(index))
}

/// `b`'s binding is wrong.
fn binding(b: &Binding, problem: BindingProblem) -> Error {
    Error::Binding {
        name: b.name.clone(),
        problem,
    }
}
