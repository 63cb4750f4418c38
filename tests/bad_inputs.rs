//! Bad inputs through the CLI: one line, the place named, exit status 2, nothing written
//! (docs/stability.md, "Bad input").

mod common;
use common::csgpix;

use std::io::Write;
use std::path::Path;

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The one-line message of a refused run (exit 2), without the `csgpix: ` prefix.
fn refused(args: &[&str]) -> String {
    let out = csgpix(args);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    err.trim_end().trim_start_matches("csgpix: ").to_string()
}

/// The refusal of `voxelize --expr A --prim A=PRIM --res 8 EXTRA… -o OUT`.
fn refused_prim(prim: &str, out: &Path, extra: &[&str]) -> String {
    let head = ["voxelize", "--expr", "A", "--prim", prim, "--res", "8x8x8"];
    refused(&[&head[..], extra, &["-o", s(out)]].concat())
}

#[test]
fn invalid_utf8_is_located_in_every_text_input() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let put = |name: &str, bytes: &[u8]| {
        let p = d.join(name);
        std::fs::write(&p, bytes).unwrap();
        p
    };
    let out = s(&d.join("o.nrrd")).to_string();
    let csg = put("u.csg", b"cube(size = [1, 1, 1]);\n  sphere(r = \xff);\n");
    let e = refused(&["voxelize", s(&csg), "--res", "8x8x8", "-o", &out]);
    assert_eq!(
        e,
        format!(
            "{}:2:14: invalid UTF-8 (byte 0xFF): text inputs are UTF-8",
            s(&csg)
        )
    );
    let dl = put("u.dl", b"# a list\n\xc3\xa9\xfe\n");
    let e = refused(&["render", s(&dl), "-o", s(&d.join("o.png"))]);
    assert!(
        e.starts_with(&format!("{}:2:2: invalid UTF-8 (byte 0xFE)", s(&dl))),
        "{e}"
    );
    let path = put("p.csv", b"0,0,0\n\xff,1,1\n");
    let e = refused(&[
        "sculpt",
        "vectors/scenes/twelve.csg",
        "--res",
        "8x8x8",
        "--tool",
        "sphere:1",
        "--path",
        s(&path),
        "-o",
        s(&d.join("o.stl")),
    ]);
    assert!(
        e.starts_with(&format!("{}:2:1: invalid UTF-8", s(&path))),
        "{e}"
    );
    let obj = put("u.obj", b"v 0 0 0\nv 1 0 \xff\n");
    let e = refused_prim(&format!("A={}", s(&obj)), Path::new(&out), &[]);
    assert!(e.starts_with(&format!("{}:2:7: ", s(&obj))), "{e}");
    assert!(!Path::new(&out).exists());
}

#[test]
fn an_ascii_stl_with_a_bad_byte_gets_the_ascii_error() {
    let dir = tempfile::tempdir().unwrap();
    let stl = dir.path().join("a.stl");
    std::fs::write(
        &stl,
        b"solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 \xff\n",
    )
    .unwrap();
    let out = dir.path().join("o.nrrd");
    let prim = format!("A={}", s(&stl));
    let e = refused_prim(&prim, &out, &[]);
    assert!(e.starts_with(&format!("{}:4:15: ", s(&stl))), "{e}");
    assert!(!e.contains("binary"), "{e}");
}

#[test]
fn bounds_that_overflow_or_are_not_numbers_are_refused() {
    for (bounds, needle) in [
        (
            "--bounds=-1e308,-1e308,-1e308,1e308,1e308,1e308",
            "overflows",
        ),
        ("--bounds=0,0,0,nan,1,1", "finite"),
        ("--bounds=0,0,0,inf,1,1", "finite"),
        ("--bounds=0,0,0,1,-1,1", "greater than"),
    ] {
        let e = refused(&[
            "requirements",
            "vectors/scenes/twelve.csg",
            "--res",
            "8x8x8",
            bounds,
        ]);
        assert!(e.contains(needle), "{bounds}: {e}");
    }
}

#[test]
fn unknown_mesh_extensions_are_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let ply = dir.path().join("m.ply");
    std::fs::write(&ply, "ply\nformat ascii 1.0\nend_header\n").unwrap();
    let out = dir.path().join("o.nrrd");
    let prim = format!("A={}", s(&ply));
    let e = refused_prim(&prim, &out, &[]);
    assert!(
        e.contains(".stl, .obj, .off, .amf and .3mf") && e.contains("PLY"),
        "{e}"
    );
}

#[cfg(unix)]
#[test]
fn a_nrrd_data_file_that_is_a_fifo_is_refused_before_it_is_opened() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("data.raw");
    assert!(std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let nrrd = dir.path().join("d.nrrd");
    std::fs::write(
        &nrrd,
        "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\ndata file: data.raw\n\n",
    )
    .unwrap();
    let out = dir.path().join("o.nrrd");
    let prim = format!("A={},threshold=1", s(&nrrd));
    // Opening the FIFO would wait for a writer forever; the run must end at once.
    let e = refused_prim(&prim, &out, &[]);
    assert!(e.starts_with(&format!("{}:6:12: ", s(&nrrd))), "{e}");
    assert!(e.contains("not a regular file"), "{e}");
}

#[test]
fn a_gzip_bomb_is_refused_by_its_sizes_before_it_is_decoded() {
    let dir = tempfile::tempdir().unwrap();
    let nrrd = dir.path().join("bomb.nrrd");
    let mut f = std::fs::File::create(&nrrd).unwrap();
    f.write_all(b"NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1024 1024 256\nencoding: gzip\n\n")
        .unwrap();
    // 256 MiB of zeros in a quarter of a MiB.
    let mut gz = flate2::write::GzEncoder::new(f, flate2::Compression::best());
    let zeros = vec![0u8; 1 << 20];
    for _ in 0..256 {
        gz.write_all(&zeros).unwrap();
    }
    gz.finish().unwrap();
    assert!(std::fs::metadata(&nrrd).unwrap().len() < 1 << 20);
    let out = dir.path().join("o.nrrd");
    let prim = format!("A={},threshold=1", s(&nrrd));
    let e = refused_prim(&prim, &out, &["--max-memory", "256"]);
    assert!(e.starts_with(&format!("{}:4:", s(&nrrd))), "{e}");
    assert!(e.contains("--max-memory") && e.contains("samples"), "{e}");
    assert!(!out.exists());
}

#[test]
fn sculpt_reads_the_gzip_phantom_and_honours_spacings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let carve = "vectors/paths/carve.csv";
    let stl = d.join("head.stl");
    let out = csgpix(&[
        "sculpt",
        "vectors/scenes/phantom.nrrd",
        "--threshold",
        "300",
        "--tool",
        "sphere:1",
        "--path",
        carve,
        "--json",
        "-o",
        s(&stl),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["triangles_before"].as_u64().unwrap() > 1000, "{v}");
    // The same 4³ block of filled samples at spacings 1 and 2: the mesh doubles.
    let extent = |spacing: u32| {
        let nrrd = d.join(format!("s{spacing}.nrrd"));
        let mut bytes = format!(
            "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 6 6 6\nspacings: {spacing} {spacing} {spacing}\nencoding: raw\n\n"
        )
        .into_bytes();
        for k in 0..6 {
            for j in 0..6 {
                for i in 0..6 {
                    let inner = [i, j, k].iter().all(|&c| (1..5).contains(&c));
                    bytes.push(u8::from(inner));
                }
            }
        }
        std::fs::write(&nrrd, bytes).unwrap();
        let path = d.join("far.csv");
        std::fs::write(&path, "1000,1000,1000\n").unwrap();
        let obj = d.join(format!("s{spacing}.obj"));
        let out = csgpix(&[
            "sculpt",
            s(&nrrd),
            "--tool",
            "sphere:1",
            "--path",
            s(&path),
            "-o",
            s(&obj),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = std::fs::read_to_string(&obj).unwrap();
        let xs: Vec<f64> = text
            .lines()
            .filter_map(|l| l.strip_prefix("v "))
            .map(|l| l.split_whitespace().next().unwrap().parse().unwrap())
            .collect();
        let (lo, hi) = xs
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
        hi - lo
    };
    let (one, two) = (extent(1), extent(2));
    assert!(one > 2.0, "{one}");
    assert!((two - 2.0 * one).abs() < 1e-9, "{one} {two}");
}

/// Errors about the whole clipping function name the scene (or `--clip`), not a place in the
/// first solid or list: the products of §5.2.1, the size of the program, a concave volume.
#[test]
fn whole_scene_clipping_errors_name_the_scene_or_clip_not_a_face() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // 13 intersected unions of two: 2^13 products.
    let mut text = String::from("intersection() {\n");
    for _ in 0..13 {
        text += " union() { cube(size = [2, 2, 2]); \
                 multmatrix([[1,0,0,0.5],[0,1,0,0.5],[0,0,1,0.5],[0,0,0,1]]) cube(size = [2, 2, 2]); }\n";
    }
    let many = d.join("many.csg");
    std::fs::write(&many, text + "}\n").unwrap();
    // A difference of 600 solids: 600² literals drawn, over the program limit.
    let mut text = String::from("difference() {\n cube(size = [10, 10, 10]);\n");
    for i in 0..600 {
        let (x, y) = (i % 20, i / 20);
        text += &format!(
            " multmatrix([[1,0,0,{x}],[0,1,0,{y}],[0,0,1,1],[0,0,0,1]]) cube(size = [0.5, 0.5, 0.5]);\n"
        );
    }
    let holes = d.join("holes.csg");
    std::fs::write(&holes, text + "}\n").unwrap();
    let png = d.join("o.png");
    let (m, h, o) = (s(&many), s(&holes), s(&png));
    for (args, want) in [
        (
            vec!["render", m, "--size", "64x64", "-o", o],
            format!("{m}: the expression expands to more than 4096 products"),
        ),
        (
            vec!["requirements", m, "--res", "16x16x16"],
            format!("{m}: the expression expands"),
        ),
        (
            vec!["throughput", "--scene", m, "--screen", "64x64"],
            format!("{m}: the expression expands"),
        ),
        (
            vec!["throughput", "--scene", h, "--screen", "64x64"],
            format!("{h}: the clipping program would have"),
        ),
    ] {
        let e = refused(&args);
        assert!(e.starts_with(&want), "{args:?}: {e}");
        assert!(
            e.contains("Blist") && !e.contains("face 1") && !e.contains("solid 1"),
            "{e}"
        );
    }
    // Display lists are clipped by --clip: A..Z, 2^13 products.
    let cube = "vectors/thesis/cube.dl";
    let mut args = vec!["render"; 1];
    args.extend([cube; 26]);
    let clip = "(A+B).(C+D).(E+F).(G+H).(I+J).(K+L).(M+N).(O+P).(Q+R).(S+T).(U+V).(W+X).(Y+Z)";
    args.extend(["--clip", clip, "-o", o]);
    let e = refused(&args);
    assert!(e.starts_with("--clip: the expression expands"), "{e}");
    // A concave list in --clip: the list named, no line of it.
    let concave = d.join("concave.dl");
    std::fs::write(
        &concave,
        "# concave\n\n46.06 -1.0 1.18 2\n1 0 1\n38.28 1.0 0 1\n0 0 1\n0 0 0 1234\n",
    )
    .unwrap();
    let c = s(&concave);
    let e = refused(&["render", cube, c, "--clip", "A.B", "-o", o]);
    assert!(
        e.starts_with(&format!(
            "{c}: a concave display list cannot be a clipping volume"
        )),
        "{e}"
    );
    assert!(!png.exists());
}

/// A run of the binary with arguments as the system gives them (some not UTF-8): its one-line
/// refusal (exit 2), without the `csgpix: ` prefix.
#[cfg(unix)]
fn refused_os(args: &[&std::ffi::OsStr]) -> String {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run csgpix");
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    err.trim_end().trim_start_matches("csgpix: ").to_string()
}

#[test]
fn one_line_inputs_of_megabytes_are_refused_in_seconds() {
    // Issue 26: a 0.96 MB display-list line took 10.9 s to be refused at column 9 (columns
    // were recounted from the line's start for every field). 4 MB of each reader here.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let big = 4 << 20;
    let timed = |args: &[&str], want: &str| {
        let start = std::time::Instant::now();
        let e = refused(args);
        let took = start.elapsed();
        assert!(e.contains(want), "{e}");
        assert!(
            took < std::time::Duration::from_secs(5),
            "{args:?}: {took:?}"
        );
    };
    let dl = d.join("long.dl");
    std::fs::write(
        &dl,
        format!("0 0 0 1{}\n1 0 0\n0 0 0 1234\n", " 0".repeat(big / 2)),
    )
    .unwrap();
    let png = d.join("o.png");
    timed(
        &["render", s(&dl), "-o", s(&png)],
        "long.dl:1:9: expected end of line",
    );
    assert!(!png.exists());
    let csv = d.join("long.csv");
    std::fs::write(&csv, format!("0,0,0{}\n", ",0".repeat(big / 2))).unwrap();
    let stl = d.join("o.stl");
    let sculpt = ["sculpt", "vectors/scenes/twelve.csg", "--res", "8x8x8"];
    let tool = ["--tool", "sphere:1", "--path", s(&csv), "-o", s(&stl)];
    timed(
        &[&sculpt[..], &tool].concat(),
        "long.csv:1:7: expected 3 fields",
    );
    let vectors = d.join("vectors");
    std::fs::create_dir(&vectors).unwrap();
    for t in ["front", "back", "close", "clip", "second"] {
        let text = std::fs::read_to_string(format!("vectors/select/{t}.pla")).unwrap();
        let long = format!(".ilb P N J T M{}", " q".repeat(big / 2));
        let text = text.replace(".ilb P N J T M", &long);
        std::fs::write(vectors.join(format!("{t}.pla")), text).unwrap();
    }
    timed(
        &["verify-select", "--vectors", s(&vectors)],
        "second.pla:7:16: ",
    );
}

#[test]
fn expression_errors_give_line_and_column_in_every_command() {
    let dir = tempfile::tempdir().unwrap();
    let (nrrd, png) = (dir.path().join("o.nrrd"), dir.path().join("o.png"));
    let prim = "A=vectors/scenes/hollow-cube.csg";
    let voxelize = |expr: &str| {
        let args = ["voxelize", "--expr", expr, "--prim", prim, "--res", "8x8x8"];
        refused(&[&args[..], &["-o", s(&nrrd)]].concat())
    };
    let found_end = "expected a primitive name, '!' or '(', found the end";
    assert_eq!(voxelize("A + ("), format!("--expr:1:6: {found_end}"));
    // Columns count characters.
    assert!(voxelize("é + A").starts_with("--expr:1:1: "));
    assert!(voxelize("A + (é").starts_with("--expr:1:6: "));
    // A name bound to no file: where the expression first names it.
    assert_eq!(
        voxelize("A -  B + B"),
        "--expr:1:6: primitive `B` needs a file: --prim B=FILE"
    );
    assert!(!nrrd.exists());
    assert_eq!(
        refused(&["blist", "A + ("]),
        format!("EXPR:1:6: {found_end}")
    );
    let clip = [
        "render",
        "vectors/thesis/cube.dl",
        "--clip",
        "A + (",
        "-o",
        s(&png),
    ];
    assert!(refused(&clip).starts_with("--clip:1:6: "));
}

#[cfg(unix)]
#[test]
fn arguments_that_are_not_utf8_are_named() {
    use std::ffi::OsStr;
    use std::os::unix::ffi::OsStrExt;
    let bad = OsStr::from_bytes(b"A\xff");
    let res = OsStr::from_bytes(b"--res=8\xff");
    fn os(v: &[&'static str]) -> Vec<&'static OsStr> {
        v.iter().map(|a| OsStr::new(*a)).collect()
    }
    let scene = os(&[
        "voxelize",
        "vectors/scenes/twelve.csg",
        "-o",
        "/nonexistent/o.nrrd",
    ]);
    let expr = os(&[
        "voxelize",
        "--prim",
        "A=vectors/scenes/twelve.csg",
        "--expr",
    ]);
    let cases = [
        ([&os(&["blist"])[..], &[bad]].concat(), "EXPR", "A\\xFF"),
        ([&expr[..], &[bad]].concat(), "--expr", "A\\xFF"),
        ([&scene[..], &[res]].concat(), "--res", "8\\xFF"),
        (
            [&scene[..], &os(&["--res"]), &[bad]].concat(),
            "--res",
            "A\\xFF",
        ),
    ];
    for (args, flag, value) in cases {
        let e = refused_os(&args);
        let want = format!("{flag}: the value \"{value}\" is not UTF-8: csgpix reads it as text");
        assert!(e.starts_with(&want), "{e}");
    }
    // A long value is cut to 64 bytes around its first byte that is not UTF-8 (a 100 kB
    // argument was a 100 kB line), with its length and that byte's offset.
    let mut long = b"--res=".to_vec();
    long.extend(std::iter::repeat_n(b'8', 100_000));
    long.push(0xff);
    long.extend(std::iter::repeat_n(b'8', 100));
    let e = refused_os(&[&scene[..], &[OsStr::from_bytes(&long)]].concat());
    let want = format!(
        "--res: the value \"…{}\\xFF{}…\" (100101 bytes, the first not UTF-8 at byte 100000)",
        "8".repeat(32),
        "8".repeat(31)
    );
    assert!(e.starts_with(&want), "{e}");
    assert!(e.len() < 200, "{e}");
    // Paths are taken as they are: the file is looked for.
    let dl = OsStr::from_bytes(b"no-such-\xff.dl");
    let e = refused_os(&[
        OsStr::new("render"),
        dl,
        OsStr::new("-o"),
        OsStr::new("o.png"),
    ]);
    assert!(e.contains("No such file"), "{e}");
}

#[test]
fn control_characters_are_escaped_where_input_is_echoed() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let png = d.join("o.png");
    let render = |dl: &Path| refused(&["render", s(dl), "-o", s(&png)]);
    // A field holding NUL, VT, FF, NEL and a line separator.
    let dl = d.join("c.dl");
    std::fs::write(
        &dl,
        "0 0 0 1\n1 0 x\0\x0b\x0c\u{85}\u{2028}\u{1b}\n0 0 0 1234\n",
    )
    .unwrap();
    let e = render(&dl);
    let want = r"c.dl:2:5: expected 0 or 1 for L, found `x\0\x0b\x0c\u{85}\u{2028}\x1b`";
    assert!(e.ends_with(want), "{e}");
    // A file's name.
    let name = d.join("a\nb\u{85}\u{2029}\x0b.dl");
    let e = render(&name);
    assert!(e.contains(r"a\nb\u{85}\u{2029}\x0b.dl: "), "{e}");
    // A name in a scene, echoed by the import's warning (a missing file imports nothing, as
    // in OpenSCAD), which `--strict` makes the refusal.
    let csg = d.join("i.csg");
    std::fs::write(&csg, "import(\"x\x0b\u{2028}.stl\");\n").unwrap();
    let nrrd = d.join("o.nrrd");
    let args = [
        "voxelize",
        s(&csg),
        "--res",
        "8x8x8",
        "--strict",
        "-o",
        s(&nrrd),
    ];
    let e = refused(&args);
    let name = r"x\x0b\u{2028}.stl";
    assert!(
        e.contains("Can't open import file") && e.contains(&format!("{name}' (no such file)")),
        "{e:?}"
    );
    assert!(!png.exists() && !nrrd.exists());
}

#[test]
fn degenerate_extents_are_refused_where_they_are_read() {
    // A cube 1e-307 across has voxels no f64 inverts: its planes came out NaN, refused as
    // `coefficient NaN does not fit the depth word` with no place.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let csg = d.join("tiny.csg");
    std::fs::write(
        &csg,
        "// too small for any grid\n  cube(size = [1e-307, 1, 1]);\n",
    )
    .unwrap();
    let (nrrd, png) = (d.join("o.nrrd"), d.join("o.png"));
    let want = format!(
        "{}:2:3: degenerate extent: the solid is 1e-307 across in x, under 1e-12",
        s(&csg)
    );
    let e = refused(&["voxelize", s(&csg), "--res", "8x8x8", "-o", s(&nrrd)]);
    assert!(e.starts_with(&want), "{e}");
    let e = refused(&["render", s(&csg), "-o", s(&png)]);
    assert!(e.starts_with(&want), "{e}");
    // Bounds given on the command line.
    let args = [
        "voxelize",
        "vectors/scenes/twelve.csg",
        "--bounds=0,0,0,1,1e-300,1",
    ];
    let e = refused(&[&args[..], &["--res", "8x8x8", "-o", s(&nrrd)]].concat());
    assert!(
        e.contains("--bounds") && e.contains("degenerate extent"),
        "{e}"
    );
    assert!(!nrrd.exists() && !png.exists());
}

/// An SVG of 10,000 nested groups aborted the process on a stack overflow (exit 134) and left
/// its staging file: refused in one line at the import and the file's place, nothing written.
#[test]
fn deeply_nested_svg_is_one_line_not_an_abort() {
    let dir = tempfile::tempdir().unwrap();
    let n = 10_000;
    let svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">{}<rect width=\"5\" \
         height=\"5\"/>{}</svg>",
        "<g>".repeat(n),
        "</g>".repeat(n)
    );
    std::fs::write(dir.path().join("deep.svg"), svg).unwrap();
    let csg = dir.path().join("deep.csg");
    std::fs::write(
        &csg,
        "linear_extrude(height = 1) import(file = \"deep.svg\");\n",
    )
    .unwrap();
    let out = dir.path().join("d.nrrd");
    let e = refused(&["voxelize", s(&csg), "--res", "16", "-o", s(&out)]);
    assert!(
        e.contains("deep.csg:1:28:") && e.contains("deep.svg:1:"),
        "{e}"
    );
    assert!(e.contains("nested more than 256 deep"), "{e}");
    let mut left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    left.sort();
    assert_eq!(left, ["deep.csg", "deep.svg"]);
}
