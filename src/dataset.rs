//! STUB (replaced by the dataset branch).
use glam::DVec3;
use std::path::Path;
pub struct Nrrd {
    pub sizes: [usize; 3],
}
pub fn read_nrrd(_p: &Path) -> Result<Nrrd, String> {
    Err("stub".into())
}
pub struct Dataset {
    pub nrrd: Nrrd,
}
impl Dataset {
    pub fn new(nrrd: Nrrd) -> Result<Dataset, String> {
        Ok(Dataset { nrrd })
    }
    pub fn sample(&self, _p: DVec3) -> Option<f64> {
        None
    }
    pub fn bounds(&self) -> (DVec3, DVec3) {
        (DVec3::ZERO, DVec3::ONE)
    }
    pub fn grey(&self, _v: f64) -> u8 {
        1
    }
}
