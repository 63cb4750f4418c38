//! The panel-by-panel path against the window-by-window one and against `word`: random
//! programs (the generator of `tests/cycle_vs_word.rs`) on random array sizes, with panels of
//! a few rows and short queues so that a program is run as many batches over many panels.

use proptest::prelude::*;

use super::{CycleArray, Internal};
use crate::array::check_program;
use crate::program::Coeffs;
use crate::{Array, ArrayConfig, Equations, Op, WordArray, WordFormat};

/// A small deterministic generator, so one proptest seed gives one whole program.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn coin(&mut self) -> bool {
        self.next() & 1 == 1
    }
}

/// A raw word biased towards the places where the select logic changes its mind.
fn word(r: &mut Rng, fmt: &WordFormat) -> i64 {
    let md = fmt.maxdepth();
    let special = [
        0,
        1,
        -1,
        md - 1,
        md,
        md + 1,
        fmt.max_word(),
        fmt.min_word(),
        md / 2,
    ];
    match r.below(4) {
        0 => special[r.below(special.len() as u64) as usize],
        1 => fmt.wrap(r.next() as i64),
        _ => fmt.wrap(r.below(2 * md as u64 + 4) as i64 - 2),
    }
}

fn slope(r: &mut Rng, fmt: &WordFormat) -> i64 {
    match r.below(4) {
        0 => 0,
        1 => fmt.wrap(r.next() as i64),
        _ => r.below(64) as i64 - 32,
    }
}

fn coeffs(r: &mut Rng, fmt: &WordFormat, prev: &[Coeffs]) -> Coeffs {
    // Re-using a plane makes A = F, A = B and F = C ties common.
    if !prev.is_empty() && r.below(5) == 0 {
        return prev[r.below(prev.len() as u64) as usize];
    }
    Coeffs {
        c0: word(r, fmt),
        dx: slope(r, fmt),
        dy: slope(r, fmt),
    }
}

fn object(r: &mut Rng, fmt: &WordFormat, ops: &mut Vec<Op>, prev: &mut Vec<Coeffs>) {
    let l = r.coin();
    let (mut front, mut back) = (false, false);
    for _ in 0..1 + r.below(6) {
        let (h, y) = match r.below(4) {
            0 => (r.coin(), true),
            1 | 2 => (true, false),
            _ => (false, false),
        };
        let seen = if h || y { &mut front } else { &mut back };
        // Mostly first-of-kind S, sometimes a random S to reach every row.
        let s = if r.below(8) == 0 { r.coin() } else { !*seen };
        *seen = true;
        let c = coeffs(r, fmt, prev);
        prev.push(c);
        let colour = r.below(256) as u32;
        ops.push(Op::Plane {
            coeffs: c,
            colour,
            interior: 7,
            l,
            s,
            h,
            y,
        });
    }
    if back || r.below(4) == 0 {
        ops.push(Op::Close { l });
    }
}

fn clip_expr(
    r: &mut Rng,
    fmt: &WordFormat,
    ops: &mut Vec<Op>,
    prev: &mut Vec<Coeffs>,
    leaves: u64,
) {
    if leaves == 1 {
        let c = coeffs(r, fmt, prev);
        prev.push(c);
        ops.push(Op::ClipPlane {
            coeffs: c,
            h: r.coin(),
            y: r.below(4) == 0,
            x: r.coin(),
        });
    } else {
        let left = 1 + r.below(leaves - 1);
        clip_expr(r, fmt, ops, prev, left);
        clip_expr(r, fmt, ops, prev, leaves - left);
        ops.push(if r.coin() { Op::ClipAnd } else { Op::ClipOr });
    }
    if r.below(4) == 0 {
        ops.push(Op::ClipNot);
    }
}

fn program(r: &mut Rng, fmt: &WordFormat) -> Vec<Op> {
    let mut ops = vec![];
    let mut prev = vec![];
    for _ in 0..1 + r.below(4) {
        object(r, fmt, &mut ops, &mut prev);
        if r.coin() {
            let leaves = 1 + r.below(4);
            clip_expr(r, fmt, &mut ops, &mut prev, leaves);
            ops.push(Op::ClipApply);
        }
        ops.push(Op::Compose { p: r.below(6) == 0 });
    }
    ops
}

fn format(r: &mut Rng) -> WordFormat {
    if r.below(3) == 0 {
        WordFormat::THESIS
    } else {
        WordFormat::new(
            r.below(4) as u32,
            1 + r.below(4) as u32,
            1 + r.below(3) as u32,
        )
        .unwrap()
    }
}

impl CycleArray {
    /// Panels of `rows` rows; the queue run after `jobs` jobs or `bytes` bytes of line bits.
    fn with_panels(mut self, rows: usize, jobs: usize, bytes: usize) -> CycleArray {
        let p = self.planes.get_mut();
        (p.panel_rows, p.queue_jobs, p.queue_bytes) = (rows, jobs, bytes);
        self
    }

    fn internals(&self) -> Vec<Internal> {
        let (w, h) = (self.cfg.width, self.cfg.height);
        (0..w * h).map(|i| self.internal(i % w, i / w)).collect()
    }
}

fn check(seed: u64) -> Result<(), TestCaseError> {
    let mut r = Rng(seed | 1);
    // Widths below, at and past 64 (padding lanes), heights of one to many panels.
    let mut cfg = ArrayConfig::new(1 + r.below(200) as usize, 1 + r.below(40) as usize);
    cfg.fmt = format(&mut r);
    cfg.colour_bits = 1 + r.below(cfg.fmt.bits().min(8) as u64) as u32;
    let ops = program(&mut r, &cfg.fmt);
    check_program(&ops, cfg.stack_depth).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let set = if r.coin() {
        Equations::Derived
    } else {
        Equations::Printed
    }
    .set();
    let rows = 1 + r.below(cfg.height as u64) as usize;
    let jobs = 1 + r.below(12) as usize;
    let bytes = if r.coin() {
        usize::MAX
    } else {
        1 + r.below(2048) as usize
    };
    let mut batched = CycleArray::new(cfg, set.clone()).with_panels(rows, jobs, bytes);
    // One panel: every window at once, chunk by chunk.
    let mut plain = CycleArray::new(cfg, set.clone()).with_panels(usize::MAX, 1, usize::MAX);
    let mut word = WordArray::new(cfg, set);
    // Sometimes an observer that does nothing comes in halfway: the queue is run and the rest
    // of the program is swept clock by clock over the whole array.
    let observe_at = if r.below(4) == 0 {
        r.below(ops.len() as u64 + 1) as usize
    } else {
        usize::MAX
    };
    let what = format!("{cfg:?}, panels of {rows} rows, queue {jobs} jobs / {bytes} bytes");
    for (i, op) in ops.iter().enumerate() {
        if i == observe_at {
            batched.observe(Box::new(|_, _| {}));
        }
        batched.step(op).unwrap();
        plain.step(op).unwrap();
        word.step(op).unwrap();
        prop_assert_eq!(
            batched.cycles(),
            plain.cycles(),
            "after op {}, {}",
            i,
            &what
        );
        prop_assert_eq!(batched.cycles(), word.cycles(), "after op {}, {}", i, &what);
        // Now and then a reader runs the queue in the middle of a batch.
        if r.below(3) == 0 {
            let (b, w) = (batched.state(), word.state());
            if let Some(d) = b.first_difference(&w) {
                return Err(TestCaseError::fail(format!(
                    "after op {i} {op:?} ({what}): pixel {:?}\n batched {:?}\n word    {:?}",
                    (d.0, d.1),
                    d.2,
                    d.3
                )));
            }
            prop_assert!(b == plain.state(), "after op {}, {}", i, &what);
            prop_assert!(batched.internals() == plain.internals(), "{}", &what);
        }
    }
    batched.finish();
    plain.finish();
    word.finish();
    prop_assert_eq!(batched.cycles(), plain.cycles());
    prop_assert_eq!(batched.cycles(), word.cycles());
    let b = batched.state();
    prop_assert!(b == plain.state(), "{}", &what);
    prop_assert!(b == word.state(), "{}", &what);
    prop_assert!(batched.internals() == plain.internals(), "{}", &what);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn panel_by_panel_equals_window_by_window_and_word(seed in any::<u64>()) {
        check(seed)?;
    }
}

/// With the default panels: an array of several panels is deferred and ends as `word` does,
/// read pixel by pixel before `finish` and as a whole after.
#[test]
fn default_panels_defer_and_agree_with_word() {
    let cfg = ArrayConfig::new(300, 400);
    let ops = crate::fixtures::program();
    let set = Equations::Derived.set();
    let mut cyc = CycleArray::new(cfg, set.clone());
    let mut word = WordArray::new(cfg, set);
    assert!(
        cyc.planes.get_mut().panel_rows * 2 < cfg.height,
        "several panels"
    );
    for op in &ops {
        cyc.step(op).unwrap();
        word.step(op).unwrap();
        assert!(!cyc.planes.get_mut().queue.is_empty(), "deferred");
        assert_eq!(cyc.pixel(299, 399), word.pixel(299, 399));
        assert!(cyc.planes.get_mut().queue.is_empty(), "run by the reader");
    }
    cyc.finish();
    word.finish();
    assert_eq!(cyc.cycles(), word.cycles());
    assert!(cyc.state() == word.state());
}
