//! The array against the behavioural case tables themselves: load actual depth words into a
//! one-pixel array with real operations, run one more, and compare the register with what
//! `select::cases` says the thesis row does. This closes the loop vectors → minimizer →
//! equations → decode → TRANSD, in both models.

use proptest::prelude::*;
use rtl_model::program::Reg;
use rtl_model::select::cases::{self, Action, Compose};
use rtl_model::{Array, ArrayConfig, Coeffs, CycleArray, Equations, Op, WordArray, WordFormat};

fn flat(v: i64) -> Coeffs {
    Coeffs {
        c0: v,
        dx: 0,
        dy: 0,
    }
}

fn plane(v: i64, s: bool, h: bool, y: bool, l: bool) -> Op {
    Op::Plane {
        coeffs: flat(v),
        colour: 3,
        interior: 7,
        l,
        s,
        h,
        y,
    }
}

/// Run `ops` on a 1x1 array in both models; return register `r` (they must agree).
fn run(ops: &[Op], r: Reg) -> i64 {
    let cfg = ArrayConfig::new(1, 1);
    let mut c = CycleArray::new(cfg, Equations::Derived.set());
    let mut w = WordArray::new(cfg, Equations::Derived.set());
    c.run(ops).unwrap();
    w.run(ops).unwrap();
    assert_eq!(c.state(), w.state());
    w.state().pixels[0].reg(r)
}

fn apply(fmt: &WordFormat, act: Action, a: i64, old: i64) -> i64 {
    match act {
        Action::PutA => a,
        Action::Put0 => 0,
        Action::Keep => old,
        Action::Put1 => fmt.max_word(),
    }
}

fn allowed(fmt: &WordFormat, v: cases::Verdict<Action>, a: i64, old: i64) -> Vec<i64> {
    let mut out = vec![apply(fmt, v.choices.0, a, old)];
    out.extend(v.choices.1.map(|c| apply(fmt, c, a, old)));
    out
}

fn word() -> impl Strategy<Value = i64> {
    let f = WordFormat::THESIS;
    let md = f.maxdepth();
    prop_oneof![
        Just(0i64),
        Just(-1i64),
        Just(md - 1),
        Just(md),
        Just(f.max_word()),
        Just(f.min_word()),
        -4i64..4,
        md - 4..md + 4,
        f.min_word()..=f.max_word(),
        0..md,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn front_plane_does_what_its_case_row_says(f0 in word(), a in word(), l: bool, y: bool) {
        let fmt = WordFormat::THESIS;
        // A first front plane leaves F in [0, maxdepth) or 0 or the Put-1 word.
        let f = run(&[plane(f0, true, true, false, l)], Reg::F);
        let got = run(&[plane(f0, true, true, false, l), plane(a, false, true, y, l)], Reg::F);
        let v = cases::front(&fmt, cases::FrontExt { l, s: false, y }, a, f);
        prop_assert!(allowed(&fmt, v, a, f).contains(&got), "{} F={f} A={a} got {got}", v.row);
    }

    #[test]
    fn back_plane_does_what_its_case_row_says(b0 in word(), a in word(), l: bool) {
        let fmt = WordFormat::THESIS;
        let b = run(&[plane(b0, true, false, false, l)], Reg::B);
        let got = run(&[plane(b0, true, false, false, l), plane(a, false, false, false, l)], Reg::B);
        let v = cases::back(&fmt, cases::BackExt { l, s: false }, a, b);
        prop_assert!(allowed(&fmt, v, a, b).contains(&got), "{} B={b} A={a} got {got}", v.row);
    }

    #[test]
    fn closing_does_what_the_table_says(f0 in word(), b0 in word(), l: bool) {
        let fmt = WordFormat::THESIS;
        let load = [plane(f0, true, true, false, l), plane(b0, true, false, false, l)];
        let (f, b) = (run(&load, Reg::F), run(&load, Reg::B));
        let mut ops = load.to_vec();
        ops.push(Op::Close { l });
        let got = run(&ops, Reg::F);
        let v = cases::close(l, b, f);
        prop_assert!(allowed(&fmt, v, b, f).contains(&got), "{} F={f} B={b} got {got}", v.row);
    }

    #[test]
    fn clipping_plane_does_what_its_case_row_says(f0 in word(), a in word(), h: bool, y: bool, x: bool) {
        let fmt = WordFormat::THESIS;
        let f = run(&[plane(f0, true, true, false, false)], Reg::F);
        let ops = [
            plane(f0, true, true, false, false),
            Op::ClipPlane { coeffs: flat(a), h, y, x },
            Op::ClipApply,
        ];
        let got = run(&ops, Reg::F);
        let v = cases::clip(&fmt, cases::ClipExt { h, y, x }, a, f);
        let want = if v.choices.0 { f } else { fmt.max_word() };
        prop_assert_eq!(got, want, "{} F={} A={}", v.row, f, a);
    }

    #[test]
    fn second_stage_does_what_its_case_row_says(c0 in word(), f0 in word(), p: bool) {
        let fmt = WordFormat::THESIS;
        let first = [plane(c0, true, true, false, false), Op::Compose { p: false }];
        let c = run(&first, Reg::C);
        let mut ops = first.to_vec();
        ops.push(plane(f0, true, true, false, false));
        let f = run(&ops, Reg::F);
        ops.push(Op::Compose { p });
        let got = run(&ops, Reg::C);
        let v = cases::second(p, f, c);
        let want = match v.choices.0 {
            Compose::Put1 => fmt.max_word(),
            Compose::PutF => f,
            Compose::KeepC => c,
        };
        prop_assert_eq!(got, want, "{} F={} C={}", v.row, f, c);
    }
}
