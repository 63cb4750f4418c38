#![warn(missing_docs)]

//! csgpix: the 2D CSG pixel-processor array of a 2005 thesis (seed 001), simulated clock by
//! clock, and what it is used for: rendering scenes, voxelizing them slice by slice, storing
//! and sculpting the voxels.
//!
//! This crate is the facade over the subsystems, each its own crate:
//!
//! | crate | re-exported as | what |
//! |---|---|---|
//! | `rtl-model` | [`rtl_model`] | the processor: depth word, DEPGEN, comparator, select logic, clipping stack, the `cycle` and `word` arrays |
//! | `csgpix-scene` | [`scene`] | display lists, expressions, scenes, meshes, NRRD, grids and volumes, outputs |
//! | `csgpix-openscad` | [`openscad`] (and [`scad`]) | the OpenSCAD language: `.csg`, `.scad` through openscad, extrusions, hulls |
//! | `csgpix-draw` | [`draw`] | scenes → display lists → array operations, the `float` model, panels, throughput |
//! | `csgpix-voxel` | [`voxel`] | slices from the array, masks, the Blist and baseline evaluators, requirements |
//! | `csgpix-sculpt` | [`sculpt`] | the hashed octree of seed 000, its baselines, Marching Cubes, sculpting |
//! | `csgpix-zarr` | [`zarr`] | volumes as OME-Zarr 0.5 stores, written a chunk row at a time |
//!
//! and holds what joins them: the accuracy/cost [`study`], charts ([`plot`]), PNG output
//! ([`png`]) and [`octree_from_scene`]. Every module of the subsystems is also reachable
//! under its own name (`csgpix::scad`, `csgpix::blist`, …).

pub mod plot;
pub mod png;
pub mod study;

pub use csgpix_draw as draw;
pub use csgpix_openscad as openscad;
pub use csgpix_openscad as scad;
pub use csgpix_scene as scene;
pub use csgpix_sculpt as sculpt;
pub use csgpix_voxel as voxel;
pub use csgpix_zarr as zarr;
pub use glam;
pub use rtl_model;

pub use csgpix_draw::{compile, float, palette, panels, polygon, project, throughput};
pub use csgpix_openscad::{extrude, hull};
pub use csgpix_scene::{
    clip_expr, csg_expr, dataset, display_list, grid, input, mesh, nrrd, output, solid, trimesh,
};
pub use csgpix_sculpt::octree;
pub use csgpix_voxel::{blend, blist, evaluate, requirements, sampled, slice};

use csgpix_scene::solid::CsgNode;
use csgpix_sculpt::octree::{OptimizedOctree, StoreBuilder};
use csgpix_voxel::{Route, Slicer};

/// The optimized octree of a sliced scene (`tree` its CSG tree), fed slice by slice from the
/// voxelizer's run route with the Blist (seed 000 §4.3.4: no dense volume of the scene
/// is made); `budget` bounds the leaves kept while building, in bytes. The store's own
/// errors come back whole (e.g. [`csgpix_sculpt::Error::OverBudget`]), the voxelizer's
/// wrapped ([`csgpix_sculpt::Error::Voxel`]).
pub fn octree_from_scene(
    slicer: &Slicer,
    tree: &CsgNode,
    budget: u64,
) -> csgpix_sculpt::Result<OptimizedOctree> {
    let eval = csgpix_voxel::blist::BlistEval::new(tree);
    let mut b = csgpix_sculpt::octree::optimized::builder(slicer.grid.dims, budget)?;
    let streamed = csgpix_voxel::voxelize_streaming(
        slicer,
        Route::Runs { float: false },
        rtl_model::Equations::Derived.set(),
        &eval,
        &|| {},
        &mut |k, s| b.push(k, s).map_err(Fed::Store),
    );
    match streamed {
        Err(Fed::Store(e)) => return Err(e),
        Err(Fed::Voxel(e)) => return Err(e.into()),
        Ok(_) => {}
    }
    b.finish_store()
}

/// Why feeding a store from the voxelizer stopped: the voxelizer's error or the store's.
enum Fed {
    Voxel(csgpix_voxel::Error),
    Store(csgpix_sculpt::Error),
}

impl From<csgpix_voxel::Error> for Fed {
    fn from(e: csgpix_voxel::Error) -> Fed {
        Fed::Voxel(e)
    }
}

/// The README's Rust blocks, run as doctests so its library example stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
