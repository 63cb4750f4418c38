//! SVG drawings (`import("x.svg")`): the nesting check, roxmltree, the element walk, paths,
//! transforms and strokes, the fill.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let Ok(text) = std::str::from_utf8(bytes) else {
        return;
    };
    if let Err(e) = csgpix::openscad::read_svg(text, "f.svg", 200_000) {
        let e = e.to_string();
        assert!(!e.contains('\n'), "two lines: {e}");
    }
});
