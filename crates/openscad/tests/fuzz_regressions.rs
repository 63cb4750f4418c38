//! Inputs the fuzzers found (fuzz/regressions/TARGET/*), each through the same checks as its
//! fuzz target (fuzz/fuzz_targets): the parser returns, and an error is one line.

use std::path::Path;

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

/// The parser's error for `bytes` as fuzz target `target` runs it, if any.
fn error_of(target: &str, bytes: &[u8]) -> Option<String> {
    match target {
        "csg" => {
            let text = csgpix_scene::input::text(bytes.to_vec(), "f.csg").ok()?;
            csgpix_openscad::parse_csg(&text, "f.csg")
                .err()
                .map(|e| e.to_string())
        }
        "display_list" => match csgpix_scene::input::text(bytes.to_vec(), "f.dl") {
            Ok(text) => csgpix_scene::display_list::DisplayList::parse(&text, "f.dl")
                .err()
                .map(|e| e.to_string()),
            Err(e) => Some(e.to_string()),
        },
        "nrrd" => {
            let dir = Path::new("/nonexistent-csgpix-fuzz");
            csgpix_scene::nrrd::parse_nrrd_limited(
                bytes,
                "f.nrrd",
                Some(dir),
                csgpix_scene::nrrd::SampleLimit {
                    samples: 1 << 20,
                    source: "",
                },
            )
            .err()
            .map(|e| e.to_string())
        }
        "stl" => csgpix_scene::trimesh::TriMesh::parse(bytes, "f.stl", false)
            .err()
            .map(|e| e.to_string()),
        "obj" => csgpix_scene::trimesh::TriMesh::parse(bytes, "f.obj", true)
            .err()
            .map(|e| e.to_string()),
        "amf" | "threemf" | "off" => {
            let format = if target == "threemf" { "3mf" } else { target };
            let name = format!("f.{format}");
            match csgpix_scene::trimesh::TriMesh::parse_format(bytes, &name, format) {
                Err(e) => Some(e.to_string()),
                Ok((_, warnings)) => warnings
                    .into_iter()
                    .map(|w| w.to_string())
                    .find(|w| w.contains('\n')),
            }
        }
        "surface" => {
            let invert = bytes.last().is_some_and(|b| b & 1 == 1);
            let read = csgpix_openscad::surface::read_from(
                std::io::Cursor::new(bytes),
                "f",
                invert,
                1 << 20,
            );
            match read {
                Err(e) => Some(e.to_string()),
                Ok(s) => s.warnings.into_iter().find(|w| w.contains('\n')),
            }
        }
        "fonts" => {
            use csgpix_openscad::text::{render_in, Fonts, TextSpec};
            let fonts = Fonts::of_data(bytes.to_vec());
            let family = fonts.families().into_iter().next()?;
            let id = fonts.find(&family).ok()?;
            let mut spec = TextSpec::new("Ag fi 1.5", 10.0);
            spec.font = family;
            render_in(&spec, &fonts, id, 200_000)
                .err()
                .map(|e| e.to_string())
        }
        "svg" => {
            let text = std::str::from_utf8(bytes).ok()?;
            csgpix_openscad::read_svg(text, "f.svg", 200_000)
                .err()
                .map(|e| e.to_string())
        }
        other => panic!("no checks for fuzz target {other}"),
    }
}

#[test]
fn every_input_the_fuzzers_found_gets_a_one_line_answer() {
    let root = Path::new(ROOT).join("fuzz/regressions");
    let mut seen = 0;
    for target in std::fs::read_dir(&root).unwrap() {
        let target = target.unwrap().path();
        let name = target.file_name().unwrap().to_string_lossy().into_owned();
        for input in std::fs::read_dir(&target).unwrap() {
            let input = input.unwrap().path();
            let bytes = std::fs::read(&input).unwrap();
            if let Some(e) = error_of(&name, &bytes) {
                assert!(!e.contains('\n'), "{}: two lines: {e}", input.display());
            }
            seen += 1;
        }
    }
    assert!(seen > 0, "no regression inputs under {}", root.display());
}

#[test]
fn a_file_name_with_line_breaks_is_quoted_on_one_line() {
    let e = csgpix_openscad::parse_csg("import(file = \"a\nb.dxf\");\n", "t.csg").unwrap_err();
    let e = e.to_string();
    assert!(!e.contains('\n'), "{e}");
    assert!(e.contains("a\\nb.dxf"), "{e}");
}
