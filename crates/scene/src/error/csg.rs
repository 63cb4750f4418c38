//! The problems of the OpenSCAD `.csg` reader (its lexer, parser and nodes), held by
//! [`super::Error::Csg`]; the place is in an enclosing [`super::Error::At`].

use std::fmt;

use super::OneLine;

/// A problem of the OpenSCAD `.csg` reader: a token, statement or argument it refuses.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CsgError {
    // --- Tokens ----------------------------------------------------------------------------
    /// A character that starts no token.
    #[error("unexpected character {found:?}")]
    UnexpectedCharacter {
        /// The character.
        found: char,
    },
    /// A comment (`comment`) or string that runs to the end of the file.
    #[error(
        "unterminated {} (missing `{}`)",
        if *comment { "comment" } else { "string" },
        if *comment { "*/" } else { "\"" }
    )]
    Unterminated {
        /// Whether it is a `/* */` comment, not a string.
        comment: bool,
    },
    /// A number token that does not parse (`out_of_range`: it parses to an infinity).
    #[error(
        "{}",
        if *out_of_range {
            format!("number `{}` is out of range", OneLine(text))
        } else {
            format!("malformed number `{}`", OneLine(text))
        }
    )]
    BadNumber {
        /// The token, as written.
        text: String,
        /// Whether it is well formed but too large.
        out_of_range: bool,
    },

    // --- Statements and arguments ----------------------------------------------------------
    /// A name where a value is expected (an expression, which a CSG export does not hold).
    #[error(
        "expected a value, found `{}` (csgpix reads numbers, true, false, undef, strings and \
         vectors, not expressions)",
        OneLine(name)
    )]
    NotAValue {
        /// The name found.
        name: String,
    },
    /// Statements or vectors (`what`) nested deeper than csgpix reads.
    #[error("{what} nested deeper than {limit} levels")]
    NestedTooDeep {
        /// `statements` or `vectors`.
        what: &'static str,
        /// The deepest nesting read.
        limit: usize,
    },
    /// A `}` with no `{` open.
    #[error("unexpected '}}' (no '{{' is open)")]
    UnexpectedCloseBrace,
    /// The file ends inside a statement.
    #[error("unexpected end of file")]
    UnexpectedEof,
    /// The root modifier `!`, which csgpix does not read.
    #[error("the root modifier '!' is not supported")]
    RootModifier,
    /// A node csgpix does not read.
    #[error("unsupported node `{}` (csgpix reads {})", OneLine(name), known.join(", "))]
    UnsupportedNode {
        /// The node's name.
        name: String,
        /// The nodes csgpix reads.
        known: Vec<&'static str>,
    },
    /// A named argument that is none of its node's parameters (`known`, maybe none).
    #[error("{}", NoParameter { node, name, known })]
    UnknownParameter {
        /// The node.
        node: &'static str,
        /// The argument's name.
        name: String,
        /// The node's parameters.
        known: Vec<&'static str>,
    },
    /// More positional arguments than the node has positional parameters.
    #[error("too many positional arguments for `{node}`")]
    TooManyPositional {
        /// The node.
        node: &'static str,
    },
    /// A parameter given twice.
    #[error("argument `{name}` given twice")]
    ArgumentTwice {
        /// The parameter.
        name: &'static str,
    },

    // --- Values ----------------------------------------------------------------------------
    /// A value that breaks its rule: `what must rule`.
    #[error("{what} must {rule}")]
    Must {
        /// The value, as the message names it (`` `size` ``, `a point`).
        what: String,
        /// What it must be.
        rule: Rule,
    },
    /// A polygon path's point index that is not one of its points.
    #[error("point index {index} is not one of the {count} points")]
    PointIndex {
        /// The index, as given.
        index: f64,
        /// The points there are.
        count: usize,
    },
    /// A colour given by name or hex code, not as a vector.
    #[error(
        "colour \"{}\" is not supported: give it as color([r, g, b, a]), as OpenSCAD's CSG \
         export writes it",
        OneLine(name)
    )]
    NamedColour {
        /// The colour, as written.
        name: String,
    },
    /// A `multmatrix` whose last row is not `[0, 0, 0, w]`.
    #[error("projective matrices are not supported: the last row of `m` must be [0, 0, 0, w]")]
    ProjectiveMatrix,
    /// A `rotate_extrude` of angle 0.
    #[error("`rotate_extrude` needs a nonzero `angle`")]
    ZeroAngle,

    // --- Dimensions ------------------------------------------------------------------------
    /// A 2D shape at the top level: `alone` when the scene has nothing else, else its first
    /// object is one.
    #[error(
        "{}",
        if *alone {
            "a 2D shape outside linear_extrude or rotate_extrude: csgpix voxelizes solids"
        } else {
            "the top level is 2D (its first object is a 2D shape): OpenSCAD renders a 2D \
             drawing, csgpix voxelizes solids"
        }
    )]
    FlatTopLevel {
        /// Whether the scene holds no solid.
        alone: bool,
    },
    /// An operation given children of the other dimension (`flat`: it takes 2D children).
    #[error(
        "`{node}` takes {} children, found {}",
        if *flat { "2D" } else { "3D" },
        if *flat { "a solid" } else { "a 2D shape" }
    )]
    ChildDimension {
        /// The operation.
        node: &'static str,
        /// Whether it takes 2D children.
        flat: bool,
    },

    // --- Limits ----------------------------------------------------------------------------
    /// A circle or revolution of more fragments than csgpix accepts (`resolution`: counted
    /// from `$fn`, `$fa`, `$fs`).
    #[error(
        "{fragments} fragments{} is more than the {limit} csgpix accepts",
        if *resolution { " (from $fn, $fa, $fs)" } else { "" }
    )]
    TooManyFragments {
        /// The fragments asked for.
        fragments: f64,
        /// The most accepted.
        limit: usize,
        /// Whether the message names `$fn`, `$fa`, `$fs`.
        resolution: bool,
    },
    /// A placed coordinate past csgpix's largest: `value` when the message shows it.
    #[error(
        "{} exceeds {limit:e} in size",
        match value { Some(v) => format!("coordinate {v}"), None => "a coordinate".to_string() }
    )]
    CoordinateTooLarge {
        /// The coordinate.
        value: Option<f64>,
        /// The largest accepted.
        limit: f64,
    },
    /// A size, point or coordinate past the coordinate limit (`resized`: after a `resize`).
    #[error(
        "{what} exceeds the coordinate limit{}",
        if *resized { " after resize" } else { "" }
    )]
    CoordinateLimit {
        /// What exceeds it (`` `size` ``, `a point`, `a coordinate`).
        what: &'static str,
        /// Whether it is a `resize` that takes it past.
        resized: bool,
    },
    /// A placed solid thinner than csgpix's smallest extent along an axis.
    #[error(
        "degenerate extent: the solid is {side:e} across in {axis}, under {min:e} (csgpix's \
         smallest, as {max:e} is its largest coordinate)"
    )]
    ThinSolid {
        /// The solid's side along `axis`.
        side: f64,
        /// `x`, `y` or `z`.
        axis: &'static str,
        /// The smallest side accepted.
        min: f64,
        /// The largest coordinate accepted.
        max: f64,
    },
    /// More vertices than the scene has left of its limit.
    #[error(
        "the scene would pass its vertex limit: {vertices} more vertices, {left} left (the \
         limit follows the memory limit, e.g. --max-memory)"
    )]
    VertexLimit {
        /// The vertices asked for.
        vertices: usize,
        /// The vertices left.
        left: usize,
    },

    // --- Imports ---------------------------------------------------------------------------
    /// An `import()` of a file whose extension names no format csgpix imports.
    #[error(
        "`import(\"{}\")`: csgpix imports .stl, .obj, .off, .amf and .3mf meshes, .nrrd \
         datasets and .svg and .dxf drawings",
        OneLine(file)
    )]
    UnknownImportFormat {
        /// The file, as given.
        file: String,
    },
    /// An `import()` of a dataset without `threshold`.
    #[error(
        "`import(\"{}\")` is a dataset: give its iso value, `threshold = t`",
        OneLine(file)
    )]
    NeedsThreshold {
        /// The file, as given.
        file: String,
    },
    /// An `import()` argument refused for the file's kind.
    #[error("{0}")]
    ImportArgument(ImportArgument),
}

/// What a value must be or do, after `what must` ([`CsgError::Must`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Rule {
    /// `be a number`.
    Number,
    /// `be a vector`.
    Vector,
    /// `be a number or [x, y]`.
    NumberOrXy,
    /// `be [x, y]`.
    Xy,
    /// `be [x, y, z]`.
    Xyz,
    /// `be [r, g, b] or [r, g, b, a]`.
    Rgba,
    /// `be a string`.
    Text,
    /// `be a string (a DXF layer's name)`.
    LayerName,
    /// `be true or false`.
    Boolean,
    /// `be a finite number`.
    FiniteNumber,
    /// `be finite`.
    Finite,
    /// `not be negative`.
    NotNegative,
    /// `be below` the limit.
    Below(usize),
    /// `be positive, found` the value.
    Positive(f64),
    /// `have 4 rows of 4 numbers`.
    MatrixRows,
    /// `have 4 numbers`.
    MatrixRow,
}

impl fmt::Display for Rule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            Rule::Number => "be a number",
            Rule::Vector => "be a vector",
            Rule::NumberOrXy => "be a number or [x, y]",
            Rule::Xy => "be [x, y]",
            Rule::Xyz => "be [x, y, z]",
            Rule::Rgba => "be [r, g, b] or [r, g, b, a]",
            Rule::Text => "be a string",
            Rule::LayerName => "be a string (a DXF layer's name)",
            Rule::Boolean => "be true or false",
            Rule::FiniteNumber => "be a finite number",
            Rule::Finite => "be finite",
            Rule::NotNegative => "not be negative",
            Rule::Below(limit) => return write!(f, "be below {limit}"),
            Rule::Positive(found) => return write!(f, "be positive, found {found}"),
            Rule::MatrixRows => "have 4 rows of 4 numbers",
            Rule::MatrixRow => "have 4 numbers",
        };
        f.write_str(text)
    }
}

/// An `import()` argument refused for the kind of file imported.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ImportArgument {
    /// `threshold` of a mesh.
    Threshold,
    /// `scale` other than 1 of a mesh or dataset.
    Scale,
    /// `id` of an SVG file.
    SvgId,
    /// A `layer` of an SVG file.
    SvgLayer,
}

impl fmt::Display for ImportArgument {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ImportArgument::Threshold => "`threshold` applies to datasets (.nrrd) only",
            ImportArgument::Scale => "`scale` is not supported for 3D imports (use multmatrix)",
            ImportArgument::SvgId => {
                "`id` (one element of an SVG file) is not supported: OpenSCAD 2021.01 imports \
                 the whole file"
            }
            ImportArgument::SvgLayer => "`layer` applies to DXF files, not SVG",
        })
    }
}

/// "`node` takes no arguments, found `name`" or "`node` has no parameter `name` (it takes
/// …)".
struct NoParameter<'a> {
    node: &'a str,
    name: &'a str,
    known: &'a [&'static str],
}

impl fmt::Display for NoParameter<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (node, name) = (self.node, OneLine(self.name));
        if self.known.is_empty() {
            write!(f, "`{node}` takes no arguments, found `{name}`")
        } else {
            let list = self.known.join(", ");
            write!(f, "`{node}` has no parameter `{name}` (it takes {list})")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Cases no `.csg` text reaches (the `offset` guard; a name with a control character,
    /// which no identifier holds): the reader's former wording, one line.
    #[test]
    fn guards_keep_their_messages() {
        let offset = CsgError::ChildDimension {
            node: "offset",
            flat: true,
        };
        assert_eq!(
            offset.to_string(),
            "`offset` takes 2D children, found a solid"
        );
        let unknown = CsgError::UnknownParameter {
            node: "cube",
            name: "a\nb".into(),
            known: vec!["size", "center"],
        };
        assert_eq!(
            unknown.to_string(),
            "`cube` has no parameter `a\\nb` (it takes size, center)"
        );
    }
}
