//! The cost of the winding-number inside test (`csgpix_scene::winding`) on meshes of a few
//! thousand triangles, over an n³ grid spanning the mesh's box:
//!
//! `cargo run --release -p csgpix-scene --example winding_cost -- 64 256`
//!
//! Words among the arguments pick the meshes by their first word (`holey`, `loose`; both
//! when none is given): `-- 256 holey` times the holey sphere alone.
//!
//! - `holey sphere`: a sphere of 3,936 triangles (its poles' degenerate ones dropped), 40
//!   of them cut out and every seventh wound the wrong way (its boundary: the hole's rim);
//! - `loose soup`: 4,000 triangles sharing no corner (every edge on the boundary: the
//!   method's worst case, three boundary edges per triangle).

use std::f64::consts::PI;
use std::time::Instant;

use csgpix_scene::trimesh::{TriMesh, Window};
use csgpix_scene::winding::OpenMesh;
use glam::DVec3;

fn sphere(rings: usize, seg: usize) -> Vec<[[f64; 3]; 3]> {
    let point = |i: usize, j: usize| {
        let th = PI * i as f64 / rings as f64;
        let ph = 2.0 * PI * (j % seg) as f64 / seg as f64;
        [th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()]
    };
    let mut t = vec![];
    for i in 0..rings {
        for j in 0..seg {
            let (a, b) = (point(i, j), point(i + 1, j));
            let (c, d) = (point(i + 1, j + 1), point(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    t
}

/// A small random number generator (xorshift), so the soup is the same every run.
fn next(s: &mut u64) -> f64 {
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    (*s >> 11) as f64 / (1u64 << 53) as f64
}

fn soup(n: usize) -> Vec<[[f64; 3]; 3]> {
    let mut s = 0x9e37_79b9_7f4a_7c15;
    (0..n)
        .map(|_| {
            let c = [0; 3].map(|_| next(&mut s) * 2.0 - 1.0);
            [0; 3].map(|_| [0, 1, 2].map(|a| c[a] + 0.2 * (next(&mut s) - 0.5)))
        })
        .collect()
}

fn measure(name: &str, tris: &[[[f64; 3]; 3]], n: usize) {
    let mesh = TriMesh::from_f64(tris);
    let t0 = Instant::now();
    let m = OpenMesh::new(&mesh);
    let prepared = t0.elapsed().as_secs_f64();
    let (lo, hi) = m.mesh().bounds();
    let scale = DVec3::splat(n as f64) / (hi - lo);
    let to_frame = |p: DVec3| (p - lo) * scale - 0.5;
    let depths: Vec<f64> = (0..n).map(|k| k as f64).collect();
    let win = Window {
        x0: 0,
        y0: 0,
        w: n,
        h: n,
    };
    let t1 = Instant::now();
    let runs = m.inside_runs_in(to_frame, win, &depths);
    let secs = t1.elapsed().as_secs_f64();
    let inside: u64 = runs
        .iter()
        .flatten()
        .map(|&(a, b)| u64::from(b - a + 1))
        .sum();
    println!(
        "{name}: {} triangles, {} boundary edges, {n}^3: prepared in {prepared:.3} s, \
         inside test {secs:.3} s ({:.1} ns per voxel and boundary edge), {inside} voxels inside",
        m.mesh().triangles.len(),
        m.boundary_edges(),
        secs * 1e9 / (n * n * n) as f64 / m.boundary_edges().max(1) as f64,
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let sizes: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    let picked: Vec<&String> = args
        .iter()
        .filter(|a| a.parse::<usize>().is_err())
        .collect();
    let wanted =
        |name: &str| picked.is_empty() || picked.iter().any(|p| name.starts_with(p.as_str()));
    let mut holey = sphere(36, 56);
    holey.drain(1000..1040);
    for k in (0..holey.len()).step_by(7) {
        holey[k].swap(1, 2);
    }
    let loose = soup(4000);
    for &n in &sizes {
        for (name, tris) in [("holey sphere", &holey), ("loose soup", &loose)] {
            if wanted(name) {
                measure(name, tris, n);
            }
        }
    }
}
