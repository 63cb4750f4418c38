//! What a scene requires of the hardware, so that the simulator models only that: the panels
//! its primitives touch, the slabs that hold geometry, the clipping-stack depth and Blist
//! label width its expressions need, and the depth word a precision needs.
//!
//! Pixels and slabs come from the array's own plane words ([`word_ranges`], the interval
//! route, proven voxel for voxel equal to the array in `tests/voxelize.rs`): a primitive is
//! nowhere outside the pixels and slabs where those words put it, because every slice's
//! display list carries the solid's silhouette planes (perpendicular, K < 0 outside) and the
//! slab's two clipping planes. So skipping the rest changes no voxel; `tests/requirements.rs`
//! checks that on every example scene and on random ones, for both processor models.

use rtl_model::WordFormat;
use serde::Serialize;

use crate::voxelize::{SlabRanges, Slicer};

/// A rectangle of pixels, `x0..x1` × `y0..y1` (half-open).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct PixelBox {
    pub x0: usize,
    pub y0: usize,
    pub x1: usize,
    pub y1: usize,
}

impl PixelBox {
    pub fn width(&self) -> usize {
        self.x1 - self.x0
    }

    pub fn height(&self) -> usize {
        self.y1 - self.y0
    }

    pub fn pixels(&self) -> usize {
        self.width() * self.height()
    }

    /// Grown outwards to whole panels of `panel` pixels, within a `w`×`h` array.
    pub fn to_panels(self, panel: [usize; 2], w: usize, h: usize) -> PixelBox {
        let [pw, ph] = panel.map(|p| p.max(1));
        PixelBox {
            x0: self.x0 / pw * pw,
            y0: self.y0 / ph * ph,
            x1: self.x1.div_ceil(pw).saturating_mul(pw).min(w),
            y1: self.y1.div_ceil(ph).saturating_mul(ph).min(h),
        }
    }

    /// The smallest box holding both.
    pub fn union(self, o: PixelBox) -> PixelBox {
        PixelBox {
            x0: self.x0.min(o.x0),
            y0: self.y0.min(o.y0),
            x1: self.x1.max(o.x1),
            y1: self.y1.max(o.y1),
        }
    }
}

/// Where one primitive is: the pixels and slabs its slices can show anything in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Footprint {
    /// Pixels whose ray meets the primitive (None: it is nowhere on the array).
    pub pixels: Option<PixelBox>,
    /// Slabs `first..=last` the primitive meets on some pixel.
    pub slabs: Option<(u32, u32)>,
}

impl Footprint {
    /// From the primitive's per-pixel slab ranges on a `w`-pixel-wide array.
    pub fn of(ranges: &SlabRanges, w: usize) -> Footprint {
        let (mut bx, mut slabs): (Option<PixelBox>, Option<(u32, u32)>) = (None, None);
        for (i, &(a, b)) in ranges.0.iter().enumerate() {
            if a > b {
                continue;
            }
            let (x, y) = (i % w, i / w);
            let px = PixelBox {
                x0: x,
                y0: y,
                x1: x + 1,
                y1: y + 1,
            };
            bx = Some(bx.map_or(px, |b| b.union(px)));
            slabs = Some(slabs.map_or((a, b), |(f, l)| (f.min(a), l.max(b))));
        }
        Footprint { pixels: bx, slabs }
    }

    /// Whether slab k can show anything of the primitive.
    pub fn holds(&self, k: usize) -> bool {
        self.pixels.is_some()
            && self
                .slabs
                .is_some_and(|(f, l)| f as usize <= k && k <= l as usize)
    }

    /// Number of slabs that hold the primitive.
    pub fn slab_count(&self) -> usize {
        self.slabs.map_or(0, |(f, l)| (l - f + 1) as usize)
    }
}

/// The footprint of every primitive of a sliced scene.
pub fn footprints(slicer: &Slicer) -> Result<Vec<Footprint>, String> {
    use rayon::prelude::*;
    let w = slicer.grid.dims[0];
    (0..slicer.lists.len())
        .into_par_iter()
        .map(|p| crate::voxelize::word_ranges(slicer, p).map(|r| Footprint::of(&r, w)))
        .collect()
}

/// Panels (of `panel` pixels, row-major over a `w`×`h` array) that `boxes` touch.
pub fn touched_panels(boxes: &[PixelBox], panel: [usize; 2], w: usize, h: usize) -> Vec<bool> {
    let [pw, ph] = panel.map(|p| p.max(1));
    let (nx, ny) = (w.div_ceil(pw), h.div_ceil(ph));
    let mut t = vec![false; nx * ny];
    for b in boxes {
        for py in b.y0 / ph..b.y1.div_ceil(ph).min(ny) {
            for px in b.x0 / pw..b.x1.div_ceil(pw).min(nx) {
                t[py * nx + px] = true;
            }
        }
    }
    t
}

/// How slicing lays a scene `extent` scene units deep into `slabs` slabs on a `w`×`h` array.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthLayout {
    pub extent: f64,
    pub slabs: usize,
    pub w: usize,
    pub h: usize,
}

impl DepthLayout {
    /// The largest depth error of a plane word anywhere on the array, in scene units, for
    /// `fmt` (None when the slabs do not fit the word).
    ///
    /// A word of I integer and F fraction bits holds depths 0..2^I (maxdepth, §2.3.1);
    /// slicing keeps [`DEPTH_MARGIN`](crate::project::DEPTH_MARGIN) depth units clear at both
    /// ends and gives each slab q = ⌊(2^I − 2·margin)·2^F / slabs⌋ raw units
    /// (docs/voxelization.md), so one raw unit is extent / (slabs·q) scene units. Z0, dZx and
    /// dZy are each rounded to the nearest raw unit, so DEPGEN's Z0 + x·dZx + y·dZy is off by
    /// at most ½(1 + x + y) raw units: ½(1 + (w − 1) + (h − 1)) at the far corner.
    pub fn error(&self, fmt: &WordFormat) -> Option<f64> {
        let margin = crate::project::DEPTH_MARGIN as i64;
        let q = (fmt.maxdepth() - 2 * (margin << fmt.frac)) / self.slabs.max(1) as i64;
        let raw_units = 0.5 * (self.w + self.h).saturating_sub(1) as f64;
        (q >= 1).then(|| raw_units * self.extent / (self.slabs as f64 * q as f64))
    }

    /// The narrowest word (fewest N_D bits, so fewest clocks per plane, eq. 2.3) whose
    /// [`error`](Self::error) is at most `precision` scene units, with `base`'s overflow
    /// field; among words of that width, the one with the most integer bits (the widest depth
    /// range, so the gentlest slopes, §2.3.1). None if no word up to 62 bits reaches it.
    pub fn word_for(&self, precision: f64, base: WordFormat) -> Option<WordFormat> {
        for total in 2..=62u32.saturating_sub(base.ovf) {
            for int in (1..total).rev() {
                let Ok(fmt) = WordFormat::new(total - int, int, base.ovf) else {
                    continue;
                };
                if self.error(&fmt).is_some_and(|e| e <= precision) {
                    return Some(fmt);
                }
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boxes_grow_to_whole_panels_within_the_array() {
        let b = PixelBox {
            x0: 5,
            y0: 33,
            x1: 6,
            y1: 65,
        };
        assert_eq!(
            b.to_panels([16, 32], 40, 70),
            PixelBox {
                x0: 0,
                y0: 32,
                x1: 16,
                y1: 70
            }
        );
    }

    #[test]
    fn panels_touched_by_a_corner_box() {
        let b = PixelBox {
            x0: 30,
            y0: 0,
            x1: 33,
            y1: 2,
        };
        // 64×64 array, 32×32 panels: the box straddles panels 0 and 1 of the top row.
        assert_eq!(
            touched_panels(&[b], [32, 32], 64, 64),
            [true, true, false, false]
        );
    }

    #[test]
    fn footprint_of_ranges() {
        // 3×2 array; pixel (1,0) meets slabs 2..=4, pixel (2,1) slab 7, the rest nothing.
        let empty = (1, 0);
        let r = SlabRanges(vec![empty, (2, 4), empty, empty, empty, (7, 7)]);
        let f = Footprint::of(&r, 3);
        assert_eq!(
            f.pixels,
            Some(PixelBox {
                x0: 1,
                y0: 0,
                x1: 3,
                y1: 2
            })
        );
        assert_eq!(f.slabs, Some((2, 7)));
        assert!(f.holds(2) && f.holds(7) && !f.holds(1) && !f.holds(8));
        assert_eq!(f.slab_count(), 6);
        let none = Footprint::of(&SlabRanges(vec![empty; 4]), 2);
        assert_eq!(
            (none.pixels, none.slabs, none.holds(0)),
            (None, None, false)
        );
    }

    #[test]
    fn the_word_for_a_precision() {
        let base = WordFormat::THESIS;
        // 20 scene units in 64 slabs on a 64×64 array, to 0.01: the far corner is off by
        // ½·127 raw units, so 63.5·20 / (64 q) <= 0.01 needs q >= 1984.4. The room is
        // (2^I − 8)·2^F raw units, q = room / 64, so I + F = 17 bits is the least:
        // 16 bits give at most (2^16 − 8·2) / 64 = 1023 (I = 15, F = 1), 17 bits give
        // (2^17 − 16) / 64 = 2047 with I = 16, F = 1.
        let d = DepthLayout {
            extent: 20.0,
            slabs: 64,
            w: 64,
            h: 64,
        };
        let f = d.word_for(0.01, base).unwrap();
        assert_eq!((f.int, f.frac, f.ovf), (16, 1, base.ovf));
        let e = d.error(&f).unwrap();
        assert!((e - 63.5 * 20.0 / (64.0 * 2047.0)).abs() < 1e-12, "{e}");
        // The thesis word (F = 10, I = 10): q = 1016·1024/64 = 16,256.
        let t = d.error(&base).unwrap();
        assert!((t - 63.5 * 20.0 / (64.0 * 16256.0)).abs() < 1e-15);
        assert!(d.word_for(0.0, base).is_none());
        // Too many slabs for a word: no error figure.
        let many = DepthLayout {
            slabs: 1 << 30,
            ..d
        };
        assert!(many.error(&base).is_none());
    }
}
