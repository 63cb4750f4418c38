//! csgpix drawing: scenes on the pixel-processor array of `rtl-model`.
//!
//! A display list (§5.2) becomes the array's operations (`compile`), polygons and lines
//! become planes (§5.3.1), a CSG scene of convex solids is projected to display lists and a
//! clipping function (§5.2.1, `project`); `float` is the exact reference the `cycle` and
//! `word` models are measured against; `panels` and `throughput` are §2.5 and §5.5.

pub mod compile;
pub mod error;
pub mod float;
pub mod palette;
pub mod panels;
pub mod polygon;
pub mod project;
pub mod throughput;

pub use error::{Error, Result};
