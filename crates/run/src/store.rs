//! Voxel stores fed from the voxelizer: a store built slice by slice as the voxelizer hands
//! the slices over (seed 000 §4.3.4), no dense volume of the scene made unless the caller
//! keeps one (`voxelize --store`).

use csgpix_scene::solid::CsgNode;
use csgpix_sculpt::octree::{OptimizedOctree, StoreBuilder};
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{Route, Slicer, Work};
use rtl_model::EquationSet;

/// Why feeding a store from the voxelizer stopped: the voxelizer's error or the store's.
#[derive(Debug)]
pub enum Fed {
    /// The voxelizer's.
    Voxel(csgpix_voxel::Error),
    /// The store's (e.g. [`csgpix_sculpt::Error::OverBudget`]).
    Store(csgpix_sculpt::Error),
}

impl From<csgpix_voxel::Error> for Fed {
    fn from(e: csgpix_voxel::Error) -> Fed {
        Fed::Voxel(e)
    }
}

impl From<Fed> for crate::Error {
    fn from(f: Fed) -> crate::Error {
        match f {
            Fed::Voxel(e) => e.into(),
            Fed::Store(e) => crate::lib_errors::sculpt(e),
        }
    }
}

/// Voxelize `slicer`'s grid by `route`, handing each slice in order of k to `push` (a
/// store's builder, and whatever else the caller keeps): the one bridge from the
/// voxelizer to the stores. `tick` once a slice (or a band of rows on the run route).
pub fn feed(
    slicer: &Slicer,
    (route, set): (Route, EquationSet),
    eval: &dyn SliceEval,
    tick: &(dyn Fn() + Sync),
    push: &mut dyn FnMut(usize, &[u8]) -> csgpix_sculpt::Result<()>,
) -> Result<Work, Fed> {
    let mut sink = |k: usize, s: &[u8]| push(k, s).map_err(Fed::Store);
    csgpix_voxel::voxelize_streaming(slicer, route, set, eval, tick, &mut sink)
}

/// The optimized octree of a sliced scene (`tree` its CSG tree), fed slice by slice from the
/// voxelizer's run route with the Blist ([`feed`]; seed 000 §4.3.4: no dense volume of the
/// scene is made); `budget` bounds the leaves kept while building, in bytes. The store's own
/// errors come back whole (e.g. [`csgpix_sculpt::Error::OverBudget`]), the voxelizer's
/// wrapped ([`csgpix_sculpt::Error::Voxel`]).
pub fn octree_from_scene(
    slicer: &Slicer,
    tree: &CsgNode,
    budget: u64,
) -> csgpix_sculpt::Result<OptimizedOctree> {
    let eval = csgpix_voxel::blist::BlistEval::new(tree);
    let mut b = csgpix_sculpt::octree::optimized::builder(slicer.grid.dims, budget)?;
    let route = (
        Route::Runs { float: false },
        rtl_model::Equations::Derived.set(),
    );
    match feed(slicer, route, &eval, &|| {}, &mut |k, s| b.push(k, s)) {
        Err(Fed::Store(e)) => return Err(e),
        Err(Fed::Voxel(e)) => return Err(e.into()),
        Ok(_) => {}
    }
    b.finish_store()
}
