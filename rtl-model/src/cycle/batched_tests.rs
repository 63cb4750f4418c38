//! The panel-by-panel path against the window-by-window one and against `word`: random
//! programs (the generator of `tests/cycle_vs_word.rs`) on random array sizes, with panels of
//! a few rows and short queues so that a program is run as many batches over many panels.

use proptest::prelude::*;

use super::{CycleArray, Internal};
use crate::array::check_program;
use crate::program::Coeffs;
use crate::{Array, ArrayConfig, Equations, Op, WordArray, WordFormat};

/// The random programs of `tests/cycle_vs_word.rs`.
#[path = "random_programs.rs"]
mod random_programs;
use random_programs::{format, program, Rng};

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
