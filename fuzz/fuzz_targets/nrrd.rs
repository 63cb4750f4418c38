//! NRRD volumes: header and data (raw or gzip) from bytes, at most 2^20 samples.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let dir = std::path::Path::new("/nonexistent-csgpix-fuzz");
    if let Err(e) = csgpix::scene::nrrd::parse_nrrd_limited(bytes, "f.nrrd", Some(dir), csgpix::scene::nrrd::SampleLimit { samples: 1 << 20, source: "" })
        .map_err(|e| e.to_string())
    {
        assert!(!e.contains('\n'), "two lines: {e}");
    }
});
