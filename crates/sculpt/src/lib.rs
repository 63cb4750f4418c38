//! csgpix voxel stores and sculpting (seed 000): the optimized hash-based octree of §4.3.4,
//! its baselines (pointer octrees, the plain hash octree, a dense grid), Marching Cubes over
//! any of them, and haptic sculpting with a spherical tool on the optimized store.
//!
//! Stores are built slice by slice from whatever hands them slices (a voxelizer, a dataset):
//! this crate knows scenes' volumes and grids, not how they are voxelized.

pub mod error;
pub mod octree;
pub mod sculpt;

pub use sculpt::*;

pub use error::{Error, Result};
