//! Straight extrusions read as footprints (`csgpix_scene::footprint`) against the same
//! extrusions read as convex prisms and meshes: random 2D trees of circles, squares and
//! polygons, extruded, placed by rotations about Z, mirrors and moves, voxelized by every
//! route. The two readings are the same solid. A footprint's walls are exact on every
//! route (an outline's crossing of a pixel row, in f64), so its voxels are the prisms' by the
//! float model, whatever the route; the word routes' prisms differ from those by the depth
//! word's plane error (docs/depth-word.md), which the footprint does not have.

use csgpix_openscad::{parse_csg_with, ReadOptions};
use csgpix_scene::grid::Grid;
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::sampled::{load_imports, Shape};
use csgpix_voxel::{voxelize, Route, Slicer, SlicerOptions};
use glam::{DVec2, DVec3};
use proptest::prelude::*;
use rtl_model::Equations;

/// The scene's voxels on `grid` by `route`, read with footprints from `least` outline
/// points (None: never).
fn voxels(text: &str, grid: Grid, route: Route, least: Option<usize>) -> (Vec<u8>, usize) {
    let options = ReadOptions {
        footprints: least,
        ..ReadOptions::default()
    };
    voxels_with(text, grid, route, &options)
}

/// [`voxels`] read with `options`.
fn voxels_with(text: &str, grid: Grid, route: Route, options: &ReadOptions) -> (Vec<u8>, usize) {
    let scene = parse_csg_with(text, "t.csg", options).unwrap_or_else(|e| panic!("{e}"));
    let sampled = load_imports(&scene, "t.csg", std::path::Path::new(".")).unwrap();
    let footprints = sampled
        .iter()
        .filter(|s| matches!(s.shape, Shape::Footprint(_)))
        .count();
    let opts = SlicerOptions {
        sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&scene, grid, opts).unwrap();
    let eval = BlistEval::new(&scene.root);
    let (v, _) = voxelize(&slicer, route, Equations::Derived.set(), &eval, &|| {}).unwrap();
    (v.voxels, footprints)
}

/// A 2D subtree's text and the outlines of its polygons (the shapes read as meshes, whose
/// walls the mesh raster places to its fixed point; circles and squares are convex prisms).
#[derive(Clone, Debug)]
struct Piece {
    text: String,
    polygons: Vec<Vec<DVec2>>,
}

fn shape() -> impl Strategy<Value = Piece> {
    let plain = |text: String| Piece {
        text,
        polygons: vec![],
    };
    prop_oneof![
        (0.3..6.0f64, 3usize..60, -8.0..8.0f64, -8.0..8.0f64).prop_map(move |(r, n, x, y)| plain(format!(
            "multmatrix([[1, 0, 0, {x}], [0, 1, 0, {y}], [0, 0, 1, 0], [0, 0, 0, 1]]) circle(r = {r}, $fn = {n});"
        ))),
        (0.3..9.0f64, 0.3..9.0f64, -8.0..8.0f64, -8.0..8.0f64, -3.2..3.2f64).prop_map(
            move |(w, h, x, y, a)| {
                let (s, c) = a.sin_cos();
                plain(format!(
                    "multmatrix([[{c}, {}, 0, {x}], [{s}, {c}, 0, {y}], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [{w}, {h}], center = true);",
                    -s
                ))
            }
        ),
        // Any points: concave or crossing itself (even-odd).
        prop::collection::vec((-9.0..9.0f64, -9.0..9.0f64), 3..8).prop_map(|v| {
            let pts: Vec<String> = v.iter().map(|(x, y)| format!("[{x}, {y}]")).collect();
            Piece {
                text: format!("polygon(points = [{}], paths = undef, convexity = 1);", pts.join(", ")),
                polygons: vec![v.iter().map(|&(x, y)| DVec2::new(x, y)).collect()],
            }
        }),
    ]
}

fn tree() -> impl Strategy<Value = Piece> {
    shape().prop_recursive(3, 16, 4, |inner| {
        (
            prop_oneof![Just("union"), Just("intersection"), Just("difference")],
            prop::collection::vec(inner, 1..4),
        )
            .prop_map(|(op, c)| Piece {
                text: format!(
                    "{op}() {{ {} }}",
                    c.iter()
                        .map(|p| p.text.as_str())
                        .collect::<Vec<_>>()
                        .join(" ")
                ),
                polygons: c.into_iter().flat_map(|p| p.polygons).collect(),
            })
    })
}

/// A placement that keeps the Z axis (a turn about Z, maybe a mirror, a move): its text
/// and its map of the plane, row-major 2×3.
fn placement() -> impl Strategy<Value = (String, [[f64; 3]; 2])> {
    (
        -3.2..3.2f64,
        any::<bool>(),
        prop::array::uniform3(-3.0..3.0f64),
    )
        .prop_map(|(a, m, t)| {
            let (s, c) = a.sin_cos();
            let f = if m { -1.0 } else { 1.0 };
            let rows = [[c * f, -s, t[0]], [s * f, c, t[1]]];
            let text = format!(
                "multmatrix([[{}, {}, 0, {}], [{}, {}, 0, {}], [0, 0, 1, {}], [0, 0, 0, 1]])",
                rows[0][0], rows[0][1], rows[0][2], rows[1][0], rows[1][1], rows[1][2], t[2]
            );
            (text, rows)
        })
}

/// The distance from `p` to the nearest edge of `polygons`.
fn to_edges(p: DVec2, polygons: &[Vec<DVec2>]) -> f64 {
    let mut best = f64::INFINITY;
    for poly in polygons {
        for i in 0..poly.len() {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
            best = best.min((a + (b - a) * t - p).length());
        }
    }
    best
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn footprints_are_the_float_prisms_voxels(
        t in tree(),
        at in placement(),
        h in 0.5..9.0f64,
        center in any::<bool>(),
        n in 16usize..40,
    ) {
        let text = format!("{} {{ linear_extrude(height = {h}, center = {center}) {{ {} }} }}", at.0, t.text);
        let grid = Grid::new([n; 3], DVec3::splat(-14.1), DVec3::splat(13.9)).unwrap();
        let (b, fb) = voxels(&text, grid, Route::Float, None);
        prop_assert_eq!(fb, 0);
        // A voxel centre's point in the plane (the placement is a rigid map: distances kept).
        let m = at.1;
        let local = |q: DVec3| {
            let d = DVec2::new(q.x - m[0][2], q.y - m[1][2]);
            let (c0, c1) = (DVec2::new(m[0][0], m[1][0]), DVec2::new(m[0][1], m[1][1]));
            DVec2::new(d.dot(c0), d.dot(c1))
        };
        for route in [Route::Float, Route::Runs { float: true }, Route::Runs { float: false }, Route::Intervals] {
            let (a, fa) = voxels(&text, grid, route, Some(0));
            prop_assert_eq!(fa, 1);
            for (i, (p, q)) in a.iter().zip(&b).enumerate() {
                if (*p != 0) == (*q != 0) {
                    continue;
                }
                // Only where a polygon's wall passes within two steps of the mesh raster's
                // fixed point (2^-16 of a pixel, `trimesh::FRAC_BITS`), which places the
                // mesh's walls: the footprint's are exact.
                let c = grid.centre(i % n, i / n % n, i / (n * n));
                let d = to_edges(local(c), &t.polygons);
                prop_assert!(d < grid.voxel().x / 32768.0, "{:?}: voxel {} differs, {} from a polygon's wall\n{}", route, i, d, text);
            }
        }
    }
}

/// How many of the scene's primitives are footprints, read with footprints from `least`
/// outline points (None: never) and, if `concave`, every concave straight extrusion.
fn footprints_read(text: &str, least: Option<usize>, concave: bool) -> usize {
    let options = ReadOptions {
        footprints: least,
        concave_footprints: concave,
        ..ReadOptions::default()
    };
    let s = parse_csg_with(text, "t.csg", &options).unwrap_or_else(|e| panic!("{e}"));
    s.imports.iter().filter(|i| i.footprint.is_some()).count()
}

/// Which extrusions become footprints: straight ones of more outline points than asked,
/// placed keeping the Z axis, under no operation that needs their geometry while the scene is
/// read.
#[test]
fn only_straight_extrusions_outside_hulls_are_footprints() {
    let footprints = |text: &str, least| footprints_read(text, least, false);
    let disc = "circle(r = 2, $fn = 100);";
    let straight = format!("linear_extrude(height = 2) {{ {disc} }}");
    assert_eq!(footprints(&straight, Some(99)), 1);
    assert_eq!(footprints(&straight, Some(100)), 0, "100 points, not more");
    assert_eq!(footprints(&straight, None), 0);
    let twisted = format!("linear_extrude(height = 2, twist = 30) {{ {disc} }}");
    assert_eq!(footprints(&twisted, Some(0)), 0);
    let scaled = format!("linear_extrude(height = 2, scale = 0.5) {{ {disc} }}");
    assert_eq!(footprints(&scaled, Some(0)), 0);
    let tilted = format!(
        "multmatrix([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]]) {{ {straight} }}"
    );
    assert_eq!(footprints(&tilted, Some(0)), 0);
    let turned = format!(
        "multmatrix([[0, -1, 0, 4], [1, 0, 0, 0], [0, 0, 2, 1], [0, 0, 0, 1]]) {{ {straight} }}"
    );
    assert_eq!(footprints(&turned, Some(0)), 1);
    let hulled = format!("hull() {{ {straight} cube(size = [1, 1, 1]); }}");
    assert_eq!(footprints(&hulled, Some(0)), 0);
    let summed = format!("minkowski() {{ {straight} cube(size = [1, 1, 1]); }}");
    assert_eq!(footprints(&summed, Some(0)), 0);
    // The vertex budget counts a footprint's outline points as its shapes are read: where
    // 150 are allowed, one extrusion of 100 points is read, and a second is refused.
    let small = ReadOptions {
        footprints: Some(0),
        max_vertices: Some(150),
        ..ReadOptions::default()
    };
    let two = format!("{straight}\n{straight}");
    let e = parse_csg_with(&two, "t.csg", &small)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("t.csg:2:") && e.contains("vertex limit"),
        "{e}"
    );
    assert!(parse_csg_with(&straight, "t.csg", &small).is_ok());
}

/// A print's rule (`concave_footprints`): a straight extrusion with a shape that is not
/// convex is a footprint whatever its points; one of convex shapes only stays prisms; `off`
/// (no count) turns both off. The footprint fills the same voxels as the mesh it replaces.
#[test]
fn a_print_reads_concave_extrusions_as_footprints() {
    let footprints = |text: &str, least| footprints_read(text, least, true);
    let ell = "polygon(points = [[0, 0], [3, 0], [3, 1], [1, 1], [1, 3], [0, 3]]);";
    let square = "square(size = [3, 3]);";
    let extrude = |s: &str| format!("linear_extrude(height = 2) {{ {s} }}");
    assert_eq!(footprints(&extrude(ell), Some(1000)), 1);
    assert_eq!(footprints(&extrude(square), Some(1000)), 0);
    let moved = "multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])";
    let both = format!("union() {{ {square} {moved} {ell} }}");
    assert_eq!(footprints(&extrude(&both), Some(1000)), 1);
    assert_eq!(footprints(&extrude(ell), None), 0);
    let twisted = format!("linear_extrude(height = 2, twist = 30) {{ {ell} }}");
    assert_eq!(footprints(&twisted, Some(1000)), 0);
    let (lo, hi) = (DVec3::new(-1.0, -1.0, -0.5), DVec3::new(9.0, 4.0, 2.5));
    let grid = Grid::new([40, 20, 6], lo, hi).unwrap();
    let text = extrude(&both);
    let filled = |v: Vec<u8>| v.iter().map(|&c| c != 0).collect::<Vec<_>>();
    let (mesh, none) = voxels(&text, grid, Route::Float, None);
    let options = ReadOptions {
        footprints: Some(1000),
        concave_footprints: true,
        ..ReadOptions::default()
    };
    let (footprint, one) = voxels_with(&text, grid, Route::Float, &options);
    assert_eq!((none, one), (0, 1));
    assert!(mesh.iter().any(|&c| c != 0));
    assert_eq!(filled(mesh), filled(footprint));
}
