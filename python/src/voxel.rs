//! Scenes and voxelization (seed 001 Ch. 3-4): `load`, `load_expr`, and `voxelize` over the
//! whole grid or a slab range, into a numpy array indexed `[k, j, i]` (z, y, x).

use std::path::PathBuf;

use glam::DVec3;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;

use csgpix_draw::Model;
use csgpix_voxel::blend::{BlendEval, Union};
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::evaluate::{StackEval, TreeEval};
use csgpix_voxel::sampled::{load_scene, scene_from_expr, Binding, Loaded};
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{voxelize_slabs, Grid, GridSpec, Route, Sampling, Slicer, SlicerOptions};
use rtl_model::{Equations, WordFormat};

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
    File(PathBuf),
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

    /// Pickled as its source: unpickling loads the files again (they must be readable where
    /// it is unpickled, as on the workers of a distributed run sharing a file system).
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
        let m = py.import("csgpix._native")?;
        Ok(match &self.source {
            Source::File(p) => (
                m.getattr("load")?,
                (p.clone(),).into_pyobject(py)?.into_any(),
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

/// Read a `.csg` scene (or a `.scad` one through OpenSCAD) and the files it imports.
#[pyfunction]
pub fn load(path: PathBuf) -> PyResult<Scene> {
    limit_readers();
    let loaded = load_scene(&path).map_err(voxel)?;
    Ok(Scene {
        loaded,
        name: path.display().to_string(),
        source: Source::File(path),
    })
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
    limit_readers();
    let loaded = scene_from_expr(expr, &bindings).map_err(voxel)?;
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

/// NRRD datasets are refused by their header's `sizes` when their samples would not fit in
/// the memory available now, before their data is read (as the command line's
/// `--max-memory` does).
fn limit_readers() {
    let bytes = csgpix_scene::memory::default_mib() << 20;
    csgpix_scene::nrrd::limit_samples_to_memory(bytes, "the memory available (MemAvailable)");
}

/// Refuse a run whose estimate `need` (bytes) is over `max_memory` MiB, by default the memory
/// available now (docs/memory.md), before anything is allocated.
pub fn check_memory(need: u64, max_memory: Option<u64>) -> PyResult<()> {
    use csgpix_scene::memory::{default_mib, MAX_MIB};
    let mib = max_memory.unwrap_or_else(default_mib).clamp(1, MAX_MIB);
    if need <= mib << 20 {
        return Ok(());
    }
    Err(text(format!(
        "this run needs about {} MiB, over max_memory {mib}: lower res (or z, or chunk) \
         or raise max_memory",
        need.div_ceil(1 << 20)
    )))
}

/// Bytes the imports of `scene` hold on `grid` (datasets' samples, meshes' runs).
pub fn imports_bytes(scene: &Scene, grid: &Grid) -> u64 {
    let each = scene.loaded.sampled.iter().map(|s| s.memory_estimate(grid));
    each.fold(0, u64::saturating_add)
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

/// The grid and sampling options of a voxelization.
pub struct GridOptions {
    pub res: Option<[usize; 3]>,
    pub voxel: Option<f64>,
    pub pad: usize,
    pub bounds: Option<([f64; 3], [f64; 3])>,
}

impl GridOptions {
    /// The options as given: `res` N or (NX, NY, NZ), or `voxel`, one of them.
    pub fn new(
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
        })
    }

    pub fn grid(&self, scene: &Scene) -> PyResult<Grid> {
        let spec = GridSpec {
            res: self.res,
            voxel: self.voxel,
            pad: self.pad,
        };
        let bounds = self
            .bounds
            .map(|(a, b)| (DVec3::from_array(a), DVec3::from_array(b)));
        scene.loaded.grid_over(&spec, bounds).map_err(voxel)
    }
}

/// `res` as N or (NX, NY, NZ).
fn resolution(res: Option<&Bound<'_, PyAny>>) -> PyResult<Option<[usize; 3]>> {
    let Some(r) = res else { return Ok(None) };
    if let Ok(n) = r.extract::<usize>() {
        return Ok(Some([n; 3]));
    }
    r.extract::<[usize; 3]>()
        .map(Some)
        .map_err(|_| text("res: an int N or a tuple (NX, NY, NZ)".into()))
}

/// Everything but the grid that decides a run's voxels.
pub struct RunOptions {
    pub sampling: Sampling,
    pub route: Route,
    pub eval: String,
    pub grey: bool,
    pub blend: Option<Union>,
    pub word: WordFormat,
}

impl RunOptions {
    #[allow(clippy::too_many_arguments)]
    pub fn parse(
        sampling: &str,
        model: &str,
        route: &str,
        eval: &str,
        grey: bool,
        blend: Option<&str>,
        word: &str,
    ) -> PyResult<RunOptions> {
        let sampling = match sampling {
            "centre" | "center" => Sampling::Centre,
            "slab" => Sampling::Slab,
            s => return Err(text(format!("sampling {s:?}: `centre` or `slab`"))),
        };
        let model = model.parse::<Model>().map_err(|e| text(e.to_string()))?;
        let route = match (model, route) {
            (Model::Cycle, _) => Route::Array { cycle: true },
            (Model::Word, "runs") => Route::Runs { float: false },
            (Model::Word, "intervals") => Route::Intervals,
            (Model::Word, "array") => Route::Array { cycle: false },
            (Model::Float, "runs") => Route::Runs { float: true },
            (Model::Float, _) => Route::Float,
            (_, r) => return Err(text(format!("route {r:?}: `runs`, `intervals` or `array`"))),
        };
        if !["blist", "tree", "stack"].contains(&eval) {
            return Err(text(format!("eval {eval:?}: `blist`, `tree` or `stack`")));
        }
        let blend = match blend {
            None => None,
            Some("max") => Some(Union::Max),
            Some(s) => Some(parse_sum(s)?),
        };
        if grey && blend.is_some() {
            return Err(text("grey and blend: give one".into()));
        }
        Ok(RunOptions {
            sampling,
            route,
            eval: eval.to_string(),
            grey,
            blend,
            word: parse_word(word)?,
        })
    }

    pub fn evaluator(&self, scene: &Scene) -> Box<dyn SliceEval + Send + Sync> {
        let root = &scene.loaded.scene.root;
        match self.eval.as_str() {
            "tree" => Box::new(TreeEval::new(root)),
            "stack" => Box::new(StackEval::new(root)),
            _ => Box::new(BlistEval::new(root)),
        }
    }

    /// The slicer of `scene` on `grid`.
    pub fn slicer(&self, scene: &Scene, grid: Grid) -> PyResult<Slicer> {
        let opts = SlicerOptions {
            fmt: self.word,
            sampling: self.sampling,
            panel: Some(csgpix_voxel::DEFAULT_PANEL),
            grey: self.grey,
            blend: self
                .blend
                .map(|u| BlendEval::new(&scene.loaded.scene.root, u)),
            sampled: scene.loaded.sampled.clone(),
        };
        Slicer::new(&scene.loaded.scene, grid, opts).map_err(voxel)
    }

    /// Slabs `z` of the scene: the slices' bytes, x fastest, then y, then k.
    pub fn run(
        &self,
        py: Python<'_>,
        scene: &Scene,
        slicer: &Slicer,
        z: std::ops::Range<usize>,
    ) -> PyResult<Vec<u8>> {
        let eval = self.evaluator(scene);
        let set = Equations::Derived.set();
        let route = self.route;
        py.detach(|| {
            let mut out = Vec::with_capacity(z.len() * slicer.grid.slice_len());
            voxelize_slabs::<csgpix_voxel::Error>(
                slicer,
                route,
                set,
                eval.as_ref(),
                &|| {},
                z,
                &mut |_, s| {
                    out.extend_from_slice(s);
                    Ok(())
                },
            )
            .map(|_| out)
        })
        .map_err(voxel)
    }
}

fn parse_sum(s: &str) -> PyResult<Union> {
    let bad = || {
        text(format!(
            "blend {s:?}: `max` or `sum:KS,KD` (e.g. sum:0.5,0.5)"
        ))
    };
    let (ks, kd) = s
        .strip_prefix("sum:")
        .and_then(|r| r.split_once(','))
        .ok_or_else(bad)?;
    let f = |v: &str| {
        v.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| *x >= 0.0 && x.is_finite())
    };
    match (f(ks), f(kd)) {
        (Some(ks), Some(kd)) => Ok(Union::Sum { ks, kd }),
        _ => Err(bad()),
    }
}

/// A depth word `FRACTION/INTEGER/OVERFLOW`, e.g. `10/10/11` (§2.3.1).
pub fn parse_word(s: &str) -> PyResult<WordFormat> {
    let f: Vec<&str> = s.split('/').collect();
    let bad = |m: String| text(format!("word {s:?}: {m}"));
    let [fr, i, o] = f[..] else {
        return Err(bad(
            "expected FRACTION/INTEGER/OVERFLOW, e.g. 10/10/11".into()
        ));
    };
    let n = |v: &str| v.trim().parse::<u32>().map_err(|e| bad(e.to_string()));
    WordFormat::new(n(fr)?, n(i)?, n(o)?).map_err(|e| bad(e.to_string()))
}

/// The slab range `z` of `nz` slabs: all of them when None.
pub fn slab_range(z: Option<(usize, usize)>, nz: usize) -> PyResult<std::ops::Range<usize>> {
    match z {
        None => Ok(0..nz),
        Some((a, b)) if a <= b && b <= nz => Ok(a..b),
        Some((a, b)) => Err(text(format!("z=({a}, {b}): the grid has slabs 0..{nz}"))),
    }
}

/// Voxelize `scene` (seed 001 §4.4): uint8 colour codes, 0 empty, as a numpy array of shape
/// (k1 − k0, NY, NX), with the grid's origin (centre of voxel (0, 0, 0)), spacing and dims.
#[pyfunction]
#[pyo3(signature = (scene, res=None, *, voxel=None, pad=0, bounds=None, sampling="centre",
    model="word", route="runs", eval="blist", grey=false, blend=None, word="10/10/11",
    z=None, max_memory=None))]
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
) -> PyResult<(Bound<'py, PyAny>, [f64; 3], [f64; 3], [usize; 3])> {
    let grid = GridOptions::new(res, voxel, pad, bounds)?.grid(scene)?;
    let opts = RunOptions::parse(sampling, model, route, eval, grey, blend, word)?;
    let slabs = slab_range(z, grid.dims[2])?;
    // The estimate of a run over these slabs: the volume it returns is theirs alone.
    let mut held = grid;
    held.dims[2] = slabs.len().max(1);
    let threads = rayon::current_num_threads();
    let prims = scene.loaded.scene.primitive_count();
    let need = csgpix_voxel::memory_estimate(&held, prims, threads)
        .saturating_add(imports_bytes(scene, &grid));
    check_memory(need, max_memory)?;
    let slicer = opts.slicer(scene, grid)?;
    let [nx, ny, _] = grid.dims;
    let n = slabs.len();
    let bytes = opts.run(py, scene, &slicer, slabs)?;
    let arr = PyArray1::from_vec(py, bytes).reshape([n, ny, nx])?;
    Ok((
        arr.into_any(),
        grid.centre(0, 0, 0).to_array(),
        grid.voxel().to_array(),
        grid.dims,
    ))
}
