//! The throughput equations of the thesis: §2.5 (eq. 2.3, 2.4, 2.5, Table 2.1, Figure 2.12)
//! and §5.5 (eq. 5.1-5.3, Figure 5.11), as printed, with the readings their printed figures
//! need (docs/throughput.md).
//!
//! Every function is a plain formula of its arguments; the realistic, scene-dependent
//! estimate is in [`crate::panels`].

use serde::Serialize;

/// N_D of the thesis: a 32-bit depth word (§2.4.1, §2.5).
pub const THESIS_BITS: u32 = 32;
/// The thesis clock, 10 MHz (T_C = 100 ns, §2.5).
pub const THESIS_CLOCK_HZ: f64 = 10e6;
/// The thesis frame time for its worked example, t = 1/50 s (§2.5).
pub const THESIS_FRAME_S: f64 = 1.0 / 50.0;
/// The screen of Table 2.1: 1024 × 1024 pixels (§2.5).
pub const THESIS_SCREEN: (usize, usize) = (1024, 1024);
/// The panel sides of Table 2.1, 512 down to 8.
pub const TABLE_2_1_PANELS: [usize; 7] = [512, 256, 128, 64, 32, 16, 8];

/// The hardware the equations describe.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Hardware {
    /// N_D: bits of the depth word, which is also clocks per surface (§2.5).
    pub bits: u32,
    /// 1 / T_C, in Hz.
    pub clock_hz: f64,
    /// t: the frame time for real-time display, in seconds (1/30 to 1/70, §2.5).
    pub frame_s: f64,
}

impl Default for Hardware {
    /// The thesis's worked example: 32 bits, 10 MHz, t = 1/50 s.
    fn default() -> Hardware {
        Hardware {
            bits: THESIS_BITS,
            clock_hz: THESIS_CLOCK_HZ,
            frame_s: THESIS_FRAME_S,
        }
    }
}

impl Hardware {
    /// T_C, the clock period in seconds.
    pub fn period(&self) -> f64 {
        1.0 / self.clock_hz
    }
}

/// Eq. 2.3 (= eq. 5.2, §5.5): P = 1 / (N_D · T_C), surfaces per second of one array.
pub fn surfaces_per_second(hw: &Hardware) -> f64 {
    1.0 / (hw.bits as f64 * hw.period())
}

/// Eq. 2.4 (= eq. 5.3, §5.5): P_R = t · P = t / (N_D · T_C), surfaces per frame time of one
/// array, whatever the size of the screen it covers.
pub fn surfaces_per_frame(hw: &Hardware) -> f64 {
    hw.frame_s * surfaces_per_second(hw)
}

/// Panels of n × m needed to cover an S_n × S_m screen, as eq. 2.5's ratio: S_n·S_m / (n·m)
/// (a fraction when a panel does not divide the screen).
pub fn panel_ratio(screen: (usize, usize), panel: (usize, usize)) -> f64 {
    (screen.0 * screen.1) as f64 / (panel.0 * panel.1) as f64
}

/// How eq. 2.5 is read (§2.5). The printed equation is
/// P_R = (n·m·M_P / (S_n·S_m)) · t / (N_D·T_C), and M_P is defined nowhere.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Reading {
    /// As printed with the undefined M_P taken as 1: a panel's share of the screen times one
    /// array's P_R. Smaller panels give fewer surfaces; Table 2.1 does not follow it.
    PrintedMp1,
    /// As printed with M_P = the number of panels, S_n·S_m/(n·m) ("enough panels to cover
    /// the entire screen"): the ratio cancels and P_R does not depend on the panel size.
    PrintedMpPanels,
    /// The ratio inverted, (S_n·S_m/(n·m)) · t/(N_D·T_C): every panel renders its own
    /// surfaces in parallel. Table 2.1 follows this reading, row for row.
    Table,
}

impl Reading {
    /// Every reading, in the order of Table 2.1's discussion.
    pub const ALL: [Reading; 3] = [
        Reading::PrintedMp1,
        Reading::PrintedMpPanels,
        Reading::Table,
    ];

    /// The reading's name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Reading::PrintedMp1 => "printed, M_P = 1",
            Reading::PrintedMpPanels => "printed, M_P = panels",
            Reading::Table => "Table 2.1 (ratio inverted)",
        }
    }
}

/// Eq. 2.5 (§2.5): real-time performance, in surfaces per frame time, of an S_n × S_m
/// screen covered by n × m panels, primitives evenly distributed, under `reading`.
pub fn panel_surfaces_per_frame(
    hw: &Hardware,
    screen: (usize, usize),
    panel: (usize, usize),
    reading: Reading,
) -> f64 {
    let ratio = panel_ratio(screen, panel);
    let factor = match reading {
        Reading::PrintedMp1 => 1.0 / ratio,
        Reading::PrintedMpPanels => 1.0,
        Reading::Table => ratio,
    };
    factor * surfaces_per_frame(hw)
}

/// Eq. 5.1 (§5.5): P_sp = P_R / N_s, slices per second, where P_R is "the performance of a 2D
/// processor in terms of surface/sec" (so eq. 2.3's P, or its panel multiple, not eq. 5.3's
/// per-frame P_R) and N_s the surfaces of the primitive.
pub fn slices_per_second(surfaces_per_second: f64, surfaces_per_primitive: f64) -> f64 {
    surfaces_per_second / surfaces_per_primitive
}

/// One row of Table 2.1 under every reading of eq. 2.5.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PanelRow {
    /// The panel, n × m pixels.
    pub panel: (usize, usize),
    /// S_n·S_m / (n·m).
    pub panels: f64,
    /// Surfaces per second by eq. 2.5 as printed, with M_P = 1.
    pub printed_mp1: f64,
    /// Surfaces per second by eq. 2.5 as printed, M_P the number of panels.
    pub printed_mp_panels: f64,
    /// Surfaces per second as Table 2.1 gives them.
    pub table: f64,
    /// Surfaces per second under the Table 2.1 reading (`table / t`), the P_R of eq. 5.1.
    pub table_per_second: f64,
}

/// Table 2.1 (§2.5) for the given panels, every reading.
pub fn table_2_1(
    hw: &Hardware,
    screen: (usize, usize),
    panels: &[(usize, usize)],
) -> Vec<PanelRow> {
    panels
        .iter()
        .map(|&panel| {
            let r = |reading| panel_surfaces_per_frame(hw, screen, panel, reading);
            PanelRow {
                panel,
                panels: panel_ratio(screen, panel),
                printed_mp1: r(Reading::PrintedMp1),
                printed_mp_panels: r(Reading::PrintedMpPanels),
                table: r(Reading::Table),
                table_per_second: r(Reading::Table) / hw.frame_s,
            }
        })
        .collect()
}

/// The square panels of Table 2.1 (512 down to 8) that fit on `screen`.
pub fn table_panels(screen: (usize, usize)) -> Vec<(usize, usize)> {
    TABLE_2_1_PANELS
        .iter()
        .filter(|&&n| n <= screen.0 && n <= screen.1)
        .map(|&n| (n, n))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn worked_example_of_section_2_5() {
        // §2.5: 1 / (32 · 100 ns) = 312500 surfaces/s; (1/50) of that = 6250 per frame.
        let hw = Hardware::default();
        assert_eq!(surfaces_per_second(&hw).round(), 312_500.0);
        assert_eq!(surfaces_per_frame(&hw).round(), 6_250.0);
    }

    #[test]
    fn readings_of_eq_2_5_on_one_panel_per_screen_agree() {
        // A panel as large as the screen: every reading is one array's P_R.
        let hw = Hardware::default();
        for r in Reading::ALL {
            let v = panel_surfaces_per_frame(&hw, (64, 64), (64, 64), r);
            assert!((v - 6_250.0).abs() < 1e-6, "{r:?}: {v}");
        }
    }
}

/// What one pixel processor costs in an FPGA: Yosys 0.23's synthesis of
/// `rtl-model/verilog/pixel.v` (`cost.ys`: `synth -lut 4`, and `synth` + `abc -lut 6`).
/// `tests/verilog.rs` runs Yosys and checks these figures against it (docs/verilog.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct PixelCost {
    /// LUT4s of `synth -lut 4`.
    pub lut4: u64,
    /// LUT6s of `synth` + `abc -lut 6`.
    pub lut6: u64,
    /// Flip-flops.
    pub flip_flops: u64,
}

/// The pixel processor of `export-verilog` (derived SGENE, 8-level stack, thesis word).
pub const PIXEL_COST: PixelCost = PixelCost {
    lut4: 179,
    lut6: 107,
    flip_flops: 172,
};

/// A panel against a LUT budget (§2.5: which panel sizes an FPGA can hold). Counts only the
/// pixel processors: DEPGEN's trees and the controller, shared by a panel, are not costed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AreaRow {
    /// The panel, n × m pixels.
    pub panel: (usize, usize),
    /// LUTs of its pixel processors.
    pub luts: u64,
    /// Flip-flops of its pixel processors.
    pub flip_flops: u64,
    /// Do they fit the budget?
    pub fits: bool,
}

/// LUTs and flip-flops of each panel's processors with `per_pixel` LUTs each, and whether
/// they fit `budget` LUTs.
pub fn area_rows(panels: &[(usize, usize)], per_pixel: u64, budget: u64) -> Vec<AreaRow> {
    panels
        .iter()
        .map(|&(n, m)| {
            let pixels = (n as u64).saturating_mul(m as u64);
            let luts = pixels.saturating_mul(per_pixel);
            AreaRow {
                panel: (n, m),
                luts,
                flip_flops: pixels.saturating_mul(PIXEL_COST.flip_flops),
                fits: luts <= budget,
            }
        })
        .collect()
}
