//! The throughput equations against every printed figure of §2.5 and §5.5, and a scene's
//! per-panel clocks against the cycle model (docs/throughput.md).

mod common;
use common::csgpix;

use std::path::Path;

use csgpix::draw::panels::{
    bins, count_cycles, estimate, panel_work, presence, tiling, translate, PanelScene,
};
use csgpix::draw::project::View;
use csgpix::draw::throughput::{
    panel_surfaces_per_frame, slices_per_second, surfaces_per_frame, surfaces_per_second,
    table_2_1, table_panels, Hardware, Reading,
};
use csgpix::openscad::parse_csg;
use rtl_model::array::program_cycles;
use rtl_model::program::CReg;
use rtl_model::{Array, CycleArray, Equations, WordFormat};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// Rows of a vectors file: whitespace-separated fields, `#` comments dropped.
fn rows(name: &str) -> Vec<Vec<String>> {
    let text =
        std::fs::read_to_string(Path::new(ROOT).join("vectors/throughput").join(name)).unwrap();
    text.lines()
        .map(|l| l.split('#').next().unwrap().split_whitespace())
        .map(|f| f.map(String::from).collect::<Vec<_>>())
        .filter(|f| !f.is_empty())
        .collect()
}

/// Table 2.1 as printed: (panel side, surfaces per frame).
fn table_2_1_printed() -> Vec<(usize, f64)> {
    rows("table-2.1.txt")
        .iter()
        .map(|r| (r[0].parse().unwrap(), r[1].parse().unwrap()))
        .collect()
}

fn printed(name: &str) -> f64 {
    let r = rows("printed.txt");
    r.iter().find(|r| r[0] == name).unwrap()[1].parse().unwrap()
}

#[test]
fn worked_examples_of_2_5_and_5_5_follow_eq_2_3_and_2_4() {
    let hw = Hardware::default();
    assert_eq!(surfaces_per_second(&hw), printed("P"));
    assert_eq!(surfaces_per_frame(&hw), printed("P_R"));
}

#[test]
fn table_2_1_follows_the_inverted_ratio_row_for_row() {
    let hw = Hardware::default();
    let table = table_2_1_printed();
    let panels: Vec<(usize, usize)> = table.iter().map(|&(n, _)| (n, n)).collect();
    assert_eq!(panels, table_panels((1024, 1024)), "Table 2.1's panels");
    for (row, &(n, want)) in table_2_1(&hw, (1024, 1024), &panels).iter().zip(&table) {
        // Printed as integers; every value is exact.
        assert_eq!(row.table, want, "{n}x{n}");
    }
}

#[test]
fn the_printed_eq_2_5_does_not_give_table_2_1() {
    let hw = Hardware::default();
    // M_P = 1: 6250 · n²/1024², worked by hand (6250 / 4^k).
    let by_hand = [
        1562.5,
        390.625,
        97.65625,
        24.4140625,
        6.103515625,
        1.52587890625,
        0.3814697265625,
    ];
    // The M_P that would make the printed equation give the table: (1024²/n²)², by hand.
    let mp_needed = [
        16.0,
        256.0,
        4096.0,
        65536.0,
        1048576.0,
        16777216.0,
        268435456.0,
    ];
    for (i, &(n, table)) in table_2_1_printed().iter().enumerate() {
        let mp1 = panel_surfaces_per_frame(&hw, (1024, 1024), (n, n), Reading::PrintedMp1);
        assert_eq!(mp1, by_hand[i], "{n}x{n}");
        assert_eq!(table / mp1, mp_needed[i], "{n}x{n}");
        // M_P = number of panels: 6250 whatever the panel.
        let mpk = panel_surfaces_per_frame(&hw, (1024, 1024), (n, n), Reading::PrintedMpPanels);
        assert_eq!(mpk, 6250.0);
        assert_ne!(mpk, table);
    }
}

#[test]
fn the_20_million_of_5_5_is_table_2_1s_128_row_not_a_128_screen() {
    let hw = Hardware::default();
    let stated = printed("P_R_5.5");
    // Table 2.1's 128x128 row (400000 surfaces per 1/50 s frame) per second.
    let row_128 = table_2_1_printed().iter().find(|r| r.0 == 128).unwrap().1;
    assert_eq!(row_128 * 50.0, stated);
    let panels_128 =
        panel_surfaces_per_frame(&hw, (1024, 1024), (128, 128), Reading::Table) / hw.frame_s;
    assert_eq!(panels_128, stated);
    // One array on a 128x128 screen (eq. 5.2, independent of the screen): 64 times less.
    assert_eq!(surfaces_per_second(&hw), 312_500.0);
    assert_eq!(stated / surfaces_per_second(&hw), 64.0);
    // Eq. 5.1 with that P_R for a cube (6 surfaces): 20e6 / 6, by hand.
    assert!((slices_per_second(stated, 6.0) - 3_333_333.333_333).abs() < 1e-3);
}

fn scene(name: &str) -> csgpix::scene::solid::CsgScene {
    let path = Path::new(ROOT).join("vectors/scenes").join(name);
    parse_csg(&std::fs::read_to_string(&path).unwrap(), name).unwrap()
}

fn thesis_word() -> WordFormat {
    WordFormat::new(10, 10, 11).unwrap()
}

/// The colour codes (G) the cycle model leaves after `ops` on an array of `cfg`, and its
/// clock count.
fn run(cfg: &rtl_model::ArrayConfig, ops: &[rtl_model::Op]) -> (Vec<u32>, u64) {
    let mut arr = CycleArray::new(*cfg, Equations::Derived.set());
    arr.run(ops).unwrap();
    let g = arr.state().pixels.iter().map(|p| p.creg(CReg::G)).collect();
    (g, arr.cycles())
}

/// Every panel's program on its own cycle-model array: the clocks equal the counted ones,
/// and the panels' images put side by side are the whole screen's image.
fn check_panels_through_the_simulator(
    name: &str,
    screen: (usize, usize),
    panel: (usize, usize),
) -> Vec<csgpix::draw::panels::PanelWork> {
    let ps = PanelScene::new(&scene(name), View::Iso, screen, thesis_word()).unwrap();
    let work = panel_work(&ps, panel, &count_cycles).unwrap();
    let cfg = ps.panel_config(panel);
    let whole = run(
        &ps.panel_config(screen),
        &ps.frame_ops(&vec![true; ps.lists.len()]).unwrap(),
    )
    .0;
    for w in &work {
        let (x0, y0) = (w.col * panel.0, w.row * panel.1);
        let mut ops = ps.frame_ops(&presence(&w.prims, ps.lists.len())).unwrap();
        translate(&mut ops, x0, y0);
        let (g, clocks) = run(&cfg, &ops);
        assert_eq!(clocks, w.frame_cycles, "{name} panel {},{}", w.col, w.row);
        let slice: u64 = w
            .prims
            .iter()
            .map(|&p| run(&cfg, &ps.slice_ops(p).unwrap()).1)
            .sum();
        assert_eq!(slice, w.slice_cycles, "{name} panel {},{}", w.col, w.row);
        for y in 0..panel.1.min(screen.1 - y0) {
            for x in 0..panel.0.min(screen.0 - x0) {
                let (a, b) = (g[y * panel.0 + x], whole[(y0 + y) * screen.0 + x0 + x]);
                assert_eq!(a, b, "{name} pixel {},{}", x0 + x, y0 + y);
            }
        }
    }
    work
}

#[test]
fn panel_clocks_and_images_agree_with_the_cycle_model_2x2() {
    let work = check_panels_through_the_simulator("cube-minus-cylinder.csg", (48, 48), (24, 24));
    assert_eq!(work.len(), 4);
}

#[test]
fn panel_clocks_and_images_agree_with_the_cycle_model_partial_panels() {
    // 3x3 panels of 20 over 56 pixels: the last row and column hang over the edge, and
    // several panels hold only some of the four solids.
    let work = check_panels_through_the_simulator("figure-5.2.csg", (56, 56), (20, 20));
    // The restriction is exercised: some panels hold some but not all of the solids.
    assert!(work
        .iter()
        .any(|w| !w.prims.is_empty() && w.prims.len() < 4));
}

#[test]
fn the_slowest_panel_is_the_frame() {
    let hw = Hardware::default();
    for name in ["csg-logo.csg", "twelve.csg", "figure-5.2.csg"] {
        let ps = PanelScene::new(&scene(name), View::Iso, (128, 128), thesis_word()).unwrap();
        let all = vec![true; ps.lists.len()];
        let one = program_cycles(&ps.panel_config((128, 128)), &ps.frame_ops(&all).unwrap());
        let work = panel_work(&ps, (32, 32), &count_cycles).unwrap();
        let e = estimate(&ps, &hw, (32, 32), &work, one);
        assert!(
            work.iter().all(|w| w.frame_cycles <= e.frame_cycles),
            "{name}"
        );
        let slowest = work.iter().find(|w| (w.col, w.row) == e.slowest).unwrap();
        assert_eq!(slowest.frame_cycles, e.frame_cycles, "{name}");
        let rel = |a: f64, b: f64| ((a - b) / b).abs() < 1e-12;
        assert!(rel(e.frame_s, e.frame_cycles as f64 / 10e6), "{name}");
        assert!(rel(e.fps, 10e6 / e.frame_cycles as f64), "{name}");
        // A panel holding every solid runs the whole program; DEPGEN's tree is 2 levels
        // shorter on 32x32 than on 128x128 (log2 128 + 1 = 8 against 6: §2.4).
        if let Some(full) = work.iter().find(|w| w.prims.len() == ps.lists.len()) {
            assert_eq!(full.frame_cycles + 2, one, "{name}");
        }
    }
}

#[test]
fn a_scene_in_two_corners_touches_only_those_panels() {
    // Two unit cubes at opposite corners of a 10 x 10 square, seen from the top on 64x64:
    // scale 63/10 = 6.3 pixels per unit, screen y = (10 − Y) · 6.3. Cube A (0..1, 0..1)
    // covers x 0..6.3, y 56.7..63: pixels 0..7 × 56..63, panel column 0, row 7 of 8x8
    // panels. Cube B (9..10, 9..10) covers x 56.7..63, y 0..6.3: column 7, row 0.
    let text = "union() {\n cube(size = [1, 1, 1]);\n \
                multmatrix([[1, 0, 0, 9], [0, 1, 0, 9], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = [1, 1, 1]);\n}\n";
    let sc = parse_csg(text, "corners.csg").unwrap();
    let ps = PanelScene::new(&sc, View::Top, (64, 64), thesis_word()).unwrap();
    assert_eq!(
        ps.footprints,
        vec![Some((0, 56, 7, 63)), Some((56, 0, 63, 7))]
    );
    let b = bins(&ps.footprints, (64, 64), (8, 8));
    assert_eq!(tiling((64, 64), (8, 8)), (8, 8));
    for (k, prims) in b.iter().enumerate() {
        let want: Vec<usize> = match (k % 8, k / 8) {
            (0, 7) => vec![0],
            (7, 0) => vec![1],
            _ => vec![],
        };
        assert_eq!(prims, &want, "panel {},{}", k % 8, k / 8);
    }
    let work = panel_work(&ps, (8, 8), &count_cycles).unwrap();
    let busy: Vec<(usize, usize)> = work
        .iter()
        .filter(|w| w.frame_cycles > 0)
        .map(|w| (w.col, w.row))
        .collect();
    assert_eq!(busy, vec![(7, 0), (0, 7)]);
    // One cube from the top: its top face (front), four side faces (perpendicular, Y) and
    // its bottom face (back), so 6 plane windows, a close (it has a back plane) and a
    // compose, each N_D = 32 clocks; one flush window that carries out the last code
    // (docs/microarchitecture.md); DEPGEN's fill of log2(8) + 1 = 4 clocks:
    // (6 + 1 + 1 + 1) · 32 + 4 = 292.
    for w in work.iter().filter(|w| w.frame_cycles > 0) {
        assert_eq!(w.frame_cycles, 292, "panel {},{}", w.col, w.row);
    }
}

#[test]
fn cli_prints_table_2_1_as_json() {
    let out = csgpix(&["throughput", "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let got: Vec<f64> = v["panels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["table"].as_f64().unwrap())
        .collect();
    let want: Vec<f64> = table_2_1_printed().iter().map(|r| r.1).collect();
    assert_eq!(got, want);
    assert_eq!(v["surfaces_per_second"].as_f64(), Some(printed("P")));
}

#[test]
fn cli_scene_estimate_and_errors() {
    let out = csgpix(&[
        "throughput",
        "--scene",
        "vectors/scenes/cube-minus-cylinder.csg",
        "--screen",
        "48x48",
        "--panel",
        "24x24",
        "--simulate",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let s = &v["scene"];
    assert_eq!(s["per_panel"].as_array().unwrap().len(), 4);
    let e = &s["estimates"][0];
    let max = s["per_panel"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["frame_cycles"].as_u64().unwrap())
        .max();
    assert_eq!(e["frame_cycles"].as_u64(), max);
    for bad in [
        vec!["throughput", "--panel", "0x8"],
        vec!["throughput", "--clock", "-1"],
        vec![
            "throughput",
            "--scene",
            "vectors/scenes/twelve.csg",
            "--word",
            "10/10/10",
        ],
        vec!["throughput", "--scene", "no-such.csg"],
    ] {
        let out = csgpix(&bad);
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{bad:?}: {err}");
    }
}

/// `--area`: 100,000 LUT6 at 107 LUT6 a pixel hold 934 processors (100,000 / 107 = 934.6), so
/// of Table 2.1's panels only 16x16 (256 · 107 = 27,392) and 8x8 (6,848) fit; 32x32 needs
/// 1024 · 107 = 109,568.
#[test]
fn area_budget_picks_the_panels_that_fit() {
    let out = csgpix(&["throughput", "--area", "100000", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let a = &v["area"];
    assert_eq!(a["processors"], 934);
    let rows = a["panels"].as_array().unwrap();
    let fits: Vec<(u64, bool)> = rows
        .iter()
        .map(|r| {
            (
                r["panel"][0].as_u64().unwrap(),
                r["fits"].as_bool().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        fits,
        [
            (512, false),
            (256, false),
            (128, false),
            (64, false),
            (32, false),
            (16, true),
            (8, true)
        ]
    );
    assert_eq!(rows[4]["luts"], 109_568);
    let bad = csgpix(&["throughput", "--area", "100", "--lut", "5"]);
    assert_eq!(bad.status.code(), Some(2));
}
