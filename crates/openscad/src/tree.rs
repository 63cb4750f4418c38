//! The CSG tree an operation makes of its children, simplified.

use crate::node::*;
use csgpix_scene::solid::CsgNode;

/// The node an operation makes of its children, simplified as the module documentation says.
pub(crate) fn combine(op: Op, children: Vec<CsgNode>) -> CsgNode {
    match op {
        Op::Union => union(children),
        Op::Intersection => intersection(children),
        Op::Difference => difference(children),
    }
}

/// Empty children dropped, unions flattened.
pub(crate) fn union(children: Vec<CsgNode>) -> CsgNode {
    let mut parts = Vec::with_capacity(children.len());
    for mut child in children {
        match &mut child {
            CsgNode::Empty => {}
            CsgNode::Union(inner) => parts.append(inner),
            _ => parts.push(child),
        }
    }
    one_or(parts, CsgNode::Union)
}

/// Empty if any child is, intersections flattened.
pub(crate) fn intersection(children: Vec<CsgNode>) -> CsgNode {
    if children.iter().any(|c| matches!(c, CsgNode::Empty)) {
        return CsgNode::Empty;
    }
    let mut parts = Vec::with_capacity(children.len());
    for mut child in children {
        match &mut child {
            CsgNode::Intersection(inner) => parts.append(inner),
            _ => parts.push(child),
        }
    }
    one_or(parts, CsgNode::Intersection)
}

/// Empty if the first child is; empty subtracted children dropped.
pub(crate) fn difference(children: Vec<CsgNode>) -> CsgNode {
    let mut children = children.into_iter();
    let first = match children.next() {
        None | Some(CsgNode::Empty) => return CsgNode::Empty,
        Some(first) => first,
    };
    let mut parts = vec![first];
    parts.extend(children.filter(|c| !matches!(c, CsgNode::Empty)));
    one_or(parts, CsgNode::Difference)
}

/// No part is empty, one part is itself, more make a `many` node.
pub(crate) fn one_or(mut parts: Vec<CsgNode>, many: fn(Vec<CsgNode>) -> CsgNode) -> CsgNode {
    match parts.len() {
        0 => CsgNode::Empty,
        1 => parts.pop().unwrap_or(CsgNode::Empty),
        _ => many(parts),
    }
}

// ---------------------------------------------------------------------------------------------
// Transforms and colours
