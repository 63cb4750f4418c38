//! Colour codes to RGB.
//!
//! The thesis names one code: "2 corresponds to green" (§5.2). Its simulator was a C program
//! of its time, whose 16-colour graphics palette has 2 = green; csgpix uses that palette:
//! 0 black (background), 1 blue, 2 green, 3 cyan, 4 red, 5 magenta, 6 brown, 7 light grey
//! (the interior colour Put 0 writes), 8-15 their bright versions. Codes above 15 repeat it.

const PALETTE: [[u8; 3]; 16] = [
    [0, 0, 0],
    [0, 0, 170],
    [0, 170, 0],
    [0, 170, 170],
    [170, 0, 0],
    [170, 0, 170],
    [170, 85, 0],
    [170, 170, 170],
    [85, 85, 85],
    [85, 85, 255],
    [85, 255, 85],
    [85, 255, 255],
    [255, 85, 85],
    [255, 85, 255],
    [255, 255, 85],
    [255, 255, 255],
];

/// RGB of a colour code.
pub fn rgb(code: u32) -> [u8; 3] {
    PALETTE[(code % 16) as usize]
}

/// Darkest shade, as a fraction of the full colour, at the farthest drawn depth.
const FAR_SHADE: f64 = 0.45;

/// RGB of every pixel. With `depths` (one per pixel, `None` where nothing is drawn) a pixel is
/// shaded by depth: the nearest drawn depth at full colour, the farthest at 0.45 of it, so
/// faces of one colour stay apart. Background (code 0) stays black.
pub fn image_rgb(codes: &[u32], depths: Option<&[Option<f64>]>) -> Vec<[u8; 3]> {
    let Some(depths) = depths else {
        return codes.iter().map(|&c| rgb(c)).collect();
    };
    let drawn = || {
        codes
            .iter()
            .zip(depths)
            .filter(|(&c, _)| c != 0)
            .filter_map(|(_, d)| *d)
    };
    let lo = drawn().fold(f64::INFINITY, f64::min);
    let hi = drawn().fold(f64::NEG_INFINITY, f64::max);
    let span = (hi - lo).max(1e-9);
    codes
        .iter()
        .zip(depths)
        .map(|(&c, d)| {
            let t = d.map_or(0.0, |d| ((d - lo) / span).clamp(0.0, 1.0));
            let k = 1.0 - (1.0 - FAR_SHADE) * t;
            rgb(c).map(|v| (v as f64 * k).round() as u8)
        })
        .collect()
}
