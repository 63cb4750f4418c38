//! `--openscad-timeout`: the time limit of every openscad run of a command that reads
//! `.scad` files (their export to CSG, and `--fallback openscad`'s meshes).

use std::time::Duration;

/// `--openscad-timeout`, flattened into each command that may run openscad.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct OpenscadTimeout {
    /// Seconds each openscad run may take (a `.scad` file's export, a `--fallback openscad`
    /// mesh) before it is killed and the command fails (exit 2); 0 for no limit. Without a
    /// limit a `.scad` that keeps openscad busy would hold the command for as long.
    #[arg(long = "openscad-timeout", value_name = "SECONDS",
          default_value_t = csgpix_openscad::DEFAULT_OPENSCAD_TIMEOUT.as_secs())]
    pub seconds: u64,
}

impl OpenscadTimeout {
    /// The limit: None for 0.
    pub fn limit(self) -> Option<Duration> {
        (self.seconds > 0).then(|| Duration::from_secs(self.seconds))
    }

    /// The reader's options with this limit, the others their defaults.
    pub fn read_options(self) -> csgpix_openscad::ReadOptions {
        csgpix_openscad::ReadOptions {
            openscad_timeout: self.limit(),
            ..Default::default()
        }
    }
}
