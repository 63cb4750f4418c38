//! Run a program on the array: the thesis's cube (§5.2) as a display list, compiled to the
//! array's operations, run on the bit-serial `cycle` model and on the `word` model, which
//! must agree in every pixel; the image is printed as characters, one per colour code.
//!
//! `cargo run --release --example array_program`

use std::fmt::Write as _;
use std::io::Write as _;

use csgpix::draw::compile::scene_ops;
use csgpix::scene::display_list::DisplayList;
use rtl_model::program::CReg;
use rtl_model::{Array, ArrayConfig, CycleArray, Equations, WordArray};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut out = String::new();
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/vectors/thesis/cube.dl");
    let cube = DisplayList::read(std::path::Path::new(path))?;
    let cfg = ArrayConfig::new(250, 250);
    let ops = scene_ops(&[cube], &cfg.fmt, cfg.colour_bits)
        .map_err(|(plane, e)| format!("plane {plane}: {e}"))?;
    let mut cycle = CycleArray::new(cfg, Equations::Derived.set());
    let mut word = WordArray::new(cfg, Equations::Derived.set());
    cycle.run(&ops)?;
    word.run(&ops)?;
    let colour = |a: &dyn Array, x, y| a.pixel(x, y).creg(CReg::G);
    for y in (0..250).step_by(10) {
        let row: String = (0..250)
            .step_by(5)
            .map(|x| match colour(&cycle, x, y) {
                0 => '.',
                c => char::from_digit(c % 36, 36).unwrap_or('#'),
            })
            .collect();
        writeln!(out, "{row}")?;
    }
    let differ = (0..250 * 250)
        .filter(|i| colour(&cycle, i % 250, i / 250) != colour(&word, i % 250, i / 250))
        .count();
    writeln!(
        out,
        "{} operations, {} clocks; cycle and word differ in {differ} pixels",
        ops.len(),
        cycle.cycles()
    )?;
    // Written at once: a closed pipe (`| head`) is an error, not a panic.
    std::io::stdout().write_all(out.as_bytes())?;
    Ok(())
}
