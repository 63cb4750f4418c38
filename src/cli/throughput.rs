//! `csgpix throughput`: flags to a [`ThroughputJob`], its figures as tables or `--json`.

use std::path::PathBuf;
use std::process::ExitCode;

use csgpix_draw::project::View;
use csgpix_draw::throughput::Reading;
use csgpix_run::array_args::{parse_size, parse_word};
use csgpix_run::throughput::{
    fmt_num, lut_inputs, parse_positive, AreaReport, SceneReport, ThroughputJob, ThroughputReport,
};
use csgpix_run::throughput_fpga::FpgaReport;
use rtl_model::WordFormat;

use super::common::{named, MaxMemory, ReadArgs};
use super::progress::Bars;

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
    #[arg(long, value_parser = named::<View>(), default_value = "iso")]
    view: View,
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
    mem: MaxMemory,
    #[command(flatten)]
    openscad: ReadArgs,
}

impl Args {
    fn job(&self) -> ThroughputJob {
        ThroughputJob {
            screen: self.screen,
            panel: self.panel,
            bits: self.bits,
            clock: self.clock,
            frame: self.frame,
            surfaces: self.surfaces,
            scene: self.scene.clone(),
            view: self.view,
            word: self.word,
            simulate: self.simulate,
            plots: self.plots.clone(),
            area: self.area,
            fpga: self.fpga.clone(),
            lut: self.lut,
            max_memory: self.mem.limit(),
            read: self.openscad.into(),
        }
    }
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let report = a
        .job()
        .run_with_charts(&super::plot::Plotters, &Bars::default())?;
    super::print(a.json, &report, print_text)
}

fn print_text(r: &ThroughputReport) {
    let hw = &r.hardware;
    outln!(
        "N_D = {} bits, clock {} Hz, t = {} s, screen {}x{}",
        hw.bits,
        hw.clock_hz,
        hw.frame_s,
        r.screen.0,
        r.screen.1
    );
    outln!("eq. 2.3  P   = {:.0} surfaces/s", r.surfaces_per_second);
    outln!("eq. 2.4  P_R = {:.1} surfaces/frame", r.surfaces_per_frame);
    outln!(
        "eq. 5.1  P_sp = {:.1} slices/s for N_s = {} on one array",
        r.slices_per_second_one_array,
        r.surfaces_per_primitive
    );
    print_panels(r);
    if let Some(s) = &r.scene {
        print_scene(s);
    }
    if let Some(a) = &r.area {
        print_area(a);
    }
    if let Some(f) = &r.fpga {
        print_fpga(f, r.screen);
    }
}

/// Eq. 2.5 for each panel, every reading, and eq. 5.1.
fn print_panels(r: &ThroughputReport) {
    outln!("eq. 2.5, surfaces per frame (Table 2.1 follows the last reading):");
    outln!(
        "{:>11} {:>9} {:>16} {:>16} {:>16} {:>14}",
        "panel",
        "panels",
        Reading::PrintedMp1.name(),
        Reading::PrintedMpPanels.name(),
        "ratio inverted",
        "eq. 5.1 sl/s"
    );
    for (row, sp) in r.panels.iter().zip(&r.slices_per_second_panels) {
        outln!(
            "{:>11} {:>9} {:>16} {:>16} {:>16} {:>14}",
            format!("{}x{}", row.panel.0, row.panel.1),
            fmt_num(row.panels),
            fmt_num(row.printed_mp1),
            fmt_num(row.printed_mp_panels),
            fmt_num(row.table),
            fmt_num(*sp)
        );
    }
}

fn print_area(r: &AreaReport) {
    outln!(
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
    outln!(
        "{:>11} {:>14} {:>14} {:>6}",
        "panel",
        "LUTs",
        "flip-flops",
        "fits"
    );
    for row in &r.panels {
        outln!(
            "{:>11} {:>14} {:>14} {:>6}",
            format!("{}x{}", row.panel.0, row.panel.1),
            row.luts,
            row.flip_flops,
            if row.fits { "yes" } else { "no" }
        );
    }
}

fn print_scene(s: &SceneReport) {
    outln!(
        "\n{} ({} view, word {}): {} solids, {} surfaces; one array: {} clocks, {:.1} frames/s",
        s.file,
        s.view,
        s.word,
        s.solids,
        s.surfaces,
        s.one_array_cycles,
        s.one_array_fps
    );
    outln!(
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
        outln!(
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

/// `--fpga`'s lines: the measured panel and clock, eq. 2.3 and 2.5 at it.
fn print_fpga(r: &FpgaReport, screen: (usize, usize)) {
    let (n, m) = r.panel;
    outln!(
        "\n--fpga {}: {}, a {n}x{m} panel ({} pixels, {:.1} LCs each) at {:.2} MHz \
         ({:.2}x the thesis's 10 MHz); critical path {}",
        r.report,
        r.device,
        n * m,
        r.lc_per_pixel,
        r.clock_hz / 1e6,
        r.clock_ratio,
        r.critical_path
    );
    outln!(
        "  eq. 2.3, one panel: {:.0} surfaces/s; devices for a {}x{} screen: {}",
        r.surfaces_per_second,
        screen.0,
        screen.1,
        r.devices_for_screen
    );
    outln!(
        "  eq. 2.5 (Table 2.1 reading), the screen: {:.0} surfaces/frame at {:.2} MHz, {:.0} at \
         10 MHz",
        r.screen_surfaces_per_frame,
        r.clock_hz / 1e6,
        r.screen_surfaces_per_frame_thesis
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags' defaults are the job's documented defaults (the memory limit is the
    /// machine's, read once by each).
    #[test]
    fn flags_make_the_default_job() {
        let a = parsed!(Throughput, ["csgpix", "throughput"]);
        let want = ThroughputJob {
            max_memory: a.mem.limit(),
            ..ThroughputJob::default()
        };
        assert_eq!(a.job(), want);
    }
}
