//! Tessellation against OpenSCAD itself. `vectors/openscad/generate.sh` had OpenSCAD (the
//! version in `vectors/openscad/VERSION`) export every case of `cases.txt` as CSG and mesh the
//! exported CSG to OFF; here csgpix reads the same CSG and must produce the same vertices
//! (OFF prints 6 significant digits) and a closed, outward mesh of the same volume.

use csgpix_scene::solid::Faces;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use csgpix_openscad::parse_csg;

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn dir() -> PathBuf {
    Path::new(ROOT).join("vectors/openscad")
}

/// Case names, in the order of `cases.txt`.
fn cases() -> Vec<String> {
    let text = std::fs::read_to_string(dir().join("cases.txt")).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| l.split('\t').next().unwrap().to_string())
        .collect()
}

/// Vertices and faces of an OFF file.
fn read_off(path: &Path) -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut words = text.split_whitespace();
    assert_eq!(words.next(), Some("OFF"), "{}", path.display());
    let mut num = || words.next().unwrap().parse::<f64>().unwrap();
    let (nv, nf, _) = (num() as usize, num() as usize, num());
    let vertices = (0..nv).map(|_| [num(), num(), num()]).collect();
    let faces = (0..nf)
        .map(|_| {
            let k = num() as usize;
            (0..k).map(|_| num() as usize).collect()
        })
        .collect();
    (vertices, faces)
}

/// Signed volume of a closed mesh (faces counter-clockwise seen from outside: positive).
fn volume(vertices: &[[f64; 3]], faces: &Faces) -> f64 {
    let det = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0])
    };
    faces
        .iter()
        .flat_map(|f| (1..f.len() - 1).map(move |i| (f[0], f[i], f[i + 1])))
        .map(|(a, b, c)| {
            det(
                vertices[a as usize],
                vertices[b as usize],
                vertices[c as usize],
            ) / 6.0
        })
        .sum()
}

/// Every directed edge appears once and its reverse once: the mesh is closed and consistent.
fn closed(faces: &Faces) -> bool {
    let mut edges = BTreeSet::new();
    for f in faces {
        for i in 0..f.len() {
            if !edges.insert((f[i], f[(i + 1) % f.len()])) {
                return false;
            }
        }
    }
    edges.iter().all(|&(a, b)| edges.contains(&(b, a)))
}

/// OFF coordinates carry 6 significant digits.
fn near(a: [f64; 3], b: [f64; 3]) -> bool {
    (0..3).all(|k| (a[k] - b[k]).abs() <= 1e-5 * b[k].abs().max(1.0))
}

#[test]
fn every_primitive_matches_openscad() {
    let names = cases();
    assert!(names.len() >= 20, "{names:?}");
    for name in &names {
        let csg = std::fs::read_to_string(dir().join(format!("{name}.csg"))).unwrap();
        let scene = parse_csg(&csg, name).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(scene.solids.len(), 1, "{name}");
        let ours = &scene.solids[0];
        let (theirs, their_faces) = read_off(&dir().join(format!("{name}.off")));
        assert_eq!(ours.vertices.len(), theirs.len(), "{name}: vertex count");
        for t in &theirs {
            let matches = ours.vertices.iter().filter(|o| near(**o, *t)).count();
            assert_eq!(
                matches, 1,
                "{name}: OpenSCAD vertex {t:?} matches {matches} of ours"
            );
        }
        assert!(closed(&ours.faces), "{name}: our mesh is not closed");
        let (v_ours, v_theirs) = (
            volume(&ours.vertices, &ours.faces),
            volume(&theirs, &Faces::from(their_faces.clone())),
        );
        assert!(v_ours > 0.0, "{name}: our faces point inward");
        assert!(
            (v_ours - v_theirs).abs() <= 1e-4 * v_theirs.abs(),
            "{name}: volume {v_ours} vs OpenSCAD {v_theirs}"
        );
    }
}

/// Nearest depth of a triangle mesh (in pixel coordinates) at every integer pixel (x, y).
fn ray_cast(tris: &[[glam::DVec3; 3]], w: usize, h: usize) -> Vec<Option<f64>> {
    let mut depth = vec![None::<f64>; w * h];
    for t in tris {
        let (lo, hi) = (t[0].min(t[1]).min(t[2]), t[0].max(t[1]).max(t[2]));
        let area = (t[1] - t[0]).truncate().perp_dot((t[2] - t[0]).truncate());
        if area.abs() < 1e-12 {
            continue; // seen edge-on
        }
        let (x0, x1) = (
            lo.x.ceil().max(0.0) as usize,
            hi.x.floor().min((w - 1) as f64),
        );
        let (y0, y1) = (
            lo.y.ceil().max(0.0) as usize,
            hi.y.floor().min((h - 1) as f64),
        );
        for y in y0..=(y1 as usize) {
            for x in x0..=(x1 as usize) {
                let p = glam::DVec2::new(x as f64, y as f64);
                let b = |i: usize, j: usize| {
                    (t[j] - t[i]).truncate().perp_dot(p - t[i].truncate()) / area
                };
                let (l0, l1, l2) = (b(1, 2), b(2, 0), b(0, 1));
                if l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9 {
                    continue;
                }
                let z = l0 * t[0].z + l1 * t[1].z + l2 * t[2].z;
                let d = &mut depth[y * w + x];
                *d = Some(d.map_or(z, |d: f64| d.min(z)));
            }
        }
    }
    depth
}

/// Pixels drawn by exactly one of the two images where neither image has a silhouette (a
/// drawn pixel beside an undrawn one) within one pixel: a difference that no sub-pixel shift
/// of an edge explains.
fn far_coverage_mismatches(a: &[Option<f64>], b: &[Option<f64>], w: usize, h: usize) -> usize {
    let edge_near = |img: &[Option<f64>], x: usize, y: usize| {
        let around = (y.saturating_sub(1)..=(y + 1).min(h - 1))
            .flat_map(|yy| (x.saturating_sub(1)..=(x + 1).min(w - 1)).map(move |xx| yy * w + xx));
        let drawn: BTreeSet<bool> = around.map(|i| img[i].is_some()).collect();
        drawn.len() == 2
    };
    (0..w * h)
        .filter(|&i| a[i].is_some() != b[i].is_some())
        .filter(|&i| !edge_near(a, i % w, i / w) && !edge_near(b, i % w, i / w))
        .count()
}

#[test]
fn scenes_match_openscads_own_csg_evaluation() {
    use csgpix_draw::compile::clip_scene_ops;
    use csgpix_draw::project::{project, Frame, View};
    use rtl_model::program::{CReg, Reg};
    use rtl_model::{Array, ArrayConfig, CycleArray, Equations};

    let scenes = Path::new(ROOT).join("vectors/scenes");
    for name in ["cube-minus-cylinder", "csg-logo"] {
        let text = std::fs::read_to_string(scenes.join(format!("{name}.csg"))).unwrap();
        let scene = parse_csg(&text, name).unwrap();
        let (vertices, faces) = read_off(&dir().join(format!("scene-{name}.off")));
        for view in [View::Top, View::Iso] {
            let n = 96;
            let cfg = ArrayConfig::new(n, n);
            let p = project(&scene, view, n, n, &cfg.fmt).unwrap();
            let ops = clip_scene_ops(&p.lists, p.clip.as_ref().unwrap(), &cfg.fmt, 8).unwrap();
            let mut arr = CycleArray::new(cfg, Equations::Derived.set());
            arr.run(&ops).unwrap();
            let ours: Vec<Option<f64>> = arr
                .state()
                .pixels
                .iter()
                .map(|px| (px.creg(CReg::G) != 0).then(|| cfg.fmt.to_real(px.reg(Reg::C))))
                .collect();
            let frame = Frame::fit(&scene, view, n, n).unwrap();
            let px = |i: usize| frame.to_pixel(glam::DVec3::from(vertices[i]));
            let tris: Vec<[glam::DVec3; 3]> = faces
                .iter()
                .flat_map(|f| (1..f.len() - 1).map(move |k| (f[0], f[k], f[k + 1])))
                .map(|(a, b, c)| [px(a), px(b), px(c)])
                .collect();
            let theirs = ray_cast(&tris, n, n);
            let both: Vec<f64> = (0..n * n)
                .filter_map(|i| Some((ours[i]? - theirs[i]?).abs()))
                .collect();
            let far = far_coverage_mismatches(&ours, &theirs, n, n);
            let deep = both.iter().filter(|&&d| d > 0.5).count();
            let one = (0..n * n)
                .filter(|&i| ours[i].is_some() != theirs[i].is_some())
                .count();
            println!(
                "{name} {view:?}: {} pixels drawn by both, {deep} differ in depth by over 0.5; \
                 {one} drawn by one only, {far} of them away from any silhouette",
                both.len()
            );
            assert!(both.len() > n * n / 10, "{name} {view:?}");
            if far > 0 {
                let mut m = String::new();
                for y in 0..n {
                    for x in 0..n {
                        let i = y * n + x;
                        m.push(match (ours[i].is_some(), theirs[i].is_some()) {
                            (true, true) => '#',
                            (true, false) => 'o',
                            (false, true) => 't',
                            _ => '.',
                        });
                    }
                    m.push('\n');
                }
                eprintln!("{m}");
            }
            assert_eq!(far, 0, "{name} {view:?}");
            assert!(
                deep * 200 < both.len(),
                "{name} {view:?}: {deep} deep differences"
            );
        }
    }
}
