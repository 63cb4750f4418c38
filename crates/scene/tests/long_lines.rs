//! Every text reader of the scene refuses (or reads) one very long line in time proportional
//! to its length: columns are carried along, never recounted from the start of the line for
//! each word (issue 26: a 0.96 MB display-list line took 10.9 s to be refused at column 9).
//!
//! Timing is compared, not absolute, where it can be: the same reader on n and 8n bytes, the
//! best of three runs each, must take less than 30 times as long (linear: about 8; quadratic:
//! about 64). A 4 MB line must also be refused within a few seconds (a quadratic reader takes
//! minutes).

use std::time::{Duration, Instant};

use csgpix_scene::display_list::DisplayList;
use csgpix_scene::trimesh::TriMesh;
use csgpix_scene::{clip_expr::Clip, csg_expr, nrrd};

/// The best of three runs of `f`.
fn best_of_three(mut f: impl FnMut()) -> Duration {
    (0..3)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed()
        })
        .min()
        .expect("three runs")
}

/// `read(make(8n))` takes less than 30 times `read(make(n))`; a floor of 5 ms on the small
/// run keeps a near-zero time (or an allocator's page faults on the large one) from making
/// the ratio meaningless: a quadratic reader takes a tenth of a second on the small input.
fn assert_linear(what: &str, make: impl Fn(usize) -> Vec<u8>, read: impl Fn(&[u8])) {
    const N: usize = 128 * 1024;
    let (small, large) = (make(N), make(8 * N));
    let t1 = best_of_three(|| read(&small)).max(Duration::from_millis(5));
    let t8 = best_of_three(|| read(&large));
    let ratio = t8.as_secs_f64() / t1.as_secs_f64();
    assert!(
        ratio < 30.0,
        "{what}: {t1:?} for {N} bytes, {t8:?} for 8 times as many"
    );
}

/// `0 0 0 1` then `n` more bytes of ` 0` fields: refused at column 9, the fifth field.
fn long_dl_line(n: usize) -> Vec<u8> {
    let mut text = b"0 0 0 1".to_vec();
    text.extend(b" 0".repeat(n / 2));
    text.extend(b"\n1 0 0\n0 0 0 1234\n");
    text
}

fn refuse_dl(bytes: &[u8]) {
    let text = std::str::from_utf8(bytes).unwrap();
    let err = DisplayList::parse(text, "long.dl").unwrap_err();
    assert!(err.to_string().starts_with("long.dl:1:9: "), "{err}");
}

#[test]
fn a_long_display_list_line_is_refused_in_linear_time() {
    assert_linear("display list", long_dl_line, refuse_dl);
}

#[test]
fn a_four_megabyte_display_list_line_is_refused_in_seconds() {
    let text = long_dl_line(4 << 20);
    let start = Instant::now();
    refuse_dl(&text);
    let took = start.elapsed();
    assert!(took < Duration::from_secs(3), "{took:?}");
}

#[test]
fn long_mesh_lines_are_read_in_linear_time() {
    // ASCII STL: every facet on one line, then a stray word.
    let facet = b"facet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 1 0 \
                  endloop endfacet ";
    let stl = |n: usize| {
        let mut t = b"solid a\n".to_vec();
        t.extend(facet.repeat(n / facet.len()));
        t.extend(b"x\n");
        t
    };
    assert_linear("ASCII STL", stl, |b| {
        assert!(TriMesh::parse(b, "long.stl", false).is_err());
    });
    // OBJ: one face of many corners, then a stray word.
    let obj = |n: usize| {
        let mut t = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf".to_vec();
        t.extend(b" 1 2 3".repeat(n / 6));
        t.extend(b" x\n");
        t
    };
    assert_linear("OBJ", obj, |b| {
        assert!(TriMesh::parse(b, "long.obj", true).is_err());
    });
}

#[test]
fn a_long_nrrd_header_line_is_refused_in_linear_time() {
    let nrrd = |n: usize| {
        let mut t = b"NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1 1 1".to_vec();
        t.extend(b" 1".repeat(n / 2));
        t.extend(b"\nencoding: raw\n\n\0");
        t
    };
    assert_linear("NRRD header", nrrd, |b| {
        assert!(nrrd::parse_nrrd(b, "long.nrrd", None).is_err());
    });
}

#[test]
fn long_expressions_are_refused_in_linear_time() {
    // `A+A+…+`: refused at the end, past every name.
    let expr = |n: usize| {
        let mut t = b"A".to_vec();
        t.extend(b"+A".repeat(n / 2));
        t.push(b'+');
        t
    };
    assert_linear("CSG expression", expr, |b| {
        assert!(csg_expr::parse(std::str::from_utf8(b).unwrap()).is_err());
    });
    // `A0+A1+…+`: as many distinct names as fit, each looked up once.
    let distinct = |n: usize| {
        let mut t = String::new();
        for i in 0.. {
            if t.len() >= n {
                break;
            }
            t += &format!("A{i}+");
        }
        t.into_bytes()
    };
    assert_linear("CSG expression of distinct names", distinct, |b| {
        assert!(csg_expr::parse(std::str::from_utf8(b).unwrap()).is_err());
    });
    let names = ["A".to_string()];
    assert_linear("clipping function", expr, |b| {
        assert!(Clip::parse(std::str::from_utf8(b).unwrap(), &names).is_err());
    });
}
