//! Where a primitive is: the pixels and slabs its slices can show anything in, from the
//! array's own plane words (docs/requirements.md), and the panels those pixels touch.

use serde::Serialize;

use crate::error::Result;
use crate::ranges::word_ranges;
use crate::slabs::SlabRanges;
use crate::slicer::Slicer;
// Here before crate::pixel_box took it: the public path stays.
pub use crate::pixel_box::PixelBox;

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
pub fn footprints(slicer: &Slicer) -> Result<Vec<Footprint>> {
    use rayon::prelude::*;
    let w = slicer.grid.dims[0];
    (0..slicer.lists.len())
        .into_par_iter()
        .map(|p| word_ranges(slicer, p).map(|r| Footprint::of(&r, w)))
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
}
