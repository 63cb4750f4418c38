//! `csgpix export-verilog`: the Verilog twin of SGENE and its checks (docs/verilog.md); with
//! `--scene`, a directory from which `tb_array` runs a scene and checks every register of
//! every pixel after every clock against the `cycle` model (docs/verilog.md, "Running
//! tb_array from the CLI").

use crate::Error;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use csgpix_draw::compile::{clip_scene_ops, coeffs, scene_ops, CompileError};
use csgpix_output::{Out, Outputs};
use rtl_model::array::{check_program, program_cycles};
use rtl_model::program::{translate, Op};
use rtl_model::verilog::{pixel, stimulus};
use rtl_model::{ArrayConfig, CycleArray, Equations, WordFormat};

use super::array_args::{parse_size, parse_word};
use super::memory::MaxMemory;
use csgpix_draw::scenes::Scene;

#[derive(clap::Args, Debug)]
#[command(
    after_help = "Examples:\n  csgpix export-verilog                 # rewrite rtl-model/verilog/\n  \
    csgpix export-verilog -o out/         # write elsewhere\n  \
    csgpix export-verilog --check         # exit 1 if the checked-in files differ\n  \
    csgpix export-verilog --scene vectors/thesis/cube.dl --origin 56,90 -o cube/\n  \
    sh cube/run.sh                        # tb_array on the cube's 16x16 window, Icarus\n  \
    sh cube/run.sh verilator              # the same under Verilator\n  \
    csgpix export-verilog --scene vectors/thesis/box1.dl --scene vectors/thesis/box2.dl \
    --clip 'A.!B' --origin 112,148 -o boxes/"
)]
pub struct Args {
    /// Directory to write (or check) the files in: rtl-model/verilog when not given; with
    /// --scene it must be given.
    #[arg(short = 'o', long)]
    out: Option<PathBuf>,
    /// Only compare with the files in the directory; exit 1 on any difference.
    #[arg(long, conflicts_with = "scene")]
    check: bool,
    /// A display list (thesis §5.2) to run on the array; repeat for more objects (A, B, …);
    /// or one OpenSCAD .csg/.scad scene, projected onto the --size array.
    /// Writes tb_array's stimulus (control.hex), the state it must see after every clock
    /// (expected.hex), the image (expected.png), the Verilog it is built from and run.sh.
    #[arg(long, value_name = "FILE.dl")]
    scene: Vec<PathBuf>,
    /// Clipping function over the objects, as for `render` (§5.2.1), e.g. "A.!B".
    #[arg(long, requires = "scene")]
    clip: Option<String>,
    /// Array size WIDTHxHEIGHT; pixel_array.v and tb_array.v are generated for it.
    #[arg(long, default_value = "16x16", value_parser = parse_size, requires = "scene")]
    size: (usize, usize),
    /// The screen pixel X,Y the array's pixel (0, 0) shows: the window of the scene drawn.
    #[arg(long, default_value = "0,0", value_parser = parse_origin, requires = "scene")]
    origin: (usize, usize),
    /// Depth word FRACTION/INTEGER/OVERFLOW bits (thesis 10/10/11).
    #[arg(long, default_value = "10/10/11", value_parser = parse_word, requires = "scene")]
    word: WordFormat,
    #[command(flatten)]
    mem: MaxMemory,
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    if !a.scene.is_empty() {
        return scene(&a);
    }
    let out = a.out.as_deref().unwrap_or(Path::new("rtl-model/verilog"));
    super::write_generated(&rtl_model::verilog::files()?, out, a.check)
}

fn parse_origin(s: &str) -> crate::error::Parsed<(usize, usize)> {
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
fn config(a: &Args) -> crate::Result<ArrayConfig> {
    let mut cfg = ArrayConfig::new(a.size.0, a.size.1);
    cfg.fmt = a.word;
    // Colour registers move within a window, so a very short word narrows them too.
    cfg.colour_bits = cfg.colour_bits.min(cfg.fmt.bits());
    cfg.check()?;
    Ok(cfg)
}

/// `--scene`: compile, bound, simulate clock by clock, stage every file, commit, report.
fn scene(a: &Args) -> crate::Result<ExitCode> {
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
    let cycles = program_cycles(&cfg, &set, &ops);
    bound(a, &cfg, cycles)?;
    let want = stimulus::expected_states(cfg, &ops, &set)?;
    let control = pixel::control_stream(&cfg, &set, &ops);
    let mut files = stimulus::array_files(&cfg);
    let machine = stimulus::machine_files(&cfg, &ops);
    files.extend(machine.map_err(|e| Error::options("--scene", e.to_string()))?);
    files.push(("control.hex".into(), control));
    files.push(("run.sh".into(), stimulus::run_script(&want.summary())));
    for (name, text) in &files {
        outs.write_in(out, name, |w| w.write_all(text.as_bytes()))?;
    }
    make_executable(&mut outs, out, "run.sh")?;
    outs.write_in(out, "expected.hex", |w| w.write_all(want.text.as_bytes()))?;
    write_image(&mut outs, out, &cfg, &want.image())?;
    outs.commit()?;
    report(dir, &cfg, &files, &want);
    Ok(ExitCode::SUCCESS)
}

/// The scene's program for the window at `--origin`: display lists compiled as `render`
/// compiles them, then moved so the array's pixel (0, 0) is the screen's (x0, y0).
/// A `.csg` or `.scad` scene is projected onto the `--size` array, as `render --size` does
/// (its tree is the clipping function); a tree that evaluates to nothing draws no plane.
fn program(a: &Args, cfg: &ArrayConfig) -> crate::Result<Vec<Op>> {
    let view = super::ViewArg::default().into();
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

/// Refuse, before simulating, a stream longer than tb_array holds or an expected-state file
/// (held in memory, [`stimulus::expected_bytes`]) over `--max-memory`.
fn bound(a: &Args, cfg: &ArrayConfig, cycles: u64) -> crate::Result<()> {
    if cycles > stimulus::MAX_CYCLES {
        let message = format!(
            "the scene takes {cycles} clocks, over the {} tb_array holds (MAXCLK): fewer planes",
            stimulus::MAX_CYCLES
        );
        return Err(Error::options("--scene", message));
    }
    let text = stimulus::expected_bytes(cfg, cycles);
    // The control stream (a line of 13 bytes a clock), the cycle model, the process.
    let need = text
        .saturating_add((cycles + 1) * 13)
        .saturating_add(CycleArray::memory_bytes(cfg))
        .saturating_add(16 << 20);
    let what = format!(
        "expected.hex ({} clocks x {} pixels x {} bytes)",
        cycles + 1,
        cfg.pixels(),
        stimulus::line_bytes(cfg)
    );
    Ok(a.mem
        .check(need, &what, "a smaller --size or fewer planes")?)
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

/// What was written and how to run it: the command lines `run.sh` holds, from the directory.
fn report(dir: &Path, cfg: &ArrayConfig, files: &[(String, String)], want: &stimulus::Expected) {
    for (name, _) in files {
        println!("wrote {}", dir.join(name).display());
    }
    let mib = want.text.len() as f64 / (1 << 20) as f64;
    println!(
        "wrote {} ({} clocks x {} pixels, {mib:.1} MiB)",
        dir.join("expected.hex").display(),
        want.cycles + 1,
        cfg.pixels()
    );
    println!(
        "wrote {} ({}x{}, G after the last clock)",
        dir.join("expected.png").display(),
        cfg.width,
        cfg.height
    );
    let d = shell_word(&dir.display().to_string());
    println!("run tb_array; it must print \"{}\":", want.summary());
    println!("  icarus:    cd {d} && {}", stimulus::ICARUS);
    println!("  verilator: cd {d} && {}", stimulus::VERILATOR);
    println!("  or:        sh {d}/run.sh [icarus|verilator]   (exit 0 only on that line)");
    println!("run tb_machine (the controller reads program.hex; every word and register checked):");
    println!("  icarus:    cd {d} && {}", stimulus::MACHINE_ICARUS);
    println!("  verilator: cd {d} && {}", stimulus::MACHINE_VERILATOR);
}

/// `s` as one shell word: as it is when it needs no quoting, else in single quotes.
fn shell_word(s: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "/._-+,:@%=".contains(c);
    if !s.is_empty() && s.chars().all(plain) {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', r"'\''"))
    }
}
