//! `cycle` against `word`, bit for bit: every register of every pixel after every operation,
//! and the clock count, on random display lists (convex, concave, perpendicular planes, ties,
//! negative depths, overflow, every stage, clipping expressions).

use proptest::prelude::*;
use rtl_model::array::{check_program, program_cycles};
use rtl_model::{Array, ArrayConfig, Coeffs, CycleArray, Equations, Op, WordArray, WordFormat};

/// The random programs (shared with the panel-by-panel tests).
#[path = "../src/cycle/random_programs.rs"]
mod random_programs;
use random_programs::{format, program, Rng};

fn check(seed: u64) -> Result<(), TestCaseError> {
    let mut r = Rng(seed | 1);
    let mut cfg = ArrayConfig::new(1 + r.below(140) as usize, 1 + r.below(6) as usize);
    cfg.fmt = format(&mut r);
    cfg.colour_bits = 1 + r.below(cfg.fmt.bits().min(8) as u64) as u32;
    let ops = program(&mut r, &cfg.fmt);
    check_program(&ops, cfg.stack_depth).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let eq = if r.coin() {
        Equations::Derived
    } else {
        Equations::Printed
    };
    let mut cyc = CycleArray::new(cfg, eq.set());
    let mut wrd = WordArray::new(cfg, eq.set());
    for (i, op) in ops.iter().enumerate() {
        cyc.step(op).unwrap();
        wrd.step(op).unwrap();
        let (a, b) = (cyc.state(), wrd.state());
        if let Some(d) = a.first_difference(&b) {
            return Err(TestCaseError::fail(format!(
                "after op {i} {op:?} ({cfg:?}): pixel {:?}\n cycle {:?}\n word  {:?}",
                (d.0, d.1),
                d.2,
                d.3
            )));
        }
        prop_assert_eq!(cyc.cycles(), wrd.cycles());
    }
    cyc.finish();
    wrd.finish();
    prop_assert_eq!(cyc.state(), wrd.state());
    prop_assert_eq!(cyc.cycles(), wrd.cycles());
    prop_assert_eq!(program_cycles(&cfg, &ops), wrd.cycles());
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]
    #[test]
    fn cycle_equals_word_after_every_operation(seed in any::<u64>()) {
        check(seed)?;
    }
}
