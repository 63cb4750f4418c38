#![warn(missing_docs)]

//! csgpix voxel stores and sculpting (seed 000): the optimized hash-based octree of §4.3.4,
//! its baselines (pointer octrees, the plain hash octree, a dense grid), Marching Cubes over
//! any of them, and haptic sculpting with a spherical tool on the optimized store.
//!
//! Stores are built slice by slice from whatever hands them slices (a voxelizer, a dataset):
//! this crate knows scenes' volumes and grids, not how they are voxelized.
//!
//! The optimized octree of a small volume meshes as the dense grid does (Marching Cubes,
//! seed 000 §3.1.2):
//!
//! ```
//! use csgpix_scene::grid::Volume;
//! use csgpix_sculpt::octree::{from_volume, mc, OptimizedOctree, StoreKind, VoxelStore};
//!
//! // An 8³ volume holding a 4³ block of filled voxels.
//! let dims = [8, 8, 8];
//! let inside = |i: usize| (2..6).contains(&i);
//! let voxels = (0..512)
//!     .map(|n| u8::from(inside(n % 8) && inside(n / 8 % 8) && inside(n / 64)))
//!     .collect();
//! let v = Volume { dims, voxels };
//! let octree = OptimizedOctree::from_volume(&v, 1 << 20)?;
//! let dense = from_volume(StoreKind::Dense, &v, 1 << 20)?;
//! assert!(octree.get(3, 3, 3) && !octree.get(0, 0, 0));
//! let tris = mc::marching_cubes(&octree).triangles.len();
//! assert!(tris > 0);
//! assert_eq!(tris, mc::marching_cubes(dense.as_ref()).triangles.len());
//! assert!(octree.node_count() < dense.node_count());
//! # Ok::<(), csgpix_sculpt::Error>(())
//! ```

pub mod error;
pub mod estimate;
pub mod octree;
pub mod sculpt;

pub use sculpt::*;

pub use error::{CellProblem, Error, Result, ToolProblem};
