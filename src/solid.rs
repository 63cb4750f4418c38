//! Scenes as CSG trees over convex solids: what the `.csg` reader produces and what projection
//! turns into planes for the array.

/// A convex polyhedron in scene coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexSolid {
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
    Solid(usize),
    Union(Vec<CsgNode>),
    Intersection(Vec<CsgNode>),
    /// The first child minus all the others.
    Difference(Vec<CsgNode>),
    /// Everything outside the child (from the `!` of CSG expressions; files never make it).
    Complement(Box<CsgNode>),
    /// Nothing (an empty group).
    Empty,
}

/// A whole scene.
#[derive(Clone, Debug, PartialEq)]
pub struct CsgScene {
    pub solids: Vec<ConvexSolid>,
    pub root: CsgNode,
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
