//! Options every job that runs the array shares (§2.3): size, model, equations and their
//! ties, word format (§2.4.1), stack depth, memory limit, waveform probes; as data, the
//! command line's `--size`, `--model`, `--equations`, … and Python's keyword arguments.

use crate::memory::{default_limit, Limit};
use crate::Error;
use std::path::PathBuf;

use csgpix_output::{Out, Outputs};
use rtl_model::array::check_program;
use rtl_model::probe::Recorder;
use rtl_model::select::vectors::{derive_with_ties, Ties};
use rtl_model::Op;
use rtl_model::{Array, ArrayConfig, CycleArray, EquationSet, Equations, WordArray, WordFormat};
use serde::{Deserialize, Serialize};

pub use csgpix_draw::Model;

named!(Ties: "ties" {
    Ties::Minimal => "minimal": "Whatever the minimum cover does (derived.eqn; see docs/select-logic.md)",
    Ties::Keep => "keep": "A = F or A = B keeps the register: the earlier plane wins",
    Ties::Put => "put": "A = F or A = B puts A: the later plane wins",
});

/// The array a job runs on and what it records of it. `Default` is the documented
/// defaults: the thesis window (250x250), the cycle model, the derived equations with the
/// minimal cover's ties, the thesis word (10/10/11), 8 stack levels, no probes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ArrayOptions {
    /// Array size, width and height in pixels (`--size`).
    pub size: (usize, usize),
    /// Processor model (`--model`).
    #[serde(with = "crate::named::by_name")]
    pub model: Model,
    /// Select equations (`--equations`).
    #[serde(with = "crate::named::by_name")]
    pub equations: Equations,
    /// Tie policy of the derived equations, A = F and A = B (`--ties`).
    #[serde(with = "crate::named::by_name")]
    pub ties: Ties,
    /// Depth word FRACTION/INTEGER/OVERFLOW bits (`--word`).
    #[serde(with = "word_text")]
    pub word: WordFormat,
    /// Levels of the per-pixel clipping stack (`--stack-depth`).
    pub stack_depth: usize,
    /// The memory limit the run's estimate is checked against (`--max-memory`). Not
    /// serialized: it is the machine's (its available memory), and a job read back gets
    /// the default of the machine that reads it.
    #[serde(skip, default = "default_limit")]
    pub max_memory: Limit,
    /// A VCD waveform of the probed pixels (`--vcd`; `-`: standard output).
    pub vcd: Option<PathBuf>,
    /// Pixels to probe (`--probe`).
    pub probe: Option<Probes>,
    /// An SVG timing diagram of the first probed pixel (`--wave`).
    pub wave: Option<PathBuf>,
    /// Clocks the timing diagram shows, first and last (`--wave-clocks`).
    pub wave_clocks: (u64, u64),
}

impl Default for ArrayOptions {
    fn default() -> Self {
        ArrayOptions {
            size: (250, 250),
            model: Model::Cycle,
            equations: Equations::Derived,
            ties: Ties::Minimal,
            word: WordFormat::THESIS,
            stack_depth: 8,
            max_memory: default_limit(),
            vcd: None,
            probe: None,
            wave: None,
            wave_clocks: (0, 120),
        }
    }
}

/// serde of a [`WordFormat`] as the command line spells it: `10/10/11`.
pub mod word_text {
    use rtl_model::WordFormat;

    /// `FRACTION/INTEGER/OVERFLOW`.
    pub fn serialize<S: serde::Serializer>(w: &WordFormat, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(&format_args!("{}/{}/{}", w.frac, w.int, w.ovf))
    }

    /// The word of a text ([`super::parse_word`]).
    pub fn deserialize<'de, D: serde::Deserializer<'de>>(d: D) -> Result<WordFormat, D::Error> {
        use serde::Deserialize;
        let s = <std::borrow::Cow<'de, str>>::deserialize(d)?;
        super::parse_word(&s).map_err(serde::de::Error::custom)
    }
}

/// serde of an `Option<WordFormat>` as [`word_text`] spells it, None as null.
pub mod word_text_opt {
    use rtl_model::WordFormat;

    /// `FRACTION/INTEGER/OVERFLOW`, or null.
    pub fn serialize<S: serde::Serializer>(
        w: &Option<WordFormat>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        match w {
            Some(w) => super::word_text::serialize(w, s),
            None => s.serialize_none(),
        }
    }

    /// The word of a text, or None for null.
    pub fn deserialize<'de, D: serde::Deserializer<'de>>(
        d: D,
    ) -> Result<Option<WordFormat>, D::Error> {
        use serde::Deserialize;
        let s = <Option<std::borrow::Cow<'de, str>>>::deserialize(d)?;
        s.map(|s| super::parse_word(&s).map_err(serde::de::Error::custom))
            .transpose()
    }
}

/// Probed pixels, as given to `--probe`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Probes(pub Vec<(usize, usize)>);

/// `--size`: WIDTHxHEIGHT, each 1..=65536.
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

/// `--word`: FRACTION/INTEGER/OVERFLOW bits, a word the model takes.
pub fn parse_word(s: &str) -> crate::error::Parsed<WordFormat> {
    let f: Vec<&str> = s.split('/').collect();
    let [fr, i, o] = f[..] else {
        return Err("expected FRACTION/INTEGER/OVERFLOW, e.g. 10/10/11".into());
    };
    let n = |v: &str| v.trim().parse::<u32>().map_err(|e| format!("{v:?}: {e}"));
    WordFormat::new(n(fr)?, n(i)?, n(o)?).map_err(|e| e.to_string().into())
}

/// `--wave-clocks`: FIRST..LAST, at most 100000 clocks.
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

/// `--probe`: "x,y;x,y", at least one pixel.
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

/// The equation set SGENE is built from (§2.3.3): `eq`, its ties settled by `ties` (the
/// derived equations only; the printed ones fix their own).
pub fn equation_set(eq: Equations, ties: Ties) -> crate::Result<EquationSet> {
    match (eq, ties) {
        (_, Ties::Minimal) => Ok(eq.set()),
        (Equations::Printed, _) => Err(Error::options(
            "--ties",
            "--ties applies to the derived equations; the printed ones fix their own ties",
        )),
        (Equations::Derived, t) => Ok(derive_with_ties(t)?),
    }
}

impl ArrayOptions {
    /// The array's configuration, checked ([`array_config`]).
    pub fn config(&self) -> crate::Result<ArrayConfig> {
        array_config(self.size, self.word, self.stack_depth)
    }

    /// The equation set SGENE is built from ([`equation_set`]).
    pub fn equations(&self) -> crate::Result<EquationSet> {
        equation_set(self.equations, self.ties)
    }

    /// The name of the equation set [`ArrayOptions::equations`] builds.
    pub fn equations_name(&self) -> String {
        let eq = self.equations;
        match self.ties {
            Ties::Minimal => eq.name().into(),
            Ties::Keep => format!("{}, ties keep", eq.name()),
            Ties::Put => format!("{}, ties put", eq.name()),
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
        self.max_memory.check(need, &what, "lower --size")?;
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

    /// Stage the VCD and the SVG timing diagram named by [`ArrayOptions::wave_outputs`].
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
