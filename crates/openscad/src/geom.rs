//! The boundary mesh of a CSG subtree.
//!
//! STUB, to be replaced at merge by the mesh boolean written on branch `geom` (the `boolmesh`
//! crate): keep the signature of [`mesh_of`]. This version handles only what needs no mesh
//! boolean: a convex solid, a closed-mesh primitive, and a union of them (whose triangles it
//! returns together: right for a bounding box or a shadow, not a boundary where they overlap).
//! A difference or intersection is an error.

use glam::DVec3;

use csgpix_scene::solid::{ConvexSolid, CsgNode, Import, IMPORTED};

/// The triangles bounding `node`'s solid. A leaf `Solid(i)` is `solids[i]` below
/// [`IMPORTED`] and `imports[i - IMPORTED]` above it (the reader's numbering while it reads);
/// a leaf from `solids.len()` up to [`IMPORTED`] is `imports[i - solids.len()]` (a finished
/// scene's numbering).
///
/// # Errors
///
/// A file import (its mesh is loaded only when voxelizing), and, in this stub, a difference
/// or intersection.
pub fn mesh_of(
    node: &CsgNode,
    solids: &[ConvexSolid],
    imports: &[Import],
) -> Result<Vec<[DVec3; 3]>, String> {
    let mut out = vec![];
    let mut stack = vec![node];
    while let Some(n) = stack.pop() {
        match n {
            CsgNode::Empty => {}
            CsgNode::Union(c) => stack.extend(c.iter()),
            CsgNode::Solid(i) => leaf_triangles(*i, solids, imports, &mut out)?,
            _ => {
                return Err(
                    "the shape of a difference or intersection needs the mesh boolean, which this csgpix build lacks"
                        .into(),
                )
            }
        }
    }
    Ok(out)
}

fn leaf_triangles(
    i: usize,
    solids: &[ConvexSolid],
    imports: &[Import],
    out: &mut Vec<[DVec3; 3]>,
) -> Result<(), String> {
    if i < solids.len() {
        let s = &solids[i];
        let v = |k: usize| DVec3::from(s.vertices[k]);
        for f in &s.faces {
            for k in 1..f.len().saturating_sub(1) {
                out.push([v(f[0]), v(f[k]), v(f[k + 1])]);
            }
        }
        return Ok(());
    }
    let j = if i >= IMPORTED {
        i - IMPORTED
    } else {
        i - solids.len()
    };
    let Some(import) = imports.get(j) else {
        return Err(format!("internal: no primitive {i}"));
    };
    let Some(mesh) = &import.mesh else {
        return Err(format!(
            "the shape of `import(\"{}\")` is not known until csgpix loads it to voxelize",
            import.file
        ));
    };
    out.extend(mesh.iter().map(|t| t.map(DVec3::from)));
    Ok(())
}
