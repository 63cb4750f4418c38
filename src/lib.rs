//! csgpix: scenes, formats and studies around the pixel-processor array of `rtl-model`.

pub mod blist;
pub mod clip_expr;
pub mod compile;
pub mod csg_expr;
pub mod display_list;
pub mod evaluate;
pub mod float;
pub mod mesh;
pub mod nrrd;
pub mod octree;
pub mod output;
pub mod palette;
pub mod panels;
pub mod plot;
pub mod polygon;
pub mod project;
pub mod requirements;
pub mod scad;
pub mod sculpt;
pub mod slice;
pub mod solid;
pub mod study;
pub mod throughput;
pub mod trimesh;
pub mod voxelize;
