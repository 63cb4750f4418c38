//! TRANSITION (issue 39): the clap grid flags `sculpt`, `study` and `requirements` still read
//! from the run layer (`--voxel`, `--pad`, `--sampling`, `--bounds`); their replacement is
//! `GridArgs` of the binary's `src/cli/common.rs` with [`crate::grid::GridOptions`]. Deleted
//! once those commands are jobs.

use clap::ValueEnum;
use glam::DVec3;

use crate::grid::{grid_spec, parse_bounds, Resolution};
use csgpix_voxel::sampled::Loaded;
use csgpix_voxel::{Grid, Sampling};

/// The grid and sampling options `voxelize` and `sculpt` share (beside their own `--res`).
#[derive(clap::Args, Debug)]
pub struct GridArgs {
    /// Instead of --res: cubic voxels of this side (scene units), as many as cover the
    /// bounds, the grid centred on them.
    #[arg(long, conflicts_with = "res")]
    voxel: Option<f64>,
    /// Add this many empty voxels on every side of the grid (the voxel size is kept).
    #[arg(long, default_value_t = 0)]
    pad: usize,
    /// `centre`: a voxel is inside when its centre is inside the solid (binvox, OpenVDB);
    /// `slab`: when the segment through its centre along Z meets each primitive (the thesis's
    /// §4.4 slab, which dilates subtracted solids). docs/voxelization.md.
    #[arg(long, value_enum, default_value_t)]
    pub sampling: SamplingArg,
    /// Region to voxelize, X0,Y0,Z0,X1,Y1,Z1 in scene units (default: the scene's bounds).
    #[arg(long, value_parser = parse_bounds, allow_hyphen_values = true)]
    pub bounds: Option<(DVec3, DVec3)>,
}

impl GridArgs {
    /// The grid of `res` (or of `--voxel`) over `--bounds` or the scene's.
    pub fn grid(&self, res: Option<Resolution>, scene: &Loaded) -> crate::Result<Grid> {
        let spec = grid_spec(res, self.voxel, self.pad);
        scene
            .grid_over(&spec, self.bounds)
            .map_err(crate::voxelize::flag_message)
    }

    /// Whether any grid option was given (they apply to scenes only).
    pub fn any(&self) -> bool {
        self.voxel.is_some() || self.pad > 0 || self.bounds.is_some()
    }
}

/// `--sampling`, shared with `sculpt`.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq)]
pub enum SamplingArg {
    /// A voxel is inside when its centre is inside the solid.
    #[default]
    #[value(alias = "center")]
    Centre,
    /// A voxel is inside a primitive when its segment along Z meets it (§4.4).
    Slab,
}

impl SamplingArg {
    pub fn sampling(self) -> Sampling {
        match self {
            SamplingArg::Centre => Sampling::Centre,
            SamplingArg::Slab => Sampling::Slab,
        }
    }
}

from_value_name!(SamplingArg: "sampling");
