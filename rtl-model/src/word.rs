//! The `word` model: the same fixed-point words and the same select logic as [`crate::cycle`],
//! one integer per register per pixel and no clock. Comparisons are integer comparisons, so it
//! is an independent check of the bit-serial comparator and adder tree.

use crate::array::{Array, Sequencer};
use crate::comparator::FlagBits;
use crate::probe::Recorder;
use crate::program::{Decide, Op, ProgramError, Transfer, Window};
use crate::select::sop::{Sop, Var};
use crate::select::EquationSet;
use crate::state::{ArchState, ArrayConfig, Pixel};

/// The array, one word per register per pixel.
pub struct WordArray {
    cfg: ArrayConfig,
    set: EquationSet,
    px: Vec<Pixel>,
    seq: Sequencer,
    ops: usize,
    probe: Option<Recorder>,
}

impl WordArray {
    /// A `cfg` array after reset (every depth register at the Put-1 word, colours 0, code
    /// Keep), its SGENE built from `set`.
    pub fn new(cfg: ArrayConfig, set: EquationSet) -> WordArray {
        WordArray {
            px: vec![Pixel::reset(&cfg.fmt); cfg.pixels()],
            cfg,
            set,
            seq: Sequencer::default(),
            ops: 0,
            probe: None,
        }
    }

    /// Carry out the waiting transfer (what the cycle model does during the next window).
    fn apply_pending(&mut self) {
        let Some(t) = self.seq.pending.take() else {
            return;
        };
        let (max, cmask) = (self.cfg.fmt.max_word(), colour_mask(&self.cfg));
        for p in &mut self.px {
            apply(p, &t, max, cmask);
        }
    }

    fn window(&mut self, w: &Window) {
        self.apply_pending();
        self.seq.cycles += self.seq.window_clocks(&self.cfg, w);
        let (fmt, width, cmask) = (self.cfg.fmt, self.cfg.width, colour_mask(&self.cfg));
        let sp = self.seq.sp;
        for (i, p) in self.px.iter_mut().enumerate() {
            if let Some((c, colour)) = w.stream {
                let (x, y) = ((i % width) as i64, (i / width) as i64);
                let z =
                    c.c0.wrapping_add(x.wrapping_mul(c.dx))
                        .wrapping_add(y.wrapping_mul(c.dy));
                p.depth[0] = fmt.wrap(z);
                if let Some(d) = colour {
                    p.colour[0] = d & cmask;
                }
            }
            let (a, r) = (p.reg(w.lhs), p.reg(w.rhs));
            p.flags = FlagBits {
                n: fmt.n(a),
                j: a <= r,
                t: a == r,
                m: fmt.m(a),
            };
            decide(p, &w.decide, sp);
        }
        if matches!(w.decide, Decide::Push(_)) {
            self.seq.sp += 1;
        }
        self.seq.pending = w.transfer;
    }

    fn stack_op(&mut self, op: &Op) {
        let sp = self.seq.sp;
        for p in &mut self.px {
            let bit = |s: u64, i: usize| s >> i & 1;
            let put = |s: u64, i: usize, b: u64| (s & !(1 << i)) | (b & 1) << i;
            p.stack = match op {
                Op::ClipAnd => put(p.stack, sp - 2, bit(p.stack, sp - 2) & bit(p.stack, sp - 1)),
                Op::ClipOr => put(p.stack, sp - 2, bit(p.stack, sp - 2) | bit(p.stack, sp - 1)),
                Op::ClipNot => put(p.stack, sp - 1, !bit(p.stack, sp - 1)),
                _ => p.stack,
            };
            if matches!(op, Op::ClipApply) {
                // LL' = 1 keeps F (code 01), LL' = 0 puts 1 (code 11).
                p.sel = (bit(p.stack, sp - 1) == 0, true);
            }
        }
        let (pop, push) = crate::program::stack_effect(op);
        self.seq.sp = sp - pop + push;
        if matches!(op, Op::ClipApply) {
            self.seq.pending = Some(Transfer::clip_apply());
        }
        self.seq.cycles += 1;
    }
}

impl WordArray {
    fn sample(&mut self, position: u8) {
        let Some(rec) = &mut self.probe else { return };
        let t = self.seq.cycles;
        let w = self.cfg.width;
        let pts = rec.probes().to_vec();
        for (i, (x, y)) in pts.into_iter().enumerate() {
            rec.sample(t, i, self.px[y * w + x]);
        }
        rec.global(t, position, self.cfg.fmt.sign_bit());
    }
}

pub(crate) fn colour_mask(cfg: &ArrayConfig) -> u32 {
    (((1u64) << cfg.colour_bits) - 1) as u32
}

/// TRANSD and TRANSC on one pixel.
fn apply(p: &mut Pixel, t: &Transfer, max: i64, cmask: u32) {
    let m = t.decode.masks(p.sel.0 as u64, p.sel.1 as u64);
    let src = p.reg(t.src);
    let dst = &mut p.depth[t.dst as usize];
    let old_dst = *dst;
    *dst = pick(m.put_src, src, m.keep, old_dst, m.put0, 0, max);
    if let Some((cd, cs)) = t.colour {
        let (src, old) = (p.colour[cs as usize], p.colour[cd as usize]);
        let v = pick(
            m.put_src,
            src as i64,
            m.keep,
            old as i64,
            m.put0,
            t.interior as i64,
            0,
        );
        p.colour[cd as usize] = v as u32 & cmask;
    }
}

fn pick(put_src: u64, src: i64, keep: u64, old: i64, put0: u64, zero: i64, one: i64) -> i64 {
    match (put_src & 1, keep & 1, put0 & 1) {
        (1, _, _) => src,
        (_, 1, _) => old,
        (_, _, 1) => zero,
        _ => one,
    }
}

fn decide(p: &mut Pixel, d: &Decide, sp: usize) {
    let mut vars = [false; 10];
    vars[Var::N as usize] = p.flags.n;
    vars[Var::J as usize] = p.flags.j;
    vars[Var::T as usize] = p.flags.t;
    vars[Var::M as usize] = p.flags.m;
    let ev = |s: &Sop| s.eval_bits(&vars);
    match d {
        Decide::Latch(hi, lo) => p.sel = (ev(hi), ev(lo)),
        Decide::Push(ll) => p.stack = (p.stack & !(1 << sp)) | (ev(ll) as u64) << sp,
    }
}

impl Array for WordArray {
    fn config(&self) -> &ArrayConfig {
        &self.cfg
    }

    fn pixel(&self, x: usize, y: usize) -> Pixel {
        self.px[y * self.cfg.width + x]
    }

    fn step(&mut self, op: &Op) -> Result<(), ProgramError> {
        self.seq.admit(op, self.ops, self.cfg.stack_depth)?;
        self.ops += 1;
        let position = match Window::of(op, &self.set) {
            Some(w) => {
                self.window(&w);
                w.position
            }
            None => {
                self.stack_op(op);
                1
            }
        };
        self.sample(position);
        Ok(())
    }

    fn finish(&mut self) {
        if self.seq.pending.is_some() {
            self.apply_pending();
            self.seq.cycles += self.cfg.fmt.bits() as u64;
            self.sample(0);
        }
    }

    fn attach_probe(&mut self, rec: Recorder) {
        self.probe = Some(rec);
    }

    fn take_probe(&mut self) -> Option<Recorder> {
        self.probe.take()
    }

    fn cycles(&self) -> u64 {
        self.seq.cycles
    }

    fn state(&self) -> ArchState {
        ArchState {
            width: self.cfg.width,
            height: self.cfg.height,
            pixels: self.px.clone(),
            sp: self.seq.sp,
        }
    }
}

impl WordArray {
    /// Bytes the pixels of a `cfg` array take.
    pub fn memory_bytes(cfg: &ArrayConfig) -> u64 {
        (cfg.pixels() * std::mem::size_of::<Pixel>()) as u64
    }
}
