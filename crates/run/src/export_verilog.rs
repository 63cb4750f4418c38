//! The export-verilog job: the Verilog twin of SGENE and its checks (docs/verilog.md); with
//! `scene`, a directory from which `tb_array` runs a scene and checks every register of
//! every pixel after every clock against the `cycle` model (docs/verilog.md, "Running
//! tb_array from the CLI").

use crate::memory::Limit;
use crate::Error;
use std::path::{Path, PathBuf};

use csgpix_draw::compile::{clip_scene_ops, coeffs, scene_ops, CompileError};
use csgpix_draw::project::View;
use csgpix_output::{Out, Outputs};
use rtl_model::array::{check_program, program_cycles};
use rtl_model::program::{translate, Op};
use rtl_model::verilog::stimulus::StatesError;
use rtl_model::verilog::{pixel, stimulus};
use rtl_model::{ArrayConfig, CycleArray, Equations, WordFormat};
use serde::{Deserialize, Serialize};

use crate::generated::{write_generated, GeneratedReport};
use crate::memory::default_limit;
use crate::progress::Progress;
use csgpix_draw::scenes::Scene;

/// Write (or check) the Verilog twin, or with `scene` the directory `tb_array` runs it from.
/// `Default` is the documented defaults: `rtl-model/verilog`, a 16x16 array at the screen's
/// origin, the thesis word.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ExportVerilogJob {
    /// The directory to write (or check) the files in (`-o`): `rtl-model/verilog` when None;
    /// with `scene` it must be given.
    pub out: Option<PathBuf>,
    /// Only compare with the files in the directory (`--check`).
    pub check: bool,
    /// Display lists (§5.2), objects A, B, …; or one OpenSCAD `.csg`/`.scad` scene
    /// (`--scene`).
    pub scene: Vec<PathBuf>,
    /// Clipping function over the objects, as for `render` (§5.2.1).
    pub clip: Option<String>,
    /// The array's width and height (`--size`).
    pub size: (usize, usize),
    /// The screen pixel X,Y the array's pixel (0, 0) shows (`--origin`).
    pub origin: (usize, usize),
    /// Depth word FRACTION/INTEGER/OVERFLOW bits (`--word`).
    #[serde(with = "crate::array_args::word_text")]
    pub word: WordFormat,
    /// The memory limit (`--max-memory`); not serialized: it is the machine's.
    #[serde(skip, default = "default_limit")]
    pub max_memory: Limit,
}

impl Default for ExportVerilogJob {
    fn default() -> Self {
        ExportVerilogJob {
            out: None,
            check: false,
            scene: vec![],
            clip: None,
            size: (16, 16),
            origin: (0, 0),
            word: WordFormat::THESIS,
            max_memory: default_limit(),
        }
    }
}

/// What the job wrote or found.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum ExportVerilogReport {
    /// The Verilog twin, written or checked.
    Generated(GeneratedReport),
    /// A scene's `tb_array` directory.
    Scene(SceneFiles),
}

/// A scene's `tb_array` directory, written: what it holds and the line `tb_array` must print.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SceneFiles {
    /// The directory.
    pub dir: PathBuf,
    /// The generated files, in order (then `expected.hex` and `expected.png`).
    pub files: Vec<String>,
    /// Bytes of `expected.hex`.
    pub expected_bytes: usize,
    /// Clocks `expected.hex` holds (the program's and the idle one).
    pub clocks: u64,
    /// The array's width and height.
    pub size: (usize, usize),
    /// The line `tb_array` prints when every register matches.
    pub summary: String,
}

impl ExportVerilogJob {
    /// The memory plan: with a scene, the cycle model, the control stream, the sources and
    /// one clock's expected states (the file is written a clock at a time; `need`); else
    /// nothing grows.
    pub fn estimate(&self) -> crate::Result<u64> {
        if self.scene.is_empty() {
            return Ok(0);
        }
        let cfg = config(self)?;
        let ops = program(self, &cfg)?;
        let cycles = program_cycles(&cfg, &ops);
        Ok(need(&cfg, cycles))
    }

    /// Write or check the twin, or a scene's directory.
    pub fn run(&self, _: &dyn Progress) -> crate::Result<ExportVerilogReport> {
        if !self.scene.is_empty() {
            return scene(self).map(ExportVerilogReport::Scene);
        }
        let out = self
            .out
            .as_deref()
            .unwrap_or(Path::new("rtl-model/verilog"));
        let files = rtl_model::verilog::files()?;
        Ok(ExportVerilogReport::Generated(write_generated(
            &files, out, self.check,
        )?))
    }
}

/// `--origin`: X,Y, each at most 2^20.
pub fn parse_origin(s: &str) -> crate::error::Parsed<(usize, usize)> {
    let (x, y) = s.split_once(',').ok_or("expected X,Y, e.g. 56,90")?;
    let n = |v: &str| v.trim().parse::<usize>().map_err(|e| format!("{v:?}: {e}"));
    let (x, y) = (n(x)?, n(y)?);
    if x > 1 << 20 || y > 1 << 20 {
        return Err(crate::error::BadValue(format!(
            "{x},{y}: each coordinate must be at most 1048576"
        )));
    }
    Ok((x, y))
}

/// The array the scene runs on: `--size`, `--word`, the thesis colours and stack.
fn config(a: &ExportVerilogJob) -> crate::Result<ArrayConfig> {
    let mut cfg = ArrayConfig::new(a.size.0, a.size.1);
    cfg.fmt = a.word;
    // Colour registers move within a window, so a very short word narrows them too.
    cfg.colour_bits = cfg.colour_bits.min(cfg.fmt.bits());
    cfg.check()?;
    Ok(cfg)
}

/// `--scene`: compile, bound, simulate clock by clock, stage every file, commit.
fn scene(a: &ExportVerilogJob) -> crate::Result<SceneFiles> {
    let Some(dir) = &a.out else {
        let message = "--scene needs -o DIR (rtl-model/verilog holds no stimulus)";
        return Err(Error::options("-o", message));
    };
    let mut outs = Outputs::new();
    let out = outs.dir("-o", dir)?;
    let cfg = config(a)?;
    let ops = program(a, &cfg)?;
    let set = Equations::Derived.set();
    check_program(&ops, cfg.stack_depth)?;
    let cycles = program_cycles(&cfg, &ops);
    bound(a, &cfg, cycles)?;
    room(&outs, out, &cfg, cycles)?;
    let control = pixel::control_stream(&cfg, &set, &ops);
    let mut files = stimulus::array_files(&cfg);
    let machine = stimulus::machine_files(&cfg, &ops);
    files.extend(machine.map_err(|e| Error::options("--scene", e.to_string()))?);
    files.push(("control.hex".into(), control));
    let want = write_expected(&mut outs, out, cfg, &ops, &set)?;
    files.push(("run.sh".into(), stimulus::run_script(&want.summary())));
    for (name, text) in &files {
        outs.write_in(out, name, |w| w.write_all(text.as_bytes()))?;
    }
    make_executable(&mut outs, out, "run.sh")?;
    write_image(&mut outs, out, &cfg, &want.image())?;
    outs.commit()?;
    Ok(SceneFiles {
        dir: dir.clone(),
        files: files.into_iter().map(|(name, _)| name).collect(),
        expected_bytes: stimulus::expected_bytes(&cfg, want.cycles) as usize,
        clocks: want.cycles + 1,
        size: (cfg.width, cfg.height),
        summary: want.summary(),
    })
}

/// The scene's program for the window at `--origin`: display lists compiled as `render`
/// compiles them, then moved so the array's pixel (0, 0) is the screen's (x0, y0).
/// A `.csg` or `.scad` scene is projected onto the `--size` array, as `render --size` does
/// (its tree is the clipping function); a tree that evaluates to nothing draws no plane.
fn program(a: &ExportVerilogJob, cfg: &ArrayConfig) -> crate::Result<Vec<Op>> {
    let view = View::Iso;
    let scene =
        Scene::load(&a.scene, a.clip.as_deref(), view, cfg).map_err(super::lib_errors::load)?;
    check_window(&scene, cfg, a.origin)
        .map_err(|(i, e)| Error::Scene(scene.locate_error(i, &e)))?;
    let mut ops = match (&scene.clip, scene.empty) {
        (_, true) => Ok(vec![]),
        (None, false) => scene_ops(&scene.lists, &cfg.fmt, cfg.colour_bits),
        (Some(expr), false) => clip_scene_ops(&scene.lists, expr, &cfg.fmt, cfg.colour_bits),
    }
    .map_err(|(i, e)| Error::Scene(scene.locate_error(i, &e)))?;
    translate(&mut ops, a.origin.0, a.origin.1);
    Ok(ops)
}

/// Refuse a plane whose value leaves the depth word somewhere on the window the array shows
/// (`csgpix_draw::compile::check_window` at an origin): DEPGEN's adders keep N_D bits and wrap
/// (docs/depth-word.md). The value is linear, so its extremes are at the window's corners.
fn check_window(
    scene: &Scene,
    cfg: &ArrayConfig,
    (x0, y0): (usize, usize),
) -> Result<(), (usize, CompileError)> {
    let fmt = &cfg.fmt;
    let (x1, y1) = (x0 + cfg.width - 1, y0 + cfg.height - 1);
    for (i, dl) in scene.lists.iter().enumerate() {
        for (k, p) in dl.planes.iter().enumerate() {
            let at = |field, msg| {
                (
                    i,
                    CompileError {
                        plane: k,
                        field,
                        msg,
                    },
                )
            };
            let c = coeffs(fmt, p.z0, p.dzx, p.dzy).map_err(|(f, m)| at(f, m))?;
            for (x, y) in [(x0, y0), (x1, y0), (x0, y1), (x1, y1)] {
                let v = c.c0 as i128 + x as i128 * c.dx as i128 + y as i128 * c.dy as i128;
                if v < fmt.min_word() as i128 || v > fmt.max_word() as i128 {
                    let msg = format!(
                        "Z0 + x*dZx + y*dZy = {} at screen pixel ({x}, {y}), in the {}x{} \
                         window at {x0},{y0}, does not fit the depth word (range {} .. {}): \
                         DEPGEN would wrap",
                        v as f64 / (1u64 << fmt.frac) as f64,
                        cfg.width,
                        cfg.height,
                        fmt.to_real(fmt.min_word()),
                        fmt.to_real(fmt.max_word()),
                    );
                    return Err(at(0, msg));
                }
            }
        }
    }
    Ok(())
}

/// `expected.hex`, written a clock at a time as the cycle model runs, into its staged file.
fn write_expected(
    outs: &mut Outputs,
    out: Out,
    cfg: ArrayConfig,
    ops: &[Op],
    set: &rtl_model::EquationSet,
) -> crate::Result<stimulus::Expected<()>> {
    let path = outs.stage_path(out, "expected.hex")?;
    let io = |source| Error::Io {
        path: path.clone(),
        source,
    };
    let file = std::fs::File::create(&path).map_err(io)?;
    let w = std::io::BufWriter::with_capacity(1 << 20, file);
    let want = match stimulus::write_expected_states(cfg, ops, set, w) {
        Ok(want) => want,
        Err(StatesError::Program(e)) => return Err(e.into()),
        Err(StatesError::Io(e)) => return Err(io(e)),
    };
    want.text.into_inner().map_err(|e| io(e.into_error()))?;
    Ok(stimulus::Expected {
        text: (),
        ends: want.ends,
        cycles: want.cycles,
        last: want.last,
    })
}

/// Bytes the files of a program of `cycles` clocks take on disk: the expected states, the
/// control stream (a line of 13 bytes a clock), and the Verilog sources and testbenches
/// (under 100 bytes a pixel, plus 1 MiB).
fn files_bytes(cfg: &ArrayConfig, cycles: u64) -> u64 {
    stimulus::expected_bytes(cfg, cycles)
        .saturating_add((cycles + 1) * 13)
        .saturating_add(cfg.pixels() as u64 * 100 + (1 << 20))
}

/// Refuse, before simulating, files larger than the space free where they are staged.
fn room(outs: &Outputs, out: Out, cfg: &ArrayConfig, cycles: u64) -> crate::Result<()> {
    let dir = outs.stage_root(out)?;
    let (need, free) = (files_bytes(cfg, cycles), csgpix_output::free_bytes(&dir));
    match free {
        Some(free) if need > free => {
            let mb = |b: u64| b.div_ceil(1_000_000);
            let message = format!(
                "the files take about {} MB (expected.hex: {} clocks x {} pixels x {} bytes), \
                 over the {} MB free where -o is: a smaller --size or fewer planes",
                mb(need),
                cycles + 1,
                cfg.pixels(),
                stimulus::line_bytes(cfg),
                mb(free)
            );
            Err(Error::options("--size", message))
        }
        _ => Ok(()),
    }
}

/// Bytes the scene's run holds for a program of `cycles` clocks: one clock's expected
/// states (the file is written a clock at a time) and its write buffer, the control stream
/// held whole (a line of 13 bytes a clock, as text and as a file), the generated sources
/// and testbenches (under 100 bytes a pixel), the image, the cycle model, the process.
fn need(cfg: &ArrayConfig, cycles: u64) -> u64 {
    let pixels = cfg.pixels() as u64;
    (pixels * stimulus::line_bytes(cfg))
        .saturating_add(1 << 20)
        .saturating_add((cycles + 1) * 13 * 2)
        .saturating_add(pixels * (100 + 16))
        .saturating_add(CycleArray::memory_bytes(cfg))
        .saturating_add(16 << 20)
}

/// Refuse, before simulating, a stream longer than tb_array holds or an expected-state file
/// (held in memory, [`need`]) over `--max-memory`.
fn bound(a: &ExportVerilogJob, cfg: &ArrayConfig, cycles: u64) -> crate::Result<()> {
    if cycles > stimulus::MAX_CYCLES {
        let message = format!(
            "the scene takes {cycles} clocks, over the {} tb_array holds (MAXCLK): fewer planes",
            stimulus::MAX_CYCLES
        );
        return Err(Error::options("--scene", message));
    }
    let what = format!(
        "the cycle model of {} pixels, {} clocks",
        cfg.pixels(),
        cycles + 1
    );
    Ok(a.max_memory
        .check(need(cfg, cycles), &what, "a smaller --size or fewer planes")?)
}

#[cfg(unix)]
fn make_executable(outs: &mut Outputs, out: Out, name: &str) -> crate::Result<()> {
    use std::os::unix::fs::PermissionsExt;
    let p = outs.stage_path(out, name)?;
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o755))
        .map_err(|source| Error::Io { path: p, source })
}

#[cfg(not(unix))]
fn make_executable(_: &mut Outputs, _: Out, _: &str) -> crate::Result<()> {
    Ok(())
}

/// expected.png: the G register of every pixel after the program, in the render palette,
/// one image pixel per processor.
fn write_image(
    outs: &mut Outputs,
    out: Out,
    cfg: &ArrayConfig,
    codes: &[u32],
) -> crate::Result<()> {
    let rgb = csgpix_draw::palette::image_rgb(codes, None);
    let mut img = image::RgbImage::new(cfg.width as u32, cfg.height as u32);
    for (i, c) in rgb.iter().enumerate() {
        img.put_pixel(
            (i % cfg.width) as u32,
            (i / cfg.width) as u32,
            image::Rgb(*c),
        );
    }
    Ok(outs.write_in(out, "expected.png", |w| crate::png::write_png(w, &img))?)
}
