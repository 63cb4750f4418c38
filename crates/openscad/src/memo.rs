//! The meshes of the booleans a scene read has already evaluated ([`crate::geom::mesh_of`]),
//! found again for the same subtree turned by a quarter turn or a mirror of the axes.
//!
//! A design often takes the same difference or intersection more than once under
//! `projection()`, `hull()`, `minkowski()` or `resize()`, each copy turned a different way
//! (openscad-geb projects its letter intersection from three sides). The reader applies a
//! transform to the leaves as it reads them, but a matrix whose entries are 0 and ±1 with no
//! translation only moves and negates coordinates, exactly: such a copy's leaves are the
//! first's with every vertex turned by the same signed permutation of the axes, and its
//! solid is the first's turned the same way. Its mesh is then the first's turned (a mirror
//! reverses each triangle's winding, so it stays outward), with no boolean taken again.

use glam::DVec3;

use crate::clip::{convex_intersection, Clipped};
use crate::geom::{leaf_mesh, mesh_of, Mesh, Polytope};
use csgpix_scene::solid::{ConvexSolid, CsgNode, Import, IMPORTED};

/// Most points the memo holds (the leaves' and the results' together, 24 bytes each): past
/// it no more are kept, and later subtrees are evaluated as they come.
const HELD: usize = 1 << 20;

/// A signed permutation of the axes: coordinate k of the image is `sign[k]` times coordinate
/// `perm[k]` of the point.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Turn {
    perm: [usize; 3],
    sign: [f64; 3],
}

impl Turn {
    const IDENTITY: Turn = Turn {
        perm: [0, 1, 2],
        sign: [1.0; 3],
    };

    /// The 48 turns and mirrors of the axes, the identity first.
    fn all() -> impl Iterator<Item = Turn> {
        const PERMS: [[usize; 3]; 6] = [
            [0, 1, 2],
            [0, 2, 1],
            [1, 0, 2],
            [1, 2, 0],
            [2, 0, 1],
            [2, 1, 0],
        ];
        PERMS.into_iter().flat_map(|perm| {
            (0..8).map(move |s: u32| Turn {
                perm,
                sign: [0, 1, 2].map(|k| if s >> k & 1 == 0 { 1.0 } else { -1.0 }),
            })
        })
    }

    fn apply(&self, v: DVec3) -> DVec3 {
        DVec3::new(
            self.sign[0] * v[self.perm[0]],
            self.sign[1] * v[self.perm[1]],
            self.sign[2] * v[self.perm[2]],
        )
    }

    /// Whether it reverses orientation (its determinant is −1).
    fn mirrors(&self) -> bool {
        let odd = [[0, 2, 1], [1, 0, 2], [2, 1, 0]].contains(&self.perm);
        let negative = self.sign.iter().filter(|&&s| s < 0.0).count() % 2 == 1;
        odd != negative
    }

    /// Mesh `m` turned, its triangles still outward.
    fn mesh(&self, m: &Mesh) -> Mesh {
        let flip = self.mirrors();
        m.iter()
            .map(|t| {
                let [a, b, c] = t.map(|v| self.apply(v));
                match flip {
                    true => [a, c, b],
                    false => [a, b, c],
                }
            })
            .collect()
    }
}

/// A leaf's geometry, for matching: a convex solid by its corners (they fix it, however
/// its faces were listed), a mesh by its triangles.
#[derive(Clone, Debug, PartialEq)]
enum Leaf {
    Corners(Vec<DVec3>),
    Triangles(Mesh),
}

/// A point's bits, −0 taken as +0.
fn bits(v: DVec3) -> [u64; 3] {
    (v + DVec3::ZERO).to_array().map(f64::to_bits)
}

impl Leaf {
    fn of(i: usize, solids: &[ConvexSolid], imports: &[Import]) -> csgpix_scene::Result<Leaf> {
        match solids.get(i) {
            Some(s) if i < IMPORTED => Ok(Leaf::Corners(
                s.vertices.iter().map(|&v| DVec3::from(v)).collect(),
            )),
            _ => Ok(Leaf::Triangles(leaf_mesh(i, solids, imports)?)),
        }
    }

    fn points(&self) -> usize {
        match self {
            Leaf::Corners(v) => v.len(),
            Leaf::Triangles(m) => 3 * m.len(),
        }
    }

    /// The leaf turned by `t`, in a form two leaves of the same geometry share: the corners
    /// in order of their bits, or each triangle from its least corner (wound outward) and
    /// the triangles in order.
    fn canonical(&self, t: Turn) -> Vec<[u64; 3]> {
        match self {
            Leaf::Corners(v) => {
                let mut c: Vec<[u64; 3]> = v.iter().map(|&p| bits(t.apply(p))).collect();
                c.sort_unstable();
                c
            }
            Leaf::Triangles(m) => {
                let mut tris: Vec<[[u64; 3]; 3]> = (t.mesh(m).iter())
                    .map(|tri| {
                        let b = tri.map(bits);
                        let k = (0..3).min_by_key(|&k| b[k]).unwrap_or(0);
                        [b[k], b[(k + 1) % 3], b[(k + 2) % 3]]
                    })
                    .collect();
                tris.sort_unstable();
                tris.into_iter().flatten().collect()
            }
        }
    }

    /// The bounding box of the leaf turned by `t`.
    fn bounds(&self, t: Turn) -> (DVec3, DVec3) {
        let pts: Box<dyn Iterator<Item = &DVec3>> = match self {
            Leaf::Corners(v) => Box::new(v.iter()),
            Leaf::Triangles(m) => Box::new(m.iter().flatten()),
        };
        pts.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), &p| {
            let q = t.apply(p);
            (a.min(q), b.max(q))
        })
    }
}

/// A subtree evaluated: its leaves and its mesh.
struct Seen {
    leaves: Vec<Leaf>,
    mesh: Mesh,
}

/// What a subtree shares with every turn of it, so that only those subtrees are compared:
/// its shape (node kinds and child counts, in pre-order) and per leaf its kind, its points
/// and its box's three sides in order (a turn permutes them, exactly).
fn signature(shape: &[u32], leaves: &[Leaf]) -> Vec<u64> {
    let mut key: Vec<u64> = shape.iter().map(|&k| u64::from(k)).collect();
    for l in leaves {
        let (lo, hi) = l.bounds(Turn::IDENTITY);
        let mut sides = bits(hi - lo);
        sides.sort_unstable();
        key.extend([u64::from(matches!(l, Leaf::Corners(_))), l.points() as u64]);
        key.extend(sides);
    }
    key
}

/// The leaves of a subtree looked up, with their boxes and (once a turn's boxes agree)
/// their canonical forms, each made once however many subtrees and turns are tried.
struct Asked<'a> {
    leaves: &'a [Leaf],
    boxes: Vec<(DVec3, DVec3)>,
    canonical: std::cell::OnceCell<Vec<Vec<[u64; 3]>>>,
}

impl<'a> Asked<'a> {
    fn of(leaves: &'a [Leaf]) -> Self {
        Asked {
            leaves,
            boxes: leaves.iter().map(|l| l.bounds(Turn::IDENTITY)).collect(),
            canonical: std::cell::OnceCell::new(),
        }
    }

    fn canonical(&self) -> &[Vec<[u64; 3]>] {
        self.canonical.get_or_init(|| {
            (self.leaves.iter())
                .map(|l| l.canonical(Turn::IDENTITY))
                .collect()
        })
    }
}

impl Seen {
    /// The turn taking this subtree's leaves to the asked ones, if one does: the turns whose
    /// boxes agree tried in full.
    fn turn_to(&self, asked: &Asked) -> Option<Turn> {
        let same_boxes =
            |t: &Turn| (self.leaves.iter().zip(&asked.boxes)).all(|(a, b)| a.bounds(*t) == *b);
        Turn::all().filter(same_boxes).find(|&t| {
            (self.leaves.iter().zip(asked.canonical())).all(|(a, b)| a.canonical(t) == *b)
        })
    }

    fn points(&self) -> usize {
        3 * self.mesh.len() + self.leaves.iter().map(Leaf::points).sum::<usize>()
    }
}

/// A subtree's solid ([`MeshMemo::solid_of`]).
pub(crate) enum Solid {
    Convex(Polytope),
    Mesh(Mesh),
}

/// The meshes of the subtrees evaluated while a scene is read.
#[derive(Default)]
pub(crate) struct MeshMemo {
    /// By [`signature`].
    seen: std::collections::HashMap<Vec<u64>, Vec<Seen>>,
    held: usize,
}

impl MeshMemo {
    /// The bytes its points hold ([`csgpix_scene::solid::CsgScene::reading_bytes`]).
    pub(crate) fn bytes(&self) -> u64 {
        (self.held as u64).saturating_mul(std::mem::size_of::<DVec3>() as u64)
    }

    /// [`mesh_of`] of `node`, or the mesh of a subtree evaluated before that `node` is a turn
    /// or mirror of, turned.
    pub(crate) fn mesh_of(
        &mut self,
        node: &CsgNode,
        solids: &[ConvexSolid],
        imports: &[Import],
    ) -> csgpix_scene::Result<Mesh> {
        let Some((shape, leaf_ids)) = shape(node) else {
            return mesh_of(node, solids, imports);
        };
        let leaves = (leaf_ids.iter())
            .map(|&i| Leaf::of(i, solids, imports))
            .collect::<csgpix_scene::Result<Vec<Leaf>>>()?;
        let key = signature(&shape, &leaves);
        let asked = Asked::of(&leaves);
        let mut alike = self.seen.get(&key).into_iter().flatten();
        if let Some((s, t)) = alike.find_map(|s| Some((s, s.turn_to(&asked)?))) {
            return Ok(t.mesh(&s.mesh));
        }
        let mesh = mesh_of(node, solids, imports)?;
        let seen = Seen { leaves, mesh };
        if self.held + seen.points() > HELD {
            return Ok(seen.mesh);
        }
        self.held += seen.points();
        let mesh = seen.mesh.clone();
        self.seen.entry(key).or_default().push(seen);
        Ok(mesh)
    }

    /// The solid of a difference or intersection `node`: an intersection of convex solids
    /// clipped into one polytope ([`convex_intersection`]), anything else its mesh (empty for
    /// nothing), through the memo.
    pub(crate) fn solid_of(
        &mut self,
        node: &CsgNode,
        solids: &[ConvexSolid],
        imports: &[Import],
    ) -> csgpix_scene::Result<Solid> {
        Ok(match convex_intersection(node, solids) {
            Clipped::Convex(p) => Solid::Convex(p),
            Clipped::Empty => Solid::Mesh(vec![]),
            Clipped::NotConvex => Solid::Mesh(self.mesh_of(node, solids, imports)?),
        })
    }

    /// How many subtrees it holds.
    #[cfg(test)]
    fn taken(&self) -> usize {
        self.seen.values().map(Vec::len).sum()
    }
}

/// The node kinds and child counts of `node` in pre-order, and its leaves in that order;
/// None for a tree with a complement (which [`mesh_of`] refuses).
fn shape(node: &CsgNode) -> Option<(Vec<u32>, Vec<usize>)> {
    let (mut shape, mut leaves) = (vec![], vec![]);
    let mut stack = vec![node];
    while let Some(n) = stack.pop() {
        let kind = match n {
            CsgNode::Empty => 0,
            CsgNode::Solid(i) => {
                leaves.push(*i);
                1
            }
            CsgNode::Union(_) => 2,
            CsgNode::Intersection(_) => 3,
            CsgNode::Difference(_) => 4,
            CsgNode::Complement(_) => return None,
        };
        shape.extend([kind, n.children().len() as u32]);
        stack.extend(n.children().iter().rev());
    }
    Some((shape, leaves))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DMat3;

    fn volume(m: &Mesh) -> f64 {
        m.iter().map(|t| t[0].dot(t[1].cross(t[2]))).sum::<f64>() / 6.0
    }

    /// The turn as a matrix (column j the image of axis j).
    fn matrix(t: Turn) -> DMat3 {
        DMat3::from_cols(t.apply(DVec3::X), t.apply(DVec3::Y), t.apply(DVec3::Z))
    }

    #[test]
    fn the_turns_are_the_48_signed_permutations_and_mirrors_are_those_of_determinant_minus_one() {
        let all: Vec<Turn> = Turn::all().collect();
        assert_eq!(all.len(), 48);
        let v = DVec3::new(1.0, 2.0, 3.0);
        for (i, a) in all.iter().enumerate() {
            assert!(all[..i].iter().all(|b| b.apply(v) != a.apply(v)));
            let m = matrix(*a);
            assert_eq!(m * v, a.apply(v));
            assert_eq!(a.mirrors(), m.determinant() < 0.0, "{a:?}");
        }
        assert_eq!(all[0].apply(v), v);
    }

    /// A difference as the reader makes it, under each of `turns` (matrices written into the
    /// scene, as a design would), the memo asked for each in turn.
    /// Also how many booleans the memo took (the others found turned).
    fn turned_copies(turns: &[&str]) -> (Vec<Mesh>, Vec<Mesh>, usize) {
        let part = "difference() { cube(size = [4, 3, 2]); \
                    multmatrix([[1,0,0,1],[0,1,0,1],[0,0,1,-1],[0,0,0,1]]) cylinder(r = 0.8, h = 4, $fn = 12); }";
        let src: String = turns
            .iter()
            .map(|m| format!("multmatrix({m}) {part}\n"))
            .collect();
        let s = crate::parse_csg(&src, "t.csg").unwrap();
        let CsgNode::Union(copies) = &s.root else {
            panic!("{:?}", s.root);
        };
        let mut memo = MeshMemo::default();
        let remembered = (copies.iter())
            .map(|c| memo.mesh_of(c, &s.solids, &s.imports).unwrap())
            .collect();
        let direct = (copies.iter())
            .map(|c| mesh_of(c, &s.solids, &s.imports).unwrap())
            .collect();
        (remembered, direct, memo.taken())
    }

    #[test]
    fn a_turned_or_mirrored_copy_is_the_first_mesh_turned_and_the_same_solid() {
        let turns = [
            "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]",
            "[[0,0,1,0],[1,0,0,0],[0,1,0,0],[0,0,0,1]]", // a turn of the axes
            "[[-1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]", // a mirror
            "[[1,0,0,0],[0,0,-1,0],[0,1,0,0],[0,0,0,1]]", // a quarter turn about x
        ];
        let (remembered, direct, taken) = turned_copies(&turns);
        assert_eq!(taken, 1, "the copies were evaluated again");
        let first = &direct[0];
        assert!(volume(first) > 20.0, "{}", volume(first));
        for (k, (r, d)) in remembered.iter().zip(&direct).enumerate() {
            // Outward and of the boolean's volume.
            assert!((volume(r) - volume(d)).abs() < 1e-9 * volume(d), "copy {k}");
            // The first mesh turned: the same corners as the copy's own boolean.
            let key = |m: &Mesh| {
                let mut v: Vec<[u64; 3]> = (m.iter().flatten())
                    .map(|p| (*p + DVec3::ZERO).to_array().map(f64::to_bits))
                    .collect();
                v.sort_unstable();
                v.dedup();
                v
            };
            assert_eq!(key(r), key(d), "copy {k}");
        }
        // The first copy is the boolean itself.
        assert_eq!(&remembered[0], first);
    }

    #[test]
    fn a_moved_or_scaled_copy_is_evaluated_again() {
        let turns = [
            "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]",
            "[[1,0,0,0.5],[0,1,0,0],[0,0,1,0],[0,0,0,1]]",
            "[[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]",
            "[[0.6,-0.8,0,0],[0.8,0.6,0,0],[0,0,1,0],[0,0,0,1]]",
        ];
        let (remembered, direct, taken) = turned_copies(&turns);
        assert_eq!(taken, 4);
        assert_eq!(remembered, direct);
    }
}
