//! DXF drawings (`import("x.dxf")`): the group-code reader, the joining of segments, the fill.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    if let Err(e) = csgpix::openscad::read_dxf(bytes, "f.dxf", 1_000) {
        let e = e.to_string();
        assert!(!e.contains('\n'), "two lines: {e}");
    }
});
