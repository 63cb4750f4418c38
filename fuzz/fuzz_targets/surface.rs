//! surface() files: a `.dat` grid or a PNG image from bytes, at most 2^20 mesh vertices; the
//! mesh made of what is read stays within that budget.
#![no_main]
use libfuzzer_sys::fuzz_target;

use csgpix::openscad::surface;

fuzz_target!(|bytes: &[u8]| {
    let budget = 1 << 20;
    match surface::read_from(
        std::io::Cursor::new(bytes),
        "f",
        bytes.last().is_some_and(|b| b & 1 == 1),
        budget,
    ) {
        Err(e) => {
            let e = e.to_string();
            assert!(!e.contains('\n'), "two lines: {e}");
        }
        Ok(s) => {
            for w in &s.warnings {
                assert!(!w.contains('\n') && !w.contains('\r'), "two lines: {w}");
            }
            let tris = surface::mesh(&s.heights, true);
            assert!(tris.len() * 3 <= budget);
        }
    }
});
