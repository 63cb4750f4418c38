//! Unit tests of the reader.

use crate::*;
use crate::{consts_::*, linalg::*, primitives::*};
use csgpix_scene::solid::{ConvexSolid, CsgNode, CsgScene};
use proptest::prelude::*;

mod messages;

const EXAMPLE: &str = include_str!("../../../vectors/scenes/cube-minus-cylinder.csg");

/// Every node kind, for the mutation fuzzing.
const ALL_NODES: &str = "group() {\n\
    \tunion() { cube(size = [1, 2, 3], center = false); sphere($fn = 6, r = 2); }\n\
    \tintersection() {\n\
    \t\tmultmatrix([[-1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]]) {\n\
    \t\t\tcolor(c = [0, 0.5, 1], alpha = 0.5) cylinder(h = 2, r1 = 1, r2 = 0, $fn = 5);\n\
    \t\t}\n\
    \t\trender(convexity = 2) %cube(2);\n\
    \t\tpolyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], \
    faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], convexity = 1);\n\
    \t}\n\
    \tdifference() { cube(1); /* c */ cylinder(h = 1, d = 1, center = true); } // end\n\
    }\n";

fn parse(text: &str) -> CsgScene {
    parse_csg(text, "test.csg").unwrap_or_else(|e| panic!("{e}"))
}

/// Checks the error's position and that its message contains `part`.
fn assert_err(text: &str, line: usize, col: usize, part: &str) {
    let e = parse_csg(text, "test.csg").expect_err("should be refused");
    let at = e.location().expect("a located error");
    assert_eq!((at.line, at.col), (line, col), "{e}");
    assert!(e.problem().to_string().contains(part), "{e}");
}

fn only_solid(text: &str) -> ConvexSolid {
    let scene = parse(text);
    assert_eq!(scene.root, CsgNode::Solid(0));
    assert_eq!(scene.solids.len(), 1);
    scene.solids.into_iter().next().unwrap()
}

/// Closed, convex, and every face normal points away from the centroid.
fn assert_outward(solid: &ConvexSolid) {
    let n = solid.vertices.len() as f64;
    let centre = solid
        .vertices
        .iter()
        .fold([0.0; 3], |c, v| [c[0] + v[0], c[1] + v[1], c[2] + v[2]])
        .map(|c| c / n);
    let faces = solid.faces.to_vecs();
    for face in &faces {
        let normal = newell(&solid.vertices, face);
        let out = sub(centroid(&solid.vertices, face), centre);
        assert!(dot(normal, out) > 0.0, "face {face:?} points inward");
    }
    check_convex_closed(&solid.vertices, &faces).unwrap();
}

fn bounds(solid: &ConvexSolid) -> [[f64; 2]; 3] {
    let mut b = [[f64::INFINITY, f64::NEG_INFINITY]; 3];
    for v in &solid.vertices {
        for axis in 0..3 {
            b[axis] = [b[axis][0].min(v[axis]), b[axis][1].max(v[axis])];
        }
    }
    b
}

fn close(a: Vec3, b: Vec3) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
}

// --- primitives ---

#[test]
fn cube_uncentred() {
    let cube = only_solid("cube(size = [1, 2, 3], center = false);");
    assert_eq!((cube.vertices.len(), cube.faces.len()), (8, 6));
    assert!(cube.faces.iter().all(|f| f.len() == 4));
    assert_eq!(bounds(&cube), [[0.0, 1.0], [0.0, 2.0], [0.0, 3.0]]);
    assert_eq!(cube.vertices[6], [0.0, 2.0, 3.0]);
    assert_outward(&cube);
    let scalar = only_solid("cube(2);");
    assert_eq!(bounds(&scalar), [[0.0, 2.0]; 3]);
}

#[test]
fn cube_centred() {
    let cube = only_solid("cube(size = [20, 20, 20], center = true);");
    assert_eq!((cube.vertices.len(), cube.faces.len()), (8, 6));
    assert_eq!(bounds(&cube), [[-10.0, 10.0]; 3]);
    assert_outward(&cube);
    assert_eq!(only_solid("cube();").vertices[7], [1.0; 3]);
}

#[test]
fn sphere_fn_8() {
    let sphere = only_solid("sphere($fn = 8, $fa = 12, $fs = 2, r = 10);");
    // 8 fragments, (8 + 1) / 2 = 4 rings at 22.5°, 67.5°, 112.5°, 157.5°.
    assert_eq!(sphere.vertices.len(), 8 * 4);
    assert_eq!(sphere.faces.len(), 2 + 3 * 8);
    let (radius, z) = (
        10.0 * 22.5_f64.to_radians().sin(),
        10.0 * 22.5_f64.to_radians().cos(),
    );
    assert!(close(sphere.vertices[0], [radius, 0.0, z]));
    // 90° is exact in OpenSCAD's degree trigonometry: x is 0, not 6e-17.
    assert_eq!(sphere.vertices[2][0], 0.0);
    assert!(close(sphere.vertices[2], [0.0, radius, z]));
    assert!(close(sphere.vertices[4], [-radius, 0.0, z]));
    assert!(close(
        sphere.vertices[31],
        [radius * 0.5_f64.sqrt(), -radius * 0.5_f64.sqrt(), -z]
    ));
    assert_eq!(sphere.faces.get(0), (0..8).collect::<Vec<u32>>());
    assert_outward(&sphere);
}

#[test]
fn sphere_fa_fs() {
    let sphere = only_solid("sphere($fn = 0, $fa = 12, $fs = 2, r = 10);");
    // ceil(max(min(360 / 12, 10 * 2π / 2), 5)) = 30 fragments, 15 rings.
    assert_eq!(sphere.vertices.len(), 30 * 15);
    assert_eq!(sphere.faces.len(), 2 + 14 * 30);
    // Ring 7 is at exactly 90°: the equator, exact in OpenSCAD's degree trigonometry.
    assert_eq!(sphere.vertices[7 * 30], [10.0, 0.0, 0.0]);
    assert_eq!(sphere.vertices[7 * 30 + 5], [5.0, 10.0 * SQRT3_4, 0.0]);
    let phi = 180.0 * 0.5 / 15.0_f64;
    let top = [
        10.0 * phi.to_radians().sin(),
        0.0,
        10.0 * phi.to_radians().cos(),
    ];
    assert!(close(sphere.vertices[0], top));
    assert_outward(&sphere);
}

#[test]
fn fragment_rules() {
    let count = |text: &str| only_solid(text).vertices.len();
    // Small radius: at least 5 fragments (3 rings).
    assert_eq!(count("sphere(r = 1);"), 5 * 3);
    // $fn below 3 means 3; a fractional $fn is truncated; d is a diameter.
    assert_eq!(count("sphere(d = 4, $fn = 2);"), 3 * 2);
    assert_eq!(count("sphere(r = 1, $fn = 7.9);"), 7 * 4);
    // $fa and $fs are clamped up to 0.01: 360 / 0.01 = 36000 > 10 * 2π / 0.05.
    assert_eq!(count("cylinder(r = 10, $fa = 0, $fs = 0.05);"), 2 * 1257);
    // A cylinder's fragments come from its larger radius.
    assert_eq!(count("cylinder(h = 1, r1 = 1, r2 = 10);"), 2 * 30);
    assert_eq!(
        Resolution {
            fn_: 0.0,
            fa: 12.0,
            fs: 2.0
        }
        .fragments_from_r(1e-7),
        3.0
    );
}

#[test]
fn cylinder_fn_6_centred() {
    let cyl =
        only_solid("cylinder($fn = 6, $fa = 12, $fs = 2, h = 10, r1 = 3, r2 = 3, center = true);");
    assert_eq!((cyl.vertices.len(), cyl.faces.len()), (12, 8));
    assert_eq!(bounds(&cyl)[2], [-5.0, 5.0]);
    assert_eq!(cyl.vertices[1], [1.5, 3.0 * SQRT3_4, -5.0]);
    assert_eq!(cyl.vertices[10], [-1.5, -3.0 * SQRT3_4, 5.0]);
    assert_outward(&cyl);
}

#[test]
fn cones_have_one_apex() {
    let cone = only_solid("cylinder($fn = 6, h = 10, r1 = 3, r2 = 0, center = true);");
    assert_eq!((cone.vertices.len(), cone.faces.len()), (7, 7));
    assert_eq!(cone.vertices[6], [0.0, 0.0, 5.0]);
    assert_eq!(cone.faces.iter().filter(|f| f.len() == 3).count(), 6);
    assert_outward(&cone);
    let inverted = only_solid("cylinder($fn = 6, h = 10, r1 = 0, r2 = 3, center = true);");
    assert_eq!((inverted.vertices.len(), inverted.faces.len()), (7, 7));
    assert_eq!(inverted.vertices[0], [0.0, 0.0, -5.0]);
    assert_outward(&inverted);
    let frustum = only_solid("cylinder(h = 2, d1 = 4, r2 = 1, $fn = 5);");
    assert_eq!(bounds(&frustum)[0][1], 2.0);
    assert_outward(&frustum);
}

const TETRAHEDRON: &str = "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], \
                           faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], convexity = 1);";

#[test]
fn polyhedron_clockwise_tetrahedron() {
    let tet = only_solid(TETRAHEDRON);
    assert_eq!(tet.faces.get(0), [2, 1, 0]);
    assert_outward(&tet);
    let old = only_solid(&TETRAHEDRON.replace("faces", "triangles"));
    assert_eq!(old, tet);
}

#[test]
fn polyhedra_as_openscad_takes_them() {
    // Not convex: a closed mesh primitive of its faces, placed by the transform above it.
    let dented = "multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n  \
                  polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.2, 0.2, 0.2]], \
                  faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [4, 2, 1], [4, 3, 2], [4, 1, 3]]);";
    let s = parse(dented);
    assert_eq!((s.solids.len(), s.imports.len()), (0, 1));
    let mesh = s.imports[0].mesh.as_ref().expect("a mesh primitive");
    assert_eq!(mesh.len(), 6);
    assert!(mesh.iter().flatten().all(|v| v[0] >= 5.0 && v[0] <= 6.0));
    assert_eq!(s.imports[0].line, 2);
    // Faces wound the other way round all together: OpenSCAD renders it; so does csgpix.
    let ccw = TETRAHEDRON.replace(
        "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]",
        "[[2, 1, 0], [1, 3, 0], [3, 2, 0], [2, 3, 1]]",
    );
    assert_eq!(only_solid(&ccw), only_solid(TETRAHEDRON));
}

#[test]
fn polyhedron_refusals() {
    // Open: a mesh primitive (voxelized by its winding number) and a warning naming the
    // open edges, where OpenSCAD's render drops it.
    let open = "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], \
                faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3]]);";
    let s = parse(open);
    assert_eq!((s.solids.len(), s.imports.len()), (0, 1));
    assert_eq!(s.warnings.len(), 1);
    let w = s.warnings[0].to_string();
    assert!(
        w.starts_with(
            "test.csg:1:1: polyhedron is not closed: 3 edges belong to one triangle (first from"
        ),
        "{w}"
    );
}

#[test]
fn polyhedron_drops_unused_points() {
    let text = TETRAHEDRON.replace("[0, 0, 1]]", "[0, 0, 1], [9, 9, 9]]");
    assert_eq!(only_solid(&text).vertices.len(), 4);
}

// --- imports ---

#[test]
fn imports_follow_the_solids_in_leaf_numbers() {
    let scene = parse(
        "union() {\n  import(\"a.stl\");\n  cube(1);\n  \
         multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) \
         import(file = \"h.nrrd\", threshold = 300);\n}\n",
    );
    assert_eq!((scene.solids.len(), scene.imports.len()), (1, 2));
    assert_eq!(
        scene.root,
        CsgNode::Union(vec![
            CsgNode::Solid(1),
            CsgNode::Solid(0),
            CsgNode::Solid(2)
        ])
    );
    let (a, h) = (&scene.imports[0], &scene.imports[1]);
    assert_eq!(
        (a.file.as_str(), a.threshold, a.line, a.col),
        ("a.stl", None, 2, 3)
    );
    assert_eq!((h.file.as_str(), h.threshold), ("h.nrrd", Some(300.0)));
    assert_eq!(h.matrix.map(|m| m[0][3]), Some(5.0));
}

#[test]
fn import_refusals() {
    assert_err("import(\"h.nrrd\");", 1, 1, "threshold");
    assert_err("import(\"a.stl\", threshold = 3);", 1, 29, "datasets");
    assert_err("import(\"a.stl\", scale = 2);", 1, 25, "scale");
    assert_err("import(3);", 1, 8, "string");
    assert_err("import();", 1, 1, "file name");
}

// --- transforms and colours ---

#[test]
fn multmatrix_translation() {
    let cube = only_solid(
        "multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, -2], [0, 0, 0, 1]]) cube(1);",
    );
    assert_eq!(bounds(&cube), [[5.0, 6.0], [0.0, 1.0], [-2.0, -1.0]]);
    assert_outward(&cube);
}

#[test]
fn multmatrix_mirror_keeps_faces_outward() {
    let plain = only_solid("cylinder(h = 3, r1 = 2, r2 = 1, $fn = 7);");
    let mirrored = only_solid(
        "multmatrix(m = [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n\
         \tcylinder(h = 3, r1 = 2, r2 = 1, $fn = 7);\n}",
    );
    assert_eq!(mirrored.vertices[0], [-2.0, 0.0, 0.0]);
    let reversed: Vec<Vec<usize>> = (plain.faces.to_vecs().into_iter())
        .map(|f| f.into_iter().rev().collect())
        .collect();
    assert_eq!(mirrored.faces.to_vecs(), reversed);
    assert_outward(&mirrored);
}

#[test]
fn nested_multmatrix_composes() {
    let cube = only_solid(
        "multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n\
         multmatrix([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]]) cube(1);",
    );
    assert_eq!(bounds(&cube), [[1.0, 3.0], [0.0, 2.0], [0.0, 2.0]]);
    // m[3][3] = 2 divides the matrix, as OpenSCAD does.
    let halved =
        only_solid("multmatrix([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 2]]) cube(1);");
    assert_eq!(bounds(&halved), [[0.0, 1.0]; 3]);
}

#[test]
fn multmatrix_refusals() {
    assert_err(
        "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, 1]]) cube(1);",
        1,
        12,
        "projective",
    );
    assert_err(
        "multmatrix([[1, 0, 0], [0, 1, 0], [0, 0, 1]]) cube(1);",
        1,
        13,
        "4 numbers",
    );
}

#[test]
fn colours_innermost_wins() {
    let scene =
        parse("color([1, 0, 0, 1]) {\n\tcube(1);\n\tcolor([0, 0, 1, 0.5]) sphere(1);\n}\ncube(3);");
    assert_eq!(scene.solids[0].colour, Some([1.0, 0.0, 0.0, 1.0]));
    assert_eq!(scene.solids[1].colour, Some([0.0, 0.0, 1.0, 0.5]));
    assert_eq!(scene.solids[2].colour, None);
    assert_eq!(
        scene.solids.iter().map(|s| s.line).collect::<Vec<_>>(),
        [2, 3, 5]
    );
    let named_args = only_solid("color(c = [0, 1, 0], alpha = 0.25) cube(1);");
    assert_eq!(named_args.colour, Some([0.0, 1.0, 0.0, 0.25]));
    assert_err(
        "color(\"red\") cube(1);",
        1,
        7,
        "colour \"red\" is not supported",
    );
}

// --- tree shapes ---

#[test]
fn tree_shapes() {
    use CsgNode::{Difference, Empty, Intersection, Solid, Union};
    let root = |text: &str| parse(text).root;
    assert_eq!(
        root("difference() { cube(1); sphere(1); cylinder(h = 1, r = 1); }"),
        Difference(vec![Solid(0), Solid(1), Solid(2)])
    );
    assert_eq!(
        root("intersection() { cube(1); sphere(1); }"),
        Intersection(vec![Solid(0), Solid(1)])
    );
    assert_eq!(
        root("union() { cube(1); sphere(1); }"),
        Union(vec![Solid(0), Solid(1)])
    );
    assert_eq!(root("cube(1); sphere(1);"), Union(vec![Solid(0), Solid(1)]));
    assert_eq!(root("group() { cube(1); }"), Solid(0));
    assert_eq!(root("render(convexity = 2) { cube(1); }"), Solid(0));
    assert_eq!(
        root("group() { group() { cube(1); cube(2); } cube(3); }"),
        Union(vec![Solid(0), Solid(1), Solid(2)])
    );
    assert_eq!(
        root("group() { difference() { cube(1); sphere(1); } cube(3); }"),
        Union(vec![Difference(vec![Solid(0), Solid(1)]), Solid(2)])
    );
    for empty in [
        "",
        "// nothing\n/* at all */",
        "group();",
        "group() {}",
        "union() { group(); }",
        "difference() { group(); cube(1); }",
        "intersection() { cube(1); group(); }",
    ] {
        assert_eq!(root(empty), Empty, "{empty}");
    }
    assert_eq!(root("difference() { cube(1); group(); }"), Solid(0));
}

#[test]
fn modifiers() {
    use CsgNode::{Difference, Solid};
    let scene = parse("difference() { %cube(1); #sphere(1); *group() { cube(5); } cube(2); }");
    assert_eq!(scene.root, Difference(vec![Solid(0), Solid(1)]));
    assert_eq!(scene.solids.len(), 2);
    assert_eq!(scene.solids[1].vertices[7], [2.0; 3]);
    assert_err("!cube(1);", 1, 1, "root modifier");
}

#[test]
fn example_scene() {
    let scene = parse(EXAMPLE);
    assert_eq!(
        scene.root,
        CsgNode::Difference(vec![CsgNode::Solid(0), CsgNode::Solid(1)])
    );
    let [cube, cylinder] = &scene.solids[..] else {
        panic!("two solids")
    };
    assert_eq!((cube.vertices.len(), cube.colour, cube.line), (8, None, 2));
    assert_eq!(cylinder.vertices.len(), 48);
    assert_eq!(cylinder.colour, Some([1.0, 0.0, 0.0, 1.0]));
    assert_eq!(bounds(cylinder)[2], [-15.0, 15.0]);
    assert_outward(cube);
    assert_outward(cylinder);
}

// --- syntax and errors ---

#[test]
fn syntax_accepted() {
    let text = "/* header */ group() { // a comment\n\
                \tcube(size = [.5, 5., 1e-1], center = false) ;\n\
                \tsphere(r = +2.5E+0, $fn = 0, $fa = 12, $fs = 2,);\n\
                \tcylinder(h = 1, r1 = 1, r2 = undef, center = false);\n}\n";
    let scene = parse(text);
    assert_eq!(scene.solids.len(), 3);
    assert_eq!(
        bounds(&scene.solids[0]),
        [[0.0, 0.5], [0.0, 5.0], [0.0, 0.1]]
    );
    // r2 = undef falls back to the default radius of 1, like OpenSCAD.
    assert_eq!(bounds(&scene.solids[2])[0][1], 1.0);
}

#[test]
fn errors_name_line_and_column() {
    assert_err(
        // `roof`: a node of OpenSCAD releases after 2021.01.
        "group() {\n  roof(method = \"straight\");\n}",
        2,
        3,
        "unsupported node `roof` (csgpix reads group",
    );
    assert_err(
        "projection() cube(1);",
        1,
        1,
        "a 2D shape outside linear_extrude",
    );
    assert_err("cube(size = 1.2.3);", 1, 13, "malformed number `1.2.3`");
    assert_err("cube(size = 1e);", 1, 13, "malformed number `1e`");
    assert_err("cube(size = 1e999);", 1, 13, "out of range");
    assert_err("cube(size = 1;\n", 1, 14, "expected ',' or ')'");
    assert_err(
        "group() {\n\tcube(1);\n",
        3,
        1,
        "expected '}' to close `group` opened at 1:9",
    );
    assert_err(
        "group() {\n  cube(1)\n}",
        3,
        1,
        "expected ';' after `cube(…)`",
    );
    assert_err("cube(1) sphere(1);", 1, 9, "expected ';' after `cube(…)`");
    assert_err(
        "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])",
        1,
        69,
        "child statement or ';'",
    );
    assert_err("cube(1);\n}", 2, 1, "unexpected '}'");
    assert_err("cube(sise = 1);", 1, 6, "no parameter `sise`");
    assert_err("cube(1, true, 3);", 1, 15, "too many positional");
    assert_err("cube(size = 1, size = 2);", 1, 16, "given twice");
    assert_err("sphere($fn = -3, r = 1);", 1, 14, "must not be negative");
    assert_err("sphere($fn = 20000, r = 1);", 1, 1, "more than the 10000");
    assert_err("sphere($fn = 9000, r = 1);", 1, 1, "vertices");
    assert_err("cube(size = [1, 2]);", 1, 13, "[x, y, z]");
    assert_err("cube(center = 1);", 1, 15, "true or false");
    assert_err("cube(size = [1, 2 3]);", 1, 19, "expected ',' or ']'");
    assert_err("/* é */ foo();", 1, 9, "unsupported node `foo`");
    assert_err("cube(1); /* open", 1, 10, "unterminated comment");
    assert_err("color(\"red) cube(1);", 1, 7, "unterminated string");
    assert_err("cube(1) @", 1, 9, "unexpected character '@'");
    assert_err("x = 3;", 1, 1, "unsupported node `x`");
}

#[test]
fn display_format() {
    let e = parse_csg("cube(size = 1.2.3);", "dir/a.csg").unwrap_err();
    assert_eq!(e.to_string(), "dir/a.csg:1:13: malformed number `1.2.3`");
}

// --- robustness ---

#[test]
fn deep_nesting_is_refused_not_a_crash() {
    let text = "group() {\n".repeat(100_000) + "cube(1);" + &"}".repeat(100_000);
    assert_err(&text, MAX_NESTING + 1, 1, "nested deeper than 1000");
    let single = "group() ".repeat(100_000) + "cube(1);";
    assert_err(&single, 1, 8 * MAX_NESTING + 1, "nested deeper");
    let vectors = "cube(size = ".to_string() + &"[".repeat(100_000);
    assert_err(
        &vectors,
        1,
        13 + MAX_VECTOR_NESTING,
        "vectors nested deeper than 64",
    );
    // The same limit where numbers follow the `[` (read straight from the text): right
    // after it, and after a `,`.
    let numbers = "cube(size = ".to_string() + &"[".repeat(100) + "1";
    let deep = "vectors nested deeper than 64";
    assert_err(&numbers, 1, 13 + MAX_VECTOR_NESTING, deep);
    let after_commas = "cube(size = ".to_string() + &"[1, ".repeat(100);
    assert_err(&after_commas, 1, 13 + 4 * MAX_VECTOR_NESTING, deep);
}

#[test]
fn size_limits() {
    assert_err("cube(1e13);", 1, 1, "exceeds");
    let far = "multmatrix([[1, 0, 0, 1e12], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(1);";
    assert_err(far, 1, 73, "exceeds");
    assert_err(
        &TETRAHEDRON.replace("[0, 0, 1]]", "[0, 0, 1e13]]"),
        1,
        1,
        "exceeds",
    );
    // 2250 rings of 4500 points: two such spheres pass the scene's vertex guard.
    let one = "sphere($fn = 4500, r = 1);";
    const { assert!(2 * 2250 * 4500 > MAX_SCENE_VERTICES && 2250 * 4500 < MAX_SCENE_VERTICES) };
    assert_err(&one.repeat(2), 1, one.len() + 1, "vertices");
}

#[test]
fn degenerate_extents_are_refused_at_the_primitive() {
    // A cube 1e-307 across made voxels no f64 inverts: NaN plane coefficients.
    assert_err(
        "cube(1e-307);",
        1,
        1,
        "degenerate extent: the solid is 1e-307 across in x",
    );
    let thin = "\n  cube(size = [1, 1e-300, 1]);";
    assert_err(
        thin,
        2,
        3,
        "degenerate extent: the solid is 1e-300 across in y",
    );
    // Tiny coordinates of a solid of ordinary size are fine.
    let near = "multmatrix([[1, 0, 0, 1e-300], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(1);";
    assert_eq!(parse(near).solids.len(), 1);
    assert_eq!(parse("cube(1e-12);").solids.len(), 1);
}

/// An extrusion's convex prisms are made all at once, in parallel; the error is still the
/// first shape's, as when they were made one at a time.
#[test]
fn an_extrusions_first_failing_shape_is_the_one_reported() {
    let shapes = [
        "square(1);",
        "square([1e-300, 1]);",
        "multmatrix([[1, 0, 0, 1e300], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(1);",
        "square([1, 1e-307]);",
    ];
    for first in 1..3 {
        let body: String = shapes[..1]
            .iter()
            .chain(&shapes[first..])
            .cloned()
            .collect();
        let text = format!("linear_extrude(height = 1) union() {{ {body} }}");
        let want = ["", "1e-300 across in x", "coordinate"][first];
        assert_err(&text, 1, 1, want);
    }
    let many = "square(1); ".repeat(300);
    let text = format!("linear_extrude(height = 2) union() {{ {many} }}");
    assert_eq!(parse(&text).solids.len(), 300);
}

#[test]
fn all_nodes_seed_parses() {
    let scene = parse(ALL_NODES);
    assert_eq!(scene.solids.len(), 6); // the `%cube` is left out
    scene.solids.iter().for_each(assert_outward);
}

#[test]
fn deepest_accepted_nesting() {
    let groups = "group() {\n".repeat(MAX_NESTING - 1) + "cube(1);" + &"}".repeat(MAX_NESTING - 1);
    assert_eq!(parse(&groups).root, CsgNode::Solid(0));
    // A tree as deep as the limit allows, built and dropped on a test thread's stack.
    let deep = "difference() { cube(1);\n".repeat(MAX_NESTING - 1)
        + "cube(1);"
        + &"}".repeat(MAX_NESTING - 1);
    let scene = parse(&deep);
    assert_eq!(scene.solids.len(), MAX_NESTING);
    drop(scene);
}

/// Ok scenes are well formed; errors point inside the text.
fn check_outcome(text: &str) {
    match parse_csg(text, "fuzz.csg") {
        Ok(scene) => {
            let mut pending = vec![&scene.root];
            while let Some(node) = pending.pop() {
                match node {
                    CsgNode::Solid(i) => assert!(*i < scene.solids.len()),
                    CsgNode::Union(c) | CsgNode::Intersection(c) | CsgNode::Difference(c) => {
                        pending.extend(c)
                    }
                    CsgNode::Complement(c) => pending.push(c),
                    CsgNode::Empty => {}
                }
            }
            scene.solids.iter().for_each(assert_outward);
        }
        Err(e) => {
            let at = e.location().expect("a located error");
            assert!(at.line >= 1 && at.col >= 1, "{e}");
            assert!(at.line <= text.lines().count() + 1, "{e}");
        }
    }
}

proptest! {
    #[test]
    fn random_text_never_panics(text in "\\PC{0,300}") {
        check_outcome(&text);
    }

    #[test]
    fn csg_like_text_never_panics(text in "[a-z$ (){}\\[\\];,=0-9.e+\\-\"/*%#\n]{0,300}") {
        check_outcome(&text);
    }

    #[test]
    fn mutated_files_never_panic(
        seed in prop::sample::select(vec![EXAMPLE, ALL_NODES]),
        edits in prop::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0..3u8), 1..6)
    ) {
        let mut bytes = seed.as_bytes().to_vec();
        for (at, byte, how) in edits {
            let i = at.index(bytes.len() + 1);
            match how {
                0 if i < bytes.len() => bytes[i] = byte,
                1 if i < bytes.len() => { bytes.remove(i); }
                _ => bytes.insert(i, byte),
            }
        }
        check_outcome(&String::from_utf8_lossy(&bytes));
    }
}

/// OpenSCAD draws a primitive of zero or negative size as nothing and goes on; csgpix does
/// the same and warns at the node.
#[test]
fn empty_primitives_are_empty_with_a_warning() {
    for (text, col) in [
        ("sphere(r = -1);", 1),
        ("cylinder(h = 0, r = 1);", 1),
        ("cylinder(h = 1, r1 = 0, r2 = 0);", 1),
        ("cube([1, 0, 1]);", 1),
        ("linear_extrude(height = 1) square(size = [0, 1]);", 28),
        ("linear_extrude(height = 1) circle(r = 0);", 28),
    ] {
        let s = parse(text);
        assert_eq!(s.root, CsgNode::Empty, "{text}");
        assert!(s.solids.is_empty() && s.imports.is_empty(), "{text}");
        assert_eq!(s.warnings.len(), 1, "{text}");
        let w = s.warnings[0].to_string();
        assert!(w.starts_with(&format!("test.csg:1:{col}: `")), "{w}");
    }
    // An empty first operand empties a difference; an empty subtracted one is dropped.
    let s = parse("difference() { cylinder(h = 1, r1 = 0, r2 = 0); cube(1); }");
    assert_eq!(s.root, CsgNode::Empty);
    let s = parse("difference() { cube(2); cube(0); }");
    assert_eq!(s.root, CsgNode::Solid(0));
    // The rest of the scene goes on.
    let s = parse("group() { cube(0); sphere(1); }");
    assert_eq!((s.solids.len(), s.root.clone()), (1, CsgNode::Solid(0)));
}

/// OpenSCAD's `applyToChildren`: the first child that is not empty sets an operation's
/// dimension; children of the other dimension are ignored with its warning, and an empty
/// `group();` is neither.
#[test]
fn children_of_the_other_dimension_are_ignored() {
    let s = parse("group() { cube(1); square(2); }");
    assert_eq!((s.solids.len(), s.root.clone()), (1, CsgNode::Solid(0)));
    assert!(s.warnings[0]
        .to_string()
        .contains("Ignoring 2D child object for 3D operation"));
    let s = parse("linear_extrude(height = 1) { group(); square(2); cube(5); }");
    assert_eq!(s.solids.len(), 1, "the extruded square only");
    assert!(s.warnings[0]
        .to_string()
        .contains("Ignoring 3D child object for 2D operation"));
    let s = parse("linear_extrude(height = 1) union() { group(); square(2); }");
    assert_eq!((s.solids.len(), s.warnings.len()), (1, 0));
    // 2D first: the solid is ignored and leaves the scene.
    let s = parse("cube(1); linear_extrude(height = 1) group() { square(2); sphere(3); }");
    assert_eq!(s.solids.len(), 2, "the cube and the extruded square");
    assert_eq!(s.warnings.len(), 1);
    // A 2D shape at the top level after solids is ignored; first, it makes the top level 2D
    // (OpenSCAD's "Top level object is a 2D object"), which csgpix refuses, as alone.
    let s = parse("cube(1); square(2);");
    assert_eq!((s.solids.len(), s.warnings.len()), (1, 1));
    assert_err("square(2); cube(1);", 1, 1, "the top level is 2D");
    assert_err("square(2);", 1, 1, "outside linear_extrude");
}

/// The scenes below are each checked against OpenSCAD 2021.01's CGAL render of the same
/// `.scad` (the geometry it kept and the warnings it printed), and refused under `--strict`.
fn lenient(text: &str) -> CsgScene {
    lenient_with(text, ReadOptions::default())
}

/// [`lenient`], read with `options`.
fn lenient_with(text: &str, options: ReadOptions) -> CsgScene {
    let s = parse_csg_with(text, "test.csg", &options).unwrap_or_else(|e| panic!("{e}"));
    assert!(!s.warnings.is_empty(), "{text}: no warning");
    let strict = ReadOptions {
        strict: true,
        ..options
    };
    let e = parse_csg_with(text, "test.csg", &strict).unwrap_err();
    assert_eq!(e.to_string(), s.warnings[0].to_string(), "{text}");
    s
}

/// `applyToChildren`: a child of the other dimension is an empty geometry in its place, so an
/// intersection with one is empty and a difference keeps its first child.
#[test]
fn mixed_dimensions_follow_openscad() {
    let s = lenient("intersection() { cube(5); circle(2); }");
    assert_eq!(s.root, CsgNode::Empty);
    assert!(s.warnings[0]
        .to_string()
        .contains("Ignoring 2D child object for 3D operation"));
    let s = lenient("difference() { cube(5); circle(2); }");
    assert_eq!(s.root, CsgNode::Solid(0));
    let s = lenient("linear_extrude(height = 1) intersection() { circle(2); cube(5); }");
    assert_eq!(s.root, CsgNode::Empty);
    let s = lenient("group() { cube(1); square(3); sphere(1); }");
    assert_eq!(s.solids.len(), 2);
}

/// `ColorModule`: a component out of 0..1 is a warning; the geometry is unchanged and the
/// colour code takes the component clamped.
#[test]
fn colours_out_of_range_are_clamped_with_a_warning() {
    let s = lenient("color([2, -1, 0.5, 3]) cube(1);");
    assert_eq!(s.solids[0].colour, Some([1.0, 0.0, 0.5, 1.0]));
    assert_eq!(s.warnings.len(), 3);
    assert!(s.warnings[0]
        .to_string()
        .starts_with("test.csg:1:8: color() expects"));
    let s = lenient("color(c = [0, 0, 1], alpha = 7) cube(1);");
    assert_eq!(s.solids[0].colour, Some([0.0, 0.0, 1.0, 1.0]));
}

/// `PolyhedronNode::createGeometry`: points that are not coordinates make it empty; an index
/// out of range is left out of its face.
#[test]
fn malformed_polyhedra_are_empty_or_mended_with_a_warning() {
    let s = lenient("polyhedron(points = undef, faces = [[0, 1, 2]], convexity = 1); cube(1);");
    assert_eq!((s.solids.len(), s.imports.len()), (1, 0));
    let s =
        lenient("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, inf]], faces = [[0, 1, 2]]);");
    assert_eq!(s.root, CsgNode::Empty);
    // A tetrahedron whose last face names a fifth point: that corner is left out.
    let tetra = "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], \
                 faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2, 9]]);";
    let s = lenient(tetra);
    assert_eq!(s.solids.len(), 1);
    assert!(s.warnings[0]
        .to_string()
        .contains("Point index 9 is out of bounds"));
}

/// A transform that flattens its objects (a scale by 0) or holds an infinity removes them
/// (`CGAL_Nef_polyhedron::transform`, `Polygon2d::transform`,
/// `GeometryEvaluator::visit(TransformNode)`); the 2D part of a matrix decides for 2D shapes.
#[test]
fn singular_and_infinite_transforms_remove_their_objects() {
    let flat3 = "multmatrix([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])";
    let s = lenient(&format!("{flat3} cube(1); cube(2);"));
    assert_eq!(s.solids.len(), 1);
    assert!(s.warnings[0]
        .to_string()
        .contains("Scaling a 3D object with 0"));
    let s = lenient(&format!("intersection() {{ cube(2); {flat3} cube(1); }}"));
    assert_eq!(s.root, CsgNode::Empty);
    let s = lenient(&format!("linear_extrude(height = 1) {flat3} square(1);"));
    assert_eq!(s.root, CsgNode::Empty);
    // Flat in z only: a 2D shape keeps its area.
    let z0 = "multmatrix([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]])";
    let s = parse(&format!("linear_extrude(height = 1) {z0} square(1);"));
    assert_eq!((s.solids.len(), s.warnings.len()), (1, 0));
    let inf = "multmatrix([[1, 0, 0, inf], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])";
    let s = lenient(&format!("{inf} cube(1); cube(2);"));
    assert_eq!(s.solids.len(), 1);
    assert!(s.warnings[0]
        .to_string()
        .contains("Not-a-Number and/or Infinity"));
}

/// `inf` and `nan` as the CSG export writes them: a primitive of such a size is empty, as
/// OpenSCAD's range checks make it.
#[test]
fn infinite_sizes_make_empty_primitives() {
    for text in [
        "cube(size = [inf, 1, 1], center = false);",
        "sphere(r = nan);",
        "cylinder(h = 1, r1 = -inf, r2 = 1);",
        "linear_extrude(height = 1) circle(r = inf);",
    ] {
        let s = lenient(text);
        assert_eq!(s.root, CsgNode::Empty, "{text}");
    }
}

/// `ImportNode::createGeometry`: an import of a file that cannot be opened, of an empty
/// name or of an unknown format gives nothing, with a warning, and the scene goes on.
#[test]
fn unreadable_imports_are_empty_with_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let here = ReadOptions {
        dir: Some(dir.path().to_path_buf()),
        ..Default::default()
    };
    let lenient = |text: &str| lenient_with(text, here.clone());
    let s = lenient("import(file = \"missing.stl\"); cube(1);");
    assert_eq!((s.solids.len(), s.imports.len()), (1, 0));
    assert!(s.warnings[0].to_string().contains("Can't open import file"));
    let s = lenient("import(file = \"\", layer = \"\"); cube(1);");
    assert!(s.warnings[0]
        .to_string()
        .contains("Unsupported file format"));
    let s = lenient("intersection() { cube(2); import(file = \"missing.stl\"); }");
    assert_eq!(s.root, CsgNode::Empty);
    let s = lenient("linear_extrude(height = 1) import(file = \"missing.svg\"); cube(1);");
    assert_eq!(s.solids.len(), 1);
}

#[test]
fn minkowski_leaves_out_empty_children_as_openscad() {
    let with = "minkowski() { cube(size = 1); group(); sphere(r = 0.5, $fn = 8); }";
    let without = "minkowski() { cube(size = 1); sphere(r = 0.5, $fn = 8); }";
    let (a, b) = (
        parse_csg(with, "t").unwrap(),
        parse_csg(without, "t").unwrap(),
    );
    assert_eq!(a, b);
    assert_eq!(a.solids.len(), 1);
    // One child is itself; the hull of a difference is one convex solid.
    let one = parse_csg(
        "minkowski() { difference() { cube(size = 2); cube(size = 1); } }",
        "t",
    );
    assert!(matches!(one.unwrap().root, CsgNode::Difference(_)));
    let h = parse_csg(
        "hull() { difference() { cube(size = 2); cube(size = 1); } }",
        "t",
    )
    .unwrap();
    assert_eq!((h.solids.len(), h.imports.len()), (1, 0));
}

#[test]
fn a_minkowski_sum_past_the_vertex_budget_is_refused_where_it_stands() {
    let text = "group() {\n  minkowski() {\n    difference() { sphere(r = 2, $fn = 40); cube(size = 1); }\n    difference() { sphere(r = 1, $fn = 40); cube(size = 0.5); }\n  }\n}";
    let e = parse_csg(text, "t.csg").unwrap_err().to_string();
    assert!(
        e.starts_with(
            "t.csg:2:3: minkowski(): the Minkowski sum would pass the scene's vertex limit"
        ),
        "{e}"
    );
}

/// A solid's vertices as bits, and its faces.
type SolidBits = (Vec<[u64; 3]>, Vec<Vec<usize>>);

/// The solids of `scene` after its first `skip`, as bits: vertices and faces.
fn solid_bits(scene: &CsgScene, skip: usize) -> Vec<SolidBits> {
    scene.solids[skip..]
        .iter()
        .map(|s| {
            let v = s.vertices.iter().map(|p| p.map(f64::to_bits)).collect();
            (v, s.faces.to_vecs())
        })
        .collect()
}

const MINKOWSKI: &str = "minkowski() {\n  cube(size = [3, 1, 2]);\n  sphere(r = 0.5, $fn = 12);\n}";

/// A `minkowski()` met again (a module called twice: the same statement, indented by its
/// depth) takes the sum made the first time, placed by its own transform: its solids are
/// those the statement gives alone, bit for bit, under a move, a turn, a scale and a mirror.
#[test]
fn a_minkowski_met_again_is_the_sum_made_alone() {
    let deeper = MINKOWSKI.replace('\n', "\n\t\t");
    for m in [
        "[[1, 0, 0, 5], [0, 1, 0, -2], [0, 0, 1, 1], [0, 0, 0, 1]]",
        "[[0, -1, 0, 0], [1, 0, 0, 3], [0, 0, 1, 0], [0, 0, 0, 1]]",
        "[[2, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, 3, 0], [0, 0, 0, 1]]",
        "[[-1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
    ] {
        let alone = parse(&format!("multmatrix({m}) {{ {MINKOWSKI} }}"));
        let text = format!(
            "multmatrix([[1, 0, 0, 9], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {MINKOWSKI}\n\
             group() {{ multmatrix({m}) {{ {deeper} }} }}"
        );
        let again = parse(&text);
        let n = alone.solids.len();
        assert_eq!(again.solids.len(), 2 * n, "{m}");
        assert_eq!(solid_bits(&again, n), solid_bits(&alone, 0), "{m}");
        again.solids[n..].iter().for_each(assert_outward);
        // One sum held for both (the reading's bytes count what the sums held).
        assert!(alone.reading_bytes > 0);
        assert_eq!(again.reading_bytes, alone.reading_bytes, "{m}");
    }
}

/// A sum made in its own coordinates and placed is the sum of the placed operands: a box
/// ⊕ a box under a scale is the box of the scaled sizes.
#[test]
fn a_minkowski_under_a_scale_is_the_sum_of_the_scaled_operands() {
    let s = parse(
        "multmatrix([[2, 0, 0, 1], [0, 3, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]]) minkowski() { \
         cube(size = [1, 1, 1]); cube(size = [2, 1, 3]); }",
    );
    assert_eq!(s.solids.len(), 1);
    let v = &s.solids[0].vertices;
    let lo = v
        .iter()
        .fold([f64::INFINITY; 3], |a, p| [0, 1, 2].map(|k| a[k].min(p[k])));
    let hi = v.iter().fold([f64::NEG_INFINITY; 3], |a, p| {
        [0, 1, 2].map(|k| a[k].max(p[k]))
    });
    assert_eq!((lo, hi), ([1.0, 0.0, -4.0], [7.0, 6.0, 0.0]));
    assert_outward(&s.solids[0]);
}

/// The sum met again is refused where the budget left could not hold it, as it is when made.
#[test]
fn a_minkowski_met_again_past_the_budget_is_refused_as_when_made() {
    let other = MINKOWSKI.replace("minkowski() {", "minkowski(convexity = 2) {");
    let options = |max| ReadOptions {
        max_vertices: Some(max),
        ..ReadOptions::default()
    };
    let sum = parse(MINKOWSKI).solids[0].vertices.len();
    // The operands bring 8 + 72 vertices and the sum is counted at 8 × 72 before it is made:
    // room for the first sum, not for the second (its operands' 80 more leave 496).
    let room = 80 + 8 * 72 + sum;
    assert!(parse_csg_with(MINKOWSKI, "t.csg", &options(room)).is_ok());
    let whole = parse_csg_with(
        &format!("{MINKOWSKI}\n{MINKOWSKI}"),
        "t.csg",
        &options(1 << 20),
    );
    for second in [MINKOWSKI.to_string(), other] {
        let text = format!("{MINKOWSKI}\n{second}");
        let e = parse_csg_with(&text, "t.csg", &options(room))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("t.csg:5:1: minkowski(): the Minkowski sum would pass"),
            "{e}"
        );
    }
    assert_eq!(whole.unwrap().solids.len(), 2);
}

/// An `offset()` met again (a module called twice) takes the outline made the first time,
/// placed by its own transform: the prism over it is the one the statement gives alone.
#[test]
fn an_offset_met_again_is_the_outline_made_alone() {
    let offset = "offset(r = 0.5, $fn = 16) {\n  square(size = [2, 1]);\n}";
    let deeper = offset.replace('\n', "\n\t\t\t");
    let m = "[[0, -2, 0, 3], [1, 0, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]";
    let alone = parse(&format!(
        "linear_extrude(height = 1) {{ multmatrix({m}) {offset} }}"
    ));
    let again = parse(&format!(
        "linear_extrude(height = 1) {{ {offset} }}\n\
         linear_extrude(height = 1) {{ group() {{ multmatrix({m}) {{ {deeper} }} }} }}"
    ));
    let n = alone.solids.len();
    assert_eq!(again.solids.len(), 2 * n);
    assert_eq!(solid_bits(&again, n), solid_bits(&alone, 0));
    // One outline held for both.
    assert!(alone.reading_bytes > 0);
    assert_eq!(again.reading_bytes, alone.reading_bytes);
}

#[test]
fn statements_are_keyed_by_their_tokens_not_their_indentation() {
    use crate::reader::spaced_once;
    assert_eq!(spaced_once("a(x = 1) {\n\t\tb();\n}"), "a(x = 1) { b(); }");
    assert_eq!(spaced_once("a(x = 1)   {  b(); }"), "a(x = 1) { b(); }");
    // White space inside a string is the string's.
    assert_ne!(
        spaced_once("t(text = \"a  b\");"),
        spaced_once("t(text = \"a b\");")
    );
    assert_eq!(
        spaced_once("t(text = \"a \\\"  b\")  ;"),
        "t(text = \"a \\\"  b\") ;"
    );
}

/// OpenSCAD reports a `rotate_extrude` of a shape on both sides of the axis as an error but
/// draws the rest of the design: csgpix warns and goes on.
#[test]
fn rotate_extrude_across_the_axis_draws_nothing_and_goes_on() {
    let s = parse("cube(1);\nrotate_extrude() square(size = [2, 1], center = true);");
    assert_eq!((s.solids.len(), s.imports.len()), (1, 0));
    assert_eq!(s.root, CsgNode::Solid(0));
    let w = s.warnings[0].to_string();
    assert!(
        w.starts_with("test.csg:2:1: ") && w.contains("X coordinate sign"),
        "{w}"
    );
}

/// A face that names a point twice in a row has that corner once, as OpenSCAD reads it.
#[test]
fn a_point_repeated_in_a_face_is_one_corner() {
    let doubled = TETRAHEDRON.replace("[1, 3, 2]]", "[1, 1, 3, 2]]");
    assert_eq!(only_solid(&doubled), only_solid(TETRAHEDRON));
    // A face of two distinct corners is dropped (it encloses nothing).
    let extra = TETRAHEDRON.replace("[1, 3, 2]]", "[1, 3, 2], [1, 3, 3]]");
    assert_eq!(only_solid(&extra), only_solid(TETRAHEDRON));
}

/// A Minkowski sum under a transform is the transformed sum: the placed operands' translation
/// counts once (3D and 2D).
#[test]
fn a_minkowski_sum_under_a_translation_is_moved_once() {
    let bounds = |s: &CsgScene| {
        let pts: Vec<[f64; 3]> = s.solids.iter().flat_map(|x| x.vertices.clone()).collect();
        let lo = pts
            .iter()
            .fold([f64::MAX; 3], |a, p| [0, 1, 2].map(|i| a[i].min(p[i])));
        let hi = pts
            .iter()
            .fold([f64::MIN; 3], |a, p| [0, 1, 2].map(|i| a[i].max(p[i])));
        (lo, hi)
    };
    let s = parse(
        "multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, 7], [0, 0, 0, 1]]) minkowski() { \
         cube(size = [10, 10, 1]); cylinder(h = 1, r = 2, $fn = 4); cube(1); }",
    );
    assert_eq!(bounds(&s), ([3.0, 3.0, 7.0], [18.0, 18.0, 10.0]));
    let s = parse(
        "multmatrix([[1, 0, 0, 3], [0, 1, 0, 4], [0, 0, 1, 0], [0, 0, 0, 1]]) \
         linear_extrude(height = 1) multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, 0], \
         [0, 0, 0, 1]]) minkowski() { square([4, 4]); circle(r = 1, $fn = 4); }",
    );
    assert_eq!(bounds(&s), ([7.0, 8.0, 0.0], [13.0, 14.0, 1.0]));
}

/// A shape across the axis that the 2D booleans cut back to one side is revolved, as
/// OpenSCAD revolves the result of its 2D booleans.
#[test]
fn rotate_extrude_of_a_boolean_cut_to_one_side_is_revolved() {
    let s = parse(
        "rotate_extrude($fn = 16) intersection() { circle(r = 2, $fn = 16); \
         square(size = [1, 1]); }",
    );
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert_eq!(s.imports.len(), 1, "one revolved mesh");
}

#[test]
fn the_vertex_limit_follows_the_memory_limit() {
    let text = "sphere(r = 1, $fn = 100);";
    let options = |bytes| ReadOptions {
        max_vertices: Some(ReadOptions::max_vertices_for(bytes)),
        ..Default::default()
    };
    // 100 × 50 vertices: 320,000 bytes at 64 a vertex.
    assert!(parse_csg_with(text, "t.csg", &options(400_000)).is_ok());
    let e = parse_csg_with(text, "t.csg", &options(100_000)).unwrap_err();
    assert!(
        e.to_string().starts_with(
            "t.csg:1:1: the scene would pass its vertex limit: 5000 more vertices, 1562 left"
        ),
        "{e}"
    );
}

/// An imported mesh below `projection`, `hull`, `minkowski` or `resize` is read while the
/// scene is, from the scene's folder; a scene given as text has none and is refused as before.
#[test]
fn geometry_operations_read_their_imported_meshes() {
    let dir = tempfile::tempdir().unwrap();
    // A closed tetrahedron and an open one (its base left out).
    let tet = "OFF\n4 4 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
    std::fs::write(dir.path().join("t.off"), tet).unwrap();
    let open = "OFF\n4 3 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
    std::fs::write(dir.path().join("o.off"), open).unwrap();
    let here = ReadOptions {
        dir: Some(dir.path().to_path_buf()),
        ..Default::default()
    };
    let text = "linear_extrude(height = 1) projection() multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) import(\"t.off\");";
    let s = parse_csg_with(text, "t.csg", &here).unwrap();
    // The shadow is the triangle (1,0)-(3,0)-(1,2): extruded, one convex prism.
    assert_eq!((s.solids.len(), s.imports.len()), (1, 0));
    let xs: Vec<f64> = s.solids[0].vertices.iter().map(|v| v[0]).collect();
    assert_eq!(xs.iter().copied().fold(f64::INFINITY, f64::min), 1.0);
    assert_eq!(xs.iter().copied().fold(f64::NEG_INFINITY, f64::max), 3.0);
    let s = parse_csg_with("hull() { import(\"t.off\"); cube(1); }", "t.csg", &here).unwrap();
    assert_eq!((s.solids.len(), s.imports.len()), (1, 0));
    // Resized, the import stays a leaf, now with its (placed) triangles.
    let s = parse_csg_with("resize([4, 4, 4]) import(\"t.off\");", "t.csg", &here).unwrap();
    let mesh = s.imports[0].mesh.as_ref().expect("read while the scene is");
    let top = mesh.iter().flatten().map(|p| p[2]).fold(0.0, f64::max);
    assert_eq!((s.imports[0].matrix, top), (None, 4.0));
    // An open mesh is used as it is, with a warning at its import.
    let s = parse_csg_with("hull() import(\"o.off\");", "t.csg", &here).unwrap();
    assert!(s.warnings[0]
        .to_string()
        .starts_with("t.csg:1:8: `o.off`: mesh is not closed"));
    // Without a folder the file is not read.
    let e = parse_csg(text, "t.csg").unwrap_err().to_string();
    assert!(
        e.contains("csgpix loads imported files only to voxelize"),
        "{e}"
    );
}

/// boolmesh appended a result's halfedges in a `HashMap`'s order (its seed differs from map to
/// map) and broke its ear-clipping queue's ties by address: the union inside this design's
/// `minkowski()` came out triangulated one of two ways, and the sum's pieces (and the colour
/// codes they carry) with it (vendor/README.md). Seven more reads in one process: the same.
#[test]
fn a_minkowski_of_a_mesh_boolean_is_the_same_in_every_run() {
    let text = include_str!("../../../vectors/designs/meshes/corner-protector.csg");
    let first = parse(text);
    // 60 primitives: the mesh's 178 triangles as 55 convex patches, each summed, and more.
    assert!(first.imports.len() + first.solids.len() >= 60);
    for _ in 0..7 {
        let again = parse(text);
        assert_eq!(again.solids, first.solids);
        assert_eq!(again.imports, first.imports);
    }
}

/// The direct statement of [`check_convex_closed`]: closed, a volume, and no used point in
/// front of any face's plane by more than the tolerance, every face against every point.
fn convex_closed_directly(vertices: &[Vec3], faces: &[Vec<usize>]) -> bool {
    let mut used: Vec<usize> = faces.iter().flatten().copied().collect();
    used.sort_unstable();
    used.dedup();
    let (extent, magnitude) = scale(vertices, &used);
    let mut planes = vec![];
    for f in faces {
        let normal = newell(vertices, f);
        if norm(normal) <= 1e-12 * extent * extent {
            return false;
        }
        planes.push((normal, centroid(vertices, f)));
    }
    let volume: f64 = planes.iter().map(|(n, c)| dot(*c, *n) / 6.0).sum();
    let tolerance = CONVEXITY_TOLERANCE * magnitude;
    let behind = planes.iter().all(|(n, c)| {
        let unit = n.map(|x| x / norm(*n));
        used.iter()
            .all(|&i| dot(unit, sub(vertices[i], *c)) <= tolerance)
    });
    check_closed(faces).is_ok() && volume > 1e-12 * extent.powi(3) && behind
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]
    /// A hull of random points, one of its vertices moved in or out (a dent, a bump, or
    /// nothing), its faces in a random turn and maybe all turned inside out: judged convex
    /// and closed exactly as the direct test judges it, though concave ones are found out by
    /// their neighbours first, before the volume is summed.
    #[test]
    fn a_polyhedron_is_convex_as_the_direct_test_says(
        points in prop::collection::vec(prop::array::uniform3(-10.0f64..10.0), 5..40),
        moved in any::<prop::sample::Index>(),
        by in -0.5f64..0.5,
        turn in 0usize..64,
        inside_out in any::<bool>(),
    ) {
        let pts: Vec<glam::DVec3> = points.iter().map(|&p| glam::DVec3::from(p)).collect();
        let Ok((v, mut faces)) = crate::hull::hull3(&pts) else { return Ok(()) };
        let mut vertices: Vec<Vec3> = v.iter().map(|p| p.to_array()).collect();
        let i = moved.index(vertices.len());
        let c = v.iter().sum::<glam::DVec3>() / v.len() as f64;
        vertices[i] = (v[i] + (v[i] - c) * by).to_array();
        let k = turn % faces.len();
        faces.rotate_left(k);
        if inside_out {
            faces.iter_mut().for_each(|f| f.reverse());
        }
        prop_assert_eq!(
            check_convex_closed(&vertices, &faces).is_ok(),
            convex_closed_directly(&vertices, &faces)
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    /// A polyhedron's points welded (equal coordinates, `-0.0` and `0.0`, made one) make the
    /// mesh its triangles' corners welded make, bit for bit, and so the same words of its
    /// open edges.
    #[test]
    fn points_welded_tell_the_open_edges_of_corners_welded(
        points in prop::collection::vec(prop::array::uniform3(-2i8..2), 4..24),
        picks in prop::collection::vec(prop::array::uniform3(any::<prop::sample::Index>()), 1..40),
        negative in any::<bool>(),
    ) {
        // Coarse coordinates, so points repeat; every other point's zeros negative.
        let points: Vec<Vec3> = points
            .iter()
            .enumerate()
            .map(|(i, p)| {
                p.map(|c| match (c, negative && i % 2 == 0) {
                    (0, true) => -0.0,
                    _ => f64::from(c) / 2.0,
                })
            })
            .collect();
        let indices: Vec<[usize; 3]> =
            picks.iter().map(|t| t.map(|i| i.index(points.len()))).collect();
        let tris: Vec<[Vec3; 3]> = indices.iter().map(|t| t.map(|i| points[i])).collect();
        let (a, b) = (welded(&points, &indices), csgpix_scene::trimesh::TriMesh::from_f64(&tris));
        let bits = |m: &csgpix_scene::trimesh::TriMesh| {
            m.vertices.iter().map(|v| v.to_array().map(f64::to_bits)).collect::<Vec<_>>()
        };
        prop_assert_eq!(bits(&a), bits(&b));
        prop_assert_eq!(&a.triangles, &b.triangles);
        prop_assert_eq!(
            a.open_edges_summary("polyhedron").ok(),
            b.open_edges_summary("polyhedron").ok()
        );
    }
}
