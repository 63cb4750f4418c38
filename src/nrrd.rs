//! NRRD volumes (format version 4): a text header and raw `uint8` voxels, placed in space
//! with `space origin` (the centre of the first voxel) and `space directions` (one voxel step
//! per axis), so ParaView and 3D Slicer show the volume exactly on the scene.

use std::path::Path;

use crate::output::write_atomic;
use crate::voxelize::Grid;

/// The header for `grid`: axis 0 is X (fastest), 1 is Y, 2 is Z, in scene units.
pub fn header(grid: &Grid, comment: &str) -> String {
    let [nx, ny, nz] = grid.dims;
    let v = grid.voxel();
    let o = grid.centre(0, 0, 0);
    let mut h = String::from("NRRD0004\n");
    for line in comment.lines() {
        h += &format!("# {line}\n");
    }
    h += "type: uint8\n";
    h += "dimension: 3\n";
    h += "space: right-anterior-superior\n";
    h += &format!("sizes: {nx} {ny} {nz}\n");
    h += &format!(
        "space directions: ({},0,0) (0,{},0) (0,0,{})\n",
        v.x, v.y, v.z
    );
    h += "kinds: domain domain domain\n";
    h += "encoding: raw\n";
    h += &format!("space origin: ({},{},{})\n", o.x, o.y, o.z);
    h += "\n";
    h
}

/// Write the volume (X fastest, then Y, then Z) whole or not at all.
pub fn write(path: &Path, grid: &Grid, voxels: &[u8], comment: &str) -> Result<(), String> {
    let head = header(grid, comment);
    write_atomic(path, |w| {
        w.write_all(head.as_bytes())?;
        w.write_all(voxels)
    })
}

/// Read back a volume this module wrote: the sizes and the voxels (for tests and tools).
pub fn read(bytes: &[u8]) -> Result<([usize; 3], Vec<u8>), String> {
    let split = bytes
        .windows(2)
        .position(|w| w == b"\n\n")
        .ok_or("no blank line after the NRRD header")?;
    let head = std::str::from_utf8(&bytes[..split]).map_err(|e| e.to_string())?;
    if !head.starts_with("NRRD000") {
        return Err("not a NRRD file".into());
    }
    let sizes = head
        .lines()
        .find_map(|l| l.strip_prefix("sizes: "))
        .ok_or("no sizes field")?;
    let dims: Vec<usize> = sizes
        .split_whitespace()
        .map(|s| s.parse().map_err(|e| format!("sizes: {e}")))
        .collect::<Result<_, String>>()?;
    let [nx, ny, nz] = dims[..] else {
        return Err(format!("sizes: expected 3, found {}", dims.len()));
    };
    let data = bytes[split + 2..].to_vec();
    if data.len() != nx * ny * nz {
        return Err(format!("{} data bytes for {nx}x{ny}x{nz}", data.len()));
    }
    Ok(([nx, ny, nz], data))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn header_places_voxel_centres() {
        let g = Grid::new(
            [2, 3, 4],
            DVec3::new(-1.0, 0.0, 2.0),
            DVec3::new(1.0, 3.0, 6.0),
        )
        .unwrap();
        let h = header(&g, "test");
        assert!(h.contains("sizes: 2 3 4\n"), "{h}");
        assert!(
            h.contains("space directions: (1,0,0) (0,1,0) (0,0,1)\n"),
            "{h}"
        );
        assert!(h.contains("space origin: (-0.5,0.5,2.5)\n"), "{h}");
        assert!(h.starts_with("NRRD0004\n# test\n") && h.ends_with("\n\n"));
    }

    #[test]
    fn round_trip() {
        let g = Grid::new([2, 2, 2], DVec3::ZERO, DVec3::ONE).unwrap();
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("v.nrrd");
        let v: Vec<u8> = (0..8).collect();
        write(&p, &g, &v, "x").unwrap();
        let (dims, data) = read(&std::fs::read(&p).unwrap()).unwrap();
        assert_eq!((dims, data), ([2, 2, 2], v));
    }
}
