//! `.scad` files through `openscad`.

use csgpix_scene::Error;

/// The `.csg` text of a scene file: a `.csg` file as it is; a `.scad` file exported to CSG by
/// OpenSCAD (`openscad -o scene.csg FILE.scad` into a temporary directory, removed after),
/// when `openscad` is on PATH. Errors are one line naming the file.
pub fn scene_text(path: &std::path::Path) -> csgpix_scene::Result<String> {
    let name = path.display();
    let scad = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("scad"));
    if !scad {
        return csgpix_scene::input::read_text(path);
    }
    if !path.is_file() {
        return Err(Error::msg(format!("{name}: no such file")));
    }
    let dir = tempfile::tempdir()
        .map_err(|e| Error::msg(format!("{name}: a temporary directory: {e}")))?;
    let out = dir.path().join("scene.csg");
    let run = std::process::Command::new("openscad")
        .arg("-o")
        .arg(&out)
        .arg(path)
        .stdin(std::process::Stdio::null())
        .output();
    let run = match run {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(Error::msg(format!(
                "{name}: reading .scad needs openscad on PATH (Debian: apt-get install openscad); \
                 or export File → Export → Export as CSG and give the .csg"
            )))
        }
        Err(e) => return Err(Error::msg(format!("{name}: running openscad: {e}"))),
        Ok(run) => run,
    };
    let text = std::fs::read_to_string(&out)
        .ok()
        .filter(|_| run.status.success());
    text.ok_or_else(|| {
        let stderr = String::from_utf8_lossy(&run.stderr);
        let line = stderr
            .lines()
            .find(|l| l.contains("ERROR"))
            .or_else(|| stderr.lines().rfind(|l| !l.trim().is_empty()))
            .unwrap_or("no output");
        Error::msg(format!(
            "{name}: openscad could not export it: {}",
            line.trim()
        ))
    })
}
