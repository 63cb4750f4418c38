//! STUB (replaced by the trimesh branch).
use glam::{DMat4, DVec3};
use std::path::Path;
pub struct TriMesh {
    pub vertices: Vec<DVec3>,
    pub triangles: Vec<[u32; 3]>,
}
impl TriMesh {
    pub fn read(_p: &Path) -> Result<TriMesh, String> {
        Err("stub".into())
    }
    pub fn bounds(&self) -> (DVec3, DVec3) {
        (DVec3::ZERO, DVec3::ONE)
    }
    pub fn transformed(&self, _m: DMat4) -> TriMesh {
        TriMesh {
            vertices: vec![],
            triangles: vec![],
        }
    }
    pub fn check_closed(&self, _f: &str) -> Result<(), String> {
        Ok(())
    }
    pub fn crossings(&self, _t: impl Fn(DVec3) -> DVec3, w: usize, h: usize) -> Vec<Vec<f64>> {
        vec![vec![]; w * h]
    }
}
