//! STL meshes, ASCII and binary.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    if let Err(e) = csgpix::trimesh::TriMesh::parse(bytes, "f.stl", false) {
        assert!(!e.contains('\n'), "two lines: {e}");
    }
});
