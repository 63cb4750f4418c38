//! The `cycle` model: the array clock by clock, bit-serial and bit-sliced.
//!
//! Every register is a set of bit-planes: plane `k` of register A holds bit `k` of A for every
//! pixel, 64 pixels to a `u64`. One clock of the hardware moves every pixel by one bit: TRANSD
//! writes bit `k` of the register the last select code targets, DEPGEN delivers bit `k` of the
//! new plane into A, and the comparator takes bit `k` of both operands. Here one clock for 64
//! pixels is a handful of word operations.
//!
//! Pixels never talk to each other, so the order in which lanes are visited is free; only the
//! controller (clock count, stack pointer, the latched transfer) is global, and it is advanced
//! as each operation is admitted. The simulator uses that freedom twice:
//!
//! - Chunks: a window is swept over a chunk of rows (about 64 words) through all N_D clocks
//!   before the next chunk, which keeps the chunk's bit-planes in L1.
//! - Panels: the machine is built of panels (§2.5, each its own array; §5.5 counts the
//!   throughput panel by panel), and so is the simulation, a panel here being a block of whole
//!   rows whose bit-planes fit in L2 (at most 256 KiB). The per-pixel work of up to 64 windows
//!   and stack operations is deferred (each window's plan: transfer, DEPGEN's line bits,
//!   colour, operands, decision, stack level) and then run panel by panel: every deferred
//!   operation, in program order, over one panel before the next panel. An array larger than
//!   the cache thus streams its state from memory once per batch rather than once per window.
//!   The queue is run when it is full and before anything reads a pixel ([`CycleArray::pixel`],
//!   `state`, `gather`, `internal`), at `finish`, and before an observer or a probe is
//!   attached; an array of one panel is not deferred at all.
//!
//! Every clock is still simulated for every pixel; the clock count is the number of clocks a
//! window takes, DEPGEN's fill included. With an observer ([`CycleArray::observe`]) or a probe
//! attached, every window runs at once over the whole array, so that they see every pixel at
//! the same clock (the observer: the whole array as one chunk).
//!
//! Layout: a row occupies `ceil(width/64)` words (lanes past the width are padding and are
//! never read out); plane `k` of a register is the slice `[k·words .. (k+1)·words]`, so a
//! panel's part of a plane is one contiguous run of words.

use std::cell::{Ref, RefCell};
use std::ops::Range;

use crate::array::{Array, Sequencer};
use crate::comparator::{BitRole, Comparator, FlagBits};
use crate::depgen::{pixel_add, DepGen, LineBits};
use crate::probe::Recorder;
use crate::program::{ActionMasks, Decide, Op, ProgramError, Reg, Transfer, Window};
use crate::select::sop::Var;
use crate::select::EquationSet;
use crate::state::{ArchState, ArrayConfig, Pixel};

/// Words of pixels swept through a window before moving on (about 64, whole rows).
const CHUNK_WORDS: usize = 64;

/// Bytes of bit-planes a panel holds at most (whole rows, at least one): well inside a core's
/// L2 (an eighth of 2 MiB), so that a batch of windows finds a panel's state there. Measured
/// with the thesis cube at 1024×1024 (2 MiB L2): 256 KiB ran faster than 128 KiB, 512 KiB or
/// 1-2 MiB.
const PANEL_BYTES: usize = 256 << 10;

/// Windows and stack operations deferred before they are run panel by panel.
const QUEUE_JOBS: usize = 64;

/// Bytes of DEPGEN line bits the deferred windows may hold before they are run.
const QUEUE_LINE_BYTES: usize = 4 << 20;

/// The array as bit-planes.
///
/// It agrees with [`WordArray`](crate::WordArray) in every register of every pixel and in
/// the clock count. A convex slab on an 8×2 array, front plane Z = 4 + x, back plane Z = 8
/// (depth units), closed and composed into the image:
///
/// ```
/// use rtl_model::program::CReg;
/// use rtl_model::{Array, ArrayConfig, Coeffs, CycleArray, Equations, Op, WordArray};
///
/// let cfg = ArrayConfig::new(8, 2);
/// let q = |v: f64| cfg.fmt.quantize(v).unwrap();
/// let plane = |z0, dzx, colour, h| Op::Plane {
///     coeffs: Coeffs { c0: q(z0), dx: q(dzx), dy: 0 },
///     colour,
///     interior: 7,
///     l: false,
///     s: true,
///     h,
///     y: false,
/// };
/// let ops = [
///     plane(4.0, 1.0, 5, true),
///     plane(8.0, 0.0, 0, false),
///     Op::Close { l: false },
///     Op::Compose { p: false },
/// ];
/// let mut cycle = CycleArray::new(cfg, Equations::Derived.set());
/// let mut word = WordArray::new(cfg, Equations::Derived.set());
/// cycle.run(&ops).unwrap();
/// word.run(&ops).unwrap();
/// assert_eq!(cycle.state(), word.state());
/// assert_eq!(cycle.cycles(), word.cycles());
/// // Colour 5 where the front plane lies before the back one (x < 4), background behind.
/// let g: Vec<u32> = (0..8).map(|x| cycle.pixel(x, 1).creg(CReg::G)).collect();
/// assert_eq!(g, [5, 5, 5, 5, 0, 0, 0, 0]);
/// ```
pub struct CycleArray {
    cfg: ArrayConfig,
    set: EquationSet,
    depgen: DepGen,
    /// Every pixel's registers, and the windows deferred on them. Readers that take `&self`
    /// run the deferred windows first (hence the cell); nothing else borrows it.
    planes: RefCell<Planes>,
    seq: Sequencer,
    ops: usize,
    probe: Option<Recorder>,
    observer: Option<Observer>,
}

/// Every register of every pixel as bit-planes, and the work not yet done on them.
struct Planes {
    cfg: ArrayConfig,
    /// Words per row and per plane.
    wpr: usize,
    nw: usize,
    /// Depth registers A, F, B, C: N_D planes each.
    depth: [Vec<u64>; 4],
    /// Colour registers D, E, G: `colour_bits` planes each.
    colour: [Vec<u64>; 3],
    /// Latched select code: S1 (or S3) and S2 (or S4).
    sel: [Vec<u64>; 2],
    /// Comparator flip-flops.
    cmp: Cmp,
    /// The pixel adder's carry.
    carry: Vec<u64>,
    /// Clipping stack, `stack_depth` planes.
    stack: Vec<u64>,
    /// Rows of a panel.
    panel_rows: usize,
    /// Windows and stack operations admitted but not yet run, in program order.
    queue: Vec<Job>,
    /// Bytes of line bits in `queue`.
    queued_bytes: usize,
    /// Most jobs and line bits `queue` holds before it is run.
    queue_jobs: usize,
    queue_bytes: usize,
}

/// One clock as [`CycleArray::observe`] reports it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Clock {
    /// Clocks completed, this one included (the first clock is 1).
    pub t: u64,
    /// Bit k of the window in this clock; `None` for DEPGEN's fill and a stack operation.
    pub bit: Option<u32>,
    /// Whether the comparator took a bit in this clock.
    pub compared: bool,
}

/// Called after every clock with the whole array as it is then.
pub type Observer = Box<dyn FnMut(&CycleArray, Clock)>;

/// The flip-flops of one pixel that [`Pixel`] leaves out or summarises: the DEPGEN adder's
/// carry and the comparator's lt, eq, ovf, sign (`Pixel` holds the flags N J T M they give).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Internal {
    /// Carry of the pixel's DEPGEN serial adder.
    pub carry: bool,
    /// Comparator: A < R on the bits seen so far.
    pub lt: bool,
    /// Comparator: no bit has differed so far.
    pub eq: bool,
    /// Comparator: an overflow bit of A was 1.
    pub ovf: bool,
    /// Comparator: the sign bit of A.
    pub sign: bool,
}

#[derive(Clone, Debug)]
struct Cmp {
    lt: Vec<u64>,
    eq: Vec<u64>,
    ovf: Vec<u64>,
    sign: Vec<u64>,
}

impl Cmp {
    fn get(&self, w: usize) -> Comparator {
        Comparator {
            lt: self.lt[w],
            eq: self.eq[w],
            ovf: self.ovf[w],
            sign: self.sign[w],
        }
    }
}

/// What one window does, in the order a clock does it.
struct Plan {
    transfer: Option<Transfer>,
    lines: Option<LineBits>,
    colour: Option<u32>,
    compare: Option<(Reg, Reg)>,
    decide: Option<Decide>,
    /// The stack level a push writes.
    sp: usize,
    /// Clock number of bit 0 of the window.
    start: u64,
    position: u8,
}

/// Per-pixel work in program order: a window, or a stack operation with the stack pointer
/// before it.
enum Job {
    Window(Plan),
    Stack(Op, usize),
}

fn bcast(v: u64, k: usize) -> u64 {
    0u64.wrapping_sub(v >> k & 1)
}

/// Bit-planes of one word of pixels (a bit each per plane): depth and colour registers,
/// select latch, comparator, carry and stack.
fn planes_per_word(cfg: &ArrayConfig) -> u64 {
    4 * cfg.fmt.bits() as u64 + 3 * cfg.colour_bits as u64 + 2 + 4 + 1 + cfg.stack_depth as u64
}

/// Rows of a panel of a `cfg` array: as many as [`PANEL_BYTES`] holds, at least one.
fn panel_rows(cfg: &ArrayConfig) -> usize {
    let row = cfg.width.div_ceil(64) as u64 * 8 * planes_per_word(cfg);
    ((PANEL_BYTES as u64 / row.max(1)) as usize).max(1)
}

impl Planes {
    fn nd(&self) -> usize {
        self.cfg.fmt.bits() as usize
    }

    /// Rows of a chunk: about [`CHUNK_WORDS`] words.
    fn chunk_rows(&self) -> usize {
        (CHUNK_WORDS / self.wpr).max(1)
    }

    /// Whether windows are deferred and run panel by panel: only when there is more than one
    /// panel (one panel is the whole array, swept as it comes).
    fn batched(&self) -> bool {
        self.panel_rows < self.cfg.height
    }

    /// Defer `job`; run the queue when it is full.
    fn defer(&mut self, job: Job) {
        if let Job::Window(Plan { lines: Some(l), .. }) = &job {
            self.queued_bytes += (l.col.len() + l.row.len()) * 8;
        }
        self.queue.push(job);
        if self.queue.len() >= self.queue_jobs || self.queued_bytes >= self.queue_bytes {
            self.flush();
        }
    }

    /// Run the deferred jobs panel by panel: every job over one panel's rows, in order, before
    /// the next panel.
    fn flush(&mut self) {
        if self.queue.is_empty() {
            return;
        }
        let jobs = std::mem::take(&mut self.queue);
        let (h, ph, cr) = (self.cfg.height, self.panel_rows, self.chunk_rows());
        let mut masks = Vec::with_capacity(cr * self.wpr);
        for y0 in (0..h).step_by(ph) {
            let panel = y0..(y0 + ph).min(h);
            for job in &jobs {
                match job {
                    Job::Window(plan) => {
                        for c0 in panel.clone().step_by(cr) {
                            let rows = c0..(c0 + cr).min(panel.end);
                            self.begin(plan, rows.clone(), &mut masks);
                            for k in 0..self.nd() {
                                self.clock(plan, k, rows.clone(), &masks);
                            }
                            self.decide_at_end(plan, rows);
                        }
                    }
                    Job::Stack(op, sp) => {
                        self.stack_op(op, *sp, panel.start * self.wpr..panel.end * self.wpr)
                    }
                }
            }
        }
        self.queue = jobs;
        self.queue.clear();
        self.queued_bytes = 0;
    }

    /// A window's start on `rows`: decode the latched code, reset the comparator and the
    /// adder's carry.
    fn begin(&mut self, plan: &Plan, rows: Range<usize>, masks: &mut Vec<ActionMasks>) {
        let words = rows.start * self.wpr..rows.end * self.wpr;
        if let Some(t) = &plan.transfer {
            masks.clear();
            masks.extend(
                words
                    .clone()
                    .map(|i| t.decode.masks(self.sel[0][i], self.sel[1][i])),
            );
        }
        if plan.compare.is_some() {
            let c = Comparator::RESET;
            self.cmp.lt[words.clone()].fill(c.lt);
            self.cmp.eq[words.clone()].fill(c.eq);
            self.cmp.ovf[words.clone()].fill(c.ovf);
            self.cmp.sign[words.clone()].fill(c.sign);
        }
        if plan.lines.is_some() {
            // The adder starts each plane with carry 0; otherwise it holds its last carry.
            self.carry[words].fill(0);
        }
    }

    /// Clock `k` of a window on `rows`; SGENE's decision comes after the last ([`Self::decide_at_end`]).
    fn clock(&mut self, plan: &Plan, k: usize, rows: Range<usize>, masks: &[ActionMasks]) {
        let words = rows.start * self.wpr..rows.end * self.wpr;
        if let Some(t) = &plan.transfer {
            self.transfer_bit(t, k, words.clone(), masks);
        }
        if let Some(lines) = &plan.lines {
            self.stream_bit(k, lines, plan.colour, rows);
        }
        if let Some((lhs, rhs)) = plan.compare {
            self.compare_bit(k, lhs, rhs, words);
        }
    }

    /// SGENE's decision at the end of a window's last clock, on `rows`: after the probes have
    /// sampled that clock, which sees the select code and stack from before it.
    fn decide_at_end(&mut self, plan: &Plan, rows: Range<usize>) {
        if let Some(d) = &plan.decide {
            let words = rows.start * self.wpr..rows.end * self.wpr;
            self.decide(d, plan.sp, words);
        }
    }

    /// TRANSD (and TRANSC) for bit `k`: the latched code picks source, keep, 0 or 1.
    fn transfer_bit(&mut self, t: &Transfer, k: usize, words: Range<usize>, masks: &[ActionMasks]) {
        let nw = self.nw;
        let one = if k == self.cfg.fmt.sign_bit() as usize {
            0
        } else {
            !0
        };
        let plane = k * nw + words.start..k * nw + words.end;
        let [dst, src] = self
            .depth
            .get_disjoint_mut([t.dst as usize, t.src as usize])
            .expect("transfer source and destination differ");
        for ((d, s), m) in dst[plane.clone()]
            .iter_mut()
            .zip(&src[plane.clone()])
            .zip(masks)
        {
            *d = (m.put_src & s) | (m.keep & *d) | (m.put1 & one);
        }
        if let Some((cd, cs)) = t.colour {
            if k < self.cfg.colour_bits as usize {
                let int = bcast(t.interior as u64, k);
                let [dst, src] = self
                    .colour
                    .get_disjoint_mut([cd as usize, cs as usize])
                    .expect("colour source and destination differ");
                for ((d, s), m) in dst[plane.clone()].iter_mut().zip(&src[plane]).zip(masks) {
                    *d = (m.put_src & s) | (m.keep & *d) | (m.put0 & int);
                }
            }
        }
    }

    /// DEPGEN's bit `k` into A (and MEM D's colour bit into D).
    fn stream_bit(&mut self, k: usize, lines: &LineBits, colour: Option<u32>, rows: Range<usize>) {
        let (nw, wpr) = (self.nw, self.wpr);
        let a = &mut self.depth[Reg::A as usize][k * nw..(k + 1) * nw];
        let cols = &lines.col[k * wpr..(k + 1) * wpr];
        for y in rows.clone() {
            let row = lines.row_mask(k, y);
            let (a, carry) = (
                &mut a[y * wpr..(y + 1) * wpr],
                &mut self.carry[y * wpr..(y + 1) * wpr],
            );
            for ((a, cy), col) in a.iter_mut().zip(carry.iter_mut()).zip(cols) {
                *a = pixel_add(*col, row, cy);
            }
        }
        if let Some(c) = colour.filter(|_| k < self.cfg.colour_bits as usize) {
            let d = &mut self.colour[0][k * nw..(k + 1) * nw];
            d[rows.start * wpr..rows.end * wpr].fill(bcast(c as u64, k));
        }
    }

    /// The comparator's clock `k`.
    fn compare_bit(&mut self, k: usize, lhs: Reg, rhs: Reg, words: Range<usize>) {
        let role = BitRole::of(&self.cfg.fmt, k as u32);
        let nw = self.nw;
        let a = &self.depth[lhs as usize][k * nw..(k + 1) * nw];
        let r = &self.depth[rhs as usize][k * nw..(k + 1) * nw];
        let c = &mut self.cmp;
        for i in words {
            let mut cmp = c.get(i);
            cmp.step(a[i], r[i], role);
            (c.lt[i], c.eq[i], c.ovf[i], c.sign[i]) = (cmp.lt, cmp.eq, cmp.ovf, cmp.sign);
        }
    }

    /// SGENE at the end of a window: latch the code or push LL at level `sp`.
    fn decide(&mut self, d: &Decide, sp: usize, words: Range<usize>) {
        for i in words {
            let f = self.cmp.get(i).flags();
            let mut vars = [0u64; 10];
            vars[Var::N as usize] = f.n;
            vars[Var::J as usize] = f.j;
            vars[Var::T as usize] = f.t;
            vars[Var::M as usize] = f.m;
            match d {
                Decide::Latch(hi, lo) => {
                    self.sel[0][i] = hi.eval(&vars);
                    self.sel[1][i] = lo.eval(&vars);
                }
                Decide::Push(ll) => self.stack[sp * self.nw + i] = ll.eval(&vars),
            }
        }
    }

    /// A postfix operator or the clipping result on `words`, the stack pointer at `sp`.
    fn stack_op(&mut self, op: &Op, sp: usize, words: Range<usize>) {
        let (nw, w0, w1) = (self.nw, words.start, words.end);
        let level = |l: usize| l * nw + w0..l * nw + w1;
        match op {
            Op::ClipAnd | Op::ClipOr => {
                let (lo, hi) = self.stack.split_at_mut((sp - 1) * nw);
                let (under, top) = (&mut lo[level(sp - 2)], &hi[words.clone()]);
                for (u, t) in under.iter_mut().zip(top) {
                    *u = if matches!(op, Op::ClipAnd) {
                        *u & t
                    } else {
                        *u | t
                    };
                }
            }
            Op::ClipNot => self.stack[level(sp - 1)].iter_mut().for_each(|v| *v = !*v),
            Op::ClipApply => {
                for (i, ll) in words.zip(&self.stack[level(sp - 1)]) {
                    self.sel[0][i] = !ll;
                    self.sel[1][i] = !0;
                }
            }
            _ => {}
        }
    }

    /// One pixel's registers gathered from the bit-planes.
    fn gather(&self, x: usize, y: usize) -> Pixel {
        let (w, lane) = (y * self.wpr + x / 64, x % 64);
        let bit = |v: &[u64], k: usize| v[k * self.nw + w] >> lane & 1;
        let word = |v: &[u64], n: usize| (0..n).fold(0u64, |acc, k| acc | bit(v, k) << k);
        let nd = self.nd();
        let f = self.cmp.get(w).flags();
        let cb = self.cfg.colour_bits as usize;
        Pixel {
            depth: std::array::from_fn(|r| self.cfg.fmt.wrap(word(&self.depth[r], nd) as i64)),
            colour: std::array::from_fn(|r| word(&self.colour[r], cb) as u32),
            sel: (bit(&self.sel[0], 0) == 1, bit(&self.sel[1], 0) == 1),
            flags: FlagBits {
                n: f.n >> lane & 1 == 1,
                j: f.j >> lane & 1 == 1,
                t: f.t >> lane & 1 == 1,
                m: f.m >> lane & 1 == 1,
            },
            stack: word(&self.stack, self.cfg.stack_depth),
        }
    }

    fn internal(&self, x: usize, y: usize) -> Internal {
        let (w, lane) = (y * self.wpr + x / 64, x % 64);
        let b = |v: u64| v >> lane & 1 == 1;
        let c = self.cmp.get(w);
        Internal {
            carry: b(self.carry[w]),
            lt: b(c.lt),
            eq: b(c.eq),
            ovf: b(c.ovf),
            sign: b(c.sign),
        }
    }
}

impl CycleArray {
    /// A `cfg` array after reset (every depth register at the Put-1 word, colours 0, code
    /// Keep), its SGENE built from `set`.
    pub fn new(cfg: ArrayConfig, set: EquationSet) -> CycleArray {
        let wpr = cfg.width.div_ceil(64);
        let nw = wpr * cfg.height;
        let nd = cfg.fmt.bits() as usize;
        let ones = |planes: usize, bits: u64| -> Vec<u64> {
            (0..planes)
                .flat_map(|k| std::iter::repeat_n(bcast(bits, k), nw))
                .collect()
        };
        let max = cfg.fmt.max_word() as u64;
        let cb = cfg.colour_bits as usize;
        let planes = Planes {
            cfg,
            wpr,
            nw,
            depth: std::array::from_fn(|_| ones(nd, max)),
            colour: std::array::from_fn(|_| ones(cb, 0)),
            sel: [vec![0; nw], vec![!0; nw]],
            cmp: Cmp {
                lt: vec![0; nw],
                eq: vec![!0; nw],
                ovf: vec![0; nw],
                sign: vec![0; nw],
            },
            carry: vec![0; nw],
            stack: vec![0; cfg.stack_depth * nw],
            panel_rows: panel_rows(&cfg),
            queue: vec![],
            queued_bytes: 0,
            queue_jobs: QUEUE_JOBS,
            queue_bytes: QUEUE_LINE_BYTES,
        };
        CycleArray {
            depgen: DepGen::new(cfg.width, cfg.height, cfg.fmt),
            planes: RefCell::new(planes),
            seq: Sequencer::default(),
            ops: 0,
            probe: None,
            observer: None,
            cfg,
            set,
        }
    }

    fn nd(&self) -> usize {
        self.cfg.fmt.bits() as usize
    }

    fn chunk_rows(&mut self) -> usize {
        if self.observer.is_some() {
            // Observed clock by clock: the whole array is one chunk, so that every pixel is at
            // the same clock when the observer looks.
            return self.cfg.height;
        }
        self.planes.get_mut().chunk_rows()
    }

    /// Whether the next window is deferred and run with others panel by panel: not when an
    /// observer or a probe watches every clock, nor on an array of one panel.
    fn deferring(&mut self) -> bool {
        self.observer.is_none() && self.probe.is_none() && self.planes.get_mut().batched()
    }

    /// Run the deferred windows (panel by panel).
    fn flush(&mut self) {
        self.planes.get_mut().flush();
    }

    /// The planes with every admitted operation carried out.
    fn planes(&self) -> Ref<'_, Planes> {
        if !self.planes.borrow().queue.is_empty() {
            self.planes.borrow_mut().flush();
        }
        self.planes.borrow()
    }

    /// Call `f` after every clock from now on, DEPGEN's fill and stack operations included,
    /// with the array as it is after that clock (every register of every pixel: [`Self::pixel`],
    /// [`Self::internal`]). The array is then swept as a whole, clock by clock, rather than in
    /// chunks; the clocks and the results are the same. The stack pointer (the controller's, in
    /// `state().sp`) moves after a clipping plane's last clock has been reported.
    pub fn observe(&mut self, f: Observer) {
        self.flush();
        self.observer = Some(f);
    }

    fn notify(&mut self, clock: Clock) {
        if let Some(mut f) = self.observer.take() {
            f(self, clock);
            self.observer = Some(f);
        }
    }

    /// Pixel (x, y)'s DEPGEN carry and comparator flip-flops.
    pub fn internal(&self, x: usize, y: usize) -> Internal {
        self.planes().internal(x, y)
    }

    fn window(&mut self, w: Window) {
        let clocks = self.seq.window_clocks(&self.cfg, &w);
        if self.observer.is_some() {
            let nd = self.nd() as u64;
            for t in self.seq.cycles + 1..=self.seq.cycles + clocks - nd {
                self.notify(Clock {
                    t,
                    bit: None,
                    compared: false,
                });
            }
        }
        let push = matches!(w.decide, Decide::Push(_));
        let plan = Plan {
            transfer: self.seq.pending.take(),
            lines: w.stream.map(|(c, _)| self.depgen.stream(&c)),
            colour: w.stream.and_then(|s| s.1),
            compare: Some((w.lhs, w.rhs)),
            decide: Some(w.decide),
            sp: self.seq.sp,
            start: self.seq.cycles + clocks - self.nd() as u64,
            position: w.position,
        };
        self.run_plan(plan);
        self.seq.cycles += clocks;
        if push {
            self.seq.sp += 1;
        }
        self.seq.pending = w.transfer;
    }

    /// Carry out a window: deferred, or at once over the whole array.
    fn run_plan(&mut self, plan: Plan) {
        if self.deferring() {
            self.planes.get_mut().defer(Job::Window(plan));
        } else {
            self.sweep(&plan);
        }
    }

    /// Run a window's clocks over the whole array, chunk by chunk, sampling the probes and
    /// telling the observer after every clock.
    fn sweep(&mut self, plan: &Plan) {
        self.flush();
        let rows_per = self.chunk_rows();
        let mut masks = Vec::with_capacity(rows_per * self.planes.get_mut().wpr);
        for y0 in (0..self.cfg.height).step_by(rows_per) {
            let rows = y0..(y0 + rows_per).min(self.cfg.height);
            self.planes.get_mut().begin(plan, rows.clone(), &mut masks);
            for k in 0..self.nd() {
                self.planes.get_mut().clock(plan, k, rows.clone(), &masks);
                self.sample(plan, k, rows.clone());
                if k + 1 == self.nd() {
                    self.planes.get_mut().decide_at_end(plan, rows.clone());
                }
                if self.observer.is_some() {
                    self.notify(Clock {
                        t: plan.start + k as u64 + 1,
                        bit: Some(k as u32),
                        compared: plan.compare.is_some(),
                    });
                }
            }
        }
        let nd = self.nd();
        if let Some(rec) = &mut self.probe {
            for k in 0..nd {
                rec.global(plan.start + k as u64 + 1, plan.position, k as u32);
            }
        }
    }

    /// Postfix operators and the clipping result: one clock, whole planes at once.
    fn stack_op(&mut self, op: &Op) {
        let sp = self.seq.sp;
        if self.deferring() {
            self.planes.get_mut().defer(Job::Stack(op.clone(), sp));
        } else {
            self.flush();
            let p = self.planes.get_mut();
            let nw = p.nw;
            p.stack_op(op, sp, 0..nw);
        }
        if matches!(op, Op::ClipApply) {
            self.seq.pending = Some(Transfer::clip_apply());
        }
        let (pop, push) = crate::program::stack_effect(op);
        self.seq.sp = sp - pop + push;
        self.seq.cycles += 1;
        self.sample_all_probes();
        if self.observer.is_some() {
            self.notify(Clock {
                t: self.seq.cycles,
                bit: None,
                compared: false,
            });
        }
    }

    /// One pixel's registers gathered from the bit-planes.
    pub fn gather(&self, x: usize, y: usize) -> Pixel {
        self.planes().gather(x, y)
    }

    fn sample(&mut self, plan: &Plan, k: usize, rows: Range<usize>) {
        let Some(rec) = &mut self.probe else { return };
        let planes = self.planes.get_mut();
        let t = plan.start + k as u64 + 1;
        for i in 0..rec.probes().len() {
            let (x, y) = rec.probes()[i];
            if rows.contains(&y) {
                rec.sample(t, i, planes.gather(x, y));
            }
        }
    }

    fn sample_all_probes(&mut self) {
        let Some(rec) = &mut self.probe else { return };
        let planes = self.planes.get_mut();
        let t = self.seq.cycles;
        for i in 0..rec.probes().len() {
            let (x, y) = rec.probes()[i];
            rec.sample(t, i, planes.gather(x, y));
        }
        rec.global(t, 1, 0);
    }
}

impl Array for CycleArray {
    fn config(&self) -> &ArrayConfig {
        &self.cfg
    }

    fn pixel(&self, x: usize, y: usize) -> Pixel {
        self.gather(x, y)
    }

    fn step(&mut self, op: &Op) -> Result<(), ProgramError> {
        self.seq.admit(op, self.ops, self.cfg.stack_depth)?;
        self.ops += 1;
        match Window::of(op, &self.set) {
            Some(w) => self.window(w),
            None => self.stack_op(op),
        }
        Ok(())
    }

    fn finish(&mut self) {
        if let Some(t) = self.seq.pending.take() {
            let plan = Plan {
                transfer: Some(t),
                lines: None,
                colour: None,
                compare: None,
                decide: None,
                sp: self.seq.sp,
                start: self.seq.cycles,
                position: 0,
            };
            self.run_plan(plan);
            self.seq.cycles += self.nd() as u64;
        }
        self.flush();
    }

    fn cycles(&self) -> u64 {
        self.seq.cycles
    }

    fn attach_probe(&mut self, rec: Recorder) {
        self.flush();
        self.probe = Some(rec);
    }

    fn take_probe(&mut self) -> Option<Recorder> {
        self.flush();
        self.probe.take()
    }

    fn state(&self) -> ArchState {
        let (w, h) = (self.cfg.width, self.cfg.height);
        let planes = self.planes();
        ArchState {
            width: w,
            height: h,
            pixels: (0..w * h).map(|i| planes.gather(i % w, i / w)).collect(),
            sp: self.seq.sp,
        }
    }
}

impl CycleArray {
    /// Bytes the bit-planes of a `cfg` array take: depth and colour registers, select latch,
    /// comparator, carry and stack, one bit each per (padded) pixel.
    pub fn memory_bytes(cfg: &ArrayConfig) -> u64 {
        let words = (cfg.width.div_ceil(64) * cfg.height) as u64;
        words * 8 * planes_per_word(cfg)
    }
}

#[cfg(test)]
mod batched_tests;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::program;
    use crate::Equations;
    use std::cell::RefCell;
    use std::rc::Rc;

    /// Observed clock by clock (one chunk), a many-chunk array ends where the unobserved one
    /// does, the observer sees every clock once, and at each operation's last clock it sees
    /// every pixel as `state()` shows it after the operation (the stack pointer, the
    /// controller's, moves after the clock).
    #[test]
    fn observing_every_clock_changes_nothing_and_sees_every_clock() {
        let cfg = ArrayConfig::new(130, 70);
        let ops = program();
        let mut plain = CycleArray::new(cfg, Equations::Derived.set());
        plain.run(&ops).unwrap();
        assert!(plain.chunk_rows() < cfg.height, "the plain run is chunked");

        let seen: Rc<RefCell<Vec<(Clock, ArchState)>>> = Rc::default();
        let log = Rc::clone(&seen);
        let mut obs = CycleArray::new(cfg, Equations::Derived.set());
        obs.observe(Box::new(move |a, c| log.borrow_mut().push((c, a.state()))));
        let mut after = vec![];
        for op in &ops {
            obs.step(op).unwrap();
            after.push((obs.cycles(), obs.state()));
        }
        obs.finish();
        assert_eq!(obs.cycles(), plain.cycles());
        assert_eq!(obs.state(), plain.state());
        let seen = seen.borrow();
        let clocks: Vec<u64> = seen.iter().map(|(c, _)| c.t).collect();
        assert_eq!(clocks, (1..=plain.cycles()).collect::<Vec<_>>());
        // DEPGEN's fill: idle clocks before the first window.
        let fill = cfg.depgen_latency() as usize;
        assert!(seen[..fill].iter().all(|(c, _)| c.bit.is_none()));
        assert_eq!(seen[fill].0.bit, Some(0));
        for (t, state) in after {
            let got = &seen[t as usize - 1].1;
            let diff = (0..state.pixels.len()).find(|&i| got.pixels[i] != state.pixels[i]);
            assert_eq!(diff, None, "clock {t}");
        }
        assert!(seen.last().unwrap().1.pixels == plain.state().pixels);
    }
}
