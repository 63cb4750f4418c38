//! `csgpix._native`: the library behind the `csgpix` Python package (python/csgpix). Thin
//! wrappers over the workspace's crates; the Python side (`csgpix/__init__.py`) adds the
//! `Volume` and `Image` types and the distributed engine.

use pyo3::prelude::*;

mod array;
mod draw;
mod errors;
mod voxel;
mod zarr;

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("CsgpixError", m.py().get_type::<errors::CsgpixError>())?;
    m.add_class::<voxel::Scene>()?;
    m.add_function(wrap_pyfunction!(voxel::load, m)?)?;
    m.add_function(wrap_pyfunction!(voxel::load_expr, m)?)?;
    m.add_function(wrap_pyfunction!(voxel::voxelize, m)?)?;
    m.add_function(wrap_pyfunction!(voxel::mesh, m)?)?;
    m.add_class::<draw::Program>()?;
    m.add_function(wrap_pyfunction!(draw::compile, m)?)?;
    m.add_function(wrap_pyfunction!(draw::render, m)?)?;
    m.add_function(wrap_pyfunction!(draw::palette, m)?)?;
    m.add_function(wrap_pyfunction!(draw::verify_select, m)?)?;
    m.add_function(wrap_pyfunction!(zarr::zarr_create, m)?)?;
    m.add_function(wrap_pyfunction!(zarr::zarr_write_rows, m)?)?;
    array::register(m)?;
    Ok(())
}
