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
