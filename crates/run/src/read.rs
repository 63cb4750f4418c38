//! How every job that reads a scene reads it, as data: openscad's time limit (a `.scad`
//! file's export to CSG, `--fallback openscad`'s meshes) and strictness (OpenSCAD's
//! warnings as refusals), and when a straight extrusion is read as a footprint; the command
//! line's `--openscad-timeout`, `--strict` and `--footprints`.

use std::time::Duration;

use serde::{Deserialize, Serialize};

/// The reading settings of a job. `Default` is the documented defaults: openscad's
/// default time limit, not strict.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct ReadSettings {
    /// Seconds each openscad run may take before it is killed and the job fails; 0 for no
    /// limit.
    pub openscad_timeout: u64,
    /// Refuse the scene at its first warning instead of going on as OpenSCAD does.
    pub strict: bool,
    /// A straight extrusion of more outline points than this is voxelized from its 2D tree
    /// (a footprint, `csgpix_scene::footprint`); None keeps every extrusion as prisms and
    /// meshes. The commands that draw on the array always keep prisms.
    pub footprints: Option<usize>,
    /// Also read as a footprint every straight extrusion with a shape that is not convex,
    /// whatever its points (`csgpix_openscad::ReadOptions::concave_footprints`). A print
    /// always reads so ([`ReadSettings::printing`], whatever its job file says); for a
    /// voxelize job it is a choice (false by default: it changes label codes).
    pub concave_footprints: bool,
}

impl Default for ReadSettings {
    fn default() -> Self {
        ReadSettings {
            openscad_timeout: csgpix_openscad::DEFAULT_OPENSCAD_TIMEOUT.as_secs(),
            strict: false,
            footprints: Some(csgpix_openscad::DEFAULT_FOOTPRINT_POINTS),
            concave_footprints: false,
        }
    }
}

impl ReadSettings {
    /// The time limit: None for 0.
    pub fn limit(self) -> Option<Duration> {
        (self.openscad_timeout > 0).then(|| Duration::from_secs(self.openscad_timeout))
    }

    /// These settings for a print: every straight extrusion with a concave shape is a
    /// footprint, as fast as its outline's edges where a mesh's triangles cost more (a
    /// layer holds no colour codes, so the shapes sharing one changes nothing printed).
    pub fn printing(self) -> ReadSettings {
        ReadSettings {
            concave_footprints: true,
            ..self
        }
    }

    /// The reader's options with this limit and strictness, the others their defaults.
    pub fn read_options(self) -> csgpix_openscad::ReadOptions {
        csgpix_openscad::ReadOptions {
            openscad_timeout: self.limit(),
            strict: self.strict,
            footprints: self.footprints,
            concave_footprints: self.concave_footprints,
            ..Default::default()
        }
    }
}
