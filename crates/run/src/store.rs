//! Voxel stores fed from the voxelizer: the optimized octree of a scene built slice by slice
//! (seed 000 §4.3.4), no dense volume of the scene made.

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
