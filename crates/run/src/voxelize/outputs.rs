//! The job's outputs beside the voxelizer (§4.4): the NRRD volume, its slices as PNGs, a
//! preview along the three axes, the surface as a mesh by Marching Cubes over the octree
//! (docs/octree.md); named before anything is computed, staged and committed whole.

use csgpix_draw::palette::rgb;
use csgpix_output::{Out, Outputs};
use csgpix_scene::nrrd::{Encoding, VolumeFormat};
use csgpix_sculpt::octree;
use csgpix_voxel::{Grid, Slicer, Volume};
use serde::Serialize;

use super::plan::Plan;
use super::{Format, VoxelizeJob};
use crate::{lib_errors, Error};

impl VoxelizeJob {
    /// A Zarr store with what it cannot do, refused in one line before anything is named:
    /// the options that need the whole volume in memory, and standard output; and the
    /// Zarr store's options beside a NRRD file.
    pub fn check_format(&self) -> crate::Result<()> {
        let o = &self.outputs;
        #[cfg(not(feature = "zarr"))]
        if self.format() == Format::Zarr {
            let message = "-o: this csgpix is built without Zarr stores (the `zarr` feature): \
                           write a .nrrd file";
            return Err(Error::options("-o", message));
        }
        if self.format() == Format::Nrrd {
            let zarr_only = [
                ("--chunk", o.chunk.is_some()),
                ("--shard", o.shard.is_some()),
                ("--levels", o.levels.is_some()),
            ];
            return match zarr_only.iter().find(|(_, given)| *given) {
                Some((flag, _)) => Err(Error::options(
                    flag,
                    format!("{flag} applies to a Zarr store only (-o OUT.zarr)"),
                )),
                None => Ok(()),
            };
        }
        if o.compress {
            let message =
                "--compress applies to a NRRD file (a Zarr store's chunks are gzip already)";
            return Err(Error::options("--compress", message));
        }
        if o.out.as_os_str() == "-" {
            let message = "-o -: --format zarr writes a directory (OUT.zarr), not standard output";
            return Err(Error::options("-o", message));
        }
        let whole = [
            ("--preview", o.preview.is_some()),
            ("--slices", o.slices.is_some()),
            ("--mesh", o.mesh.is_some()),
            ("--store", o.store.is_some()),
        ];
        match whole.iter().find(|(_, given)| *given) {
            Some((flag, _)) => Err(Error::options(
                flag,
                format!(
                    "{flag} needs the whole volume in memory: not with a Zarr store, which is \
                     written a brick at a time (write a .nrrd file)"
                ),
            )),
            None => Ok(()),
        }
    }
}

/// The run's outputs, named before anything is computed.
pub struct Staged {
    pub outs: Outputs,
    /// `-o`: the NRRD file, or the Zarr store's directory.
    pub nrrd: Out,
    slices: Option<Out>,
    preview: Option<Out>,
    mesh: Option<(Out, csgpix_scene::mesh::Format)>,
}

impl Staged {
    /// Name the job's outputs (refused when one cannot be written, before any work).
    pub fn name(job: &VoxelizeJob) -> crate::Result<Staged> {
        let o = &job.outputs;
        let mut outs = Outputs::new();
        let nrrd = match job.format() {
            Format::Nrrd => outs.file_or_stdout("-o", &o.out, &["nrrd"])?,
            Format::Zarr => outs.tree("-o", &o.out, &["zarr"], "zarr.json")?,
        };
        let slices = o.slices.as_ref();
        let slices = slices.map(|d| outs.series("--slices", d, "slice-", ".png"));
        let slices = slices.transpose()?;
        let preview = o.preview.as_ref();
        let preview = preview.map(|p| outs.file_or_stdout("--preview", p, &["png"]));
        let preview = preview.transpose()?;
        let mesh = match &o.mesh {
            Some(p) => {
                let out = outs.file("--mesh", p, &csgpix_scene::mesh::EXTENSIONS)?;
                Some((out, csgpix_scene::mesh::Format::of_path(p)?))
            }
            None => None,
        };
        if o.report_to_stdout && outs.uses_stdout() {
            return Err(Error::options(
                "--json",
                "--json prints to standard output: write the outputs to files",
            ));
        }
        Ok(Staged {
            outs,
            nrrd,
            slices,
            preview,
            mesh,
        })
    }

    /// How the NRRD volume is written: gzip with `compress`; the `space` of the first
    /// dataset the scene imports that declares one, else the neutral `3D-right-handed`.
    pub fn nrrd_format(&self, job: &VoxelizeJob, slicer: &Slicer) -> VolumeFormat {
        let declared = slicer.sampled.iter().find_map(|s| s.space());
        VolumeFormat {
            space: declared.unwrap_or(csgpix_scene::nrrd::NEUTRAL_SPACE).into(),
            encoding: match job.outputs.compress {
                true => Encoding::Gzip,
                false => Encoding::Raw,
            },
        }
    }

    /// Every output of the volume `v`, then the commit: the mesh's figures (its step's
    /// budget is `rest`, what the limit leaves) and whether an output went to standard
    /// output.
    pub fn write_volume(
        mut self,
        job: &VoxelizeJob,
        plan: &Plan,
        v: &Volume,
        rest: u64,
    ) -> crate::Result<(Option<MeshReport>, bool)> {
        let values = Values::of(job);
        let nrrd_format = self.nrrd_format(job, &plan.slicer);
        let outs = &mut self.outs;
        if let Some(dir) = self.slices {
            write_slices(outs, dir, v, values)?;
        }
        if let Some(out) = self.preview {
            write_preview(outs, out, v, values)?;
        }
        let comment = format!("csgpix voxelize {}", job.name());
        let grid = &plan.slicer.grid;
        let mesh = match self.mesh {
            Some(m) => Some(write_mesh(outs, m, grid, v, rest, &comment)?),
            None => None,
        };
        outs.write_sparse(self.nrrd, VOLUME_HOLE, |w| {
            csgpix_scene::nrrd::write_volume_as(w, grid, &v.voxels, &comment, &nrrd_format)
        })?;
        let to_stdout = outs.uses_stdout();
        self.outs.commit()?;
        Ok((mesh, to_stdout))
    }
}

/// The `--mesh` figures of the JSON report.
#[derive(Serialize, Clone, Copy, Debug)]
pub struct MeshReport {
    pub mesh_triangles: usize,
    /// The mesh step's memory estimate, bytes, checked before it ran (docs/memory.md).
    pub mesh_memory_estimate: u64,
    /// Edges not in exactly two triangles (0: closed).
    pub mesh_open_edges: usize,
}

/// Bytes the mesh step holds per surface voxel beyond the octree's estimate: Marching
/// Cubes' triangles (about 3 a surface voxel, 36 bytes each, and their copy in scene units)
/// and the writer's welded vertices; measured 196-404 bytes (docs/memory.md).
const MESH_BYTES_PER_SURFACE_VOXEL: u64 = 420;

/// Write the volume's surface (`--mesh`, [`mesh`]) and report it.
fn write_mesh(
    outs: &mut Outputs,
    (out, format): (Out, csgpix_scene::mesh::Format),
    grid: &Grid,
    v: &Volume,
    budget: u64,
    comment: &str,
) -> crate::Result<MeshReport> {
    let (tris, need) = mesh(grid, v, budget)?;
    outs.write(out, |w| {
        csgpix_scene::mesh::write_format(w, format, &tris, comment)
    })?;
    Ok(MeshReport {
        mesh_triangles: tris.len(),
        mesh_memory_estimate: need,
        mesh_open_edges: csgpix_scene::mesh::open_edges(&tris),
    })
}

/// The surface of `v` on `grid` by global Marching Cubes over the optimized octree, in scene
/// units: closed and wound outward, as the cells past the grid's far faces are meshed too
/// (docs/octree.md); and its memory estimate, refused when over `budget` bytes.
pub fn mesh(
    grid: &Grid,
    v: &Volume,
    budget: u64,
) -> crate::Result<(Vec<csgpix_scene::mesh::Tri>, u64)> {
    let surface = csgpix_voxel::surface_voxels(v);
    let need = octree::memory_estimate(octree::StoreKind::Octree, v.dims)?
        .saturating_add(surface.saturating_mul(MESH_BYTES_PER_SURFACE_VOXEL));
    if need > budget {
        let message = format!(
            "--mesh: the mesh of {surface} surface voxels needs about {} MiB more, over \
             --max-memory: lower --res or raise the limit",
            need.div_ceil(1 << 20)
        );
        return Err(Error::options("--mesh", message));
    }
    let store = octree::OptimizedOctree::from_volume(v, budget).map_err(lib_errors::sculpt)?;
    let frame = csgpix_sculpt::Frame::of_grid(grid);
    let tris: Vec<csgpix_scene::mesh::Tri> = octree::mc::marching_cubes(&store)
        .triangles
        .iter()
        .map(|t| t.map(|p| frame.to_scene(p)))
        .collect();
    Ok((tris, need))
}

/// One view of the volume along an axis: per pixel the first filled voxel's colour code and
/// its depth along the axis. `axis` 2 looks along +Z (X right, Y down), 1 along +Y (X right,
/// Z down), 0 along +X (Y right, Z down).
fn view(v: &Volume, axis: usize) -> (usize, usize, Vec<u32>, Vec<Option<f64>>) {
    let [nx, ny, nz] = v.dims;
    let at = |i: usize, j: usize, k: usize| v.voxels[(k * ny + j) * nx + i];
    let (w, h, depth) = match axis {
        2 => (nx, ny, nz),
        1 => (nx, nz, ny),
        _ => (ny, nz, nx),
    };
    let (mut codes, mut depths) = (vec![0u32; w * h], vec![None; w * h]);
    for r in 0..h {
        for c in 0..w {
            let hit = (0..depth).find_map(|d| {
                let code = match axis {
                    2 => at(c, r, d),
                    1 => at(c, d, r),
                    _ => at(d, c, r),
                };
                (code != 0).then_some((code, d))
            });
            if let Some((code, d)) = hit {
                codes[r * w + c] = code as u32;
                depths[r * w + c] = Some(d as f64);
            }
        }
    }
    (w, h, codes, depths)
}

/// What a volume's values mean, for pictures.
#[derive(Clone, Copy, PartialEq)]
enum Values {
    /// Palette codes.
    Codes,
    /// Palette codes below GREY_BASE, grey levels from it (`--grey`).
    Mixed,
    /// Grey levels (`--blend`).
    Grey,
}

impl Values {
    /// What the job's voxel values mean.
    fn of(job: &VoxelizeJob) -> Values {
        match (job.voxels.blend.is_some(), job.voxels.grey) {
            (true, _) => Values::Grey,
            (false, true) => Values::Mixed,
            (false, false) => Values::Codes,
        }
    }

    fn rgb(self, c: u8) -> [u8; 3] {
        match self {
            Values::Grey => [c; 3],
            Values::Mixed if c >= csgpix_voxel::GREY_BASE => [c; 3],
            _ => rgb(c as u32),
        }
    }
}

/// The three axis views side by side, 4 pixels apart, scaled up by a whole factor towards
/// 256 pixels.
fn write_preview(outs: &mut Outputs, out: Out, v: &Volume, grey: Values) -> crate::Result<()> {
    let views: Vec<_> = (0..3).rev().map(|a| view(v, a)).collect();
    let scale = (256 / v.dims.iter().copied().max().unwrap_or(1)).max(1);
    let width: usize = views.iter().map(|x| x.0 * scale + 4).sum();
    let height = views.iter().map(|x| x.1 * scale).max().unwrap_or(1);
    let mut img =
        image::RgbImage::from_pixel(width as u32, height as u32, image::Rgb([255, 255, 255]));
    let mut left = 0;
    for (w, h, codes, depths) in &views {
        let rgb = match grey {
            Values::Codes => csgpix_draw::palette::image_rgb(codes, Some(depths)),
            _ => shaded(codes, depths, grey),
        };
        for (i, c) in rgb.iter().enumerate() {
            for dy in 0..scale {
                for dx in 0..scale {
                    let (x, y) = (left + (i % w) * scale + dx, (i / w) * scale + dy);
                    img.put_pixel(x as u32, y as u32, image::Rgb(*c));
                }
            }
        }
        left += w * scale + 4;
        let _ = h;
    }
    Ok(outs.write(out, |w| crate::png::write_png(w, &img))?)
}

/// Values shaded by depth as the palette view shades colours: nearest full, farthest 45%.
fn shaded(codes: &[u32], depths: &[Option<f64>], values: Values) -> Vec<[u8; 3]> {
    let ds = depths.iter().flatten();
    let (lo, hi) = ds.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &d| {
        (a.min(d), b.max(d))
    });
    codes
        .iter()
        .zip(depths)
        .map(|(&c, d)| {
            let t = d.map_or(0.0, |d| if hi > lo { (d - lo) / (hi - lo) } else { 0.0 });
            values
                .rgb(c as u8)
                .map(|x| (x as f64 * (1.0 - 0.55 * t)).round() as u8)
        })
        .collect()
}

/// Every slice as `slice-KKKK.png`, staged with the run's other outputs: an indexed PNG whose
/// pixel indices are the voxels' values (label codes, or grey values with `grey`/`blend`),
/// so the codes survive, shown in the palette's colours (or grey levels).
fn write_slices(outs: &mut Outputs, dir: Out, v: &Volume, grey: Values) -> crate::Result<()> {
    let [nx, ny, nz] = v.dims;
    // Entries up to the largest value of the volume: every slice's indices are in range.
    let top = v.voxels.iter().copied().max().unwrap_or(0);
    let palette: Vec<[u8; 3]> = (0..=top).map(|c| grey.rgb(c)).collect();
    for k in 0..nz {
        let slice = &v.voxels[k * nx * ny..(k + 1) * nx * ny];
        let name = format!("slice-{k:04}.png");
        let size = (nx as u32, ny as u32);
        outs.write_in(dir, &name, |w| {
            crate::png::write_indexed_png(w, size, slice, &palette)
        })?;
    }
    Ok(())
}

/// The shortest run of zeros a volume file leaves as a hole: 1 MiB. Every hole splits the
/// file into one more extent, which the file system frees one by one when the file is
/// replaced or removed (on ext4 mounted with `discard`, a discard request each: 0.1 to 3.5 ms
/// here), while writing 1 MiB of zeros costs about 0.3 ms; `csgpix_output::Sparse` has the
/// figures.
pub(crate) const VOLUME_HOLE: u64 = 1 << 20;
