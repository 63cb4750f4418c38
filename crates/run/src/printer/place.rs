//! Where the part sits on the display and which heights its layers sample: the part's box
//! centred on the display (as slicers place one part) with its bottom on the platform, its
//! footprint cut to whole display pixels, and the grid of sub-pixel samples the voxelizer
//! runs on (each pixel k×k columns, each layer one slab).

use glam::{DVec2, DVec3};

use super::profile::Printer;

/// The part on the display: scene units are mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Display position (mm from the display's corner, along the bed's X and Y) minus the
    /// scene's: display = scene + shift.
    pub shift: DVec2,
    /// The scene's Z of the platform (the part's bottom).
    pub floor: f64,
    /// The part's pixels: columns `i.0..i.1` along X, `j.0..j.1` along Y.
    pub i: (u32, u32),
    pub j: (u32, u32),
    /// Layers.
    pub layers: usize,
}

/// Why a part cannot be placed.
#[derive(Debug, PartialEq)]
pub enum Misfit {
    /// The part is wider than the display (or placed off it): its size, the display's.
    Off { part: [f64; 2], display: [f64; 2] },
    /// More layers than an archive holds.
    Layers(usize),
    /// A part of no height.
    Flat,
}

impl std::fmt::Display for Misfit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Misfit::Off { part, display } => write!(
                f,
                "the part ({:.2} × {:.2} mm) does not fit on the display ({:.2} × {:.2} mm) \
                 where it is placed",
                part[0], part[1], display[0], display[1]
            ),
            Misfit::Layers(n) => write!(
                f,
                "{n} layers: more than an archive holds ({}); raise --layer-height",
                super::zip::MAX_MEMBERS - 16
            ),
            Misfit::Flat => write!(f, "the part has no height to slice"),
        }
    }
}

/// Place the part of box `lo`..`hi` on `p`'s display: its XY centre at `centre` (mm from
/// the display's centre; default 0, 0).
pub fn place(p: &Printer, (lo, hi): (DVec3, DVec3), centre: DVec2) -> Result<Placement, Misfit> {
    let size = DVec2::from_array(p.size);
    let at = size / 2.0 + centre;
    let shift = at - (lo.truncate() + hi.truncate()) / 2.0;
    let [px, py] = p.pitch();
    let (a, b) = (lo.truncate() + shift, hi.truncate() + shift);
    let fits = a.x >= -1e-9 && a.y >= -1e-9 && b.x <= size.x + 1e-9 && b.y <= size.y + 1e-9;
    if !fits {
        let part = (hi - lo).truncate().to_array();
        return Err(Misfit::Off {
            part,
            display: p.size,
        });
    }
    let cut = |v: f64, pitch: f64, n: u32| ((v / pitch).max(0.0) as u32).min(n);
    let up = |v: f64, pitch: f64, n: u32| ((v / pitch).ceil().max(0.0) as u32).min(n);
    let i = (cut(a.x, px, p.pixels[0]), up(b.x, px, p.pixels[0]));
    let j = (cut(a.y, py, p.pixels[1]), up(b.y, py, p.pixels[1]));
    let height = hi.z - lo.z;
    if height.is_nan() || height <= 0.0 {
        return Err(Misfit::Flat);
    }
    let layers = layer_count(p, height);
    if layers > super::zip::MAX_MEMBERS - 16 {
        return Err(Misfit::Layers(layers));
    }
    Ok(Placement {
        shift,
        floor: lo.z,
        i,
        j,
        layers,
    })
}

/// Layers of a part `height` mm tall: the first, then every whole layer above it (a top
/// thinner than a layer is not printed), as PrusaSlicer 2.5 counts them.
pub fn layer_count(p: &Printer, height: f64) -> usize {
    let rest = ((height - p.initial_layer_height) / p.layer_height + 1e-9).floor();
    1 + rest.max(0.0) as usize
}

/// The height above the platform, mm, at which layer `l` samples the part: the middle of
/// the layer.
pub fn sample_height(p: &Printer, l: usize) -> f64 {
    match l {
        0 => p.initial_layer_height / 2.0,
        _ => p.initial_layer_height + (l as f64 - 0.5) * p.layer_height,
    }
}

impl Placement {
    /// Whether `other` samples the part where this placement does, to 1/256 of a pixel
    /// along X and Y and of a layer along Z: the same pixels, layers and (so nearly that no
    /// sample can tell) the same shift and floor.
    pub fn near(&self, other: &Placement, p: &Printer) -> bool {
        let [px, py] = p.pitch();
        let d = (self.shift - other.shift).abs();
        (self.i, self.j, self.layers) == (other.i, other.j, other.layers)
            && d.x <= px / 256.0
            && d.y <= py / 256.0
            && (self.floor - other.floor).abs() <= p.layer_height / 256.0
    }

    /// The scene's X (`axis` 0) or Y (1) of the low edge of the part's `n`-th pixel along
    /// that axis (`n` = its pixels: the high edge of the last).
    pub fn edge(&self, p: &Printer, axis: usize, n: usize) -> f64 {
        let first = [self.i.0, self.j.0][axis];
        (f64::from(first) + n as f64) * p.pitch()[axis] - self.shift[axis]
    }

    /// The part's pixels along X and Y.
    pub fn pixels(&self) -> [usize; 2] {
        [
            (self.i.1 - self.i.0) as usize,
            (self.j.1 - self.j.0) as usize,
        ]
    }

    /// The voxelizer's box for `layers` (scene units), whose voxel centres are the
    /// sub-pixels' centres and the layers' sample heights when it has `aa`·pixels columns
    /// and a slab per layer. Layers after the first are evenly spaced; the first shares
    /// their grid only when it is as high (else it is a grid of its own, `layers` 0..1).
    pub fn grid(&self, p: &Printer, layers: std::ops::Range<usize>) -> [DVec3; 2] {
        let [w, h] = self.pixels();
        let step = match layers.start == 0 && layers.len() == 1 {
            true => p.initial_layer_height,
            false => p.layer_height,
        };
        let z0 = sample_height(p, layers.start) - step / 2.0;
        let z1 = z0 + step * layers.len() as f64;
        [
            DVec3::new(self.edge(p, 0, 0), self.edge(p, 1, 0), self.floor + z0),
            DVec3::new(self.edge(p, 0, w), self.edge(p, 1, h), self.floor + z1),
        ]
    }
}
