//! The study job: sweep the knobs that trade speed for accuracy when voxelizing a scene
//! through the array (depth-word fraction bits §2.3.1/§2.5, tessellation, slabs §4.4/§5.5,
//! model), and write the figures as CSV and PNG charts ([`crate::sweep`]).

use std::path::PathBuf;
use std::time::Instant;

use csgpix_output::{Out, Outputs};
use csgpix_voxel::memory_estimate;
use serde::{Deserialize, Serialize};

use crate::memory::Limit;
use crate::plot::{Chart, Charts};
use crate::progress::Progress;
use crate::read::ReadSettings;
use crate::sweep::{charts, csv, prepare, Point, Prepared, Sweep};

/// The charts' size in pixels.
const CHART_SIZE: (u32, u32) = (800, 560);

/// Sweep `sweep` over the `.csg` scene `scene`; write `out`/study.csv and the charts.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct StudyJob {
    /// OpenSCAD `.csg` scene.
    pub scene: PathBuf,
    /// Output directory (created if missing; files are written only when the whole sweep
    /// succeeded).
    pub out: PathBuf,
    /// The ranges swept and the fixed word bits, resolution and sampling.
    #[serde(flatten)]
    pub sweep: Sweep,
    /// The memory limit in MiB (`--max-memory`); None: the memory available when it runs.
    pub max_memory: Option<u64>,
    /// openscad's time limit (`--openscad-timeout`; `--strict` does not apply: a study reads
    /// `.csg` text).
    pub read: ReadSettings,
}

/// What a study measured. The JSON fields in this order, as `--json` prints them.
#[derive(Clone, Debug, Serialize)]
pub struct StudyReport {
    /// The scene's file name.
    pub scene: String,
    /// The sweep, normalized (sorted, without repeats).
    pub sweep: Sweep,
    /// The grid box shared by every point, scene units.
    pub bounds: [[f64; 3]; 2],
    /// Every point, slabs outermost, then fragments, bits and models.
    pub points: Vec<Point>,
    /// The sweep's wall time.
    pub wall_seconds: f64,
    /// The CSV written (text only).
    #[serde(skip)]
    pub csv: PathBuf,
    /// The charts' data, `(file name, chart)`: staged as PNG beside the CSV when the job ran
    /// with a drawer ([`StudyJob::run_with_charts`]); for a caller to draw otherwise.
    #[serde(skip)]
    pub charts: Vec<(&'static str, Chart)>,
}

impl StudyJob {
    /// The memory plan (docs/memory.md): the scene read at every tessellation, then the
    /// largest grid's voxelization with the reference and float volumes beside it.
    pub fn estimate(&self) -> crate::Result<u64> {
        self.prepare().and_then(|p| need(&p))
    }

    /// Run the sweep and write study.csv alone: a caller without a chart drawer gets the
    /// charts' data in the report.
    pub fn run(&self, progress: &dyn Progress) -> crate::Result<StudyReport> {
        self.sweep_and_write(None, progress)
    }

    /// Run the sweep and write study.csv and the charts, drawn by `charts`, as one
    /// directory: all of them or, on any error or signal, none.
    pub fn run_with_charts(
        &self,
        charts: &dyn Charts,
        progress: &dyn Progress,
    ) -> crate::Result<StudyReport> {
        self.sweep_and_write(Some(charts), progress)
    }

    /// The memory limit, named as the command line names it.
    fn limit(&self) -> Limit {
        Limit::new(self.max_memory, "--max-memory")
    }

    /// The scene read at every tessellation, every grid and word laid on it.
    fn prepare(&self) -> crate::Result<Prepared> {
        let file = self.scene.display().to_string();
        let text = csgpix_openscad::scene_text_with(&self.scene, self.read.limit())?;
        prepare(&text, &file, self.sweep.clone())
    }

    fn sweep_and_write(
        &self,
        drawer: Option<&dyn Charts>,
        progress: &dyn Progress,
    ) -> crate::Result<StudyReport> {
        let file = self.scene.display().to_string();
        let text = csgpix_openscad::scene_text_with(&self.scene, self.read.limit())?;
        let mut outs = Outputs::new();
        let dir = outs.dir("-o", &self.out)?;
        let prep = prepare(&text, &file, self.sweep.clone())?;
        self.limit()
            .check(need(&prep)?, "this sweep", "lower --res or --slabs")?;
        let t0 = Instant::now();
        progress.stage("points", prep.sweep.len() as u64);
        let points = prep.run(&|| progress.advance(1))?;
        progress.finish();
        let wall_seconds = t0.elapsed().as_secs_f64();
        let scene = self
            .scene
            .file_name()
            .map_or(file, |n| n.to_string_lossy().into());
        let charts = charts(&points, &scene);
        write_outputs(&mut outs, dir, &points, &charts, drawer)?;
        outs.commit()?;
        Ok(StudyReport {
            scene,
            bounds: [prep.min.to_array(), prep.max.to_array()],
            sweep: prep.sweep,
            points,
            wall_seconds,
            csv: self.out.join("study.csv"),
            charts,
        })
    }
}

/// The largest grid's voxelization, and the reference and float volumes kept beside it.
fn need(prep: &Prepared) -> crate::Result<u64> {
    let slabs = prep.sweep.slabs.iter().copied().max().unwrap_or(1);
    let grid = prep.grid(slabs)?;
    let solids = prep
        .scenes
        .iter()
        .map(|(_, s)| s.solids.len())
        .max()
        .unwrap_or(0);
    Ok(memory_estimate(&grid, solids, rayon::current_num_threads()).saturating_mul(3))
}

/// Stage study.csv and (with a drawer) the charts as the files of directory output `dir`.
fn write_outputs(
    outs: &mut Outputs,
    dir: Out,
    points: &[Point],
    charts: &[(&'static str, Chart)],
    drawer: Option<&dyn Charts>,
) -> crate::Result<()> {
    let table = csv(points);
    outs.write_in(dir, "study.csv", |w| w.write_all(table.as_bytes()))?;
    if let Some(drawer) = drawer {
        let (width, height) = CHART_SIZE;
        for (name, chart) in charts {
            let png = drawer.png(chart, width, height)?;
            outs.write_in(dir, name, |w| w.write_all(&png))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::progress::Quiet;

    /// A drawer that writes the chart's title as its "PNG".
    struct Titles;

    impl Charts for Titles {
        fn png(&self, c: &Chart, _: u32, _: u32) -> Result<Vec<u8>, crate::plot::PlotError> {
            Ok(c.title.clone().into_bytes())
        }
    }

    fn job(out: PathBuf) -> StudyJob {
        let scene = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../vectors/scenes/cube-minus-cylinder.csg"
        );
        StudyJob {
            scene: scene.into(),
            out,
            sweep: Sweep {
                bits: vec![6],
                fragments: vec![8],
                slabs: vec![8],
                res: 8,
                ..Sweep::default()
            },
            ..StudyJob::default()
        }
    }

    #[test]
    fn the_csv_alone_without_a_drawer_and_the_charts_with_one() {
        let dir = tempfile::tempdir().unwrap();
        let plain = dir.path().join("plain");
        let r = job(plain.clone()).run(&Quiet).unwrap();
        assert_eq!(r.points.len(), 2);
        assert_eq!(r.csv, plain.join("study.csv"));
        let files = |d: &std::path::Path| {
            let mut f: Vec<String> = std::fs::read_dir(d)
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into())
                .collect();
            f.sort();
            f
        };
        assert_eq!(files(&plain), ["study.csv"]);
        let drawn = dir.path().join("drawn");
        let r = job(drawn.clone()).run_with_charts(&Titles, &Quiet).unwrap();
        let names = [
            "bits.png",
            "depth.png",
            "fragments.png",
            "study.csv",
            "wall.png",
        ];
        assert_eq!(files(&drawn), names);
        let bits = std::fs::read_to_string(drawn.join("bits.png")).unwrap();
        assert_eq!(bits, r.charts[0].1.title);
        assert!(job(drawn).estimate().unwrap() > 0);
    }

    #[test]
    fn a_job_goes_through_json_unchanged() {
        let j = job("out".into());
        let text = serde_json::to_string(&j).unwrap();
        assert!(text.contains("\"models\":[\"word\",\"float\"]"), "{text}");
        assert_eq!(serde_json::from_str::<StudyJob>(&text).unwrap(), j);
        let empty: StudyJob = serde_json::from_str("{}").unwrap();
        assert_eq!(empty, StudyJob::default());
    }
}
