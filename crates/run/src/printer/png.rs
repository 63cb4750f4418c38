//! Layer PNGs at the cost of their lit pixels. A layer image is the whole display (an
//! SL1's is 1440×2560), but only the box the part's footprint covers can hold a lit pixel,
//! the same box in every layer. The rows above and below it are deflated once per run and
//! their bytes reused (a zlib stream may be cut into pieces that each end on a byte boundary
//! and start afresh); the rows across it are coded here as runs (a byte, then copies of the
//! byte before: deflate's fixed codes, as zlib's `Z_RLE` strategy codes them), so the zeros
//! left and right of the box cost no scan; and the Adler-32 of a run of zeros is a
//! formula. A layer costs a pass over its footprint's pixels.

use std::io::Write;

use flate2::{Compress, Compression, FlushCompress};

/// The zlib stream's pieces shared by every layer of one run.
pub struct LayerPng {
    width: u32,
    height: u32,
    /// PNG rows `rows.0..rows.1` and columns `cols.0..cols.1` may hold lit pixels; all
    /// others are zero.
    rows: (u32, u32),
    cols: (u32, u32),
    above: Vec<u8>,
    below: Vec<u8>,
}

impl LayerPng {
    /// Grey 8-bit layers of `width` × `height` whose lit pixels are all in rows `rows` and
    /// columns `cols`.
    pub fn new(width: u32, height: u32, rows: (u32, u32), cols: (u32, u32)) -> LayerPng {
        let rows = (rows.0.min(height), rows.1.clamp(rows.0.min(height), height));
        let cols = (cols.0.min(width), cols.1.clamp(cols.0.min(width), width));
        let row = width as usize + 1;
        LayerPng {
            width,
            height,
            rows,
            cols,
            above: deflate_zeros(rows.0 as usize * row),
            below: deflate_zeros((height - rows.1) as usize * row),
        }
    }

    /// Write the PNG whose box `rows` × `cols` is `lit` (row by row, `cols` wide).
    pub fn write(&self, w: &mut dyn Write, lit: &[u8]) -> std::io::Result<()> {
        let width = self.width as u64;
        let bw = (self.cols.1 - self.cols.0) as usize;
        let n = (self.rows.1 - self.rows.0) as usize;
        debug_assert_eq!(lit.len(), n * bw);
        let mut idat = vec![0x78, 0x01];
        idat.extend_from_slice(&self.above);
        let mut rle = Rle::new(self.rows.0 > 0);
        rle.adler.run(0, u64::from(self.rows.0) * (width + 1));
        let (left, right) = (u64::from(self.cols.0), u64::from(self.width - self.cols.1));
        for r in lit.chunks(bw.max(1)).take(n) {
            rle.zeros(1 + left); // the row's filter (none) and the zeros left of the box
            rle.bytes(r);
            rle.zeros(right);
        }
        let mut adler = rle.adler;
        idat.extend_from_slice(&rle.finish());
        idat.extend_from_slice(&self.below);
        idat.extend_from_slice(&[0x03, 0x00]); // an empty final block
        adler.run(0, u64::from(self.height - self.rows.1) * (width + 1));
        idat.extend_from_slice(&adler.value().to_be_bytes());
        w.write_all(b"\x89PNG\r\n\x1a\n")?;
        let mut ihdr = Vec::with_capacity(13);
        ihdr.extend_from_slice(&self.width.to_be_bytes());
        ihdr.extend_from_slice(&self.height.to_be_bytes());
        ihdr.extend_from_slice(&[8, 0, 0, 0, 0]); // 8-bit grey, deflate, no interlace
        chunk(w, b"IHDR", &ihdr)?;
        chunk(w, b"IDAT", &idat)?;
        chunk(w, b"IEND", &[])
    }
}

/// How many bytes `data` starts with that are `b`: eight at a time.
fn run_len(data: &[u8], b: u8) -> usize {
    let pattern = u64::from_le_bytes([b; 8]);
    let mut words = data.chunks_exact(8);
    let mut n = 0;
    for w in words.by_ref() {
        let diff = u64::from_le_bytes(w.try_into().unwrap_or([0; 8])) ^ pattern;
        if diff != 0 {
            return n + diff.trailing_zeros() as usize / 8;
        }
        n += 8;
    }
    n + words.remainder().iter().take_while(|&&x| x == b).count()
}

/// A deflate block of fixed codes (RFC 1951 §3.2.6) holding runs: each byte that differs
/// from the one before is a literal, each repeat a copy at distance 1.
struct Rle {
    out: Vec<u8>,
    bits: u64,
    nbits: u32,
    /// The last byte of the stream so far (none at its start).
    prev: Option<u8>,
    /// The run being gathered: its byte and length.
    run: (u8, u64),
    /// The Adler-32 of the stream so far, run by run.
    adler: Adler,
}

/// Lengths 3..=258: the base of each length code 257..=285 and its extra bits.
const LEN_BASE: [u16; 29] = [
    3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131,
    163, 195, 227, 258,
];
const LEN_EXTRA: [u8; 29] = [
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
];

impl Rle {
    /// A block after `history` (whether a byte of the stream comes before it: zero).
    fn new(history: bool) -> Rle {
        let mut r = Rle {
            out: Vec::with_capacity(1 << 14),
            bits: 0,
            nbits: 0,
            prev: history.then_some(0),
            run: (0, 0),
            adler: Adler::default(),
        };
        r.put(0b010, 3); // not final, fixed codes
        r
    }

    fn put(&mut self, v: u32, n: u32) {
        self.bits |= u64::from(v) << self.nbits;
        self.nbits += n;
        while self.nbits >= 8 {
            self.out.push(self.bits as u8);
            self.bits >>= 8;
            self.nbits -= 8;
        }
    }

    /// A Huffman code: its bits from the most significant.
    fn code(&mut self, code: u32, len: u32) {
        self.put(code.reverse_bits() >> (32 - len), len);
    }

    fn symbol(&mut self, s: u32) {
        match s {
            0..=143 => self.code(0x30 + s, 8),
            144..=255 => self.code(0x190 + s - 144, 9),
            256..=279 => self.code(s - 256, 7),
            _ => self.code(0xc0 + s - 280, 8),
        }
    }

    fn zeros(&mut self, n: u64) {
        self.repeat(0, n);
    }

    fn bytes(&mut self, mut data: &[u8]) {
        while let Some(&b) = data.first() {
            let n = run_len(data, b);
            self.repeat(b, n as u64);
            data = &data[n..];
        }
    }

    fn repeat(&mut self, b: u8, n: u64) {
        self.adler.run(b, n);
        if self.run.0 != b || self.run.1 == 0 {
            self.flush();
            self.run = (b, 0);
        }
        self.run.1 += n;
    }

    /// The gathered run: a literal unless the byte before is the same, then copies.
    fn flush(&mut self) {
        let (b, mut n) = self.run;
        if n == 0 {
            return;
        }
        if self.prev != Some(b) {
            self.symbol(u32::from(b));
            n -= 1;
        }
        while n >= 3 {
            let m = match n {
                259..=260 => n - 3,
                _ => n.min(258),
            };
            self.copy(m as u16);
            n -= m;
        }
        for _ in 0..n {
            self.symbol(u32::from(b));
        }
        self.prev = Some(b);
        self.run = (b, 0);
    }

    /// A copy of `len` bytes at distance 1.
    fn copy(&mut self, len: u16) {
        let i = LEN_BASE.partition_point(|&b| b <= len) - 1;
        self.symbol(257 + i as u32);
        let extra = u32::from(LEN_EXTRA[i]);
        if extra > 0 {
            self.put(u32::from(len - LEN_BASE[i]), extra);
        }
        self.code(0, 5); // distance code 0: distance 1
    }

    /// The block's end, then an empty stored block to end on a byte boundary.
    fn finish(mut self) -> Vec<u8> {
        self.flush();
        self.symbol(256);
        self.put(0, 3); // stored, not final
        if self.nbits > 0 {
            self.put(0, 8 - self.nbits);
        }
        self.out.extend_from_slice(&[0, 0, 0xff, 0xff]);
        self.out
    }
}

/// One PNG chunk: length, type, data, CRC of type and data.
fn chunk(w: &mut dyn Write, kind: &[u8; 4], data: &[u8]) -> std::io::Result<()> {
    let len = u32::try_from(data.len()).map_err(std::io::Error::other)?;
    w.write_all(&len.to_be_bytes())?;
    w.write_all(kind)?;
    w.write_all(data)?;
    let mut crc = crc32fast::Hasher::new();
    crc.update(kind);
    crc.update(data);
    w.write_all(&crc.finalize().to_be_bytes())
}

/// `n` zero bytes as raw deflate blocks ending on a byte boundary, not final.
fn deflate_zeros(n: usize) -> Vec<u8> {
    let zeros = vec![0u8; n.min(1 << 20)];
    let mut c = Compress::new(Compression::fast(), false);
    let mut out = Vec::with_capacity(n / 256 + 64);
    let mut left = n;
    while left > 0 {
        let take = left.min(zeros.len());
        compress_all(&mut c, &zeros[..take], &mut out, FlushCompress::None);
        left -= take;
    }
    compress_all(&mut c, &[], &mut out, FlushCompress::Sync);
    out
}

/// Feed `data` to `c`, growing `out`, until all is taken and the output drained: a call
/// that leaves room in `out` has nothing more to give.
fn compress_all(c: &mut Compress, data: &[u8], out: &mut Vec<u8>, flush: FlushCompress) {
    let mut taken = 0;
    loop {
        out.reserve(64 * 1024);
        let before = c.total_in();
        // Into a Vec's spare room, deflate cannot fail (no dictionary, no finished stream).
        let _ = c.compress_vec(&data[taken..], out, flush);
        taken += (c.total_in() - before) as usize;
        if taken == data.len() && out.len() < out.capacity() {
            return;
        }
    }
}

/// Adler-32 (RFC 1950), a run of bytes in constant time.
#[derive(Clone, Copy)]
struct Adler {
    a: u64,
    b: u64,
}

impl Default for Adler {
    fn default() -> Adler {
        Adler { a: 1, b: 0 }
    }
}

const MOD: u64 = 65_521;

impl Adler {
    /// `n` bytes `v`: after k of them a has grown by k·v, and b by the sum of those.
    fn run(&mut self, v: u8, n: u64) {
        let (v, m) = (u64::from(v), n % MOD);
        let tri = (n % (2 * MOD)) * ((n + 1) % (2 * MOD)) / 2 % MOD;
        self.b = (self.b + m * self.a + v * tri) % MOD;
        self.a = (self.a + m * v) % MOD;
    }

    #[cfg(test)]
    fn bytes(&mut self, data: &[u8]) {
        for &x in data {
            self.run(x, 1);
        }
    }

    fn value(&self) -> u32 {
        ((self.b << 16) | self.a) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pieces make the PNG a standard decoder reads back, pixel for pixel.
    #[test]
    fn a_layer_decodes_to_its_pixels() {
        let cases = [
            (37u32, 50u32, (10u32, 23u32), (5u32, 30u32)),
            (5, 4, (0, 4), (0, 5)),
            (9, 3, (3, 3), (2, 2)),
            (700, 9, (1, 8), (0, 700)),
        ];
        for (w, h, rows, cols) in cases {
            let bw = cols.1 - cols.0;
            let n = ((rows.1 - rows.0) * bw) as usize;
            // Runs of every length up to 700, zeros among them, and single bytes.
            let lit: Vec<u8> = (0..n)
                .map(|i| [0, 255, (i % 7) as u8][i / 97 % 3])
                .collect();
            let mut bytes = vec![];
            LayerPng::new(w, h, rows, cols)
                .write(&mut bytes, &lit)
                .unwrap();
            let img = image::load_from_memory(&bytes).unwrap().to_luma8();
            assert_eq!(img.dimensions(), (w, h));
            for (x, y, p) in img.enumerate_pixels() {
                let inside = (rows.0..rows.1).contains(&y) && (cols.0..cols.1).contains(&x);
                let want = match inside {
                    true => lit[((y - rows.0) * bw + x - cols.0) as usize],
                    false => 0,
                };
                assert_eq!(p.0[0], want, "pixel {x},{y} of {w}x{h}");
            }
        }
    }

    #[test]
    fn a_run_ends_at_the_first_other_byte() {
        for len in 0..40 {
            for at in 0..=len {
                let mut v = vec![7u8; len];
                if at < len {
                    v[at] = 8;
                }
                assert_eq!(run_len(&v, 7), at, "{len} {at}");
            }
        }
    }

    #[test]
    fn adler_of_zeros_is_the_adler_of_the_bytes() {
        let mut a = Adler::default();
        a.bytes(&[1, 2, 3]);
        a.run(0, 100_000);
        a.run(7, 70_000);
        a.bytes(&[9]);
        let mut b = Adler::default();
        let mut data = vec![1, 2, 3];
        data.extend(std::iter::repeat_n(0u8, 100_000));
        data.extend(std::iter::repeat_n(7u8, 70_000));
        data.push(9);
        let mut h = adler2::Adler32::new();
        h.write_slice(&data);
        assert_eq!(a.value(), h.checksum());
        b.bytes(&data);
        assert_eq!(b.value(), h.checksum());
    }
}
