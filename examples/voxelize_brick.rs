//! One brick of a large volume (`csgpix::voxel::runs::voxelize_brick`): a box of columns × a
//! range of slabs, computed alone as one task of a run split into bricks would, with the time
//! it took. What docs/scale-out.md's per-brick figures come from.
//!
//! `cargo run --release --example voxelize_brick -- SCENE.csg N X0 Y0 SIDE K0 DEPTH`
//! (defaults: csg-logo.csg, 16384, the brick of 512 × 512 columns and 64 slabs at the grid's
//! centre). Peak memory: run it under `/usr/bin/time -f %M`.

use std::time::Instant;

use csgpix::voxel::blist::BlistEval;
use csgpix::voxel::{runs, Grid, PixelBox, Slicer, SlicerOptions};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args.first().cloned().unwrap_or_else(|| {
        concat!(env!("CARGO_MANIFEST_DIR"), "/vectors/scenes/csg-logo.csg").into()
    });
    let num = |i: usize, default: usize| -> Result<usize, std::num::ParseIntError> {
        args.get(i).map_or(Ok(default), |s| s.parse())
    };
    let n = num(1, 16384)?;
    let side = num(4, 512)?;
    let depth = num(6, 64)?;
    let (x0, y0, k0) = (
        num(2, (n - side) / 2)?,
        num(3, (n - side) / 2)?,
        num(5, (n - depth) / 2)?,
    );
    let t0 = Instant::now();
    let loaded = csgpix::voxel::sampled::load_scene(std::path::Path::new(&path))?;
    let grid = Grid::of_scene(&loaded.scene, [n; 3])?;
    let opts = SlicerOptions {
        sampled: loaded.sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&loaded.scene, grid, opts)?;
    let set_up = t0.elapsed().as_secs_f64();
    let eval = BlistEval::new(&loaded.scene.root);
    let columns = PixelBox {
        x0,
        y0,
        x1: x0 + side,
        y1: y0 + side,
    };
    let t1 = Instant::now();
    let (voxels, filled) = runs::voxelize_brick(&slicer, false, &eval, columns, k0..k0 + depth)?;
    let brick = t1.elapsed().as_secs_f64();
    println!(
        "{path}: {n}³ grid, brick x {x0}..{} y {y0}..{} z {k0}..{}: {} voxels, {filled} filled; \
         set-up {set_up:.3} s, brick {brick:.3} s",
        x0 + side,
        y0 + side,
        k0 + depth,
        voxels.len()
    );
    Ok(())
}
