//! What several commands' flags share: value parsers of named options, the reading flags
//! (`--openscad-timeout`, `--strict`), `--max-memory`, the grid flags, standard output.

use std::io::Write;

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use csgpix_openscad::Fallback;
use csgpix_run::grid::{parse_bounds, GridOptions, Resolution};
use csgpix_run::memory::{default_mib, Limit};
use csgpix_run::named::Named;
use csgpix_run::read::ReadSettings;
use csgpix_voxel::Sampling;

/// The value parser of a [`Named`] option: its names (and aliases) as clap's possible
/// values, each with its help, so `--help` lists them and completions offer them.
pub fn named<T: Named + Clone>() -> impl TypedValueParser<Value = T> {
    let values = T::VALUES.iter().map(|&(v, name, help)| {
        let aliases = T::ALIASES.iter().filter(move |a| a.1 == v).map(|a| a.0);
        PossibleValue::new(name).help(help).aliases(aliases)
    });
    PossibleValuesParser::new(values)
        .map(|s| csgpix_run::named::parse::<T>(&s).expect("a possible value"))
}

/// `--openscad-timeout` and `--strict`, flattened into each command that reads scenes.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct ReadArgs {
    /// Seconds each openscad run may take (a `.scad` file's export, a `--fallback openscad`
    /// mesh) before it is killed and the command fails (exit 2); 0 for no limit. Without a
    /// limit a `.scad` that keeps openscad busy would hold the command for as long.
    #[arg(long = "openscad-timeout", value_name = "SECONDS",
          default_value_t = csgpix_openscad::DEFAULT_OPENSCAD_TIMEOUT.as_secs())]
    pub seconds: u64,
    /// Refuse the scene at its first warning (exit 2, nothing written) instead of doing what
    /// OpenSCAD does and going on: a colour out of range, a singular transform, an import of
    /// a missing file, a child of the other dimension, a font substituted, an open mesh, …
    /// (docs/volume-scenes.md lists them).
    #[arg(long)]
    pub strict: bool,
}

impl From<ReadArgs> for ReadSettings {
    fn from(a: ReadArgs) -> ReadSettings {
        ReadSettings {
            openscad_timeout: a.seconds,
            strict: a.strict,
            ..ReadSettings::default()
        }
    }
}

/// `--threads` and `--fallback`, flattened into each command that voxelizes a scene.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct SweepArgs {
    /// Worker threads, 1 to 256 (default: all cores), on which the scene is read (its
    /// imports and meshes in parallel) and voxelized. The output does not depend on it;
    /// each thread holds a slab's masks, counted in the memory estimate.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
    threads: Option<u16>,
    /// What becomes of a node csgpix does not draw (`surface()`, a 2D import, a node it
    /// does not know): refused (`none`), or meshed by openscad, that subtree alone, and
    /// drawn as a closed mesh primitive, reported on stderr and in --json's `warnings`
    /// (a choice, so not with `--strict`, which refuses every warning).
    #[arg(long, value_parser = named::<Fallback>(), default_value = "none",
          conflicts_with = "strict")]
    pub fallback: Fallback,
    /// A straight `linear_extrude` (no twist or scale) of more outline points than this is
    /// voxelized from its 2D tree, evaluated over the pixel centres once for every slab (a
    /// footprint), instead of as a convex prism or mesh per shape; `print` also reads so
    /// every straight extrusion with a shape that is not convex (text, say); `off` keeps
    /// prisms and meshes. The same voxels are filled either way; the shapes of an uncoloured
    /// footprint share one colour code, as one primitive (docs/voxelize-bench.md,
    /// "Footprints").
    #[arg(long, value_name = "POINTS|off", value_parser = parse_footprints,
          default_value_t = Footprints(Some(csgpix_openscad::DEFAULT_FOOTPRINT_POINTS)))]
    pub footprints: Footprints,
}

/// `--footprints`: a count of outline points, or `off`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Footprints(pub Option<usize>);

impl std::fmt::Display for Footprints {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self.0 {
            Some(n) => write!(f, "{n}"),
            None => f.write_str("off"),
        }
    }
}

fn parse_footprints(s: &str) -> Result<Footprints, String> {
    match s {
        "off" => Ok(Footprints(None)),
        _ => s
            .parse()
            .map(|n| Footprints(Some(n)))
            .map_err(|_| format!("`{s}`: give a count of outline points or `off`")),
    }
}

impl SweepArgs {
    /// `read` with this command's `--footprints`.
    pub fn reading(&self, read: ReadSettings) -> ReadSettings {
        ReadSettings {
            footprints: self.footprints.0,
            ..read
        }
    }

    /// The job's worker threads (None: all cores).
    pub fn threads(&self) -> Option<usize> {
        self.threads.map(usize::from)
    }
}

/// `--max-memory`, flattened into each command that allocates in proportion to its input.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct MaxMemory {
    /// Refuse a run whose memory estimate is over this many MiB, before allocating. The
    /// default is the memory available now (MemAvailable), capped by what the process may
    /// hold: the address-space and data limits (`ulimit -v`, `ulimit -d`) less the process's
    /// own code, stacks and buffers, and the room left in its cgroup. A larger value is
    /// lowered to that cap, with a note; at most 2^43.
    #[arg(long = "max-memory", value_name = "MIB", default_value_t = default_mib(),
          value_parser = parse_max_memory)]
    pub mib: u64,
}

impl MaxMemory {
    /// The limit, named as the flag.
    pub fn limit(&self) -> Limit {
        Limit {
            mib: self.mib,
            name: "--max-memory",
        }
    }
}

/// `--max-memory MIB`: 1 to `MAX_MIB`, lowered to what the process may hold (`Cap`) with
/// a one-line note on standard error, so that a limit above the address space cannot let a
/// run start that the system will not let finish.
fn parse_max_memory(s: &str) -> csgpix_run::error::Parsed<u64> {
    let (mib, note) = csgpix_run::memory::parse_mib(s)?;
    if let Some(note) = note {
        eprintln!("csgpix: note: {note}");
    }
    Ok(mib)
}

/// The grid and sampling flags `voxelize` and `sculpt` share (beside their own `--res`).
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct GridArgs {
    /// Instead of --res: cubic voxels of this side (scene units), as many as cover the
    /// bounds, the grid centred on them.
    #[arg(long, conflicts_with = "res")]
    pub voxel: Option<f64>,
    /// Add this many empty voxels on every side of the grid (the voxel size is kept).
    #[arg(long, default_value_t = 0)]
    pub pad: usize,
    /// `centre`: a voxel is inside when its centre is inside the solid (binvox, OpenVDB);
    /// `slab`: when the segment through its centre along Z meets each primitive (the thesis's
    /// §4.4 slab, which dilates subtracted solids). docs/voxelization.md.
    #[arg(long, value_parser = named::<Sampling>(), default_value = "centre")]
    pub sampling: Sampling,
    /// Region to voxelize, X0,Y0,Z0,X1,Y1,Z1 in scene units (default: the scene's bounds).
    #[arg(long, value_parser = parse_bounds, allow_hyphen_values = true)]
    pub bounds: Option<(glam::DVec3, glam::DVec3)>,
}

impl GridArgs {
    /// The job's grid options with the command's resolution `res`.
    pub fn options(&self, res: Option<Resolution>) -> GridOptions {
        GridOptions {
            res,
            voxel: self.voxel,
            pad: self.pad,
            sampling: self.sampling,
            bounds: self.bounds.map(|(a, b)| (a.to_array(), b.to_array())),
        }
    }
}

/// Write `bytes` to standard output; a closed pipe (`| head`) is an error to report.
pub fn stdout(bytes: &[u8]) -> csgpix_run::Result<()> {
    std::io::stdout()
        .write_all(bytes)
        .map_err(|source| csgpix_run::Error::Io {
            path: "standard output".into(),
            source,
        })
}
