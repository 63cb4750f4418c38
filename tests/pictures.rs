//! Every picture of README.md and docs/ is current: `docs/img/make.sh --check` regenerates
//! each one with this build's `csgpix` and compares it byte for byte with docs/img (the
//! pictures that depend on timing are listed as UNCHECKED in the script and not compared).
//! On failure, `bash docs/img/make.sh` (after `cargo build --release`) rewrites them.
//! `extrusions.png` needs `openscad`, skipped without it unless `CSGPIX_OPENSCAD=require`.

use std::process::Command;

#[test]
fn every_picture_in_docs_img_is_current() {
    let root = env!("CARGO_MANIFEST_DIR");
    let out = Command::new("bash")
        .arg("docs/img/make.sh")
        .arg("--check")
        .current_dir(root)
        .env("CSGPIX", env!("CARGO_BIN_EXE_csgpix"))
        .output()
        .expect("run bash docs/img/make.sh --check");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    println!("{stdout}{stderr}");
    assert!(
        out.status.success(),
        "docs/img/make.sh --check failed ({}); regenerate with `bash docs/img/make.sh`:\n{stdout}{stderr}",
        out.status
    );
}
