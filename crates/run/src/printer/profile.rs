//! Printer profiles: the display a resin (MSLA) printer shows each layer on, and the
//! exposure figures its archive carries. Prusa's figures are those of PrusaSlicer 2.5's
//! bundled profiles (`PrusaResearch.ini`, "Original Prusa SL1" and "Original Prusa SL1S
//! SPEED"); the two generic panels are the published sizes of common 4K and 8K LCDs.

use std::borrow::Cow;

use serde::{Deserialize, Serialize};

/// How the archive is packed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Archive {
    /// Prusa's `.sl1` (SL1) or `.sl1s` (SL1S): a zip of `config.ini`, `prusaslicer.ini`,
    /// the layer PNGs and thumbnails.
    Prusa,
    /// A directory of `layer-NNNNN.png` and `print.json`, for other printers.
    Stack,
}

/// A printer's display and layer settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Printer {
    /// The profile's name on the command line (`--printer`).
    pub id: Cow<'static, str>,
    /// `printerModel` in `config.ini` (SL1, SL1S), or the panel's name.
    pub model: Cow<'static, str>,
    /// PrusaSlicer's `printer_settings_id`.
    pub settings_id: Cow<'static, str>,
    /// The display's size, mm, along the bed's X and Y (`display_width`, `display_height`).
    pub size: [f64; 2],
    /// Pixels along X and Y (`display_pixels_x`, `display_pixels_y`).
    pub pixels: [u32; 2],
    /// The layer images are turned a quarter turn (`display_orientation = portrait`): the
    /// PNG is `pixels[1]` wide and `pixels[0]` high.
    pub portrait: bool,
    /// The image is mirrored along X, Y (`display_mirror_x`, `display_mirror_y`).
    pub mirror: [bool; 2],
    /// Layer height, mm.
    pub layer_height: f64,
    /// The first layer's height, mm (`initial_layer_height`).
    pub initial_layer_height: f64,
    /// Exposure of every layer after the faded ones, s (`exposure_time`).
    pub exposure: f64,
    /// Exposure of the first layer, s (`initial_exposure_time`).
    pub initial_exposure: f64,
    /// Layers over which the exposure falls from the first layer's to the others'.
    pub faded_layers: u32,
    /// The tilt after a layer of at most `area_fill` of the display, s (`fast_tilt_time`).
    pub fast_tilt: f64,
    /// The tilt after a larger layer, s (`slow_tilt_time`).
    pub slow_tilt: f64,
    /// The share of the display, %, up to which a layer is fast (`area_fill`).
    pub area_fill: f64,
}

/// `--printer`: the bundled profiles.
pub const PROFILES: [Printer; 4] = [
    Printer {
        id: Cow::Borrowed("sl1"),
        model: Cow::Borrowed("SL1"),
        settings_id: Cow::Borrowed("Original Prusa SL1"),
        size: [120.96, 68.04],
        pixels: [2560, 1440],
        portrait: true,
        mirror: [true, false],
        layer_height: 0.05,
        initial_layer_height: 0.05,
        exposure: 7.5,
        initial_exposure: 35.0,
        faded_layers: 10,
        fast_tilt: 5.0,
        slow_tilt: 8.0,
        area_fill: 50.0,
    },
    Printer {
        id: Cow::Borrowed("sl1s"),
        model: Cow::Borrowed("SL1S"),
        settings_id: Cow::Borrowed("Original Prusa SL1S SPEED"),
        size: [128.0, 81.0],
        pixels: [2560, 1620],
        portrait: true,
        mirror: [true, false],
        layer_height: 0.05,
        initial_layer_height: 0.05,
        exposure: 2.0,
        initial_exposure: 25.0,
        faded_layers: 10,
        fast_tilt: 2.5,
        slow_tilt: 5.0,
        area_fill: 45.0,
    },
    Printer {
        id: Cow::Borrowed("mono-4k"),
        model: Cow::Borrowed("6.1-inch 4K mono LCD"),
        settings_id: Cow::Borrowed("6.1-inch 4K mono LCD (3840x2400, 35 um)"),
        size: [134.4, 84.0],
        pixels: [3840, 2400],
        portrait: false,
        mirror: [false, false],
        layer_height: 0.05,
        initial_layer_height: 0.05,
        exposure: 2.5,
        initial_exposure: 30.0,
        faded_layers: 5,
        fast_tilt: 6.0,
        slow_tilt: 8.0,
        area_fill: 50.0,
    },
    Printer {
        id: Cow::Borrowed("mono-8k"),
        model: Cow::Borrowed("10-inch 8K mono LCD"),
        settings_id: Cow::Borrowed("10-inch 8K mono LCD (7680x4320, 28.5 um)"),
        size: [218.88, 123.12],
        pixels: [7680, 4320],
        portrait: false,
        mirror: [false, false],
        layer_height: 0.05,
        initial_layer_height: 0.05,
        exposure: 2.5,
        initial_exposure: 30.0,
        faded_layers: 5,
        fast_tilt: 6.0,
        slow_tilt: 8.0,
        area_fill: 50.0,
    },
];

impl Printer {
    /// The bundled profile `id`.
    pub fn named(id: &str) -> Option<Printer> {
        PROFILES.iter().find(|p| p.id == id).cloned()
    }

    /// A pixel's side along X and Y, mm.
    pub fn pitch(&self) -> [f64; 2] {
        [
            self.size[0] / f64::from(self.pixels[0]),
            self.size[1] / f64::from(self.pixels[1]),
        ]
    }

    /// The layer PNG's width and height.
    pub fn png_size(&self) -> (u32, u32) {
        match self.portrait {
            true => (self.pixels[1], self.pixels[0]),
            false => (self.pixels[0], self.pixels[1]),
        }
    }

    /// Every setting in range, or the flag that is not, in one line.
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        let positive = [
            ("--display", self.size[0]),
            ("--display", self.size[1]),
            ("--layer-height", self.layer_height),
            ("--initial-layer-height", self.initial_layer_height),
        ];
        for (flag, v) in positive {
            if !(v.is_finite() && v > 0.0) {
                return Err((flag, format!("{flag}: {v} is not a positive length (mm)")));
            }
        }
        if self.pixels.contains(&0) || self.pixels.iter().any(|&p| p > MAX_PIXELS) {
            let [x, y] = self.pixels;
            let m = format!("--pixels: {x}x{y}: each side must be 1 to {MAX_PIXELS} pixels");
            return Err(("--pixels", m));
        }
        let times = [
            ("--exposure", self.exposure),
            ("--initial-exposure", self.initial_exposure),
        ];
        for (flag, v) in times {
            if !(v.is_finite() && v >= 0.0) {
                return Err((flag, format!("{flag}: {v} is not a time in seconds")));
            }
        }
        Ok(())
    }
}

/// The widest display side a profile may give, pixels (a 16K panel is 15,360).
pub const MAX_PIXELS: u32 = 32_768;

impl Printer {
    /// Where display pixel (`i` along X, `j` along Y) lands in the layer PNG (column, row):
    /// mirrored on the display first (`display_mirror_x`, `_y`), then, landscape, X to the
    /// right and Y up (rows run down); portrait, turned a quarter turn: Y to the right and
    /// X down, as PrusaSlicer 2.5 lays out the SL1's layers (checked against its archives,
    /// docs/printer.md).
    pub fn png_of(&self, i: u32, j: u32) -> (u32, u32) {
        let [nx, ny] = self.pixels;
        let i = if self.mirror[0] { nx - 1 - i } else { i };
        let j = if self.mirror[1] { ny - 1 - j } else { j };
        match self.portrait {
            true => (j, i),
            false => (i, ny - 1 - j),
        }
    }
}
