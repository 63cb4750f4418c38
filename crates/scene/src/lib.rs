//! csgpix scenes and formats: what a user hands the simulator and what it hands back.
//!
//! Display lists (§5.2) and clipping functions (§5.2.1) for the array; CSG scenes over convex
//! solids (read from OpenSCAD by `csgpix-openscad`), CSG expressions over named primitives (§4.3); triangle meshes (closed ones by parity, others by [`winding`] number) and NRRD volume
//! datasets as primitives (§3.2-3.3); the voxel grid and volumes (§4.4); mesh and volume
//! writers (written whole or not at all through `csgpix-output`). No processor here: `csgpix-draw` turns
//! scenes into array operations.
//!
//! Clipping functions and CSG expressions share one grammar and parser ([`expr`]). Every
//! fallible function returns the crate's [`Result`]: an [`Error`] is one line, located
//! `FILE:LINE:COL` ([`Location`]) where its input has a place for it, and never names a
//! command-line option (callers add those, e.g. by [`Error::in_file`] or [`Kind`]).

#![warn(missing_docs)]

pub mod clip_expr;
pub mod csg_expr;
pub mod dataset;
pub mod display_list;
pub mod error;
pub mod expr;
pub mod facet;
pub mod footprint;
pub mod grid;
pub mod input;
pub mod mesh;
// The OFF, AMF and 3MF readers behind `trimesh::TriMesh::read`.
mod amf;
mod meshfile;
pub use meshfile::{check_xml_nesting, MAX_XML_DEPTH, MAX_XML_NODES};
mod meshread;
pub mod nrrd;
mod off;
pub mod solid;
mod threemf;
pub mod trimesh;
pub mod winding;
mod zipped;

pub use error::{CsgError, Error, IoError, Kind, Location, OneLine, Result};
