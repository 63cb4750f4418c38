//! `csgpix blist` end to end: the printed tables of the thesis through the binary.

mod common;
use common::csgpix;

use std::process::Output;

/// Rows of a transcribed table in `vectors/blist/` (tab-separated, header and `#` skipped).
fn printed(file: &str) -> Vec<Vec<String>> {
    let path = format!("{}/vectors/blist/{file}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('P'))
        .map(|l| l.split('\t').map(str::to_string).collect())
        .collect()
}

fn json(out: &Output) -> serde_json::Value {
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The JSON rows as the printed columns P, name, sign, reference, stamp.
fn columns(v: &serde_json::Value) -> Vec<Vec<String>> {
    v["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            ["p", "name", "sign", "reference", "stamp"]
                .iter()
                .map(|k| match &r[*k] {
                    serde_json::Value::String(s) => s.clone(),
                    x => x.to_string(),
                })
                .collect()
        })
        .collect()
}

#[test]
fn figure_4_4_json_is_table_4_1() {
    let v = json(&csgpix(&["blist", "(A+B)-((C+(D-E)).(F+G))", "--json"]));
    assert_eq!(columns(&v), printed("table-4.1.txt"));
    assert_eq!(v["in_name"], 1);
    assert_eq!(v["label_bits"], 2);
    assert!(v.get("trace").is_none());
}

#[test]
fn trace_is_table_4_2() {
    let args = ["blist", "(A+B)-((C+(D-E)).(F+G))", "--trace", "0100110"];
    let v = json(&csgpix(&[&args[..], &["--json"]].concat()));
    let table = printed("table-4.2.txt");
    let labels: Vec<String> = table.iter().map(|r| r[6].clone()).collect();
    let trace: Vec<String> = v["trace"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.to_string())
        .collect();
    assert_eq!(trace, labels);
    assert_eq!(v["inside"], true);
    // The text form prints the Class and label columns of Table 4.2 and the result.
    let out = csgpix(&args);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .take(7)
        .map(|l| l.split_whitespace().collect())
        .collect();
    for (row, want) in rows.iter().zip(&table) {
        assert_eq!(row, want, "{text}");
    }
    assert!(text.contains("label register 2 bits"));
    assert_eq!(text.lines().last(), Some("inside"));
}

#[test]
fn figure_5_6_tree_is_table_5_1() {
    let v = json(&csgpix(&["blist", "(A+B+C)-(D+E)", "--json"]));
    assert_eq!(columns(&v), printed("table-5.1.txt"));
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    for (args, want) in [
        (vec!["blist", "A+(B"], "csgpix: EXPR:1:5: expected ')'"),
        (
            vec!["blist", "A..B"],
            "csgpix: EXPR:1:3: expected a primitive name",
        ),
        (vec!["blist", "-A"], "csgpix: EXPR:1:1: "),
        (
            vec!["blist", "A.B", "--trace", "1"],
            "csgpix: --trace:1:1: expected 2 bits",
        ),
        (
            vec!["blist", "A.B", "--trace", "1x"],
            "csgpix: --trace:1:2: expected 0 or 1",
        ),
    ] {
        let out = csgpix(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.starts_with(want), "{args:?}: {err}");
    }
    // As deep as one argument may be (Linux caps one at 128 KiB).
    let deep = format!("{}A{}", "(".repeat(60_000), ")".repeat(60_000));
    let out = csgpix(&["blist", &deep]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("nested deeper than 10000"));
}
