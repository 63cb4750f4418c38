//! The reader's refusals word for word, `FILE:LINE:COL: message`: the texts are those the
//! reader printed before its problems were typed ([`csgpix_scene::CsgError`]), so a change
//! of wording fails here.

use crate::consts_::{MAX_COORDINATE, MAX_FRAGMENTS, MAX_NESTING, MAX_VECTOR_NESTING, MIN_EXTENT};
use crate::{parse_csg, parse_csg_with, Fallback, ReadOptions};
use csgpix_scene::{CsgError, Error};

/// The message of `text` refused as `m.csg`.
fn refusal(text: &str) -> String {
    refusal_with(text, &ReadOptions::default())
}

fn refusal_with(text: &str, options: &ReadOptions) -> String {
    match parse_csg_with(text, "m.csg", options) {
        Ok(_) => panic!("{text:?} should be refused"),
        Err(e) => e.to_string(),
    }
}

/// Each `(text, message)`: `text` is refused with exactly `message`.
fn assert_refusals(cases: &[(&str, &str)]) {
    for (text, message) in cases {
        assert_eq!(refusal(text), *message, "{text:?}");
    }
}

#[test]
fn tokens() {
    assert_refusals(&[
        ("cube(1);\n  @", "m.csg:2:3: unexpected character '@'"),
        ("cube(1);\u{1}", "m.csg:1:9: unexpected character '\\u{1}'"),
        (
            "cube(1); /* x",
            "m.csg:1:10: unterminated comment (missing `*/`)",
        ),
        (
            "import(\"a.stl",
            "m.csg:1:8: unterminated string (missing `\"`)",
        ),
        ("cube(1e999);", "m.csg:1:6: number `1e999` is out of range"),
        ("cube(1x);", "m.csg:1:6: malformed number `1x`"),
    ]);
}

#[test]
fn statements_and_arguments() {
    assert_refusals(&[
        (
            "cube(size = foo);",
            "m.csg:1:13: expected a value, found `foo` (csgpix reads numbers, true, false, \
             undef, strings and vectors, not expressions)",
        ),
        ("cube(1);\n}", "m.csg:2:1: unexpected '}' (no '{' is open)"),
        (
            "!cube(1);",
            "m.csg:1:1: the root modifier '!' is not supported",
        ),
        (
            "sphere2(1);",
            "m.csg:1:1: unsupported node `sphere2` (csgpix reads group, union, difference, \
             intersection, multmatrix, color, render, cube, sphere, cylinder, polyhedron, \
             import, square, circle, polygon, linear_extrude, rotate_extrude, hull, minkowski, \
             offset, projection, resize, text, surface)",
        ),
        (
            "cube(sise = 1);",
            "m.csg:1:6: `cube` has no parameter `sise` (it takes size, center)",
        ),
        (
            "group(a = 1);",
            "m.csg:1:7: `group` takes no arguments, found `a`",
        ),
        (
            "cube(1, true, 3);",
            "m.csg:1:15: too many positional arguments for `cube`",
        ),
        (
            "cube(1, size = 2);",
            "m.csg:1:9: argument `size` given twice",
        ),
    ]);
}

#[test]
fn nesting_past_the_limits() {
    let vectors = format!("cube({}", "[".repeat(MAX_VECTOR_NESTING + 1));
    assert_eq!(
        refusal(&vectors),
        format!(
            "m.csg:1:{}: vectors nested deeper than {MAX_VECTOR_NESTING} levels",
            6 + MAX_VECTOR_NESTING
        )
    );
    let statements = "group() {\n".repeat(MAX_NESTING) + "cube(1);";
    assert_eq!(
        refusal(&statements),
        format!(
            "m.csg:{}:1: statements nested deeper than {MAX_NESTING} levels",
            MAX_NESTING + 1
        )
    );
}

#[test]
fn a_fallback_statement_cut_short() {
    let options = ReadOptions {
        fallback: Fallback::Openscad,
        ..ReadOptions::default()
    };
    assert_eq!(
        refusal_with("foo(1", &options),
        "m.csg:1:6: unexpected end of file"
    );
}

#[test]
fn values_that_break_their_rule() {
    assert_refusals(&[
        (
            "cube(size = [1, 2]);",
            "m.csg:1:13: `size` must be [x, y, z]",
        ),
        ("sphere(r = \"a\");", "m.csg:1:12: `r` must be a number"),
        (
            "multmatrix(m = 1) cube(1);",
            "m.csg:1:16: `m` must be a vector",
        ),
        (
            "square(size = [1, 2, 3]);",
            "m.csg:1:15: `size` must be a number or [x, y]",
        ),
        (
            "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0]]) cube(1);",
            "m.csg:1:12: `m` must have 4 rows of 4 numbers",
        ),
        (
            "multmatrix([[1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]) cube(1);",
            "m.csg:1:13: a row of `m` must have 4 numbers",
        ),
        (
            "color([1, 0]) cube(1);",
            "m.csg:1:7: `c` must be [r, g, b] or [r, g, b, a]",
        ),
        (
            "cube(1, center = 1);",
            "m.csg:1:18: `center` must be true or false",
        ),
        (
            "linear_extrude(height = inf) square(1);",
            "m.csg:1:25: `height` must be a finite number",
        ),
        (
            "sphere(1, $fn = -1);",
            "m.csg:1:17: `$fn` must not be negative",
        ),
        (
            "linear_extrude(1, scale = -1) square(1);",
            "m.csg:1:27: `scale` must not be negative",
        ),
        (
            "text(\"a\", size = -1);",
            "m.csg:1:18: `size` must be positive, found -1",
        ),
        ("import(file = 1);", "m.csg:1:15: `file` must be a string"),
        (
            "import(\"a.dxf\", layer = 1);",
            "m.csg:1:25: `layer` must be a string (a DXF layer's name)",
        ),
        (
            "import(\"a.dxf\", origin = [inf, 0]);",
            "m.csg:1:26: `origin` must be finite",
        ),
        (
            "import(\"v.nrrd\", threshold = inf);",
            "m.csg:1:30: `threshold` must be a finite number",
        ),
        (
            "polygon([[0, 0, 0, 0]]);",
            "m.csg:1:10: a point must be [x, y]",
        ),
        (
            "polygon([[0, 0], [1, 0], [0, 1]], [[0, 1, 5]]);",
            "m.csg:1:43: point index 5 is not one of the 3 points",
        ),
    ]);
    assert_eq!(
        refusal("linear_extrude(1, slices = 20000) square(1);"),
        format!("m.csg:1:28: `slices` must be below {MAX_FRAGMENTS}")
    );
}

#[test]
fn colours_matrices_and_angles() {
    assert_refusals(&[
        (
            "color(\"red\") cube(1);",
            "m.csg:1:7: colour \"red\" is not supported: give it as color([r, g, b, a]), as \
             OpenSCAD's CSG export writes it",
        ),
        (
            "color(\"a\\nb\") cube(1);",
            "m.csg:1:7: colour \"a\\nb\" is not supported: give it as color([r, g, b, a]), as \
             OpenSCAD's CSG export writes it",
        ),
        (
            "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, 1]]) cube(1);",
            "m.csg:1:12: projective matrices are not supported: the last row of `m` must be \
             [0, 0, 0, w]",
        ),
        (
            "rotate_extrude(angle = 0) square(1);",
            "m.csg:1:1: `rotate_extrude` needs a nonzero `angle`",
        ),
    ]);
}

#[test]
fn shapes_of_the_wrong_dimension() {
    assert_refusals(&[
        (
            "square(1);",
            "m.csg:1:1: a 2D shape outside linear_extrude or rotate_extrude: csgpix voxelizes \
             solids",
        ),
        (
            "square(1);\ncube(1);",
            "m.csg:1:1: the top level is 2D (its first object is a 2D shape): OpenSCAD renders \
             a 2D drawing, csgpix voxelizes solids",
        ),
        (
            "projection() square(1);",
            "m.csg:1:1: `projection` takes 3D children, found a 2D shape",
        ),
    ]);
}

#[test]
fn limits() {
    let solid = "[[0, 0, 0], [X, 0, 0], [0, 1, 0], [0, 0, 1]], \
                 [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]";
    let tetrahedron = |x: &str| format!("polyhedron({});", solid.replace('X', x));
    assert_eq!(
        refusal("sphere(1, $fn = 20000);"),
        format!(
            "m.csg:1:1: 20000 fragments (from $fn, $fa, $fs) is more than the {MAX_FRAGMENTS} \
             csgpix accepts"
        )
    );
    let revolved = "rotate_extrude($fn = 20000) \
                    multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(1);";
    assert_eq!(
        refusal(revolved),
        format!("m.csg:1:1: 20000 fragments is more than the {MAX_FRAGMENTS} csgpix accepts")
    );
    assert_eq!(
        refusal("cube(2e12);"),
        format!("m.csg:1:1: a coordinate exceeds {MAX_COORDINATE:e} in size")
    );
    assert_eq!(
        refusal(&tetrahedron("2e12")),
        format!("m.csg:1:1: coordinate 2000000000000 exceeds {MAX_COORDINATE:e} in size")
    );
    assert_refusals(&[
        (
            "square([2e12, 1]);",
            "m.csg:1:8: `size` exceeds the coordinate limit",
        ),
        (
            "polygon([[0, 0], [2e12, 0], [0, 1]]);",
            "m.csg:1:18: a point exceeds the coordinate limit",
        ),
        (
            "resize([1e12, 0, 0]) \
             multmatrix([[1, 0, 0, 1e6], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(1);",
            "m.csg:1:1: a coordinate exceeds the coordinate limit after resize",
        ),
    ]);
    assert_eq!(
        refusal("cube(1e-307);"),
        format!(
            "m.csg:1:1: degenerate extent: the solid is {:e} across in x, under {MIN_EXTENT:e} \
             (csgpix's smallest, as {MAX_COORDINATE:e} is its largest coordinate)",
            1e-307
        )
    );
    let options = ReadOptions {
        max_vertices: Some(3),
        ..ReadOptions::default()
    };
    assert_eq!(
        refusal_with(&tetrahedron("1"), &options),
        "m.csg:1:1: the scene would pass its vertex limit: 4 more vertices, 3 left (the limit \
         follows the memory limit, e.g. --max-memory)"
    );
}

#[test]
fn imports() {
    assert_refusals(&[
        (
            "import(\"m.stl/\");",
            "m.csg:1:8: `import(\"m.stl/\")`: csgpix imports .stl, .obj, .off, .amf and .3mf \
             meshes, .nrrd datasets and .svg and .dxf drawings",
        ),
        (
            "import(\"v.nrrd\");",
            "m.csg:1:1: `import(\"v.nrrd\")` is a dataset: give its iso value, `threshold = t`",
        ),
        (
            "import(\"v\\n.nrrd\");",
            "m.csg:1:1: `import(\"v\\n.nrrd\")` is a dataset: give its iso value, `threshold = t`",
        ),
        (
            "import(\"m.stl\", threshold = 1);",
            "m.csg:1:29: `threshold` applies to datasets (.nrrd) only",
        ),
        (
            "import(\"m.stl\", scale = 2);",
            "m.csg:1:25: `scale` is not supported for 3D imports (use multmatrix)",
        ),
        (
            "import(\"a.svg\", id = \"x\");",
            "m.csg:1:22: `id` (one element of an SVG file) is not supported: OpenSCAD 2021.01 \
             imports the whole file",
        ),
        (
            "import(\"a.svg\", layer = \"x\");",
            "m.csg:1:25: `layer` applies to DXF files, not SVG",
        ),
    ]);
}

/// The syntax errors that read `expected …, found …` ([`Error::Expected`]).
#[test]
fn expected_and_found() {
    assert_refusals(&[
        (
            "cube(1)",
            "m.csg:1:8: expected ';' after `cube(…)` (it takes no children), found end of file",
        ),
        (
            "cube 1;",
            "m.csg:1:6: expected '(' after `cube`, found a number",
        ),
        (
            "cube(1 2);",
            "m.csg:1:8: expected ',' or ')' in the arguments of `cube`, found a number",
        ),
        (
            "cube([1 2]);",
            "m.csg:1:9: expected ',' or ']' in a vector, found a number",
        ),
        (
            "cube(-x);",
            "m.csg:1:7: expected a number after '-', found `x`",
        ),
        ("cube(=);", "m.csg:1:6: expected a value, found '='"),
        (
            "group() {",
            "m.csg:1:10: expected '}' to close `group` opened at 1:9, found end of file",
        ),
        (
            "group()",
            "m.csg:1:8: expected a child statement or ';' after `group(…)`, found end of file",
        ),
        (
            "group() }",
            "m.csg:1:9: expected a child statement or ';' after `group(…)`, found '}'",
        ),
        (
            "1;",
            "m.csg:1:1: expected a statement such as `group() {`, found a number",
        ),
    ]);
}

/// The problem is a field: a caller tells the cases apart without reading the text.
#[test]
fn the_problem_is_typed() {
    let e = parse_csg("!cube(1);", "m.csg").unwrap_err();
    assert_eq!(e.problem(), &Error::Csg(CsgError::RootModifier));
    let e = parse_csg("cube(1)", "m.csg").unwrap_err();
    assert!(matches!(e.problem(), Error::Expected { .. }), "{e:?}");
}
