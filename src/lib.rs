#![warn(missing_docs)]

//! csgpix: the 2D CSG pixel-processor array of a 2005 thesis (seed 001), simulated clock by
//! clock, and what it is used for: rendering scenes, voxelizing them slice by slice, storing
//! and sculpting the voxels.
//!
//! This crate is the facade over the subsystems, each its own crate, re-exported whole (one
//! path per item: `csgpix::voxel::blist::BlistEval` is `csgpix_voxel::blist::BlistEval`):
//!
//! | crate | re-exported as | what |
//! |---|---|---|
//! | `rtl-model` | [`rtl_model`] | the processor: depth word, DEPGEN, comparator, select logic, clipping stack, the `cycle` and `word` arrays |
//! | `csgpix-output` | [`output`] | outputs staged and committed whole, removed on a signal |
//! | `csgpix-scene` | [`scene`] | display lists, expressions, scenes, meshes, NRRD, grids and volumes |
//! | `csgpix-openscad` | [`openscad`] | the OpenSCAD language: `.csg`, `.scad` through openscad, extrusions, hulls |
//! | `csgpix-draw` | [`draw`] | scenes → display lists → array operations, the `float` model, panels, throughput |
//! | `csgpix-voxel` | [`voxel`] | slices from the array, masks, the Blist and baseline evaluators, requirements |
//! | `csgpix-sculpt` | [`sculpt`] | the hashed octree of seed 000, its baselines, Marching Cubes, sculpting |
//! | `csgpix-zarr` | `zarr` (feature `zarr`, default) | volumes as OME-Zarr 0.5 stores, written a chunk row at a time |
//! | `csgpix-run` | [`run`] | one job per command as plain data (`estimate`, `run` with a `Progress`, a report as data), shared by the binary and Python; the memory limit, stores fed from the voxelizer |

pub use csgpix_draw as draw;
pub use csgpix_openscad as openscad;
pub use csgpix_output as output;
pub use csgpix_run as run;
pub use csgpix_scene as scene;
pub use csgpix_sculpt as sculpt;
pub use csgpix_voxel as voxel;
#[cfg(feature = "zarr")]
pub use csgpix_zarr as zarr;
pub use glam;
pub use rtl_model;

/// The README's Rust blocks, run as doctests so its library example stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
