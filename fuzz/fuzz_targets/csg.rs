//! OpenSCAD `.csg` scenes: the text parser (never `openscad` itself).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let Ok(text) = csgpix::scene::input::text(bytes.to_vec(), "f.csg") else {
        return;
    };
    if let Err(e) = csgpix::openscad::parse_csg(&text, "f.csg") {
        let e = e.to_string();
        assert!(!e.contains('\n'), "two lines: {e}");
    }
});
