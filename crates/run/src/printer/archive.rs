//! What a printer takes: Prusa's `.sl1`/`.sl1s` (a zip of `config.ini`, `prusaslicer.ini`,
//! numbered layer PNGs and thumbnails, with the fields PrusaSlicer 2.5 writes), or a plain
//! stack of layer PNGs with `print.json` for other printers.

use std::path::Path;

use serde::Serialize;

use super::place::{sample_height, Placement};
use super::profile::Printer;
use super::raster::Raster;

/// The output's kind, from `-o`'s extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `*.sl1`, `*.sl1s`.
    Prusa,
    /// Anything else: a directory.
    Stack,
}

impl Kind {
    pub fn of(out: &Path) -> Kind {
        let ext = out.extension().and_then(|e| e.to_str()).unwrap_or("");
        match ext.to_ascii_lowercase().as_str() {
            "sl1" | "sl1s" => Kind::Prusa,
            _ => Kind::Stack,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Kind::Prusa => "sl1",
            Kind::Stack => "png stack",
        }
    }
}

/// The job's name in the archive (`jobDir`, the layers' prefix): the output's stem.
pub fn job_name(out: &Path) -> String {
    let stem = out.file_stem().and_then(|s| s.to_str()).unwrap_or("part");
    let name: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if name.is_empty() {
        "part".into()
    } else {
        name
    }
}

/// Layer `l`'s file name: PrusaSlicer's `{jobDir}{l:05}.png` in an archive,
/// `layer-{l:05}.png` in a stack.
pub fn layer_name(kind: Kind, job: &str, l: usize) -> String {
    match kind {
        Kind::Prusa => format!("{job}{l:05}.png"),
        Kind::Stack => format!("layer-{l:05}.png"),
    }
}

/// Every layer's exposure, s, as PrusaSlicer 2.5 times them (`SLAPrint::Steps::
/// merge_slices_and_eval_stats`): the first three layers the first layer's, then a time
/// falling by (first − others) / (faded + 1) a layer while it is above the others', then
/// the others'.
pub fn exposures(p: &Printer, layers: usize) -> Vec<f64> {
    let delta = (p.initial_exposure - p.exposure) / (f64::from(p.faded_layers) + 1.0);
    let mut fade = p.initial_exposure;
    (0..layers)
        .map(|l| match l {
            0..3 => p.initial_exposure,
            _ if fade > p.exposure => {
                fade -= delta;
                fade
            }
            _ => p.exposure,
        })
        .collect()
}

/// Whether a layer of `area` mm² is fast: at most `area_fill` % of the display.
pub fn fast(p: &Printer, area: f64) -> bool {
    area <= p.size[0] * p.size[1] * p.area_fill / 100.0
}

/// The print's duration, s, as PrusaSlicer 2.5 estimates it from the layers' areas (mm²):
/// each layer's exposure, its tilt (fast or slow by area), 1 s more before a slow layer's
/// exposure, and the tower's move (5 s a mm of layer).
pub fn print_seconds(p: &Printer, areas: &[f64]) -> f64 {
    let e = exposures(p, areas.len());
    let layer = |(l, &a): (usize, &f64)| {
        let h = if l == 0 {
            p.initial_layer_height
        } else {
            p.layer_height
        };
        let tilt = if fast(p, a) {
            p.fast_tilt
        } else {
            p.slow_tilt + 1.0
        };
        e[l] + tilt + h * 5.0
    };
    areas.iter().enumerate().map(layer).sum()
}

/// The totals an archive states, from the layers made.
pub struct Summary {
    pub material_ml: f64,
    pub print_seconds: f64,
    /// Layers of at most `area_fill` of the display, and the others.
    pub fast: usize,
    pub slow: usize,
    pub materials: Vec<u8>,
    /// The array's clocks and frames for these layers.
    pub array: [u64; 2],
}

impl Summary {
    pub fn of(p: &Printer, raster: &Raster, array: [u64; 2]) -> Summary {
        let [px, py] = p.pitch();
        let areas: Vec<f64> = raster
            .areas
            .iter()
            .map(|&g| g as f64 / 255.0 * px * py)
            .collect();
        let heights = (0..areas.len()).map(|l| match l {
            0 => p.initial_layer_height,
            _ => p.layer_height,
        });
        let volume: f64 = areas.iter().zip(heights).map(|(a, h)| a * h).sum();
        let fast = areas.iter().filter(|&&a| fast(p, a)).count();
        Summary {
            material_ml: volume / 1000.0,
            print_seconds: print_seconds(p, &areas),
            fast,
            slow: areas.len() - fast,
            materials: raster.materials(),
            array,
        }
    }
}

/// `config.ini` as PrusaSlicer 2.5 writes it (its keys, in its order).
pub fn config_ini(p: &Printer, job: &str, s: &Summary, stamp: &str) -> String {
    let fields = [
        ("action", "print".to_string()),
        ("expTime", fmt(p.exposure)),
        ("expTimeFirst", fmt(p.initial_exposure)),
        ("expUserProfile", "0".into()),
        ("fileCreationTimestamp", stamp.to_string()),
        ("hollow", "0".into()),
        ("jobDir", job.to_string()),
        ("layerHeight", fmt(p.layer_height)),
        ("materialName", "csgpix".into()),
        ("numFade", p.faded_layers.to_string()),
        ("numFast", s.fast.to_string()),
        ("numSlow", s.slow.to_string()),
        ("printProfile", "csgpix".into()),
        ("printTime", format!("{:.6}", s.print_seconds)),
        ("printerModel", p.model.to_string()),
        ("printerProfile", p.settings_id.to_string()),
        ("printerVariant", "default".into()),
        (
            "prusaSlicerVersion",
            format!("csgpix-{}", env!("CARGO_PKG_VERSION")),
        ),
        ("usedMaterial", format!("{:.6}", s.material_ml)),
    ];
    fields.iter().map(|(k, v)| format!("{k} = {v}\n")).collect()
}

/// `prusaslicer.ini`: the printer's and the print's settings under PrusaSlicer's names.
pub fn prusaslicer_ini(p: &Printer, at: &Placement) -> String {
    let b = |v: bool| if v { "1" } else { "0" };
    let fields = [
        ("display_height", fmt(p.size[1])),
        ("display_mirror_x", b(p.mirror[0]).into()),
        ("display_mirror_y", b(p.mirror[1]).into()),
        (
            "display_orientation",
            if p.portrait { "portrait" } else { "landscape" }.into(),
        ),
        ("display_pixels_x", p.pixels[0].to_string()),
        ("display_pixels_y", p.pixels[1].to_string()),
        ("display_width", fmt(p.size[0])),
        ("area_fill", fmt(p.area_fill)),
        ("exposure_time", fmt(p.exposure)),
        ("fast_tilt_time", fmt(p.fast_tilt)),
        ("faded_layers", p.faded_layers.to_string()),
        ("initial_exposure_time", fmt(p.initial_exposure)),
        ("initial_layer_height", fmt(p.initial_layer_height)),
        ("layer_height", fmt(p.layer_height)),
        ("pad_enable", "0".into()),
        ("printer_model", p.model.to_string()),
        ("printer_settings_id", p.settings_id.to_string()),
        ("printer_technology", "SLA".into()),
        ("slow_tilt_time", fmt(p.slow_tilt)),
        ("supports_enable", "0".into()),
    ];
    let mut s = String::from("# generated by csgpix\n");
    for (k, v) in fields {
        s += &format!("{k} = {v}\n");
    }
    s += &format!(
        "# part pixels x {}..{}, y {}..{}\n",
        at.i.0, at.i.1, at.j.0, at.j.1
    );
    s
}

/// A number as PrusaSlicer's ini files write it: no trailing zeros.
fn fmt(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

/// `print.json` beside a PNG stack: what a printer needs to show the layers.
#[derive(Serialize)]
pub struct StackInfo<'a> {
    pub printer: &'a str,
    pub image: [u32; 2],
    pub display_mm: [f64; 2],
    pub pixels: [u32; 2],
    pub portrait: bool,
    pub mirror: [bool; 2],
    pub layer_height: f64,
    pub initial_layer_height: f64,
    pub layers: usize,
    /// Height above the platform at which each layer samples the part, mm.
    pub sample_heights: Vec<f64>,
    pub exposure: Vec<f64>,
    pub part_pixels: [usize; 2],
    pub part_origin: [u32; 2],
    pub aa: u32,
    pub material_ml: f64,
    pub print_seconds: f64,
    pub files: String,
}

impl StackInfo<'_> {
    pub fn of<'a>(p: &'a Printer, at: &Placement, aa: u32, s: &Summary) -> StackInfo<'a> {
        let (w, h) = p.png_size();
        StackInfo {
            printer: &p.id,
            image: [w, h],
            display_mm: p.size,
            pixels: p.pixels,
            portrait: p.portrait,
            mirror: p.mirror,
            layer_height: p.layer_height,
            initial_layer_height: p.initial_layer_height,
            layers: at.layers,
            sample_heights: (0..at.layers).map(|l| sample_height(p, l)).collect(),
            exposure: exposures(p, at.layers),
            part_pixels: at.pixels(),
            part_origin: [at.i.0, at.j.0],
            aa,
            material_ml: s.material_ml,
            print_seconds: s.print_seconds,
            files: "layer-NNNNN.png".into(),
        }
    }
}

/// The thumbnails of `sizes` as PNG bytes, made in parallel ([`thumbnail`]).
pub fn thumbnail_pngs(
    raster: &mut Raster,
    layers: usize,
    sizes: &[(u32, u32)],
) -> std::io::Result<Vec<Vec<u8>>> {
    use rayon::prelude::*;
    let footprint = raster.footprint();
    let top = raster.top();
    sizes
        .par_iter()
        .map(|&size| png_bytes(&thumbnail(top, footprint, layers, size)))
        .collect()
}

/// Thumbnails as PrusaSlicer names them, of the part seen from above: each pixel of the
/// footprint (`fw`×`fh`, 1 + its top layer in `top`, 0 where none lights it) shaded by the
/// height of its top layer, fitted into `w`×`h`.
pub fn thumbnail(
    top: &[u16],
    [fw, fh]: [usize; 2],
    layers: usize,
    (w, h): (u32, u32),
) -> image::RgbImage {
    let mut img = image::RgbImage::from_pixel(w, h, image::Rgb([32, 32, 36]));
    if fw == 0 || fh == 0 || layers == 0 {
        return img;
    }
    let scale = (f64::from(w) / fw as f64).min(f64::from(h) / fh as f64);
    let (dw, dh) = ((fw as f64 * scale) as u32, (fh as f64 * scale) as u32);
    let (ox, oy) = ((w - dw.min(w)) / 2, (h - dh.min(h)) / 2);
    for y in 0..dh.min(h) {
        for x in 0..dw.min(w) {
            let a = ((f64::from(x) / scale) as usize).min(fw - 1);
            let b = fh - 1 - ((f64::from(y) / scale) as usize).min(fh - 1);
            let top = top[b * fw + a];
            if top == 0 {
                continue;
            }
            let t = f64::from(top) / layers as f64;
            let shade = |c: f64| (c * (0.35 + 0.65 * t)) as u8;
            img.put_pixel(
                ox + x,
                oy + y,
                image::Rgb([shade(255.0), shade(128.0), shade(64.0)]),
            );
        }
    }
    img
}

/// PNG bytes of an RGB image.
pub fn png_bytes(img: &image::RgbImage) -> std::io::Result<Vec<u8>> {
    let mut v = vec![];
    crate::png::write_png(&mut v, img)?;
    Ok(v)
}
