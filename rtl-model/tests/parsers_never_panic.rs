//! The select-logic file readers on arbitrary text: a value or an error, never a panic, and
//! errors point inside the text.

use proptest::prelude::*;
use rtl_model::select::pla::Pla;
use rtl_model::select::{EquationSet, GOLDEN};

fn mutate(base: &str, edits: &[(usize, char)]) -> String {
    let mut chars: Vec<char> = base.chars().collect();
    for &(at, c) in edits {
        if !chars.is_empty() {
            let i = at % chars.len();
            chars[i] = c;
        }
    }
    chars.into_iter().collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn pla_reader(text in "\\PC{0,200}", edits in prop::collection::vec((any::<usize>(), any::<char>()), 0..8)) {
        for t in [text.clone(), mutate(GOLDEN[1].1, &edits)] {
            if let Err(e) = Pla::parse(&t) {
                prop_assert!(e.line >= 1 && e.line <= t.lines().count() + 1, "{e}");
            }
        }
    }

    #[test]
    fn equation_reader(text in "[a-zA-Z.'+= \\n#01]{0,120}", edits in prop::collection::vec((any::<usize>(), any::<char>()), 0..8)) {
        let derived = rtl_model::select::DERIVED_TEXT;
        for t in [text.clone(), mutate(derived, &edits)] {
            if let Err(e) = EquationSet::parse("t", &t) {
                prop_assert!(e.line <= t.lines().count() + 1, "{e}");
            }
        }
    }
}
