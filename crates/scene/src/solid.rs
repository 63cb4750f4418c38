//! Scenes as CSG trees over convex solids: what the `.csg` reader produces and what projection
//! turns into planes for the array.

/// A convex polyhedron in scene coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexSolid {
    /// The corners, in scene coordinates.
    pub vertices: Vec<[f64; 3]>,
    /// Faces as vertex indices, counter-clockwise seen from outside (outward normals by the
    /// right-hand rule).
    pub faces: Faces,
    /// RGBA from `color(...)`, if any.
    pub colour: Option<[f64; 4]>,
    /// 1-based line of the node that made it, for messages.
    pub line: usize,
}

/// A solid's faces, each its vertex indices counter-clockwise seen from outside, held face
/// after face in one vector. A prism of 1,080 sides has 1,082 faces: a heap vector per face
/// (72 bytes a side with its header, 20 here) was about a third of the peak of a plate of
/// thousands of such prisms, and an allocation and a free per face (docs/memory.md).
///
/// Invariant: every index and the total count of indices fit a `u32` (the reader's vertex
/// budget keeps a solid far below that). The reader makes no face of fewer than three
/// indices; `push` does not check.
///
/// ```
/// use csgpix_scene::solid::Faces;
///
/// let mut faces = Faces::default();
/// faces.push([0, 1, 2]);
/// faces.push([2, 1, 3, 4]);
/// assert_eq!(faces.len(), 2);
/// assert_eq!(faces.get(1), &[2, 1, 3, 4]);
/// assert_eq!(faces.iter().map(|f| f.len()).sum::<usize>(), 7);
/// assert_eq!(Faces::from(vec![vec![0, 1, 2], vec![2, 1, 3, 4]]), faces);
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Faces {
    /// Every face's indices, face after face.
    index: Vec<u32>,
    /// Where each face ends in `index`.
    end: Vec<u32>,
}

impl Faces {
    /// Room for `faces` faces of `indices` indices in all.
    pub fn with_capacity(faces: usize, indices: usize) -> Faces {
        Faces {
            index: Vec::with_capacity(indices),
            end: Vec::with_capacity(faces),
        }
    }

    /// Add a face (at least three indices, each below 2^32).
    pub fn push(&mut self, face: impl IntoIterator<Item = usize>) {
        self.index.extend(face.into_iter().map(small));
        self.end.push(small(self.index.len()));
    }

    /// The number of faces.
    pub fn len(&self) -> usize {
        self.end.len()
    }

    /// No faces.
    pub fn is_empty(&self) -> bool {
        self.end.is_empty()
    }

    /// Face `i`'s vertex indices.
    pub fn get(&self, i: usize) -> &[u32] {
        &self.index[self.span(i)]
    }

    /// Where face `i`'s indices lie in `index`.
    fn span(&self, i: usize) -> std::ops::Range<usize> {
        let start = i.checked_sub(1).map_or(0, |j| self.end[j] as usize);
        start..self.end[i] as usize
    }

    /// The faces in order.
    pub fn iter(&self) -> FaceIter<'_> {
        FaceIter {
            faces: self,
            next: 0..self.len(),
        }
    }

    /// Turn every face around (a mirroring placement).
    pub fn reverse_each(&mut self) {
        for i in 0..self.len() {
            let span = self.span(i);
            self.index[span].reverse();
        }
    }

    /// Each face as a vector of indices (for code that edits faces one by one).
    pub fn to_vecs(&self) -> Vec<Vec<usize>> {
        self.iter()
            .map(|f| f.iter().map(|&i| i as usize).collect())
            .collect()
    }

    /// The bytes of its two vectors' capacity (indices, ends), for memory estimates.
    pub fn capacity_bytes(&self) -> [usize; 2] {
        [self.index.capacity() * 4, self.end.capacity() * 4]
    }
}

impl<'a> IntoIterator for &'a Faces {
    type Item = &'a [u32];
    type IntoIter = FaceIter<'a>;
    fn into_iter(self) -> FaceIter<'a> {
        self.iter()
    }
}

/// The faces of a [`Faces`], in order ([`Faces::iter`]).
#[derive(Clone, Debug)]
pub struct FaceIter<'a> {
    faces: &'a Faces,
    next: std::ops::Range<usize>,
}

impl<'a> Iterator for FaceIter<'a> {
    type Item = &'a [u32];
    fn next(&mut self) -> Option<&'a [u32]> {
        self.next.next().map(|i| self.faces.get(i))
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        self.next.size_hint()
    }
}

impl DoubleEndedIterator for FaceIter<'_> {
    fn next_back(&mut self) -> Option<Self::Item> {
        self.next.next_back().map(|i| self.faces.get(i))
    }
}

impl ExactSizeIterator for FaceIter<'_> {}

impl From<Vec<Vec<usize>>> for Faces {
    /// Sized once for all the faces, then [`Faces::push`]ed as [`FromIterator`] does.
    fn from(faces: Vec<Vec<usize>>) -> Faces {
        let mut out = Faces::with_capacity(faces.len(), faces.iter().map(Vec::len).sum());
        out.extend(faces);
        out
    }
}

impl<F: IntoIterator<Item = usize>> Extend<F> for Faces {
    fn extend<I: IntoIterator<Item = F>>(&mut self, faces: I) {
        faces.into_iter().for_each(|f| self.push(f));
    }
}

impl<F: IntoIterator<Item = usize>> FromIterator<F> for Faces {
    fn from_iter<I: IntoIterator<Item = F>>(faces: I) -> Faces {
        let mut out = Faces::default();
        out.extend(faces);
        out
    }
}

/// An index or a count of [`Faces`] (its invariant: below 2^32).
fn small(i: usize) -> u32 {
    u32::try_from(i).expect("a solid's face indices fit 32 bits (the reader's vertex budget)")
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
    /// A straight extrusion of a large 2D tree the scene made, kept as its footprint
    /// ([`crate::footprint`]); `file` then names the node.
    pub footprint: Option<std::sync::Arc<crate::footprint::Footprint>>,
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
                let name = match i.mesh.is_some() || i.footprint.is_some() {
                    true => format!("`{}` (not a convex solid)", i.file),
                    false => format!("`import(\"{}\")`", i.file),
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

#[cfg(test)]
mod tests {
    use super::Faces;
    use proptest::prelude::*;

    proptest! {
        /// Faces held in one vector are the faces pushed, in order, whichever way they are
        /// built, and turning each around twice gives them back.
        #[test]
        fn faces_keep_every_face_in_order(
            faces in prop::collection::vec(prop::collection::vec(0usize..100_000, 3..12), 0..40)
        ) {
            let held = Faces::from(faces.clone());
            prop_assert_eq!(held.len(), faces.len());
            prop_assert_eq!(held.to_vecs(), faces.clone());
            prop_assert_eq!(held.iter().len(), faces.len());
            let backwards: Vec<Vec<usize>> = (held.iter().rev())
                .map(|f| f.iter().map(|&v| v as usize).collect())
                .collect();
            prop_assert!(backwards.iter().eq(faces.iter().rev()));
            let collected: Faces = faces.iter().map(|f| f.iter().copied()).collect();
            prop_assert_eq!(&collected, &held);
            for (i, f) in faces.iter().enumerate() {
                let got: Vec<usize> = held.get(i).iter().map(|&v| v as usize).collect();
                prop_assert_eq!(&got, f);
            }
            let mut turned = held.clone();
            turned.reverse_each();
            for (t, f) in turned.iter().zip(&faces) {
                prop_assert!(t.iter().rev().map(|&v| v as usize).eq(f.iter().copied()));
            }
            turned.reverse_each();
            prop_assert_eq!(turned, held);
        }
    }
}
