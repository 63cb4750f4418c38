//! What a scene requires of the hardware, so that the simulator models only that: the panels
//! its primitives touch, the slabs that hold geometry, the clipping-stack depth and Blist
//! label width its expressions need, and the depth word a precision needs.
//!
//! Pixels and slabs come from the array's own plane words ([`word_ranges`](crate::ranges::word_ranges), the interval
//! route, proven voxel for voxel equal to the array in `tests/voxelize.rs`): a primitive is
//! nowhere outside the pixels and slabs where those words put it, because every slice's
//! display list carries the solid's silhouette planes (perpendicular, K < 0 outside) and the
//! slab's two clipping planes. So skipping the rest changes no voxel; `tests/requirements.rs`
//! checks that on every example scene and on random ones, for both processor models.

use rtl_model::WordFormat;

/// How slicing lays a scene `extent` scene units deep into `slabs` slabs on a `w`×`h` array.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthLayout {
    /// The grid's depth (Z extent), scene units.
    pub extent: f64,
    /// Slabs (Z voxels).
    pub slabs: usize,
    /// Array width, pixels.
    pub w: usize,
    /// Array height, pixels.
    pub h: usize,
}

impl DepthLayout {
    /// The largest depth error of a plane word anywhere on the array, in scene units, for
    /// `fmt` (None when the slabs do not fit the word).
    ///
    /// A word of I integer and F fraction bits holds depths 0..2^I (maxdepth, §2.3.1);
    /// slicing keeps [`DEPTH_MARGIN`](csgpix_draw::project::DEPTH_MARGIN) depth units clear at both
    /// ends and gives each slab q = ⌊(2^I − 2·margin)·2^F / slabs⌋ raw units
    /// (docs/voxelization.md), so one raw unit is extent / (slabs·q) scene units. Z0, dZx and
    /// dZy are each rounded to the nearest raw unit, so DEPGEN's Z0 + x·dZx + y·dZy is off by
    /// at most ½(1 + x + y) raw units: ½(1 + (w − 1) + (h − 1)) at the far corner.
    pub fn error(&self, fmt: &WordFormat) -> Option<f64> {
        let margin = csgpix_draw::project::DEPTH_MARGIN as i64;
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
