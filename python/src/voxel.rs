//! Scenes and voxelization (seed 001 Ch. 3-4): `load`, `load_expr`, and `voxelize` over the
//! whole grid or a slab range, into a numpy array indexed `[k, j, i]` (z, y, x).

use std::path::PathBuf;

use glam::DVec3;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;

use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::Mutex;

use csgpix_run::array_args::parse_word;
use csgpix_run::grid::{GridOptions, Resolution};
use csgpix_run::memory::Limit;
use csgpix_run::progress::Progress;
use csgpix_run::voxelize::{parse_blend, Voxelization, VoxelizeJob};
use csgpix_voxel::sampled::{load_scene_with, scene_from_expr_with, Binding, Loaded};
use csgpix_voxel::Grid;
use rtl_model::WordFormat;

use crate::errors::{text, voxel};

/// A scene ready to voxelize: a `.csg`/`.scad` file and its imports, or a CSG expression
/// over named files.
#[pyclass(module = "csgpix._native", frozen)]
pub struct Scene {
    pub loaded: Loaded,
    /// How messages name the scene.
    #[pyo3(get)]
    pub name: String,
    /// Where it was loaded from: how a pickled scene is loaded again (in a worker process
    /// of a distributed run, csgpix.distributed).
    source: Source,
}

/// A scene's source.
#[derive(Clone)]
enum Source {
    /// The file, openscad's time limit in seconds and `strict`, as `load` was given them.
    File(PathBuf, Option<f64>, bool),
    Expr(String, Vec<(String, PathBuf, Option<f64>)>),
}

#[pymethods]
impl Scene {
    /// Primitives: convex solids, then imports (datasets and meshes).
    #[getter]
    fn primitives(&self) -> usize {
        self.loaded.scene.primitive_count()
    }

    /// The box around every primitive, `((x0, y0, z0), (x1, y1, z1))` in scene units.
    #[getter]
    fn bounds(&self) -> PyResult<([f64; 3], [f64; 3])> {
        let (lo, hi) = self.loaded.bounds().map_err(voxel)?;
        Ok((lo.to_array(), hi.to_array()))
    }

    /// What the reader warned of, as OpenSCAD warns and goes on (a colour out of range, a
    /// child of the other dimension, a substituted font, …): `FILE:LINE:COL: message` each,
    /// also raised as `warnings.warn` by `load`.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.loaded
            .scene
            .warnings
            .iter()
            .map(|w| w.to_string())
            .collect()
    }

    /// Pickled as its source: unpickling loads the files again (they must be readable where
    /// it is unpickled, as on the workers of a distributed run sharing a file system).
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
        let m = py.import("csgpix._native")?;
        Ok(match &self.source {
            Source::File(p, t, strict) => (
                m.getattr("load")?,
                (p.clone(), *t, *strict).into_pyobject(py)?.into_any(),
            ),
            Source::Expr(e, prims) => {
                let prims: Vec<(String, Bound<'py, PyAny>)> = prims
                    .iter()
                    .map(|(n, f, t)| {
                        let v = match t {
                            Some(t) => (f.clone(), *t).into_pyobject(py)?.into_any(),
                            None => f.clone().into_pyobject(py)?.into_any(),
                        };
                        Ok((n.clone(), v))
                    })
                    .collect::<PyResult<_>>()?;
                (
                    m.getattr("load_expr")?,
                    (e.clone(), prims).into_pyobject(py)?.into_any(),
                )
            }
        })
    }

    fn __repr__(&self) -> String {
        format!(
            "Scene({:?}, primitives={})",
            self.name,
            self.loaded.scene.primitive_count()
        )
    }
}

/// Read a `.csg` scene (or a `.scad` one through OpenSCAD, each openscad run killed after
/// `openscad_timeout` seconds; None or 0: no limit) and the files it imports. Each warning
/// (where OpenSCAD warns and goes on, so does csgpix) is raised with `warnings.warn`;
/// `strict=True` refuses the scene at its first warning instead (the command line's
/// `--strict`).
#[pyfunction]
#[pyo3(signature = (path, openscad_timeout = DEFAULT_TIMEOUT, strict = false))]
pub fn load(
    py: Python<'_>,
    path: PathBuf,
    openscad_timeout: Option<f64>,
    strict: bool,
) -> PyResult<Scene> {
    let options = csgpix_openscad::ReadOptions {
        openscad_timeout: timeout(openscad_timeout)?,
        strict,
        ..read_options()
    };
    let loaded = load_scene_with(&path, &options).map_err(voxel)?;
    warn_all(py, &loaded.scene.warnings)?;
    Ok(Scene {
        loaded,
        name: path.display().to_string(),
        source: Source::File(path, openscad_timeout, strict),
    })
}

/// Each of a scene's warnings as a Python `UserWarning` (`warnings.warn`), so that
/// `warnings.simplefilter("error")` turns them into exceptions as `strict=True` does.
fn warn_all(py: Python<'_>, warnings: &[csgpix_scene::Error]) -> PyResult<()> {
    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
    for w in warnings {
        let msg = std::ffi::CString::new(w.to_string().replace('\0', " "))?;
        PyErr::warn(py, &category, &msg, 1)?;
    }
    Ok(())
}

/// `openscad_timeout`'s default: the command line's (`--openscad-timeout`).
pub const DEFAULT_TIMEOUT: Option<f64> =
    Some(csgpix_openscad::DEFAULT_OPENSCAD_TIMEOUT.as_secs() as f64);

/// `openscad_timeout` seconds as a limit: None for None or 0; refused when negative or not
/// a number.
pub fn timeout(seconds: Option<f64>) -> PyResult<Option<std::time::Duration>> {
    match seconds {
        None => Ok(None),
        Some(0.0) => Ok(None),
        Some(s) => std::time::Duration::try_from_secs_f64(s)
            .map(Some)
            .map_err(|_| {
                text(format!(
                    "openscad_timeout={s}: seconds, a number >= 0 (0 or None: no limit)"
                ))
            }),
    }
}

/// A scene from a CSG expression (`+` union, `.` intersection, `-` difference, `!`
/// complement) over names, each bound to a file: a `.csg` scene, a closed `.stl`/`.obj` mesh,
/// or a `.nrrd` dataset given as `(path, threshold)`.
#[pyfunction]
pub fn load_expr(expr: &str, prims: Vec<(String, Bound<'_, PyAny>)>) -> PyResult<Scene> {
    let bindings = prims
        .into_iter()
        .map(|(name, v)| binding(name, &v))
        .collect::<PyResult<Vec<_>>>()?;
    let loaded = scene_from_expr_with(expr, &bindings, &read_options()).map_err(voxel)?;
    let prims = bindings
        .iter()
        .map(|b| (b.name.clone(), b.file.clone(), b.threshold))
        .collect();
    Ok(Scene {
        loaded,
        name: format!("--expr {expr:?}"),
        source: Source::Expr(expr.to_string(), prims),
    })
}

/// The readers' options: NRRD datasets are refused by their header's `sizes` when their
/// samples would not fit in the memory available now, before their data is read (as the
/// command line's `--max-memory` does).
fn read_options() -> csgpix_openscad::ReadOptions {
    let limit = Limit::new(None, "the memory available (MemAvailable)");
    csgpix_openscad::ReadOptions {
        samples: limit.samples(),
        ..Default::default()
    }
}

fn binding(name: String, v: &Bound<'_, PyAny>) -> PyResult<Binding> {
    let (file, threshold) = match v.extract::<(PathBuf, f64)>() {
        Ok((f, t)) => (f, Some(t)),
        Err(_) => (
            v.extract::<PathBuf>().map_err(|_| {
                text(format!(
                    "primitive `{name}`: bind it to a path, or to (path, threshold) for a dataset"
                ))
            })?,
            None,
        ),
    };
    Ok(Binding {
        name,
        file,
        threshold,
    })
}

/// The grid options of a voxelization as given: `res` N or (NX, NY, NZ), or `voxel`, one of
/// them; `pad` and `bounds` as `--pad` and `--bounds`.
pub fn grid_options(
    res: Option<&Bound<'_, PyAny>>,
    voxel: Option<f64>,
    pad: usize,
    bounds: Option<([f64; 3], [f64; 3])>,
) -> PyResult<GridOptions> {
    let res = resolution(res)?;
    if res.is_some() == voxel.is_some() {
        return Err(text("give res or voxel (one of them)".into()));
    }
    Ok(GridOptions {
        res,
        voxel,
        pad,
        bounds,
        ..GridOptions::default()
    })
}

/// `res` as N (cubic voxels, N along the longest side, as `--res N`) or (NX, NY, NZ).
fn resolution(res: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Resolution>> {
    let Some(r) = res else { return Ok(None) };
    if let Ok(n) = r.extract::<usize>() {
        return Ok(Some(Resolution::Longest(n)));
    }
    r.extract::<[usize; 3]>()
        .map(|dims| Some(Resolution::Axes(dims)))
        .map_err(|_| text("res: an int N or a tuple (NX, NY, NZ)".into()))
}

/// A keyword argument's value by its flag's parser: the command line's names and forms.
fn parsed<T: std::str::FromStr>(s: &str) -> PyResult<T>
where
    T::Err: std::fmt::Display,
{
    s.parse().map_err(|e: T::Err| text(e.to_string()))
}

/// The keyword arguments that decide a run's voxels beside its grid, spelled as the command
/// line's flags' values.
pub struct Options<'a> {
    pub sampling: &'a str,
    pub model: &'a str,
    pub route: &'a str,
    pub eval: &'a str,
    pub grey: bool,
    pub blend: Option<&'a str>,
    pub word: &'a str,
}

impl Options<'_> {
    /// The job of voxelizing `scene` on `grid` with these options (the command line's
    /// defaults for the rest: derived equations, 32×32 panels), within `max_memory` MiB (by
    /// default the memory available now, docs/memory.md).
    pub fn job(
        &self,
        scene: &Scene,
        mut grid: GridOptions,
        max_memory: Option<u64>,
    ) -> PyResult<VoxelizeJob> {
        let blend = match self.blend {
            None => None,
            Some(b) => Some(parse_blend(b).map_err(|e| text(format!("blend {b:?}: {e}")))?),
        };
        if self.grey && blend.is_some() {
            return Err(text("grey and blend: give one".into()));
        }
        let word = word_format(self.word)?;
        grid.sampling = csgpix_run::named::parse(self.sampling).map_err(|e| text(e.to_string()))?;
        let voxels = Voxelization {
            model: parsed(self.model)?,
            route: parsed(self.route)?,
            eval: parsed(self.eval)?,
            word,
            grey: self.grey,
            blend,
            ..Voxelization::default()
        };
        let (scene_path, expr, prim) = scene.input();
        Ok(VoxelizeJob {
            scene: scene_path,
            expr,
            prim,
            grid,
            voxels,
            max_memory: Limit::new(max_memory, "max_memory"),
            ..VoxelizeJob::default()
        })
    }
}

impl Scene {
    /// The job's input: the scene's file, or its expression and bindings.
    fn input(&self) -> (Option<PathBuf>, Option<String>, Vec<Binding>) {
        match &self.source {
            Source::File(p, _, _) => (Some(p.clone()), None, vec![]),
            Source::Expr(e, prims) => {
                let prims = prims.iter().map(|(name, file, threshold)| Binding {
                    name: name.clone(),
                    file: file.clone(),
                    threshold: *threshold,
                });
                (None, Some(e.clone()), prims.collect())
            }
        }
    }
}

/// A depth word `FRACTION/INTEGER/OVERFLOW`, e.g. `10/10/11` (§2.3.1), as `--word`.
pub fn word_format(s: &str) -> PyResult<WordFormat> {
    parse_word(s).map_err(|e| text(format!("word {s:?}: {e}")))
}

/// Voxelize `scene` (seed 001 §4.4): uint8 colour codes, 0 empty, as a numpy array of shape
/// (k1 − k0, NY, NX), with the grid's origin (centre of voxel (0, 0, 0)), spacing and dims.
/// `progress`: called as `progress(done, total)` as the slices are computed.
#[pyfunction]
#[pyo3(signature = (scene, res=None, *, voxel=None, pad=0, bounds=None, sampling="centre",
    model="word", route="runs", eval="blist", grey=false, blend=None, word="10/10/11",
    z=None, max_memory=None, progress=None))]
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
pub fn voxelize<'py>(
    py: Python<'py>,
    scene: &Scene,
    res: Option<&Bound<'py, PyAny>>,
    voxel: Option<f64>,
    pad: usize,
    bounds: Option<([f64; 3], [f64; 3])>,
    sampling: &str,
    model: &str,
    route: &str,
    eval: &str,
    grey: bool,
    blend: Option<&str>,
    word: &str,
    z: Option<(usize, usize)>,
    max_memory: Option<u64>,
    progress: Option<Py<PyAny>>,
) -> PyResult<(Bound<'py, PyAny>, [f64; 3], [f64; 3], [usize; 3])> {
    let grid = grid_options(res, voxel, pad, bounds)?;
    let options = Options {
        sampling,
        model,
        route,
        eval,
        grey,
        blend,
        word,
    };
    let job = options.job(scene, grid, max_memory)?;
    let sink = Callback::new(progress);
    let slabs = py.detach(|| job.slabs(&scene.loaded, z, &sink));
    sink.raise()?;
    let (bytes, grid) = slabs.map_err(crate::errors::run)?;
    let [nx, ny, _] = grid.dims;
    let n = bytes.len() / (nx * ny).max(1);
    let arr = PyArray1::from_vec(py, bytes).reshape([n, ny, nx])?;
    Ok((
        arr.into_any(),
        grid.centre(0, 0, 0).to_array(),
        grid.voxel().to_array(),
        grid.dims,
    ))
}

/// A job's progress handed to a Python callable as `progress(done, total)` (tqdm-friendly:
/// `lambda done, total: bar.update(done - bar.n)`), the GIL taken for each call. The first
/// exception it raises is kept and raised once the job is over.
pub struct Callback {
    f: Option<Py<PyAny>>,
    done: AtomicU64,
    total: AtomicU64,
    raised: Mutex<Option<PyErr>>,
}

impl Callback {
    /// The sink of `f`, or one that shows nothing.
    pub fn new(f: Option<Py<PyAny>>) -> Callback {
        Callback {
            f,
            done: AtomicU64::new(0),
            total: AtomicU64::new(0),
            raised: Mutex::new(None),
        }
    }

    fn call(&self) {
        let Some(f) = &self.f else { return };
        let mut raised = self.raised.lock().unwrap_or_else(|e| e.into_inner());
        if raised.is_some() {
            return;
        }
        let (done, total) = (self.done.load(Relaxed), self.total.load(Relaxed));
        if let Err(e) = Python::attach(|py| f.call1(py, (done, total)).map(drop)) {
            *raised = Some(e);
        }
    }

    /// The callback's first exception, if it raised one.
    pub fn raise(&self) -> PyResult<()> {
        let raised = self.raised.lock().unwrap_or_else(|e| e.into_inner()).take();
        raised.map_or(Ok(()), Err)
    }
}

impl Progress for Callback {
    fn stage(&self, _: &str, total: u64) {
        self.done.store(0, Relaxed);
        self.total.store(total, Relaxed);
        self.call();
    }

    fn advance(&self, n: u64) {
        self.done.fetch_add(n, Relaxed);
        self.call();
    }
}

/// The surface of a volume (`data[k, j, i]`, uint8, 0 empty) on its grid (`origin` the centre
/// of voxel (0, 0, 0), `spacing` the voxel's size, both x, y, z) as `csgpix voxelize --mesh`
/// makes it: global Marching Cubes over the optimized octree, closed and wound outward, in
/// scene units. Returns the welded vertices (float32, shape (V, 3)) and faces (uint32, shape
/// (F, 3)), a trimesh-compatible pair.
#[pyfunction]
#[pyo3(signature = (data, origin, spacing, *, max_memory=None))]
#[allow(clippy::type_complexity)]
pub fn mesh<'py>(
    py: Python<'py>,
    data: numpy::PyReadonlyArray3<'py, u8>,
    origin: [f64; 3],
    spacing: [f64; 3],
    max_memory: Option<u64>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let array = data.as_array();
    let &[nz, ny, nx] = array.shape() else {
        return Err(text("data: a 3-dimensional array, [k, j, i]".into()));
    };
    let dims = [nx, ny, nz];
    let (o, s) = (DVec3::from_array(origin), DVec3::from_array(spacing));
    let grid = Grid::new(
        dims,
        o - s / 2.0,
        o - s / 2.0 + s * DVec3::new(nx as f64, ny as f64, nz as f64),
    )
    .map_err(crate::errors::scene)?;
    let voxels = array.iter().copied().collect();
    let volume = csgpix_voxel::Volume { dims, voxels };
    let limit = Limit::new(max_memory, "max_memory");
    let (tris, _) = py
        .detach(|| csgpix_run::voxelize::mesh(&grid, &volume, limit.bytes()))
        .map_err(crate::errors::run)?;
    let (vertices, faces) = csgpix_scene::mesh::indexed(&tris);
    let (nv, nf) = (vertices.len(), faces.len());
    let v = PyArray1::from_vec(py, vertices.into_iter().flatten().collect()).reshape([nv, 3])?;
    let f = PyArray1::from_vec(py, faces.into_iter().flatten().collect()).reshape([nf, 3])?;
    Ok((v.into_any(), f.into_any()))
}
