//! `csgpix.CsgpixError`: every error of the library as one Python exception, its message the
//! one line the command line prints, with `file`, `line` and `col` set from the error's place
//! in an input (None otherwise). A file the system could not read or write raises the
//! matching `OSError` subclass instead.

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

/// The exception for a file the system could not read or write: the `OSError` subclass of
/// its kind (`FileNotFoundError`, `PermissionError`, `IsADirectoryError`, else `OSError`),
/// its message the one line the command line prints.
fn os_error(kind: std::io::ErrorKind, message: String) -> PyErr {
    use pyo3::exceptions::{
        PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyPermissionError,
    };
    use std::io::ErrorKind;
    match kind {
        ErrorKind::NotFound => PyFileNotFoundError::new_err(message),
        ErrorKind::PermissionDenied => PyPermissionError::new_err(message),
        ErrorKind::IsADirectory => PyIsADirectoryError::new_err(message),
        _ => PyOSError::new_err(message),
    }
}

/// The place of a located error, as the exception's attributes.
fn place(at: Option<&csgpix_scene::Location>) -> Option<Place> {
    at.map(|l| Place {
        file: l.file.clone(),
        line: l.line,
        col: l.col,
    })
}

/// An error of the scene crate: its place and the system's kind of failure are in the error.
pub fn scene(e: csgpix_scene::Error) -> PyErr {
    match e.io_kind() {
        Some(kind) => os_error(kind, e.to_string()),
        None => error(message(&e, e.to_string()), place(e.location())),
    }
}

/// The line of an error that is or wraps `scene`: openscad stopped at its time limit names
/// the keyword that sets it, as the command line names its option.
fn message(scene: &csgpix_scene::Error, line: String) -> String {
    match scene.kind() {
        csgpix_scene::Kind::TimedOut => format!("{line} (openscad_timeout=)"),
        _ => line,
    }
}

/// An error known only by its text (the binding's own checks): no place.
pub fn text(message: String) -> PyErr {
    error(message, None)
}

/// A drawing error, kept whole where it wraps a scene error.
pub fn draw(e: csgpix_draw::Error) -> PyErr {
    match e {
        csgpix_draw::Error::Scene(e) => scene(e),
        e => {
            let at = place(e.location());
            error(e.to_string(), at)
        }
    }
}

/// A voxelizer's error, kept whole where it wraps a scene error.
pub fn voxel(e: csgpix_voxel::Error) -> PyErr {
    match e {
        csgpix_voxel::Error::Scene(e) => scene(e),
        csgpix_voxel::Error::Draw(e) => draw(e),
        e @ csgpix_voxel::Error::Binding {
            problem: csgpix_voxel::BindingProblem::NoSuchFile { .. },
            ..
        } => os_error(std::io::ErrorKind::NotFound, e.to_string()),
        e => {
            let at = place(e.location());
            error(e.to_string(), at)
        }
    }
}

/// A Zarr store's error, kept whole where it wraps a voxelizer's.
pub fn zarr(e: csgpix_zarr::Error) -> PyErr {
    match e {
        csgpix_zarr::Error::Voxel(e) => voxel(e),
        e => text(e.to_string()),
    }
}

/// An error of the run layer: the libraries' errors as above; a scene error wrapped in
/// context keeps its place, and a file the system refused (an input or an output) raises its
/// `OSError`.
pub fn run(e: csgpix_run::Error) -> PyErr {
    use csgpix_run::Error as R;
    match e {
        R::Scene(e) => scene(e),
        R::Voxel(e) => voxel(e),
        R::Draw(e) => draw(e),
        R::Zarr(e) => zarr(e),
        e => match (e.io_kind(), e.scene()) {
            (Some(kind), _) => os_error(kind, e.to_string()),
            (None, Some(s)) => error(message(s, e.to_string()), place(s.location())),
            (None, None) => text(e.to_string()),
        },
    }
}
