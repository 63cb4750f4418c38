//! Voxelize a scene from Rust: an OpenSCAD `.csg` scene sliced on the array (§4.4) and
//! evaluated by the Blist (§4.3-4.5); the middle slice is printed, `#` filled.
//!
//! `cargo run --release --example voxelize_scene [SCENE.csg] [N]`

use std::fmt::Write as _;
use std::io::Write as _;

use csgpix::voxel::blist::BlistEval;
use csgpix::voxel::{voxelize, Grid, Route, Slicer, SlicerOptions};
use rtl_model::Equations;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut out = String::new();
    let mut args = std::env::args().skip(1);
    let path = args.next().unwrap_or_else(|| {
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/vectors/scenes/hollow-cube.csg"
        )
        .into()
    });
    let n: usize = args.next().map_or(Ok(32), |s| s.parse())?;
    let loaded = csgpix::voxel::sampled::load_scene(std::path::Path::new(&path))?;
    let grid = Grid::of_scene(&loaded.scene, [n; 3])?;
    let opts = SlicerOptions {
        sampled: loaded.sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&loaded.scene, grid, opts)?;
    let eval = BlistEval::new(&loaded.scene.root);
    let set = Equations::Derived.set();
    let (volume, work) = voxelize(&slicer, Route::Intervals, set, &eval, &|| {})?;
    writeln!(
        out,
        "{path}: {n}³ voxels, {} filled, {} P·Vz frames, {} array clocks",
        work.filled, work.frames, work.cycles
    )?;
    let slice = n / 2;
    for j in (0..n).rev() {
        let row: String = (0..n)
            .map(|i| match volume.voxels[(slice * n + j) * n + i] {
                0 => '.',
                _ => '#',
            })
            .collect();
        writeln!(out, "{row}")?;
    }
    // Written at once: a closed pipe (`| head`) is an error, not a panic.
    std::io::stdout().write_all(out.as_bytes())?;
    Ok(())
}
