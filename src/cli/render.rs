//! `csgpix render`: display lists through the array, the composed scene (C, G) as an image.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::ValueEnum;
use csgpix::compile::object_ops;
use csgpix::display_list::DisplayList;
use csgpix::output::write_atomic;
use csgpix::palette::rgb;
use rtl_model::probe::Recorder;
use rtl_model::program::{CReg, Op};
use rtl_model::{Array, ArrayConfig, CycleArray, Equations, WordArray, WordFormat};
use serde::Serialize;

use super::EquationsArg;

#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq)]
pub enum Model {
    /// Bit-serial, clock by clock, bit-sliced.
    #[default]
    Cycle,
    /// One word per pixel, no clock.
    Word,
}

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix render vectors/thesis/cube.dl -o cube.png\n  \
    csgpix render vectors/thesis/box1.dl vectors/thesis/box2.dl --model word --json -o boxes.png\n  \
    csgpix render vectors/thesis/cube.dl --vcd cube.vcd --probe '120,100;10,10' -o cube.png")]
pub struct Args {
    /// Display-list files (thesis §5.2); several objects are composed by the second stage.
    #[arg(required = true)]
    scenes: Vec<PathBuf>,
    /// Output PNG.
    #[arg(short = 'o', long)]
    out: PathBuf,
    /// Array size WIDTHxHEIGHT (the thesis window is 250x250).
    #[arg(long, default_value = "250x250", value_parser = parse_size)]
    size: (usize, usize),
    /// Processor model.
    #[arg(long, value_enum, default_value_t)]
    model: Model,
    /// Select equations.
    #[arg(long, value_enum, default_value_t)]
    equations: EquationsArg,
    /// Depth word FRACTION/INTEGER/OVERFLOW bits (thesis 10/10/11).
    #[arg(long, default_value = "10/10/11", value_parser = parse_word)]
    word: WordFormat,
    /// Levels of the per-pixel clipping stack.
    #[arg(long, default_value_t = 8)]
    stack_depth: usize,
    /// Write a VCD waveform of the probed pixels.
    #[arg(long, requires = "probe")]
    vcd: Option<PathBuf>,
    /// Pixels to probe: "x,y;x,y".
    #[arg(long, value_parser = parse_probes, requires = "vcd")]
    probe: Option<Probes>,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
}

pub fn parse_size(s: &str) -> Result<(usize, usize), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or("expected WIDTHxHEIGHT, e.g. 250x250")?;
    let n = |v: &str| v.trim().parse::<usize>().map_err(|e| format!("{v:?}: {e}"));
    let (w, h) = (n(w)?, n(h)?);
    if w == 0 || h == 0 || w > 16384 || h > 16384 {
        return Err(format!("{w}x{h}: each side must be 1..=16384"));
    }
    Ok((w, h))
}

pub fn parse_word(s: &str) -> Result<WordFormat, String> {
    let f: Vec<&str> = s.split('/').collect();
    let [fr, i, o] = f[..] else {
        return Err("expected FRACTION/INTEGER/OVERFLOW, e.g. 10/10/11".into());
    };
    let n = |v: &str| v.trim().parse::<u32>().map_err(|e| format!("{v:?}: {e}"));
    WordFormat::new(n(fr)?, n(i)?, n(o)?).map_err(|e| e.to_string())
}

/// Probed pixels, as given to `--probe`.
#[derive(Clone, Debug)]
pub struct Probes(pub Vec<(usize, usize)>);

pub fn parse_probes(s: &str) -> Result<Probes, String> {
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
        .collect::<Result<Vec<_>, String>>()?;
    if v.is_empty() {
        return Err("expected at least one x,y".into());
    }
    Ok(Probes(v))
}

#[derive(Serialize)]
struct Report {
    model: &'static str,
    equations: &'static str,
    width: usize,
    height: usize,
    objects: usize,
    planes: usize,
    operations: usize,
    cycles: u64,
    /// Hardware time at the thesis's 10 MHz clock.
    hardware_seconds: f64,
    wall_seconds: f64,
}

/// Build the chosen model.
pub fn build(model: Model, cfg: ArrayConfig, eq: Equations) -> Box<dyn Array> {
    match model {
        Model::Cycle => Box::new(CycleArray::new(cfg, eq.set())),
        Model::Word => Box::new(WordArray::new(cfg, eq.set())),
    }
}

pub fn run(a: Args) -> Result<ExitCode, String> {
    let lists: Vec<DisplayList> = a
        .scenes
        .iter()
        .map(|p| DisplayList::read(p).map_err(|e| e.to_string()))
        .collect::<Result<_, _>>()?;
    let mut cfg = ArrayConfig::new(a.size.0, a.size.1);
    cfg.fmt = a.word;
    cfg.stack_depth = a.stack_depth;
    cfg.check()?;
    let mut ops = vec![];
    for (dl, path) in lists.iter().zip(&a.scenes) {
        ops.extend(
            object_ops(dl, &cfg.fmt, cfg.colour_bits)
                .map_err(|e| format!("{}: {e}", path.display()))?,
        );
        ops.push(Op::Compose { p: false });
    }
    let eq: Equations = a.equations.into();
    let mut arr = build(a.model, cfg, eq);
    if let Some(p) = &a.probe {
        arr.attach_probe(Recorder::new(cfg, p.0.clone())?);
    }
    let t0 = Instant::now();
    arr.run(&ops).map_err(|e| e.to_string())?;
    let wall = t0.elapsed().as_secs_f64();
    write_png(&a.out, &arr.state())?;
    if let (Some(path), Some(rec)) = (&a.vcd, arr.take_probe()) {
        write_atomic(path, |w| rec.write_vcd(w))?;
    }
    let report = Report {
        model: if a.model == Model::Cycle {
            "cycle"
        } else {
            "word"
        },
        equations: eq.name(),
        width: cfg.width,
        height: cfg.height,
        objects: lists.len(),
        planes: lists.iter().map(|l| l.planes.len()).sum(),
        operations: ops.len(),
        cycles: arr.cycles(),
        hardware_seconds: arr.cycles() as f64 * 1e-7,
        wall_seconds: wall,
    };
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?
        );
    } else {
        println!(
            "{}: {} objects, {} planes, {} cycles ({:.1} us at 10 MHz), {:.3} s wall",
            a.out.display(),
            report.objects,
            report.planes,
            report.cycles,
            report.hardware_seconds * 1e6,
            wall
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// The scene colour register G of every pixel, through the palette.
fn write_png(path: &Path, st: &rtl_model::ArchState) -> Result<(), String> {
    let mut img = image::RgbImage::new(st.width as u32, st.height as u32);
    for (i, p) in st.pixels.iter().enumerate() {
        let (x, y) = ((i % st.width) as u32, (i / st.width) as u32);
        img.put_pixel(x, y, image::Rgb(rgb(p.creg(CReg::G))));
    }
    write_atomic(path, |w| {
        let mut buf = std::io::Cursor::new(Vec::new());
        img.write_to(&mut buf, image::ImageFormat::Png)
            .map_err(std::io::Error::other)?;
        w.write_all(buf.get_ref())
    })
}
