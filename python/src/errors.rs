//! `csgpix.CsgpixError`: every error of the library as one Python exception, its message the
//! one line the command line prints, with `file`, `line` and `col` set where the error has a
//! place in an input (None otherwise).

use pyo3::prelude::*;

pyo3::create_exception!(
    _native,
    CsgpixError,
    pyo3::exceptions::PyValueError,
    "A csgpix error: `str(e)` is the one-line message (`FILE:LINE:COL: ...` where the \
     problem has a place in a file); `e.file`, `e.line` and `e.col` give that place, or None."
);

/// Where an error points, if anywhere.
pub struct Place {
    pub file: String,
    pub line: usize,
    pub col: usize,
}

/// The exception for `message`, with its place.
pub fn error(message: String, place: Option<Place>) -> PyErr {
    Python::attach(|py| {
        let err = CsgpixError::new_err(message);
        let value = err.value(py);
        let r = match place {
            Some(p) => value
                .setattr("file", p.file)
                .and(value.setattr("line", p.line))
                .and(value.setattr("col", p.col)),
            None => value
                .setattr("file", py.None())
                .and(value.setattr("line", py.None()))
                .and(value.setattr("col", py.None())),
        };
        match r {
            Ok(()) => err,
            Err(e) => e,
        }
    })
}

/// An error of the scene crate: its place is in the error.
pub fn scene(e: csgpix_scene::Error) -> PyErr {
    let place = e.location().map(|l| Place {
        file: l.file.clone(),
        line: l.line,
        col: l.col,
    });
    error(e.to_string(), place)
}

/// An error known only by its text: a `FILE:LINE:COL: ` prefix, when there is one, is its
/// place (the form every csgpix message with a place has).
pub fn text(message: String) -> PyErr {
    let place = parse_place(&message);
    error(message, place)
}

fn parse_place(m: &str) -> Option<Place> {
    let head = m.split(": ").next()?;
    let mut parts = head.rsplitn(3, ':');
    let col = parts.next()?.parse().ok()?;
    let line = parts.next()?.parse().ok()?;
    let file = parts.next()?.to_string();
    Some(Place { file, line, col })
}

/// A voxelizer's error, kept whole where it wraps a scene error.
pub fn voxel(e: csgpix_voxel::Error) -> PyErr {
    match e {
        csgpix_voxel::Error::Scene(e) => scene(e),
        e => text(e.to_string()),
    }
}

/// A scene that could not be loaded for drawing.
pub fn load(e: csgpix_draw::scenes::LoadError) -> PyErr {
    use csgpix_draw::scenes::LoadError;
    match e {
        LoadError::Scene(e) => scene(e),
        e => text(e.to_string()),
    }
}
