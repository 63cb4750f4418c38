//! Triangle meshes out: binary STL, OBJ and binary PLY, each written whole or not at all
//! ([`csgpix_output::write_atomic`]). OBJ and PLY share vertices (equal coordinates are one
//! vertex), so a closed surface stays closed in the file; STL has no vertex sharing.

use std::collections::HashMap;
use std::io::Write;
use std::path::Path;

use crate::{Error, Result};
use csgpix_output::write_atomic;

/// A triangle: three vertices, counter-clockwise seen from outside.
pub type Tri = [[f32; 3]; 3];

/// Mesh file formats, chosen by the output's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Binary STL (`.stl`).
    Stl,
    /// Wavefront OBJ (`.obj`).
    Obj,
    /// Binary PLY (`.ply`).
    Ply,
}

impl Format {
    /// The format of `path` from its extension (`.stl`, `.obj`, `.ply`, any case).
    pub fn of_path(path: &Path) -> Result<Format> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("stl") => Ok(Format::Stl),
            Some("obj") => Ok(Format::Obj),
            Some("ply") => Ok(Format::Ply),
            _ => Err(Error::MeshWriteExtension.context(path.display())),
        }
    }
}

/// Writes `tris` to `path` in the format of its extension, atomically.
pub fn write(path: &Path, tris: &[Tri], comment: &str) -> Result<()> {
    let f = Format::of_path(path)?;
    Ok(write_atomic(path, |w| write_format(w, f, tris, comment))?)
}

/// Writes `tris` into `w` in format `f`.
pub fn write_format(
    w: &mut dyn Write,
    f: Format,
    tris: &[Tri],
    comment: &str,
) -> std::io::Result<()> {
    match f {
        Format::Stl => write_stl(w, tris, comment),
        Format::Obj => write_obj(w, tris, comment),
        Format::Ply => write_ply(w, tris, comment),
    }
}

/// The extensions [`Format::of_path`] knows.
pub const EXTENSIONS: [&str; 3] = ["stl", "obj", "ply"];

/// Unit normal of a counter-clockwise triangle (zero for a degenerate one).
pub fn normal(t: &Tri) -> [f32; 3] {
    let u = [t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]];
    let v = [t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]];
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if l > 0.0 {
        n.map(|c| c / l)
    } else {
        [0.0; 3]
    }
}

/// Binary STL: 80-byte header, triangle count, then per triangle normal, 3 vertices and a
/// zero attribute word, little-endian.
pub fn write_stl(w: &mut dyn Write, tris: &[Tri], comment: &str) -> std::io::Result<()> {
    let mut head = [b' '; 80];
    let c = comment.as_bytes();
    let n = c.len().min(80);
    head[..n].copy_from_slice(&c[..n]);
    // An STL header must not start with "solid" (that marks ASCII STL).
    if head.starts_with(b"solid") {
        head[0] = b'S';
    }
    w.write_all(&head)?;
    let count = u32::try_from(tris.len()).map_err(std::io::Error::other)?;
    w.write_all(&count.to_le_bytes())?;
    for t in tris {
        for c in normal(t).iter().chain(t.iter().flatten()) {
            w.write_all(&c.to_le_bytes())?;
        }
        w.write_all(&[0, 0])?;
    }
    Ok(())
}

/// Shared vertices and faces as indices: equal coordinates (bit for bit) are one vertex.
pub fn indexed(tris: &[Tri]) -> (Vec<[f32; 3]>, Vec<[u32; 3]>) {
    let mut at: HashMap<[u32; 3], u32> = HashMap::with_capacity(tris.len());
    let mut verts = Vec::with_capacity(tris.len() / 2 + 3);
    let faces = tris
        .iter()
        .map(|t| {
            t.map(|p| {
                *at.entry(p.map(f32::to_bits)).or_insert_with(|| {
                    verts.push(p);
                    (verts.len() - 1) as u32
                })
            })
        })
        .collect();
    (verts, faces)
}

/// Wavefront OBJ: `v x y z` lines, then `f a b c` (1-based).
pub fn write_obj(w: &mut dyn Write, tris: &[Tri], comment: &str) -> std::io::Result<()> {
    let (verts, faces) = indexed(tris);
    for line in comment.lines() {
        writeln!(w, "# {line}")?;
    }
    for v in &verts {
        writeln!(w, "v {} {} {}", v[0], v[1], v[2])?;
    }
    for f in &faces {
        writeln!(w, "f {} {} {}", f[0] + 1, f[1] + 1, f[2] + 1)?;
    }
    Ok(())
}

/// Binary little-endian PLY: float vertices, faces as a uchar count and three int indices.
pub fn write_ply(w: &mut dyn Write, tris: &[Tri], comment: &str) -> std::io::Result<()> {
    let (verts, faces) = indexed(tris);
    let mut h = String::from("ply\nformat binary_little_endian 1.0\n");
    for line in comment.lines() {
        h += &format!("comment {line}\n");
    }
    h += &format!(
        "element vertex {}\nproperty float x\nproperty float y\nproperty float z\n",
        verts.len()
    );
    h += &format!(
        "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        faces.len()
    );
    w.write_all(h.as_bytes())?;
    for c in verts.iter().flatten() {
        w.write_all(&c.to_le_bytes())?;
    }
    for f in &faces {
        w.write_all(&[3])?;
        for i in f {
            w.write_all(&(*i as i32).to_le_bytes())?;
        }
    }
    Ok(())
}

/// Edges used by other than exactly two triangles (0 for a closed surface), counting each
/// undirected edge between vertices that are equal bit for bit.
pub fn open_edges(tris: &[Tri]) -> usize {
    let (_, faces) = indexed(tris);
    let mut uses: HashMap<(u32, u32), u32> = HashMap::with_capacity(faces.len() * 3 / 2);
    for f in &faces {
        for i in 0..3 {
            let (a, b) = (f[i], f[(i + 1) % 3]);
            *uses.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    uses.values().filter(|&&n| n != 2).count()
}
