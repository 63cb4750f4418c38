//! `csgpix render`: display lists through the array, the composed scene (C, G) as an image.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use csgpix::clip_expr::Clip;
use csgpix::compile::{clip_scene_ops, scene_ops};
use csgpix::display_list::{field_position, DisplayList};
use csgpix::output::write_atomic;
use csgpix::palette::rgb;
use indicatif::{ProgressBar, ProgressStyle};
use rtl_model::array::check_program;
use rtl_model::program::{CReg, Op};
use rtl_model::Array;

use serde::Serialize;

use super::array_args::{ArrayArgs, Model};
use csgpix::float::{self, ScreenRule};

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix render vectors/thesis/cube.dl -o cube.png\n  \
    csgpix render vectors/thesis/box1.dl vectors/thesis/box2.dl --model word --json -o boxes.png\n  \
    csgpix render vectors/thesis/box1.dl vectors/thesis/box2.dl --clip 'A.!B' -o fig5-1e.png\n  \
    csgpix render vectors/thesis/cube.dl --vcd cube.vcd --probe '120,100;10,10' -o cube.png\n  \
    csgpix render vectors/thesis/cube.dl --probe 120,100 --wave cube.svg --wave-clocks 0..120 -o cube.png")]
pub struct Args {
    /// Display-list files (thesis §5.2); several objects are composed by the second stage.
    #[arg(required = true)]
    scenes: Vec<PathBuf>,
    /// Output PNG.
    #[arg(short = 'o', long)]
    out: PathBuf,
    #[command(flatten)]
    array: ArrayArgs,
    /// Clipping function over the objects, named A, B, … in the order given (§5.2.1), e.g.
    /// "A.!B"; each literal is drawn, clipped by the rest of its product and composed.
    #[arg(long)]
    clip: Option<String>,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Report {
    model: &'static str,
    equations: String,
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

pub fn run(a: Args) -> Result<ExitCode, String> {
    let mut lists = vec![];
    let mut texts = vec![];
    for p in &a.scenes {
        let text = std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
        lists.push(DisplayList::parse(&text, &p.display().to_string()).map_err(|e| e.to_string())?);
        texts.push(text);
    }
    let cfg = a.array.config()?;
    let compiled = match clip_expr(&a, &lists)? {
        None => scene_ops(&lists, &cfg.fmt, cfg.colour_bits),
        Some(expr) => clip_scene_ops(&lists, &expr, &cfg.fmt, cfg.colour_bits),
    };
    let ops = compiled.map_err(|(i, e)| {
        let (line, col) = field_position(&texts[i], e.plane, e.field).unwrap_or((1, 1));
        format!("{}:{line}:{col}: {}", a.scenes[i].display(), e.msg)
    })?;
    let t0 = Instant::now();
    let (image, cycles) = if a.array.model == Model::Float {
        if a.array.probe.is_some() {
            return Err("--probe needs an array model (cycle or word)".into());
        }
        let expr = clip_expr(&a, &lists)?;
        let f = float::render(
            &lists,
            expr.as_ref(),
            cfg.width,
            cfg.height,
            &cfg.fmt,
            ScreenRule::Exact,
        );
        (f.colour, 0)
    } else {
        let mut arr = a.array.build()?;
        run_with_progress(arr.as_mut(), &ops)?;
        a.array.write_waves(arr.as_mut())?;
        let st = arr.state();
        (
            st.pixels.iter().map(|p| p.creg(CReg::G)).collect(),
            arr.cycles(),
        )
    };
    let wall = t0.elapsed().as_secs_f64();
    write_png(&a.out, cfg.width, cfg.height, &image)?;
    let report = Report {
        model: a.array.model.name(),
        equations: a.array.equations_name(),
        width: cfg.width,
        height: cfg.height,
        objects: lists.len(),
        planes: lists.iter().map(|l| l.planes.len()).sum(),
        operations: ops.len(),
        cycles,
        hardware_seconds: cycles as f64 * 1e-7,
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

/// The parsed `--clip` function, if any.
fn clip_expr(a: &Args, lists: &[DisplayList]) -> Result<Option<Clip>, String> {
    let Some(text) = &a.clip else { return Ok(None) };
    let names: Vec<String> = (0..lists.len()).map(object_name).collect();
    let expr = Clip::parse(text, &names).map_err(|e| format!("--clip:1:{}: {}", e.col, e.msg))?;
    Ok(Some(expr))
}

/// The name `--clip` uses for the `i`-th object: A … Z, then O26, O27, …
pub fn object_name(i: usize) -> String {
    match u8::try_from(i) {
        Ok(n) if n < 26 => ((b'A' + n) as char).to_string(),
        _ => format!("O{i}"),
    }
}

/// Run a program, with a progress bar on a terminal when it is long enough to wait for.
pub fn run_with_progress(arr: &mut dyn Array, ops: &[Op]) -> Result<(), String> {
    check_program(ops, arr.config().stack_depth).map_err(|e| e.to_string())?;
    let work = ops.len() as u64 * arr.config().pixels() as u64;
    let bar = if work > 50_000_000 {
        ProgressBar::new(ops.len() as u64)
    } else {
        ProgressBar::hidden()
    };
    bar.set_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} operations")
            .map_err(|e| e.to_string())?,
    );
    for op in ops {
        arr.step(op).map_err(|e| e.to_string())?;
        bar.inc(1);
    }
    arr.finish();
    bar.finish_and_clear();
    Ok(())
}

/// Colour codes of every pixel, through the palette.
fn write_png(path: &Path, width: usize, height: usize, codes: &[u32]) -> Result<(), String> {
    let mut img = image::RgbImage::new(width as u32, height as u32);
    for (i, c) in codes.iter().enumerate() {
        img.put_pixel((i % width) as u32, (i / width) as u32, image::Rgb(rgb(*c)));
    }
    write_atomic(path, |w| {
        let mut buf = std::io::Cursor::new(Vec::new());
        img.write_to(&mut buf, image::ImageFormat::Png)
            .map_err(std::io::Error::other)?;
        w.write_all(buf.get_ref())
    })
}
