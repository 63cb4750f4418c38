//! Volume scene graphs (§3.2-3.3, Figure 5.6): datasets and meshes as primitives beside the
//! convex solids. The evaluators agree on a mixed scene and with direct evaluation, a mesh of
//! a solid's own faces voxelizes as the solid, a Marching Cubes mesh of a scene re-imports to
//! the scene's volume within one voxel of its surface, cavities survive, bad input is refused.

mod common;

use std::path::{Path, PathBuf};

use common::csgpix;
use csgpix::scene::solid::{CsgScene, Import};
use csgpix::voxel::blist::BlistEval;
use csgpix::voxel::evaluate::{direct, StackEval, TreeEval};
use csgpix::voxel::sampled::{load_imports, load_scene, Loaded};
use csgpix::voxel::slice::SliceEval;
use csgpix::voxel::{voxelize, word_ranges, Grid, Route, Slicer, SlicerOptions, Volume};
use rtl_model::Equations;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn scene_path(name: &str) -> PathBuf {
    root().join(format!("vectors/scenes/{name}.csg"))
}

fn slicer(l: Loaded, grid: Grid) -> (Slicer, CsgScene) {
    let scene = l.scene.clone();
    let opts = SlicerOptions {
        sampled: l.sampled,
        ..SlicerOptions::default()
    };
    let s = Slicer::new(&l.scene, grid, opts).unwrap();
    (s, scene)
}

fn run(s: &Slicer, route: Route, eval: &dyn SliceEval) -> Volume {
    voxelize(s, route, Equations::Derived.set(), eval, &|| {})
        .unwrap()
        .0
}

fn filled(v: &Volume) -> Vec<bool> {
    v.voxels.iter().map(|&c| c != 0).collect()
}

/// Figure 5.6: Blist, tree and stack fill the same voxels, equal to direct evaluation of the
/// tree over each primitive's own membership (the solids' processor intervals, the dataset's
/// samples), on the fast route at 32³ and the cycle model at 12³.
#[test]
fn figure_5_6_evaluators_agree_with_direct_evaluation() {
    for (n, route) in [(32, Route::Intervals), (12, Route::Array { cycle: true })] {
        let l = load_scene(&scene_path("figure-5.6")).unwrap();
        let grid = l.grid([n; 3]).unwrap();
        let (s, scene) = slicer(l, grid);
        assert_eq!((scene.solids.len(), s.sampled.len()), (4, 1));
        let blist = run(&s, route, &BlistEval::new(&scene.root));
        let tree = run(&s, route, &TreeEval::new(&scene.root));
        let stack = run(&s, route, &StackEval::new(&scene.root));
        assert_eq!(filled(&blist), filled(&tree), "{n}: blist and tree");
        assert_eq!(tree, stack, "{n}: tree and stack");
        let ranges: Vec<_> = (0..4).map(|p| word_ranges(&s, p).unwrap()).collect();
        let [nx, ny, nz] = grid.dims;
        let mut dataset_voxels = 0;
        for k in 0..nz {
            let masks: Vec<_> = ranges.iter().map(|r| r.mask(k)).collect();
            for j in 0..ny {
                for i in 0..nx {
                    let px = j * nx + i;
                    let head = s.sampled[0].inside(grid.centre(i, j, k));
                    let want = direct(&scene.root, |p| match p {
                        4 => head,
                        p => masks[p].get(px),
                    });
                    let v = (k * ny + j) * nx + i;
                    assert_eq!(tree.voxels[v] != 0, want, "{n}: voxel {i},{j},{k}");
                    dataset_voxels += usize::from(tree.voxels[v] == s.colours[4] && head);
                }
            }
        }
        assert!(dataset_voxels > 0, "the dataset shows in the scene");
    }
}

/// The dataset's cavities (the phantom's ventricles, below the threshold) and the bores of
/// the cylinders are empty; the skull is full.
#[test]
fn figure_5_6_keeps_the_phantoms_cavities_and_the_bores() {
    let l = load_scene(&scene_path("figure-5.6")).unwrap();
    let grid = Grid::new(
        [40; 3],
        (-10.0, -10.0, -10.0).into(),
        (10.0, 10.0, 10.0).into(),
    )
    .unwrap();
    let (s, scene) = slicer(l, grid);
    let v = run(&s, Route::Intervals, &BlistEval::new(&scene.root));
    let at = |p: [f64; 3]| {
        let ijk = [0, 1, 2].map(|a| ((p[a] + 10.0) / 0.5) as usize);
        v.voxels[(ijk[2] * 40 + ijk[1]) * 40 + ijk[0]]
    };
    let d = &s.sampled[0];
    // Somewhere inside the head below the threshold (a ventricle): found by sampling, so the
    // test follows the phantom's definition rather than repeating it.
    let cavity = (0..40 * 40 * 40)
        .map(|i| grid.centre(i % 40, i / 40 % 40, i / 1600))
        .find(|p| p.length() < 4.0 && p.x.abs() > 1.0 && d.sample(*p).is_some_and(|x| x < 300.0))
        .expect("the phantom has an inner cavity");
    assert_eq!(at(cavity.into()), 0, "cavity at {cavity} filled");
    assert_eq!(at([-4.0, 0.25, 0.25]), 0, "cylinder1's bore is empty");
    assert_ne!(
        at([-4.0, 4.25, 0.25]),
        0,
        "beside the bore, inside the head"
    );
}

/// Triangles of a convex solid's faces (fans), in scene units.
fn faces_of(s: &csgpix::scene::solid::ConvexSolid) -> Vec<csgpix::scene::mesh::Tri> {
    let v = |i: u32| s.vertices[i as usize].map(|c| c as f32);
    s.faces
        .iter()
        .flat_map(|f| (1..f.len() - 1).map(move |k| [v(f[0]), v(f[k]), v(f[k + 1])]))
        .collect()
}

/// The scene with every convex solid replaced by an STL mesh of its own faces, same tree.
fn as_meshes(scene: &CsgScene, dir: &Path) -> Loaded {
    let imports = scene
        .solids
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let file = format!("solid{i}.stl");
            csgpix::scene::mesh::write(&dir.join(&file), &faces_of(s), "test").unwrap();
            Import {
                file,
                threshold: None,
                matrix: None,
                colour: s.colour,
                line: s.line,
                col: 1,
                footprint: None,
                mesh: None,
            }
        })
        .collect();
    let meshes = CsgScene {
        solids: vec![],
        imports,
        root: scene.root.clone(),
        warnings: vec![],
        reading_bytes: 0,
    };
    let sampled = load_imports(&meshes, "meshes", dir).unwrap();
    Loaded {
        scene: meshes,
        sampled,
    }
}

/// Voxels that differ, and whether each lies on the surface of `a` (a 6-neighbour of it in
/// `a` has the other classification).
fn differences(a: &Volume, b: &Volume) -> (usize, usize) {
    let [nx, ny, nz] = a.dims;
    let get = |v: &Volume, i: isize, j: isize, k: isize| {
        let inside = |c: isize, n: usize| (0..n as isize).contains(&c);
        (inside(i, nx) && inside(j, ny) && inside(k, nz))
            && v.voxels[((k as usize * ny) + j as usize) * nx + i as usize] != 0
    };
    let (mut diff, mut off_surface) = (0, 0);
    for k in 0..nz as isize {
        for j in 0..ny as isize {
            for i in 0..nx as isize {
                let here = get(a, i, j, k);
                if here == get(b, i, j, k) {
                    continue;
                }
                diff += 1;
                let n6 = [
                    (1, 0, 0),
                    (-1, 0, 0),
                    (0, 1, 0),
                    (0, -1, 0),
                    (0, 0, 1),
                    (0, 0, -1),
                ];
                if !n6
                    .iter()
                    .any(|(di, dj, dk)| get(a, i + di, j + dj, k + dk) != here)
                {
                    off_surface += 1;
                }
            }
        }
    }
    (diff, off_surface)
}

/// A mesh of each solid's own faces, imported, gives the solids' voxels: the mesh route
/// reduces its crossings to slabs exactly as the float route reduces a solid's interval, so
/// only rays through a silhouette edge or vertex may differ (the mesh's fill rule against the
/// solid's closed perpendicular planes), and those voxels are on the surface.
#[test]
fn a_mesh_of_a_solids_faces_voxelizes_as_the_solid() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["figure-5.2", "cube-minus-cylinder", "hollow-cube", "twelve"] {
        let l = load_scene(&scene_path(name)).unwrap();
        let grid = l.grid([40; 3]).unwrap();
        let meshes = as_meshes(&l.scene, dir.path());
        let (s, scene) = slicer(l, grid);
        let (m, _) = slicer(meshes, grid);
        let eval = TreeEval::new(&scene.root);
        let solid = run(&s, Route::Float, &eval);
        let mesh = run(&m, Route::Float, &eval);
        let (diff, off) = differences(&solid, &mesh);
        let total = solid.voxels.iter().filter(|&&c| c != 0).count();
        eprintln!("{name}: {diff} of {total} voxels differ");
        assert_eq!(off, 0, "{name}: {off} differing voxels off the surface");
        assert!(
            diff * 200 <= total,
            "{name}: {diff} of {total} differ (over 0.5%)"
        );
        // Colours follow: the same primitive wins where both are filled, except where a voxel
        // centre lies on a face two solids share (the solid's closed planes and the mesh's
        // rounded crossings break that tie either way): as rare as the differing voxels.
        let recoloured = solid
            .voxels
            .iter()
            .zip(&mesh.voxels)
            .filter(|(a, b)| **a != 0 && **b != 0 && a != b)
            .count();
        eprintln!("{name}: {recoloured} voxels won by another primitive");
        assert!(recoloured * 200 <= total, "{name}: {recoloured} recoloured");
    }
}

/// A closed mesh with an inner, reversed shell (a hollow cube as one STL) keeps its hidden
/// cavity (§5.9): parity along the ray enters, leaves, enters and leaves.
#[test]
fn a_hollow_mesh_keeps_its_cavity() {
    let dir = tempfile::tempdir().unwrap();
    let cube = |lo: f32, hi: f32, flip: bool| -> Vec<csgpix::scene::mesh::Tri> {
        let c = |x: bool, y: bool, z: bool| [x, y, z].map(|b| if b { hi } else { lo });
        // Outward faces of the unit box, as quads (counter-clockwise from outside).
        let quads = [
            [
                c(false, false, false),
                c(false, true, false),
                c(true, true, false),
                c(true, false, false),
            ],
            [
                c(false, false, true),
                c(true, false, true),
                c(true, true, true),
                c(false, true, true),
            ],
            [
                c(false, false, false),
                c(true, false, false),
                c(true, false, true),
                c(false, false, true),
            ],
            [
                c(false, true, false),
                c(false, true, true),
                c(true, true, true),
                c(true, true, false),
            ],
            [
                c(false, false, false),
                c(false, false, true),
                c(false, true, true),
                c(false, true, false),
            ],
            [
                c(true, false, false),
                c(true, true, false),
                c(true, true, true),
                c(true, false, true),
            ],
        ];
        quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .map(|mut t| {
                if flip {
                    t.swap(1, 2);
                }
                t
            })
            .collect()
    };
    let mut tris = cube(0.0, 10.0, false);
    tris.extend(cube(3.0, 7.0, true));
    let stl = dir.path().join("hollow.stl");
    csgpix::scene::mesh::write(&stl, &tris, "hollow").unwrap();
    let out = dir.path().join("h.nrrd");
    let o = csgpix(&[
        "voxelize",
        "--expr",
        "H",
        "--prim",
        &format!("H={}", stl.display()),
        "--res",
        "20x20x20",
        "--bounds=0,0,0,10,10,10",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (dims, v) = csgpix::scene::nrrd::read(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!(dims, [20; 3]);
    let at = |i: usize, j: usize, k: usize| v[(k * 20 + j) * 20 + i];
    assert_ne!(at(1, 1, 1), 0, "the shell");
    assert_eq!(at(10, 10, 10), 0, "the cavity");
    assert_eq!(at(7, 10, 10), 0, "the cavity's edge, voxel 3.5..4.0");
    assert_ne!(at(5, 10, 10), 0, "the inner wall");
    // Along Z as across: a voxel is its centre (docs/voxelization.md); voxel z = 5 (centre
    // 2.75) is wall, z = 6 (3.25) and z = 13 (6.75) cavity, z = 14 (7.25) wall.
    assert_ne!(at(10, 10, 5), 0, "the cavity's front wall");
    assert_eq!(at(10, 10, 6), 0, "the cavity's front, 3.0..3.5");
    assert_eq!(at(10, 10, 13), 0, "the cavity's back, 6.5..7.0");
    assert_ne!(at(10, 10, 14), 0, "the cavity's back wall");
    let inner = (0..20usize.pow(3)).filter(|&i| {
        let (x, y, z) = (i % 20, i / 20 % 20, i / 400);
        (6..14).contains(&x) && (6..14).contains(&y) && (6..14).contains(&z)
    });
    assert!(
        inner.clone().all(|i| v[i] == 0),
        "the whole cavity is empty"
    );
    assert_eq!(
        v.iter().filter(|&&c| c == 0).count(),
        8 * 8 * 8,
        "and only the cavity"
    );
}

/// `voxelize --mesh` writes the volume's Marching Cubes surface, closed even where the solid
/// reaches the grid's faces; imported again through `--expr`, it voxelizes to exactly the
/// scene's volume under centre sampling (the surface runs through the midpoints between voxel
/// centres, so no centre lies on it). Under the thesis's slab sampling it gains exactly one
/// voxel behind every face that looks along +Z: the midpoint along Z is the next slab's front
/// plane, which that slab's segment includes (docs/voxelization.md). Both with a voxel of
/// margin all round and with the grid's faces on the solid's.
#[test]
fn a_marching_cubes_mesh_reimports_to_the_scenes_volume() {
    let mut figures = vec![];
    for sampling in ["centre", "slab"] {
        for (res, bounds, slice) in [
            ("34x34x20", "--bounds=-2,-2,-3,32,32,17", 34 * 34),
            ("30x30x14", "--bounds=0,0,0,30,30,14", 30 * 30),
        ] {
            let (total, gained, lost, behind_back_faces) =
                mc_round_trip(sampling, res, bounds, slice);
            eprintln!(
                "marching cubes round trip ({sampling}, {res}): {total} voxels, {} gained, {lost} lost",
                gained.len()
            );
            assert_eq!(lost, 0, "{sampling} {res}");
            match sampling {
                "centre" => assert!(gained.is_empty(), "{res}"),
                _ => assert_eq!(gained, behind_back_faces, "{res}"),
            }
            figures.push((total, gained.len()));
        }
    }
    // Slab sampling with the margin: slab z 14..15 is solid too (its front plane is the
    // cubes' top face) and the re-import gains the voxels behind the back faces; the tight
    // grid ends at z = 14, so no voxel behind a back face lies in it.
    assert_eq!(figures, [(7560, 0), (7560, 0), (8100, 540), (7560, 0)]);
}

/// Voxelize figure-5.2 with `--mesh`, re-import the mesh: the voxel count, the voxels gained
/// and lost, and the voxels just behind the volume's +Z-facing surfaces.
fn mc_round_trip(
    sampling: &str,
    res: &str,
    bounds: &str,
    slice: usize,
) -> (usize, Vec<usize>, usize, Vec<usize>) {
    let dir = tempfile::tempdir().unwrap();
    let d = |f: &str| dir.path().join(f).display().to_string();
    let scene = scene_path("figure-5.2").display().to_string();
    let common = ["--res", res, bounds, "--sampling", sampling];
    let mut args = vec!["voxelize", &scene];
    args.extend(common);
    let (stl, a_out) = (d("s.stl"), d("a.nrrd"));
    args.extend(["--mesh", &stl, "-o", &a_out]);
    let o = csgpix(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (prim, b_out) = (format!("S={stl}"), d("b.nrrd"));
    let mut args = vec!["voxelize", "--expr", "S", "--prim", &prim];
    args.extend(common);
    args.extend(["-o", &b_out]);
    let o = csgpix(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let read = |f: &str| {
        let (_, voxels) = csgpix::scene::nrrd::read(&std::fs::read(f).unwrap()).unwrap();
        voxels.iter().map(|&c| c != 0).collect::<Vec<bool>>()
    };
    let (a, b) = (read(&a_out), read(&b_out));
    let behind_back_faces: Vec<usize> = (slice..a.len())
        .filter(|&i| a[i - slice] && !a[i])
        .collect();
    let gained: Vec<usize> = (0..a.len()).filter(|&i| b[i] && !a[i]).collect();
    let lost = (0..a.len()).filter(|&i| a[i] && !b[i]).count();
    let total = a.iter().filter(|&&x| x).count();
    (total, gained, lost, behind_back_faces)
}

fn fails_with(args: &[&str], parts: &[&str]) {
    let o = csgpix(args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.trim().lines().count(), 1, "one line: {err}");
    for p in parts {
        assert!(err.contains(p), "{args:?}: {err:?} lacks {p:?}");
    }
}

#[test]
fn bad_imports_are_refused_with_file_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let w = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p.display().to_string()
    };
    let out = dir.path().join("o.nrrd").display().to_string();
    let missing = w(
        "missing.csg",
        "union() {\n  cube(1);\n  import(\"nothing.stl\");\n}\n",
    );
    // A missing file imports nothing (OpenSCAD's warning); --strict refuses at it.
    fails_with(
        &[
            "voxelize", &missing, "--res", "8x8x8", "--strict", "-o", &out,
        ],
        &["missing.csg:3:3", "nothing.stl", "Can't open import file"],
    );
    w("phantom.nrrd", ""); // present: the refusal is the missing threshold
    let no_threshold = w("nt.csg", "import(file = \"phantom.nrrd\");\n");
    fails_with(
        &["voxelize", &no_threshold, "--res", "8x8x8", "-o", &out],
        &["nt.csg:1:1", "threshold"],
    );
    // An open mesh (ten loose triangles): voxelized by its winding number, with a warning.
    let open = "solid o\n".to_string()
        + &(0..10)
            .map(|i| {
                let z = i as f32;
                format!(
                    "facet normal 0 0 0\nouter loop\nvertex 0 0 {z}\nvertex 1 0 {z}\nvertex 0 1 {z}\nendloop\nendfacet\n"
                )
            })
            .collect::<String>()
        + "endsolid o\n";
    w("open.stl", &open);
    let uses_open = w("open.csg", "import(\"open.stl\");\n");
    let open_out = dir.path().join("open.nrrd").display().to_string();
    let o = csgpix(&[
        "voxelize", &uses_open, "--res", "8x8x8", "-o", &open_out, "--json",
    ]);
    let report = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let warning = format!("{uses_open}:1:1: `open.stl`: mesh is not closed: 30 edges");
    assert!(report.contains(&warning), "{report}");
    fails_with(
        &[
            "voxelize", "--expr", "A+B", "--prim", "A=x.stl", "--res", "8x8x8", "-o", &out,
        ],
        &["`B`"],
    );
    let phantom = format!("A={}", root().join("vectors/scenes/phantom.nrrd").display());
    fails_with(
        &[
            "voxelize", "--expr", "A", "--prim", &phantom, "--res", "8x8x8", "-o", &out,
        ],
        &["--prim A", "threshold"],
    );
    let fig = scene_path("figure-5.6").display().to_string();
    let png = dir.path().join("r.png").display().to_string();
    fails_with(
        &["render", &fig, "-o", &png],
        &["figure-5.6.csg:", "import(\"phantom.nrrd\")"],
    );
    assert!(!Path::new(&out).exists(), "no partial output");
}

/// `--blend max`: with the solids binary (255), blending fills exactly the voxels the labels
/// fill; dataset voxels carry the dataset's grey values, the solids 255. `--grey` colours the
/// dataset's winning voxels by grey value, the rest by colour code.
#[test]
fn blending_and_grey_output() {
    let dir = tempfile::tempdir().unwrap();
    let d = |f: &str| dir.path().join(f).display().to_string();
    let fig = scene_path("figure-5.6").display().to_string();
    for (flag, file) in [
        (None, "l.nrrd"),
        (Some("--grey"), "g.nrrd"),
        (Some("--blend=max"), "b.nrrd"),
    ] {
        let mut args = vec!["voxelize", &fig, "--res", "24x24x24", "-o"];
        let f = d(file);
        args.push(&f);
        args.extend(flag);
        let o = csgpix(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let read = |f: &str| {
        csgpix::scene::nrrd::read(&std::fs::read(d(f)).unwrap())
            .unwrap()
            .1
    };
    let (labels, grey, blend) = (read("l.nrrd"), read("g.nrrd"), read("b.nrrd"));
    let f = |v: &[u8]| v.iter().map(|&c| c != 0).collect::<Vec<_>>();
    assert_eq!(
        f(&labels),
        f(&blend),
        "blend max fills what the labels fill"
    );
    assert_eq!(f(&labels), f(&grey));
    let greys: std::collections::BTreeSet<u8> = blend
        .iter()
        .copied()
        .filter(|&c| c != 0 && c != 255)
        .collect();
    assert!(
        greys.len() > 10,
        "the dataset's grey levels show: {greys:?}"
    );
    assert!(grey.iter().any(|&c| c > 15), "--grey writes grey values");
    assert!(
        grey.iter().any(|&c| (1..=15).contains(&c)),
        "and colour codes for solids"
    );
}

/// `vectors/scenes/phantom.nrrd` (what figure-5.6.csg imports) is what `csgpix phantom`
/// writes, byte for byte.
#[test]
fn the_checked_in_phantom_is_what_the_generator_writes() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("p.nrrd");
    let o = csgpix(&["phantom", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let fresh = std::fs::read(&out).unwrap();
    let checked_in = std::fs::read(root().join("vectors/scenes/phantom.nrrd")).unwrap();
    assert!(
        fresh == checked_in,
        "regenerate: csgpix phantom -o vectors/scenes/phantom.nrrd"
    );
}

/// `import()` as OpenSCAD exports it (all its parameters), placed by `multmatrix`, gives the
/// voxels of the solid whose faces the mesh holds, placed the same way. On the float route,
/// whose interval-to-slab rounding the mesh route shares, with no face exactly on a slab
/// plane: there the two f64 computations of the same depth (the solid's plane equation, the
/// mesh's barycentric interpolation) can fall either side (7 of 858 voxels with bounds
/// −6,−6,−8..8,8,8, where the cube's bottom face is slab 3's front plane).
#[test]
fn an_openscad_import_statement_places_the_mesh_like_a_solid() {
    let dir = tempfile::tempdir().unwrap();
    let cube = csgpix::openscad::parse_csg("cube(size = [4, 6, 8], center = true);", "c").unwrap();
    csgpix::scene::mesh::write(
        &dir.path().join("box.stl"),
        &faces_of(&cube.solids[0]),
        "box",
    )
    .unwrap();
    let m = "multmatrix([[0, -1, 0, 3], [1, 0, 0, 1], [0, 0, 1, -2], [0, 0, 0, 1]])";
    let scenes = [
        format!("{m} import(file = \"box.stl\", layer = \"\", origin = [0, 0], scale = 1, convexity = 1, $fn = 0, $fa = 12, $fs = 2, timestamp = 1700000000);\n"),
        format!("{m} cube(size = [4, 6, 8], center = true);\n"),
    ];
    let volumes: Vec<Vec<u8>> = scenes
        .iter()
        .enumerate()
        .map(|(i, text)| {
            let csg = dir.path().join(format!("s{i}.csg"));
            std::fs::write(&csg, text).unwrap();
            let out = dir.path().join(format!("s{i}.nrrd"));
            let o = csgpix(&[
                "voxelize",
                csg.to_str().unwrap(),
                "--res",
                "24x24x24",
                "--bounds=-6.1,-6.2,-8.3,8,8,8",
                "--model",
                "float",
                "-o",
                out.to_str().unwrap(),
            ]);
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            csgpix::scene::nrrd::read(&std::fs::read(&out).unwrap())
                .unwrap()
                .1
        })
        .collect();
    let count = |v: &[u8]| v.iter().filter(|&&c| c != 0).count();
    let differ = volumes[0]
        .iter()
        .zip(&volumes[1])
        .filter(|(a, b)| a != b)
        .count();
    assert!(count(&volumes[1]) > 0);
    assert_eq!(
        differ,
        0,
        "{} and {} voxels filled",
        count(&volumes[0]),
        count(&volumes[1])
    );
}
