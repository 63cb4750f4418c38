//! Sculpting (seed 000 Ch. 5-6, `crates/sculpt/src/sculpt.rs`): the incremental mesh after random steps is
//! the full Marching Cubes of the final store, the store holds the volume a plain dense model
//! of the carve gives, the surface stays closed, hand-counted steps, the spring force, path and
//! tool parsing, the mesh files and the command line.

mod common;

use std::collections::HashMap;

use csgpix::scene::mesh::{self, Tri};
use csgpix::sculpt::octree::{mc, OptimizedOctree, VoxelStore};
use csgpix::sculpt::{parse_path, parse_tool, Frame, Sculptor, Tool};
use csgpix::voxel::Volume;
use glam::DVec3;
use proptest::prelude::*;

const BUDGET: u64 = 1 << 30;

/// Voxel units are scene units.
const UNIT: Frame = Frame {
    origin: DVec3::ZERO,
    voxel: DVec3::ONE,
};

fn volume(dims: [usize; 3], f: impl Fn(usize, usize, usize) -> bool) -> Volume {
    let mut voxels = vec![0u8; dims.iter().product()];
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                voxels[(z * dims[1] + y) * dims[0] + x] = u8::from(f(x, y, z));
            }
        }
    }
    Volume { dims, voxels }
}

/// Triangles as sortable bit patterns.
fn sorted(tris: &[Tri]) -> Vec<[u32; 9]> {
    let mut v: Vec<[u32; 9]> = tris
        .iter()
        .map(|t| {
            let f: Vec<u32> = t.iter().flatten().map(|c| c.to_bits()).collect();
            f.try_into().expect("9 floats")
        })
        .collect();
    v.sort_unstable();
    v
}

/// The carve as a plain dense model: each step sets (add) or clears every voxel whose centre
/// lies within `r` of the step's point, inside `0..limit` on each axis.
fn dense_model(v: &Volume, path: &[DVec3], r: f64, add: bool, limit: [usize; 3]) -> Volume {
    let mut out = v.clone();
    let [nx, ny, _] = v.dims;
    for c in path {
        for z in 0..limit[2] {
            for y in 0..limit[1] {
                for x in 0..limit[0] {
                    let d = DVec3::new(x as f64, y as f64, z as f64) - *c;
                    if d.length_squared() <= r * r {
                        out.voxels[(z * ny + y) * nx + x] = u8::from(add);
                    }
                }
            }
        }
    }
    out
}

fn sculptor(v: &Volume, r: f64, add: bool, k: f64) -> Sculptor {
    let store = OptimizedOctree::from_volume(v, BUDGET).expect("store");
    let tool = Tool {
        radius: r,
        add,
        stiffness: k,
    };
    Sculptor::new(store, UNIT, v.dims, tool).expect("sculptor")
}

/// A random volume of boxes and a ball, often touching the octree grid's faces.
fn random_volume() -> impl Strategy<Value = Volume> {
    let dims = [4usize..=16, 4usize..=16, 4usize..=16];
    let boxes = prop::collection::vec(
        ([0usize..16, 0..16, 0..16], [1usize..10, 1..10, 1..10]),
        1..4,
    );
    let ball = ([2.0..14.0f64, 2.0..14.0, 2.0..14.0], 0.0..6.0f64);
    (dims, boxes, ball).prop_map(|(dims, boxes, (c, r))| {
        volume(dims, |x, y, z| {
            let p = [x, y, z];
            let inside_box = boxes
                .iter()
                .any(|(o, s)| (0..3).all(|a| p[a] >= o[a] && p[a] < o[a] + s[a]));
            let d = DVec3::new(x as f64 - c[0], y as f64 - c[1], z as f64 - c[2]);
            let inside_ball = d.length() <= r;
            inside_box || inside_ball
        })
    })
}

fn random_path() -> impl Strategy<Value = Vec<DVec3>> {
    prop::collection::vec([-3.0..19.0f64, -3.0..19.0, -3.0..19.0], 1..14)
        .prop_map(|v| v.into_iter().map(DVec3::from_array).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn random_carving_keeps_the_mesh_equal_to_a_full_remesh_and_closed(
        v in random_volume(),
        path in random_path(),
        r in 0.3..4.5f64,
        add in any::<bool>(),
    ) {
        let mut s = sculptor(&v, r, add, 1.0);
        for p in &path {
            s.step(*p).expect("step");
        }
        // Incremental mesh == global Marching Cubes of the final store.
        let full = mc::marching_cubes(&s.store).triangles;
        let inc = s.mesh.triangles();
        prop_assert_eq!(sorted(&inc), sorted(&full));
        // The store holds the dense model's volume, cell for cell.
        let side = s.store.side();
        let want = OptimizedOctree::from_volume(&dense_model(&v, &path, r, add, v.dims), BUDGET)
            .expect("reference store");
        for z in 0..side as u32 {
            for y in 0..side as u32 {
                for x in 0..side as u32 {
                    prop_assert_eq!(s.store.cell(x, y, z), want.cell(x, y, z), "cell {:?}", (x, y, z));
                }
            }
        }
        prop_assert_eq!(sorted(&inc), sorted(&mc::marching_cubes(&want).triangles));
        // Watertight: every edge in exactly two triangles.
        prop_assert_eq!(mesh::open_edges(&inc), 0);
    }
}

/// A 3×3×3 block of voxels 1..=3 in an 8³ grid.
fn block() -> Volume {
    volume([8, 8, 8], |x, y, z| {
        [x, y, z].iter().all(|&c| (1..=3).contains(&c))
    })
}

#[test]
fn a_unit_tool_at_the_block_centre_removes_a_plus_and_rewrites_32_cells() {
    let mut s = sculptor(&block(), 1.0, false, 2.0);
    let before = s.store.node_count();
    let a = s.step(DVec3::new(2.0, 2.0, 2.0)).unwrap();
    // Centres within 1 of (2, 2, 2): the centre and its 6 face neighbours, all filled.
    assert!(a.contact);
    assert_eq!(a.voxels, 7);
    // Cells having one of them as a corner: the centre's 2×2×2 cells, plus 4 more per arm.
    assert_eq!(a.cells, 8 + 6 * 4);
    // The path starts in contact: P_s is the first HIP, no force yet.
    assert_eq!(a.force, [0.0; 3]);
    assert_eq!(a.nodes_added, (s.store.node_count() - before) as u64);
    // One voxel along +x: (3, 2, 2) is gone, (4, 2, 2) was never filled, the other four
    // neighbours (3, 2±1, 2), (3, 2, 2±1) are still there.
    let b = s.step(DVec3::new(3.0, 2.0, 2.0)).unwrap();
    assert!(b.contact);
    assert_eq!(b.voxels, 4);
    // ΔX = P_s − P_c = (2, 2, 2) − (3, 2, 2); F = 2·ΔX.
    assert_eq!(b.displacement, [-1.0, 0.0, 0.0]);
    assert_eq!(b.force, [-2.0, 0.0, 0.0]);
    // Far away: no contact, no force, and the contact is over.
    let c = s.step(DVec3::new(6.5, 6.5, 6.5)).unwrap();
    assert!(!c.contact);
    assert_eq!((c.voxels, c.cells, c.force), (0, 0, [0.0; 3]));
}

#[test]
fn contact_starts_at_the_last_free_position() {
    // A slab of voxels x = 4..=5 in a 16³ grid; the tool (r = 1) comes in along +x.
    let v = volume([16, 16, 16], |x, y, z| {
        (4..=5).contains(&x) && y < 14 && z < 14
    });
    let mut s = sculptor(&v, 1.0, false, 10.0);
    let free = s.step(DVec3::new(2.5, 7.0, 7.0)).unwrap();
    assert!(!free.contact);
    let touch = s.step(DVec3::new(3.25, 7.0, 7.0)).unwrap();
    assert!(touch.contact);
    // P_s = (2.5, 7, 7), P_c = (3.25, 7, 7): ΔX = (−0.75, 0, 0), F = 10·ΔX.
    assert_eq!(touch.displacement, [-0.75, 0.0, 0.0]);
    assert_eq!(touch.force, [-7.5, 0.0, 0.0]);
    let deeper = s.step(DVec3::new(4.0, 7.0, 7.0)).unwrap();
    assert!(deeper.contact);
    assert_eq!(deeper.force, [-15.0, 0.0, 0.0]);
}

#[test]
fn carving_every_voxel_but_one_leaves_an_octahedron() {
    // A 2×2×2 block at 2..=3; unit tools at (3, 3, 3) (taking it and its 3 face
    // neighbours), then (2, 2, 4), (2, 4, 2), (4, 2, 2) (one voxel each, 2 from (2, 2, 2)).
    let v = volume([8, 8, 8], |x, y, z| {
        [x, y, z].iter().all(|&c| (2..=3).contains(&c))
    });
    let mut s = sculptor(&v, 1.0, false, 1.0);
    let mut removed = 0;
    for p in [
        [3.0, 3.0, 3.0],
        [2.0, 2.0, 4.0],
        [2.0, 4.0, 2.0],
        [4.0, 2.0, 2.0],
    ] {
        removed += s.step(DVec3::from_array(p)).unwrap().voxels;
    }
    assert_eq!(removed, 7);
    let filled: Vec<_> = (0..8u32)
        .flat_map(|z| (0..8u32).flat_map(move |y| (0..8u32).map(move |x| [x, y, z])))
        .filter(|p| s.store.get(p[0], p[1], p[2]))
        .collect();
    assert_eq!(filled, vec![[2, 2, 2]]);
    assert_eq!(s.mesh.len(), 8);
    assert_eq!(mesh::open_edges(&s.mesh.triangles()), 0);
}

#[test]
fn splitting_adds_seven_nodes_per_level() {
    // A full 8³ grid but its far layer: voxels 0..=6 filled. Cell (3, 3, 3) lies in the
    // interior, under coarse leaves; one voxel's removal rewrites 8 cells.
    let v = volume([8, 8, 8], |x, y, z| x < 7 && y < 7 && z < 7);
    let mut s = sculptor(&v, 0.4, false, 1.0);
    let before = s.store.node_count();
    let st = s.step(DVec3::new(3.0, 3.0, 3.0)).unwrap();
    assert_eq!((st.voxels, st.cells), (1, 8));
    // Every level-1 node touches the mixed outer cell layers (cells 0 and 7), so it is
    // internal; the level-2 nodes covering cells 2..=3 or 4..=5 on every axis are all 255,
    // homogeneous leaves. Cells 3..=4 on every axis lie in 8 of those, each split once
    // into its 8 cells: 8 · (8 − 1) = 56 nodes more.
    let added = s.store.node_count() - before;
    assert_eq!(added, 56);
    assert_eq!(st.nodes_added, 56);
}

#[test]
fn a_path_outside_the_grid_touches_nothing() {
    let mut s = sculptor(&block(), 3.0, true, 1.0);
    let tris = s.mesh.len();
    for p in [[-50.0, 2.0, 2.0], [2.0, 1e12, 2.0], [2.0, 2.0, -1e300]] {
        let st = s.step(DVec3::from_array(p)).unwrap();
        assert_eq!((st.contact, st.voxels, st.cells), (false, 0, 0));
    }
    assert_eq!(s.mesh.len(), tris);
}

#[test]
fn paths_parse_with_a_header_and_report_line_and_column() {
    let p = parse_path("x,y,z\n1,2,3\n\n# note\n 4 , 5,6.5\n", "p.csv").unwrap();
    assert_eq!(
        p,
        vec![DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 5.0, 6.5)]
    );
    assert_eq!(
        parse_path("x,y,z\n1,2,3\n1, b,3\n", "p.csv")
            .unwrap_err()
            .to_string(),
        "p.csv:3:4: \"b\" is not a number"
    );
    assert_eq!(
        parse_path("1,2,3,4\n", "p.csv").unwrap_err().to_string(),
        "p.csv:1:7: expected 3 fields x,y,z, found 4"
    );
    assert_eq!(
        parse_path("1,2\n", "p.csv").unwrap_err().to_string(),
        "p.csv:1:4: expected 3 fields x,y,z, found 2"
    );
    assert_eq!(
        parse_path("1,2,3\nx,y,z\n", "p.csv")
            .unwrap_err()
            .to_string(),
        "p.csv:2:1: \"x\" is not a number"
    );
    assert_eq!(
        parse_path("1,inf,3\n", "p.csv").unwrap_err().to_string(),
        "p.csv:1:3: \"inf\" is not a finite number"
    );
    assert_eq!(
        parse_path("x,y,z\n", "p.csv").unwrap_err().to_string(),
        "p.csv: no tool positions: give one row x,y,z per step"
    );
}

#[test]
fn tools_outside_0_to_128_voxels_are_refused() {
    assert_eq!(parse_tool("sphere:4"), Ok(4.0));
    assert_eq!(parse_tool("sphere:0.5"), Ok(0.5));
    for bad in [
        "sphere:0",
        "sphere:-1",
        "sphere:1e9",
        "sphere:nan",
        "cube:3",
        "sphere:",
    ] {
        assert!(parse_tool(bad).is_err(), "{bad}");
    }
}

fn tetra() -> Vec<Tri> {
    let (a, b, c, d) = (
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    );
    vec![[a, c, b], [a, b, d], [a, d, c], [b, c, d]]
}

#[test]
fn mesh_files_hold_what_was_given() {
    let t = tetra();
    assert_eq!(mesh::open_edges(&t), 0);
    assert_eq!(mesh::open_edges(&t[..1]), 3);
    let mut stl = Vec::new();
    mesh::write_stl(&mut stl, &t, "solid test").unwrap();
    assert_eq!(stl.len(), 84 + 50 * 4);
    assert_eq!(&stl[80..84], &4u32.to_le_bytes());
    assert!(!stl.starts_with(b"solid"));
    // First facet: normal of (a, c, b) is −z.
    let f = |i: usize| f32::from_le_bytes(stl[84 + 4 * i..88 + 4 * i].try_into().unwrap());
    assert_eq!([f(0), f(1), f(2)], [0.0, 0.0, -1.0]);
    let mut obj = Vec::new();
    mesh::write_obj(&mut obj, &t, "c").unwrap();
    let obj = String::from_utf8(obj).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), 4);
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), 4);
    assert!(obj.contains("f 1 2 3\n"), "{obj}");
    let mut ply = Vec::new();
    mesh::write_ply(&mut ply, &t, "c").unwrap();
    let head = String::from_utf8_lossy(&ply[..200]).to_string();
    assert!(head.contains("element vertex 4\n") && head.contains("element face 4\n"));
    let end = head.find("end_header\n").unwrap() + "end_header\n".len();
    assert_eq!(ply.len(), end + 4 * 12 + 4 * 13);
}

#[test]
fn the_example_sculpt_writes_a_closed_mesh_and_forces() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("carved.obj");
    let forces = dir.path().join("f.csv");
    let o = common::csgpix(&[
        "sculpt",
        "vectors/scenes/twelve.csg",
        "--res",
        "64x64x64",
        // Room around the scene (it reaches ±14 in z), so that the tool reaches round it.
        "--bounds=-15,-15,-15,15,15,15",
        "--tool",
        "sphere:3",
        "--path",
        "vectors/paths/carve.csv",
        "--json",
        "--forces",
        forces.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(r["contact_steps"].as_u64().unwrap() > 0, "{r}");
    assert!(r["voxels_changed"].as_u64().unwrap() > 0, "{r}");
    let obj = std::fs::read_to_string(&out).unwrap();
    let faces = obj.lines().filter(|l| l.starts_with("f ")).count();
    assert_eq!(faces as u64, r["triangles_after"].as_u64().unwrap());
    // Closed in the file: every undirected edge of the indexed faces in exactly two faces.
    let mut uses: HashMap<(u32, u32), u32> = HashMap::new();
    for l in obj.lines().filter(|l| l.starts_with("f ")) {
        let f: Vec<u32> = l[2..].split(' ').map(|i| i.parse().unwrap()).collect();
        for i in 0..3 {
            let (a, b) = (f[i], f[(i + 1) % 3]);
            *uses.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    assert!(uses.values().all(|&n| n == 2));
    assert_eq!(r["open_edges"], 0);
    let csv = std::fs::read_to_string(&forces).unwrap();
    let path_rows = std::fs::read_to_string("vectors/paths/carve.csv")
        .unwrap()
        .lines()
        .filter(|l| l.starts_with(|c: char| c == '-' || c.is_ascii_digit()))
        .count();
    assert_eq!(csv.lines().count(), path_rows + 1);
    assert!(csv.starts_with("step,x,y,z,contact,"));
}

#[test]
fn bad_input_is_one_line_exit_2_and_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "x,y,z\n1,2,oops\n").unwrap();
    let out = dir.path().join("o.stl");
    let run = |tool: &str, path: &str, o: &str| {
        common::csgpix(&[
            "sculpt",
            "vectors/scenes/twelve.csg",
            "--res",
            "16x16x16",
            "--tool",
            tool,
            "--path",
            path,
            "-o",
            o,
        ])
    };
    let bad_s = bad.to_str().unwrap();
    let out_s = out.to_str().unwrap();
    let cases = [
        run("sphere:2", bad_s, out_s),
        run("sphere:0", "vectors/paths/carve.csv", out_s),
        run("sphere:1e40", "vectors/paths/carve.csv", out_s),
        run("sphere:2", "no/such.csv", out_s),
        run("sphere:2", "vectors/paths/carve.csv", "o.txt"),
    ];
    for o in &cases {
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(!out.exists());
    }
    let err = String::from_utf8_lossy(&cases[0].stderr);
    assert!(
        err.contains("bad.csv:2:5: \"oops\" is not a number"),
        "{err}"
    );
}
