//! The behavioural case tables of §2.3.3-2.3.5, on depth values.
//!
//! Each function takes the externals of a plane and the two actual words the comparator sees
//! (the A side and the stored register) and returns what the thesis says must happen, citing
//! the row. These are the specification the golden vectors are generated from; the select
//! equations are checked against the vectors, never against each other.
//!
//! Where the printed rows do not cover a pair of values the reading is noted at the row and in
//! `docs/select-logic.md`. The thesis gives the flags it means beside each row (e.g. "(M=1,
//! N=0)"); when a row's value condition is narrower than its flags (for example
//! "B < Maxdepth ≤ A" beside "(M=1, N=0)") the flags are taken as the condition.

use crate::depth_word::WordFormat;

/// What TRANSD does with the register being written (stage positions 1-3, §2.3.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Action {
    /// Put A: transfer the incoming word (and colour D to E on front planes).
    PutA,
    /// Put 0: the screen (and the object's internal colour).
    Put0,
    /// Keep the register (and colour).
    Keep,
    /// Put 1 / "Put maxdepth": the largest positive word (and the background colour).
    Put1,
}

impl Action {
    /// Select code (S1, S2) of §2.3.3 for front/perpendicular and back planes; stage 3 and the
    /// clipping result use the same TRANSD, hence the same code.
    pub fn code(self) -> (bool, bool) {
        match self {
            Action::PutA => (false, false),
            Action::Put0 => (true, false),
            Action::Keep => (false, true),
            Action::Put1 => (true, true),
        }
    }

    /// Decode (S1, S2).
    pub fn from_code(s1: bool, s2: bool) -> Action {
        match (s1, s2) {
            (false, false) => Action::PutA,
            (true, false) => Action::Put0,
            (false, true) => Action::Keep,
            (true, true) => Action::Put1,
        }
    }
}

/// What the second stage does with C (§2.3.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Compose {
    /// Put 1: S3 = 0, S4 = 0 (initialise C).
    Put1,
    /// Put F: S3 = 0, S4 = 1.
    PutF,
    /// Keep C: S3 = 1, S4 = don't care.
    KeepC,
}

impl Compose {
    /// Decode (S3, S4).
    pub fn from_code(s3: bool, s4: bool) -> Compose {
        match (s3, s4) {
            (false, false) => Compose::Put1,
            (false, true) => Compose::PutF,
            (true, _) => Compose::KeepC,
        }
    }
}

/// A row's verdict: one action, or two when the thesis leaves a tie "up to the user".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Verdict<T> {
    /// The required outcome, and the second one allowed when the row is a tie.
    pub choices: (T, Option<T>),
    /// The thesis row that decides, as conditions `->` outcome.
    pub row: &'static str,
}

fn one<T>(a: T, row: &'static str) -> Verdict<T> {
    Verdict {
        choices: (a, None),
        row,
    }
}

fn tie<T>(a: T, b: T, row: &'static str) -> Verdict<T> {
    Verdict {
        choices: (a, Some(b)),
        row,
    }
}

/// Externals of a front or perpendicular plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrontExt {
    /// L: 1 for a concave object, 0 for a convex one.
    pub l: bool,
    /// S: 1 for the first front or perpendicular plane of the object (F holds no surface yet).
    pub s: bool,
    /// Y: 1 for a perpendicular plane (A holds K).
    pub y: bool,
}

/// §2.3.3, front/perpendicular plane: A (Z, or K when perpendicular) against F.
pub fn front(fmt: &WordFormat, e: FrontExt, a: i64, f: i64) -> Verdict<Action> {
    use Action::*;
    let md = fmt.maxdepth();
    match (e.s, e.y, e.l) {
        (true, true, _) if a < 0 => one(Put1, "S=1 Y=1: K < 0 -> Put 1"),
        (true, true, _) => one(Put0, "S=1 Y=1: K >= 0 -> Put 0"),
        (true, false, _) if a < 0 => one(Put0, "S=1 Y=0 H=1: Z < 0 -> Put 0"),
        (true, false, _) if a >= md => one(Put1, "S=1 Y=0 H=1: Z >= Maxdepth -> Put 1"),
        (true, false, _) => one(PutA, "S=1 Y=0 H=1: 0 <= Z < Maxdepth -> Put A"),
        (false, true, false) if a < 0 => one(Put1, "S=0 Y=1 L=0: K < 0 -> Put 1"),
        (false, true, false) => one(Keep, "S=0 Y=1 L=0: K >= 0 -> Keep F"),
        (false, true, true) if a < 0 => one(Keep, "S=0 Y=1 L=1: K < 0 -> Keep F"),
        (false, true, true) => one(Put0, "S=0 Y=1 L=1: K >= 0 -> Put 0"),
        (false, false, false) => front_convex(md, a, f),
        (false, false, true) => front_concave(md, a, f),
    }
}

fn front_convex(md: i64, a: i64, f: i64) -> Verdict<Action> {
    use Action::*;
    if a >= md {
        one(Put1, "S=0 Y=0 H=1 L=0: Maxdepth <= A -> Put 1")
    } else if a < 0 {
        one(Keep, "S=0 Y=0 H=1 L=0: A < 0 <= F -> Keep F")
    } else if a > f {
        one(PutA, "S=0 Y=0 H=1 L=0: F < A < Maxdepth -> Put A")
    } else if a < f {
        // Includes F = Put-1 word (no front surface left): the greater depth is F.
        one(Keep, "S=0 Y=0 H=1 L=0: 0 <= A < F -> Keep F")
    } else {
        tie(PutA, Keep, "S=0 Y=0 H=1 L=0: A = F -> Put A or F (user)")
    }
}

fn front_concave(md: i64, a: i64, f: i64) -> Verdict<Action> {
    use Action::*;
    if a >= md {
        one(Keep, "S=0 Y=0 H=1 L=1: Maxdepth <= A -> Keep F")
    } else if a < 0 {
        one(Put0, "S=0 Y=0 H=1 L=1: A < 0 <= F -> Put 0")
    } else if a > f {
        one(Keep, "S=0 Y=0 H=1 L=1: 0 <= F < A < Maxdepth -> Keep F")
    } else if a < f {
        one(PutA, "S=0 Y=0 H=1 L=1: 0 <= A < F -> Put A")
    } else {
        tie(PutA, Keep, "S=0 Y=0 H=1 L=1: A = F -> Put A or F (user)")
    }
}

/// Externals of a back plane (H = 0, Y = 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BackExt {
    /// L: 1 for a concave object, 0 for a convex one.
    pub l: bool,
    /// S: 1 for the first back plane of the object (B holds no surface yet).
    pub s: bool,
}

/// §2.3.3, back plane: A against B.
pub fn back(fmt: &WordFormat, e: BackExt, a: i64, b: i64) -> Verdict<Action> {
    use Action::*;
    let md = fmt.maxdepth();
    match (e.s, e.l) {
        (true, _) if a < 0 => one(Put1, "S=1 Y=0 H=0: Z < 0 -> Put 1"),
        (true, _) => one(PutA, "S=1 Y=0 H=0: Z >= 0 -> Put A"),
        (false, false) => back_convex(md, a, b),
        (false, true) => back_concave(md, a, b),
    }
}

fn back_convex(md: i64, a: i64, b: i64) -> Verdict<Action> {
    use Action::*;
    if a < 0 {
        one(Put1, "S=0 Y=0 H=0 L=0: A < 0 <= B -> Put 1")
    } else if a >= md {
        // Printed "B < Maxdepth <= A (M=1, N=0)"; the flags hold for any B.
        one(Keep, "S=0 Y=0 H=0 L=0: Maxdepth <= A (M=1 N=0) -> Keep B")
    } else if a == b {
        tie(
            Keep,
            PutA,
            "S=0 Y=0 H=0 L=0: A = B -> Keep B or Put A (user)",
        )
    } else if a < b {
        // Includes B >= Maxdepth (an overflowed first back plane): the smaller depth is A.
        one(PutA, "S=0 Y=0 H=0 L=0: 0 <= A < B -> Put A")
    } else {
        one(Keep, "S=0 Y=0 H=0 L=0: 0 <= B < A < Maxdepth -> Keep B")
    }
}

fn back_concave(md: i64, a: i64, b: i64) -> Verdict<Action> {
    use Action::*;
    if a < 0 {
        one(Keep, "S=0 Y=0 H=0 L=1: A < 0 <= B -> Keep B")
    } else if a >= md {
        // Printed "B < Maxdepth <= A (M=1, N=0)"; the flags hold for any B.
        one(Put1, "S=0 Y=0 H=0 L=1: Maxdepth <= A (M=1 N=0) -> Put 1")
    } else if a == b {
        tie(
            Keep,
            PutA,
            "S=0 Y=0 H=0 L=1: A = B -> Keep B or Put A (user)",
        )
    } else if a > b {
        one(PutA, "S=0 Y=0 H=0 L=1: 0 <= B < A < Maxdepth -> Put A")
    } else {
        // Includes B >= Maxdepth: the greater depth is B.
        one(Keep, "S=0 Y=0 H=0 L=1: 0 <= A < B -> Keep B")
    }
}

/// §2.3.3, "after processing all the planes of the object" (stage position 3): B on the A
/// side against F. Convex keeps F where F < B, concave where F > B; otherwise Put maxdepth.
pub fn close(l: bool, b: i64, f: i64) -> Verdict<Action> {
    use Action::*;
    match l {
        false if f < b => one(Keep, "convex: Z_F < Z_B -> Keep Z_F"),
        false => one(Put1, "convex: Z_F >= Z_B -> Put maxdepth"),
        true if f > b => one(Keep, "concave: Z_F > Z_B -> Keep Z_F"),
        true => one(Put1, "concave: Z_F <= Z_B -> Put maxdepth"),
    }
}

/// Externals of a clipping plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClipExt {
    /// H: 1 for a front-facing clipping plane, 0 for a back-facing one.
    pub h: bool,
    /// Y: 1 for a perpendicular clipping plane (A holds K).
    pub y: bool,
    /// X: at A = F, 0 if the surface is kept and 1 if not (so LL = X').
    pub x: bool,
}

/// §2.3.4, the partial inside/outside test LL of a clipping plane A against F.
///
/// At A = F the text defines "X=0 if the surface will be kept, and X=1 if not", so LL = X'
/// there (the tables print "LL=X"; see docs/select-logic.md).
pub fn clip(fmt: &WordFormat, e: ClipExt, a: i64, f: i64) -> Verdict<bool> {
    let md = fmt.maxdepth();
    match (e.y, e.h) {
        (true, _) if a < 0 => one(false, "Y=1: K < 0 -> LL=0"),
        (true, _) => one(true, "Y=1: K >= 0 -> LL=1"),
        (false, true) if a >= md => one(false, "Y=0 H=1: A > Maxdepth (M=1 N=0) -> LL=0"),
        (false, true) if a < 0 => one(true, "Y=0 H=1: A < 0 -> LL=1"),
        (false, true) if a > f => one(false, "Y=0 H=1: A > F -> LL=0"),
        (false, true) if a < f => one(true, "Y=0 H=1: A < F -> LL=1"),
        (false, false) if a < 0 => one(false, "Y=0 H=0: A < 0 -> LL=0"),
        (false, false) if a >= md => one(true, "Y=0 H=0: A > Maxdepth (M=1 N=0) -> LL=1"),
        (false, false) if a < f => one(false, "Y=0 H=0: A < F -> LL=0"),
        (false, false) if a > f => one(true, "Y=0 H=0: A > F -> LL=1"),
        (false, _) => one(!e.x, "Y=0: A = F -> LL=X' (X=0 keeps the surface)"),
    }
}

/// §2.3.5, second stage: F on the A side against C, with P.
pub fn second(p: bool, f: i64, c: i64) -> Verdict<Compose> {
    match p {
        true => one(Compose::Put1, "P=1 -> Put 1 (initialise C)"),
        false if f <= c => one(Compose::PutF, "P=0: F <= C -> Put F"),
        false => one(Compose::KeepC, "P=0: F > C -> Keep C"),
    }
}
