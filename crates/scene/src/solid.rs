//! Scenes as CSG trees over convex solids: what the `.csg` reader produces and what projection
//! turns into planes for the array.

/// A convex polyhedron in scene coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexSolid {
    /// The corners, in scene coordinates.
    pub vertices: Vec<[f64; 3]>,
    /// Faces as vertex indices, counter-clockwise seen from outside (outward normals by the
    /// right-hand rule).
    pub faces: Vec<Vec<usize>>,
    /// RGBA from `color(...)`, if any.
    pub colour: Option<[f64; 4]>,
    /// 1-based line of the node that made it, for messages.
    pub line: usize,
}

/// A CSG tree whose leaves index [`CsgScene::solids`].
#[derive(Clone, Debug, PartialEq)]
pub enum CsgNode {
    /// Primitive i of the scene (a leaf).
    Solid(usize),
    /// Everything in any child.
    Union(Vec<CsgNode>),
    /// Everything in every child.
    Intersection(Vec<CsgNode>),
    /// The first child minus all the others.
    Difference(Vec<CsgNode>),
    /// Everything outside the child (from the `!` of CSG expressions; files never make it).
    Complement(Box<CsgNode>),
    /// Nothing (an empty group).
    Empty,
}

/// A primitive read from a file rather than drawn from planes (§3.2: "volumetric shapes
/// defined ... by data sets read from disk"): a volume dataset with an iso threshold, or a
/// closed triangle mesh. The scene only names it; `csgpix_voxel::sampled` loads it.
#[derive(Clone, Debug, PartialEq)]
pub struct Import {
    /// The file as written in the scene (relative paths are relative to the scene's file).
    pub file: String,
    /// Datasets: InPrimitive(v) is "the sample at v's centre is at or above this".
    pub threshold: Option<f64>,
    /// Scene ← file coordinates, row-major 4×4 (affine); None is the identity.
    pub matrix: Option<[[f64; 4]; 4]>,
    /// RGBA from `color(...)`, if any.
    pub colour: Option<[f64; 4]>,
    /// The line where the scene names it (1-based), for messages.
    pub line: usize,
    /// The column there (1-based, in characters).
    pub col: usize,
    /// A mesh the scene itself made (an extrusion the array cannot draw as a convex solid,
    /// `csgpix_openscad::extrude`): closed triangles in scene coordinates; `file` then names the node.
    pub mesh: Option<std::sync::Arc<Vec<[[f64; 3]; 3]>>>,
}

/// Leaf numbers from which imports count while a scene is assembled (no scene holds this many
/// solids); [`CsgNode::number_imports_after`] puts them after the solids.
pub const IMPORTED: usize = usize::MAX / 2;

/// A whole scene. The tree's leaf `Solid(i)` is `solids[i]` for i below `solids.len()`, and
/// `imports[i - solids.len()]` above: the Blist and the other evaluators treat both alike
/// (§4.3.2); only where a primitive's slice comes from differs.
#[derive(Clone, Debug, PartialEq)]
pub struct CsgScene {
    /// The convex solids, leaves `0..solids.len()`.
    pub solids: Vec<ConvexSolid>,
    /// The imported primitives, the leaves after the solids.
    pub imports: Vec<Import>,
    /// The tree over both.
    pub root: CsgNode,
    /// What the reader noticed but drew anyway, as OpenSCAD warns (an empty primitive, a 2D
    /// child beside solids, a colour out of range): one located line each,
    /// `FILE:LINE:COL: message`, the refusal `--strict` makes of it. The command line prints
    /// each as `csgpix: warning: …`, `--json` lists them, Python raises `warnings.warn`.
    pub warnings: Vec<crate::Error>,
    /// The memory (bytes) the reader held besides the scene and freed: what drawing `text()`
    /// charged against its budget (its glyphs and their union), and the most one extrusion's
    /// 2D outlines held before they were extruded. Freed blocks stay with the process (the
    /// allocator keeps their pages for later blocks: the 4,956 circles of
    /// `vectors/scenes/pulley-plate.scad`, 86 MB, left the run's resident size that much
    /// above what the run holds), so a voxelize run's estimate counts this beside its own.
    pub reading_bytes: u64,
}

impl CsgScene {
    /// A scene of convex solids only.
    pub fn convex(solids: Vec<ConvexSolid>, root: CsgNode) -> CsgScene {
        CsgScene {
            solids,
            imports: vec![],
            root,
            warnings: vec![],
            reading_bytes: 0,
        }
    }

    /// Primitives of every kind: the leaves' index range.
    pub fn primitive_count(&self) -> usize {
        self.solids.len() + self.imports.len()
    }

    /// Refuse a scene with imported primitives, for the commands that only draw planes.
    pub fn require_convex(&self, file: &str, what: &str) -> crate::Result<()> {
        match self.imports.first() {
            None => Ok(()),
            Some(i) => {
                let name = match i.mesh {
                    Some(_) => format!("`{}` (not a convex solid)", i.file),
                    None => format!("`import(\"{}\")`", i.file),
                };
                let problem = crate::Error::ConvexOnly {
                    primitive: name,
                    command: what.to_string(),
                };
                Err(problem.located(file, i.line, i.col))
            }
        }
    }
}

impl CsgNode {
    /// The node's operands, in order (none for a solid or an empty node).
    pub fn children(&self) -> &[CsgNode] {
        match self {
            CsgNode::Union(c) | CsgNode::Intersection(c) | CsgNode::Difference(c) => c,
            CsgNode::Complement(c) => std::slice::from_ref(&**c),
            CsgNode::Solid(_) | CsgNode::Empty => &[],
        }
    }

    /// Call `f` on every leaf (`Solid` or `Empty`) of the tree, mutably, without recursion
    /// (trees can be as deep as a file makes them). `f` may replace the leaf.
    pub fn for_each_leaf_mut(&mut self, mut f: impl FnMut(&mut CsgNode)) {
        let mut stack = vec![self];
        while let Some(node) = stack.pop() {
            match node {
                CsgNode::Union(c) | CsgNode::Intersection(c) | CsgNode::Difference(c) => {
                    stack.extend(c.iter_mut())
                }
                CsgNode::Complement(c) => stack.push(c),
                CsgNode::Solid(_) | CsgNode::Empty => f(node),
            }
        }
    }

    /// Imports numbered `Solid(IMPORTED + j)` while a scene is assembled become
    /// `Solid(solids + j)`: they follow the solids ([`CsgScene`]).
    pub fn number_imports_after(&mut self, solids: usize) {
        self.for_each_leaf_mut(|n| {
            if let CsgNode::Solid(i) = n {
                if *i >= IMPORTED {
                    *i = *i - IMPORTED + solids;
                }
            }
        });
    }

    /// Move the operands out, leaving the node without children.
    fn take_children(&mut self) -> Vec<CsgNode> {
        match self {
            CsgNode::Union(c) | CsgNode::Intersection(c) | CsgNode::Difference(c) => {
                std::mem::take(c)
            }
            CsgNode::Complement(c) => vec![std::mem::replace(&mut **c, CsgNode::Empty)],
            CsgNode::Solid(_) | CsgNode::Empty => vec![],
        }
    }
}

impl Drop for CsgNode {
    /// Dropping a tree as deep as a file can make must not recurse once per level.
    fn drop(&mut self) {
        let mut stack = self.take_children();
        while let Some(mut n) = stack.pop() {
            stack.append(&mut n.take_children());
        }
    }
}
