//! Every mesh csgpix writes is closed and wound outward, also where the solid touches the
//! grid's faces: Marching Cubes treats everything outside the grid as empty (the cells past
//! the far faces are meshed too; docs/octree.md). The check here is the test's own (not
//! `mesh::open_edges`): vertices welded by position, every directed edge used exactly once
//! and its reverse exactly once, and a positive signed volume.

mod common;
use common::volume;

use csgpix::sculpt::octree::mc::marching_cubes;
use csgpix::sculpt::octree::{from_volume, OptimizedOctree, StoreKind};
use csgpix::sculpt::{Frame, Sculptor, Tool};
use csgpix::voxel::Volume;
use glam::DVec3;
use std::collections::HashMap;

type Tri = [[f32; 3]; 3];

const BUDGET: u64 = 1 << 30;

/// Checks that `tris` is closed and consistently wound (each directed edge between welded
/// vertices once, its reverse once) and returns its signed volume.
fn closed_volume(tris: &[Tri], what: &str) -> f64 {
    assert!(!tris.is_empty(), "{what}: no triangles");
    // Weld: positions snapped to a grid far finer than half a voxel (MC vertices are edge
    // midpoints, at least half a voxel apart), relative to the mesh's box.
    let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
    for p in tris.iter().flatten() {
        for a in 0..3 {
            lo[a] = lo[a].min(f64::from(p[a]));
            hi[a] = hi[a].max(f64::from(p[a]));
        }
    }
    let extent = (0..3).map(|a| hi[a] - lo[a]).fold(0.0, f64::max).max(1e-30);
    let mut ids: HashMap<[i64; 3], usize> = HashMap::new();
    let mut weld = |p: [f32; 3]| {
        let q = [0, 1, 2].map(|a| ((f64::from(p[a]) - lo[a]) / extent * 1e6).round() as i64);
        let n = ids.len();
        *ids.entry(q).or_insert(n)
    };
    let mut edges: HashMap<(usize, usize), u32> = HashMap::new();
    for t in tris {
        let v = t.map(&mut weld);
        assert!(
            v[0] != v[1] && v[1] != v[2] && v[2] != v[0],
            "{what}: degenerate triangle {t:?}"
        );
        for i in 0..3 {
            *edges.entry((v[i], v[(i + 1) % 3])).or_default() += 1;
        }
    }
    let bad: Vec<_> = edges
        .iter()
        .filter(|(&(a, b), &n)| n != 1 || edges.get(&(b, a)) != Some(&1))
        .collect();
    assert!(
        bad.is_empty(),
        "{what}: {} of {} directed edges not used once with their reverse once (first {:?})",
        bad.len(),
        edges.len(),
        bad[0]
    );
    // Signed volume: Σ a·(b×c)/6 over the triangles (divergence theorem).
    let vol: f64 = tris
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into()));
            a.dot(b.cross(c)) / 6.0
        })
        .sum();
    assert!(vol > 0.0, "{what}: signed volume {vol} (wound inward)");
    vol
}

/// Every store's global Marching Cubes mesh of `v`: closed, outward, the same signed volume;
/// returns it.
fn every_store_closed(v: &Volume, what: &str) -> f64 {
    let mut vols = vec![];
    for kind in StoreKind::ALL {
        let s = from_volume(kind, v, BUDGET).unwrap();
        let mesh = marching_cubes(s.as_ref()).triangles;
        vols.push(closed_volume(&mesh, &format!("{what}, {kind:?}")));
    }
    assert!(
        vols.iter()
            .all(|&x| (x - vols[0]).abs() < 1e-9 * x.abs().max(1.0)),
        "{what}: {vols:?}"
    );
    vols[0]
}

#[test]
fn a_box_filling_the_whole_grid_gives_a_closed_mesh() {
    for n in [1, 2, 4, 8, 16] {
        let vol = every_store_closed(&volume([n; 3], |_, _, _| true), &format!("full {n}³"));
        // The surface runs half a voxel outside the voxel centres, the box's 12 edges and 8
        // corners cut off: less than n³, more than n³ less a half-voxel prism per edge voxel.
        let n = n as f64;
        assert!(
            vol < n * n * n && vol > n * n * n - 12.0 * n * 0.125 - 1.0,
            "{n}: {vol}"
        );
    }
}

#[test]
fn solids_touching_one_face_give_closed_meshes() {
    // A slab on each face of an 8×5×6 grid (side 8): only the far X face is a face of the
    // octree's cell grid, the others leave empty voxels before it, and the near faces have
    // cell 0's empty corners.
    let dims = [8, 5, 6];
    for a in 0..3 {
        for far in [false, true] {
            let v = volume(dims, |x, y, z| {
                let p = [x, y, z];
                let inner = (0..3).all(|b| b == a || (1..dims[b] - 1).contains(&p[b]));
                let at = if far { dims[a] - 3..dims[a] } else { 0..3 };
                inner && at.contains(&p[a])
            });
            every_store_closed(&v, &format!("axis {a} far {far}"));
        }
    }
    // The whole grid but a hole, and a lone voxel in each far corner.
    every_store_closed(
        &volume([8, 8, 8], |x, y, z| [x, y, z] != [7, 3, 7]),
        "holed",
    );
    let corners = volume([8, 8, 8], |x, y, z| {
        [x, y, z].iter().all(|&c| c == 0 || c == 7)
    });
    let vol = every_store_closed(&corners, "corners");
    // Eight octahedra of volume 1/6 each.
    assert!((vol - 8.0 / 6.0).abs() < 1e-9, "{vol}");
}

/// The triangles of a binary STL file.
fn read_stl(bytes: &[u8]) -> Vec<Tri> {
    let n = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
    assert_eq!(bytes.len(), 84 + 50 * n);
    let f = |at: usize| f32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
    (0..n)
        .map(|i| {
            let at = 84 + 50 * i + 12;
            std::array::from_fn(|v| std::array::from_fn(|c| f(at + 12 * v + 4 * c)))
        })
        .collect()
}

#[test]
fn every_example_scene_voxelizes_to_a_closed_mesh() {
    let dir = tempfile::tempdir().unwrap();
    let mut scenes: Vec<_> = std::fs::read_dir("vectors/scenes")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "csg"))
        .collect();
    scenes.sort();
    assert!(scenes.len() >= 7, "{scenes:?}");
    for scene in &scenes {
        let name = scene.file_stem().unwrap().to_string_lossy().to_string();
        // The default bounds are the scene's own: it touches every face of the grid.
        for res in ["16", "13x9x11"] {
            let stl = dir.path().join(format!("{name}.stl"));
            let o = common::csgpix(&[
                "voxelize",
                scene.to_str().unwrap(),
                "--res",
                res,
                "--mesh",
                stl.to_str().unwrap(),
                "-o",
                dir.path().join("v.nrrd").to_str().unwrap(),
                "--json",
            ]);
            assert!(
                o.status.success(),
                "{name}: {}",
                String::from_utf8_lossy(&o.stderr)
            );
            let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
            let tris = read_stl(&std::fs::read(&stl).unwrap());
            closed_volume(&tris, &format!("{name} at {res}"));
            assert_eq!(r["mesh_open_edges"], 0, "{name}: {r}");
            assert_eq!(r["mesh_triangles"], tris.len(), "{name}: {r}");
        }
    }
}

#[test]
fn voxelize_reports_no_mesh_figures_without_mesh() {
    let dir = tempfile::tempdir().unwrap();
    let o = common::csgpix(&[
        "voxelize",
        "vectors/scenes/figure-5.2.csg",
        "--res",
        "8x8x8",
        "-o",
        dir.path().join("v.nrrd").to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(r.get("mesh_triangles").is_none() && r.get("mesh_open_edges").is_none());
}

#[test]
fn sculpting_at_the_grid_faces_keeps_the_mesh_closed() {
    // A full 8³ grid: carve at the far corner and along the far faces, add back part of it.
    let v = volume([8, 8, 8], |_, _, _| true);
    let unit = Frame {
        origin: DVec3::ZERO,
        voxel: DVec3::ONE,
    };
    for add in [false, true] {
        let start = if add {
            volume([8, 8, 8], |x, y, z| x >= 5 && y < 3 && z < 4)
        } else {
            v.clone()
        };
        let store = OptimizedOctree::from_volume(&start, BUDGET).unwrap();
        let tool = Tool {
            radius: 2.2,
            add,
            stiffness: 1.0,
        };
        let mut s = Sculptor::new(store, unit, start.dims, tool).unwrap();
        let mut changed = 0;
        for p in [
            [7.0, 7.0, 7.0],
            [7.5, 4.0, 7.0],
            [3.0, 7.2, 7.6],
            [8.5, 0.0, 3.0],
        ] {
            changed += s.step(DVec3::from_array(p)).unwrap().voxels;
        }
        assert!(changed > 0);
        let inc = s.mesh.triangles();
        let what = format!("sculpt add {add}");
        let vol = closed_volume(&inc, &what);
        let full = marching_cubes(&s.store).triangles;
        assert_eq!(inc.len(), full.len(), "{what}");
        assert!(
            (closed_volume(&full, &what) - vol).abs() < 1e-9 * vol,
            "{what}"
        );
    }
}

#[test]
fn sculpt_output_touching_the_grid_is_closed() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("carved.stl");
    // Default bounds: the scene fills the grid to its faces, and the path carves at them.
    let o = common::csgpix(&[
        "sculpt",
        "vectors/scenes/twelve.csg",
        "--res",
        "32x32x32",
        "--tool",
        "sphere:3",
        "--path",
        "vectors/paths/carve.csv",
        "--json",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(r["voxels_changed"].as_u64().unwrap() > 0, "{r}");
    let tris = read_stl(&std::fs::read(&out).unwrap());
    closed_volume(&tris, "carved twelve");
    assert_eq!(r["open_edges"], 0);
    assert_eq!(r["triangles_after"], tris.len());
}
