//! The render job: display lists or a `.csg` scene through the array (§5.2), the composed
//! scene (C, G) as an image.

use crate::Error;
use std::path::PathBuf;
use std::time::Instant;

use csgpix_draw::compile::{clip_scene_ops, scene_ops};
use csgpix_draw::palette::image_rgb;
use csgpix_draw::project::View;
use csgpix_output::{Out, Outputs};
use rtl_model::array::check_program;
use rtl_model::program::{CReg, Op, Reg};
use rtl_model::{Array, ArrayConfig, EquationSet};
use serde::{Deserialize, Serialize};

use super::array_args::{new_array, ArrayOptions, Model};
use crate::progress::{warn_all, Progress};
use crate::read::ReadSettings;
use csgpix_draw::float::{self, ScreenRule};
use csgpix_draw::scenes::Scene;

/// Draw `scenes` on the array and write the image as a PNG. `Default` is the documented
/// defaults (the iso view, the default array, no clip, no panels, no shading); `scenes`
/// and `out` are the caller's.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RenderJob {
    /// Display-list files (§5.2), composed by the second stage; or one OpenSCAD `.csg`
    /// file, projected onto the array, its tree evaluated as a clipping function.
    pub scenes: Vec<PathBuf>,
    /// View direction for a `.csg` scene (the scene's bounds fill the array).
    #[serde(with = "crate::named::by_name")]
    pub view: View,
    /// The PNG (`-`: standard output).
    pub out: PathBuf,
    /// The array and its probes.
    pub array: ArrayOptions,
    /// Clipping function over the objects, named A, B, … in the order given (§5.2.1).
    pub clip: Option<String>,
    /// For a `.csg` scene: panels of NX×NY pixels (§2.5), each running only the solids whose
    /// footprint touches it (None: the whole array).
    pub panel: Option<[usize; 2]>,
    /// Shade by depth (C): nearest drawn depth at full colour, farthest at 45%.
    pub shade: bool,
    /// How the scene is read.
    pub read: ReadSettings,
    /// The caller prints the report on standard output (the command line's `--json`): no
    /// output may go there.
    pub report_on_stdout: bool,
}

impl Default for RenderJob {
    fn default() -> Self {
        RenderJob {
            scenes: vec![],
            view: View::Iso,
            out: PathBuf::new(),
            array: ArrayOptions::default(),
            clip: None,
            panel: None,
            shade: false,
            read: ReadSettings::default(),
            report_on_stdout: false,
        }
    }
}

/// What a render drew and what it took (`--json` prints these fields, in this order).
#[derive(Clone, Debug, Serialize)]
pub struct RenderReport {
    pub model: &'static str,
    pub equations: String,
    pub width: usize,
    pub height: usize,
    pub objects: usize,
    pub planes: usize,
    pub operations: usize,
    pub cycles: u64,
    /// Clipping-stack levels the program needs, which is all the array models (array models).
    pub stack_levels: usize,
    /// Levels the hardware has (`--stack-depth`).
    pub stack_depth: usize,
    /// Pixel-clocks simulated, against the whole screen's: the same unless `--panel` draws a
    /// `.csg` scene on panels (docs/requirements.md).
    pub simulated_pixel_clocks: u64,
    pub full_pixel_clocks: u64,
    /// Hardware time at the thesis's 10 MHz clock.
    pub hardware_seconds: f64,
    pub wall_seconds: f64,
    /// Whether an output went to standard output (the report's line goes to standard error).
    #[serde(skip)]
    pub to_stdout: bool,
}

/// The picture and the clocks of one run, before the image is written.
struct Run {
    drawn: Drawn,
    /// Stack levels the array modelled (0 on panels and for the float reference).
    stack_levels: usize,
    /// Pixel-clocks simulated on panels, when drawn on panels.
    simulated: Option<u64>,
}

impl RenderJob {
    /// The memory plan (docs/memory.md): the array (the whole screen's, or one panel's, the
    /// panels' C words and their lists of solids), the image, the process.
    pub fn estimate(&self) -> crate::Result<u64> {
        Ok(memory_estimate(self, &self.array.config()?))
    }

    /// Name the outputs, check the estimate, compile, draw, write the PNG (and waveforms).
    pub fn run(&self, progress: &dyn Progress) -> crate::Result<RenderReport> {
        let mut outs = Outputs::new();
        let png = outs.file_or_stdout("-o", &self.out, &["png"])?;
        let waves = self.array.wave_outputs(&mut outs)?;
        if self.report_on_stdout && outs.uses_stdout() {
            return Err(Error::options(
                "--json",
                "--json prints to standard output: write the outputs to files",
            ));
        }
        let cfg = self.array.config()?;
        let need = memory_estimate(self, &cfg);
        self.array
            .max_memory
            .check(need, "this render", "lower --size")?;
        let options = self.read.read_options();
        let (scene, ops) = compile_with(
            &self.scenes,
            self.clip.as_deref(),
            self.view,
            &cfg,
            &options,
        )?;
        if let Some(csg) = &scene.csg {
            warn_all(progress, &csg.warnings);
        }
        let t0 = Instant::now();
        let run = self.draw_scene(&scene, &ops, &cfg, (&mut outs, waves), progress)?;
        let drawn = &run.drawn;
        let image = image_rgb(&drawn.colour, self.shade.then_some(&drawn.depth[..]));
        let wall = t0.elapsed().as_secs_f64();
        write_png(&mut outs, png, cfg.width, cfg.height, &image)?;
        let to_stdout = outs.uses_stdout();
        outs.commit()?;
        let mut report = self.report(&scene, &ops, &cfg, &run, wall);
        report.to_stdout = to_stdout;
        Ok(report)
    }

    /// Draw the compiled scene: the float reference, on panels, or on one array (whose
    /// waveforms are staged).
    fn draw_scene(
        &self,
        scene: &Scene,
        ops: &[Op],
        cfg: &ArrayConfig,
        (outs, waves): (&mut Outputs, [Option<Out>; 2]),
        progress: &dyn Progress,
    ) -> crate::Result<Run> {
        if self.array.model == Model::Float {
            if self.array.probe.is_some() {
                let message = "--probe needs an array model (cycle or word)";
                return Err(Error::options("--probe", message));
            }
            let drawn = float_image(scene, cfg);
            return Ok(Run {
                drawn,
                stack_levels: 0,
                simulated: None,
            });
        }
        if let Some([pw, ph]) = self.panel {
            let img = on_panels(self, scene, cfg, (pw, ph))?;
            let depth = img
                .depth
                .iter()
                .map(|&c| Some(cfg.fmt.to_real(c)))
                .collect();
            let cycles = rtl_model::array::program_cycles(cfg, ops);
            let drawn = Drawn {
                colour: img.colour,
                depth,
                cycles,
            };
            return Ok(Run {
                drawn,
                stack_levels: 0,
                simulated: Some(img.simulated_pixel_clocks),
            });
        }
        let (mut arr, stack_levels) = self.array.build(ops)?;
        let drawn = draw_on(arr.as_mut(), ops, progress)?;
        self.array.write_waves(arr.as_mut(), outs, waves)?;
        Ok(Run {
            drawn,
            stack_levels,
            simulated: None,
        })
    }

    /// The report of a run.
    fn report(
        &self,
        scene: &Scene,
        ops: &[Op],
        cfg: &ArrayConfig,
        run: &Run,
        wall: f64,
    ) -> RenderReport {
        let lists = &scene.lists;
        let cycles = run.drawn.cycles;
        RenderReport {
            model: self.array.model.name(),
            equations: self.array.equations_name(),
            width: cfg.width,
            height: cfg.height,
            objects: lists.len(),
            planes: lists.iter().map(|l| l.planes.len()).sum(),
            operations: ops.len(),
            cycles,
            stack_levels: run.stack_levels,
            stack_depth: cfg.stack_depth,
            simulated_pixel_clocks: run.simulated.unwrap_or(cycles * cfg.pixels() as u64),
            full_pixel_clocks: cycles * cfg.pixels() as u64,
            hardware_seconds: cycles as f64 * 1e-7,
            wall_seconds: wall,
            to_stdout: false,
        }
    }
}

/// Load display lists (composed, or clipped by `clip` over objects A, B, … in order, §5.2.1)
/// or one `.csg` scene (projected along `view`) and compile them for the array `cfg`: the
/// scene and its program, every plane checked to fit the window.
pub fn compile(
    scenes: &[PathBuf],
    clip: Option<&str>,
    view: View,
    cfg: &ArrayConfig,
) -> crate::Result<(Scene, Vec<Op>)> {
    compile_with(scenes, clip, view, cfg, &Default::default())
}

/// [`compile`] with the `.csg`/`.scad` reader's options (openscad's time limit).
pub fn compile_with(
    scenes: &[PathBuf],
    clip: Option<&str>,
    view: View,
    cfg: &ArrayConfig,
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
pub fn draw_on(arr: &mut dyn Array, ops: &[Op], progress: &dyn Progress) -> crate::Result<Drawn> {
    run_with_progress(arr, ops, progress)?;
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
/// pieces the render job runs without panels.
pub fn draw(
    scene: &Scene,
    ops: &[Op],
    cfg: &ArrayConfig,
    model: Model,
    set: EquationSet,
    progress: &dyn Progress,
) -> crate::Result<Drawn> {
    if model == Model::Float {
        return Ok(float_image(scene, cfg));
    }
    draw_on(new_array(model, *cfg, set).as_mut(), ops, progress)
}

/// Bytes a render holds per pixel besides the array (docs/memory.md): G and C read out
/// (4 + 16 bytes), the RGB image and the encoder's copy (3 + 3), the PNG (at most about 3).
const IMAGE_BYTES: u64 = 29;

/// The process before any pixel: code, libraries, the scene's planes.
const BASE_BYTES: u64 = 16 << 20;

/// An upper bound of a render's peak memory: the array (the whole screen's, or one panel's,
/// the panels' C words and their lists of solids), the image, the process.
fn memory_estimate(job: &RenderJob, cfg: &ArrayConfig) -> u64 {
    let pixels = cfg.pixels() as u64;
    let model = job.array.model;
    let array = |c: &ArrayConfig| match model {
        Model::Cycle => rtl_model::CycleArray::memory_bytes(c),
        Model::Word => rtl_model::WordArray::memory_bytes(c),
        Model::Float => 0,
    };
    let arrays = match job.panel {
        Some([pw, ph]) if model != Model::Float => {
            let (pw, ph) = csgpix_draw::panels::clamp_panel((pw, ph), (cfg.width, cfg.height));
            let panel = ArrayConfig {
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

/// Run a program, its operations a stage of `progress` when it is long enough to wait for.
pub fn run_with_progress(
    arr: &mut dyn Array,
    ops: &[Op],
    progress: &dyn Progress,
) -> crate::Result<()> {
    check_program(ops, arr.config().stack_depth)?;
    let work = ops.len() as u64 * arr.config().pixels() as u64;
    let shown = work > 50_000_000;
    if shown {
        progress.stage("operations", ops.len() as u64);
    }
    for op in ops {
        arr.step(op)?;
        if shown {
            progress.advance(1);
        }
    }
    arr.finish();
    if shown {
        progress.finish();
    }
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
    outs.write(out, |w| crate::png::write_png(w, &img))?;
    Ok(())
}

/// Draw a `.csg` scene on panels (`--panel`): only the panels its solids touch are simulated.
fn on_panels(
    job: &RenderJob,
    scene: &Scene,
    cfg: &ArrayConfig,
    panel: (usize, usize),
) -> crate::Result<csgpix_draw::panels::PanelImage> {
    let Some(csg) = &scene.csg else {
        let message = "--panel needs one .csg scene (display lists have no footprint)";
        return Err(Error::options("--panel", message));
    };
    if job.array.probe.is_some() {
        let message = "--panel and --probe do not go together: probes watch the whole array";
        return Err(Error::options("--panel", message));
    }
    let ps = csgpix_draw::panels::PanelScene::new(csg, job.view, (cfg.width, cfg.height), cfg.fmt)
        .map_err(|e| super::lib_errors::draw(e).context(job.scenes[0].display().to_string()))?;
    let cycle = job.array.model == Model::Cycle;
    Ok(csgpix_draw::panels::render_on_panels(
        &ps,
        panel,
        cycle,
        &job.array.equations()?,
    )?)
}
