//! The run layer of csgpix: every command's job, from its flags to its outputs, shared by
//! the `csgpix` binary (clap → [`Cli`] → [`run`]) and the Python binding (keyword arguments
//! → the same options and runs, `python/src`).
//!
//! One module per command ([`voxelize`], [`render`], [`sculpt`], …): its flags (`Args`,
//! parsed by clap), its run and its report; beside them what the commands share: the memory
//! limit ([`memory`]), the study's sweep ([`sweep`]) and charts ([`plot`]), PNG output
//! ([`png`]), voxel stores fed from the voxelizer ([`store`]) and OME-Zarr stores written by
//! chunk rows or bricks (`voxelize::zarr`). Each command returns its
//! exit code, or an [`Error`] (typed, one line when printed; exit status 2).

/// The flags' value names as [`FromStr`](std::str::FromStr), for the Python binding's keyword
/// arguments: one spelling of every value, the command line's.
macro_rules! from_value_name {
    ($($t:ty: $what:literal),*) => {$(
        impl std::str::FromStr for $t {
            type Err = crate::error::BadValue;
            fn from_str(s: &str) -> crate::error::Parsed<Self> {
                <$t as clap::ValueEnum>::from_str(s, false).map_err(|_| {
                    let names: Vec<String> = <$t as clap::ValueEnum>::value_variants()
                        .iter()
                        .filter_map(|v| v.to_possible_value())
                        .map(|v| format!("`{}`", v.get_name()))
                        .collect();
                    crate::error::BadValue(format!("{} {s:?}: {}", $what, names.join(", ")))
                })
            }
        }
    )*};
}

#[macro_use]
pub mod named;
pub mod array_args;
pub mod blist;
pub mod error;
pub mod export_verilog;
pub mod gen_vectors;
pub mod generated;
pub mod grid;
pub mod grid_args;
mod lib_errors;
pub mod memory;

pub mod phantom;
pub mod plot;
// TRANSITION (issue 39): throughput's charts drawn to files, until they go through `plot::Charts`.
pub mod plot_file;
pub mod png;
pub mod progress;
pub mod read;
pub mod read_args;
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

use std::process::ExitCode;

use clap::ValueEnum;
use csgpix_draw::project::View;
use csgpix_draw::Model;
use rtl_model::Equations;

pub use error::{Error, Result};

from_value_name!(ViewArg: "view", EquationsArg: "equations");

/// `--model`: the names of [`Model`], each with its summary in `--help`.
pub fn model_parser() -> impl clap::builder::TypedValueParser<Value = Model> {
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    let values = Model::ALL.map(|m| PossibleValue::new(m.name()).help(m.summary()));
    PossibleValuesParser::new(values).map(|s| s.parse::<Model>().expect("a possible value"))
}

/// Which equation set SGENE uses.
#[derive(ValueEnum, Clone, Copy, Debug, Default)]
pub enum EquationsArg {
    /// Minimized from the golden vectors (default).
    #[default]
    Derived,
    /// Exactly the thesis text, faults included.
    Printed,
}

impl From<EquationsArg> for Equations {
    fn from(e: EquationsArg) -> Equations {
        match e {
            EquationsArg::Derived => Equations::Derived,
            EquationsArg::Printed => Equations::Printed,
        }
    }
}

/// A view of a `.csg` scene on the array (`render`, `throughput`, `requirements`).
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default)]
pub enum ViewArg {
    /// Looking down −Z (x right, y up).
    Top,
    /// Looking along +Y (x right, z up).
    Front,
    /// Isometric, from (+1, −1, +1).
    #[default]
    Iso,
}

impl From<ViewArg> for View {
    fn from(v: ViewArg) -> View {
        match v {
            ViewArg::Top => View::Top,
            ViewArg::Front => View::Front,
            ViewArg::Iso => View::Iso,
        }
    }
}

impl ViewArg {
    pub fn name(self) -> &'static str {
        match self {
            ViewArg::Top => "top",
            ViewArg::Front => "front",
            ViewArg::Iso => "iso",
        }
    }
}

/// A command's closing line: on standard output, or on standard error when an output goes
/// to standard output (`-o -`).
pub fn report_line(line: &str, to_stderr: bool) {
    if to_stderr {
        eprintln!("{line}");
    } else {
        println!("{line}");
    }
}

/// Write generated files into `out`, all or none, or with `check` only compare them with
/// what is there: exit 1 when any differs (`gen-vectors`, `export-verilog`).
pub fn write_generated(
    files: &[(String, String)],
    out: &std::path::Path,
    check: bool,
) -> Result<ExitCode> {
    if check {
        let stale = files
            .iter()
            .map(|(name, text)| (out.join(name), text))
            .filter(|(path, text)| std::fs::read_to_string(path).unwrap_or_default() != **text)
            .inspect(|(path, _)| println!("differs: {}", path.display()))
            .count();
        return Ok(if stale == 0 {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        });
    }
    let mut outs = csgpix_output::Outputs::new();
    let dir = outs.dir("--out", out)?;
    for (name, text) in files {
        outs.write_in(dir, name, |w| w.write_all(text.as_bytes()))?;
    }
    outs.commit()?;
    for (name, _) in files {
        println!("wrote {}", out.join(name).display());
    }
    Ok(ExitCode::SUCCESS)
}
