//! An operand of `minkowski()` as a union of pieces ([`crate::geom`]'s module documentation,
//! "Minkowski sums"): the convex ones as polytopes, the others as closed meshes.

use csgpix_scene::solid::{ConvexSolid, CsgNode, Import, IMPORTED};
use csgpix_scene::Error;

use crate::geom::{convex_hull_of, leaf_mesh, Mesh, Piece, Polytope};
use crate::memo::{MeshMemo, Solid};

/// An operand of `minkowski()` as a union of pieces: unions distributed, a convex solid as
/// itself, an intersection of convex solids as the polytope they bound
/// ([`crate::clip::convex_intersection`]), a closed mesh primitive as its triangles, any other difference
/// or intersection as its [`crate::geom::mesh_of`] (through the memo).
pub(crate) fn pieces(
    node: &CsgNode,
    solids: &[ConvexSolid],
    imports: &[Import],
    memo: &mut MeshMemo,
) -> csgpix_scene::Result<Vec<Piece>> {
    let mut out = vec![];
    let mut stack = vec![node];
    while let Some(n) = stack.pop() {
        match n {
            CsgNode::Empty => {}
            CsgNode::Union(c) => stack.extend(c.iter()),
            CsgNode::Solid(i) if *i < IMPORTED => {
                let s = solids.get(*i).ok_or(Error::NoPrimitive {
                    kind: "solid",
                    index: *i,
                })?;
                out.push(Piece::Convex(Polytope::of_solid(s)));
            }
            CsgNode::Solid(i) => out.push(mesh_piece(leaf_mesh(*i, solids, imports)?)),
            _ => match memo.solid_of(n, solids, imports)? {
                Solid::Convex(p) => out.push(Piece::Convex(p)),
                Solid::Mesh(m) if m.is_empty() => {}
                Solid::Mesh(m) => out.push(mesh_piece(m)),
            },
        }
    }
    Ok(out)
}

/// A closed mesh as a piece: convex by its hull's vertices when it is its own hull (a sphere
/// cut by a plane, a box with a chamfer), so that its sum with a convex piece is one hull
/// rather than one hull per triangle; else the mesh.
fn mesh_piece(m: Mesh) -> Piece {
    match convex_hull_of(&m) {
        Some(p) => Piece::Convex(p),
        None => Piece::Mesh(m),
    }
}
