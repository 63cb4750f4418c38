//! 3MF meshes (crates/scene/src/threemf.rs), united as OpenSCAD 2021.01 imports them.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let read = csgpix::scene::trimesh::TriMesh::parse_format(bytes, "f.3mf", "3mf");
    match read {
        Err(e) => {
            let e = e.to_string();
            assert!(!e.contains('\n'), "two lines: {e}");
        }
        Ok((_, warnings)) => {
            for w in warnings {
                let w = w.to_string();
                assert!(!w.contains('\n'), "two lines: {w}");
            }
        }
    }
});
