//! The throughput job: the performance equations of §2.5 and §5.5 (Table 2.1, Figures 2.12
//! and 5.11), and a scene's measured frame and slice rates on panels against them.

use crate::memory::Limit;
use crate::Error;
use std::path::{Path, PathBuf};

use csgpix_output::{Out, Outputs};

use crate::plot::{Chart, Charts, Series};
use csgpix_draw::panels::{
    count_cycles, estimate, panel_work, PanelScene, PanelWork, SceneEstimate,
};
use csgpix_draw::project::{Frame, View};
use csgpix_draw::throughput::{
    area_rows, panel_ratio, panel_surfaces_per_frame, slices_per_second, surfaces_per_frame,
    surfaces_per_second, table_2_1, table_panels, AreaRow, Hardware, PanelRow, PixelCost, Reading,
    PIXEL_COST,
};
use csgpix_scene::solid::CsgScene;
use rtl_model::{Array, ArrayConfig, CycleArray, Equations, Op, WordFormat};
use serde::{Deserialize, Serialize};

use crate::memory::default_limit;
use crate::named::Named;
use crate::progress::{warn_all, Progress};
use crate::read::ReadSettings;

/// The §2.5 figures of a screen, its panels and (with `scene`) a scene's measured rates.
/// `Default` is the documented defaults: a 1024x1024 screen, Table 2.1's panels, N_D = 32,
/// 10 MHz, t = 1/50 s, N_s = 6, LUT6.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ThroughputJob {
    /// Screen S_n x S_m in pixels (`--screen`).
    pub screen: (usize, usize),
    /// One panel n x m (`--panel`; None: Table 2.1's panels, 512x512 down to 8x8).
    pub panel: Option<(usize, usize)>,
    /// N_D: bits of the depth word = clocks per surface, eq. 2.3 (`--bits`, 3..=63).
    pub bits: u32,
    /// Clock frequency in Hz (`--clock`).
    pub clock: f64,
    /// Frame time t in seconds, eq. 2.4 (`--frame`).
    pub frame: f64,
    /// N_s: surfaces per primitive for eq. 5.1 (`--surfaces`, at least 1).
    pub surfaces: u32,
    /// An OpenSCAD `.csg` scene whose solids are binned to panels (`--scene`).
    pub scene: Option<PathBuf>,
    /// View direction for the scene (`--view`).
    #[serde(with = "crate::named::by_name")]
    pub view: View,
    /// Depth word for the scene (`--word`; None: 10 fraction bits, as many integer bits from
    /// 10 up as the scene's depth needs, N_D = `bits`).
    #[serde(with = "crate::array_args::word_text_opt")]
    pub word: Option<WordFormat>,
    /// Run every distinct panel program through the cycle model instead of counting it
    /// (`--simulate`).
    pub simulate: bool,
    /// A directory for Figure 2.12, Figure 5.11 and the scene's chart (`--plots`).
    pub plots: Option<PathBuf>,
    /// A LUT budget: which panels' pixel processors fit it (`--area`).
    pub area: Option<u64>,
    /// A place-and-route report: every figure at the clock its largest panel met (`--fpga`).
    pub fpga: Option<PathBuf>,
    /// LUT size for `area`: 4 or 6 inputs (`--lut`).
    pub lut: u8,
    /// The memory limit (`--max-memory`); not serialized: it is the machine's.
    #[serde(skip, default = "default_limit")]
    pub max_memory: Limit,
    /// How the scene is read.
    pub read: ReadSettings,
}

impl Default for ThroughputJob {
    fn default() -> Self {
        ThroughputJob {
            screen: (1024, 1024),
            panel: None,
            bits: 32,
            clock: 10e6,
            frame: 1.0 / 50.0,
            surfaces: 6,
            scene: None,
            view: View::Iso,
            word: None,
            simulate: false,
            plots: None,
            area: None,
            fpga: None,
            lut: 6,
            max_memory: default_limit(),
            read: ReadSettings::default(),
        }
    }
}

/// `--clock`, `--frame`: a positive number, or a fraction A/B.
pub fn parse_positive(s: &str) -> crate::error::Parsed<f64> {
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

/// The figures (`--json` prints these fields, in this order).
#[derive(Clone, Debug, Serialize)]
pub struct ThroughputReport {
    pub hardware: Hardware,
    pub screen: (usize, usize),
    /// Eq. 2.3.
    pub surfaces_per_second: f64,
    /// Eq. 2.4.
    pub surfaces_per_frame: f64,
    /// Eq. 2.5 for each panel, every reading.
    pub panels: Vec<PanelRow>,
    /// Eq. 5.1 for N_s = --surfaces: one array, and each panel size (Table 2.1 reading).
    pub surfaces_per_primitive: u32,
    pub slices_per_second_one_array: f64,
    pub slices_per_second_panels: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scene: Option<SceneReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub area: Option<AreaReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fpga: Option<crate::throughput_fpga::FpgaReport>,
    /// The charts' data, `(file name, chart)`: drawn into `plots` by
    /// [`ThroughputJob::run_with_charts`]; for a caller to draw otherwise.
    #[serde(skip)]
    pub charts: Vec<(String, Chart)>,
}

/// Which panels fit a LUT budget.
#[derive(Clone, Debug, Serialize)]
pub struct AreaReport {
    pub budget_luts: u64,
    pub lut_inputs: u8,
    pub per_pixel: PixelCost,
    /// Pixel processors the budget holds.
    pub processors: u64,
    pub panels: Vec<AreaRow>,
}

/// A scene's measured rates on panels.
#[derive(Clone, Debug, Serialize)]
pub struct SceneReport {
    pub file: String,
    pub view: &'static str,
    pub word: String,
    pub solids: usize,
    pub surfaces: usize,
    pub counted_by: &'static str,
    /// The whole scene on one array as large as the screen.
    pub one_array_cycles: u64,
    pub one_array_fps: f64,
    pub estimates: Vec<SceneEstimate>,
    /// Every panel's work, when one --panel is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub per_panel: Option<Vec<PanelWork>>,
}

impl ThroughputJob {
    /// The memory plan (docs/memory.md): the process; with a scene, every panel's record and
    /// the solids binned to it, for the panel size that has most (one size is held at a
    /// time), and with `simulate` that panel's cycle model. The scene is read to know where
    /// its solids fall.
    pub fn estimate(&self) -> crate::Result<u64> {
        let Some(path) = &self.scene else {
            return Ok(BASE_BYTES);
        };
        let panels = self.panels()?;
        let scene = read_scene(path, self.read, &crate::progress::Quiet)?;
        let fmt = scene_word(self, &scene)?;
        let ps = PanelScene::new(&scene, self.view, self.screen, fmt)
            .map_err(|e| crate::lib_errors::draw(e).context(path.display().to_string()))?;
        Ok(memory_need(&ps, &panels, self.simulate))
    }

    /// Read the FPGA report and the scene and compute every figure; a caller without a
    /// chart drawer gets the charts' data in the report (`plots` is not written).
    pub fn run(&self, progress: &dyn Progress) -> crate::Result<ThroughputReport> {
        self.figures(None, progress)
    }

    /// As [`ThroughputJob::run`], and with `plots` the charts drawn by `charts` into that
    /// directory, all of them or, on any error or signal, none.
    pub fn run_with_charts(
        &self,
        charts: &dyn Charts,
        progress: &dyn Progress,
    ) -> crate::Result<ThroughputReport> {
        self.figures(Some(charts), progress)
    }

    fn figures(
        &self,
        drawer: Option<&dyn Charts>,
        progress: &dyn Progress,
    ) -> crate::Result<ThroughputReport> {
        let mut hw = Hardware {
            bits: self.bits,
            clock_hz: self.clock,
            frame_s: self.frame,
        };
        let fpga = self
            .fpga
            .as_ref()
            .map(|p| crate::throughput_fpga::report(p, &hw, self.screen))
            .transpose()?;
        if let Some(f) = &fpga {
            hw.clock_hz = f.clock_hz;
        }
        let panels = self.panels()?;
        let mut outs = Outputs::new();
        let plots = match (&self.plots, drawer) {
            (Some(d), Some(_)) => Some(outs.dir("--plots", d)?),
            _ => None,
        };
        let scene = self
            .scene
            .as_ref()
            .map(|p| scene_report(self, p, &hw, &panels, progress))
            .transpose()?;
        let mut report = self.report(hw, &panels, scene, fpga);
        report.charts = charts(&hw, self.screen, report.scene.as_ref());
        if let (Some(dir), Some(drawer)) = (plots, drawer) {
            write_plots(&mut outs, dir, &report.charts, drawer)?;
            outs.commit()?;
        }
        Ok(report)
    }

    /// `panel`, or Table 2.1's panels that fit the screen.
    fn panels(&self) -> crate::Result<Vec<(usize, usize)>> {
        let panels = match self.panel {
            Some(p) => vec![p],
            None => table_panels(self.screen),
        };
        if panels.is_empty() {
            let message = format!(
                "a {}x{} screen is smaller than Table 2.1's smallest panel (8x8): give --panel",
                self.screen.0, self.screen.1
            );
            return Err(Error::options("--panel", message));
        }
        Ok(panels)
    }

    /// Eq. 2.3-2.5 and 5.1 on `panels`, beside the scene's and the FPGA's figures.
    fn report(
        &self,
        hw: Hardware,
        panels: &[(usize, usize)],
        scene: Option<SceneReport>,
        fpga: Option<crate::throughput_fpga::FpgaReport>,
    ) -> ThroughputReport {
        let rows = table_2_1(&hw, self.screen, panels);
        let ns = self.surfaces as f64;
        ThroughputReport {
            hardware: hw,
            screen: self.screen,
            surfaces_per_second: surfaces_per_second(&hw),
            surfaces_per_frame: surfaces_per_frame(&hw),
            slices_per_second_panels: rows
                .iter()
                .map(|r| slices_per_second(r.table_per_second, ns))
                .collect(),
            panels: rows,
            surfaces_per_primitive: self.surfaces,
            slices_per_second_one_array: slices_per_second(surfaces_per_second(&hw), ns),
            scene,
            area: self
                .area
                .map(|budget| area_report(budget, self.lut, panels)),
            fpga,
            charts: vec![],
        }
    }
}

/// `--lut`: 4 or 6.
pub fn lut_inputs(s: &str) -> crate::error::Parsed<u8> {
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

fn read_scene(path: &Path, read: ReadSettings, progress: &dyn Progress) -> crate::Result<CsgScene> {
    let scene = csgpix_openscad::read_scene_with(path, &read.read_options().for_the_array())?;
    warn_all(progress, &scene.warnings);
    scene.require_convex(&path.display().to_string(), "`throughput`")?;
    Ok(scene)
}

/// `--word`, or 10 fraction bits and the fewest integer bits (10 or more) under which the
/// scene's deepest point stays below maxdepth, the rest overflow bits, N_D = `bits`.
fn scene_word(a: &ThroughputJob, scene: &CsgScene) -> crate::Result<WordFormat> {
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
    let frame = Frame::fit(scene, a.view, a.screen.0, a.screen.1)?;
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

/// The process, the scene's planes and the report's fixed figures.
const BASE_BYTES: u64 = 16 << 20;
/// A panel's record (`PanelWork`), its bin's vector and the allocator's share of both,
/// besides the solids binned to it (8 bytes each): 4,194,304 panels of 1x1 with twelve.csg
/// peak at 534 MB, about 123 bytes a panel with 3 solids each (tests/memory.rs).
const PANEL_BYTES: u64 = 112;
/// A plane of the scene as read, projected twice (drawn and sliced) and compiled: a sphere of
/// 80,000 faces peaks at 40 MiB, about 410 bytes a plane over the process's 7 MiB.
const PLANE_BYTES: u64 = 512;

/// [`ThroughputJob::estimate`] of a projected scene.
fn memory_need(ps: &PanelScene, panels: &[(usize, usize)], simulate: bool) -> u64 {
    let planes: u64 = ps.lists.iter().map(|l| l.planes.len() as u64).sum();
    let per_size = |p: (usize, usize)| {
        let (cols, rows) = csgpix_draw::panels::tiling(ps.screen, p);
        let records = (cols as u64 * rows as u64).saturating_mul(PANEL_BYTES);
        let binned: u64 = ps
            .footprints
            .iter()
            .flatten()
            .map(|&(x0, y0, x1, y1)| ((x1 / p.0 - x0 / p.0 + 1) * (y1 / p.1 - y0 / p.1 + 1)) as u64)
            .fold(0u64, u64::saturating_add);
        let array = if simulate {
            CycleArray::memory_bytes(&ps.panel_config(p))
        } else {
            0
        };
        records
            .saturating_add(binned.saturating_mul(8))
            .saturating_add(array)
    };
    let most = panels.iter().map(|&p| per_size(p)).max().unwrap_or(0);
    most.saturating_add(planes.saturating_mul(PLANE_BYTES))
        .saturating_add(BASE_BYTES)
}

fn scene_report(
    a: &ThroughputJob,
    path: &Path,
    hw: &Hardware,
    panels: &[(usize, usize)],
    progress: &dyn Progress,
) -> crate::Result<SceneReport> {
    let scene = read_scene(path, a.read, progress)?;
    let fmt = scene_word(a, &scene)?;
    let ps = PanelScene::new(&scene, a.view, a.screen, fmt)
        .map_err(|e| crate::lib_errors::draw(e).context(path.display().to_string()))?;
    let need = memory_need(&ps, panels, a.simulate);
    a.max_memory
        .check(need, "this throughput", "use larger panels (--panel)")?;
    let set = Equations::Derived.set();
    let counted = count_cycles;
    let simulated = |cfg: &ArrayConfig, ops: &[Op]| {
        simulate(cfg, &set, ops, a.max_memory, progress)
            .map_err(|e| csgpix_draw::Error::Counter(e.to_string()))
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
/// the array's memory checked against `--max-memory` first; a long one shows its operations
/// as a stage of `progress` (a sphere of 80,000 faces is 2.6 million clocks a panel size).
fn simulate(
    cfg: &ArrayConfig,
    set: &rtl_model::EquationSet,
    ops: &[Op],
    mem: Limit,
    progress: &dyn Progress,
) -> crate::Result<u64> {
    let what = format!("--simulate: a {}x{} panel", cfg.width, cfg.height);
    mem.check(CycleArray::memory_bytes(cfg), &what, "use smaller panels")?;
    let mut arr = CycleArray::new(*cfg, set.clone());
    crate::render::run_with_progress(&mut arr, ops, progress)?;
    Ok(arr.cycles())
}

/// A number as an integer when it is one (to 1e-9), else with 4 significant digits.
pub fn fmt_num(v: f64) -> String {
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

/// Figure 2.12, Figure 5.11 and (with a scene) the scene's frame rates on panels, each
/// with its file name.
fn charts(
    hw: &Hardware,
    screen: (usize, usize),
    scene: Option<&SceneReport>,
) -> Vec<(String, Chart)> {
    let mut charts = vec![
        ("figure-2.12.png".to_string(), figure_2_12(hw, screen)),
        ("figure-5.11.png".to_string(), figure_5_11(hw, screen)),
    ];
    if let Some(s) = scene {
        let stem = Path::new(&s.file)
            .file_stem()
            .map_or("scene".into(), |f| f.to_string_lossy());
        let name = format!("scene-{stem}-{}.png", s.view);
        charts.push((name, scene_chart(s)));
    }
    charts
}

/// Stage `charts`, drawn by `drawer`, as the files of directory output `out`.
fn write_plots(
    outs: &mut Outputs,
    out: Out,
    charts: &[(String, Chart)],
    drawer: &dyn Charts,
) -> crate::Result<()> {
    for (name, chart) in charts {
        let png = drawer.png(chart, 800, 560)?;
        outs.write_in(out, name, |w| w.write_all(&png))?;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::progress::Quiet;
    use std::sync::Mutex;

    /// A sink that keeps the stages begun and the steps advanced.
    #[derive(Default)]
    struct Stages(Mutex<Vec<(String, u64, u64)>>);

    impl Progress for Stages {
        fn stage(&self, what: &str, total: u64) {
            self.0.lock().unwrap().push((what.to_string(), total, 0));
        }
        fn advance(&self, n: u64) {
            if let Some(s) = self.0.lock().unwrap().last_mut() {
                s.2 += n;
            }
        }
    }

    fn twelve() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../vectors/scenes/twelve.csg")
    }

    /// `--simulate` shows each long panel program's operations as a stage, run to its end,
    /// and counts what the counter counts.
    #[test]
    fn simulated_panels_show_their_progress() {
        let job = |simulate| ThroughputJob {
            screen: (512, 512),
            panel: Some((512, 512)),
            scene: Some(twelve()),
            simulate,
            ..ThroughputJob::default()
        };
        let stages = Stages::default();
        let simulated = job(true).run(&stages).unwrap();
        let stages = stages.0.into_inner().unwrap();
        assert!(!stages.is_empty());
        for (what, total, done) in &stages {
            assert_eq!(what, "operations");
            assert!(*total > 0 && done == total, "{stages:?}");
        }
        let counted = job(false).run(&Quiet).unwrap();
        let cycles = |r: &ThroughputReport| r.scene.as_ref().unwrap().one_array_cycles;
        assert_eq!(cycles(&simulated), cycles(&counted));
    }

    /// The estimate grows with the panels a scene is binned to, and is what the run checks.
    #[test]
    fn the_estimate_counts_the_panels() {
        let job = |panel| ThroughputJob {
            screen: (1024, 1024),
            panel: Some(panel),
            scene: Some(twelve()),
            ..ThroughputJob::default()
        };
        let (small, large) = (
            job((2, 2)).estimate().unwrap(),
            job((256, 256)).estimate().unwrap(),
        );
        // 262,144 panels of 2x2: their records alone.
        assert!(small >= 262_144 * PANEL_BYTES + BASE_BYTES, "{small}");
        assert!(large < small / 2, "{large} {small}");
        let limited = ThroughputJob {
            max_memory: Limit::new(Some(1), "--max-memory"),
            ..job((2, 2))
        };
        let e = limited.run(&Quiet).unwrap_err().to_string();
        assert!(e.contains("this throughput needs about"), "{e}");
    }
}
