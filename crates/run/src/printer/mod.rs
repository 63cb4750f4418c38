//! The print job: a CSG scene sliced straight onto a resin (MSLA) printer's display. The
//! thesis's machine makes Z slices of the scene (§4.4); a resin printer shows exactly that,
//! one image per layer. Each layer pixel's grey is the share of its k×k sub-pixel samples
//! inside the part (`--aa k`; 1 thresholds), computed by the voxelizer's run route on a grid
//! whose columns are the sub-pixels' centres and whose slabs are the layers, and written as
//! the voxelizer sweeps the layers: memory holds the columns' runs, not the layers.
//!
//! By stage: [`profile`] is the printer, [`place`] puts the part on its display and makes
//! the grid, [`raster`] turns a slab of samples into a layer image, [`png`] and [`zip`]
//! encode it, [`archive`] writes Prusa's `.sl1`/`.sl1s` or a PNG stack with `print.json`.

pub mod archive;
pub mod extent;
pub mod place;
pub mod png;
pub mod profile;
pub mod raster;
pub mod zip;

use std::path::PathBuf;
use std::time::Instant;

use csgpix_openscad::Fallback;
use csgpix_voxel::sampled::Loaded;
use csgpix_voxel::Grid;
use glam::DVec2;
use serde::{Deserialize, Serialize};

use csgpix_output::Outputs;

use crate::memory::{default_limit, Limit};
use crate::progress::Progress;
use crate::read::ReadSettings;
use crate::voxelize::{OutputOptions, VoxelizeJob};
use crate::Error;
pub use extent::part_box;
pub use profile::{Printer, PROFILES};

use extent::{exact_box, Box3};

/// Most sub-pixel samples per pixel side (`--aa`): 16×16 gives every grey level.
pub const MAX_AA: u32 = 16;

/// A print job (`csgpix print`): the scene, the printer, the output.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PrintJob {
    /// OpenSCAD `.csg` (or `.scad`) scene, in mm.
    pub scene: PathBuf,
    /// `*.sl1`/`*.sl1s`: Prusa's archive; anything else: a directory of layer PNGs.
    pub out: PathBuf,
    pub printer: Printer,
    /// Samples per pixel side.
    pub aa: u32,
    /// The part's centre, mm from the display's centre.
    pub centre: [f64; 2],
    pub threads: Option<usize>,
    /// The memory limit; not serialized: the memory available is the machine's, now.
    #[serde(skip, default = "default_limit")]
    pub max_memory: Limit,
    pub read: ReadSettings,
    #[serde(with = "crate::named::by_name")]
    pub fallback: Fallback,
}

impl Default for PrintJob {
    /// The documented defaults: the SL1, no anti-aliasing (`--aa 1`), the part centred.
    fn default() -> Self {
        PrintJob {
            scene: PathBuf::new(),
            out: PathBuf::new(),
            printer: PROFILES[0].clone(),
            aa: 1,
            centre: [0.0, 0.0],
            threads: None,
            max_memory: default_limit(),
            read: ReadSettings::default(),
            fallback: Fallback::default(),
        }
    }
}

/// What a print job made.
#[derive(Serialize, Clone, Debug)]
pub struct PrintReport {
    pub printer: String,
    pub out: PathBuf,
    pub archive: &'static str,
    pub layers: usize,
    /// The layer PNG's width and height.
    pub image: [u32; 2],
    /// The part's pixels on the display along X and Y (before any turn).
    pub part_pixels: [usize; 2],
    /// Its first pixel along X and Y.
    pub part_origin: [u32; 2],
    pub aa: u32,
    /// Material, ml (the grey levels' sum × pixel area × layer height).
    pub material_ml: f64,
    /// The print's duration, s, by [`archive::print_seconds`].
    pub print_seconds: f64,
    /// The material labels (colour codes) that have a stack of their own: a PNG stack's, where
    /// the scene's `color()`s give more than one code; else none.
    pub materials: Vec<u8>,
    /// The voxelizer's grid of the layers (after the first, when it is of another height):
    /// its voxels and box, scene units, for `csgpix requirements --res --bounds`.
    pub grid_dims: [usize; 3],
    pub grid_min: [f64; 3],
    pub grid_max: [f64; 3],
    /// The thesis's array slicing this print (one processor a sample, §2): its clocks and
    /// P·Vz frames, and the seconds those clocks take at 10 MHz.
    pub array_clocks: u64,
    pub array_frames: u64,
    pub array_seconds: f64,
    pub memory_estimate: u64,
    pub wall_seconds: f64,
    pub warnings: Vec<String>,
}

impl PrintJob {
    /// Read, place, slice and write.
    pub fn run(&self, progress: &dyn Progress) -> crate::Result<PrintReport> {
        let t0 = Instant::now();
        self.check()?;
        let kind = archive::Kind::of(&self.out);
        let mut outs = Outputs::new();
        let out = match kind {
            archive::Kind::Prusa => outs.file("-o", &self.out, &["sl1", "sl1s"])?,
            archive::Kind::Stack => outs.dir("-o", &self.out)?,
        };
        let vjob = self.voxelize_job();
        // Read on the threads asked, as `voxelize` reads.
        let pool = crate::voxelize::Workers::new(self.threads)?;
        let loaded = pool.install(|| vjob.load(progress))?;
        drop(pool);
        let part = part_box(&loaded).map_err(|m| Error::options("SCENE", m))?;
        let part = self.placed_box(&vjob, &loaded, part)?;
        let done = self.print_at(&mut outs, out, kind, (&vjob, &loaded, progress), part)?;
        let Printed {
            placed,
            grid,
            need,
            summary,
            ..
        } = done;
        let (w, h) = self.printer.png_size();
        progress.finish();
        outs.commit()?;
        Ok(PrintReport {
            printer: self.printer.id.to_string(),
            out: self.out.clone(),
            archive: kind.name(),
            layers: placed.layers,
            image: [w, h],
            part_pixels: placed.pixels(),
            part_origin: [placed.i.0, placed.j.0],
            aa: self.aa,
            material_ml: summary.material_ml,
            print_seconds: summary.print_seconds,
            materials: summary.materials,
            grid_dims: grid.dims,
            grid_min: grid.min.to_array(),
            grid_max: grid.max.to_array(),
            array_clocks: summary.array[0],
            array_frames: summary.array[1],
            array_seconds: summary.array[0] as f64 * 1e-7,
            memory_estimate: need,
            wall_seconds: t0.elapsed().as_secs_f64(),
            warnings: loaded
                .scene
                .warnings
                .iter()
                .map(|w| w.to_string())
                .collect(),
        })
    }

    /// The box the part is placed on: the tree's `part` where nothing can cut it (or where
    /// what the print's samples light, cut to a fraction of a pixel, places the part within
    /// 1/256 of a pixel and a layer of where `part` does: it seldom moves); else that cut.
    fn placed_box(&self, vjob: &VoxelizeJob, loaded: &Loaded, part: Box3) -> crate::Result<Box3> {
        if exact_box(loaded) {
            return Ok(part);
        }
        let cut = self.lit_box(vjob, loaded, part, self.aa as usize)?;
        let moved = !self
            .place(vjob, cut)?
            .near(&self.place(vjob, part)?, &self.printer);
        Ok(if moved { cut } else { part })
    }

    /// The print of the part of box `part` staged in `out`.
    fn print_at(
        &self,
        outs: &mut Outputs,
        out: csgpix_output::Out,
        kind: archive::Kind,
        (vjob, loaded, progress): (&VoxelizeJob, &Loaded, &dyn Progress),
        part: Box3,
    ) -> crate::Result<Printed> {
        let placed = self.place(vjob, part)?;
        let passes = self.passes(vjob, loaded, &placed, self.aa as usize)?;
        let grid = passes.last().map(|p| p.0.slicer.grid);
        let grid = grid.ok_or_else(|| Error::options("SCENE", "the part has no layer"))?;
        // Material stacks are a PNG stack's, and only where the scene has `color()`: the
        // codes solids take by default (1..6 in turn) are not materials.
        let codes = match kind {
            archive::Kind::Stack if coloured(&loaded.scene) => {
                passes.first().map_or(&[][..], |p| &p.0.slicer.colours[..])
            }
            _ => &[],
        };
        let bytes = raster::Raster::bytes(&placed, self.aa, codes.len().min(256));
        let need = passes.iter().map(|p| p.1).max().unwrap_or(0);
        let need = need.saturating_add(bytes);
        self.max_memory
            .check(need, "this print", "raise --max-memory")?;
        let mut raster = raster::Raster::new(&self.printer, &placed, self.aa, codes);
        let (w, h) = self.printer.png_size();
        let png = png::LayerPng::new(w, h, raster.rows, raster.cols);
        progress.stage("layers", placed.layers as u64);
        let make = Make {
            vjob,
            passes: &passes,
            png: &png,
            progress,
        };
        let summary = match kind {
            archive::Kind::Prusa => self.write_prusa(outs, out, &placed, &mut raster, make)?,
            archive::Kind::Stack => self.write_stack(outs, out, &placed, &mut raster, make)?,
        };
        Ok(Printed {
            placed,
            grid,
            need,
            summary,
        })
    }

    /// Prusa's archive: the layers as they come, then `config.ini`, `prusaslicer.ini` and
    /// the thumbnails, which need every layer.
    fn write_prusa(
        &self,
        outs: &mut Outputs,
        out: csgpix_output::Out,
        placed: &place::Placement,
        raster: &mut raster::Raster,
        make: Make,
    ) -> crate::Result<archive::Summary> {
        let job = archive::job_name(&self.out);
        let (mut failed, mut summary) = (None, None);
        let written = outs.write(out, |w| {
            let mut z = zip::ZipOut::new(w);
            let mut emit = |l: usize, pngs: &[Vec<u8>]| {
                z.add(
                    &archive::layer_name(archive::Kind::Prusa, &job, l),
                    &pngs[0],
                )
            };
            let array = match self.sweep(&make, raster, &mut emit) {
                Ok(array) => array,
                Err(e) => {
                    failed = Some(e);
                    return Err(std::io::Error::other("the slicing failed"));
                }
            };
            let s = archive::Summary::of(&self.printer, raster, array);
            let config = archive::config_ini(&self.printer, &job, &s, &stamp(&self.scene));
            z.add("config.ini", config.as_bytes())?;
            let ini = archive::prusaslicer_ini(&self.printer, placed);
            z.add("prusaslicer.ini", ini.as_bytes())?;
            let sizes = [(400, 400), (800, 480)];
            let pngs = archive::thumbnail_pngs(raster, placed.layers, &sizes)?;
            for (size, png) in sizes.iter().zip(pngs) {
                let name = format!("thumbnail/thumbnail{}x{}.png", size.0, size.1);
                z.add(&name, &png)?;
            }
            summary = Some(s);
            z.finish()
        });
        if let Some(e) = failed {
            return Err(e);
        }
        written?;
        summary.ok_or_else(|| self.io(std::io::Error::other("no summary")))
    }

    /// A directory of layer PNGs (and one stack per material where the scene has several),
    /// `print.json` and `thumbnail.png`.
    fn write_stack(
        &self,
        outs: &mut Outputs,
        out: csgpix_output::Out,
        placed: &place::Placement,
        raster: &mut raster::Raster,
        make: Make,
    ) -> crate::Result<archive::Summary> {
        let job = archive::job_name(&self.out);
        let materials = raster.materials();
        let mut emit = |l: usize, pngs: &[Vec<u8>]| {
            let name = archive::layer_name(archive::Kind::Stack, &job, l);
            let by_material = materials
                .iter()
                .map(|c| format!("material-{c}-layer-{l:05}.png"));
            for (name, bytes) in std::iter::once(name).chain(by_material).zip(pngs) {
                outs.write_in(out, &name, |w| w.write_all(bytes))
                    .map_err(|e| std::io::Error::other(e.to_string()))?;
            }
            Ok(())
        };
        let array = self.sweep(&make, raster, &mut emit)?;
        let s = archive::Summary::of(&self.printer, raster, array);
        let info = archive::StackInfo::of(&self.printer, placed, self.aa, &s);
        let text = serde_json::to_string_pretty(&info)?;
        outs.write_in(out, "print.json", |w| w.write_all(text.as_bytes()))?;
        let pngs = archive::thumbnail_pngs(raster, placed.layers, &[(400, 400)]);
        let bytes = pngs.map_err(|e| self.io(e))?.concat();
        outs.write_in(out, "thumbnail.png", |w| w.write_all(&bytes))?;
        Ok(s)
    }

    /// Every layer of every pass, in order, made by `raster`, encoded by `png` and handed
    /// to `emit` on this thread: the voxelizer and the raster run on a thread of their own
    /// (the voxelizer on its pool), the PNG encoder on another, so that slicing, encoding
    /// and writing overlap.
    fn sweep(
        &self,
        make: &Make,
        raster: &mut raster::Raster,
        emit: &mut Emit,
    ) -> crate::Result<[u64; 2]> {
        let Make {
            vjob,
            passes,
            png,
            progress,
        } = *make;
        // Queues of [`raster::BOX_SETS`]: four layers' boxes to the encoder, two spare sets
        // back; four encoded layers to the writer (compressed, small).
        let (tx, boxes) = std::sync::mpsc::sync_channel::<Boxes>(4);
        let (back, spare) = std::sync::mpsc::sync_channel::<Vec<Vec<u8>>>(2);
        let (encoded, rx) = std::sync::mpsc::sync_channel::<Boxes>(4);
        let made = std::thread::scope(|scope| {
            let maker = scope.spawn(move || make_layers(vjob, passes, raster, (tx, spare)));
            let encoder = scope.spawn(move || encode_layers(png, (boxes, back), encoded));
            let mut wrote = Ok(());
            // A layer with no files repeats the one before (`Raster::repeated`).
            let mut last = vec![];
            for (l, bytes) in rx.iter() {
                if !bytes.is_empty() {
                    last = bytes;
                }
                wrote = emit(l, &last);
                progress.advance(1);
                if wrote.is_err() {
                    break;
                }
            }
            drop(rx);
            let made = maker
                .join()
                .unwrap_or_else(|p| std::panic::resume_unwind(p));
            let coded = encoder
                .join()
                .unwrap_or_else(|p| std::panic::resume_unwind(p));
            wrote.map(|_| coded.map_err(Stop::Io).and(made))
        });
        match made {
            Err(e) => Err(self.io(e)),
            Ok(Err(Stop::Io(e))) => Err(self.io(e)),
            Ok(Err(Stop::Voxel(e))) => Err(e.into()),
            Ok(Ok(array)) => Ok(array),
        }
    }

    /// An error writing the output.
    fn io(&self, source: std::io::Error) -> Error {
        Error::Io {
            path: self.out.clone(),
            source,
        }
    }

    /// The settings, each in range, refused in one line.
    fn check(&self) -> crate::Result<()> {
        self.printer
            .check()
            .map_err(|(flag, m)| Error::options(flag, m))?;
        if !(1..=MAX_AA).contains(&self.aa) {
            let m = format!(
                "--aa: {}: 1 (no anti-aliasing) to {MAX_AA} samples a side",
                self.aa
            );
            return Err(Error::options("--aa", m));
        }
        if self.centre.iter().any(|c| !c.is_finite()) {
            return Err(Error::options(
                "--position",
                "--position: not a finite point",
            ));
        }
        Ok(())
    }

    /// The voxelize job whose reader, plan and memory limit this print uses.
    fn voxelize_job(&self) -> VoxelizeJob {
        VoxelizeJob {
            scene: Some(self.scene.clone()),
            outputs: OutputOptions {
                out: self.out.clone(),
                ..OutputOptions::default()
            },
            threads: self.threads,
            max_memory: self.max_memory,
            read: self.read.printing(),
            fallback: self.fallback,
            ..VoxelizeJob::default()
        }
    }

    /// The part placed on the display, or the one-line refusal.
    fn place(&self, vjob: &VoxelizeJob, part: Box3) -> crate::Result<place::Placement> {
        let centre = DVec2::from_array(self.centre);
        place::place(&self.printer, part, centre)
            .map_err(|m| Error::options("--position", format!("{}: {m}", vjob.name())))
    }

    /// The voxelizer's plans: one over every layer, or one for the first layer and one for
    /// the others when the first is not as high; each with its memory estimate.
    fn passes(
        &self,
        vjob: &VoxelizeJob,
        loaded: &Loaded,
        placed: &place::Placement,
        k: usize,
    ) -> crate::Result<Vec<Pass>> {
        let p = &self.printer;
        let [w, h] = placed.pixels();
        let mut out = vec![];
        for layers in layer_runs(p, 0..placed.layers) {
            let [lo, hi] = placed.grid(p, layers.clone());
            let dims = [w * k, h * k, layers.len()];
            let grid =
                Grid::new(dims, lo, hi).map_err(|e| Error::from(csgpix_voxel::Error::from(e)))?;
            let plan = vjob.plan_on(loaded, grid).map_err(Error::from)??;
            let need = plan.budget(vjob, &loaded.scene)?.need;
            out.push((plan, need, layers));
        }
        Ok(out)
    }
}

/// The runs of evenly spaced layers among `layers`: the first layer is a run of its own
/// when it is not as high as the others.
fn layer_runs(p: &Printer, layers: std::ops::Range<usize>) -> Vec<std::ops::Range<usize>> {
    let same = (p.initial_layer_height - p.layer_height).abs() <= 1e-12 * p.layer_height;
    let runs = match same || layers.start > 0 || layers.len() < 2 {
        true => [layers.clone(), layers.end..layers.end],
        false => [0..1, 1..layers.end],
    };
    runs.into_iter().filter(|r| !r.is_empty()).collect()
}

/// What makes the layers: the voxelizer's job and passes, the PNG encoder, the progress.
#[derive(Clone, Copy)]
struct Make<'a> {
    vjob: &'a VoxelizeJob,
    passes: &'a [Pass],
    png: &'a png::LayerPng,
    progress: &'a dyn Progress,
}

/// Where a layer's PNG files go: its index, the part's file, then each material's.
type Emit<'e> = dyn FnMut(usize, &[Vec<u8>]) -> std::io::Result<()> + 'e;

/// A layer's number and its boxes (or files): the part's, then each material's.
type Boxes = (usize, Vec<Vec<u8>>);

/// The sending end of a bounded queue between the print's threads.
type Sender<T> = std::sync::mpsc::SyncSender<T>;

/// Whether any of the scene's primitives carries a colour of its own (`color()`).
fn coloured(scene: &csgpix_scene::solid::CsgScene) -> bool {
    let solids = scene.solids.iter().map(|s| s.colour);
    let imports = scene.imports.iter().map(|i| i.colour);
    solids.chain(imports).any(|c| c.is_some())
}

/// A voxelizer plan, its memory estimate and the layers it makes.
type Pass = (crate::voxelize::plan::Plan, u64, std::ops::Range<usize>);

/// The archive's creation time as PrusaSlicer writes it, from the scene file's
/// modification time (so that the same scene makes the same archive).
fn stamp(scene: &std::path::Path) -> String {
    let t = std::fs::metadata(scene).and_then(|m| m.modified()).ok();
    let secs = t
        .and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok())
        .map_or(0, |d| d.as_secs());
    let (days, rest) = (secs / 86_400, secs % 86_400);
    let (y, m, d) = civil(days as i64);
    let (hh, mm, ss) = (rest / 3600, rest / 60 % 60, rest % 60);
    format!("{y:04}-{m:02}-{d:02} at {hh:02}:{mm:02}:{ss:02} UTC")
}

/// The calendar date of a day count from 1970-01-01 (H. Hinnant's civil_from_days).
fn civil(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (yoe + era * 400 + i64::from(m <= 2), m, d)
}

/// The voxelizer's layers, pass by pass, each made into its PNG boxes (the part's, then
/// each material's) and sent to the encoder.
fn make_layers(
    vjob: &VoxelizeJob,
    passes: &[Pass],
    raster: &mut raster::Raster,
    (tx, spare): (Sender<Boxes>, std::sync::mpsc::Receiver<Vec<Vec<u8>>>),
) -> Result<[u64; 2], Stop> {
    // Shared with the voxelizer's pool, which runs the sink.
    let spare = std::sync::Mutex::new(spare);
    let mut array = [0, 0];
    for (plan, _, layers) in passes {
        let first = layers.start;
        let work = sweep_plan(vjob, plan, 0..layers.len(), |k: usize, s: &[u8]| {
            raster.layer(s);
            // No boxes: the writer writes the layer before's files again.
            let boxes = match raster.repeated() {
                true => vec![],
                false => {
                    let spare = spare.lock().ok().and_then(|r| r.try_recv().ok());
                    raster.take_boxes(spare.unwrap_or_default())
                }
            };
            // The encoder stopped: the writer's error is the one to report.
            tx.send((first + k, boxes))
                .map_err(|_| Stop::Io(std::io::Error::other("writer stopped")))
        })?;
        array[0] += work.cycles;
        array[1] += work.frames;
    }
    Ok(array)
}

/// Slabs `slabs` of `plan` voxelized on its own pool, each slab's samples handed to `sink`
/// in order (the three sweeps of a print: the layers, the lit box, the top probe).
fn sweep_plan<E, F>(
    vjob: &VoxelizeJob,
    plan: &crate::voxelize::plan::Plan,
    slabs: std::ops::Range<usize>,
    mut sink: F,
) -> Result<csgpix_voxel::work::Work, E>
where
    E: From<csgpix_voxel::Error> + Send,
    F: FnMut(usize, &[u8]) -> Result<(), E> + Send,
{
    plan.pool.install(move || {
        let set = vjob.voxels.equations.set();
        let (sl, eval) = (&plan.slicer, plan.eval.as_ref());
        csgpix_voxel::voxelize_slabs(sl, plan.route, set, eval, &|| {}, slabs, &mut sink)
    })
}

/// Each layer's boxes as PNG files, in order, to the writer.
fn encode_layers(
    png: &png::LayerPng,
    (boxes, spare): (std::sync::mpsc::Receiver<Boxes>, Sender<Vec<Vec<u8>>>),
    tx: Sender<Boxes>,
) -> std::io::Result<()> {
    for (l, layer) in boxes {
        // A layer with no boxes repeats the one before: no files, the writer's again.
        let mut files = Vec::with_capacity(layer.len());
        for b in &layer {
            let mut f = Vec::with_capacity(8192);
            png.write(&mut f, b)?;
            files.push(f);
        }
        // Back to the raster for a later layer, unless two are waiting there already.
        if !layer.is_empty() {
            let _ = spare.try_send(layer);
        }
        if tx.send((l, files)).is_err() {
            break; // the writer stopped and says why
        }
    }
    Ok(())
}

/// Why the sweep stopped: the output's write or the voxelizer.
enum Stop {
    Io(std::io::Error),
    Voxel(csgpix_voxel::Error),
}

impl From<csgpix_voxel::Error> for Stop {
    fn from(e: csgpix_voxel::Error) -> Stop {
        Stop::Voxel(e)
    }
}

impl From<crate::Error> for Stop {
    fn from(e: crate::Error) -> Stop {
        Stop::Io(std::io::Error::other(e.to_string()))
    }
}

/// What one print made: where, on which grid, its memory estimate and its totals.
struct Printed {
    placed: place::Placement,
    grid: Grid,
    need: u64,
    summary: archive::Summary,
}
