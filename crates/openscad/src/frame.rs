//! What the reader holds for each open operation (a [`Frame`]), what its children inherit (a
//! [`Ctx`]) and what a finished statement gives its parent (an [`Item`]): the plain data the
//! node families (`primitives`, `flat`, `project`, `import`, …) take and give, so that they
//! depend on it and not on the reader that drives them.

use crate::extrude::{Linear, Offset, Region};
use crate::lex::Pos;
use crate::linalg::Mat4;
use crate::node::NodeKind;
use csgpix_scene::solid::CsgNode;

/// What the solids below a node inherit.
#[derive(Clone, Debug, Default)]
pub(crate) struct Ctx {
    /// `None` is the identity.
    pub(crate) matrix: Option<Mat4>,
    pub(crate) colour: Option<[f64; 4]>,
    pub(crate) skip: bool,
}

/// How an open operation's children end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Closer {
    /// `{ … }`, opened at this position.
    Brace(Pos),
    /// A single child statement: `multmatrix(…) cube(…);`
    Single,
}

/// An operation whose children are being read.
pub(crate) struct Frame {
    pub(crate) kind: NodeKind,
    pub(crate) closer: Closer,
    pub(crate) ctx: Ctx,
    pub(crate) children: Vec<CsgNode>,
    /// 2D children (shapes in the plane of the nearest extrusion), and where the first
    /// 2D shape among them stands.
    pub(crate) flats: Vec<Region>,
    pub(crate) first_flat: Option<Pos>,
    /// 2D or 3D: as OpenSCAD's `applyToChildren`, the dimension of the first child that is
    /// not empty (extrusions and offsets are 2D from the start); children of the other
    /// dimension are ignored with OpenSCAD's warning.
    pub(crate) dim: Option<Dim>,
    /// Where the node stands, for messages.
    pub(crate) pos: Pos,
    /// An extrusion's or offset's parameters, read when it opened.
    pub(crate) spec: Spec,
    /// The transform above an extrusion, a `minkowski()`, … (their children start from the
    /// identity).
    pub(crate) placement: Option<Mat4>,
    /// Where the statement's text starts, for a result kept by its text
    /// ([`crate::reader::Reader`]'s sums).
    pub(crate) start: usize,
}

/// The dimension of an operation's children.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Dim {
    /// Shapes in the plane.
    Flat,
    /// Solids.
    Solid,
}

/// What a finished statement gives its parent: a solid's tree or a 2D region.
pub(crate) enum Item {
    Solid(CsgNode),
    Flat(Region, Pos),
}

/// The parameters of the nodes that act on 2D children.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Spec {
    None,
    Linear(LinearArgs),
    Rotate { angle: f64, res: (f64, f64, f64) },
    Offset(Offset),
    Projection { cut: bool },
    Resize { newsize: [f64; 3], auto: [bool; 3] },
}

/// `linear_extrude` as read: the slices may be left to OpenSCAD's rule.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LinearArgs {
    pub(crate) linear: Linear,
    pub(crate) slices: Option<usize>,
    pub(crate) res: (f64, f64, f64),
}
