//! Numerical stability at the extremes (docs/stability.md): depths exactly 0 and maxdepth,
//! exact ties, overflow into and out of the overflow bits, faces approaching perpendicular,
//! huge and tiny coefficients, DEPGEN's error over a 1024×1024 screen against its bound,
//! sub-pixel primitives, scenes of 1000+ primitives and trees 100,000 deep.
//!
//! Expected values are worked out by hand from the thesis's rules (§2.3.3-2.3.5, §2.4.1) and
//! written in the tests; the float reference (`crates/draw/src/float.rs`) is run beside the array and
//! compared. Measured numbers are printed: `cargo test --release --test stability --
//! --nocapture`.

mod common;
use common::csgpix;

use std::path::Path;

use csgpix::draw::compile::{check_window, clip_scene_ops, scene_ops};
use csgpix::draw::float::{self, agreement, rounding_bound, ScreenRule};
use csgpix::draw::project::{self, display_lists, max_slope, Frame, View};
use csgpix::openscad::parse_csg;
use csgpix::scene::clip_expr::Clip;
use csgpix::scene::display_list::{DisplayList, DlPlane};
use csgpix::voxel::blist::BlistTable;
use rtl_model::depgen::{pixel_add, DepGen};
use rtl_model::program::{CReg, Coeffs, Op, Reg};
use rtl_model::select::vectors::{derive_with_ties, Ties};
use rtl_model::{
    ArchState, Array, ArrayConfig, CycleArray, EquationSet, Equations, WordArray, WordFormat,
};

const INTERIOR: u32 = csgpix::draw::compile::INTERIOR_COLOUR;

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A display-list plane (§5.2).
fn pl(z0: f64, dzx: f64, dzy: f64, colour: u32, h: bool, y: bool, l: bool) -> DlPlane {
    DlPlane {
        z0,
        dzx,
        dzy,
        colour,
        h,
        y,
        l,
    }
}

fn list(planes: Vec<DlPlane>) -> DisplayList {
    DisplayList {
        planes,
        terminator: 1234,
    }
}

/// A raw-word plane of an object (no colour transfer matters for back planes).
fn plane(c0: i64, dx: i64, colour: u32, s: bool, h: bool, l: bool) -> Op {
    Op::Plane {
        coeffs: Coeffs { c0, dx, dy: 0 },
        colour,
        interior: INTERIOR,
        l,
        s,
        h,
        y: false,
    }
}

/// Run `ops` in both models; they must agree in every register.
fn run_both(cfg: ArrayConfig, set: &EquationSet, ops: &[Op]) -> ArchState {
    let mut c = CycleArray::new(cfg, set.clone());
    let mut w = WordArray::new(cfg, set.clone());
    c.run(ops).unwrap();
    w.run(ops).unwrap();
    let (sc, sw) = (c.state(), w.state());
    assert_eq!(sc, sw, "cycle and word differ");
    sw
}

fn colours(st: &ArchState) -> Vec<u32> {
    st.pixels.iter().map(|p| p.creg(CReg::G)).collect()
}

/// Display lists through both models and the float reference: (array colours, C depths in
/// depth units, float image). Every colour difference must be explained (near tie or the
/// screen rule), none unexplained.
fn lists_vs_float(
    lists: &[DisplayList],
    clip: Option<&Clip>,
    cfg: ArrayConfig,
) -> (Vec<u32>, Vec<f64>, float::FloatImage) {
    let ops = match clip {
        Some(e) => clip_scene_ops(lists, e, &cfg.fmt, cfg.colour_bits).unwrap(),
        None => scene_ops(lists, &cfg.fmt, cfg.colour_bits).unwrap(),
    };
    let st = run_both(cfg, &Equations::Derived.set(), &ops);
    let g = colours(&st);
    let c: Vec<f64> = st
        .pixels
        .iter()
        .map(|p| cfg.fmt.to_real(p.reg(Reg::C)))
        .collect();
    let a = agreement(&g, lists, clip, cfg.width, cfg.height, &cfg.fmt);
    assert!(
        a.unexplained.is_empty(),
        "unexplained pixels {:?}",
        &a.unexplained[..a.unexplained.len().min(10)]
    );
    let f = float::render(
        lists,
        clip,
        cfg.width,
        cfg.height,
        &cfg.fmt,
        ScreenRule::Exact,
    );
    (g, c, f)
}

// ---------------------------------------------------------------------------------------------
// Depths exactly 0 and exactly maxdepth (§2.3.3: "visible only if 0 ≤ Z < Maxdepth").

#[test]
fn depth_exactly_zero_and_exactly_maxdepth() {
    let fmt = WordFormat::THESIS;
    let ulp = fmt.to_real(1);
    let md = fmt.to_real(fmt.maxdepth());
    // One flat slab per case: front plane at `z`, back plane at 2000 (beyond maxdepth, still
    // put into B by the S = 1 row "Z >= 0: Put A").
    let cases = [
        (0.0, Some(0.0), 2),           // Z = 0: Put A, the face is on the screen
        (md - ulp, Some(md - ulp), 2), // last value before maxdepth: visible
        (md, None, 0),                 // Z = maxdepth: M = 1, Put 1, background
        (md + ulp, None, 0),
    ];
    let cfg = ArrayConfig::new(3, 2);
    for (z, want_depth, want_colour) in cases {
        let dl = list(vec![
            pl(z, 0.0, 0.0, 2, true, false, false),
            pl(2000.0, 0.0, 0.0, 3, false, false, false),
        ]);
        let (g, c, f) = lists_vs_float(std::slice::from_ref(&dl), None, cfg);
        assert!(g.iter().all(|&v| v == want_colour), "z = {z}: {g:?}");
        assert!(f.colour.iter().all(|&v| v == want_colour), "float, z = {z}");
        match want_depth {
            Some(d) => assert!(c.iter().all(|&v| v == d), "z = {z}: C {c:?}"),
            // Put 1 leaves the largest word in C: the reset value, "infinity".
            None => assert!(c.iter().all(|&v| v == fmt.to_real(fmt.max_word()))),
        }
        assert!(f.depth.iter().all(|d| *d == want_depth), "float depth {z}");
    }
    // A front plane sweeping through 0 and maxdepth along x: -512, 0, 512, 1024, 1536.
    let dl = list(vec![
        pl(-512.0, 512.0, 0.0, 2, true, false, false),
        pl(2000.0, 0.0, 0.0, 3, false, false, false),
    ]);
    let cfg = ArrayConfig::new(5, 1);
    let (g, c, f) = lists_vs_float(std::slice::from_ref(&dl), None, cfg);
    // x = 0: Z < 0, Put 0: the screen clips the object, interior colour at depth 0.
    assert_eq!(g, [INTERIOR, 2, 2, 0, 0]);
    assert_eq!(f.colour, [INTERIOR, 2, 2, 0, 0]);
    assert_eq!(&c[..3], [0.0, 0.0, 512.0]);
    assert_eq!(f.depth, [Some(0.0), Some(0.0), Some(512.0), None, None]);
    // A back plane exactly at 0 (and the front plane too): zero thickness on the screen.
    // Close (§2.3.3, convex): Z_F >= Z_B puts maxdepth; float: an empty interval.
    let dl = list(vec![
        pl(0.0, 0.0, 0.0, 2, true, false, false),
        pl(0.0, 0.0, 0.0, 3, false, false, false),
    ]);
    let (g, _, f) = lists_vs_float(std::slice::from_ref(&dl), None, ArrayConfig::new(2, 2));
    assert!(g.iter().all(|&v| v == 0) && f.colour.iter().all(|&v| v == 0));
}

// ---------------------------------------------------------------------------------------------
// Ties (§2.3.3 "up to the user", §2.3.4 X, §2.3.5 F <= C), under each `--ties` policy.

fn tie_sets() -> [(&'static str, EquationSet); 3] {
    [
        ("minimal", Equations::Derived.set()),
        ("keep", derive_with_ties(Ties::Keep).unwrap()),
        ("put", derive_with_ties(Ties::Put).unwrap()),
    ]
}

#[test]
fn ties_a_eq_f_a_eq_b_f_eq_c() {
    let fmt = WordFormat::THESIS;
    let q = |v: f64| fmt.quantize(v).unwrap();
    let cfg = ArrayConfig::new(1, 1);
    let one = |set: &EquationSet, ops: &[Op]| *run_both(cfg, set, ops).at(0, 0);
    let compose = Op::Compose { p: false };
    for (name, set) in tie_sets() {
        // A = F, convex front planes: two front planes at 10 (colours 2, 3), back at 50.
        let ops = [
            plane(q(10.0), 0, 2, true, true, false),
            plane(q(10.0), 0, 3, false, true, false),
            plane(q(50.0), 0, 4, true, false, false),
            Op::Close { l: false },
            compose.clone(),
        ];
        let p = one(&set, &ops);
        let want = match name {
            "put" => 3,
            _ => 2, // minimal keeps F on convex front planes (docs/select-logic.md)
        };
        assert_eq!((p.creg(CReg::G), p.reg(Reg::C)), (want, q(10.0)), "{name}");

        // A = F, concave front planes (the far wall of a void, §2.3.2): the complement of the
        // slab [10, 50] as the compiler draws it: the screen and the slab's front as back
        // planes (L = 1), its back at 50 as two front planes.
        let ops = [
            plane(0, 0, 2, true, false, true),
            plane(q(10.0), 0, 2, false, false, true),
            plane(q(50.0), 0, 2, true, true, true),
            plane(q(50.0), 0, 3, false, true, true),
            Op::Close { l: true },
            compose.clone(),
        ];
        let p = one(&set, &ops);
        let want = match name {
            "keep" => 2,
            _ => 3, // minimal puts A on concave front planes
        };
        assert_eq!((p.creg(CReg::G), p.reg(Reg::C)), (want, q(50.0)), "{name}");

        // A = B, back planes: the same depth is stored whichever way the tie goes.
        let ops = [
            plane(q(10.0), 0, 2, true, true, false),
            plane(q(50.0), 0, 4, true, false, false),
            plane(q(50.0), 0, 5, false, false, false),
        ];
        let mut w = WordArray::new(cfg, set.clone());
        w.run(&ops).unwrap();
        assert_eq!(w.state().at(0, 0).reg(Reg::B), q(50.0), "{name}");

        // F = B at the close: a zero-thickness object vanishes (convex Z_F >= Z_B and concave
        // Z_F <= Z_B put maxdepth).
        for l in [false, true] {
            let ops = [
                plane(q(30.0), 0, 2, true, true, l),
                plane(q(30.0), 0, 4, true, false, l),
                Op::Close { l },
                compose.clone(),
            ];
            assert_eq!(one(&set, &ops).creg(CReg::G), 0, "{name} L={l}");
        }

        // F = C, second stage: "Put F if F <= C": the later object wins the tie.
        let obj = |colour| {
            [
                plane(q(20.0), 0, colour, true, true, false),
                plane(q(60.0), 0, 4, true, false, false),
                Op::Close { l: false },
                compose.clone(),
            ]
        };
        let ops: Vec<Op> = obj(2).into_iter().chain(obj(3)).collect();
        assert_eq!(one(&set, &ops).creg(CReg::G), 3, "{name}");

        // A = F on a clipping plane: X = 0 keeps the surface, X = 1 does not (§2.3.4).
        for (x, want) in [(false, 2), (true, 0)] {
            let ops = [
                plane(q(20.0), 0, 2, true, true, false),
                plane(q(60.0), 0, 4, true, false, false),
                Op::Close { l: false },
                Op::ClipPlane {
                    coeffs: Coeffs {
                        c0: q(20.0),
                        dx: 0,
                        dy: 0,
                    },
                    h: true,
                    y: false,
                    x,
                },
                Op::ClipApply,
                compose.clone(),
            ];
            assert_eq!(one(&set, &ops).creg(CReg::G), want, "{name} X={x}");
        }
    }
    // The float reference on the same ties: the earlier of two coincident convex front faces
    // and of two concave far walls, the later of two coincident objects, nothing for zero
    // thickness, a face on a clipping plane kept.
    let fr = |lists: &[DisplayList], clip: Option<&Clip>| {
        float::render(lists, clip, 1, 1, &fmt, ScreenRule::Exact).colour[0]
    };
    let convex = list(vec![
        pl(10.0, 0.0, 0.0, 2, true, false, false),
        pl(10.0, 0.0, 0.0, 3, true, false, false),
        pl(50.0, 0.0, 0.0, 4, false, false, false),
    ]);
    assert_eq!(fr(std::slice::from_ref(&convex), None), 2);
    let concave = list(vec![
        pl(0.0, 0.0, 0.0, 2, false, false, true),
        pl(10.0, 0.0, 0.0, 2, false, false, true),
        pl(50.0, 0.0, 0.0, 2, true, false, true),
        pl(50.0, 0.0, 0.0, 3, true, false, true),
    ]);
    assert_eq!(fr(std::slice::from_ref(&concave), None), 2);
    let slab = |colour| {
        list(vec![
            pl(20.0, 0.0, 0.0, colour, true, false, false),
            pl(60.0, 0.0, 0.0, 4, false, false, false),
        ])
    };
    assert_eq!(fr(&[slab(2), slab(3)], None), 3);
    let thin = list(vec![
        pl(30.0, 0.0, 0.0, 2, true, false, false),
        pl(30.0, 0.0, 0.0, 4, false, false, false),
    ]);
    assert_eq!(fr(std::slice::from_ref(&thin), None), 0);
    // A.B with B's front face exactly on A's: both surfaces are kept (on a face is inside,
    // X = 0) and composed, so the later literal's colour wins, in the array and in float.
    let names = ["A".to_string(), "B".to_string()];
    let and = Clip::parse("A.B", &names).unwrap();
    assert_eq!(fr(&[slab(2), slab(3)], Some(&and)), 3);
    let (g, _, _) = lists_vs_float(&[slab(2), slab(3)], Some(&and), ArrayConfig::new(1, 1));
    assert_eq!(g, [3]);
}

// ---------------------------------------------------------------------------------------------
// Overflow into and out of the overflow bits (§2.4.1, docs/depth-word.md).

#[test]
fn overflow_into_the_overflow_bits_is_beyond_the_display() {
    let fmt = WordFormat::THESIS;
    let md = fmt.maxdepth();
    let cfg = ArrayConfig::new(1, 1);
    let set = Equations::Derived.set();
    // Values whose first overflow bit (bit F+I = 20) is set or not, up to the last word whose
    // sign is clear: M = 1 exactly from maxdepth on, and the plane is not drawn there.
    let top = fmt.max_word();
    for v in [md - 1, md, md + 1, 2 * md, 1 << 30, top - 1] {
        let ops = [
            plane(v, 0, 2, true, true, false),
            plane(top, 0, 4, true, false, false),
            Op::Close { l: false },
            Op::Compose { p: false },
        ];
        let p = *run_both(cfg, &set, &ops).at(0, 0);
        let m = fmt.overflow_bits().any(|k| fmt.bit(v, k));
        assert_eq!(m, v >= md, "{v:#x}");
        let want = if m { (0, top) } else { (2, v) };
        assert_eq!((p.creg(CReg::G), p.reg(Reg::C)), want, "{v:#x}");
    }
}

#[test]
fn overflow_out_of_the_overflow_bits_wraps_and_is_refused_by_the_compiler() {
    let fmt = WordFormat::THESIS;
    let (top, bottom) = (fmt.max_word(), fmt.min_word());
    let set = Equations::Derived.set();
    let far = fmt.quantize(100.0).unwrap();
    let object = |c0: i64, dx: i64| {
        vec![
            plane(c0, dx, 2, true, true, false),
            plane(far, 0, 4, true, false, false),
            Op::Close { l: false },
            Op::Compose { p: false },
        ]
    };
    // Past the top: top-2, top-1, top, then the carry reaches the sign and the value wraps
    // to the most negative words, which the hardware reads as in front of the screen
    // (S = 1, Z < 0: Put 0, interior colour). The thesis word cannot saturate: the sign is
    // the last bit streamed.
    let st = run_both(ArrayConfig::new(5, 1), &set, &object(top - 2, 1));
    assert_eq!(colours(&st), [0, 0, 0, INTERIOR, INTERIOR]);
    // Past the bottom: bottom+1, bottom, then top: in front of the screen, then beyond it.
    let st = run_both(ArrayConfig::new(3, 1), &set, &object(bottom + 1, -1));
    assert_eq!(colours(&st), [INTERIOR, INTERIOR, 0]);
    // Float: a plane 2^21 deep is beyond maxdepth everywhere, one at -2^21 clips the slab to
    // the screen everywhere: the wrapped pixels are wrong answers ...
    let real = |c0: i64, dx: i64| {
        list(vec![
            pl(fmt.to_real(c0), fmt.to_real(dx), 0.0, 2, true, false, false),
            pl(100.0, 0.0, 0.0, 4, false, false, false),
        ])
    };
    let f = float::render(&[real(top - 2, 1)], None, 5, 1, &fmt, ScreenRule::Exact);
    assert_eq!(f.colour, [0, 0, 0, 0, 0]);
    let f = float::render(&[real(bottom + 1, -1)], None, 3, 1, &fmt, ScreenRule::Exact);
    assert_eq!(f.colour, [INTERIOR, INTERIOR, INTERIOR]);
    // ... so the compiler refuses such a plane on that window (and accepts it on a window
    // where it fits), naming the plane and the pixel.
    let e = check_window(&[real(top - 2, 1)], &fmt, 5, 1).unwrap_err();
    assert_eq!((e.0, e.1.plane), (0, 0));
    assert!(e.1.msg.contains("at pixel (4, 0)"), "{}", e.1.msg);
    assert!(check_window(&[real(top - 2, 1)], &fmt, 3, 1).is_ok());
    assert!(check_window(&[real(bottom + 1, -1)], &fmt, 3, 1).is_err());
    assert!(check_window(&[real(bottom + 1, -1)], &fmt, 2, 1).is_ok());

    // A partial sum may leave the word harmlessly: DEPGEN's x line carries x·dx modulo 2^N_D
    // and the pixel's adder the full sum modulo 2^N_D, so a value that fits is exact even when
    // x·dx alone does not (here 2·2^30 = 2^31 wraps on the column line).
    let (c0, dx) = (bottom + 1000, 1i64 << 30);
    let st = run_both(ArrayConfig::new(3, 1), &set, &object(c0, dx));
    assert_eq!(colours(&st), [INTERIOR, INTERIOR, 2]);
    assert_eq!(st.at(2, 0).reg(Reg::C), 1000);
    assert!(check_window(&[real(c0, dx)], &fmt, 3, 1).is_ok());
    let f = float::render(&[real(c0, dx)], None, 3, 1, &fmt, ScreenRule::Exact);
    assert_eq!(f.colour, [INTERIOR, INTERIOR, 2]);
}

#[test]
fn wrapping_display_list_is_refused_by_render_with_file_line_col() {
    let dir = tempfile::tempdir().unwrap();
    let dl = dir.path().join("wrap.dl");
    // Coefficients that fit the word (|Z0|, |dZx| < 2^21) but a sum that does not: 100 +
    // 10000·x passes 2^21 at x = 210 on a 250-wide window.
    let text =
        "# a plane that leaves the word\n100 10000 0 2\n1 0 0\n300 0 0 3\n0 0 0\n0 0 0 1234\n";
    std::fs::write(&dl, text).unwrap();
    let out_png = dir.path().join("out.png");
    let out = csgpix(&["render", s(&dl), "-o", s(&out_png), "--model", "word"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with(&format!("csgpix: {}:2:1: ", dl.display())),
        "{err}"
    );
    assert!(err.contains("DEPGEN would wrap"), "{err}");
    assert!(!out_png.exists());
    // The same list on a window where it fits renders.
    let out = csgpix(&["render", s(&dl), "-o", s(&out_png), "--size", "200x200"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

// ---------------------------------------------------------------------------------------------
// Faces approaching perpendicular: normal z from 1e-1 to 1e-12 and exactly 0.

/// A 40×40×20 box rotated about X by the angle whose sine is `sn` (its ±Y faces have normal z
/// ±sn, the ±X faces exactly 0), and a unit cube off one corner, so that the box does not fill
/// the array and its edges do not fall on pixel centres.
fn tilted_box(sn: f64) -> String {
    let cs = (1.0 - sn * sn).sqrt();
    format!(
        "union() {{\n\
         multmatrix([[1, 0, 0, 0], [0, {cs:e}, {:e}, 0], [0, {sn:e}, {cs:e}, 0], [0, 0, 0, 1]]) \
         cube(size = [40, 40, 20], center = true);\n\
         multmatrix([[1, 0, 0, -27.3], [0, 1, 0, -26.1], [0, 0, 1, -12], [0, 0, 0, 1]]) \
         cube(size = 1);\n}}\n",
        -sn
    )
}

#[test]
fn faces_approaching_perpendicular() {
    let fmt = WordFormat::THESIS;
    let n = 64;
    let cfg = ArrayConfig::new(n, n);
    let limit = max_slope(&fmt, n, n);
    assert_eq!(limit, 1024.0);
    println!("faces approaching perpendicular, {n}x{n}, top view, slope limit {limit}:");
    println!(
        "normal z | slope | drawn as | silhouette planes added | differ from float, same planes (near a tie) | \
         differ from exact geometry (of them near a tie)"
    );
    for sn in [1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-9, 1e-12, 0.0] {
        let scene = parse_csg(&tilted_box(sn), "tilted.csg").unwrap();
        let p = project::project(&scene, View::Top, n, n, &fmt).unwrap();
        // The ±Y faces' slope in depth units per pixel is cot = cos/sin (uniform scale).
        let slope = (1.0 - sn * sn).sqrt() / sn;
        let faces = &p.lists[0].planes[..6];
        let perpendicular = faces.iter().filter(|q| q.y).count();
        let want = if slope > limit { 4 } else { 2 };
        assert_eq!(perpendicular, want, "sin {sn}: slope {slope}");
        for q in p.lists.iter().flat_map(|l| &l.planes) {
            assert!(q.z0.is_finite() && q.dzx.is_finite() && q.dzy.is_finite());
        }
        // The box's steep back face comes in front of the screen beside the box when it is
        // sloped (slope 10: 20 depth units in 2 pixels): projection closes the silhouette.
        let silhouette = p.lists[0].planes.len() - 6;
        if sn == 1e-1 {
            assert!(silhouette > 0);
        }
        let (g, c, f) = lists_vs_float(&p.lists, p.clip.as_ref(), cfg);
        let a = agreement(&g, &p.lists, p.clip.as_ref(), n, n, &fmt);
        assert_eq!(
            a.screen_rule, 0,
            "sin {sn}: the silhouette planes keep the rule out"
        );
        // Exact geometry: the same faces with no slope limit (only n_z = 0 is perpendicular).
        let frame = Frame::fit(&scene, View::Top, n, n).unwrap();
        let exact = display_lists(&scene, &frame, f64::MAX);
        let t = float::render(&exact, p.clip.as_ref(), n, n, &fmt, ScreenRule::Exact);
        let (mut differ_exact, mut tie_exact) = (0, 0);
        for i in 0..n * n {
            let e = rounding_bound(&fmt, i % n, i / n);
            let same =
                g[i] == t.colour[i] && t.depth[i].is_none_or(|d| (c[i] - d).abs() <= 3.0 * e);
            if !same {
                differ_exact += 1;
                tie_exact += (f.margin[i] < 2.0 * e || t.margin[i] < 2.0 * e) as usize;
            }
        }
        println!(
            "{sn:e} | {slope:.3e} | {} | {silhouette} | {} ({}) | {differ_exact} ({tie_exact})",
            if slope > limit {
                "perpendicular (Y=1)"
            } else {
                "sloped"
            },
            a.differ(),
            a.near_tie
        );
        // A face replaced by its trace moves the silhouette by less than a pixel: at most one
        // pixel per column along each of the two replaced faces' traces.
        assert!(
            differ_exact - tie_exact <= 2 * n,
            "sin {sn}: {differ_exact}"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Huge and tiny coefficients.

#[test]
fn huge_coefficients_are_refused_with_the_field_named() {
    let fmt = WordFormat::THESIS;
    let big = fmt.to_real(fmt.max_word()) + 1.0;
    for (planes, field) in [
        (vec![pl(big, 0.0, 0.0, 2, true, false, false)], 0),
        (vec![pl(1e300, 0.0, 0.0, 2, true, false, false)], 0),
        (vec![pl(10.0, f64::MAX, 0.0, 2, true, false, false)], 1),
        (vec![pl(10.0, 0.0, -1e20, 2, true, false, false)], 2),
        (vec![pl(10.0, 0.0, f64::NAN, 2, true, false, false)], 2),
        (vec![pl(f64::INFINITY, 0.0, 0.0, 2, true, false, false)], 0),
    ] {
        let dl = list(planes);
        let (i, e) = scene_ops(std::slice::from_ref(&dl), &fmt, 8).unwrap_err();
        assert_eq!((i, e.plane, e.field), (0, 0, field), "{}", e.msg);
        assert!(e.msg.contains("does not fit the depth word"), "{}", e.msg);
        assert!(check_window(std::slice::from_ref(&dl), &fmt, 4, 4).is_err());
    }
    // The largest coefficient that fits is accepted; the CLI reports one that does not with
    // file:line:col of the field, exit 2 and no output file.
    assert!(fmt.quantize(fmt.to_real(fmt.max_word())).is_ok());
    let dir = tempfile::tempdir().unwrap();
    let dl = dir.path().join("huge.dl");
    std::fs::write(&dl, "10 0 1e300 2\n1 0 0\n0 0 0 1234\n").unwrap();
    let png = dir.path().join("o.png");
    let out = csgpix(&["render", s(&dl), "-o", s(&png)]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1);
    assert!(
        err.starts_with(&format!("csgpix: {}:1:6: dZy", dl.display())),
        "{err}"
    );
    assert!(!png.exists());
}

#[test]
fn tiny_coefficients_round_to_the_word_without_panics() {
    let fmt = WordFormat::THESIS;
    let half = fmt.to_real(1) / 2.0;
    // Round to nearest, ties to even: a half unit rounds to 0, one and a half to 2 units.
    assert_eq!(fmt.quantize(half).unwrap(), 0);
    assert_eq!(fmt.quantize(3.0 * half).unwrap(), 2);
    assert_eq!(fmt.quantize(half * (1.0 + 1e-15)).unwrap(), 1);
    for v in [1e-300, 5e-324, -5e-324, -1e-300, 0.0, -0.0] {
        assert_eq!(fmt.quantize(v).unwrap(), 0, "{v:e}");
    }
    // A slab whose slopes are below the last place: drawn flat, within the rounding bound of
    // the exact planes, no difference from float unexplained.
    let dl = list(vec![
        pl(10.0 + 1e-300, 5e-324, 1e-12, 2, true, false, false),
        pl(20.0, -1e-300, half, 3, false, false, false),
    ]);
    let cfg = ArrayConfig::new(8, 8);
    let (g, c, f) = lists_vs_float(std::slice::from_ref(&dl), None, cfg);
    assert!(g.iter().all(|&v| v == 2));
    for (i, d) in f.depth.iter().enumerate() {
        let e = rounding_bound(&fmt, i % 8, i / 8);
        assert!((c[i] - d.unwrap()).abs() <= e, "pixel {i}");
    }
    // Tiny and huge solids in a .csg scene: the reader refuses coordinates beyond 1e12 and
    // solids under 1e-12 across (a 1e-307 cube's planes came out NaN) with a position; a cube
    // of 1e11 renders, and one of 1e-12.
    let e = parse_csg("cube(1e13);", "huge.csg").unwrap_err();
    assert!(e.to_string().starts_with("huge.csg:1:1: "), "{e}");
    let e = parse_csg("cube(1e-300);", "tiny.csg").unwrap_err();
    assert!(
        e.to_string()
            .starts_with("tiny.csg:1:1: degenerate extent: "),
        "{e}"
    );
    for text in ["cube(1e-12);", "cube(1e11);", "cube(1e11); cube(1e-3);"] {
        let scene = parse_csg(&format!("union() {{ {text} }}"), "t.csg").unwrap();
        let p = project::project(&scene, View::Iso, 16, 16, &fmt).unwrap();
        for dl in &p.lists {
            for q in &dl.planes {
                assert!(q.z0.is_finite() && q.dzx.is_finite() && q.dzy.is_finite());
            }
        }
        let (g, _, _) = lists_vs_float(&p.lists, p.clip.as_ref(), ArrayConfig::new(16, 16));
        let drawn = g.iter().filter(|&&v| v != 0).count();
        println!("{text}: {drawn} of 256 pixels drawn at 16x16 (iso)");
    }
}

// ---------------------------------------------------------------------------------------------
// DEPGEN error over a 1024×1024 screen against the bound 2^-(F+1)·(1 + x + y).

/// Every pixel's value as the bit-serial DEPGEN tree and pixel adder deliver it, raw.
fn depgen_values(g: &DepGen, fmt: &WordFormat, c: &Coeffs, w: usize, h: usize) -> Vec<i64> {
    let lines = g.stream(c);
    let nd = fmt.bits() as usize;
    let mut out = vec![0i64; w * h];
    for y in 0..h {
        for i in 0..lines.col_words {
            let mut carry = 0u64;
            let mut bits = [0u64; 64];
            for (k, b) in bits.iter_mut().enumerate().take(nd) {
                *b = pixel_add(
                    lines.col[k * lines.col_words + i],
                    lines.row_mask(k, y),
                    &mut carry,
                );
            }
            for lane in 0..64 {
                let x = i * 64 + lane;
                if x >= w {
                    break;
                }
                let mut v = 0i64;
                for (k, b) in bits.iter().enumerate().take(nd) {
                    v |= ((b >> lane & 1) as i64) << k;
                }
                out[y * w + x] = fmt.wrap(v);
            }
        }
    }
    out
}

/// Max over the screen of |word − exact| / 1, that error at the four corners, and the
/// largest ratio error / bound.
fn depgen_error(fmt: &WordFormat, g: &DepGen, z: [f64; 3], n: usize) -> (f64, [f64; 4], f64) {
    let c = csgpix::draw::compile::coeffs(fmt, z[0], z[1], z[2]).unwrap();
    let v = depgen_values(g, fmt, &c, n, n);
    let (mut max, mut ratio) = (0.0f64, 0.0f64);
    let mut corners = [0.0; 4];
    for y in 0..n {
        for x in 0..n {
            let exact = z[0] + x as f64 * z[1] + y as f64 * z[2];
            let err = (fmt.to_real(v[y * n + x]) - exact).abs();
            let bound = rounding_bound(fmt, x, y);
            assert!(
                err <= bound,
                "F={} {z:?} ({x},{y}): {err} > {bound}",
                fmt.frac
            );
            max = max.max(err);
            ratio = ratio.max(err / bound);
            let m = n - 1;
            if let Some(k) = [(0, 0), (m, 0), (0, m), (m, m)]
                .iter()
                .position(|&p| p == (x, y))
            {
                corners[k] = err;
            }
        }
    }
    (max, corners, ratio)
}

fn fmt_corners(c: &[f64; 4]) -> String {
    c.iter()
        .map(|v| format!("{v:.4e}"))
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn depgen_error_grows_with_x_and_y_within_the_bound() {
    let n = 1024;
    println!("DEPGEN |word - exact| on {n}x{n}; bound e(x,y) = 2^-(F+1)(1+x+y), e(1023,1023) = 2047/2^(F+1):");
    println!("F | plane | max error | corners (0,0) (1023,0) (0,1023) (1023,1023) | bound at (1023,1023) | max error/bound");
    let mut rng = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64
    };
    for (frac, int, ovf) in [(4, 10, 11), (10, 10, 11), (16, 10, 11)] {
        let fmt = WordFormat::new(frac, int, ovf).unwrap();
        let g = DepGen::new(n, n, fmt);
        let ulp = fmt.to_real(1);
        let far = rounding_bound(&fmt, n - 1, n - 1);
        // Worst case, by construction: every coefficient exactly half a unit above an even
        // multiple of the unit, so ties-to-even rounds each down by exactly half a unit and the
        // errors add: the bound is attained at every pixel (ratio 1).
        let worst = [100.0 + ulp / 2.0, 0.25 + 2.5 * ulp, 0.125 + 4.5 * ulp];
        let (max, corners, ratio) = depgen_error(&fmt, &g, worst, n);
        println!(
            "{frac} | worst case | {max:.6e} | {} | {far:.6e} | {ratio:.6}",
            fmt_corners(&corners)
        );
        assert_eq!(max, far, "the bound is attained at the far corner");
        assert!(ratio >= 1.0 - 1e-9);
        // Random planes (depth in [0, 512), slopes in ±0.25): no provable fraction of the
        // bound; the ratio is reported.
        let mut ratios = vec![];
        for k in 0..6 {
            let z = [512.0 * next(), 0.5 * next() - 0.25, 0.5 * next() - 0.25];
            let (max, corners, ratio) = depgen_error(&fmt, &g, z, n);
            if k < 2 {
                println!(
                    "{frac} | random {k} | {max:.6e} | {} | {far:.6e} | {ratio:.4}",
                    fmt_corners(&corners)
                );
            }
            ratios.push(max / far);
        }
        let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
        println!(
            "{frac} | 6 random planes | max error / e(1023,1023): min {:.3}, mean {mean:.3}, max {:.3}",
            ratios.iter().cloned().fold(f64::INFINITY, f64::min),
            ratios.iter().cloned().fold(0.0, f64::max),
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Sub-pixel primitives.

#[test]
fn sub_pixel_primitives() {
    let fmt = WordFormat::THESIS;
    // Top view of a 63×63×10 base: one pixel per scene unit, pixel (X, 63 − Y). Two cubes
    // 0.1 wide float above it: one centred on pixel (20, 30), one between pixel centres at
    // (40.5, 30.5). The array samples pixel centres: the first is one pixel, the second none.
    let text = "union() {\n\
        cube(size = [63, 63, 10]);\n\
        multmatrix([[1, 0, 0, 19.95], [0, 1, 0, 32.95], [0, 0, 1, 14.95], [0, 0, 0, 1]]) cube(size = 0.1);\n\
        multmatrix([[1, 0, 0, 40.45], [0, 1, 0, 32.45], [0, 0, 1, 14.95], [0, 0, 0, 1]]) cube(size = 0.1);\n\
        }\n";
    let scene = parse_csg(text, "sub.csg").unwrap();
    let n = 64;
    let p = project::project(&scene, View::Top, n, n, &fmt).unwrap();
    let (g, _, f) = lists_vs_float(&p.lists, p.clip.as_ref(), ArrayConfig::new(n, n));
    let at = |c: u32| -> Vec<(usize, usize)> {
        (0..n * n)
            .filter(|&i| g[i] == c)
            .map(|i| (i % n, i / n))
            .collect()
    };
    // Solids without a colour take codes 1, 2, 3 in turn.
    assert_eq!(at(2), [(20, 30)]);
    assert_eq!(at(3), []);
    assert_eq!(f.colour[30 * n + 20], 2);
    assert!(!f.colour.contains(&3));
    println!(
        "sub-pixel cubes 0.1 px wide: on a pixel centre {} pixel drawn, between centres {}",
        at(2).len(),
        at(3).len()
    );

    // Sub-pixel in depth: a plate 1e-4 deep (a tenth of a unit in the last place) quantizes to
    // F = B, and the close (convex, Z_F >= Z_B) puts maxdepth: the array does not draw it.
    // Float does; the difference is a near tie (margin 1e-4 < 2e).
    let plate = list(vec![
        pl(10.0001, 0.0, 0.0, 2, true, false, false),
        pl(10.0002, 0.0, 0.0, 3, false, false, false),
    ]);
    let cfg = ArrayConfig::new(4, 4);
    let (g, _, f) = lists_vs_float(std::slice::from_ref(&plate), None, cfg);
    assert!(g.iter().all(|&v| v == 0));
    assert!(f.colour.iter().all(|&v| v == 2));
    let a = agreement(&g, std::slice::from_ref(&plate), None, 4, 4, &fmt);
    assert_eq!(a.near_tie, 16);
    // A plate one unit deep is drawn by both.
    let plate = list(vec![
        pl(10.0, 0.0, 0.0, 2, true, false, false),
        pl(10.0 + fmt.to_real(1), 0.0, 0.0, 3, false, false, false),
    ]);
    let (g, _, f) = lists_vs_float(std::slice::from_ref(&plate), None, cfg);
    assert!(g.iter().all(|&v| v == 2) && f.colour.iter().all(|&v| v == 2));
}

// ---------------------------------------------------------------------------------------------
// Scenes of 1000+ primitives.

/// A union of `k`×`k` unit-spaced cubes 0.8 wide, each at its own height.
fn many_cubes(k: usize) -> String {
    let mut t = String::from("union() {\n");
    for i in 0..k * k {
        let (x, y, z) = ((i % k) as f64, (i / k) as f64, (i % 7) as f64 * 0.5);
        t += &format!(
            "multmatrix([[1, 0, 0, {x}], [0, 1, 0, {y}], [0, 0, 1, {z}], [0, 0, 0, 1]]) cube(size = 0.8);\n"
        );
    }
    t + "}\n"
}

#[test]
fn a_thousand_and_twenty_four_primitives() {
    let text = many_cubes(32);
    let scene = parse_csg(&text, "many.csg").unwrap();
    assert_eq!(scene.solids.len(), 1024);
    // The Blist of a union: every row stamps IN (1) when inside and passes 0 on: names 0 and
    // 1 only, a 1-bit label register, whatever the number of primitives (§4.3.2).
    let table = BlistTable::compile(&scene.root);
    assert_eq!(table.rows.len(), 1024);
    assert_eq!(table.label_bits, 1);
    for probe in [0usize, 1, 513, 1023] {
        assert!(table.classify(|p| p == probe, None));
    }
    assert!(!table.classify(|_| false, None));
    // The array image against float on 48×48 (top view): every difference explained.
    let fmt = WordFormat::THESIS;
    let p = project::project(&scene, View::Top, 48, 48, &fmt).unwrap();
    let (g, _, _) = lists_vs_float(&p.lists, p.clip.as_ref(), ArrayConfig::new(48, 48));
    let drawn = g.iter().filter(|&&v| v != 0).count();
    assert!(drawn > 0);
    // Voxelize through the CLI: Blist and tree evaluation fill the same voxels.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("many.csg");
    std::fs::write(&path, &text).unwrap();
    let mut filled = vec![];
    for eval in ["blist", "tree"] {
        let out_path = dir.path().join(format!("{eval}.nrrd"));
        let out = csgpix(&[
            "voxelize",
            s(&path),
            "--res",
            "64x64x64",
            "--eval",
            eval,
            "-o",
            s(&out_path),
            "--json",
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["label_bits"], 1);
        assert_eq!(v["blist_rows"], 1024);
        filled.push(v["filled"].as_u64().unwrap());
        println!(
            "1024 cubes, 64^3, --eval {eval}: {} filled, {} label bits, {} s wall",
            v["filled"], v["label_bits"], v["wall_seconds"]
        );
    }
    assert!(filled[0] > 0 && filled[0] == filled[1], "{filled:?}");
    println!("1024 cubes, 48x48 top view: {drawn} pixels drawn, word = cycle, float agrees");
}

// ---------------------------------------------------------------------------------------------
// CSG trees 100,000 deep (crates/voxel/tests/blist.rs covers Blist compilation of 100,000-level trees and
// tests/cli_blist.rs a 60,000-deep EXPR; crates/openscad/src the reader's limit on a string).

#[test]
fn trees_100000_deep_from_a_file_are_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("deep.csg");
    let depth = 100_000;
    let text = "union() {\n".repeat(depth) + "cube(1);\n" + &"}\n".repeat(depth);
    std::fs::write(&path, &text).unwrap();
    let limit = csgpix::openscad::MAX_NESTING;
    let want = format!(
        "csgpix: {}:{}:1: statements nested deeper than {limit} levels",
        path.display(),
        limit + 1
    );
    for (cmd, out_name) in [("render", "deep.png"), ("voxelize", "deep.nrrd")] {
        let out_path = dir.path().join(out_name);
        let mut args = vec![cmd, s(&path), "-o", s(&out_path)];
        if cmd == "voxelize" {
            args.extend(["--res", "8x8x8"]);
        }
        let out = csgpix(&args);
        assert_eq!(out.status.code(), Some(2), "{cmd}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{cmd}: {err}");
        assert!(err.starts_with(&want), "{cmd}: {err}");
        assert!(!out_path.exists());
    }
    // The same in the library, on this test thread's stack.
    let e = parse_csg(&text, "deep.csg").unwrap_err();
    assert!(e
        .to_string()
        .starts_with(&format!("deep.csg:{}:1: ", limit + 1)));
    // `csgpix blist`: 100,000 nested `!` (one argument holds 100,001 bytes) is refused at the
    // expression parser's limit, in one line.
    let expr = "!".repeat(depth) + "A";
    let out = csgpix(&["blist", &expr]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1);
    let max = csgpix::scene::csg_expr::MAX_DEPTH;
    assert!(
        err.starts_with(&format!("csgpix: EXPR:1:{}: ", max + 1)),
        "{err}"
    );
    // A tree just under the file limit (999 nested differences) is read, compiled to a Blist
    // and classified on the default test stack; its label register stays small.
    let deep = "difference() { cube(1);\n".repeat(limit - 1) + "cube(1);" + &"}".repeat(limit - 1);
    let scene = parse_csg(&deep, "deep999.csg").unwrap();
    assert_eq!(scene.solids.len(), limit);
    let table = BlistTable::compile(&scene.root);
    assert_eq!(table.rows.len(), limit);
    // c0 − (c1 − (… − (c998 − c999))): with a voxel inside every cube, c998 − c999 is out,
    // c997 − out is in, …: 999 alternations from "c999 in" leave c0's result out.
    let mut inside = true;
    for _ in 0..limit - 1 {
        inside = !inside;
    }
    assert_eq!(table.classify(|_| true, None), inside);
    assert!(table.classify(|p| p == 0, None));
    println!(
        "999 nested differences: {} Blist rows, {} label bits",
        table.rows.len(),
        table.label_bits
    );
}

/// Scenes thinner than a voxel (a grid one voxel high or deep) are voxelized, not refused:
/// `cube([50, 1, 1])` at `--res 32` made a perpendicular plane's dKy one past the word. Every
/// model gives the voxels of direct evaluation at the voxel centres (a bar, a sliver, and a bar
/// with 40 slots cut across it).
#[test]
fn scenes_thinner_than_a_voxel_are_voxelized() {
    let dir = tempfile::tempdir().unwrap();
    // Slots 0.5 wide every 1.25 units, through the bar's whole height and depth.
    let slot = |i: usize| 1.0 + 1.25 * i as f64;
    let slots: String = (0..40)
        .map(|i| {
            format!(
                "multmatrix([[1,0,0,{}],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube([0.5, 1, 1]);\n",
                slot(i)
            )
        })
        .collect();
    let in_bar = |x: f64, len: f64| (0.0..=len).contains(&x);
    let in_slot = |x: f64| (0..40).any(|i| (slot(i)..=slot(i) + 0.5).contains(&x));
    /// A scene: its name, its text, and which X its voxel centres are inside at.
    type Thin<'a> = (&'a str, String, &'a dyn Fn(f64) -> bool);
    let scenes: [Thin; 3] = [
        ("bar", "cube([50, 1, 1]);".into(), &|x| in_bar(x, 50.0)),
        ("sliver", "cube([50, 0.1, 0.1]);".into(), &|x| {
            in_bar(x, 50.0)
        }),
        (
            "slots",
            format!("difference() {{ cube([51, 1, 1]);\n{slots}}}"),
            &|x| in_bar(x, 51.0) && !in_slot(x),
        ),
    ];
    for (name, text, inside) in scenes {
        let csg = dir.path().join(format!("{name}.csg"));
        std::fs::write(&csg, text).unwrap();
        for model in ["word", "cycle", "float"] {
            let out = dir.path().join(format!("{name}-{model}.nrrd"));
            let args = [
                "voxelize",
                s(&csg),
                "--res",
                "32",
                "--model",
                model,
                "--json",
            ];
            let o = csgpix(&[&args[..], &["-o", s(&out)]].concat());
            let e = String::from_utf8_lossy(&o.stderr);
            assert!(o.status.success(), "{name} {model}: {e}");
            let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
            let (x0, h) = (
                r["min"][0].as_f64().unwrap(),
                r["voxel"][0].as_f64().unwrap(),
            );
            let (dims, v) = csgpix::scene::nrrd::read(&std::fs::read(&out).unwrap()).unwrap();
            assert_eq!(dims[1] * dims[2], 1, "{name}: one voxel thick");
            // The one row's centres lie inside the bar's height and depth: X decides.
            let want: Vec<bool> = (0..dims[0])
                .map(|i| inside(x0 + (i as f64 + 0.5) * h))
                .collect();
            let got: Vec<bool> = v.iter().map(|&c| c != 0).collect();
            assert_eq!(got, want, "{name} {model}");
        }
    }
}
