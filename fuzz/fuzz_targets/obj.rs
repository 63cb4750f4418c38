//! OBJ meshes.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    if let Err(e) = csgpix::scene::trimesh::TriMesh::parse(bytes, "f.obj", true).map_err(|e| e.to_string())
    {
        assert!(!e.contains('\n'), "two lines: {e}");
    }
});
