//! The flags of the array every drawing command shares (`--size`, `--model`, `--equations`,
//! `--ties`, `--word`, `--stack-depth`, `--max-memory`, the probes): an [`ArrayOptions`].

use std::path::PathBuf;

use csgpix_run::array_args::{
    parse_probes, parse_range, parse_size, parse_word, ArrayOptions, Model, Probes,
};
use rtl_model::select::vectors::Ties;
use rtl_model::{Equations, WordFormat};

use super::common::{named, MaxMemory};

#[derive(clap::Args, Debug, Clone)]
pub struct ArrayArgs {
    /// Array size WIDTHxHEIGHT (the thesis window is 250x250).
    #[arg(long, default_value = "250x250", value_parser = parse_size)]
    pub size: (usize, usize),
    /// Processor model.
    #[arg(long, value_parser = named::<Model>(), default_value = "cycle")]
    pub model: Model,
    /// Select equations.
    #[arg(long, value_parser = named::<Equations>(), default_value = "derived")]
    pub equations: Equations,
    /// Tie policy of the derived equations (A = F, A = B).
    #[arg(long, value_parser = named::<Ties>(), default_value = "minimal")]
    pub ties: Ties,
    /// Depth word FRACTION/INTEGER/OVERFLOW bits (thesis 10/10/11).
    #[arg(long, default_value = "10/10/11", value_parser = parse_word)]
    pub word: WordFormat,
    /// Levels of the per-pixel clipping stack.
    #[arg(long, default_value_t = 8)]
    pub stack_depth: usize,
    #[command(flatten)]
    pub mem: MaxMemory,
    /// Write a VCD waveform of the probed pixels.
    #[arg(long, requires = "probe")]
    pub vcd: Option<PathBuf>,
    /// Pixels to probe: "x,y;x,y".
    #[arg(long, value_parser = parse_probes)]
    pub probe: Option<Probes>,
    /// Write an SVG timing diagram of the first probed pixel.
    #[arg(long, requires = "probe")]
    pub wave: Option<PathBuf>,
    /// Clocks the timing diagram shows, FIRST..LAST.
    #[arg(long, default_value = "0..120", value_parser = parse_range)]
    pub wave_clocks: (u64, u64),
}

impl ArrayArgs {
    /// The job's array options.
    pub fn options(&self) -> ArrayOptions {
        ArrayOptions {
            size: self.size,
            model: self.model,
            equations: self.equations,
            ties: self.ties,
            word: self.word,
            stack_depth: self.stack_depth,
            max_memory: self.mem.limit(),
            vcd: self.vcd.clone(),
            probe: self.probe.clone(),
            wave: self.wave.clone(),
            wave_clocks: self.wave_clocks,
        }
    }
}
