//! The run layer of csgpix: one job per command, as plain data, shared by the `csgpix`
//! binary (its flags become a job, `src/cli`) and the Python binding (keyword arguments
//! become the same job, `python/src`); docs/jobs.md.
//!
//! One module per command ([`voxelize`], [`render`], [`sculpt`], …): its job (typed fields,
//! `Default` the documented defaults, `estimate()` the memory plan, `run(&dyn Progress)`)
//! and its report (data, serde). Nothing here parses flags or prints: progress, warnings and
//! notes go to a [`progress::Progress`], the report is returned. Beside the jobs, what they
//! share: option values by name ([`named`]), the grid ([`grid`]), reading settings
//! ([`read`]), the memory limit ([`memory`]), the study's sweep ([`sweep`]) and charts as
//! data ([`plot`]), PNG output ([`png`]), voxel stores fed from the voxelizer ([`store`]).
//! A job fails with an [`Error`] (typed, one line when printed; exit status 2).

#[macro_use]
pub mod named;
pub mod array_args;
pub mod blist;
pub mod error;
pub mod export_verilog;
pub mod gen_vectors;
pub mod generated;
pub mod grid;
mod lib_errors;
pub mod memory;
pub mod phantom;
pub mod plot;
pub mod png;
pub mod printer;
pub mod progress;
pub mod read;
pub mod render;
pub mod requirements;
pub mod sculpt;
pub mod store;
pub mod study;
pub mod sweep;
pub mod throughput;
pub mod throughput_fpga;
pub mod value;
pub mod verify_select;
pub mod voxelize;

pub use error::{Error, Result};
