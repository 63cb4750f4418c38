//! Font files (`text(font = …)` with a scene's own `.ttf`/`.otf`): fontdb's face list, the
//! lookup by family, rustybuzz's shaping, the outlines flattened and united, across and down.
#![no_main]
use csgpix::openscad::text::{render_in, Fonts, TextSpec};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let fonts = Fonts::of_data(bytes.to_vec());
    let Some(family) = fonts.families().into_iter().next() else {
        return;
    };
    let Ok(id) = fonts.find(&family) else {
        return;
    };
    for (direction, valign) in [("ltr", "baseline"), ("ttb", "center")] {
        let mut spec = TextSpec::new("Ag fi 1.5 \u{2713} \u{0639}\u{0631}", 10.0);
        spec.font = family.clone();
        spec.direction = direction.into();
        spec.valign = valign.into();
        if let Err(e) = render_in(&spec, &fonts, id, 200_000) {
            let e = e.to_string();
            assert!(!e.contains('\n'), "two lines: {e}");
        }
    }
});
