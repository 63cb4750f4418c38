//! A layer image from a slab of samples: each display pixel of the part's footprint takes
//! the share of its k×k samples that are inside (8-bit grey, 255 all in), placed where the
//! display shows it in the PNG; per material label too where the scene has several.

use super::place::Placement;
use super::profile::Printer;

/// Put footprint greys `grey` (rows `fw` wide) in `lit` at `origin` + a·`step[0]` +
/// b·`step[1]`. A landscape display keeps the footprint's rows as the PNG's (each a copy,
/// reversed when mirrored); a portrait one turns them into the PNG's columns, 8×8 pixels
/// at a time: eight words read along the footprint's rows, transposed, written along the
/// PNG's.
fn place(grey: &[u8], fw: usize, lit: &mut [u8], origin: isize, step: [isize; 2]) {
    let fh = grey.len() / fw.max(1);
    if step[0].abs() == 1 || fw <= 1 {
        for (b, src) in grey.chunks_exact(fw.max(1)).enumerate() {
            let start = (origin + b as isize * step[1]) as usize;
            match step[0] >= 0 {
                true => lit[start..start + fw].copy_from_slice(src),
                false => {
                    let dst = &mut lit[start + 1 - fw..=start];
                    dst.iter_mut().rev().zip(src).for_each(|(d, &g)| *d = g);
                }
            }
        }
        return;
    }
    let whole = |n: usize| n - n % 8;
    // By tiles of 64 footprint columns: the 64 PNG rows a tile writes stay in the first
    // cache level (and its pages in the TLB) while the tile's footprint rows go by.
    let tiles = (0..whole(fw)).step_by(64);
    for (t0, b0) in tiles.flat_map(|t| (0..whole(fh)).step_by(8).map(move |b| (t, b))) {
        for a0 in (t0..(t0 + 64).min(whole(fw))).step_by(8) {
            let rows: [u64; 8] = std::array::from_fn(|r| {
                let at = (b0 + r) * fw + a0;
                u64::from_le_bytes(grey[at..at + 8].try_into().unwrap_or([0; 8]))
            });
            // A block of one grey (inside or outside the part, most of a layer) is its own
            // transpose.
            let uniform = rows
                .iter()
                .all(|&w| w == u64::from_le_bytes([rows[0] as u8; 8]));
            let words = if uniform { rows } else { transpose8(rows) };
            for (c, word) in words.into_iter().enumerate() {
                let row = origin + (a0 + c) as isize * step[0];
                let bytes = word.to_le_bytes();
                match step[1] >= 0 {
                    true => {
                        let at = (row + b0 as isize) as usize;
                        lit[at..at + 8].copy_from_slice(&bytes);
                    }
                    false => {
                        let at = (row - b0 as isize) as usize;
                        lit[at - 7..=at]
                            .iter_mut()
                            .rev()
                            .zip(bytes)
                            .for_each(|(d, g)| *d = g);
                    }
                }
            }
        }
    }
    // The columns and rows the 8×8 blocks leave, one pixel at a time.
    let at = |a: usize, b: usize| (origin + a as isize * step[0] + b as isize * step[1]) as usize;
    for b in 0..fh {
        let from = if b < whole(fh) { whole(fw) } else { 0 };
        for a in from..fw {
            lit[at(a, b)] = grey[b * fw + a];
        }
    }
}

/// Samples [`Raster::layer_by_changes`] compares to the last layer's greys at once.
const CHANGE_SCAN: usize = 64;

/// The sum of `b`'s bytes, in 64 KiB chunks whose sums fit a `u32`: a loop the compiler
/// runs 16 or 32 bytes a step, where widening each byte to a `u64` it runs one.
fn byte_sum(b: &[u8]) -> u64 {
    let chunk = |c: &[u8]| u64::from(c.iter().map(|&v| u32::from(v)).sum::<u32>());
    b.chunks(1 << 16).map(chunk).sum()
}

// `Raster::top` holds 1 + a layer's index in a `u16`.
const _: () = assert!(super::zip::MAX_MEMBERS <= u16::MAX as usize);

/// Places a layer's boxes are held at once ([`Raster::bytes`]): the raster's, four queued
/// for the encoder, one being encoded, two spares on their way back.
pub const BOX_SETS: u64 = 8;

/// An 8×8 block of bytes transposed: word r's byte c becomes word c's byte r (three rounds
/// of swapping 1-, 2- and 4-byte blocks between words, Hacker's Delight §7-3).
fn transpose8(mut w: [u64; 8]) -> [u64; 8] {
    #[inline(always)]
    fn swap(w: &mut [u64; 8], r: usize, span: usize, shift: u32, mask: u64) {
        let t = ((w[r] >> shift) ^ w[r + span]) & mask;
        w[r + span] ^= t;
        w[r] ^= t << shift;
    }
    const M1: u64 = 0x00ff_00ff_00ff_00ff;
    const M2: u64 = 0x0000_ffff_0000_ffff;
    const M4: u64 = 0x0000_0000_ffff_ffff;
    for r in [0, 2, 4, 6] {
        swap(&mut w, r, 1, 8, M1);
    }
    for r in [0, 1, 4, 5] {
        swap(&mut w, r, 2, 16, M2);
    }
    for r in [0, 1, 2, 3] {
        swap(&mut w, r, 4, 32, M4);
    }
    w
}

/// The layer being made, and what the run keeps across layers.
pub struct Raster {
    printer: Printer,
    k: usize,
    /// The footprint's pixels along X and Y.
    fw: usize,
    fh: usize,
    i0: u32,
    j0: u32,
    /// The PNG rows and columns the footprint covers.
    pub rows: (u32, u32),
    pub cols: (u32, u32),
    /// The box `rows` × `cols` of the PNG, the current layer, row by row.
    lit: Vec<u8>,
    /// The footprint's greys of the last layer made, and a buffer for the next one's.
    grey: Vec<u8>,
    next: Vec<u8>,
    /// Per footprint pixel, 1 + the highest layer that lit it (0: none), for thumbnails,
    /// up to the layers before the greys in `grey` ([`Raster::top`] adds them). A `u16`:
    /// a print has fewer layers than an archive has members (`place::place` refuses more),
    /// and the select that updates it every layer moves half the bytes of a `u32`'s.
    top: Vec<u16>,
    /// Layers made.
    layer: u32,
    /// Whether the last layer made is the one before it again: its boxes are the ones
    /// already handed over, and [`Raster::take_boxes`] is not to be called for it.
    repeated: bool,
    /// Per layer made, its grey levels' sum (255 a full pixel).
    pub areas: Vec<u64>,
    /// The scene's material labels (colour codes) when it has more than one, each with the
    /// PNG rows of its own stack; else empty.
    by_code: Vec<(u8, Vec<u8>)>,
    /// With materials, the last layer's samples (their codes), to tell a repeated layer.
    samples: Vec<u8>,
}

impl Raster {
    /// The raster of the part placed `at` on `p`'s display, `aa`×`aa` samples a pixel; a
    /// stack per label of `codes` when there are several.
    pub fn new(p: &Printer, at: &Placement, aa: u32, codes: &[u8]) -> Raster {
        let [fw, fh] = at.pixels();
        let corners = [(at.i.0, at.j.0), (at.i.1.max(1) - 1, at.j.1.max(1) - 1)];
        let png = corners.map(|(i, j)| p.png_of(i, j));
        let rows = (png[0].1.min(png[1].1), png[0].1.max(png[1].1) + 1);
        let cols = (png[0].0.min(png[1].0), png[0].0.max(png[1].0) + 1);
        let (rows, cols) = match fw * fh {
            0 => ((0, 0), (0, 0)),
            _ => (rows, cols),
        };
        let band = (rows.1 - rows.0) as usize * (cols.1 - cols.0) as usize;
        let mut codes: Vec<u8> = codes.iter().copied().filter(|&c| c != 0).collect();
        codes.sort_unstable();
        codes.dedup();
        if codes.len() < 2 {
            codes.clear();
        }
        Raster {
            printer: p.clone(),
            k: aa as usize,
            fw,
            fh,
            i0: at.i.0,
            j0: at.j.0,
            rows,
            cols,
            lit: vec![0; band],
            grey: vec![],
            next: vec![],
            top: vec![0; fw * fh],
            layer: 0,
            repeated: false,
            areas: vec![],
            by_code: codes.into_iter().map(|c| (c, vec![0; band])).collect(),
            samples: vec![],
        }
    }

    /// Bytes a raster holds for `at` (the estimate beside the voxelizer's).
    ///
    /// A layer's boxes (the part's and each material's) are held in [`BOX_SETS`] places at
    /// once: the raster's own, the encoder's queue, the one being encoded and the spares
    /// coming back. Beside them, the footprint's greys of two layers (a byte a pixel each)
    /// and `top` (two), and with materials the last layer's `aa`² samples a pixel.
    pub fn bytes(at: &Placement, aa: u32, codes: usize) -> u64 {
        let [fw, fh] = at.pixels();
        let band = (fw * fh) as u64;
        let samples = if codes > 1 {
            band * u64::from(aa * aa)
        } else {
            0
        };
        band * (1 + codes as u64) * BOX_SETS + 4 * band + samples + (1 << 20)
    }

    /// Make the layer whose samples are `s` (the voxelizer's slab: k·fw samples a row,
    /// k·fh rows; a sample's colour code, 0 outside): its PNG box, then each material's,
    /// are what [`Raster::take_boxes`] hands over next, unless the layer repeats the one
    /// before ([`Raster::repeated`]).
    pub fn layer(&mut self, s: &[u8]) {
        if self.k == 1 && self.by_code.is_empty() && self.layer > 0 {
            return self.layer_by_changes(s);
        }
        let mut grey = std::mem::take(&mut self.next);
        self.greys(s, None, &mut grey);
        // Most of a part's layers are the one below again (walls run straight between
        // the tops and bottoms of its features): such a layer keeps the boxes, the area and
        // the extent it had. With materials, equal greys can hide a change of colour, so
        // the samples themselves (their codes) must be the layer before's.
        let same_codes = self.by_code.is_empty() || s == &self.samples[..];
        self.repeated = self.layer > 0 && same_codes && grey == self.grey;
        if !same_codes {
            self.samples.clear();
            self.samples.extend_from_slice(s);
        }
        if self.repeated {
            self.next = grey;
            self.repeat();
            return;
        }
        self.settle_top();
        self.next = std::mem::replace(&mut self.grey, grey);
        let grey = &self.grey;
        let area = byte_sum(grey);
        let (origin, step) = self.strides();
        place(grey, self.fw, &mut self.lit, origin, step);
        let mut mat = std::mem::take(&mut self.next);
        for m in 0..self.by_code.len() {
            self.greys(s, Some(self.by_code[m].0), &mut mat);
            place(&mat, self.fw, &mut self.by_code[m].1, origin, step);
        }
        self.next = mat;
        self.areas.push(area);
        self.layer += 1;
    }

    /// [`Raster::layer`] at one sample a pixel and of one material, after the first layer:
    /// a pixel's grey is 255 where its sample is inside and 0 where not, so the last layer's
    /// greys tell its samples, and only the pixels whose sample went in or out are made
    /// again, in `grey`, the PNG box, the area and `top` (a pixel's top settles when it goes
    /// dark). The samples are compared [`CHANGE_SCAN`] at a time, a loop that runs a vector
    /// at a time: most of a layer is the one before again, even where the part's outline
    /// moves.
    fn layer_by_changes(&mut self, s: &[u8]) {
        let mask = |v: u8| u8::from(v != 0).wrapping_neg();
        let last = u16::try_from(self.layer).unwrap_or(u16::MAX);
        let (origin, step) = self.strides();
        let (fw, lit, top) = (self.fw.max(1), &mut self.lit, &mut self.top);
        let mut area = self.areas.last().copied().unwrap_or(0);
        let chunks = s.chunks(CHANGE_SCAN).zip(self.grey.chunks_mut(CHANGE_SCAN));
        let mut changed = false;
        for (c, (samples, greys)) in chunks.enumerate() {
            let pairs = samples.iter().zip(greys.iter());
            if pairs.fold(0, |d, (&v, &g)| d | (mask(v) ^ g)) == 0 {
                continue;
            }
            changed = true;
            for (j, (&v, g)) in samples.iter().zip(greys.iter_mut()).enumerate() {
                let (new, i) = (mask(v), c * CHANGE_SCAN + j);
                if new == *g {
                    continue;
                }
                let (a, b) = ((i % fw) as isize, (i / fw) as isize);
                lit[(origin + a * step[0] + b * step[1]) as usize] = new;
                if new == 0 {
                    area -= 255;
                    top[i] = last;
                } else {
                    area += 255;
                }
                *g = new;
            }
        }
        self.repeated = !changed;
        self.areas.push(area);
        self.layer += 1;
    }

    /// The layer just made is the one before again.
    fn repeat(&mut self) {
        let area = self.areas.last().copied().unwrap_or(0);
        self.areas.push(area);
        self.layer += 1;
    }

    /// Whether the last layer made repeats the one before: its PNG boxes are that layer's,
    /// not handed over again.
    pub fn repeated(&self) -> bool {
        self.repeated
    }

    /// `top` up to the last layer made: the pixels the greys in `grey` light were lit last
    /// by that layer (the layers since they were made repeat them).
    fn settle_top(&mut self) {
        let last = u16::try_from(self.layer).unwrap_or(u16::MAX);
        // A select, not a branch, in a loop of its own: it runs a vector at a time.
        for (t, &g) in self.top.iter_mut().zip(&self.grey) {
            *t = if g != 0 { last } else { *t };
        }
    }

    /// Per footprint pixel, 1 + the highest layer that lit it (0: none), for thumbnails.
    pub fn top(&mut self) -> &[u16] {
        self.settle_top();
        &self.top
    }

    /// Every footprint pixel's grey (row by row along Y, each along X): the share of its
    /// samples inside, or of material `code` with one.
    fn greys(&self, s: &[u8], code: Option<u8>, out: &mut Vec<u8>) {
        let (k, fw) = (self.k, self.fw);
        out.resize(fw * self.fh, 0);
        let hit = |v: u8| u32::from(code.map_or(v != 0, |c| v == c));
        if k == 1 {
            // 255 or 0, written as a byte mask so that the loop runs 16 or 32 samples a step.
            let mask = |b: bool| u8::from(b).wrapping_neg();
            let pairs = out.iter_mut().zip(s);
            match code {
                None => pairs.for_each(|(g, &v)| *g = mask(v != 0)),
                Some(c) => pairs.for_each(|(g, &v)| *g = mask(v == c)),
            }
            return;
        }
        let mut counts = vec![0u32; fw];
        for (b, row_out) in out.chunks_exact_mut(fw).enumerate() {
            counts.fill(0);
            for sub in s.chunks_exact(fw * k).skip(b * k).take(k) {
                for (c, px) in counts.iter_mut().zip(sub.chunks_exact(k)) {
                    *c += px.iter().map(|&v| hit(v)).sum::<u32>();
                }
            }
            for (g, &n) in row_out.iter_mut().zip(&counts) {
                *g = self.grey(n);
            }
        }
    }

    /// Where footprint pixel (0, 0) is in the PNG box, and the steps to (1, 0) and (0, 1):
    /// the display's placement in the PNG is a turn and flips, so these two steps give
    /// every pixel's place.
    fn strides(&self) -> (isize, [isize; 2]) {
        let at = |a: u32, b: u32| {
            let (c, r) = self.printer.png_of(self.i0 + a, self.j0 + b);
            let bw = (self.cols.1 - self.cols.0) as isize;
            (r - self.rows.0) as isize * bw + (c - self.cols.0) as isize
        };
        let o = at(0, 0);
        let sa = if self.fw > 1 { at(1, 0) - o } else { 0 };
        let sb = if self.fh > 1 { at(0, 1) - o } else { 0 };
        (o, [sa, sb])
    }

    /// Grey of `n` samples in of k².
    fn grey(&self, n: u32) -> u8 {
        let full = (self.k * self.k) as u32;
        ((n * 255 + full / 2) / full) as u8
    }

    /// The last layer's PNG boxes, the part's then each material's: the part's a copy in a
    /// buffer of `spare` (or a new one), the raster keeping its own for the next layer; each
    /// material's handed over without a copy, a buffer of `spare` or a new one taking its
    /// place (any content: placing a layer writes every byte of a material's box).
    pub fn take_boxes(&mut self, spare: Vec<Vec<u8>>) -> Vec<Vec<u8>> {
        let band = self.lit.len();
        let mut spare = spare.into_iter();
        let mut fresh = || {
            let mut b = spare.next().unwrap_or_default();
            b.resize(band, 0);
            b
        };
        // The part's box stays, for the next layer to change where its samples do
        // ([`Raster::layer_by_changes`]).
        let mut part = fresh();
        part.copy_from_slice(&self.lit);
        let mut out = vec![part];
        for (_, m) in &mut self.by_code {
            out.push(std::mem::replace(m, fresh()));
        }
        out
    }

    /// The material labels with a stack of their own (none for a scene of one colour).
    pub fn materials(&self) -> Vec<u8> {
        self.by_code.iter().map(|(c, _)| *c).collect()
    }

    /// The footprint's size in pixels.
    pub fn footprint(&self) -> [usize; 2] {
        [self.fw, self.fh]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A part of `w`×`h` pixels from pixel `(i, j)`, `layers` high.
    fn footprint((i, j): (u32, u32), (w, h): (usize, usize), layers: usize) -> Placement {
        Placement {
            shift: glam::DVec2::ZERO,
            floor: 0.0,
            i: (i, i + w as u32),
            j: (j, j + h as u32),
            layers,
        }
    }

    /// Layers that repeat the one before hand over no boxes, and the raster's areas,
    /// extent and thumbnail heights are those of making every layer afresh: the boxes each
    /// layer would have are the last ones handed over, checked pixel by pixel against the
    /// samples, and `top` against the highest layer lighting each pixel.
    #[test]
    fn repeated_layers_keep_the_boxes_areas_extent_and_tops_of_the_layers_they_repeat() {
        let p = Printer::named("sl1").unwrap();
        let (fw, fh) = (13usize, 11usize);
        let at = footprint((100, 200), (fw, fh), 8);
        // Layer samples (aa 1): a disc of radius r at (cx, 5); 0 = empty.
        let disc = |r: f64, cx: f64| -> Vec<u8> {
            (0..fw * fh)
                .map(|n| {
                    let (a, b) = ((n % fw) as f64 - cx, (n / fw) as f64 - 5.0);
                    u8::from(a * a + b * b <= r * r)
                })
                .collect()
        };
        let (a, b, e) = (disc(4.0, 6.0), disc(2.5, 3.0), vec![0u8; fw * fh]);
        let layers = [&a, &a, &b, &b, &b, &e, &a, &a];
        let mut r = Raster::new(&p, &at, 1, &[]);
        let mut last: Vec<u8> = vec![];
        let mut top = vec![0u16; fw * fh];
        let (origin, step) = r.strides();
        for (l, s) in layers.iter().enumerate() {
            r.layer(s);
            assert_eq!(r.repeated(), l > 0 && layers[l - 1] == *s, "layer {l}");
            if !r.repeated() {
                last = r.take_boxes(vec![]).remove(0);
            }
            for (n, &v) in s.iter().enumerate() {
                let (i, j) = (n % fw, n / fw);
                let at = (origin + i as isize * step[0] + j as isize * step[1]) as usize;
                assert_eq!(last[at], v * 255, "layer {l} pixel {i},{j}");
                top[n] = if v != 0 { l as u16 + 1 } else { top[n] };
            }
            let area: u64 = s.iter().map(|&v| u64::from(v) * 255).sum();
            assert_eq!(r.areas[l], area, "layer {l}");
        }
        assert_eq!(r.top(), &top[..]);
    }

    /// At one sample a pixel a layer is made from the pixels that changed
    /// ([`Raster::layer_by_changes`]); over random layers, on every turn and mirror, each
    /// box handed over, area and top is what the layer's samples give directly.
    #[test]
    fn layers_made_from_their_changes_are_the_layers_their_samples_give() {
        let (fw, fh) = (150usize, 37usize);
        let at = footprint((40, 60), (fw, fh), 40);
        let mut seed = 0x2005_u64;
        let mut next = move |n: u64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) % n
        };
        // Layers of one to three random boxes, a layer repeating the one before one time
        // in four; codes 1 to 3 (one material: any code is inside).
        let mut layers: Vec<Vec<u8>> = vec![];
        for l in 0..40 {
            if l > 0 && next(4) == 0 {
                layers.push(layers[l - 1].clone());
                continue;
            }
            let mut s = vec![0u8; fw * fh];
            for _ in 0..=next(3) {
                let (x0, y0) = (next(fw as u64) as usize, next(fh as u64) as usize);
                let (x1, y1) = (
                    (x0 + 1 + next(90) as usize).min(fw),
                    (y0 + 1 + next(30) as usize).min(fh),
                );
                let code = 1 + next(3) as u8;
                for y in y0..y1 {
                    s[y * fw + x0..y * fw + x1].fill(code);
                }
            }
            layers.push(s);
        }
        for (portrait, mirror) in [
            (true, [true, false]),
            (false, [false, false]),
            (true, [false, true]),
            (false, [true, true]),
        ] {
            let mut p = Printer::named("sl1").unwrap();
            (p.portrait, p.mirror) = (portrait, mirror);
            let mut r = Raster::new(&p, &at, 1, &[]);
            let (origin, step) = r.strides();
            let (mut last, mut top) = (vec![], vec![0u16; fw * fh]);
            for (l, s) in layers.iter().enumerate() {
                r.layer(s);
                let inside = |s: &[u8]| s.iter().map(|&v| v != 0).collect::<Vec<_>>();
                let same = l > 0 && inside(&layers[l - 1]) == inside(s);
                assert_eq!(r.repeated(), same, "layer {l}");
                if !r.repeated() {
                    last = r.take_boxes(vec![vec![7; 3]]).remove(0);
                }
                for (n, &v) in s.iter().enumerate() {
                    let (i, j) = ((n % fw) as isize, (n / fw) as isize);
                    let grey = u8::from(v != 0) * 255;
                    assert_eq!(
                        last[(origin + i * step[0] + j * step[1]) as usize],
                        grey,
                        "layer {l} pixel {n}"
                    );
                    top[n] = if v != 0 { l as u16 + 1 } else { top[n] };
                }
                let area = s.iter().filter(|&&v| v != 0).count() as u64 * 255;
                assert_eq!(r.areas[l], area, "layer {l} {portrait} {mirror:?}");
            }
            assert_eq!(r.top(), &top[..]);
        }
    }

    /// With materials, a layer repeats the one before only when its codes do: the same
    /// part in another colour is made afresh, and every material's box handed over is the
    /// one its samples give.
    #[test]
    fn with_materials_a_layer_repeats_only_when_its_colours_do() {
        let p = Printer::named("sl1").unwrap();
        let (fw, fh) = (11usize, 9usize);
        let at = footprint((300, 500), (fw, fh), 6);
        let block = |code: u8, x0: usize| -> Vec<u8> {
            (0..fw * fh)
                .map(|n| {
                    if (x0..x0 + 5).contains(&(n % fw)) && n / fw > 2 {
                        code
                    } else {
                        0
                    }
                })
                .collect()
        };
        let (a, b, c) = (block(1, 2), block(2, 2), block(2, 5));
        let layers = [&a, &a, &b, &b, &c, &a];
        let mut r = Raster::new(&p, &at, 1, &[1, 2]);
        let mut last: Vec<Vec<u8>> = vec![];
        let (origin, step) = r.strides();
        for (l, s) in layers.iter().enumerate() {
            r.layer(s);
            assert_eq!(r.repeated(), l > 0 && layers[l - 1] == *s, "layer {l}");
            if !r.repeated() {
                last = r.take_boxes(vec![]);
            }
            assert_eq!(last.len(), 3, "the part's box and two materials'");
            for (n, &v) in s.iter().enumerate() {
                let at =
                    (origin + (n % fw) as isize * step[0] + (n / fw) as isize * step[1]) as usize;
                let want = [v != 0, v == 1, v == 2].map(|b| u8::from(b) * 255);
                for (m, w) in want.iter().enumerate() {
                    assert_eq!(last[m][at], *w, "layer {l} box {m} pixel {n}");
                }
            }
        }
    }

    /// Every placement (a turn or not, each mirror) puts each grey where the strides say,
    /// for footprints of whole 8×8 blocks and of leftovers.
    #[test]
    fn place_puts_every_pixel_where_its_strides_say() {
        for (fw, fh) in [
            (1, 1),
            (8, 8),
            (13, 21),
            (24, 3),
            (3, 17),
            (150, 19),
            (70, 131),
        ] {
            let grey: Vec<u8> = (0..fw * fh).map(|i| (i % 251) as u8 + 1).collect();
            for turn in [false, true] {
                for flip in [[1isize, 1], [-1, 1], [1, -1], [-1, -1]] {
                    let (w, h) = if turn { (fh, fw) } else { (fw, fh) };
                    let unit = |s: isize, n: usize| if s > 0 { 0 } else { n as isize - 1 };
                    let (sa, sb, origin) = match turn {
                        false => (
                            flip[0],
                            flip[1] * w as isize,
                            unit(flip[0], w) + unit(flip[1], h) * w as isize,
                        ),
                        true => (
                            flip[0] * w as isize,
                            flip[1],
                            unit(flip[0], h) * w as isize + unit(flip[1], w),
                        ),
                    };
                    let mut lit = vec![0u8; w * h];
                    place(&grey, fw, &mut lit, origin, [sa, sb]);
                    for b in 0..fh {
                        for a in 0..fw {
                            let at = (origin + a as isize * sa + b as isize * sb) as usize;
                            assert_eq!(lit[at], grey[b * fw + a], "{fw}x{fh} {turn} {flip:?}");
                        }
                    }
                }
            }
        }
    }
}
