//! The nodes csgpix reads, their parameters, and arguments bound to them.

use csgpix_scene::error::{CsgError, Rule};

use crate::{lex::*, value::*};

// Nodes and their parameters

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum NodeKind {
    Group,
    Union,
    Difference,
    Intersection,
    Render,
    Multmatrix,
    Color,
    Cube,
    Sphere,
    Cylinder,
    Polyhedron,
    Import,
    Square,
    Circle,
    Polygon,
    LinearExtrude,
    RotateExtrude,
    Hull,
    Minkowski,
    Offset,
    Projection,
    Resize,
    Text,
    Surface,
}

/// How the children of an operation combine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Op {
    Union,
    Intersection,
    Difference,
}

/// Every node this reader understands, by name.
pub(crate) const NODES: [(&str, NodeKind); 24] = [
    ("group", NodeKind::Group),
    ("union", NodeKind::Union),
    ("difference", NodeKind::Difference),
    ("intersection", NodeKind::Intersection),
    ("multmatrix", NodeKind::Multmatrix),
    ("color", NodeKind::Color),
    ("render", NodeKind::Render),
    ("cube", NodeKind::Cube),
    ("sphere", NodeKind::Sphere),
    ("cylinder", NodeKind::Cylinder),
    ("polyhedron", NodeKind::Polyhedron),
    ("import", NodeKind::Import),
    ("square", NodeKind::Square),
    ("circle", NodeKind::Circle),
    ("polygon", NodeKind::Polygon),
    ("linear_extrude", NodeKind::LinearExtrude),
    ("rotate_extrude", NodeKind::RotateExtrude),
    ("hull", NodeKind::Hull),
    ("minkowski", NodeKind::Minkowski),
    ("offset", NodeKind::Offset),
    ("projection", NodeKind::Projection),
    ("resize", NodeKind::Resize),
    ("text", NodeKind::Text),
    ("surface", NodeKind::Surface),
];

impl NodeKind {
    pub(crate) fn from_name(name: &str) -> Option<Self> {
        NODES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, kind)| kind)
    }

    pub(crate) fn name(self) -> &'static str {
        NODES
            .iter()
            .find(|(_, kind)| *kind == self)
            .map_or("?", |(name, _)| name)
    }

    /// Parameters taken by position (in OpenSCAD's order), then those taken only by name.
    pub(crate) fn parameters(self) -> (&'static [&'static str], &'static [&'static str]) {
        match self {
            NodeKind::Group
            | NodeKind::Union
            | NodeKind::Difference
            | NodeKind::Intersection
            | NodeKind::Hull => (&[], &[]),
            NodeKind::Square => (&["size", "center"], &[]),
            NodeKind::Circle => (&["r"], &["d", "$fn", "$fa", "$fs"]),
            NodeKind::Polygon => (&["points", "paths", "convexity"], &[]),
            NodeKind::LinearExtrude => (
                &["height", "center", "convexity", "twist", "slices", "scale"],
                &["v", "$fn", "$fa", "$fs"],
            ),
            NodeKind::RotateExtrude => (&["angle", "convexity"], &["$fn", "$fa", "$fs"]),
            NodeKind::Offset => (&["r"], &["delta", "chamfer", "$fn", "$fa", "$fs"]),
            NodeKind::Text => (
                &["text", "size", "font"],
                &[
                    "direction",
                    "language",
                    "script",
                    "halign",
                    "valign",
                    "spacing",
                    "$fn",
                    "$fa",
                    "$fs",
                ],
            ),
            // `convexity` only guides OpenSCAD's preview: read and ignored.
            NodeKind::Render | NodeKind::Minkowski => (&["convexity"], &[]),
            NodeKind::Projection => (&["cut"], &["convexity"]),
            NodeKind::Resize => (&["newsize", "auto", "convexity"], &[]),
            NodeKind::Multmatrix => (&["m"], &[]),
            NodeKind::Color => (&["c", "alpha"], &[]),
            NodeKind::Cube => (&["size", "center"], &[]),
            NodeKind::Sphere => (&["r"], &["d", "$fn", "$fa", "$fs"]),
            NodeKind::Cylinder => (
                &["h", "r1", "r2", "center"],
                &["r", "d", "d1", "d2", "$fn", "$fa", "$fs"],
            ),
            NodeKind::Polyhedron => (&["points", "faces", "convexity"], &["triangles"]),
            // `timestamp`: the CSG export's, ignored (module [`crate::surface`]).
            NodeKind::Surface => (&["file", "center", "convexity"], &["invert", "timestamp"]),
            // OpenSCAD's own parameters (read and ignored: they concern 2D files), and ours.
            NodeKind::Import => (
                &["file", "layer", "convexity"],
                &[
                    "origin",
                    "scale",
                    "center",
                    "dpi",
                    "id",
                    "timestamp",
                    "$fn",
                    "$fa",
                    "$fs",
                    "threshold",
                ],
            ),
        }
    }

    pub(crate) fn is_leaf(self) -> bool {
        matches!(
            self,
            NodeKind::Cube
                | NodeKind::Sphere
                | NodeKind::Cylinder
                | NodeKind::Polyhedron
                | NodeKind::Import
                | NodeKind::Square
                | NodeKind::Circle
                | NodeKind::Polygon
                | NodeKind::Text
                | NodeKind::Surface
        )
    }

    /// Operations that take their children's geometry while the scene is read (their result
    /// is a new leaf, or their leaves are moved), so an imported mesh file below one is read
    /// then.
    pub(crate) fn needs_geometry(self) -> bool {
        matches!(
            self,
            NodeKind::Projection | NodeKind::Hull | NodeKind::Minkowski | NodeKind::Resize
        )
    }

    /// Leaves of the plane (2D shapes).
    pub(crate) fn is_flat(self) -> bool {
        matches!(
            self,
            NodeKind::Square | NodeKind::Circle | NodeKind::Polygon | NodeKind::Text
        )
    }

    pub(crate) fn op(self) -> Op {
        match self {
            NodeKind::Difference => Op::Difference,
            NodeKind::Intersection => Op::Intersection,
            _ => Op::Union,
        }
    }
}

/// A node's arguments bound to its parameter names.
pub(crate) struct Params {
    pub(crate) node: NodeKind,
    pub(crate) pos: Pos,
    pub(crate) values: Vec<(&'static str, Value)>,
}

impl Params {
    /// Binds arguments as OpenSCAD's `Parameters::parse` does: positional ones in order,
    /// named ones by name; unknown names and repeated parameters are refused.
    pub(crate) fn bind(node: NodeKind, pos: Pos, args: Vec<Arg>) -> Result<Self, Fail> {
        let (positional, named) = node.parameters();
        let mut values: Vec<(&'static str, Value)> = Vec::new();
        let mut next_positional = positional.iter();
        for arg in args {
            let (name, at) = match &arg.name {
                Some((name, at)) => {
                    let known = positional.iter().chain(named).find(|p| **p == name);
                    let Some(&known) = known else {
                        return fail(*at, Self::unknown(node, name));
                    };
                    (known, *at)
                }
                None => match next_positional.next() {
                    Some(&name) => (name, arg.value.pos),
                    None => {
                        let node = node.name();
                        return fail(arg.value.pos, CsgError::TooManyPositional { node });
                    }
                },
            };
            if values.iter().any(|(n, _)| *n == name) {
                return fail(at, CsgError::ArgumentTwice { name });
            }
            values.push((name, arg.value));
        }
        Ok(Params { node, pos, values })
    }

    pub(crate) fn unknown(node: NodeKind, name: &str) -> CsgError {
        let (positional, named) = node.parameters();
        CsgError::UnknownParameter {
            node: node.name(),
            name: name.to_string(),
            known: positional.iter().chain(named).copied().collect(),
        }
    }

    /// The value of a parameter; `undef` counts as not given.
    pub(crate) fn get(&self, name: &str) -> Option<&Value> {
        self.values
            .iter()
            .find(|(n, v)| *n == name && v.kind != Kind::Undef)
            .map(|(_, v)| v)
    }

    pub(crate) fn number(&self, name: &str) -> Result<Option<(f64, Pos)>, Fail> {
        match self.get(name) {
            None => Ok(None),
            Some(v) => Ok(Some((v.number(&format!("`{name}`"))?, v.pos))),
        }
    }

    pub(crate) fn boolean(&self, name: &str) -> Result<bool, Fail> {
        match self.get(name) {
            None => Ok(false),
            Some(Value {
                kind: Kind::Bool(b),
                ..
            }) => Ok(*b),
            Some(v) => fail(v.pos, must(&format!("`{name}`"), Rule::Boolean)),
        }
    }

    pub(crate) fn require(&self, name: &str, usage: &str) -> Result<&Value, Fail> {
        self.get(name).ok_or_else(|| Fail {
            pos: self.pos,
            problem: csgpix_scene::Error::NeedsArgument {
                node: self.node.name().to_string(),
                usage: usage.to_string(),
            },
        })
    }
}

/// A statement up to its children: modifiers, node name and arguments.
pub(crate) struct Head {
    pub(crate) kind: NodeKind,
    pub(crate) pos: Pos,
    pub(crate) params: Params,
    /// `%` or `*`: the statement is left out of the result.
    pub(crate) skip: bool,
}

// ---------------------------------------------------------------------------------------------
// Statements, read with an explicit stack of open nodes
