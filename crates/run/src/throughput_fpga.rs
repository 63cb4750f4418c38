//! `csgpix throughput --fpga REPORT.json`: the performance equations of §2.5 at the clock a
//! panel of the Verilog machine met on an FPGA (`rtl-model/verilog/fpga/report.sh`,
//! docs/verilog.md), beside the thesis's 10 MHz.

use crate::Error;
use std::path::Path;

use csgpix_draw::throughput::{
    panel_surfaces_per_frame, surfaces_per_second, Hardware, Reading, THESIS_CLOCK_HZ,
};
use serde::Serialize;

/// What `--fpga` reads from a place-and-route report and what it makes of it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FpgaReport {
    /// The report read.
    pub report: String,
    /// The device (`hx8k`, `up5k`).
    pub device: String,
    /// The largest panel that routed on it, n × m pixels (one device = one panel, §2.5).
    pub panel: (usize, usize),
    /// Logic cells per pixel processor (the slope over the panels routed).
    pub lc_per_pixel: f64,
    /// The panel's max clock (nextpnr), in Hz: the clock of every figure of this run.
    pub clock_hz: f64,
    /// Its critical path, as nextpnr reports it.
    pub critical_path: String,
    /// Devices (panels) to cover the screen: ⌈S_n/n⌉·⌈S_m/m⌉.
    pub devices_for_screen: u64,
    /// Eq. 2.3 at the measured clock: surfaces per second of one panel.
    pub surfaces_per_second: f64,
    /// Eq. 2.5 (Table 2.1 reading) for the screen covered by these panels, at the measured
    /// clock, surfaces per frame time.
    pub screen_surfaces_per_frame: f64,
    /// The same at the thesis's 10 MHz.
    pub screen_surfaces_per_frame_thesis: f64,
    /// The measured clock over the thesis's.
    pub clock_ratio: f64,
}

/// What a place-and-route report states: the device, the largest panel that routed, its
/// clock (Hz) and critical path, logic cells per pixel.
pub struct Measured {
    /// `device`.
    pub device: String,
    /// `largest_panel`'s `nx`, `ny`.
    pub panel: (usize, usize),
    /// `clock_mhz`, in Hz.
    pub clock_hz: f64,
    /// `largest_panel`'s `critical_path`.
    pub critical_path: String,
    /// `lc_per_pixel`.
    pub lc_per_pixel: f64,
}

/// Read `--fpga`. A file that is not such a report is one line naming the field.
pub fn read(path: &Path) -> crate::Result<Measured> {
    let bad = |m: String| Error::options("--fpga", format!("{}: {m}", path.display()));
    let text = std::fs::read_to_string(path).map_err(|e| bad(e.to_string()))?;
    let v: serde_json::Value = serde_json::from_str(&text).map_err(|e| bad(e.to_string()))?;
    let field = |p: &str| {
        v.pointer(p).ok_or_else(|| {
            bad(format!(
                "no {p} (write it with rtl-model/verilog/fpga/report.sh)"
            ))
        })
    };
    let num = |p: &str| {
        field(p)?
            .as_f64()
            .filter(|x| x.is_finite() && *x > 0.0)
            .ok_or_else(|| bad(format!("{p} is not a positive number")))
    };
    let size = |p: &str| {
        let x = num(p)?;
        (x.fract() == 0.0 && x <= 1e6)
            .then_some(x as usize)
            .ok_or_else(|| bad(format!("{p} is not a panel side")))
    };
    let text_of = |p: &str| {
        field(p)?
            .as_str()
            .map(String::from)
            .ok_or_else(|| bad(format!("{p} is not text")))
    };
    Ok(Measured {
        device: text_of("/device")?,
        panel: (size("/largest_panel/nx")?, size("/largest_panel/ny")?),
        clock_hz: num("/clock_mhz")? * 1e6,
        critical_path: text_of("/largest_panel/critical_path")?,
        lc_per_pixel: num("/lc_per_pixel")?,
    })
}

/// The §2.5 figures of the report's panel on `screen`, at its clock and at 10 MHz.
pub fn report(path: &Path, hw: &Hardware, screen: (usize, usize)) -> crate::Result<FpgaReport> {
    let Measured {
        device,
        panel,
        clock_hz,
        critical_path,
        lc_per_pixel,
    } = read(path)?;
    let at = |clock_hz| Hardware { clock_hz, ..*hw };
    let screen_frame = |clock| panel_surfaces_per_frame(&at(clock), screen, panel, Reading::Table);
    Ok(FpgaReport {
        report: path.display().to_string(),
        device,
        panel,
        lc_per_pixel,
        clock_hz,
        critical_path,
        devices_for_screen: (screen.0.div_ceil(panel.0) * screen.1.div_ceil(panel.1)) as u64,
        surfaces_per_second: surfaces_per_second(&at(clock_hz)),
        screen_surfaces_per_frame: screen_frame(clock_hz),
        screen_surfaces_per_frame_thesis: screen_frame(THESIS_CLOCK_HZ),
        clock_ratio: clock_hz / THESIS_CLOCK_HZ,
    })
}
