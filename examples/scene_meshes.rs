//! A scene as meshes and a tree, for a mesh-boolean peer (`python/bench/manifold_peer.py`):
//! every primitive as a closed triangle mesh, the CSG tree over them, and the grid box
//! `csgpix voxelize` lays over the scene.
//!
//! `cargo run --release --example scene_meshes -- SCENE.csg`
//!
//! Prints one JSON object:
//!
//! ```text
//! {"primitives": [{"vertices": [[x,y,z],...], "triangles": [[a,b,c],...]}, ...],
//!  "tree": <nested>, "nodes": [<flat>], "bounds": [[x0,y0,z0],[x1,y1,z1]]}
//! ```
//!
//! Primitive `i` is the tree's leaf `Solid(i)`: the convex solids first (faces, counter-clockwise
//! from outside, fanned into triangles), then the imported meshes (`sampled[j]` is leaf
//! `solids.len() + j`, `CsgNode::number_imports_after`). Datasets are refused. The tree is
//! nested (`{"solid": i}`, `{"union": [...]}`, `{"intersection": [...]}`,
//! `{"difference": [...]}`, `{"complement": node}`, `"empty"`) and also flat in `nodes`, in
//! post-order (children before parents, children as indices into `nodes`, the root last), for
//! readers that do not recurse as deep as a file's tree can be.

use std::fmt::Write as _;
use std::io::Write as _;

use csgpix::scene::solid::CsgNode;
use csgpix::voxel::sampled::Shape;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args()
        .nth(1)
        .ok_or("usage: scene_meshes SCENE.csg")?;
    // Straight extrusions as prisms and meshes, never as footprints (a 2D tree, no mesh).
    let options = csgpix::openscad::ReadOptions {
        footprints: None,
        ..Default::default()
    };
    let loaded = csgpix::voxel::sampled::load_scene_with(std::path::Path::new(&path), &options)?;
    let (lo, hi) = loaded.bounds()?;
    let mut out = String::new();
    out.push_str("{\"primitives\": [");
    let mut first = true;
    for s in &loaded.scene.solids {
        sep(&mut out, &mut first);
        let mut tris = Vec::new();
        for f in &s.faces {
            for k in 1..f.len().saturating_sub(1) {
                tris.push([f[0], f[k], f[k + 1]].map(|i| i as usize));
            }
        }
        primitive(&mut out, s.vertices.iter().copied(), &tris)?;
    }
    for s in &loaded.sampled {
        sep(&mut out, &mut first);
        let mesh = match &s.shape {
            Shape::Mesh(m) => Some(m),
            // A mesh that is not closed: its welded, consistently wound triangles.
            Shape::OpenMesh(m, _) => Some(m.mesh()),
            Shape::Dataset { .. } | Shape::Footprint(_) => None,
        };
        match mesh {
            Some(m) => {
                let tris: Vec<[usize; 3]> =
                    m.triangles.iter().map(|t| t.map(|v| v as usize)).collect();
                primitive(&mut out, m.vertices.iter().map(|v| v.to_array()), &tris)?;
            }
            None => {
                return Err(format!("{}: a dataset, not a mesh: refused", s.file).into());
            }
        }
    }
    out.push_str("],\n\"tree\": ");
    nested(&mut out, &loaded.scene.root)?;
    out.push_str(",\n\"nodes\": ");
    flat(&mut out, &loaded.scene.root)?;
    write!(
        out,
        ",\n\"bounds\": [[{}, {}, {}], [{}, {}, {}]]}}\n",
        num(lo.x),
        num(lo.y),
        num(lo.z),
        num(hi.x),
        num(hi.y),
        num(hi.z)
    )?;
    // Written at once: a closed pipe is an error, not a panic.
    std::io::stdout().write_all(out.as_bytes())?;
    Ok(())
}

/// A comma before every item but the first.
fn sep(out: &mut String, first: &mut bool) {
    if !*first {
        out.push_str(",\n");
    }
    *first = false;
}

/// A number as JSON: f64's shortest round-trip form (`{:?}` keeps `1.0`; never NaN here).
fn num(x: f64) -> String {
    format!("{x:?}")
}

/// One primitive's vertices and triangles.
fn primitive(
    out: &mut String,
    vertices: impl Iterator<Item = [f64; 3]>,
    tris: &[[usize; 3]],
) -> std::fmt::Result {
    out.push_str("{\"vertices\": [");
    for (n, v) in vertices.enumerate() {
        if n > 0 {
            out.push(',');
        }
        write!(out, "[{},{},{}]", num(v[0]), num(v[1]), num(v[2]))?;
    }
    out.push_str("], \"triangles\": [");
    for (n, t) in tris.iter().enumerate() {
        if n > 0 {
            out.push(',');
        }
        write!(out, "[{},{},{}]", t[0], t[1], t[2])?;
    }
    out.push_str("]}");
    Ok(())
}

/// What a node is, as a JSON key.
fn op(node: &CsgNode) -> &'static str {
    match node {
        CsgNode::Union(_) => "union",
        CsgNode::Intersection(_) => "intersection",
        CsgNode::Difference(_) => "difference",
        CsgNode::Complement(_) => "complement",
        CsgNode::Solid(_) => "solid",
        CsgNode::Empty => "empty",
    }
}

/// The tree, nested, written with an explicit stack (trees can be as deep as a file makes them).
fn nested(out: &mut String, root: &CsgNode) -> std::fmt::Result {
    enum Step<'a> {
        Node(&'a CsgNode),
        Text(&'static str),
    }
    let mut stack = vec![Step::Node(root)];
    while let Some(step) = stack.pop() {
        let node = match step {
            Step::Text(t) => {
                out.push_str(t);
                continue;
            }
            Step::Node(n) => n,
        };
        match node {
            CsgNode::Solid(i) => write!(out, "{{\"solid\": {i}}}")?,
            CsgNode::Empty => out.push_str("\"empty\""),
            CsgNode::Complement(c) => {
                out.push_str("{\"complement\": ");
                stack.push(Step::Text("}"));
                stack.push(Step::Node(c));
            }
            CsgNode::Union(c) | CsgNode::Intersection(c) | CsgNode::Difference(c) => {
                write!(out, "{{\"{}\": [", op(node))?;
                stack.push(Step::Text("]}"));
                for (n, child) in c.iter().enumerate().rev() {
                    stack.push(Step::Node(child));
                    if n > 0 {
                        stack.push(Step::Text(", "));
                    }
                }
            }
        }
    }
    Ok(())
}

/// The tree in post-order: `[{"op": "union", "children": [k, ...]}, {"op": "solid", "index": i},
/// {"op": "empty"}, ...]`, the root last.
fn flat(out: &mut String, root: &CsgNode) -> std::fmt::Result {
    // (node, whether its children are done); `done` holds the finished nodes' indices.
    let mut stack = vec![(root, false)];
    let mut done: Vec<usize> = Vec::new();
    let mut count = 0usize;
    out.push('[');
    while let Some((node, expanded)) = stack.pop() {
        let children = node.children();
        if !expanded && !children.is_empty() {
            stack.push((node, true));
            // Pushed in reverse so the first child is finished first.
            stack.extend(children.iter().rev().map(|c| (c, false)));
            continue;
        }
        if count > 0 {
            out.push(',');
        }
        match node {
            CsgNode::Solid(i) => write!(out, "{{\"op\": \"solid\", \"index\": {i}}}")?,
            CsgNode::Empty => out.push_str("{\"op\": \"empty\"}"),
            _ => {
                let ids = done.split_off(done.len() - children.len());
                let list: Vec<String> = ids.iter().map(usize::to_string).collect();
                write!(
                    out,
                    "{{\"op\": \"{}\", \"children\": [{}]}}",
                    op(node),
                    list.join(",")
                )?;
            }
        }
        done.push(count);
        count += 1;
    }
    out.push(']');
    Ok(())
}
