//! OFF meshes as OpenSCAD 2021.01 imports them (`import_off.cc`, `import_off`): the file is
//! read into a CGAL `Polyhedron_3` (CGAL's `File_header_OFF` and `File_scanner_OFF`), whose
//! facets become the polygons of one PolySet (`cgalutils-polyhedron.cc`,
//! `createPolySetFromPolyhedron`).
//!
//! Read here: the header keyword `[C][N][4][n]OFF` (colours, normals, homogeneous
//! coordinates, a dimension, which must be 3) or none (the file starts with the vertex count),
//! the counts (vertices, facets and, after a keyword, edges, which are ignored), each vertex's
//! `x y z` (`x y z w` for `4OFF`, divided by `w`) with the rest of its line (normals, colours)
//! skipped, and each facet's `n i1 … in` with the rest of its line (a colour) skipped. `#`
//! starts a comment up to the end of its line. Binary OFF (`OFF BINARY`) and `SKEL` files are
//! refused.
//!
//! Facets of any size become triangles as OpenSCAD tessellates them
//! ([`crate::facet::triangulate`]: a convex facet fanned from its first vertex, a concave one
//! ear-clipped in its plane, so that no triangle reaches outside the facet). A non-planar facet
//! has no single surface: csgpix and OpenSCAD's tessellation may bend it along different
//! diagonals.
//!
//! Where CGAL's polyhedron builder gives up (a vertex index out of range, a facet of fewer
//! than 3 vertices), OpenSCAD imports nothing; csgpix refuses with the place. A polyhedron
//! CGAL rejects as non-manifold but whose edges pair up is read (the parity rule does not need
//! a manifold); an open surface is refused by [`crate::trimesh::TriMesh::check_closed`] when voxelized.

use crate::meshfile::{Objects, Soup};
use crate::{Error, Result};

/// A word of the file and where it starts (1-based line and byte column).
#[derive(Clone, Copy)]
struct Word<'a> {
    text: &'a str,
    line: usize,
    col: usize,
}

/// The words of the file, comments dropped, with the line of each.
struct Words<'a> {
    words: std::iter::Peekable<std::vec::IntoIter<Word<'a>>>,
    file: &'a str,
    end: (usize, usize),
}

impl<'a> Words<'a> {
    fn new(text: &'a str, file: &'a str) -> Words<'a> {
        let mut words = vec![];
        let mut end = (1, 1);
        for (i, line) in text.split('\n').enumerate() {
            let line = line.split('#').next().unwrap_or_default();
            let mut rest = line;
            while let Some(start) = rest.find(|c: char| !c.is_ascii_whitespace()) {
                let tail = &rest[start..];
                let len = tail
                    .find(|c: char| c.is_ascii_whitespace())
                    .unwrap_or(tail.len());
                let col = line.len() - rest.len() + start + 1;
                words.push(Word {
                    text: &tail[..len],
                    line: i + 1,
                    col,
                });
                rest = &tail[len..];
            }
            end = (i + 1, line.len() + 1);
        }
        Words {
            words: words.into_iter().peekable(),
            file,
            end,
        }
    }

    fn next(&mut self, what: &str) -> Result<Word<'a>> {
        self.words.next().ok_or_else(|| {
            let (l, c) = self.end;
            let e = Error::Expected {
                expected: what.to_string(),
                found: "the end of the file".to_string(),
            };
            Error::at(self.file, l, c, e)
        })
    }

    fn error(&self, w: Word, problem: Error) -> Error {
        Error::at(self.file, w.line, w.col, problem)
    }

    /// `expected WHAT, found `WORD``, at the word.
    fn expected(&self, w: Word, what: impl Into<String>) -> Error {
        let found = format!("`{}`", w.text);
        let e = Error::Expected {
            expected: what.into(),
            found,
        };
        self.error(w, e)
    }

    /// A finite number and its line.
    fn number(&mut self, what: &str) -> Result<(f64, usize)> {
        let w = self.next(what)?;
        let v = w.text.parse::<f64>().ok().filter(|v| v.is_finite());
        let v = v.ok_or_else(|| self.expected(w, what))?;
        Ok((v, w.line))
    }

    fn count(&mut self, what: &str) -> Result<(usize, Word<'a>)> {
        let w = self.next(what)?;
        let n = w
            .text
            .parse::<usize>()
            .map_err(|_| self.expected(w, format!("{what} (a whole number)")))?;
        Ok((n, w))
    }

    /// Drops the rest of `line` (normals, colours).
    fn skip_line(&mut self, line: usize) {
        while self.words.next_if(|w| w.line == line).is_some() {}
    }
}

/// The header: whether counts include edges; homogeneous coordinates.
struct Header {
    edges: bool,
    homogeneous: bool,
}

/// Reads the keyword, if any, as CGAL's `operator>>(istream, File_header_OFF)` does.
fn header(w: &mut Words) -> Result<Header> {
    let first = *w
        .words
        .peek()
        .ok_or_else(|| Error::EmptyOff.context(w.file))?;
    let t = first.text.as_bytes();
    // CGAL: a keyword unless the word starts with a digit other than '4' or has a digit second.
    if t.len() < 2 || (t[0].is_ascii_digit() && t[0] != b'4') || t[1].is_ascii_digit() {
        return Ok(Header {
            edges: false,
            homogeneous: false,
        });
    }
    w.words.next();
    let mut rest = first.text;
    let mut flag = |c: char| match rest.strip_prefix(c) {
        Some(r) => {
            rest = r;
            true
        }
        None => false,
    };
    let (_colours, _normals, homogeneous, dimension) = (flag('C'), flag('N'), flag('4'), flag('n'));
    match rest {
        "OFF" => {}
        "SKEL" => return Err(w.error(first, Error::SkelFile)),
        _ => {
            let what = "an OFF header (`OFF`, `COFF`, `NOFF`, `4OFF`, …)";
            return Err(w.expected(first, what));
        }
    }
    if w.words.peek().is_some_and(|n| n.text == "BINARY") {
        let b = w.next("")?;
        return Err(w.error(b, Error::BinaryOff));
    }
    if dimension {
        let (d, at) = w.count("the dimension of an nOFF file")?;
        if d != 3 {
            return Err(w.error(at, Error::OffDimension { dimension: d }));
        }
    }
    Ok(Header {
        edges: true,
        homogeneous,
    })
}

/// Parses an OFF file: one object, its facets fanned into triangles.
pub(crate) fn parse(bytes: &[u8], file: &str) -> Result<Objects> {
    let text = crate::meshfile::utf8(bytes, file)?;
    let mut w = Words::new(text, file);
    let h = header(&mut w)?;
    let (nv, at) = w.count("the number of vertices")?;
    let (nf, _) = w.count("the number of facets")?;
    if h.edges {
        w.count("the number of edges")?;
    }
    if nv == 0 {
        return Err(w.error(at, Error::NoVertices));
    }
    // Each vertex and facet takes at least 6 bytes of text: no count past that is believed
    // when reserving memory.
    let room = bytes.len() / 6;
    let mut vs = Vec::with_capacity(nv.min(room));
    for _ in 0..nv {
        vs.push(vertex(&mut w, h.homogeneous)?);
    }
    let mut soup: Soup = Vec::with_capacity(nf.min(room));
    for k in 0..nf {
        facet(&mut w, k, &vs, &mut soup)?;
    }
    Ok(Objects {
        parts: vec![soup],
        warnings: vec![],
    })
}

fn vertex(w: &mut Words, homogeneous: bool) -> Result<[f64; 3]> {
    let mut p = [0.0; 3];
    let mut line = 0;
    for c in &mut p {
        (*c, line) = w.number("a vertex coordinate")?;
    }
    if homogeneous {
        let at = w.next("the homogeneous coordinate w")?;
        let h = at
            .text
            .parse::<f64>()
            .ok()
            .filter(|h| h.is_finite() && *h != 0.0);
        let h = h.ok_or_else(|| w.expected(at, "a nonzero w"))?;
        p = p.map(|c| c / h);
        if p.iter().any(|c| !c.is_finite()) {
            return Err(w.error(at, Error::InfiniteVertex));
        }
        line = at.line;
    }
    w.skip_line(line);
    Ok(p)
}

/// Facet `k`: `n i1 … in`, as triangles ([`crate::facet::triangulate`]).
fn facet(w: &mut Words, k: usize, vs: &[[f64; 3]], soup: &mut Soup) -> Result<()> {
    let (n, at) = w.count("the number of vertices of a facet")?;
    if n < 3 {
        let e = Error::FacetTooSmall {
            facet: k,
            vertices: n,
        };
        return Err(w.error(at, e));
    }
    let mut idx = Vec::with_capacity(n.min(vs.len()));
    let mut line = at.line;
    for _ in 0..n {
        let (i, iw) = w.count("a vertex index")?;
        if i >= vs.len() {
            let e = Error::FacetVertex {
                facet: k,
                vertex: i,
                count: vs.len(),
            };
            return Err(w.error(iw, e));
        }
        idx.push(i);
        line = iw.line;
    }
    w.skip_line(line);
    let corners: Vec<glam::DVec3> = idx.iter().map(|&i| glam::DVec3::from(vs[i])).collect();
    for t in crate::facet::triangulate(&corners) {
        soup.push(t.map(|j| vs[idx[j]]));
    }
    Ok(())
}

/// [`parse`] as one mesh (the objects of an OFF file are one).
#[cfg(test)]
fn mesh(bytes: &[u8]) -> Result<crate::trimesh::TriMesh> {
    let o = parse(bytes, "t.off")?;
    crate::meshfile::unite(o.parts, "t.off")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        let e = mesh(text.as_bytes()).unwrap_err().to_string();
        assert_eq!(e.lines().count(), 1, "{e}");
        e
    }

    const TETRA: &str =
        "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

    #[test]
    fn header_variants_and_comments() {
        let m = mesh(TETRA.as_bytes()).unwrap();
        assert_eq!((m.vertices.len(), m.triangles.len()), (4, 4));
        m.check_closed("t.off").unwrap();
        // Colours and normals after the coordinates, comments, a facet colour, no keyword.
        let coff = "# a comment\nCOFF # here too\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 1 2 3 4\n\
                    0 1 0 0 0 0 0\n0 0 1 0 0 0 0\n3 0 2 1 0.5 0.5 0.5\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
        assert_eq!(mesh(coff.as_bytes()).unwrap(), m);
        let bare = TETRA
            .strip_prefix("OFF\n")
            .unwrap()
            .replacen("4 4 6", "4 4", 1);
        assert_eq!(mesh(bare.as_bytes()).unwrap(), m);
        let homog = "4OFF\n4 4 0\n0 0 0 2\n2 0 0 2\n0 3 0 3\n0 0 0.5 0.5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
        assert_eq!(mesh(homog.as_bytes()).unwrap(), m);
        let dim = TETRA.replacen("OFF\n", "nOFF 3\n", 1);
        assert_eq!(mesh(dim.as_bytes()).unwrap(), m);
    }

    #[test]
    fn polygons_are_fanned() {
        // A unit cube of quads: 12 triangles.
        let cube = "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n\
                    4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
        let m = mesh(cube.as_bytes()).unwrap();
        assert_eq!((m.vertices.len(), m.triangles.len()), (8, 12));
        m.check_closed("c.off").unwrap();
    }

    #[test]
    fn malformed_files_are_one_line_at_their_place() {
        assert!(err("").contains("empty file"));
        assert!(err("PLY\n").starts_with("t.off:1:1: expected an OFF header"));
        assert!(err("SKEL\n1 0\n0 0 0\n").contains("SKEL"));
        assert!(err("OFF BINARY\n").starts_with("t.off:1:5: binary OFF"));
        assert!(err("nOFF 4\n").starts_with("t.off:1:6: an OFF file of dimension 4"));
        assert!(err("OFF\n4 x 0\n").starts_with("t.off:2:3: expected the number of facets"));
        assert!(err("OFF\n-4 4 0\n").starts_with("t.off:2:1:"));
        assert!(err("OFF\n0 0 0\n").contains("no vertices"));
        let e = err("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 nan\n");
        assert!(
            e.starts_with("t.off:6:5: expected a vertex coordinate"),
            "{e}"
        );
        let e = err(&TETRA.replacen("3 1 2 3", "3 1 2 4", 1));
        assert!(
            e.starts_with("t.off:10:7: facet 3 refers to vertex 4"),
            "{e}"
        );
        let e = err(&TETRA.replacen("3 1 2 3", "2 1 2", 1));
        assert!(e.starts_with("t.off:10:1: facet 3 has 2 vertices"), "{e}");
        let e = err(&TETRA[..TETRA.len() - 4]);
        assert!(
            e.starts_with("t.off:10:5: expected a vertex index, found the end"),
            "{e}"
        );
        assert!(err("4OFF\n1 0 0\n0 0 0 0\n").contains("nonzero w"));
        let e = mesh(b"OFF\n1 0 0\n0 0 \xff").unwrap_err().to_string();
        assert!(e.starts_with("t.off:3:5: not UTF-8"), "{e}");
    }

    #[test]
    fn huge_counts_do_not_reserve_memory() {
        let e = err("OFF\n4000000000000 4000000000000 0\n0 0 0\n");
        assert!(
            e.starts_with("t.off:4:1: expected a vertex coordinate, found the end"),
            "{e}"
        );
    }
}
