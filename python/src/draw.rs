//! Drawing on the array (seed 001 Ch. 2, §5.2): `compile` a scene to the array's program,
//! `render` it to a numpy image of colour codes, `palette` them, and `verify_select` the
//! select logic against the golden vectors (§2.3.3).

use std::path::PathBuf;

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use csgpix_draw::project::View;
use csgpix_draw::scenes::Scene;
use csgpix_draw::Model;
use rtl_model::program::Op;
use rtl_model::{ArrayConfig, Equations};

use crate::errors::{run, text};
use crate::voxel::word_format;
use csgpix_run::array_args::array_config;
use csgpix_run::named::parse;
use csgpix_run::progress::Quiet;
use csgpix_run::verify_select::VerifySelectJob;

/// The array's program for a scene, and the configuration it was compiled for.
#[pyclass(module = "csgpix._native", frozen)]
pub struct Program {
    pub ops: Vec<Op>,
    pub cfg: ArrayConfig,
    /// The scene as loaded (kept for the float reference).
    pub scene: Scene,
}

#[pymethods]
impl Program {
    /// Operations of the program (planes, closes, clip planes, composes, ...).
    fn __len__(&self) -> usize {
        self.ops.len()
    }

    /// The array's width and height in pixels.
    #[getter]
    fn size(&self) -> (usize, usize) {
        (self.cfg.width, self.cfg.height)
    }

    /// Clipping-stack levels the program needs.
    #[getter]
    fn stack_levels(&self) -> PyResult<usize> {
        rtl_model::array::check_program(&self.ops, usize::MAX).map_err(|e| text(e.to_string()))
    }

    /// Clocks the program takes on the array with `equations` (`derived` or `printed`),
    /// DEPGEN's fill and the flush window included.
    #[pyo3(signature = (equations="derived"))]
    fn cycles(&self, equations: &str) -> PyResult<u64> {
        equation_set(equations)?; // checked; the clocks do not depend on it
        Ok(rtl_model::array::program_cycles(&self.cfg, &self.ops))
    }

    /// One line per operation, as the models print them.
    fn ops(&self) -> Vec<String> {
        self.ops.iter().map(|o| format!("{o:?}")).collect()
    }

    fn __repr__(&self) -> String {
        format!(
            "Program({} ops on a {}x{} array)",
            self.ops.len(),
            self.cfg.width,
            self.cfg.height
        )
    }
}

/// `derived` or `printed` select equations (§2.3.3), as `--equations`.
fn equations_arg(name: &str) -> PyResult<Equations> {
    parse::<Equations>(name).map_err(|e| text(e.to_string()))
}

/// The set of [`equations_arg`] `name`.
pub fn equation_set(name: &str) -> PyResult<rtl_model::EquationSet> {
    Ok(equations_arg(name)?.set())
}

fn view(name: &str) -> PyResult<View> {
    parse::<View>(name).map_err(|e| text(e.to_string()))
}

/// The scene's paths: one path or a list of them.
fn paths(scene: &Bound<'_, PyAny>) -> PyResult<Vec<PathBuf>> {
    if let Ok(p) = scene.extract::<PathBuf>() {
        return Ok(vec![p]);
    }
    scene
        .extract::<Vec<PathBuf>>()
        .map_err(|_| text("scene: a path or a list of paths".into()))
}

/// Compile display lists (`.dl`, composed, or clipped by `clip` over objects A, B, … in
/// order) or one `.csg`/`.scad` scene (projected along `view`) for a `width`×`height` array;
/// each openscad run a `.scad` needs killed after `openscad_timeout` seconds (None or 0: no
/// limit).
#[pyfunction]
#[pyo3(signature = (scene, width=250, height=250, *, clip=None, view="iso", word="10/10/11",
                    openscad_timeout=crate::voxel::DEFAULT_TIMEOUT))]
pub fn compile(
    scene: &Bound<'_, PyAny>,
    width: usize,
    height: usize,
    clip: Option<&str>,
    view: &str,
    word: &str,
    openscad_timeout: Option<f64>,
) -> PyResult<Program> {
    let options = csgpix_openscad::ReadOptions {
        openscad_timeout: crate::voxel::timeout(openscad_timeout)?,
        ..Default::default()
    };
    // The model's default stack, deepened below to the levels the program reaches.
    let stack = ArrayConfig::new(width, height).stack_depth;
    let mut cfg = array_config((width, height), word_format(word)?, stack).map_err(run)?;
    let (scene, ops) =
        csgpix_run::render::compile_with(&paths(scene)?, clip, self::view(view)?, &cfg, &options)
            .map_err(run)?;
    let levels =
        rtl_model::array::check_program(&ops, usize::MAX).map_err(|e| text(e.to_string()))?;
    cfg.stack_depth = cfg.stack_depth.max(levels);
    Ok(Program { ops, cfg, scene })
}

/// Run `program` on a model (`cycle`, `word` or the `float` reference) and return the image:
/// every pixel's colour code (G), shape (height, width), uint8, and the clocks taken.
#[pyfunction]
#[pyo3(signature = (program, model="cycle", equations="derived"))]
pub fn render<'py>(
    py: Python<'py>,
    program: &Program,
    model: &str,
    equations: &str,
) -> PyResult<(Bound<'py, PyAny>, u64)> {
    let model = model.parse::<Model>().map_err(|e| text(e.to_string()))?;
    let set = equation_set(equations)?;
    let (p, cfg) = (program, program.cfg);
    let drawn = py
        .detach(|| csgpix_run::render::draw(&p.scene, &p.ops, &cfg, model, set, &Quiet))
        .map_err(run)?;
    let codes = drawn.colour.iter().map(|&c| c as u8).collect();
    let cycles = drawn.cycles;
    let img = PyArray1::from_vec(py, codes).reshape([cfg.height, cfg.width])?;
    Ok((img.into_any(), cycles))
}

/// The palette's RGB of every colour code, shape (256, 3), uint8: `palette()[image]` is
/// the picture the command line writes.
#[pyfunction]
pub fn palette(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    let rgb: Vec<u8> = (0..256u32).flat_map(csgpix_draw::palette::rgb).collect();
    Ok(PyArray1::from_vec(py, rgb).reshape([256, 3])?.into_any())
}

/// Check the select equations (`derived` or `printed`) on every care row of the golden
/// vectors (§2.3.3) — the built-in ones, or the `.pla` files of directory `vectors`. One
/// dict per signal: `signal`, `rows`, `mismatches` (dicts of `inputs`, `expected`, `got`,
/// `case`: the rows where the equation disagrees).
#[pyfunction]
#[pyo3(signature = (equations="derived", vectors=None))]
pub fn verify_select<'py>(
    py: Python<'py>,
    equations: &str,
    vectors: Option<PathBuf>,
) -> PyResult<Vec<Bound<'py, PyDict>>> {
    let job = VerifySelectJob {
        equations: equations_arg(equations)?,
        vectors,
    };
    let reports = job.run(&Quiet).map_err(run)?.signals;
    let mut out = vec![];
    {
        for r in reports {
            let d = PyDict::new(py);
            d.set_item("signal", &r.signal)?;
            d.set_item("rows", r.rows)?;
            let rows = r
                .mismatches
                .iter()
                .map(|m| {
                    let row = PyDict::new(py);
                    row.set_item("inputs", &m.inputs)?;
                    row.set_item("expected", m.expected)?;
                    row.set_item("got", m.got)?;
                    row.set_item("case", &m.case)?;
                    Ok(row)
                })
                .collect::<PyResult<Vec<_>>>()?;
            d.set_item("mismatches", rows)?;
            out.push(d);
        }
    }
    Ok(out)
}
