//! The tests every [`VoxelStore`] passes, whatever its layout: [`voxel_store_suite!`] writes
//! them out once per store, in the store's own module, so that a store added later gets them
//! by one line and a broken one fails under its own name.
//!
//! The reference is the volume itself: every cell's byte computed straight from the voxels
//! ([`cell_of`], seed 000 §3.1.1.5), which is what the dense grid stores, and the Marching
//! Cubes triangles of those cells. Node counts follow each kind's own invariant (Table 7.1:
//! 8·I + 1 nodes with child pointers, 7·I + 1 leaves for the optimized octree, I the internal
//! nodes), which the leaves the store reports must give.

use std::collections::{BTreeSet, HashMap};

use super::cell::cell_of;
use super::key::{self, Key};
use super::mc::{self, Tri};
use super::{from_volume, StoreKind, VoxelStore};
use csgpix_scene::grid::Volume;
use proptest::prelude::*;

/// The shared tests of a [`VoxelStore`] as a module `$name`, for the store of kind `$kind`
/// (built by [`from_volume`], slice by slice, as every caller builds it).
macro_rules! voxel_store_suite {
    ($name:ident, $kind:expr) => {
        mod $name {
            use proptest::prelude::*;
            use $crate::octree::suite;

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(64))]

                /// Cells, voxels, leaves, counts, the surface and its mesh, on random volumes.
                #[test]
                fn random_volumes_read_back(v in suite::random_volume()) {
                    suite::check_volume($kind, &v);
                }
            }

            #[test]
            fn empty_full_and_flat_volumes() {
                suite::check_edge_volumes($kind);
            }

            #[test]
            fn the_thesis_examples_in_cell_1_1_1() {
                suite::check_thesis_examples($kind);
            }

            #[test]
            fn a_lone_voxel_gives_an_octahedron_facing_out() {
                suite::check_lone_voxel($kind);
            }
        }
    };
}
pub(crate) use voxel_store_suite;

/// Enough for any test volume.
const BUDGET: u64 = 1 << 30;

/// A volume from a voxel predicate (1 inside, 0 outside; X fastest).
pub(crate) fn volume(dims: [usize; 3], f: impl Fn(usize, usize, usize) -> bool) -> Volume {
    let mut voxels = Vec::with_capacity(dims.iter().product());
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                voxels.push(u8::from(f(x, y, z)));
            }
        }
    }
    Volume { dims, voxels }
}

/// A volume of a few random boxes (so that octants merge) and random single voxels.
pub(crate) fn random_volume() -> impl Strategy<Value = Volume> {
    let dims = [1usize..=19, 1usize..=19, 1usize..=19];
    let boxes = prop::collection::vec(
        ([0usize..19, 0..19, 0..19], [1usize..12, 1..12, 1..12]),
        0..4,
    );
    let dots = prop::collection::vec([0usize..19, 0..19, 0..19], 0..30);
    (dims, boxes, dots).prop_map(|(dims, boxes, dots)| {
        volume(dims, |x, y, z| {
            let p = [x, y, z];
            boxes
                .iter()
                .any(|(o, s)| (0..3).all(|a| p[a] >= o[a] && p[a] < o[a] + s[a]))
                || dots.contains(&p)
        })
    })
}

/// Is voxel (x, y, z) of `v` filled (false outside the volume)?
fn filled(v: &Volume, x: i64, y: i64, z: i64) -> bool {
    let [nx, ny, nz] = v.dims.map(|d| d as i64);
    (0..nx).contains(&x)
        && (0..ny).contains(&y)
        && (0..nz).contains(&z)
        && v.voxels[((z * ny + y) * nx + x) as usize] != 0
}

/// The store of `kind` over `v`.
fn store(kind: StoreKind, v: &Volume) -> Box<dyn VoxelStore> {
    let s = from_volume(kind, v, BUDGET).unwrap();
    assert_eq!(s.kind(), kind);
    s
}

/// Every check of the suite on the store of `kind` over `v`.
pub(crate) fn check_volume(kind: StoreKind, v: &Volume) {
    let s = store(kind, v);
    check_cells(s.as_ref(), v);
    check_leaves(s.as_ref());
    check_surface(s.as_ref(), v);
}

/// The grid is the next power of two of the largest side; every cell is the one computed
/// from the volume, every voxel its cell's bit 6, and past the grid there is nothing.
fn check_cells(s: &dyn VoxelStore, v: &Volume) {
    let largest = v.dims.iter().copied().max().unwrap_or(1).max(1);
    assert_eq!(s.side(), largest.next_power_of_two(), "side");
    assert_eq!(s.side(), 1 << s.depth(), "depth");
    let side = s.side() as i64;
    for z in 0..side {
        for y in 0..side {
            for x in 0..side {
                let want = cell_of(|i, j, k| filled(v, i, j, k), x, y, z);
                let (a, b, c) = (x as u32, y as u32, z as u32);
                assert_eq!(s.cell(a, b, c), want, "cell ({x},{y},{z})");
                assert_eq!(s.get(a, b, c), filled(v, x, y, z), "voxel ({x},{y},{z})");
            }
        }
    }
    let n = side as u32;
    for p in [[n, 0, 0], [0, n, 0], [0, 0, n], [n, n, n], [u32::MAX, 0, 0]] {
        assert_eq!(s.cell(p[0], p[1], p[2]), 0, "outside the grid at {p:?}");
    }
}

/// The leaves tile the grid, each cell once; a leaf holds its cell's byte, or the 0 or 255
/// of every cell under it; an octree's leaves are merged as far as they go (no eight
/// sibling leaves of one 0 or 255); and the node counts follow from the leaves.
fn check_leaves(s: &dyn VoxelStore) {
    let depth = s.depth();
    let mut leaves: Vec<(Key, u8)> = vec![];
    s.for_each_leaf(&mut |k, v| leaves.push((k, v)));
    let mut covered = 0u64;
    let mut seen = BTreeSet::new();
    for &(k, val) in &leaves {
        assert!(seen.insert(k), "leaf {k:#o} twice");
        let (level, p) = key::coords(k);
        assert!(level <= depth, "leaf {k:#o} below the deepest level");
        let size = 1u32 << (depth - level);
        covered += u64::from(size).pow(3);
        if size > 1 {
            assert!(val == 0 || val == 255, "coarse leaf {k:#o} holds {val}");
            for c in [
                [0, 0, 0],
                [size - 1, size - 1, size - 1],
                [size / 2, 0, size - 1],
            ] {
                let q = [0, 1, 2].map(|a| p[a] * size + c[a]);
                assert_eq!(
                    s.cell(q[0], q[1], q[2]),
                    val,
                    "cell {q:?} under leaf {k:#o}"
                );
            }
        } else {
            assert_eq!(s.cell(p[0], p[1], p[2]), val, "leaf {k:#o}");
        }
    }
    assert_eq!(covered, (s.side() as u64).pow(3), "leaves tile the grid");
    let internal: BTreeSet<Key> = leaves
        .iter()
        .filter(|&&(k, _)| k != key::ROOT)
        .flat_map(|&(k, _)| {
            std::iter::successors(Some(key::parent(k)), |&p| {
                (p > key::ROOT).then(|| key::parent(p))
            })
        })
        .collect();
    let nodes = s.node_count();
    assert!(s.bytes() >= nodes, "{} bytes for {nodes} nodes", s.bytes());
    if s.kind() == StoreKind::Dense {
        assert_eq!((nodes, s.internal_count()), (leaves.len(), 0), "dense");
        return;
    }
    let mut by_parent: HashMap<Key, Vec<u8>> = HashMap::new();
    for &(k, val) in leaves.iter().filter(|&&(k, _)| k != key::ROOT) {
        by_parent.entry(key::parent(k)).or_default().push(val);
    }
    for (parent, vals) in &by_parent {
        let merged =
            vals.len() == 8 && (vals.iter().all(|&v| v == 0) || vals.iter().all(|&v| v == 255));
        assert!(!merged, "the children of {parent:#o} are one leaf");
    }
    assert_eq!(s.internal_count(), internal.len(), "internal nodes");
    let i = internal.len();
    match s.kind() {
        StoreKind::Octree => assert_eq!(nodes, 7 * i + 1, "7·I + 1 leaves"),
        _ => assert_eq!(nodes, 8 * i + 1, "8·I + 1 nodes"),
    }
    assert_eq!(leaves.len(), 7 * i + 1, "leaves of a full octree");
}

/// Triangles with doubled (integer) coordinates, each rotated to start at its least vertex,
/// sorted.
fn sorted(tris: &[Tri]) -> Vec<[[i32; 3]; 3]> {
    let mut t: Vec<[[i32; 3]; 3]> = tris
        .iter()
        .map(|t| {
            let t = t.map(|p| p.map(|c| (c * 2.0) as i32));
            let m = (0..3).min_by_key(|&i| t[i]).unwrap_or(0);
            [t[m], t[(m + 1) % 3], t[(m + 2) % 3]]
        })
        .collect();
    t.sort();
    t
}

/// The surface cells are the cells of the volume neither empty nor full, those just past the
/// grid's far faces included, each once; Marching Cubes gives their triangles, the same into
/// a reused vector, and the mesh is closed and consistently oriented.
fn check_surface(s: &dyn VoxelStore, v: &Volume) {
    let n = s.side() as i64;
    let mut want = vec![];
    for z in 0..=n {
        for y in 0..=n {
            for x in 0..=n {
                let b = cell_of(|i, j, k| filled(v, i, j, k), x, y, z);
                if b != 0 && b != 255 {
                    want.push(([x as u32, y as u32, z as u32], b));
                }
            }
        }
    }
    let mut got = vec![];
    s.for_each_surface_cell(&mut |p, b| got.push((p, b)));
    got.sort();
    want.sort();
    assert_eq!(got, want, "surface cells");

    let mut reference = vec![];
    for &(p, b) in &want {
        mc::cell_triangles(p, b, &mut reference);
    }
    let mesh = mc::marching_cubes(s).triangles;
    let mut reused = vec![[[9.0f32; 3]; 3]; 5];
    s.marching_cubes_into(&mut reused);
    assert_eq!(reused, mesh, "into a reused vector");
    let mesh = sorted(&mesh);
    assert_eq!(mesh, sorted(&reference), "the cells' triangles");
    let mut edges: HashMap<([i32; 3], [i32; 3]), i32> = HashMap::new();
    for t in &mesh {
        for i in 0..3 {
            *edges.entry((t[i], t[(i + 1) % 3])).or_default() += 1;
        }
    }
    for (&(a, b), &count) in &edges {
        assert_eq!(count, 1, "edge {a:?}->{b:?} used {count} times");
        assert_eq!(
            edges.get(&(b, a)),
            Some(&1),
            "edge {a:?}->{b:?} has no twin"
        );
    }
    assert_eq!(
        mesh.is_empty(),
        v.voxels.iter().all(|&c| c == 0),
        "a mesh iff a solid"
    );
}

/// Empty volumes, full ones (their surface only past the far faces and on the near ones),
/// one voxel, and flat or thin ones.
pub(crate) fn check_edge_volumes(kind: StoreKind) {
    for dims in [[1, 1, 1], [5, 3, 2], [16, 16, 16], [1, 19, 3], [17, 1, 1]] {
        check_volume(kind, &volume(dims, |_, _, _| false));
        check_volume(kind, &volume(dims, |_, _, _| true));
        check_volume(kind, &volume(dims, |x, y, z| (x + y + z) % 2 == 0));
    }
}

/// seed 000's examples: V1 = voxel (1,0,0), V4 = (0,1,0), V5 = (1,1,0), V7 = (0,1,1) of cell
/// (1,1,1) give 178; a lone voxel (1,1,1) is V6 of cell (1,1,1) (64) and V0 of cell (2,2,2)
/// (1); a full 4³ block inside 8³ fills cell (3,3,3) (255).
pub(crate) fn check_thesis_examples(kind: StoreKind) {
    let on = [[1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 1, 1]];
    let v = volume([4, 4, 4], |x, y, z| on.contains(&[x, y, z]));
    assert_eq!(store(kind, &v).cell(1, 1, 1), 178);
    let lone = volume([4, 4, 4], |x, y, z| [x, y, z] == [1, 1, 1]);
    let s = store(kind, &lone);
    assert_eq!(
        (s.cell(1, 1, 1), s.cell(2, 2, 2), s.cell(0, 0, 0)),
        (64, 1, 0)
    );
    let block = volume([8, 8, 8], |x, y, z| {
        [x, y, z].iter().all(|c| (1..5).contains(c))
    });
    assert_eq!(store(kind, &block).cell(3, 3, 3), 255);
}

/// A lone voxel: 8 triangles, every one facing away from the voxel.
pub(crate) fn check_lone_voxel(kind: StoreKind) {
    let v = volume([4, 4, 4], |x, y, z| [x, y, z] == [1, 1, 1]);
    check_volume(kind, &v);
    let mesh = mc::marching_cubes(store(kind, &v).as_ref());
    assert_eq!(mesh.triangles.len(), 8);
    for t in &mesh.triangles {
        let c = [0, 1, 2].map(|a| (t[0][a] + t[1][a] + t[2][a]) / 3.0 - 1.0);
        let (u, w) = (
            [0, 1, 2].map(|a| t[1][a] - t[0][a]),
            [0, 1, 2].map(|a| t[2][a] - t[0][a]),
        );
        let n = [
            u[1] * w[2] - u[2] * w[1],
            u[2] * w[0] - u[0] * w[2],
            u[0] * w[1] - u[1] * w[0],
        ];
        assert!(
            n[0] * c[0] + n[1] * c[1] + n[2] * c[2] > 0.0,
            "triangle {t:?} faces in"
        );
    }
}
