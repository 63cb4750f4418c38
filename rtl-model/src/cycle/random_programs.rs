//! Random display lists for the `cycle` = `word` checks, shared by `rtl-model/tests/cycle_vs_word.rs`
//! and the panel-by-panel tests (`batched_tests.rs`), which include this file by path: it
//! names only what both import (`Coeffs`, `Op`, `WordFormat`) through `super`.

use super::{Coeffs, Op, WordFormat};

/// A small deterministic generator, so one proptest seed gives one whole program.
pub(super) struct Rng(pub(super) u64);

impl Rng {
    pub(super) fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    pub(super) fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    pub(super) fn coin(&mut self) -> bool {
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

pub(super) fn program(r: &mut Rng, fmt: &WordFormat) -> Vec<Op> {
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

pub(super) fn format(r: &mut Rng) -> WordFormat {
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
