//! A black-box fuzzing campaign at the command line (docs/stability.md, "The command line
//! under fuzzing"): every subcommand, every input kind and option, mutated inputs and
//! arguments, outputs onto new files, symlinks, FIFOs, directories and devices, some runs
//! interrupted by a signal at a random time, all under a 4 GiB address-space limit. Each run
//! is classified as a success, a clean refusal or a failure:
//!
//! - success: exit 0, nothing on standard error but notes and the report;
//! - clean refusal: exit 2, exactly one line (`csgpix: …`, no control character) besides
//!   notes and the scene's warnings (`csgpix: warning: FILE:LINE:COL: …`, a line each, as
//!   OpenSCAD warns: a file that draws nothing, then the refusal of an empty scene), and no
//!   output written;
//! - interrupted: killed by the signal it was sent (or finished before it);
//! - standard output closed (some runs' standard output is a pipe without a reader): exit 2,
//!   one line `csgpix: cannot write to standard output: …`, the outputs already whole kept;
//! - failure: anything else (an abort, a panic, another status, a run past the time limit,
//!   several lines, a control character echoed, a staging file or a partial output left, a
//!   symlink replaced).
//!
//! Every run leaves no staging file (`.NAME.*.csgpix-*`) behind. Failures are written to
//! `target/cli-fuzz/failures/` as regression cases (`args` and the input files); copied to
//! `tests/cli_fuzz/regressions/`, they are replayed first by every later run.
//!
//! The test runs for `CSGPIX_CLI_FUZZ_SECONDS` (default 60) from seed
//! `CSGPIX_CLI_FUZZ_SEED` (default 1, so CI is deterministic in what it tries), on
//! `CSGPIX_CLI_FUZZ_JOBS` threads (default 2); `CSGPIX_CLI_FUZZ_CASES` caps the cases.
//! `CSGPIX_CLI_FUZZ_BIN` runs another csgpix binary than the one built with the test (a
//! copy, so a long campaign is not changed under it by a rebuild).

use std::fs;
use std::io::Read;
use std::os::unix::ffi::OsStrExt;
use std::os::unix::process::{CommandExt, ExitStatusExt};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The address space every run gets (`ulimit -v`).
const ADDRESS_SPACE: u64 = 4 << 30;
/// A run still going after this long is a failure (a slow path to find).
const TIME_LIMIT: Duration = Duration::from_secs(60);

/// A small deterministic generator (xorshift64*): the same seed tries the same cases.
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Rng {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn chance(&mut self, percent: u64) -> bool {
        self.next() % 100 < percent
    }
    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// Tokens a mutation inserts: numbers at the extremes, syntax, control characters.
const TOKENS: &[&str] = &[
    "1e-300",
    "-1e-300",
    "5e-324",
    "1e308",
    "-1e308",
    "1e400",
    "NaN",
    "nan",
    "inf",
    "-inf",
    "-0",
    "0",
    "99999999999999999999",
    "0x10",
    "1_000",
    ".",
    "-",
    "+",
    ",",
    ";",
    "(",
    ")",
    "{",
    "}",
    "[",
    "]",
    "(((((((((",
    ")))))",
    "union(){",
    "difference(){",
    "cube(",
    "sphere(r=",
    "multmatrix([[",
    "\0",
    "\x0b",
    "\x0c",
    "\u{85}",
    "\u{2028}",
    "\r",
    "\n",
    "\t",
    "é",
    "\u{fffd}",
    "$fn=1000000;",
    "$fn=0;",
    "A",
    "!",
    ".!",
    "+",
    "solid",
    "endsolid",
    "facet normal",
    "v ",
    "f 1 2 3",
    "sizes: ",
    "type: ",
    "encoding: gzip",
    "dimension: 3",
    "space directions: ",
    "NRRD0004",
    "#",
    "//",
    "/*",
    "\"",
    "'",
];

/// Seeds of every input kind, by extension: the bundled inputs.
fn seeds() -> Vec<(&'static str, Vec<u8>)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors");
    let files = [
        ("dl", "thesis/cube.dl"),
        ("dl", "thesis/box1.dl"),
        ("dl", "thesis/box2.dl"),
        ("csg", "scenes/twelve.csg"),
        ("csg", "scenes/figure-5.2.csg"),
        ("csg", "scenes/hollow-cube.csg"),
        ("csg", "scenes/cube-minus-cylinder.csg"),
        ("csg", "scenes/table-7.1-cube.csg"),
        ("csv", "paths/carve.csv"),
        ("pla", "select/front.pla"),
        ("pla", "select/second.pla"),
        // What a scene imports (`imported`): drawings, meshes, height maps, a font.
        ("svg", "openscad/svg/rect.svg"),
        ("svg", "openscad/svg/units.svg"),
        ("dxf", "openscad/dxf/lines.dxf"),
        ("dxf", "openscad/dxf/arcs.dxf"),
        ("off", "openscad/imports/cube-off.off"),
        ("amf", "openscad/imports/cube.amf"),
        ("amf", "openscad/imports/zipped.amf"),
        ("3mf", "openscad/imports/cube.3mf"),
        ("png", "openscad/surface/grey.png"),
        ("png", "openscad/surface/palette.png"),
        ("dat", "openscad/surface/comments.dat"),
        ("ttf", "fonts/LiberationSans-Regular.ttf"),
    ];
    let mut out: Vec<(&str, Vec<u8>)> = files
        .iter()
        .map(|(ext, p)| (*ext, fs::read(root.join(p)).unwrap()))
        .collect();
    out.push(("stl", ascii_stl()));
    out.push(("obj", obj_cube()));
    out.push(("nrrd", small_nrrd()));
    out
}

/// A closed tetrahedron as ASCII STL.
fn ascii_stl() -> Vec<u8> {
    let v = [[0., 0., 0.], [4., 0., 0.], [0., 4., 0.], [0., 0., 4.]];
    let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    let mut s = String::from("solid t\n");
    for f in faces {
        s += "facet normal 0 0 0\nouter loop\n";
        for i in f {
            let p: [f64; 3] = v[i];
            s += &format!("vertex {} {} {}\n", p[0], p[1], p[2]);
        }
        s += "endloop\nendfacet\n";
    }
    s += "endsolid t\n";
    s.into_bytes()
}

/// A unit cube as OBJ.
fn obj_cube() -> Vec<u8> {
    let mut s = String::new();
    for i in 0..8 {
        s += &format!("v {} {} {}\n", i & 1, (i >> 1) & 1, (i >> 2) & 1);
    }
    for f in [
        [1, 3, 4, 2],
        [5, 6, 8, 7],
        [1, 2, 6, 5],
        [3, 7, 8, 4],
        [1, 5, 7, 3],
        [2, 4, 8, 6],
    ] {
        s += &format!("f {} {} {} {}\n", f[0], f[1], f[2], f[3]);
    }
    s.into_bytes()
}

/// An 8³ uint8 NRRD volume with a ball in it.
fn small_nrrd() -> Vec<u8> {
    let mut b =
        b"NRRD0004\ntype: uint8\ndimension: 3\nsizes: 8 8 8\nspacings: 1 1 1\nencoding: raw\n\n"
            .to_vec();
    for i in 0..512i32 {
        let (x, y, z) = (i % 8 - 4, (i / 8) % 8 - 4, i / 64 - 4);
        b.push(if x * x + y * y + z * z < 9 { 200 } else { 0 });
    }
    b
}

/// 0-4 mutations of `data`: flips, cuts, copies, tokens, truncation.
fn mutate(rng: &mut Rng, data: &[u8]) -> Vec<u8> {
    let mut d = data.to_vec();
    for _ in 0..rng.below(5) {
        let at = rng.below(d.len() + 1);
        match rng.below(6) {
            0 if !d.is_empty() => {
                let i = at.min(d.len() - 1);
                d[i] ^= 1 << rng.below(8);
            }
            1 => {
                let end = (at + rng.below(16)).min(d.len());
                d.drain(at..end);
            }
            2 => {
                let end = (at + rng.below(64)).min(d.len());
                let copy = d[at..end].to_vec();
                let to = rng.below(d.len() + 1);
                d.splice(to..to, copy);
            }
            3 => d.truncate(at),
            _ => {
                let t = rng.pick(TOKENS).as_bytes().to_vec();
                d.splice(at..at, t);
            }
        }
    }
    d
}

/// An input file of the case, its bytes and extension.
#[derive(Clone, Debug)]
struct Input {
    ext: String,
    bytes: Vec<u8>,
}

/// How the case's output path is prepared before the run.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Target {
    New,
    Existing,
    Symlink,
    Fifo,
    Directory,
    DevNull,
    MissingDir,
}

/// One run: arguments (`{IN0}`, `{IN1}`, `{OUT}`, `{OUT2}`, `{DIR}` filled in per run).
#[derive(Clone, Debug)]
struct Case {
    args: Vec<Vec<u8>>,
    inputs: Vec<Input>,
    target: Target,
    out_ext: String,
    signal: Option<(i32, u64)>,
    /// Standard output is a pipe whose reader has gone (`| head` after it exits).
    closed_stdout: bool,
}

/// Values of an option: mostly valid, some not.
fn value(rng: &mut Rng, good: &[&str], bad: &[&str]) -> Vec<u8> {
    let v = if rng.chance(80) || bad.is_empty() {
        rng.pick(good)
    } else {
        rng.pick(bad)
    };
    v.as_bytes().to_vec()
}

/// An argument mutated: a token, a control character, bytes that are not UTF-8.
fn bad_arg(rng: &mut Rng) -> Vec<u8> {
    match rng.below(4) {
        0 => vec![0xff, 0xfe, b'x'],
        1 => rng.pick(TOKENS).as_bytes().to_vec(),
        2 => format!("{}", rng.next() as i64).into_bytes(),
        _ => b"\x1b[31mred\x07".to_vec(),
    }
}

fn opt(args: &mut Vec<Vec<u8>>, rng: &mut Rng, p: u64, flag: &str, good: &[&str], bad: &[&str]) {
    if rng.chance(p) {
        args.push(flag.as_bytes().to_vec());
        args.push(value(rng, good, bad));
    }
}

fn flag(args: &mut Vec<Vec<u8>>, rng: &mut Rng, p: u64, name: &str) {
    if rng.chance(p) {
        args.push(name.as_bytes().to_vec());
    }
}

const RES: &[&str] = &["8", "16", "24", "5x7x9", "1", "16x16x16", "32"];
const BAD_RES: &[&str] = &["0", "-1", "8x8", "1e9", "100000", "x", "16x16x16x16", ""];
const WORD: &[&str] = &["10/10/11", "4/6/3", "12/12/7", "1/1/1"];
const BAD_WORD: &[&str] = &["0/0/0", "40/40/40", "10/10", "a/b/c", "-1/2/3"];
const SIZE: &[&str] = &["16x16", "64x48", "1x1", "250x250"];
const BAD_SIZE: &[&str] = &["0x0", "99999999x99999999", "16", "16x", "-5x5"];
const BOUNDS: &[&str] = &["-20,-20,-20,20,20,20", "0,0,0,1,1,1"];
const BAD_BOUNDS: &[&str] = &[
    "1,1,1,0,0,0",
    "nan,0,0,1,1,1",
    "1e308,0,0,1e309,1,1",
    "1,2,3",
];

/// A case of a random subcommand.
fn case(rng: &mut Rng, seeds: &[(&'static str, Vec<u8>)]) -> Case {
    let of = |ext: &str, rng: &mut Rng| -> Input {
        let pool: Vec<&(&str, Vec<u8>)> = seeds.iter().filter(|(e, _)| *e == ext).collect();
        let (_, bytes) = rng.pick(&pool);
        let bytes = if rng.chance(70) {
            mutate(rng, bytes)
        } else {
            bytes.clone()
        };
        Input {
            ext: ext.into(),
            bytes,
        }
    };
    let mut args: Vec<Vec<u8>> = vec![];
    let mut inputs = vec![];
    let a = |s: &str| s.as_bytes().to_vec();
    let out_ext: &str = match rng.below(11) {
        9 => return imported(rng, &of),
        10 => return verilog_scene(rng, &of),
        0 | 1 => {
            args.push(a("render"));
            let ext = *rng.pick(&["dl", "dl", "csg"]);
            inputs.push(of(ext, rng));
            args.push(a("{IN0}"));
            if ext == "dl" && rng.chance(30) {
                inputs.push(of("dl", rng));
                args.push(a("{IN1}"));
                opt(
                    &mut args,
                    rng,
                    70,
                    "--clip",
                    &["A.!B", "A+B", "A.B"],
                    &["A.", "C", "(("],
                );
            }
            opt(&mut args, rng, 60, "--size", SIZE, BAD_SIZE);
            opt(
                &mut args,
                rng,
                40,
                "--model",
                &["cycle", "word", "float"],
                &["x"],
            );
            opt(&mut args, rng, 20, "--word", WORD, BAD_WORD);
            opt(
                &mut args,
                rng,
                15,
                "--equations",
                &["derived", "printed"],
                &["y"],
            );
            opt(
                &mut args,
                rng,
                15,
                "--ties",
                &["minimal", "keep", "put"],
                &["z"],
            );
            opt(
                &mut args,
                rng,
                15,
                "--panel",
                &["8x8", "16x4"],
                &["0x0", "1x99999999"],
            );
            opt(
                &mut args,
                rng,
                10,
                "--view",
                &["top", "front", "iso"],
                &["side"],
            );
            opt(
                &mut args,
                rng,
                10,
                "--stack-depth",
                &["1", "4"],
                &["0", "99999999999"],
            );
            flag(&mut args, rng, 15, "--shade");
            flag(&mut args, rng, 15, "--json");
            "png"
        }
        2 | 3 => {
            args.push(a("voxelize"));
            if rng.chance(75) {
                inputs.push(of("csg", rng));
                args.push(a("{IN0}"));
            } else {
                let ext = *rng.pick(&["stl", "obj", "nrrd", "csg"]);
                inputs.push(of(ext, rng));
                args.push(a("--expr"));
                args.push(value(rng, &["a", "!a", "a-a", "a.a+a"], &["a-", "b", "(a"]));
                args.push(a("--prim"));
                let bind = if ext == "nrrd" {
                    "a={IN0},threshold=100"
                } else {
                    "a={IN0}"
                };
                args.push(a(bind));
            }
            opt(&mut args, rng, 80, "--res", RES, BAD_RES);
            opt(
                &mut args,
                rng,
                15,
                "--route",
                &["runs", "intervals", "array"],
                &["q"],
            );
            opt(
                &mut args,
                rng,
                15,
                "--eval",
                &["blist", "tree", "stack"],
                &["q"],
            );
            opt(
                &mut args,
                rng,
                15,
                "--sampling",
                &["centre", "slab"],
                &["q"],
            );
            opt(
                &mut args,
                rng,
                15,
                "--model",
                &["cycle", "word", "float"],
                &["q"],
            );
            opt(
                &mut args,
                rng,
                10,
                "--pad",
                &["0", "2"],
                &["-1", "99999999"],
            );
            opt(&mut args, rng, 10, "--bounds", BOUNDS, BAD_BOUNDS);
            opt(&mut args, rng, 10, "--word", WORD, BAD_WORD);
            opt(
                &mut args,
                rng,
                10,
                "--threads",
                &["1", "2", "3"],
                &["0", "100000"],
            );
            opt(&mut args, rng, 10, "--panel", &["4x4", "16x16"], &["0x0"]);
            flag(&mut args, rng, 10, "--grey");
            flag(&mut args, rng, 10, "--json");
            let zarr = rng.chance(20);
            let out_ext = if zarr {
                opt(
                    &mut args,
                    rng,
                    50,
                    "--chunk",
                    &["4", "8x4x2", "1"],
                    &["0", "3x3"],
                );
                opt(&mut args, rng, 30, "--shard", &["2", "none"], &["0", "x"]);
                opt(&mut args, rng, 30, "--levels", &["1", "2"], &["0", "99"]);
                "zarr"
            } else {
                flag(&mut args, rng, 10, "--compress");
                opt(
                    &mut args,
                    rng,
                    10,
                    "--preview",
                    &["{OUT2}.png"],
                    &["{OUT2}.jpg"],
                );
                opt(
                    &mut args,
                    rng,
                    10,
                    "--mesh",
                    &["{OUT2}.stl", "{OUT2}.obj"],
                    &["{OUT2}"],
                );
                opt(
                    &mut args,
                    rng,
                    10,
                    "--slices",
                    &["{DIR}/slices"],
                    &["{OUT}"],
                );
                opt(
                    &mut args,
                    rng,
                    10,
                    "--store",
                    &["octree", "pointer", "hash", "dense"],
                    &[],
                );
                "nrrd"
            };
            return finish(rng, args, inputs, out_ext.to_string());
        }
        4 => {
            args.push(a("sculpt"));
            let ext = *rng.pick(&["csg", "csg", "nrrd"]);
            inputs.push(of(ext, rng));
            args.push(a("{IN0}"));
            inputs.push(of("csv", rng));
            args.push(a("--path"));
            args.push(a("{IN1}"));
            args.push(a("--tool"));
            args.push(value(
                rng,
                &["sphere:1", "sphere:3"],
                &["sphere:0", "cube:1", "sphere:nan"],
            ));
            if ext == "csg" {
                opt(&mut args, rng, 70, "--res", &["16", "24", "8x8x8"], BAD_RES);
            } else {
                args.push(a("--threshold"));
                args.push(value(rng, &["100", "0.5"], &["nan", "x"]));
            }
            flag(&mut args, rng, 20, "--add");
            opt(
                &mut args,
                rng,
                10,
                "--stiffness",
                &["0", "0.5"],
                &["-1", "inf"],
            );
            rng.pick::<&str>(&["stl", "obj", "ply"])
        }
        5 => {
            args.push(a("blist"));
            let e = rng.pick(&["A+B.!C", "(A-B)+C.D", "!A", "A.B.C.D.E.F"]);
            let e = if rng.chance(60) {
                mutate(rng, e.as_bytes())
            } else {
                e.as_bytes().to_vec()
            };
            args.push(e);
            opt(
                &mut args,
                rng,
                30,
                "--trace",
                &["101", "0", "1111"],
                &["2", "x"],
            );
            flag(&mut args, rng, 20, "--json");
            return no_output(rng, args, inputs);
        }
        6 => {
            args.push(a("requirements"));
            inputs.push(of("csg", rng));
            args.push(a("{IN0}"));
            opt(&mut args, rng, 60, "--res", &["16", "64", "128"], BAD_RES);
            opt(&mut args, rng, 20, "--panel", &["8x8", "64x64"], &["0x0"]);
            opt(&mut args, rng, 20, "--word", WORD, BAD_WORD);
            opt(&mut args, rng, 20, "--view", &["top", "iso"], &["q"]);
            flag(&mut args, rng, 20, "--json");
            return no_output(rng, args, inputs);
        }
        7 => {
            args.push(a("throughput"));
            if rng.chance(50) {
                inputs.push(of("csg", rng));
                args.push(a("--scene"));
                args.push(a("{IN0}"));
                opt(
                    &mut args,
                    rng,
                    30,
                    "--screen",
                    &["64x64", "128x96"],
                    &["0x0"],
                );
                opt(&mut args, rng, 30, "--panel", &["16x16", "32x32"], &["0x0"]);
            }
            opt(
                &mut args,
                rng,
                20,
                "--clock",
                &["10e6", "25e6"],
                &["0", "-1", "nan"],
            );
            opt(
                &mut args,
                rng,
                20,
                "--bits",
                &["31", "16"],
                &["0", "999999"],
            );
            flag(&mut args, rng, 20, "--json");
            return no_output(rng, args, inputs);
        }
        _ => {
            args.push(a("verify-select"));
            inputs.push(of("pla", rng));
            args.push(a("--vectors"));
            args.push(a("{VECDIR}"));
            opt(
                &mut args,
                rng,
                30,
                "--equations",
                &["derived", "printed"],
                &["q"],
            );
            flag(&mut args, rng, 20, "--json");
            return no_output(rng, args, inputs);
        }
    };
    finish(rng, args, inputs, out_ext.to_string())
}

/// `voxelize` of a scene that imports a file of another kind (its name relative to the
/// scene's directory, as `in1.EXT` lies beside `in0.csg`), the scene itself mutated now and
/// then: SVG, DXF, OFF, AMF, 3MF, `surface()` images and data, and `text()` in a font read from
/// the scene's directory. With the reader's options: `--strict`, `--max-memory`,
/// `--openscad-timeout`.
fn imported(rng: &mut Rng, of: &dyn Fn(&str, &mut Rng) -> Input) -> Case {
    let (ext, statement) = *rng.pick(&[
        (
            "svg",
            "linear_extrude(height = 2) import(file = \"in1.svg\");",
        ),
        (
            "dxf",
            "linear_extrude(height = 2) import(file = \"in1.dxf\");",
        ),
        ("off", "import(file = \"in1.off\");"),
        ("amf", "import(file = \"in1.amf\");"),
        ("3mf", "import(file = \"in1.3mf\");"),
        ("png", "surface(file = \"in1.png\", center = true);"),
        ("dat", "surface(file = \"in1.dat\", invert = false);"),
        (
            "ttf",
            "linear_extrude(height = 1) text(text = \"csgpix\", size = 4, \
             font = \"Liberation Sans\");",
        ),
    ]);
    let scene = match rng.chance(20) {
        true => mutate(rng, statement.as_bytes()),
        false => statement.as_bytes().to_vec(),
    };
    let csg = Input {
        ext: "csg".into(),
        bytes: scene,
    };
    let a = |s: &str| s.as_bytes().to_vec();
    let mut args = vec![a("voxelize"), a("{IN0}")];
    opt(&mut args, rng, 80, "--res", &["16", "32", "8x8x8"], BAD_RES);
    flag(&mut args, rng, 20, "--strict");
    opt(
        &mut args,
        rng,
        20,
        "--max-memory",
        &["64", "512"],
        &["0", "-1", "x"],
    );
    opt(
        &mut args,
        rng,
        10,
        "--openscad-timeout",
        &["5", "0"],
        &["-1", "1e99"],
    );
    flag(&mut args, rng, 10, "--json");
    let inputs = vec![csg, of(ext, rng)];
    finish(rng, args, inputs, "nrrd".to_string())
}

/// `export-verilog --scene` of one or two display lists or a `.csg` scene, into a directory.
fn verilog_scene(rng: &mut Rng, of: &dyn Fn(&str, &mut Rng) -> Input) -> Case {
    let a = |s: &str| s.as_bytes().to_vec();
    let ext = *rng.pick(&["dl", "dl", "csg"]);
    let mut args = vec![a("export-verilog"), a("--scene"), a("{IN0}")];
    let mut inputs = vec![of(ext, rng)];
    if ext == "dl" && rng.chance(30) {
        inputs.push(of("dl", rng));
        args.extend([a("--scene"), a("{IN1}")]);
        opt(&mut args, rng, 50, "--clip", &["A.!B", "A+B"], &["A.", "C"]);
    }
    // A scene's program runs to tens of thousands of clocks (twelve.csg: 84,381), each a line
    // a pixel in expected.hex: a few pixels keep such a case to megabytes.
    let (p, sizes): (u64, &[&str]) = match ext {
        "csg" => (100, &["2x2", "4x2"]),
        _ => (50, &["4x4", "16x16", "32x2"]),
    };
    opt(&mut args, rng, p, "--size", sizes, BAD_SIZE);
    opt(
        &mut args,
        rng,
        30,
        "--origin",
        &["56,90", "0,0"],
        &["-1,0", "9999999,0"],
    );
    opt(&mut args, rng, 20, "--word", WORD, BAD_WORD);
    opt(&mut args, rng, 10, "--max-memory", &["64"], &["0"]);
    finish(rng, args, inputs, "dir".to_string())
}

/// A case of a command that writes no file (its report goes to standard output).
fn no_output(rng: &mut Rng, args: Vec<Vec<u8>>, inputs: Vec<Input>) -> Case {
    Case {
        args,
        inputs,
        target: Target::New,
        out_ext: "none".into(),
        signal: None,
        closed_stdout: rng.chance(5),
    }
}

/// The output and its target, a mutated argument now and then, a signal now and then.
fn finish(rng: &mut Rng, mut args: Vec<Vec<u8>>, inputs: Vec<Input>, out_ext: String) -> Case {
    args.push(b"-o".to_vec());
    args.push(b"{OUT}".to_vec());
    if rng.chance(10) {
        let at = 1 + rng.below(args.len() - 1);
        args[at] = bad_arg(rng);
    }
    let target = *rng.pick(&[
        Target::New,
        Target::New,
        Target::New,
        Target::Existing,
        Target::Symlink,
        Target::Fifo,
        Target::Directory,
        Target::DevNull,
        Target::MissingDir,
    ]);
    let signal = rng.chance(5).then(|| {
        let sig = *rng.pick(&[libc::SIGINT, libc::SIGTERM, libc::SIGHUP]);
        (sig, rng.below(400) as u64)
    });
    // Drawn last: the rest of the case is what the same seed drew before.
    let closed_stdout = rng.chance(3);
    Case {
        args,
        inputs,
        target,
        out_ext,
        signal,
        closed_stdout,
    }
}

/// How a run ended, when it failed.
type Failure = String;

/// How a run ended, when it did not fail.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Success,
    Refusal,
    Interrupted,
    /// Standard output closed under the report: one line, exit 2, the outputs whole.
    StdoutClosed,
}

/// Lay out the case's files in `dir`, run it, and classify the run.
fn run(case: &Case, dir: &Path) -> Result<Kind, Failure> {
    let ins: Vec<PathBuf> = case
        .inputs
        .iter()
        .enumerate()
        .map(|(i, inp)| {
            let p = dir.join(format!("in{i}.{}", inp.ext));
            fs::write(&p, &inp.bytes).unwrap();
            p
        })
        .collect();
    let vecdir = dir.join("vectors");
    if case.args.iter().any(|a| a == b"{VECDIR}") {
        fs::create_dir(&vecdir).unwrap();
        for (i, inp) in case.inputs.iter().enumerate() {
            fs::write(vecdir.join(format!("v{i}.pla")), &inp.bytes).unwrap();
        }
    }
    let out = prepare(case, dir);
    let before = snapshot(dir);
    let args: Vec<std::ffi::OsString> = case
        .args
        .iter()
        .map(|a| fill(a, &ins, &out, dir, &vecdir))
        .collect();
    let bin = std::env::var_os("CSGPIX_CLI_FUZZ_BIN")
        .unwrap_or_else(|| env!("CARGO_BIN_EXE_csgpix").into());
    let mut cmd = Command::new(bin);
    cmd.args(&args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    if case.closed_stdout {
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        cmd.stdout(writer);
    }
    // SAFETY: setrlimit(2) between fork and exec, async-signal-safe, no allocation.
    unsafe {
        cmd.pre_exec(|| {
            let lim = libc::rlimit {
                rlim_cur: ADDRESS_SPACE,
                rlim_max: libc::RLIM_INFINITY,
            };
            libc::setrlimit(libc::RLIMIT_AS, &lim);
            Ok(())
        });
    }
    let reader = (case.target == Target::Fifo).then(|| fifo_reader(out.clone()));
    let mut child = cmd.spawn().unwrap();
    let mut stderr = child.stderr.take().unwrap();
    let err_thread = std::thread::spawn(move || {
        let mut s = vec![];
        let _ = stderr.read_to_end(&mut s);
        s
    });
    let t0 = Instant::now();
    let mut sent = false;
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break Some(s);
        }
        if let Some((sig, ms)) = case.signal {
            if !sent && t0.elapsed() >= Duration::from_millis(ms) {
                // SAFETY: kill(2) on our own child, not yet reaped.
                unsafe { libc::kill(child.id() as i32, sig) };
                sent = true;
            }
        }
        if t0.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    if let Some((stop, handle)) = reader {
        stop.store(true, Ordering::SeqCst);
        let _ = handle.join();
    }
    let err = err_thread.join().unwrap();
    let status = status.ok_or_else(|| format!("still running after {TIME_LIMIT:?}"))?;
    let kind = classify(case, status, &err, sent)?;
    left_behind(case, dir, &before, &out, kind)?;
    Ok(kind)
}

/// Replace the placeholders of an argument.
fn fill(a: &[u8], ins: &[PathBuf], out: &Path, dir: &Path, vecdir: &Path) -> std::ffi::OsString {
    let mut s = a.to_vec();
    let subst = |s: &mut Vec<u8>, key: &str, val: &[u8]| {
        while let Some(i) = s.windows(key.len()).position(|w| w == key.as_bytes()) {
            s.splice(i..i + key.len(), val.iter().copied());
        }
    };
    for (i, p) in ins.iter().enumerate() {
        subst(&mut s, &format!("{{IN{i}}}"), p.as_os_str().as_bytes());
    }
    subst(&mut s, "{OUT2}", dir.join("extra").as_os_str().as_bytes());
    subst(&mut s, "{OUT}", out.as_os_str().as_bytes());
    subst(&mut s, "{VECDIR}", vecdir.as_os_str().as_bytes());
    subst(&mut s, "{DIR}", dir.as_os_str().as_bytes());
    // An argument cannot hold a NUL (exec(2) ends it there).
    s.retain(|&b| b != 0);
    std::ffi::OsString::from(std::ffi::OsStr::from_bytes(&s))
}

/// Make the output path what the case says; return it.
fn prepare(case: &Case, dir: &Path) -> PathBuf {
    let name = format!("out.{}", case.out_ext);
    let p = dir.join(&name);
    match case.target {
        Target::New => {}
        Target::Existing => fs::write(&p, b"old").unwrap(),
        Target::Symlink => {
            fs::write(dir.join("real"), b"old").unwrap();
            std::os::unix::fs::symlink("real", &p).unwrap();
        }
        Target::Fifo => {
            let c = std::ffi::CString::new(p.as_os_str().as_bytes()).unwrap();
            // SAFETY: mkfifo(3) with a NUL-terminated path.
            assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0);
        }
        Target::Directory => fs::create_dir(&p).unwrap(),
        Target::DevNull => return PathBuf::from("/dev/null"),
        Target::MissingDir => return dir.join("no/such/dir").join(name),
    }
    p
}

/// Read a FIFO until told to stop, so a run writing through it is never blocked.
fn fifo_reader(p: PathBuf) -> (std::sync::Arc<AtomicBool>, std::thread::JoinHandle<()>) {
    let stop = std::sync::Arc::new(AtomicBool::new(false));
    let flag = stop.clone();
    let handle = std::thread::spawn(move || {
        use std::os::unix::fs::OpenOptionsExt;
        let Ok(mut f) = fs::OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_NONBLOCK)
            .open(&p)
        else {
            return;
        };
        let mut buf = vec![0u8; 1 << 16];
        loop {
            match f.read(&mut buf) {
                Ok(n) if n > 0 => continue,
                _ if flag.load(Ordering::SeqCst) => return,
                _ => std::thread::sleep(Duration::from_millis(1)),
            }
        }
    });
    (stop, handle)
}

/// Names and sizes of what is in `dir` (one level, and one below).
fn snapshot(dir: &Path) -> Vec<(String, u64)> {
    let mut v = vec![];
    for e in fs::read_dir(dir).unwrap().flatten() {
        let meta = fs::symlink_metadata(e.path()).unwrap();
        v.push((e.file_name().to_string_lossy().into_owned(), meta.len()));
    }
    v.sort();
    v
}

/// Success, clean refusal or interrupted; anything else is a failure.
fn classify(
    case: &Case,
    status: std::process::ExitStatus,
    err: &[u8],
    sent: bool,
) -> Result<Kind, Failure> {
    let text = String::from_utf8_lossy(err);
    if text.contains("panicked") || text.contains("RUST_BACKTRACE") {
        return Err(format!("panic: {text}"));
    }
    if let Some(sig) = status.signal() {
        return match case.signal {
            Some((s, _)) if sent && s == sig => Ok(Kind::Interrupted),
            _ => Err(format!("killed by signal {sig}: {text}")),
        };
    }
    // Notes, and the warnings of a scene read as OpenSCAD reads it (one line each, before
    // the report or the refusal), are not the refusal's line; none may echo a control
    // character.
    let said = |l: &&str| l.starts_with("csgpix: note: ") || l.starts_with("csgpix: warning: ");
    let lines: Vec<&str> = text.lines().filter(|l| !said(l)).collect();
    match status.code() {
        Some(0) => Ok(Kind::Success),
        Some(2) => {
            if lines.len() != 1 {
                return Err(format!("refusal of {} lines: {text}", lines.len()));
            }
            let line = lines[0];
            if !line.starts_with("csgpix: ") {
                return Err(format!("refusal not from csgpix: {line}"));
            }
            if let Some(c) = text
                .lines()
                .flat_map(str::chars)
                .find(|c| c.is_control() || matches!(c, '\u{2028}' | '\u{2029}'))
            {
                return Err(format!("control character {c:?} echoed: {text:?}"));
            }
            if case.closed_stdout && line.starts_with("csgpix: cannot write to standard output: ") {
                return Ok(Kind::StdoutClosed);
            }
            Ok(Kind::Refusal)
        }
        Some(c) if sent && c == 128 + case.signal.map_or(0, |s| s.0) => Ok(Kind::Interrupted),
        c => Err(format!("exit status {c:?}: {text}")),
    }
}

/// Nothing staged left; on a refusal no output written; a symlink still a symlink.
fn left_behind(
    case: &Case,
    dir: &Path,
    before: &[(String, u64)],
    out: &Path,
    kind: Kind,
) -> Result<(), Failure> {
    let after = snapshot(dir);
    if let Some((n, _)) = after.iter().find(|(n, _)| n.contains(".csgpix-")) {
        return Err(format!("staging left behind: {n}"));
    }
    if case.target == Target::Symlink
        && !fs::symlink_metadata(out).unwrap().file_type().is_symlink()
    {
        return Err("the output's symlink was replaced".into());
    }
    if kind == Kind::Refusal {
        // Nothing new, nothing changed.
        let changed: Vec<_> = after.iter().filter(|e| !before.contains(e)).collect();
        if !changed.is_empty() {
            return Err(format!("a refusal left output: {changed:?}"));
        }
    }
    Ok(())
}

/// Write a failing case as a regression: its arguments (one per line, hex where not UTF-8
/// text) and its inputs.
fn save(case: &Case, why: &str, root: &Path, n: u64) -> PathBuf {
    let d = root.join(format!("case-{n:06}"));
    fs::create_dir_all(&d).unwrap();
    let mut text = format!("# {}\n", why.lines().next().unwrap_or(""));
    text += &format!("target {:?} {}\n", case.target, case.out_ext);
    if let Some((s, ms)) = case.signal {
        text += &format!("signal {s} {ms}\n");
    }
    if case.closed_stdout {
        text += "stdout closed\n";
    }
    for a in &case.args {
        text += &format!("arg {}\n", hex(a));
    }
    for (i, inp) in case.inputs.iter().enumerate() {
        text += &format!("input {i} {}\n", inp.ext);
        fs::write(d.join(format!("in{i}.{}", inp.ext)), &inp.bytes).unwrap();
    }
    fs::write(d.join("case"), text).unwrap();
    d
}

fn hex(b: &[u8]) -> String {
    b.iter().map(|x| format!("{x:02x}")).collect()
}

fn unhex(s: &str) -> Vec<u8> {
    (0..s.len() / 2)
        .map(|i| u8::from_str_radix(&s[2 * i..2 * i + 2], 16).unwrap())
        .collect()
}

/// A saved case, read back.
fn load(d: &Path) -> Case {
    let text = fs::read_to_string(d.join("case")).unwrap();
    let (mut args, mut inputs, mut target, mut out_ext, mut signal) =
        (vec![], vec![], Target::New, String::new(), None);
    let mut closed_stdout = false;
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let f: Vec<&str> = line.split(' ').collect();
        match f[0] {
            "target" => {
                target = match f[1] {
                    "Existing" => Target::Existing,
                    "Symlink" => Target::Symlink,
                    "Fifo" => Target::Fifo,
                    "Directory" => Target::Directory,
                    "DevNull" => Target::DevNull,
                    "MissingDir" => Target::MissingDir,
                    _ => Target::New,
                };
                out_ext = f[2].to_string();
            }
            "signal" => signal = Some((f[1].parse().unwrap(), f[2].parse().unwrap())),
            "stdout" => closed_stdout = f.get(1) == Some(&"closed"),
            "arg" => args.push(unhex(f.get(1).copied().unwrap_or(""))),
            "input" => inputs.push(Input {
                ext: f[2].to_string(),
                bytes: fs::read(d.join(format!("in{}.{}", f[1], f[2]))).unwrap(),
            }),
            _ => {}
        }
    }
    Case {
        args,
        inputs,
        target,
        out_ext,
        signal,
        closed_stdout,
    }
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Replay the kept regressions, then fuzz for the time given; fail on any failure, with the
/// case saved.
#[test]
fn the_command_line_survives_fuzzing() {
    let regressions = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/cli_fuzz/regressions");
    let failed_root = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/cli-fuzz/failures");
    let mut failures: Vec<String> = vec![];
    if let Ok(entries) = fs::read_dir(&regressions) {
        let mut dirs: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
        dirs.sort();
        for d in dirs {
            let work = tempfile::tempdir().unwrap();
            if let Err(why) = run(&load(&d), work.path()) {
                failures.push(format!("{}: {why}", d.display()));
            }
        }
    }
    let seconds = env_u64("CSGPIX_CLI_FUZZ_SECONDS", 60);
    let seed = env_u64("CSGPIX_CLI_FUZZ_SEED", 1);
    let jobs = env_u64("CSGPIX_CLI_FUZZ_JOBS", 2).max(1);
    let cap = env_u64("CSGPIX_CLI_FUZZ_CASES", u64::MAX);
    let seeds = seeds();
    let deadline = Instant::now() + Duration::from_secs(seconds);
    let next = AtomicU64::new(0);
    let counts = Mutex::new([0u64; 5]);
    let found = Mutex::new(vec![]);
    std::thread::scope(|s| {
        for _ in 0..jobs {
            s.spawn(|| loop {
                let n = next.fetch_add(1, Ordering::SeqCst);
                if n >= cap || Instant::now() >= deadline {
                    return;
                }
                // One generator per case: case n is the same whatever the threads.
                let mut rng = Rng::new(seed.wrapping_mul(1_000_003).wrapping_add(n));
                let case = case(&mut rng, &seeds);
                let work = tempfile::tempdir().unwrap();
                let outcome = run(&case, work.path());
                let mut c = counts.lock().unwrap();
                match outcome {
                    Ok(kind) => c[kind as usize] += 1,
                    Err(why) => {
                        c[4] += 1;
                        let d = save(&case, &why, &failed_root, n);
                        found
                            .lock()
                            .unwrap()
                            .push(format!("{}: {why}", d.display()));
                    }
                }
            });
        }
    });
    let [ok, refused, stopped, closed, bad] = *counts.lock().unwrap();
    eprintln!(
        "cli fuzz: seed {seed}, {} cases: {ok} succeeded, {refused} refused cleanly, \
         {stopped} interrupted cleanly, {closed} ended cleanly on a closed standard output, \
         {bad} failed",
        ok + refused + stopped + closed + bad
    );
    failures.extend(found.into_inner().unwrap());
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
