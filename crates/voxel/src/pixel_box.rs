//! A rectangle of pixels. A leaf module: the footprints, the routes, the slicer and the
//! drivers all speak of pixel boxes, and it speaks of none of them.

use serde::Serialize;

/// A rectangle of pixels, `x0..x1` × `y0..y1` (half-open).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct PixelBox {
    /// First column.
    pub x0: usize,
    /// First row.
    pub y0: usize,
    /// One past the last column.
    pub x1: usize,
    /// One past the last row.
    pub y1: usize,
}

impl PixelBox {
    /// The box `x0..x1` × `y0..y1`.
    pub const fn new(x0: usize, y0: usize, x1: usize, y1: usize) -> PixelBox {
        PixelBox { x0, y0, x1, y1 }
    }

    /// Columns.
    pub fn width(&self) -> usize {
        self.x1 - self.x0
    }

    /// Rows.
    pub fn height(&self) -> usize {
        self.y1 - self.y0
    }

    /// Pixels, width × height.
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

    /// The pixels in both (None when they share none).
    pub fn intersect(self, o: PixelBox) -> Option<PixelBox> {
        let b = PixelBox {
            x0: self.x0.max(o.x0),
            y0: self.y0.max(o.y0),
            x1: self.x1.min(o.x1),
            y1: self.y1.min(o.y1),
        };
        (b.x0 < b.x1 && b.y0 < b.y1).then_some(b)
    }

    /// Whether pixel (x, y) is in the box.
    pub fn contains(&self, x: usize, y: usize) -> bool {
        (self.x0..self.x1).contains(&x) && (self.y0..self.y1).contains(&y)
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
