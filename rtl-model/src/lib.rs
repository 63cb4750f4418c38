#![warn(missing_docs)]

//! The csgpix pixel processor (seed 001, Chapter 2), clock by clock.
//!
//! One module per block of Figure 2.9: the [`depth_word`] format, the [`comparator`], the
//! [`select`] logic (SGENE) with its golden vectors, [`depgen`] (the tree of bit-serial adders),
//! TRANSD/TRANSC and the stage selector ([`program`]), and the two models of the array:
//! [`cycle`] (bit-sliced, clock by clock) and [`word`] (one word per pixel, no clock), which
//! share the select logic and the controller ([`array`](mod@array)). Probes record chosen pixels to VCD
//! ([`probe`]).

pub mod array;
pub mod comparator;
pub mod cycle;
pub mod depgen;
pub mod depth_word;
#[cfg(test)]
mod fixtures;
pub mod probe;
pub mod program;
pub mod select;
pub mod state;
pub mod verilog;
pub mod word;

pub use array::Array;
pub use cycle::CycleArray;
pub use depth_word::WordFormat;
pub use program::{Coeffs, Op};
pub use select::{EquationSet, Equations};
pub use state::{ArchState, ArrayConfig, ConfigError, Pixel};
pub use word::WordArray;
