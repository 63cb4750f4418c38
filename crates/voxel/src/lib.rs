#![warn(missing_docs)]

//! csgpix voxelization: CSG scenes slice by slice (§4.4; DESIGN.md, "From images to voxels").
//!
//! The grid's X and Y map to the array's pixels and its Z to depth: slab k lies between
//! Z-plane(k) and Z-plane(k + 1). The slice of primitive P is what the array shows for P·Vz,
//! drawn the thesis way (§5.2.1): @(P)·Vz + @(Vz)·P, P's own surface inside the slab or the
//! slab's front plane inside P, composed by the second stage. A pixel shows something exactly
//! when P meets the slab along the pixel's ray.
//!
//! # Sampling conventions ([`Sampling`])
//!
//! * `centre` (the default): voxel (i, j, k) is inside primitive P when its centre is inside
//!   P. Pixel (i, j) samples the ray at the centre's X and Y; Vz is one least unit of the
//!   depth word thick, at the centre's depth. Point membership commutes with CSG, so the
//!   volume is the point membership of the CSG solid at every centre.
//! * `slab` (the thesis's §4.4 slab): voxel (i, j, k) is inside P when the segment through
//!   the voxel's centre parallel to Z, from its front face up to (not including) its back
//!   face, meets P. The slab's clipping planes are the voxel's front face and a plane one least
//!   unit of the depth word before its back face, so every depth word belongs to exactly one
//!   slab. CSG over such classifications dilates every subtracted solid by up to a voxel.
//!
//! # Routes to the same masks
//!
//! * [`Route::Array`]: the processor itself (`cycle` or `word`), one frame per primitive per
//!   slab; the reference, and the only route that reports clocks.
//! * [`Route::Intervals`]: the same plane words the array computes (Z0 + x·dZx + y·dZy in the
//!   depth word, §2.3.1), reduced once per pixel to the interval of depths where P lies, then
//!   intersected with every slab. Tests prove it gives the processor's masks voxel for voxel.
//! * [`Route::Float`]: the same intervals in exact f64 arithmetic: the reference geometry.
//! * [`Route::Runs`]: the same depths (plane words or f64) column by column, merged into runs
//!   of constant membership, the tree evaluated once per run and the volume written run by
//!   run ([`runs`]); equal voxel for voxel to the slab route it takes its depths from.

//!
//! # Example
//!
//! A cube with a square hole through it, voxelized on a 16³ grid by the interval route and
//! the Blist, is its point membership at every voxel centre (centre sampling):
//!
//! ```
//! use csgpix_voxel::blist::BlistEval;
//! use csgpix_voxel::evaluate::direct;
//! use csgpix_voxel::{voxelize, Grid, Route, Slicer, SlicerOptions};
//! use glam::DVec3;
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let text = "difference() {
//!   cube(size = [8, 8, 8], center = false);
//!   multmatrix([[1, 0, 0, 2], [0, 1, 0, 2], [0, 0, 1, -1], [0, 0, 0, 1]]) {
//!     cube(size = [4, 4, 10], center = false);
//!   }
//! }";
//! let scene = csgpix_openscad::parse_csg(text, "x.csg")?;
//! let grid = Grid::new([16; 3], DVec3::ZERO, DVec3::splat(8.0))?;
//! let slicer = Slicer::new(&scene, grid, SlicerOptions::default())?;
//! let eval = BlistEval::new(&scene.root);
//! let set = rtl_model::Equations::Derived.set();
//! let (volume, work) = voxelize(&slicer, Route::Intervals, set, &eval, &|| {})?;
//!
//! // Direct point membership: each solid here is an axis-aligned box, its vertices' box.
//! let boxes: Vec<(DVec3, DVec3)> = scene.solids.iter().map(|s| {
//!     let pts = s.vertices.iter().map(|v| DVec3::from(*v));
//!     pts.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(p), hi.max(p)))
//! }).collect();
//! let mut filled = 0;
//! for k in 0..16 {
//!     for j in 0..16 {
//!         for i in 0..16 {
//!             let c = grid.centre(i, j, k);
//!             let inside = |p: usize| c.cmpge(boxes[p].0).all() && c.cmple(boxes[p].1).all();
//!             let want = direct(&scene.root, inside);
//!             assert_eq!(volume.voxels[(k * 16 + j) * 16 + i] != 0, want);
//!             filled += usize::from(want);
//!         }
//!     }
//! }
//! assert_eq!(work.filled, filled);
//! assert_eq!(filled, 16 * 16 * 16 - 8 * 8 * 16); // the hole is 4 × 4 units, 8 × 8 voxels
//! # Ok(())
//! # }
//! ```
//!
//! # The pipeline, block by block
//!
//! Scene → [`Slicer`] (the grid on the array, `slicer`) → per-pixel slab ranges (`ranges`)
//! or the array's own masks (`masks`) → where each primitive is (`footprint`) → per-slab
//! masks evaluated by a [`SliceEval`](slice::SliceEval) (the Blist §4.3-4.5, the tree §4.2,
//! the slice stack §3.4.1) → colour codes slice by slice (`drive`).

pub mod blend;
pub mod blist;
pub mod cells;
pub mod dataset_runs;
pub mod drive;
pub mod error;
pub mod evaluate;
pub mod footprint;
pub mod masks;
pub mod pixel_box;
pub mod ranges;
pub mod requirements;
pub mod runs;
pub mod sampled;
pub mod slabs;
pub mod slice;
pub mod slicer;
pub mod work;

pub use csgpix_scene::grid::{surface_voxels, Grid, GridSpec, Volume, MAX_GRID_SIDE};
pub use drive::{
    grey_code, memory_estimate, memory_estimate_rows, voxelize, voxelize_slabs, voxelize_streaming,
    SliceSink, Work, GREY_BASE, PROCESS_BYTES,
};
pub use footprint::{footprints, touched_panels, Footprint};
pub use masks::{array_mask, array_mask_in, slice_ops};
pub use pixel_box::PixelBox;
pub use ranges::{float_interval, float_ranges, mesh_runs, ray_interval, word_ranges};
pub use slabs::{toggle_run, SlabRanges};
pub use slicer::{voxel_slope, Route, Sampling, Slicer, SlicerOptions, DEFAULT_PANEL};

pub use error::{BindingProblem, BindingSyntax, Error, ExprError, Result};
