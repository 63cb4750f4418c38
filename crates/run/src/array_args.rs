//! Options every command that runs the array shares: size, model, equations, word format,
//! stack depth, memory limit, waveform probes.

use crate::Error;
use std::path::PathBuf;

use clap::ValueEnum;
use csgpix_output::{Out, Outputs};
use rtl_model::array::check_program;
use rtl_model::probe::Recorder;
use rtl_model::select::vectors::{derive_with_ties, Ties};
use rtl_model::Op;
use rtl_model::{Array, ArrayConfig, CycleArray, EquationSet, Equations, WordArray, WordFormat};

pub use csgpix_draw::Model;

use super::EquationsArg;

/// How the `derived` equations settle the ties the thesis leaves to the user.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq)]
pub enum TiesArg {
    /// Whatever the minimum cover does (derived.eqn; see docs/select-logic.md).
    #[default]
    Minimal,
    /// A = F or A = B keeps the register: the earlier plane wins.
    Keep,
    /// A = F or A = B puts A: the later plane wins.
    Put,
}

#[derive(clap::Args, Debug, Clone)]
pub struct ArrayArgs {
    /// Array size WIDTHxHEIGHT (the thesis window is 250x250).
    #[arg(long, default_value = "250x250", value_parser = parse_size)]
    pub size: (usize, usize),
    /// Processor model.
    #[arg(long, value_parser = super::model_parser(), default_value = "cycle")]
    pub model: Model,
    /// Select equations.
    #[arg(long, value_enum, default_value_t)]
    pub equations: EquationsArg,
    /// Tie policy of the derived equations (A = F, A = B).
    #[arg(long, value_enum, default_value_t)]
    pub ties: TiesArg,
    /// Depth word FRACTION/INTEGER/OVERFLOW bits (thesis 10/10/11).
    #[arg(long, default_value = "10/10/11", value_parser = parse_word)]
    pub word: WordFormat,
    /// Levels of the per-pixel clipping stack.
    #[arg(long, default_value_t = 8)]
    pub stack_depth: usize,
    #[command(flatten)]
    pub mem: super::memory::MaxMemory,
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

/// Probed pixels, as given to `--probe`.
#[derive(Clone, Debug)]
pub struct Probes(pub Vec<(usize, usize)>);

pub fn parse_size(s: &str) -> crate::error::Parsed<(usize, usize)> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or("expected WIDTHxHEIGHT, e.g. 250x250")?;
    let n = |v: &str| v.trim().parse::<usize>().map_err(|e| format!("{v:?}: {e}"));
    let (w, h) = (n(w)?, n(h)?);
    if w == 0 || h == 0 || w > 65536 || h > 65536 {
        return Err(crate::error::BadValue(format!(
            "{w}x{h}: each side must be 1..=65536"
        )));
    }
    Ok((w, h))
}

pub fn parse_word(s: &str) -> crate::error::Parsed<WordFormat> {
    let f: Vec<&str> = s.split('/').collect();
    let [fr, i, o] = f[..] else {
        return Err("expected FRACTION/INTEGER/OVERFLOW, e.g. 10/10/11".into());
    };
    let n = |v: &str| v.trim().parse::<u32>().map_err(|e| format!("{v:?}: {e}"));
    WordFormat::new(n(fr)?, n(i)?, n(o)?).map_err(|e| e.to_string().into())
}

pub fn parse_range(s: &str) -> crate::error::Parsed<(u64, u64)> {
    let (a, b) = s
        .split_once("..")
        .ok_or("expected FIRST..LAST, e.g. 0..120")?;
    let n = |v: &str| v.trim().parse::<u64>().map_err(|e| format!("{v:?}: {e}"));
    let (a, b) = (n(a)?, n(b)?);
    if a > b || b - a > 100_000 {
        return Err(crate::error::BadValue(format!(
            "{a}..{b}: need FIRST <= LAST and at most 100000 clocks"
        )));
    }
    Ok((a, b))
}

pub fn parse_probes(s: &str) -> crate::error::Parsed<Probes> {
    let v = s
        .split(';')
        .filter(|p| !p.trim().is_empty())
        .map(|p| {
            let (x, y) = p
                .split_once(',')
                .ok_or_else(|| format!("{p:?}: expected x,y"))?;
            let n = |v: &str| v.trim().parse::<usize>().map_err(|e| format!("{v:?}: {e}"));
            Ok((n(x)?, n(y)?))
        })
        .collect::<crate::error::Parsed<Vec<_>>>()?;
    if v.is_empty() {
        return Err("expected at least one x,y".into());
    }
    Ok(Probes(v))
}

/// The configuration of a `width`×`height` array with depth words `word` (§2.3.1) and
/// `stack_depth` clipping-stack levels, checked (`--size`, `--word`, `--stack-depth`; the
/// Python binding's `compile`).
pub fn array_config(
    (width, height): (usize, usize),
    word: WordFormat,
    stack_depth: usize,
) -> crate::Result<ArrayConfig> {
    let mut cfg = ArrayConfig::new(width, height);
    cfg.fmt = word;
    // Colour registers move within a window, so a very short word narrows them too.
    cfg.colour_bits = cfg.colour_bits.min(cfg.fmt.bits());
    cfg.stack_depth = stack_depth;
    cfg.check()?;
    Ok(cfg)
}

/// A fresh array of `cfg` on `model` running `set`: the word model's for
/// [`Model::Word`], else the cycle model's (the float model has no array: callers take it
/// apart first).
pub fn new_array(model: Model, cfg: ArrayConfig, set: EquationSet) -> Box<dyn Array> {
    match model {
        Model::Word => Box::new(WordArray::new(cfg, set)),
        _ => Box::new(CycleArray::new(cfg, set)),
    }
}

impl ArrayArgs {
    /// The array's configuration, checked ([`array_config`]).
    pub fn config(&self) -> crate::Result<ArrayConfig> {
        array_config(self.size, self.word, self.stack_depth)
    }

    /// The equation set SGENE is built from.
    pub fn equations(&self) -> crate::Result<EquationSet> {
        let eq: Equations = self.equations.into();
        match (eq, self.ties) {
            (_, TiesArg::Minimal) => Ok(eq.set()),
            (Equations::Printed, _) => Err(Error::options(
                "--ties",
                "--ties applies to the derived equations; the printed ones fix their own ties",
            )),
            (Equations::Derived, TiesArg::Keep) => Ok(derive_with_ties(Ties::Keep)?),
            (Equations::Derived, TiesArg::Put) => Ok(derive_with_ties(Ties::Put)?),
        }
    }

    /// The name of the equation set [`ArrayArgs::equations`] builds.
    pub fn equations_name(&self) -> String {
        let eq: Equations = self.equations.into();
        match self.ties {
            TiesArg::Minimal => eq.name().into(),
            TiesArg::Keep => format!("{}, ties keep", eq.name()),
            TiesArg::Put => format!("{}, ties put", eq.name()),
        }
    }

    /// Build the chosen model for `ops`, after checking its memory estimate against
    /// `--max-memory`. The array gets only the clipping-stack levels `ops` use (at most
    /// `--stack-depth`, else the program is refused): the levels no operation reaches hold 0
    /// throughout, so the state is the same, and the cycle model stores one bit-plane less per
    /// level. Returns the array and the levels modelled.
    pub fn build(&self, ops: &[Op]) -> crate::Result<(Box<dyn Array>, usize)> {
        let mut cfg = self.config()?;
        cfg.stack_depth = check_program(ops, cfg.stack_depth)?;
        let need = match self.model {
            Model::Cycle => CycleArray::memory_bytes(&cfg),
            Model::Word => WordArray::memory_bytes(&cfg),
            Model::Float => {
                return Err(Error::options(
                    "--model",
                    "the float model is not an array: it has no registers or clock",
                ))
            }
        };
        let what = format!("a {}x{} {} array", cfg.width, cfg.height, self.model.name());
        self.mem.check(need, &what, "lower --size")?;
        let set = self.equations()?;
        let mut arr = new_array(self.model, cfg, set);
        if let Some(p) = &self.probe {
            arr.attach_probe(Recorder::new(cfg, p.0.clone())?);
        }
        Ok((arr, cfg.stack_depth))
    }

    /// Name the VCD and the SVG timing diagram among the run's outputs, if asked for.
    pub fn wave_outputs(&self, outs: &mut Outputs) -> crate::Result<[Option<Out>; 2]> {
        let vcd = self
            .vcd
            .as_ref()
            .map(|p| outs.file_or_stdout("--vcd", p, &["vcd"]));
        let svg = self
            .wave
            .as_ref()
            .map(|p| outs.file_or_stdout("--wave", p, &["svg"]));
        Ok([vcd.transpose()?, svg.transpose()?])
    }

    /// Stage the VCD and the SVG timing diagram named by [`ArrayArgs::wave_outputs`].
    pub fn write_waves(
        &self,
        arr: &mut dyn Array,
        outs: &mut Outputs,
        [vcd, svg]: [Option<Out>; 2],
    ) -> crate::Result<()> {
        let Some(rec) = arr.take_probe() else {
            return Ok(());
        };
        if let Some(out) = vcd {
            outs.write(out, |w| rec.write_vcd(w))?;
        }
        if let Some(out) = svg {
            let (t0, t1) = self.wave_clocks;
            outs.write(out, |w| rec.write_svg(w, 0, t0, t1))?;
        }
        Ok(())
    }
}
