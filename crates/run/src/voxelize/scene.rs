//! The job's input: a `.csg` (or `.scad`) scene and its imports, or a CSG expression over
//! bound files (docs/volume-scenes.md), read within the memory limit; the reader's warnings
//! go to the job's progress.

use csgpix_voxel::sampled::{load_scene_with, scene_from_expr_with, Loaded};

use super::VoxelizeJob;
use crate::lib_errors::voxel as voxel_error;
use crate::progress::{warn_all, Progress};
use crate::Error;

impl VoxelizeJob {
    /// Read the input; a scene file's warnings are told to `progress`.
    pub fn load(&self, progress: &dyn Progress) -> crate::Result<Loaded> {
        let samples = self.max_memory.samples();
        match (&self.scene, &self.expr) {
            (Some(p), _) => {
                // The scene's vertices count against the memory limit too.
                let max_vertices =
                    csgpix_openscad::ReadOptions::max_vertices_for(self.max_memory.bytes());
                let options = csgpix_openscad::ReadOptions {
                    fallback: self.fallback,
                    max_vertices: Some(max_vertices),
                    samples,
                    ..self.read.read_options()
                };
                let loaded = load_scene_with(p, &options).map_err(voxel_error)?;
                warn_all(progress, &loaded.scene.warnings);
                Ok(loaded)
            }
            (None, Some(e)) => {
                let options = csgpix_openscad::ReadOptions {
                    samples,
                    ..self.read.read_options()
                };
                scene_from_expr_with(e, &self.prim, &options).map_err(voxel_error)
            }
            (None, None) => Err(Error::options("--expr", "give a scene file or --expr")),
        }
    }
}
