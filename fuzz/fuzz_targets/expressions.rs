//! The expression parsers: `blist` / `voxelize --expr` CSG expressions, `render --clip`
//! clipping functions, `sculpt --path` tool paths. The first byte picks the parser.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let Some((&which, rest)) = bytes.split_first() else {
        return;
    };
    let text = String::from_utf8_lossy(rest);
    let err = match which % 3 {
        0 => csgpix::scene::csg_expr::parse(&text).err().map(|e| e.to_string()),
        1 => {
            let names: Vec<String> = ["A", "B", "C"].map(String::from).to_vec();
            csgpix::scene::clip_expr::Clip::parse(&text, &names)
                .err()
                .map(|e| e.to_string())
        }
        _ => csgpix::sculpt::parse_path(&text, "p.csv")
            .err()
            .map(|e| e.to_string()),
    };
    if let Some(e) = err {
        assert!(!e.contains('\n'), "two lines: {e}");
    }
});
