//! Architectural state: every register of every pixel, as both models must agree on it.

use serde::Serialize;

use crate::comparator::FlagBits;
use crate::depth_word::WordFormat;
use crate::program::{CReg, Reg};

/// The size and word format of an array.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct ArrayConfig {
    /// Pixels per row (x runs 0..width, left to right).
    pub width: usize,
    /// Rows (y runs 0..height, top to bottom).
    pub height: usize,
    /// Format of the depth registers A, F, B, C (N_D bits, §2.4.1).
    pub fmt: WordFormat,
    /// Bits of the colour registers D, E, G (at most N_D: they move in the same window).
    pub colour_bits: u32,
    /// Levels of the per-pixel clipping stack.
    pub stack_depth: usize,
}

impl ArrayConfig {
    /// A `width`×`height` array with the thesis word, 8-bit colours and an 8-level stack.
    pub fn new(width: usize, height: usize) -> ArrayConfig {
        ArrayConfig {
            width,
            height,
            fmt: WordFormat::THESIS,
            colour_bits: 8,
            stack_depth: 8,
        }
    }

    /// Number of pixel processors, width × height.
    pub fn pixels(&self) -> usize {
        self.width * self.height
    }

    /// Reject shapes the array cannot be built in.
    pub fn check(&self) -> Result<(), ConfigError> {
        if self.width == 0 || self.height == 0 {
            return Err(ConfigError::NoPixels {
                width: self.width,
                height: self.height,
            });
        }
        let max = self.fmt.bits().min(32);
        if self.colour_bits == 0 || self.colour_bits > max {
            let bits = self.colour_bits;
            return Err(ConfigError::ColourBits { bits, max });
        }
        if self.stack_depth > 64 {
            return Err(ConfigError::StackDepth {
                levels: self.stack_depth,
            });
        }
        Ok(())
    }

    /// Pipeline latency of DEPGEN in clocks: one registered adder per level of the x and y trees
    /// (which run side by side) and the flip-flops that take the coefficient bits in at the
    /// root (§2.4). A bit the controller presents in clock t is on the lines in clock t + L,
    /// and the pixel's adder writes it into A in that clock (`depgen.v` does exactly this).
    pub fn depgen_latency(&self) -> u64 {
        let levels = |n: usize| usize::BITS - (n.max(1) - 1).leading_zeros();
        levels(self.width).max(levels(self.height)) as u64 + 1
    }
}

/// Every register of one pixel processor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Pixel {
    /// Depth registers A, F, B, C (raw words).
    pub depth: [i64; 4],
    /// Colour registers D, E, G.
    pub colour: [u32; 3],
    /// Latched select code (S1/S3, S2/S4).
    pub sel: (bool, bool),
    /// Comparator result of the last window.
    pub flags: FlagBits,
    /// Clipping stack, bit i = level i (level 0 at the bottom).
    pub stack: u64,
}

impl Pixel {
    /// After reset: depth registers hold the Put-1 word, colours the background 0.
    pub fn reset(fmt: &WordFormat) -> Pixel {
        Pixel {
            depth: [fmt.max_word(); 4],
            colour: [0; 3],
            sel: (false, true),
            flags: FlagBits {
                n: false,
                j: true,
                t: true,
                m: false,
            },
            stack: 0,
        }
    }

    /// Depth register `r` (raw word).
    pub fn reg(&self, r: Reg) -> i64 {
        self.depth[r as usize]
    }

    /// Colour register `r`.
    pub fn creg(&self, r: CReg) -> u32 {
        self.colour[r as usize]
    }
}

/// All pixels, row-major, plus the stack pointer the pixels share.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ArchState {
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Every pixel, row-major: pixel (x, y) is `pixels[y * width + x]`.
    pub pixels: Vec<Pixel>,
    /// Clipping stack pointer: levels in use, the next push goes to level `sp`.
    pub sp: usize,
}

impl ArchState {
    /// Pixel (x, y), (0, 0) at the top left.
    pub fn at(&self, x: usize, y: usize) -> &Pixel {
        &self.pixels[y * self.width + x]
    }

    /// The first pixel where two states differ, for test messages.
    pub fn first_difference(&self, other: &ArchState) -> Option<(usize, usize, Pixel, Pixel)> {
        if self.sp != other.sp {
            return Some((usize::MAX, usize::MAX, self.pixels[0], other.pixels[0]));
        }
        let i = (0..self.pixels.len()).find(|&i| self.pixels[i] != other.pixels[i])?;
        Some((
            i % self.width,
            i / self.width,
            self.pixels[i],
            other.pixels[i],
        ))
    }
}

/// Why an array cannot be built in a configuration ([`ArrayConfig::check`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ConfigError {
    /// A width or height of 0.
    NoPixels {
        /// Pixels across.
        width: usize,
        /// Pixels down.
        height: usize,
    },
    /// Colour registers of 0 bits or wider than the depth word (and 32).
    ColourBits {
        /// Bits asked for.
        bits: u32,
        /// The most allowed: N_D, at most 32.
        max: u32,
    },
    /// A clipping stack deeper than 64 levels.
    StackDepth {
        /// Levels asked for.
        levels: usize,
    },
}

impl std::fmt::Display for ConfigError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ConfigError::NoPixels { width, height } => {
                write!(f, "array {width}x{height} has no pixels")
            }
            ConfigError::ColourBits { bits, max } => {
                write!(
                    f,
                    "colour registers of {bits} bits: need 1..={max} (N_D and 32)"
                )
            }
            ConfigError::StackDepth { levels } => {
                write!(f, "clipping stack of {levels} levels: at most 64")
            }
        }
    }
}

impl std::error::Error for ConfigError {}
