//! `csgpix render`: display lists or a `.csg` scene through the array, the composed scene
//! (C, G) as an image.

use crate::Error;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use csgpix_draw::compile::{clip_scene_ops, scene_ops};
use csgpix_draw::palette::image_rgb;
use csgpix_output::{Out, Outputs};
use indicatif::{ProgressBar, ProgressStyle};
use rtl_model::array::check_program;
use rtl_model::program::{CReg, Op, Reg};
use rtl_model::{Array, ArrayConfig, EquationSet};

use serde::Serialize;

use super::array_args::{new_array, ArrayArgs, Model};
use super::ViewArg;
use csgpix_draw::float::{self, ScreenRule};
use csgpix_draw::scenes::Scene;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix render vectors/thesis/cube.dl -o cube.png\n  \
    csgpix render vectors/scenes/cube-minus-cylinder.csg --view iso --shade -o scene.png\n  \
    csgpix render vectors/scenes/twelve.csg --panel 32x32 --json -o twelve.png\n  \
    csgpix render vectors/thesis/box1.dl vectors/thesis/box2.dl --model word --json -o boxes.png\n  \
    csgpix render vectors/thesis/box1.dl vectors/thesis/box2.dl --clip 'A.!B' -o fig5-1e.png\n  \
    csgpix render vectors/thesis/cube.dl --vcd cube.vcd --probe '120,100;10,10' -o cube.png\n  \
    csgpix render vectors/thesis/cube.dl --probe 120,100 --wave cube.svg --wave-clocks 0..120 -o cube.png")]
pub struct Args {
    /// Display-list files (thesis §5.2), composed by the second stage; or one OpenSCAD `.csg`
    /// file, projected onto the array, its tree evaluated as a clipping function.
    #[arg(required = true)]
    scenes: Vec<PathBuf>,
    /// View direction for a `.csg` scene (the scene's bounds fill the array).
    #[arg(long, value_enum, default_value_t)]
    view: ViewArg,
    /// Output PNG (`-`: standard output).
    #[arg(short = 'o', long)]
    out: PathBuf,
    #[command(flatten)]
    array: ArrayArgs,
    /// Clipping function over the objects, named A, B, … in the order given (§5.2.1), e.g.
    /// "A.!B"; each literal is drawn, clipped by the rest of its product and composed.
    #[arg(long)]
    clip: Option<String>,
    /// For a `.csg` scene: draw on panels of NXxNY pixels (§2.5), each running only the solids
    /// whose footprint touches it; panels no solid touches are not simulated. Same image.
    #[arg(long, value_parser = super::voxelize::parse_panel)]
    panel: Option<super::voxelize::PanelArg>,
    /// Shade by depth (C): nearest drawn depth at full colour, farthest at 45%.
    #[arg(long)]
    shade: bool,
    /// Print figures as JSON.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    openscad: super::read_args::ReadArgs,
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
    /// Clipping-stack levels the program needs, which is all the array models (array models).
    stack_levels: usize,
    /// Levels the hardware has (`--stack-depth`).
    stack_depth: usize,
    /// Pixel-clocks simulated, against the whole screen's: the same unless `--panel` draws a
    /// `.csg` scene on panels (docs/requirements.md).
    simulated_pixel_clocks: u64,
    full_pixel_clocks: u64,
    /// Hardware time at the thesis's 10 MHz clock.
    hardware_seconds: f64,
    wall_seconds: f64,
}

/// Load display lists (composed, or clipped by `clip` over objects A, B, … in order, §5.2.1)
/// or one `.csg` scene (projected along `view`) and compile them for the array `cfg`: the
/// scene and its program, every plane checked to fit the window.
pub fn compile(
    scenes: &[PathBuf],
    clip: Option<&str>,
    view: csgpix_draw::project::View,
    cfg: &rtl_model::ArrayConfig,
) -> crate::Result<(Scene, Vec<Op>)> {
    compile_with(scenes, clip, view, cfg, &Default::default())
}

/// [`compile`] with the `.csg`/`.scad` reader's options (openscad's time limit).
pub fn compile_with(
    scenes: &[PathBuf],
    clip: Option<&str>,
    view: csgpix_draw::project::View,
    cfg: &rtl_model::ArrayConfig,
    options: &csgpix_openscad::ReadOptions,
) -> crate::Result<(Scene, Vec<Op>)> {
    let scene =
        Scene::load_with(scenes, clip, view, cfg, options).map_err(super::lib_errors::load)?;
    let locate = |(i, e)| Error::Scene(scene.locate_error(i, &e));
    csgpix_draw::compile::check_window(&scene.lists, &cfg.fmt, cfg.width, cfg.height)
        .map_err(locate)?;
    let compiled = match (&scene.clip, scene.empty) {
        (_, true) => Ok(vec![]),
        (None, false) => scene_ops(&scene.lists, &cfg.fmt, cfg.colour_bits),
        (Some(expr), false) => clip_scene_ops(&scene.lists, expr, &cfg.fmt, cfg.colour_bits),
    };
    let ops = compiled.map_err(locate)?;
    Ok((scene, ops))
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let mut outs = Outputs::new();
    let png = outs.file_or_stdout("-o", &a.out, &["png"])?;
    let waves = a.array.wave_outputs(&mut outs)?;
    if a.json && outs.uses_stdout() {
        return Err(Error::options(
            "--json",
            "--json prints to standard output: write the outputs to files",
        ));
    }
    let cfg = a.array.config()?;
    a.array
        .mem
        .check(memory_estimate(&a, &cfg), "this render", "lower --size")?;
    let options = a.openscad.read_options();
    let (scene, ops) = compile_with(&a.scenes, a.clip.as_deref(), a.view.into(), &cfg, &options)?;
    if let Some(csg) = &scene.csg {
        crate::read_args::print_warnings(&csg.warnings);
    }
    let t0 = Instant::now();
    let mut stack_levels = 0;
    let mut simulated = None;
    let drawn = if a.array.model == Model::Float {
        if a.array.probe.is_some() {
            let message = "--probe needs an array model (cycle or word)";
            return Err(Error::options("--probe", message));
        }
        float_image(&scene, &cfg)
    } else if let Some([pw, ph]) = a.panel.and_then(|p| p.0) {
        let img = on_panels(&a, &scene, &cfg, (pw, ph))?;
        simulated = Some(img.simulated_pixel_clocks);
        let depth = img
            .depth
            .iter()
            .map(|&c| Some(cfg.fmt.to_real(c)))
            .collect();
        let cycles = rtl_model::array::program_cycles(&cfg, &a.array.equations()?, &ops);
        Drawn {
            colour: img.colour,
            depth,
            cycles,
        }
    } else {
        let (mut arr, levels) = a.array.build(&ops)?;
        stack_levels = levels;
        let drawn = draw_on(arr.as_mut(), &ops)?;
        a.array.write_waves(arr.as_mut(), &mut outs, waves)?;
        drawn
    };
    let cycles = drawn.cycles;
    let image = image_rgb(&drawn.colour, a.shade.then_some(&drawn.depth[..]));
    let wall = t0.elapsed().as_secs_f64();
    write_png(&mut outs, png, cfg.width, cfg.height, &image)?;
    let to_stdout = outs.uses_stdout();
    outs.commit()?;
    let lists = &scene.lists;
    let report = Report {
        model: a.array.model.name(),
        equations: a.array.equations_name(),
        width: cfg.width,
        height: cfg.height,
        objects: lists.len(),
        planes: lists.iter().map(|l| l.planes.len()).sum(),
        operations: ops.len(),
        cycles,
        stack_levels,
        stack_depth: cfg.stack_depth,
        simulated_pixel_clocks: simulated.unwrap_or(cycles * cfg.pixels() as u64),
        full_pixel_clocks: cycles * cfg.pixels() as u64,
        hardware_seconds: cycles as f64 * 1e-7,
        wall_seconds: wall,
    };
    if a.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        let line = format!(
            "{}: {} objects, {} planes, {} cycles ({:.1} us at 10 MHz), {:.3} s wall",
            a.out.display(),
            report.objects,
            report.planes,
            report.cycles,
            report.hardware_seconds * 1e6,
            wall
        );
        super::report_line(&line, to_stdout);
    }
    Ok(ExitCode::SUCCESS)
}

/// A scene as a model drew it: every pixel's colour code (G) and depth (C, in scene depth
/// units; None where the float reference drew nothing), row-major, and the clocks taken
/// (0 for the float reference, which has none).
pub struct Drawn {
    /// G, pixel by pixel: the palette's colour codes.
    pub colour: Vec<u32>,
    /// C, pixel by pixel.
    pub depth: Vec<Option<f64>>,
    /// The array's clocks, DEPGEN's fill and the flush window included.
    pub cycles: u64,
}

/// The float reference's picture of `scene` on the array `cfg`: exact depth intervals, the
/// screen's edge as the array's (§5.2); no clock.
pub fn float_image(scene: &Scene, cfg: &ArrayConfig) -> Drawn {
    let (lists, clip) = (&scene.lists, scene.clip.as_ref());
    let (w, h) = (cfg.width, cfg.height);
    let f = float::render(lists, clip, w, h, &cfg.fmt, ScreenRule::Exact);
    Drawn {
        colour: f.colour,
        depth: f.depth,
        cycles: 0,
    }
}

/// Run `ops` on `arr` ([`run_with_progress`]) and read every pixel's G and C out.
pub fn draw_on(arr: &mut dyn Array, ops: &[Op]) -> crate::Result<Drawn> {
    run_with_progress(arr, ops)?;
    let cfg = *arr.config();
    // G and C pixel by pixel: a copy of every register would be 64 bytes a pixel.
    let (colour, depth) = (0..cfg.pixels())
        .map(|i| arr.pixel(i % cfg.width, i / cfg.width))
        .map(|p| (p.creg(CReg::G), Some(cfg.fmt.to_real(p.reg(Reg::C)))))
        .unzip();
    Ok(Drawn {
        colour,
        depth,
        cycles: arr.cycles(),
    })
}

/// `scene`, compiled to `ops` for the array `cfg` ([`compile`]), drawn by `model`: the
/// float reference's picture ([`float_image`]), or a fresh array's of `cfg` running `set`
/// (§2.3.3) after the whole program ([`draw_on`]): the Python binding's `render`, from the
/// pieces the command line's `render` runs without panels.
pub fn draw(
    scene: &Scene,
    ops: &[Op],
    cfg: &ArrayConfig,
    model: Model,
    set: EquationSet,
) -> crate::Result<Drawn> {
    if model == Model::Float {
        return Ok(float_image(scene, cfg));
    }
    draw_on(new_array(model, *cfg, set).as_mut(), ops)
}

/// Bytes a render holds per pixel besides the array (docs/memory.md): G and C read out
/// (4 + 16 bytes), the RGB image and the encoder's copy (3 + 3), the PNG (at most about 3).
const IMAGE_BYTES: u64 = 29;

/// The process before any pixel: code, libraries, the scene's planes.
const BASE_BYTES: u64 = 16 << 20;

/// An upper bound of a render's peak memory: the array (the whole screen's, or one panel's,
/// the panels' C words and their lists of solids), the image, the process.
fn memory_estimate(a: &Args, cfg: &rtl_model::ArrayConfig) -> u64 {
    let pixels = cfg.pixels() as u64;
    let array = |c: &rtl_model::ArrayConfig| match a.array.model {
        Model::Cycle => rtl_model::CycleArray::memory_bytes(c),
        Model::Word => rtl_model::WordArray::memory_bytes(c),
        Model::Float => 0,
    };
    let arrays = match a.panel.and_then(|p| p.0) {
        Some([pw, ph]) if a.array.model != Model::Float => {
            let (pw, ph) = csgpix_draw::panels::clamp_panel((pw, ph), (cfg.width, cfg.height));
            let panel = rtl_model::ArrayConfig {
                width: pw,
                height: ph,
                ..*cfg
            };
            // Per panel its list of solids (a vector and an index at least, 32 bytes).
            let (cols, rows) = csgpix_draw::panels::tiling((cfg.width, cfg.height), (pw, ph));
            let lists = (cols as u64 * rows as u64).saturating_mul(32);
            array(&panel)
                .saturating_add(pixels * 8)
                .saturating_add(lists)
        }
        _ => array(cfg),
    };
    arrays
        .saturating_add(pixels.saturating_mul(IMAGE_BYTES))
        .saturating_add(BASE_BYTES)
}

/// Run a program, with a progress bar on a terminal when it is long enough to wait for.
pub fn run_with_progress(arr: &mut dyn Array, ops: &[Op]) -> crate::Result<()> {
    check_program(ops, arr.config().stack_depth)?;
    let work = ops.len() as u64 * arr.config().pixels() as u64;
    let bar = if work > 50_000_000 {
        ProgressBar::new(ops.len() as u64)
    } else {
        ProgressBar::hidden()
    };
    let template = "{elapsed_precise} [{bar:40}] {pos}/{len} operations";
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style);
    }
    for op in ops {
        arr.step(op)?;
        bar.inc(1);
    }
    arr.finish();
    bar.finish_and_clear();
    Ok(())
}

/// Stage the RGB of every pixel as a PNG.
fn write_png(
    outs: &mut Outputs,
    out: Out,
    width: usize,
    height: usize,
    pixels: &[[u8; 3]],
) -> crate::Result<()> {
    let mut img = image::RgbImage::new(width as u32, height as u32);
    for (i, c) in pixels.iter().enumerate() {
        img.put_pixel((i % width) as u32, (i / width) as u32, image::Rgb(*c));
    }
    outs.write(out, |w| {
        let mut buf = std::io::Cursor::new(Vec::new());
        img.write_to(&mut buf, image::ImageFormat::Png)
            .map_err(std::io::Error::other)?;
        w.write_all(buf.get_ref())
    })?;
    Ok(())
}

/// Draw a `.csg` scene on panels (`--panel`): only the panels its solids touch are simulated.
fn on_panels(
    a: &Args,
    scene: &Scene,
    cfg: &rtl_model::ArrayConfig,
    panel: (usize, usize),
) -> crate::Result<csgpix_draw::panels::PanelImage> {
    let Some(csg) = &scene.csg else {
        let message = "--panel needs one .csg scene (display lists have no footprint)";
        return Err(Error::options("--panel", message));
    };
    if a.array.probe.is_some() {
        let message = "--panel and --probe do not go together: probes watch the whole array";
        return Err(Error::options("--panel", message));
    }
    let ps =
        csgpix_draw::panels::PanelScene::new(csg, a.view.into(), (cfg.width, cfg.height), cfg.fmt)
            .map_err(|e| super::lib_errors::draw(e).context(a.scenes[0].display().to_string()))?;
    let cycle = a.array.model == Model::Cycle;
    Ok(csgpix_draw::panels::render_on_panels(
        &ps,
        panel,
        cycle,
        &a.array.equations()?,
    )?)
}
