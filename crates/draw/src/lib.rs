#![warn(missing_docs)]

//! csgpix drawing: scenes on the pixel-processor array of `rtl-model`.
//!
//! A display list (§5.2) becomes the array's operations (`compile`), polygons and lines
//! become planes (§5.3.1), a CSG scene of convex solids is projected to display lists and a
//! clipping function (§5.2.1, `project`); `float` is the exact reference the `cycle` and
//! `word` models are measured against; `panels` and `throughput` are §2.5 and §5.5.
//!
//! A polygon (§5.3.1) drawn on a 16 × 16 array of the word model:
//!
//! ```
//! use csgpix_draw::compile::scene_ops;
//! use csgpix_draw::polygon::{polygon, Support};
//! use rtl_model::program::CReg;
//! use rtl_model::{Array, ArrayConfig, Equations, WordArray};
//!
//! let flat = Support { z0: 40.0, dzx: 0.0, dzy: 0.0 };
//! let square = polygon(flat, 3, &[(2.0, 2.0), (12.0, 2.0), (12.0, 12.0), (2.0, 12.0)])?;
//! let cfg = ArrayConfig::new(16, 16);
//! let ops = scene_ops(&[square], &cfg.fmt, cfg.colour_bits).expect("the square compiles");
//! let mut array = WordArray::new(cfg, Equations::Derived.set());
//! array.run(&ops)?;
//! assert_eq!(array.pixel(7, 7).creg(CReg::G), 3); // inside: the square's colour
//! assert_eq!(array.pixel(0, 15).creg(CReg::G), 0); // outside: background
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod compile;
pub mod error;
pub mod float;
pub mod model;
pub mod palette;
pub mod panels;
pub mod polygon;
pub mod project;
pub mod scenes;
pub mod throughput;

pub use error::{Error, Result};
pub use model::Model;
