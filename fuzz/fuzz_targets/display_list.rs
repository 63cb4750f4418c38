//! `.dl` display lists (thesis §5.2): any bytes read as `DisplayList::read` reads a file.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let r = match csgpix::scene::input::text(bytes.to_vec(), "f.dl") {
        Ok(text) => {
            csgpix::scene::display_list::DisplayList::parse(&text, "f.dl").map_err(|e| e.to_string())
        }
        Err(e) => Err(e.to_string()),
    };
    if let Err(e) = r {
        assert!(!e.contains('\n'), "two lines: {e}");
    }
});
