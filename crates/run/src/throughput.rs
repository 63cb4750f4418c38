//! `csgpix throughput`: the performance equations of §2.5 and §5.5 (Table 2.1, Figures 2.12
//! and 5.11), and a scene's measured frame and slice rates on panels against them.

use crate::Error;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use csgpix_output::{Out, Outputs};

use crate::plot::{Chart, Series};
use csgpix_draw::panels::{
    count_cycles, estimate, panel_work, PanelScene, PanelWork, SceneEstimate,
};
use csgpix_draw::project::Frame;
use csgpix_draw::throughput::{
    area_rows, panel_ratio, panel_surfaces_per_frame, slices_per_second, surfaces_per_frame,
    surfaces_per_second, table_2_1, table_panels, AreaRow, Hardware, PanelRow, PixelCost, Reading,
    PIXEL_COST,
};
use csgpix_scene::solid::CsgScene;
use rtl_model::{Array, ArrayConfig, CycleArray, Equations, Op, WordFormat};
use serde::Serialize;

use super::array_args::{parse_size, parse_word};
use super::read_args::ReadArgs;
use super::ViewArg;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix throughput                                   # Table 2.1, every reading of eq. 2.5\n  \
    csgpix throughput --panel 128x128 --surfaces 6 --json\n  \
    csgpix throughput --clock 20e6 --bits 24 --frame 1/30\n  \
    csgpix throughput --scene vectors/scenes/csg-logo.csg --panel 128x128\n  \
    csgpix throughput --scene vectors/scenes/twelve.csg --view top --simulate --screen 256x256\n  \
    csgpix throughput --plots docs/img --scene vectors/scenes/csg-logo.csg\n  \
    csgpix throughput --area 100000 --lut 6            # which panels fit 100,000 LUT6\n  \
    csgpix throughput --fpga rtl-model/verilog/fpga/report-hx8k.json  # at the measured clock")]
pub struct Args {
    /// Screen S_n x S_m in pixels.
    #[arg(long, default_value = "1024x1024", value_parser = parse_size)]
    screen: (usize, usize),
    /// Panel n x m (default: Table 2.1's panels, 512x512 down to 8x8).
    #[arg(long, value_parser = parse_size)]
    panel: Option<(usize, usize)>,
    /// N_D: bits of the depth word = clocks per surface (eq. 2.3).
    #[arg(long, default_value_t = 32, value_parser = clap::value_parser!(u32).range(3..=63))]
    bits: u32,
    /// Clock frequency in Hz (1/T_C), e.g. 10e6.
    #[arg(long, default_value = "10e6", value_parser = parse_positive)]
    clock: f64,
    /// Frame time t in seconds, e.g. 0.02 or 1/50 (eq. 2.4).
    #[arg(long, default_value = "1/50", value_parser = parse_positive)]
    frame: f64,
    /// N_s: surfaces per primitive for eq. 5.1.
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u32).range(1..))]
    surfaces: u32,
    /// An OpenSCAD .csg scene: bin its solids to panels and count every panel's clocks.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// View direction for --scene (slices are cut perpendicular to it).
    #[arg(long, value_enum, default_value_t)]
    view: ViewArg,
    /// Depth word FRACTION/INTEGER/OVERFLOW for --scene (default: 10 fraction bits, as
    /// many integer bits from 10 up as the scene's depth needs, N_D = --bits).
    #[arg(long, value_parser = parse_word)]
    word: Option<WordFormat>,
    /// Run every distinct panel program through the cycle model instead of counting it.
    #[arg(long)]
    simulate: bool,
    /// Write figure-2.12.png, figure-5.11.png (and scene-NAME-VIEW.png with --scene) here.
    #[arg(long)]
    plots: Option<PathBuf>,
    /// A LUT budget: which panels' pixel processors fit it (Yosys's cost of one processor,
    /// docs/verilog.md; DEPGEN and the controller are not counted).
    #[arg(long, value_name = "LUTS")]
    area: Option<u64>,
    /// A place-and-route report (rtl-model/verilog/fpga/report-DEVICE.json): every figure at
    /// the clock its largest panel met, and that panel (one device) costed for --screen
    /// beside the thesis's 10 MHz.
    #[arg(long, value_name = "REPORT.json", conflicts_with = "clock")]
    fpga: Option<PathBuf>,
    /// LUT size for --area: 4 or 6 inputs.
    #[arg(long, default_value = "6", value_parser = lut_inputs)]
    lut: u8,
    /// Print every number as JSON.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    mem: super::memory::MaxMemory,
    #[command(flatten)]
    openscad: super::read_args::ReadArgs,
}

/// A positive number, or a fraction A/B.
fn parse_positive(s: &str) -> crate::error::Parsed<f64> {
    let n = |v: &str| v.trim().parse::<f64>().map_err(|e| format!("{v:?}: {e}"));
    let v = match s.split_once('/') {
        Some((a, b)) => n(a)? / n(b)?,
        None => n(s)?,
    };
    if !(v.is_finite() && v > 0.0) {
        return Err(crate::error::BadValue(format!(
            "{s:?}: expected a positive number"
        )));
    }
    Ok(v)
}

#[derive(Serialize)]
struct Report {
    hardware: Hardware,
    screen: (usize, usize),
    /// Eq. 2.3.
    surfaces_per_second: f64,
    /// Eq. 2.4.
    surfaces_per_frame: f64,
    /// Eq. 2.5 for each panel, every reading.
    panels: Vec<PanelRow>,
    /// Eq. 5.1 for N_s = --surfaces: one array, and each panel size (Table 2.1 reading).
    surfaces_per_primitive: u32,
    slices_per_second_one_array: f64,
    slices_per_second_panels: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    scene: Option<SceneReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    area: Option<AreaReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fpga: Option<super::throughput_fpga::FpgaReport>,
}

#[derive(Serialize)]
struct AreaReport {
    budget_luts: u64,
    lut_inputs: u8,
    per_pixel: PixelCost,
    /// Pixel processors the budget holds.
    processors: u64,
    panels: Vec<AreaRow>,
}

#[derive(Serialize)]
struct SceneReport {
    file: String,
    view: &'static str,
    word: String,
    solids: usize,
    surfaces: usize,
    counted_by: &'static str,
    /// The whole scene on one array as large as the screen.
    one_array_cycles: u64,
    one_array_fps: f64,
    estimates: Vec<SceneEstimate>,
    /// Every panel's work, when one --panel is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    per_panel: Option<Vec<PanelWork>>,
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let mut hw = Hardware {
        bits: a.bits,
        clock_hz: a.clock,
        frame_s: a.frame,
    };
    let fpga = a
        .fpga
        .as_ref()
        .map(|p| super::throughput_fpga::report(p, &hw, a.screen))
        .transpose()?;
    if let Some(f) = &fpga {
        hw.clock_hz = f.clock_hz;
    }
    let panels = match a.panel {
        Some(p) => vec![p],
        None => table_panels(a.screen),
    };
    if panels.is_empty() {
        let message = format!(
            "a {}x{} screen is smaller than Table 2.1's smallest panel (8x8): give --panel",
            a.screen.0, a.screen.1
        );
        return Err(Error::options("--panel", message));
    }
    let mut outs = Outputs::new();
    let plots = a
        .plots
        .as_ref()
        .map(|d| outs.dir("--plots", d))
        .transpose()?;
    let rows = table_2_1(&hw, a.screen, &panels);
    let scene = a
        .scene
        .as_ref()
        .map(|p| scene_report(&a, p, &hw, &panels))
        .transpose()?;
    let ns = a.surfaces as f64;
    let report = Report {
        hardware: hw,
        screen: a.screen,
        surfaces_per_second: surfaces_per_second(&hw),
        surfaces_per_frame: surfaces_per_frame(&hw),
        slices_per_second_panels: rows
            .iter()
            .map(|r| slices_per_second(r.table_per_second, ns))
            .collect(),
        panels: rows,
        surfaces_per_primitive: a.surfaces,
        slices_per_second_one_array: slices_per_second(surfaces_per_second(&hw), ns),
        scene,
        area: a.area.map(|budget| area_report(budget, a.lut, &panels)),
        fpga,
    };
    if let Some(dir) = plots {
        write_plots(&mut outs, dir, &hw, a.screen, report.scene.as_ref())?;
        outs.commit()?;
    }
    if a.json {
        let text = serde_json::to_string_pretty(&report)?;
        println!("{text}");
    } else {
        print_text(&report);
    }
    Ok(ExitCode::SUCCESS)
}

fn lut_inputs(s: &str) -> crate::error::Parsed<u8> {
    match s {
        "4" => Ok(4),
        "6" => Ok(6),
        _ => Err("LUT4 and LUT6 are costed: give 4 or 6".into()),
    }
}

fn area_report(budget: u64, lut: u8, panels: &[(usize, usize)]) -> AreaReport {
    let per = if lut == 4 {
        PIXEL_COST.lut4
    } else {
        PIXEL_COST.lut6
    };
    AreaReport {
        budget_luts: budget,
        lut_inputs: lut,
        per_pixel: PIXEL_COST,
        processors: budget / per,
        panels: area_rows(panels, per, budget),
    }
}

fn print_area(r: &AreaReport) {
    println!(
        "\n--area {} LUT{}: {} pixel processors at {} LUT{} each (pixels only, docs/verilog.md)",
        r.budget_luts,
        r.lut_inputs,
        r.processors,
        if r.lut_inputs == 4 {
            r.per_pixel.lut4
        } else {
            r.per_pixel.lut6
        },
        r.lut_inputs
    );
    println!(
        "{:>11} {:>14} {:>14} {:>6}",
        "panel", "LUTs", "flip-flops", "fits"
    );
    for row in &r.panels {
        println!(
            "{:>11} {:>14} {:>14} {:>6}",
            format!("{}x{}", row.panel.0, row.panel.1),
            row.luts,
            row.flip_flops,
            if row.fits { "yes" } else { "no" }
        );
    }
}

fn read_scene(path: &Path, openscad: ReadArgs) -> crate::Result<CsgScene> {
    let scene = csgpix_openscad::read_scene_with(path, &openscad.read_options())?;
    crate::read_args::print_warnings(&scene.warnings);
    scene.require_convex(&path.display().to_string(), "`throughput`")?;
    Ok(scene)
}

/// `--word`, or 10 fraction bits and the fewest integer bits (10 or more) under which the
/// scene's deepest point stays below maxdepth, the rest overflow bits, N_D = `bits`.
fn scene_word(a: &Args, scene: &CsgScene) -> crate::Result<WordFormat> {
    if let Some(w) = a.word {
        if w.bits() != a.bits {
            let message = format!(
                "--word gives N_D = {} but --bits is {}: they must agree",
                w.bits(),
                a.bits
            );
            return Err(Error::options("--word", message));
        }
        return Ok(w);
    }
    let frame = Frame::fit(scene, a.view.into(), a.screen.0, a.screen.1)?;
    let deepest = frame.deepest(scene).max(1.0);
    let int = (deepest.log2().floor() as u32 + 1).max(10);
    let ovf = a.bits as i64 - 1 - 10 - int as i64;
    if ovf < 1 {
        let message = format!(
            "the scene is {deepest:.0} depth units deep on a {}x{} screen: {} bits cannot hold \
             10 fraction, {int} integer and 1 overflow bit (give --word or a smaller --screen)",
            a.screen.0, a.screen.1, a.bits
        );
        return Err(Error::options("--word", message));
    }
    WordFormat::new(10, int, ovf as u32).map_err(|e| Error::options("--bits", e.to_string()))
}

fn scene_report(
    a: &Args,
    path: &Path,
    hw: &Hardware,
    panels: &[(usize, usize)],
) -> crate::Result<SceneReport> {
    let scene = read_scene(path, a.openscad)?;
    let fmt = scene_word(a, &scene)?;
    let ps = PanelScene::new(&scene, a.view.into(), a.screen, fmt)
        .map_err(|e| super::lib_errors::draw(e).context(path.display().to_string()))?;
    let set = Equations::Derived.set();
    let counted = count_cycles(&set);
    let simulated = |cfg: &ArrayConfig, ops: &[Op]| {
        simulate(cfg, &set, ops, a.mem).map_err(|e| csgpix_draw::Error::Counter(e.to_string()))
    };
    let count: &csgpix_draw::panels::Counter = if a.simulate { &simulated } else { &counted };
    let all = vec![true; ps.lists.len()];
    let in_scene = |e: csgpix_draw::Error| Error::from(e).context(path.display().to_string());
    let ops = ps.frame_ops(&all).map_err(in_scene)?;
    let one = counted(&ps.panel_config(a.screen), &ops)?;
    let mut estimates = vec![];
    let mut per_panel = None;
    for &p in panels {
        let work = panel_work(&ps, p, count)?;
        estimates.push(estimate(&ps, hw, p, &work, one));
        if a.panel.is_some() {
            per_panel = Some(work);
        }
    }
    Ok(SceneReport {
        file: path.display().to_string(),
        view: a.view.name(),
        word: format!("{}/{}/{}", fmt.frac, fmt.int, fmt.ovf),
        solids: ps.lists.len(),
        surfaces: ps.surfaces(),
        counted_by: if a.simulate {
            "cycle model run"
        } else {
            "program_cycles"
        },
        one_array_cycles: one,
        one_array_fps: hw.clock_hz / one as f64,
        estimates,
        per_panel,
    })
}

/// Run a program on a cycle-model array of configuration `cfg` and read its clock counter,
/// the array's memory checked against `--max-memory` first.
fn simulate(
    cfg: &ArrayConfig,
    set: &rtl_model::EquationSet,
    ops: &[Op],
    mem: super::memory::MaxMemory,
) -> crate::Result<u64> {
    let what = format!("--simulate: a {}x{} panel", cfg.width, cfg.height);
    mem.check(CycleArray::memory_bytes(cfg), &what, "use smaller panels")?;
    let mut arr = CycleArray::new(*cfg, set.clone());
    arr.run(ops)?;
    Ok(arr.cycles())
}

fn print_text(r: &Report) {
    let hw = &r.hardware;
    println!(
        "N_D = {} bits, clock {} Hz, t = {} s, screen {}x{}",
        hw.bits, hw.clock_hz, hw.frame_s, r.screen.0, r.screen.1
    );
    println!("eq. 2.3  P   = {:.0} surfaces/s", r.surfaces_per_second);
    println!("eq. 2.4  P_R = {:.1} surfaces/frame", r.surfaces_per_frame);
    println!(
        "eq. 5.1  P_sp = {:.1} slices/s for N_s = {} on one array",
        r.slices_per_second_one_array, r.surfaces_per_primitive
    );
    println!("eq. 2.5, surfaces per frame (Table 2.1 follows the last reading):");
    println!(
        "{:>11} {:>9} {:>16} {:>16} {:>16} {:>14}",
        "panel",
        "panels",
        Reading::PrintedMp1.name(),
        Reading::PrintedMpPanels.name(),
        "ratio inverted",
        "eq. 5.1 sl/s"
    );
    for (row, sp) in r.panels.iter().zip(&r.slices_per_second_panels) {
        println!(
            "{:>11} {:>9} {:>16} {:>16} {:>16} {:>14}",
            format!("{}x{}", row.panel.0, row.panel.1),
            fmt_num(row.panels),
            fmt_num(row.printed_mp1),
            fmt_num(row.printed_mp_panels),
            fmt_num(row.table),
            fmt_num(*sp)
        );
    }
    if let Some(s) = &r.scene {
        print_scene(s);
    }
    if let Some(a) = &r.area {
        print_area(a);
    }
    if let Some(f) = &r.fpga {
        super::throughput_fpga::print(f, r.screen);
    }
}

fn print_scene(s: &SceneReport) {
    println!(
        "\n{} ({} view, word {}): {} solids, {} surfaces; one array: {} clocks, {:.1} frames/s",
        s.file, s.view, s.word, s.solids, s.surfaces, s.one_array_cycles, s.one_array_fps
    );
    println!(
        "{:>11} {:>7} {:>7} {:>4} {:>9} {:>9} {:>9} {:>10} {:>10} {:>9} {:>10}",
        "panel",
        "panels",
        "touched",
        "max",
        "slowest",
        "clocks",
        "fps",
        "fps split",
        "fps eq2.5",
        "slices/s",
        "sl/s eq5.1"
    );
    for e in &s.estimates {
        println!(
            "{:>11} {:>7} {:>7} {:>4} {:>9} {:>9} {:>9} {:>10} {:>10} {:>9} {:>10}",
            format!("{}x{}", e.panel.0, e.panel.1),
            e.panels,
            e.touched,
            e.max_solids,
            format!("{},{}", e.slowest.0, e.slowest.1),
            e.frame_cycles,
            fmt_num(e.fps),
            fmt_num(e.even_split_fps),
            fmt_num(e.formula_fps),
            fmt_num(e.slices_per_s),
            fmt_num(e.formula_slices_per_s)
        );
    }
}

/// A number as an integer when it is one (to 1e-9), else with 4 significant digits.
fn fmt_num(v: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    if (v - v.round()).abs() < 1e-9 * v.abs().max(1.0) {
        format!("{:.0}", v)
    } else {
        let digits = (3 - v.abs().log10().floor() as i32).max(0) as usize;
        format!("{v:.digits$}")
    }
}

/// Stage Figure 2.12, Figure 5.11 and (with a scene) the scene's frame rates on panels as
/// the files of directory output `out`.
fn write_plots(
    outs: &mut Outputs,
    out: Out,
    hw: &Hardware,
    screen: (usize, usize),
    scene: Option<&SceneReport>,
) -> crate::Result<()> {
    let mut write = |c: Chart, name: &str| -> crate::Result<()> {
        Ok(c.write_png(&outs.stage_path(out, name)?, 800, 560)?)
    };
    write(figure_2_12(hw, screen), "figure-2.12.png")?;
    write(figure_5_11(hw, screen), "figure-5.11.png")?;
    if let Some(s) = scene {
        let stem = Path::new(&s.file)
            .file_stem()
            .map_or("scene".into(), |f| f.to_string_lossy());
        write(scene_chart(s), &format!("scene-{stem}-{}.png", s.view))?;
    }
    Ok(())
}

/// Figure 2.12: surfaces per frame against the number of arrays working in parallel.
fn figure_2_12(hw: &Hardware, screen: (usize, usize)) -> Chart {
    let panels = table_panels(screen);
    let series = |r: Reading| Series {
        label: format!("eq. 2.5, {}", r.name()),
        points: panels
            .iter()
            .map(|&p| {
                let x = panel_ratio(screen, p);
                (x, panel_surfaces_per_frame(hw, screen, p, r))
            })
            .collect(),
    };
    Chart {
        title: format!(
            "Figure 2.12: real-time performance, {}x{} screen, t = {:.4} s",
            screen.0, screen.1, hw.frame_s
        ),
        x_label: "processor arrays (panels) working in parallel".into(),
        y_label: "surfaces per frame time".into(),
        log_x: true,
        log_y: true,
        series: Reading::ALL.into_iter().rev().map(series).collect(),
    }
}

/// Figure 5.11: slices per second against surfaces per primitive (eq. 5.1), for §5.5's
/// 20,000,000 surfaces/s (128x128 panels, Table 2.1 reading) and for one array (eq. 5.2).
fn figure_5_11(hw: &Hardware, screen: (usize, usize)) -> Chart {
    let p = surfaces_per_second(hw);
    let panels = panel_ratio(screen, (128, 128));
    let curve = |label: String, pr: f64| Series {
        label,
        points: (4..=64)
            .map(|n| (n as f64, slices_per_second(pr, n as f64)))
            .collect(),
    };
    Chart {
        title: "Figure 5.11: performance of slice generation (eq. 5.1)".into(),
        x_label: "surfaces per primitive, N_s".into(),
        y_label: "slices per second, P_sp".into(),
        log_x: false,
        log_y: true,
        series: vec![
            curve(
                format!(
                    "P_R = {} surfaces/s (§5.5; 128x128 panels on {}x{})",
                    fmt_num(panels * p),
                    screen.0,
                    screen.1
                ),
                panels * p,
            ),
            curve(
                format!("P_R = P = {} surfaces/s (eq. 5.2, one array)", fmt_num(p)),
                p,
            ),
        ],
    }
}

/// A scene's frames per second on panels: measured (slowest panel) and eq. 2.5.
fn scene_chart(s: &SceneReport) -> Chart {
    let pts = |f: &dyn Fn(&SceneEstimate) -> f64| {
        s.estimates
            .iter()
            .map(|e| (e.panels as f64, f(e)))
            .collect()
    };
    Chart {
        title: format!("{} ({} view): frames per second on panels", s.file, s.view),
        x_label: "panels".into(),
        y_label: "frames per second".into(),
        log_x: true,
        log_y: true,
        series: vec![
            Series {
                label: "eq. 2.5, even distribution".into(),
                points: pts(&|e| e.formula_fps),
            },
            Series {
                label: "one array's clocks split evenly".into(),
                points: pts(&|e| e.even_split_fps),
            },
            Series {
                label: "measured: slowest panel's program".into(),
                points: pts(&|e| e.fps),
            },
        ],
    }
}
