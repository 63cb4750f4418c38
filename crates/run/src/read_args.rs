//! How every command that reads a scene reads it: `--openscad-timeout` (the time limit of
//! every openscad run: a `.scad` file's export to CSG, `--fallback openscad`'s meshes) and
//! `--strict` (OpenSCAD's warnings as refusals); and the one place a scene's warnings are
//! printed.

use std::time::Duration;

/// `--openscad-timeout` and `--strict`, flattened into each command that reads scenes.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct ReadArgs {
    /// Seconds each openscad run may take (a `.scad` file's export, a `--fallback openscad`
    /// mesh) before it is killed and the command fails (exit 2); 0 for no limit. Without a
    /// limit a `.scad` that keeps openscad busy would hold the command for as long.
    #[arg(long = "openscad-timeout", value_name = "SECONDS",
          default_value_t = csgpix_openscad::DEFAULT_OPENSCAD_TIMEOUT.as_secs())]
    pub seconds: u64,
    /// Refuse the scene at its first warning (exit 2, nothing written) instead of doing what
    /// OpenSCAD does and going on: a colour out of range, a singular transform, an import of
    /// a missing file, a child of the other dimension, a font substituted, an open mesh, …
    /// (docs/volume-scenes.md lists them).
    #[arg(long)]
    pub strict: bool,
}

impl ReadArgs {
    /// The limit: None for 0.
    pub fn limit(self) -> Option<Duration> {
        (self.seconds > 0).then(|| Duration::from_secs(self.seconds))
    }

    /// The reader's options with this limit and strictness, the others their defaults.
    pub fn read_options(self) -> csgpix_openscad::ReadOptions {
        csgpix_openscad::ReadOptions {
            openscad_timeout: self.limit(),
            strict: self.strict,
            ..Default::default()
        }
    }
}

/// Prints a scene's warnings on stderr, one line each, as `csgpix: warning: FILE:LINE:COL:
/// message` (the run goes on; `--json` lists the same lines without the prefix).
pub fn print_warnings<W: std::fmt::Display>(warnings: &[W]) {
    for w in warnings {
        eprintln!("csgpix: warning: {}", csgpix_scene::OneLine(w.to_string()));
    }
}
