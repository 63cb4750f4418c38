//! `text(…)`: a 2D leaf whose outline is the shaped, flattened glyph contours of a string,
//! following OpenSCAD 2021.01's `FreetypeRenderer::render` (`src/FreetypeRenderer.cc`),
//! `DrawingCallback` (`src/DrawingCallback.cc`) and `TextModule::instantiate` (`src/text.cc`).
//!
//! * Scale. OpenSCAD sets FreeType's character size to `1e5` (26.6 points) at 100 dpi, so a
//!   font unit is `ppem26 / units_per_em` 26.6 units with `ppem26 = (1e5 · 100 + 36) / 72`
//!   (integer division, as `FT_Request_Size`), rounded down to whole pixels (`× 64`) when the
//!   font's `head` flags ask for an integer ppem (bit 3), as FreeType's TrueType driver does
//!   for the hinted outlines OpenSCAD loads. HarfBuzz's positions (hb-ft, unhinted advances)
//!   are scaled without that rounding (`ppem26 = 138889` whatever the flags).
//!   Outline points are divided by `scale = 1e5`, but HarfBuzz positions (advances, offsets)
//!   and the glyph boxes by `1.024e5` (OpenSCAD's `unscale`, which its source keeps "for
//!   compatibility"); everything is then multiplied by `size`. So the glyphs are drawn
//!   2.4 % larger than their advances.
//! * Curves. Each quadratic or cubic Bézier segment becomes `n` straight segments at
//!   parameters `i / n`, `n = max(floor(f / 8) + 1, 2)` with `f = get_fragments_from_r(size,
//!   $fn, $fs, $fa)`.
//! * Alignment. `halign`: the width is the sum of the advances × `spacing` (`right`: −width,
//!   `center`: −width/2). `valign`: the ascent and descent are the largest of the glyphs'
//!   grid-fitted control boxes above and below the baseline (`top`: −ascent, `center`:
//!   (descent − ascent)/2, `bottom`: +descent). For vertical directions the width is the widest
//!   box and the "ascent" the sum of the vertical advances, as OpenSCAD has it.
//! * Fill. The contours of every glyph are united with the nonzero rule (OpenSCAD passes the
//!   glyph polygons to Clipper's union with `pftNonZero`), here with `i_overlay`; the result's
//!   paths are filled even-odd like every [`Poly2`].
//! * Shaping: `rustybuzz` (a port of HarfBuzz) with the node's `direction`, `script` and
//!   `language`, as OpenSCAD calls `hb_shape`; outlines from `ttf-parser` (unhinted, where
//!   OpenSCAD loads hinted outlines at about 2170 pixels per em: a difference of under 1/2000
//!   of the em). For `ttb`/`btt` in a font without `vmtx` the vertical advance and origin are
//!   FreeType's made-up ones, which hb-ft hands OpenSCAD, not HarfBuzz's own fallback.
//!
//! Fonts are looked up by fontconfig's `Family:style=Style` syntax in, in this order, the
//! scene's own font files ([`crate::ReadOptions::fonts`]: those a `.scad` names in
//! `use <x.ttf>`, or those beside a `.csg` file), the directories of `CSGPIX_FONT_PATH`
//! (colon-separated), the bundled `vectors/fonts` (when it exists beside the sources this
//! crate was built from), then the system fonts, scanned only when a lookup needs them
//! ([`Fonts::find`]). `font = ""` is OpenSCAD's default,
//! `Liberation Sans:style=Regular`. A family or style not found there is asked of fontconfig
//! itself (`fc-match`, which answers as OpenSCAD's `FontCache::find_face_fontconfig` does:
//! the name parsed as a fontconfig pattern, the configuration's substitutions and defaults,
//! the best match), and its answer is drawn with a warning naming the font substituted
//! (`--strict` refuses instead); without fontconfig the font is refused.

use csgpix_scene::error::Rule;
use csgpix_scene::Error;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use glam::DVec2;
use rustybuzz::ttf_parser;

use crate::extrude::Poly2;
use crate::node::Params;
use crate::primitives::{check_budget, Resolution};
use crate::value::must;
use crate::{consts_::*, lex::*};

/// OpenSCAD's default font (`FontCache::DEFAULT_FONT`).
pub const DEFAULT_FONT: &str = "Liberation Sans:style=Regular";

/// The name a font is looked up by: `name` trimmed, or [`DEFAULT_FONT`] where it is blank.
fn lookup_name(name: &str) -> &str {
    match name.trim() {
        "" => DEFAULT_FONT,
        trimmed => trimmed,
    }
}

/// `FreetypeRenderer::scale`: outline coordinates (26.6) are divided by it.
const SCALE: f64 = 1e5;
/// The em in 26.6 units: OpenSCAD's character size [`SCALE`] points at 100 dpi, as
/// `FT_Set_Char_Size` rounds it.
const EM_26_6: f64 = ((SCALE as u64 * 100 + 36) / 72) as f64;
/// 1 / `FreetypeRenderer::unscale`: HarfBuzz positions and boxes are divided by it.
const UNSCALE: f64 = 1.024e5;

/// The fonts csgpix can draw, in lookup order.
pub struct Fonts {
    db: fontdb::Database,
    /// Looked up after `db`: a scene's own fonts come first, then [`Fonts::standard`], then
    /// [`Fonts::system`].
    then: Option<Then>,
    /// Whether these are a scene's own font files.
    scene: bool,
    /// The style names of the faces read by [`crate::fontscan`] (the others' are read when
    /// a lookup asks).
    styles: crate::fontscan::Styles,
}

/// The set looked up after another: made when first asked for, and, when `lazy`, asked for
/// only where the sets before cannot settle a lookup ([`Fonts::find`]).
#[derive(Clone, Copy)]
struct Then {
    set: fn() -> &'static Fonts,
    lazy: bool,
}

/// A face [`Fonts::find`] found: which set of the lookup order, and the face in it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FaceId {
    layer: usize,
    id: fontdb::ID,
}

/// The bundled font directory, if the sources this crate was built from are still there.
pub fn bundled_font_dir() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../vectors/fonts");
    dir.is_dir().then_some(dir)
}

impl Fonts {
    /// The fonts of the given directories, in order, then (if `system`) the system's.
    pub fn new(dirs: &[PathBuf], system: bool) -> Fonts {
        let (mut db, mut styles) = (fontdb::Database::new(), crate::fontscan::Styles::new());
        for d in dirs {
            crate::fontscan::load_dir(&mut db, &mut styles, d);
        }
        if system {
            crate::fontscan::load_system(&mut db, &mut styles);
        }
        Fonts {
            db,
            then: None,
            scene: false,
            styles,
        }
    }

    /// A scene's own font files, looked up before [`Fonts::standard`] (which stays shared
    /// and unchanged: these fonts belong to this value alone). A file that cannot be read
    /// adds no face, as OpenSCAD only logs it; a `text()` asking for its font then fails.
    pub fn scene(files: &[PathBuf]) -> Fonts {
        let mut db = fontdb::Database::new();
        for f in files {
            if file_collection_fits(f) {
                let _ = db.load_font_file(f);
            }
        }
        Fonts {
            db,
            then: Some(Then {
                set: Fonts::standard,
                lazy: false,
            }),
            scene: true,
            styles: Default::default(),
        }
    }

    /// The faces of one font file's bytes, looked up alone (the fuzz target's: no file, no
    /// other font).
    pub fn of_data(data: Vec<u8>) -> Fonts {
        let mut db = fontdb::Database::new();
        if collection_fits(&data) {
            db.load_font_data(data);
        }
        Fonts {
            db,
            then: None,
            scene: false,
            styles: Default::default(),
        }
    }

    /// The family names of every face, in order.
    pub fn families(&self) -> Vec<String> {
        self.db
            .faces()
            .flat_map(|f| f.families.iter().map(|(n, _)| n.clone()))
            .collect()
    }

    /// The sets of the lookup order: this one's faces, then those it defers to; with
    /// `lazy`, the sets made only when needed too (which makes them).
    fn layers(&self, lazy: bool) -> Vec<&Fonts> {
        let mut layers = vec![self];
        while let Some(next) = layers[layers.len() - 1].then {
            if next.lazy && !lazy {
                break;
            }
            layers.push((next.set)());
        }
        layers
    }

    /// A face's style names ([`crate::fontscan::style_names`]): read with the scan, else
    /// from its font data.
    fn style_names(&self, f: &fontdb::FaceInfo) -> std::borrow::Cow<'_, [String]> {
        match self.styles.get(&f.id) {
            Some(names) => names.into(),
            None => (self.db.with_face_data(f.id, crate::fontscan::style_names))
                .unwrap_or_default()
                .into(),
        }
    }

    /// The font data of a face [`Fonts::find`] returned (its set was made to find it).
    fn with_face_data<T>(&self, face: FaceId, f: impl FnOnce(&[u8], u32) -> T) -> Option<T> {
        let mut set = self;
        for _ in 0..face.layer {
            set = (set.then?.set)();
        }
        set.db.with_face_data(face.id, f)
    }

    /// `CSGPIX_FONT_PATH` and the bundled fonts, loaded once per process, then the system
    /// fonts, scanned when first needed.
    pub fn standard() -> &'static Fonts {
        static FONTS: OnceLock<Fonts> = OnceLock::new();
        FONTS.get_or_init(|| {
            let mut dirs: Vec<PathBuf> = std::env::var_os("CSGPIX_FONT_PATH")
                .map(|v| {
                    std::env::split_paths(&v)
                        .filter(|p| !p.as_os_str().is_empty())
                        .collect()
                })
                .unwrap_or_default();
            dirs.extend(bundled_font_dir());
            Fonts {
                then: Some(Then {
                    set: Fonts::system,
                    lazy: true,
                }),
                ..Fonts::new(&dirs, false)
            }
        })
    }

    /// The system's fonts, scanned once per process, and only when a lookup needs them:
    /// parsing every installed face took about 7 ms of a `text()` design's run, whose font
    /// (OpenSCAD's default, Liberation Sans) is most often bundled. The scan reads of each
    /// file only the tables fontdb parses ([`crate::fontscan`]).
    fn system() -> &'static Fonts {
        static FONTS: OnceLock<Fonts> = OnceLock::new();
        FONTS.get_or_init(|| Fonts::new(&[], true))
    }

    /// The face a fontconfig-style name (`"Liberation Sans:style=Bold"`, `"DejaVu Sans:bold"`)
    /// names; `""` is [`DEFAULT_FONT`]. The first face found in lookup order wins. The sets
    /// made only when needed (the system's fonts) are looked in when the others give no face
    /// or one that a face after them could beat (a weight not the one asked): a face with
    /// the asked style, or of the asked weight, is the first of its kind, as with them.
    pub fn find(&self, name: &str) -> csgpix_scene::Result<FaceId> {
        let eager = self.layers(false);
        // The last set made has a `then` only when that set is one made when needed.
        if eager[eager.len() - 1].then.is_some() {
            if let Ok((face, true)) = self.find_in(&eager, name) {
                return Ok(face);
            }
        }
        self.find_in(&self.layers(true), name).map(|(face, _)| face)
    }

    /// [`Fonts::find`] over `layers`, and whether no face of a later set could be picked
    /// instead: the first family named has faces here, and the style named matched or the
    /// weight asked was found.
    fn find_in(&self, layers: &[&Fonts], name: &str) -> csgpix_scene::Result<(FaceId, bool)> {
        let lookup = lookup_name(name);
        let (families, props) = lookup.split_once(':').unwrap_or((lookup, ""));
        let props = FontProps::parse(name, props)?;
        // Whether a family named before had no face here (a later set may have one).
        let mut passed = false;
        for family in families.split(',').map(str::trim).filter(|f| !f.is_empty()) {
            // The faces of the family, in lookup order.
            let faces: Vec<(usize, &fontdb::FaceInfo)> = layers
                .iter()
                .enumerate()
                .flat_map(|(layer, fonts)| fonts.db.faces().map(move |f| (layer, f)))
                .filter(|(_, f)| {
                    f.families
                        .iter()
                        .any(|(n, _)| n.eq_ignore_ascii_case(family))
                })
                .collect();
            if faces.is_empty() {
                passed = true;
                continue;
            }
            return match props.pick(layers, &faces) {
                Some((layer, f)) => Ok((
                    FaceId {
                        layer: *layer,
                        id: f.id,
                    },
                    !passed && (props.style.is_some() || f.weight.0 == props.weight.unwrap_or(400)),
                )),
                None => Err(Error::NoSuchStyle {
                    family: family.to_string(),
                }
                .context(format_args!("font `{name}`"))),
            };
        }
        Err(Error::FontNotFound {
            font: name.to_string(),
            scene: self.scene,
        })
    }
}

/// The properties after a font name's families (fontconfig's pattern syntax, the part
/// csgpix reads): `style=…`, `weight=…` and the constants `bold`, `italic`, `regular`.
struct FontProps {
    style: Option<String>,
    weight: Option<u16>,
    italic: bool,
}

impl FontProps {
    /// The properties `props` of font `name`; an error names one csgpix does not read.
    fn parse(name: &str, props: &str) -> csgpix_scene::Result<FontProps> {
        let mut style: Option<String> = None;
        let mut weight: Option<u16> = None;
        let mut italic = false;
        for prop in props.split(':').map(str::trim).filter(|p| !p.is_empty()) {
            match prop.split_once('=') {
                Some((k, v)) if k.trim().eq_ignore_ascii_case("style") => {
                    style = Some(v.trim().to_string())
                }
                Some((k, v)) if k.trim().eq_ignore_ascii_case("weight") => {
                    weight = Some(match v.trim().to_ascii_lowercase().as_str() {
                        "bold" => 700,
                        "regular" | "normal" | "medium" => 400,
                        _ => {
                            return Err(Error::UnsupportedFontWeight {
                                weight: v.to_string(),
                            }
                            .context(format_args!("font `{name}`")))
                        }
                    })
                }
                None if prop.eq_ignore_ascii_case("bold") => weight = Some(700),
                None if prop.eq_ignore_ascii_case("italic") => italic = true,
                None if prop.eq_ignore_ascii_case("regular") => weight = Some(400),
                _ => {
                    return Err(Error::UnsupportedFontProperty {
                        property: prop.to_string(),
                    }
                    .context(format_args!("font `{name}`")))
                }
            }
        }
        Ok(FontProps {
            style,
            weight,
            italic,
        })
    }

    /// The face of a family's `faces` (in lookup order) these properties pick: the first
    /// with the named style; else, of normal stretch and the wanted slant, the nearest in
    /// weight to the one asked (400 when none), which must match it when one was asked.
    fn pick<'f, 'd>(
        &self,
        layers: &[&Fonts],
        faces: &'f [(usize, &'d fontdb::FaceInfo)],
    ) -> Option<&'f (usize, &'d fontdb::FaceInfo)> {
        if let Some(style) = &self.style {
            return faces.iter().find(|(layer, f)| {
                layers[*layer]
                    .style_names(f)
                    .iter()
                    .any(|s| s.eq_ignore_ascii_case(style))
            });
        }
        let (weight, italic) = (self.weight, self.italic);
        let want = weight.unwrap_or(400);
        let wants_italic =
            |(_, f): &&(usize, &fontdb::FaceInfo)| (f.style != fontdb::Style::Normal) == italic;
        faces
            .iter()
            .filter(wants_italic)
            .filter(|(_, f)| f.stretch == fontdb::Stretch::Normal)
            .min_by_key(|(_, f)| (f.weight.0 as i32 - want as i32).abs())
            .filter(|(_, f)| weight.is_none() || f.weight.0 == want)
    }
}

impl Fonts {
    /// [`Fonts::find`], or where it finds nothing, the face fontconfig matches for the name
    /// (as OpenSCAD draws it), with a note saying so.
    pub fn find_or_substitute(&self, name: &str) -> csgpix_scene::Result<(FaceId, Option<String>)> {
        let missing = match self.find(name) {
            Ok(id) => return Ok((id, None)),
            Err(e) => e,
        };
        let lookup = lookup_name(name);
        let Some(m) = fontconfig_match(lookup) else {
            return Err(missing);
        };
        let layers = self.layers(true);
        let face = layers.iter().enumerate().find_map(|(layer, fonts)| {
            fonts
                .db
                .faces()
                .find(|f| f.index == m.index && source_path(&f.source).is_some_and(|p| m.is(p)))
                .map(|f| FaceId { layer, id: f.id })
        });
        let Some(face) = face else {
            return Err(missing);
        };
        let note = format!(
            "{missing}: drawn in `{}:style={}` ({}), fontconfig's match, as OpenSCAD draws it",
            m.family,
            m.style,
            m.file.display()
        );
        Ok((face, Some(note)))
    }
}

/// Whether a font collection's header (`ttcf`) counts no more faces than its offset table
/// has room for: fontdb reserves (and walks) as many faces as the count says, so a damaged
/// count of 2^31 was a 33 GB allocation and an abort (found by the `fonts` fuzz target). A
/// single font is not a collection and fits.
fn collection_fits(data: &[u8]) -> bool {
    header_fits(data, data.len() as u64)
}

/// Whether the faces a font file's `header` counts fit a file of `len` bytes.
fn header_fits(header: &[u8], len: u64) -> bool {
    match ttf_parser::fonts_in_collection(header) {
        Some(n) => 12 + 4 * n as u64 <= len,
        None => true,
    }
}

/// [`collection_fits`] of a font file, from its header and its length (the file is not read
/// twice); false when it cannot be read.
fn file_collection_fits(path: &Path) -> bool {
    use std::io::Read;
    let Ok(file) = std::fs::File::open(path) else {
        return false;
    };
    let Ok(len) = file.metadata().map(|m| m.len()) else {
        return false;
    };
    let mut header = Vec::with_capacity(12);
    file.take(12).read_to_end(&mut header).is_ok() && header_fits(&header, len)
}

/// Where a face's data comes from, when it is a file.
fn source_path(s: &fontdb::Source) -> Option<&Path> {
    match s {
        fontdb::Source::File(p) => Some(p),
        fontdb::Source::SharedFile(p, _) => Some(p),
        _ => None,
    }
}

/// Fontconfig's answer for a pattern.
#[derive(Clone)]
struct Match {
    file: PathBuf,
    index: u32,
    family: String,
    style: String,
}

impl Match {
    /// Whether `path` is the matched file (the same name, or the same file through links).
    fn is(&self, path: &Path) -> bool {
        path == self.file
            || (path.file_name() == self.file.file_name()
                && std::fs::canonicalize(path).ok() == std::fs::canonicalize(&self.file).ok())
    }
}

/// Asks fontconfig (`fc-match`) for the font it matches to `pattern`; None without fontconfig
/// or an answer. OpenSCAD's own configuration also registers its font path
/// (`OPENSCAD_FONT_PATH`), which `FONTCONFIG_PATH`/`FONTCONFIG_FILE` can give fc-match.
///
/// Each pattern is asked once a process, as [`Fonts::standard`] scans the fonts once: a
/// design naming a missing font in every `text()` started an `fc-match` (about 8 ms) for each.
fn fontconfig_match(pattern: &str) -> Option<Match> {
    use std::collections::HashMap;
    use std::sync::{Mutex, OnceLock};
    static ASKED: OnceLock<Mutex<HashMap<String, Option<Match>>>> = OnceLock::new();
    let asked = ASKED.get_or_init(Mutex::default);
    if let Some(m) = asked.lock().ok().and_then(|a| a.get(pattern).cloned()) {
        return m;
    }
    let m = ask_fontconfig(pattern);
    if let Ok(mut a) = asked.lock() {
        a.insert(pattern.to_string(), m.clone());
    }
    m
}

/// The patterns [`ask_fontconfig`] ran `fc-match` for, in the tests.
#[cfg(test)]
static ASKED_FONTCONFIG: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());

/// [`fontconfig_match`] without its memory: one `fc-match` run.
fn ask_fontconfig(pattern: &str) -> Option<Match> {
    #[cfg(test)]
    if let Ok(mut asked) = ASKED_FONTCONFIG.lock() {
        asked.push(pattern.to_string());
    }
    let out = std::process::Command::new("fc-match")
        .arg("--format=%{file}\\t%{index}\\t%{family[0]}\\t%{style[0]}")
        .arg("--")
        .arg(pattern)
        .stdin(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .output()
        .ok()?;
    if !out.status.success() {
        return None;
    }
    let text = String::from_utf8(out.stdout).ok()?;
    let mut parts = text.trim_end_matches('\n').split('\t');
    let file = PathBuf::from(parts.next()?);
    let index = parts.next()?.trim().parse().ok()?;
    let family = parts.next().unwrap_or("").to_string();
    let style = parts.next().unwrap_or("").to_string();
    file.is_file().then_some(Match {
        file,
        index,
        family,
        style,
    })
}

/// The arguments of one `text()` node.
#[derive(Clone, Debug)]
pub struct TextSpec {
    /// The string.
    pub text: String,
    /// `size` (10): the scale of the em, see the module docs.
    pub size: f64,
    /// `spacing` (1): multiplies the advances.
    pub spacing: f64,
    /// `font`, fontconfig syntax; `""` is [`DEFAULT_FONT`].
    pub font: String,
    /// `direction`: `ltr`, `rtl`, `ttb`, `btt`; anything else lets the shaper guess.
    pub direction: String,
    /// `language` for the shaper (`en`).
    pub language: String,
    /// `script` as an ISO 15924 tag (`Latn`); anything else lets the shaper guess.
    pub script: String,
    /// `halign`: `left`, `center`, `right`.
    pub halign: String,
    /// `valign`: `top`, `center`, `baseline`, `bottom`.
    pub valign: String,
    /// Straight segments per Bézier segment.
    pub segments: usize,
}

impl TextSpec {
    /// OpenSCAD's defaults (`TextModule::instantiate`) with `$fn = 0, $fa = 12, $fs = 2`.
    pub fn new(text: &str, size: f64) -> TextSpec {
        TextSpec {
            text: text.into(),
            size,
            spacing: 1.0,
            font: String::new(),
            direction: String::new(),
            language: "en".into(),
            script: String::new(),
            halign: "left".into(),
            valign: "baseline".into(),
            segments: segments(size, 0.0, 12.0, 2.0),
        }
    }
}

/// `text_segments` of `TextModule::instantiate`: `max(floor(f / 8) + 1, 2)`.
pub fn segments(size: f64, fn_: f64, fa: f64, fs: f64) -> usize {
    let f = Resolution { fn_, fa, fs }.fragments_from_r(size);
    ((f / 8.0).floor() + 1.0).max(2.0).min(MAX_FRAGMENTS as f64) as usize
}

/// One glyph's contours in outline units (26.6 / [`SCALE`]) and its 26.6 control box.
#[derive(Default)]
struct Outline {
    n: usize,
    to26: f64,
    contours: Vec<Vec<DVec2>>,
    pen: DVec2,
    start: DVec2,
    lo: DVec2,
    hi: DVec2,
}

impl Outline {
    fn p(&mut self, x: f32, y: f32) -> DVec2 {
        let p26 = DVec2::new(x as f64, y as f64) * self.to26;
        self.lo = self.lo.min(p26);
        self.hi = self.hi.max(p26);
        p26 / SCALE
    }
    fn add(&mut self, v: DVec2) {
        if let Some(c) = self.contours.last_mut() {
            c.push(v);
        }
    }
}

impl ttf_parser::OutlineBuilder for Outline {
    fn move_to(&mut self, x: f32, y: f32) {
        let v = self.p(x, y);
        self.contours.push(vec![v]);
        self.pen = v;
        self.start = v;
    }
    fn line_to(&mut self, x: f32, y: f32) {
        let v = self.p(x, y);
        self.add(v);
        self.pen = v;
    }
    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (c1, to) = (self.p(x1, y1), self.p(x, y));
        let pen = self.pen;
        for i in 1..=self.n {
            let a = i as f64 * (1.0 / self.n as f64);
            self.add(pen * (1.0 - a).powi(2) + c1 * 2.0 * (1.0 - a) * a + to * a.powi(2));
        }
        self.pen = to;
    }
    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (c1, c2, to) = (self.p(x1, y1), self.p(x2, y2), self.p(x, y));
        let pen = self.pen;
        for i in 1..=self.n {
            let a = i as f64 * (1.0 / self.n as f64);
            self.add(
                pen * (1.0 - a).powi(3)
                    + c1 * 3.0 * (1.0 - a).powi(2) * a
                    + c2 * 3.0 * (1.0 - a) * a.powi(2)
                    + to * a.powi(3),
            );
        }
        self.pen = to;
    }
    fn close(&mut self) {
        // FT_Outline_Decompose ends every contour with a line back to its start.
        let s = self.start;
        self.add(s);
        self.pen = s;
    }
}

/// 26.6 units per font unit at OpenSCAD's character size, as the hinted outlines are
/// scaled (`FT_LOAD_DEFAULT`: the TrueType driver's `hinted_metrics`, whole pixels per em
/// when `head` asks for it).
fn units_26_6(face: &ttf_parser::Face) -> f64 {
    let upem = face.units_per_em() as f64;
    let mut ppem26 = EM_26_6;
    let head = face.raw_face().table(ttf_parser::Tag::from_bytes(b"head"));
    let integer_ppem = head
        .and_then(|h| h.get(16..18))
        .is_some_and(|f| u16::from_be_bytes([f[0], f[1]]) & 8 != 0);
    if integer_ppem && face.tables().glyf.is_some() {
        ppem26 = ((ppem26 + 32.0) / 64.0).floor() * 64.0;
    }
    ppem26 / upem
}

/// 26.6 units per font unit as HarfBuzz positions are scaled: hb-ft asks FreeType for
/// unhinted advances (`FT_LOAD_NO_HINTING`), scaled by the size's own `x_scale`, which the
/// TrueType driver leaves unrounded (FreeType >= 2.8 rounds only its `hinted_metrics`).
fn units_26_6_positions(face: &ttf_parser::Face) -> f64 {
    EM_26_6 / face.units_per_em() as f64
}

/// The outline of a `text()` node in its own plane.
/// At most `max_points` outline points are made (before the union).
pub fn render(spec: &TextSpec, fonts: &Fonts, max_points: usize) -> csgpix_scene::Result<Poly2> {
    render_noting(spec, fonts, max_points, &mut vec![])
}

/// [`render`], a font fontconfig substituted ([`Fonts::find_or_substitute`]) noted in `notes`.
pub fn render_noting(
    spec: &TextSpec,
    fonts: &Fonts,
    max_points: usize,
    notes: &mut Vec<String>,
) -> csgpix_scene::Result<Poly2> {
    let (id, note) = fonts.find_or_substitute(&spec.font)?;
    notes.extend(note);
    render_in(spec, fonts, id, max_points)
}

/// [`render`] in face `id` of `fonts` (as [`Fonts::find`] found it).
pub fn render_in(
    spec: &TextSpec,
    fonts: &Fonts,
    id: FaceId,
    max_points: usize,
) -> csgpix_scene::Result<Poly2> {
    render_counted(spec, fonts, id, max_points).map(|(poly, _)| poly)
}

/// An error for a `halign` or `valign` OpenSCAD does not know.
fn check_alignment(spec: &TextSpec) -> csgpix_scene::Result<()> {
    if !matches!(spec.halign.as_str(), "left" | "right" | "center") {
        return Err(Error::UnknownAlignment {
            axis: "halign",
            value: spec.halign.clone(),
            allowed: "left, center or right",
        });
    }
    if !matches!(
        spec.valign.as_str(),
        "top" | "center" | "baseline" | "bottom"
    ) {
        return Err(Error::UnknownAlignment {
            axis: "valign",
            value: spec.valign.clone(),
            allowed: "top, center, baseline or bottom",
        });
    }
    Ok(())
}

/// [`render_in`], and the outline points the glyphs made (what `max_points` bounds).
fn render_counted(
    spec: &TextSpec,
    fonts: &Fonts,
    id: FaceId,
    max_points: usize,
) -> csgpix_scene::Result<(Poly2, usize)> {
    check_alignment(spec)?;
    fonts
        .with_face_data(id, |data, index| render_face(spec, data, index, max_points))
        .unwrap_or_else(|| {
            Err(Error::FontUnreadable {
                font: spec.font.clone(),
                parsed: false,
            })
        })
}

/// OpenSCAD's `FreetypeRenderer::render` of `spec` with the face in `data`: the text shaped,
/// its glyphs outlined, the whole aligned by `halign` and `valign` and scaled by `size`.
fn render_face(
    spec: &TextSpec,
    data: &[u8],
    index: u32,
    max_points: usize,
) -> csgpix_scene::Result<(Poly2, usize)> {
    let face = rustybuzz::Face::from_slice(data, index).ok_or_else(|| Error::FontUnreadable {
        font: spec.font.clone(),
        parsed: true,
    })?;
    let buffer = shaping_buffer(spec);
    let horizontal = matches!(
        buffer.direction(),
        rustybuzz::Direction::LeftToRight | rustybuzz::Direction::RightToLeft
    );
    let shaped = rustybuzz::shape(&face, &[], buffer);
    let glyphs = outline_glyphs(spec, &face, &shaped, horizontal, max_points)?;
    // Positions as hb-ft reports them: whole 26.6 units.
    let pos_to26 = units_26_6_positions(&face);
    let (width, ascend, descend) = text_extent(spec, &glyphs, horizontal, pos_to26);
    let x_offset = match spec.halign.as_str() {
        "right" => -width,
        "center" => -width / 2.0,
        _ => 0.0,
    };
    let y_offset = match spec.valign.as_str() {
        "top" => -ascend,
        "center" => descend / 2.0 - ascend / 2.0,
        "bottom" => descend,
        _ => 0.0,
    };
    let offset = DVec2::new(x_offset, y_offset);
    let points = (glyphs.iter())
        .map(|(o, _)| o.contours.iter().map(Vec::len).sum::<usize>())
        .sum();
    Ok((
        nonzero_union(place_glyphs(spec, &glyphs, offset, pos_to26)),
        points,
    ))
}

/// A glyph position in whole 26.6 units (hb-ft's), from font units scaled by `pos_to26`.
fn whole_26_6(v: i32, pos_to26: f64) -> f64 {
    (v as f64 * pos_to26).round()
}

/// The HarfBuzz buffer of `spec`'s text with its direction, script and language where they
/// parse; the rest guessed from the text.
fn shaping_buffer(spec: &TextSpec) -> rustybuzz::UnicodeBuffer {
    let mut buffer = rustybuzz::UnicodeBuffer::new();
    buffer.push_str(&spec.text);
    if let Ok(d) = spec.direction.parse::<rustybuzz::Direction>() {
        buffer.set_direction(d);
    }
    if let Some(s) = rustybuzz::Script::from_iso15924_tag(ttf_parser::Tag::from_bytes_lossy(
        spec.script.as_bytes(),
    )) {
        buffer.set_script(s);
    }
    if let Ok(l) = spec.language.parse::<rustybuzz::Language>() {
        buffer.set_language(l);
    }
    buffer.guess_segment_properties();
    buffer
}

/// Each shaped glyph's outline (in 26.6 units) with its position, vertical positions as
/// FreeType gives them; an error once the outlines pass `max_points` points.
fn outline_glyphs(
    spec: &TextSpec,
    face: &rustybuzz::Face,
    shaped: &rustybuzz::GlyphBuffer,
    horizontal: bool,
    max_points: usize,
) -> csgpix_scene::Result<Vec<(Outline, rustybuzz::GlyphPosition)>> {
    let to26 = units_26_6(face);
    let mut glyphs = Vec::new();
    let mut points = 0usize;
    for (info, pos) in shaped.glyph_infos().iter().zip(shaped.glyph_positions()) {
        let mut o = Outline {
            n: spec.segments,
            to26,
            lo: DVec2::splat(f64::INFINITY),
            hi: DVec2::splat(f64::NEG_INFINITY),
            ..Outline::default()
        };
        let id = ttf_parser::GlyphId(info.glyph_id as u16);
        face.outline_glyph(id, &mut o);
        points += o.contours.iter().map(Vec::len).sum::<usize>();
        if points > max_points {
            return Err(Error::TextTooDetailed { limit: max_points });
        }
        let mut pos = *pos;
        if !horizontal {
            freetype_vertical_metrics(face, id, &mut pos);
        }
        glyphs.push((o, pos));
    }
    Ok(glyphs)
}

/// hb-ft's vertical metrics, which OpenSCAD gets: FreeType's TrueType loader makes them up
/// for a font without `vmtx` (TT_Get_VMetrics, compute_glyph_metrics): the advance is
/// sTypoAscender − sTypoDescender (hhea's without OS/2) and the origin lies
/// `top = (advance − height) / 2` above the glyph's box; HarfBuzz's own fallback
/// (rustybuzz) uses the font ascender and descender instead.
fn freetype_vertical_metrics(
    face: &rustybuzz::Face,
    id: ttf_parser::GlyphId,
    pos: &mut rustybuzz::GlyphPosition,
) {
    if face.tables().vmtx.is_none() {
        let advance = match face.tables().os2 {
            Some(os2) => os2.typographic_ascender() as i32 - os2.typographic_descender() as i32,
            None => face.ascender() as i32 - face.descender() as i32,
        };
        let (y_min, y_max) = face
            .glyph_bounding_box(id)
            .map_or((0, 0), |b| (b.y_min as i32, b.y_max as i32));
        let top = (advance - (y_max - y_min)) / 2;
        pos.y_offset = -(y_max + top);
        pos.y_advance = -advance;
    }
}

/// The text's width, ascent and descent (in units of `size`) as OpenSCAD measures them for
/// alignment: from the grid-fitted glyph boxes and the advances.
fn text_extent(
    spec: &TextSpec,
    glyphs: &[(Outline, rustybuzz::GlyphPosition)],
    horizontal: bool,
    pos_to26: f64,
) -> (f64, f64, f64) {
    let (mut width, mut ascend, mut descend) = (0.0f64, 0.0f64, 0.0f64);
    for (o, pos) in glyphs {
        let pos = *pos;
        // FT_Glyph_Get_CBox(FT_GLYPH_BBOX_GRIDFIT): an empty glyph's box is all zeros.
        let (lo, hi) = if o.lo.x.is_finite() {
            ((o.lo / 64.0).floor() * 64.0, (o.hi / 64.0).ceil() * 64.0)
        } else {
            (DVec2::ZERO, DVec2::ZERO)
        };
        if horizontal {
            ascend = ascend.max((hi.y / UNSCALE).max(0.0));
            descend = descend.max((-lo.y / UNSCALE).max(0.0));
            width += whole_26_6(pos.x_advance, pos_to26) / UNSCALE * spec.spacing;
        } else {
            width = width.max((hi.x - lo.x) / UNSCALE);
            ascend += whole_26_6(pos.y_advance, pos_to26) / UNSCALE * spec.spacing;
        }
    }
    (width, ascend, descend)
}

/// The glyphs' contours placed one after another along the advances, moved by the
/// alignment `offset` and scaled by `size`.
fn place_glyphs(
    spec: &TextSpec,
    glyphs: &[(Outline, rustybuzz::GlyphPosition)],
    offset: DVec2,
    pos_to26: f64,
) -> Vec<Vec<[f64; 2]>> {
    let pos26 = |v: i32| whole_26_6(v, pos_to26);
    let mut advance = DVec2::ZERO;
    let mut paths: Vec<Vec<[f64; 2]>> = Vec::new();
    for (o, pos) in glyphs {
        let offset = DVec2::new(
            offset.x + pos26(pos.x_offset) / UNSCALE,
            offset.y + pos26(pos.y_offset) / UNSCALE,
        );
        for c in &o.contours {
            paths.push(
                c.iter()
                    .map(|v| (spec.size * (*v + offset + advance)).to_array())
                    .collect(),
            );
        }
        advance += DVec2::new(
            pos26(pos.x_advance) / UNSCALE * spec.spacing,
            pos26(pos.y_advance) / UNSCALE * spec.spacing,
        );
    }
    paths
}

/// The contours united with the nonzero rule, as simple paths (outer outlines and holes).
fn nonzero_union(paths: Vec<Vec<[f64; 2]>>) -> Poly2 {
    use i_overlay::core::fill_rule::FillRule;
    use i_overlay::core::overlay_rule::OverlayRule;
    use i_overlay::float::single::SingleFloatOverlay;
    if paths.is_empty() {
        return Poly2 { paths: vec![] };
    }
    let none: Vec<Vec<[f64; 2]>> = vec![];
    let shapes = paths.overlay(&none, OverlayRule::Subject, FillRule::NonZero);
    Poly2 {
        paths: shapes
            .into_iter()
            .flatten()
            .map(|c| c.into_iter().map(DVec2::from).collect())
            .collect(),
    }
}

/// A string argument, or its default.
fn string(p: &Params, name: &str, default: &str) -> Result<String, Fail> {
    match p.get(name) {
        None => Ok(default.into()),
        Some(v) => match &v.kind {
            crate::value::Kind::Str(s) => Ok(s.clone()),
            _ => fail(v.pos, must(&format!("`{name}`"), Rule::Text)),
        },
    }
}

/// `text(text, size, font, direction, language, script, halign, valign, spacing, $fn, $fa,
/// $fs)` as a shape in its own plane.
pub(crate) fn text_shape(
    p: &Params,
    fonts: &Fonts,
    budget: usize,
    notes: &mut Vec<String>,
    drawn: &mut Drawn,
) -> Result<Poly2, Fail> {
    let size = match p.number("size")? {
        None => 10.0,
        Some((s, at)) if !(s > 0.0 && s <= MAX_COORDINATE) => {
            return fail(at, must("`size`", Rule::Positive(s)))
        }
        Some((s, _)) => s,
    };
    let spacing = match p.number("spacing")? {
        None => 1.0,
        Some((s, at)) if !(s.is_finite() && s.abs() <= MAX_COORDINATE) => {
            return fail(at, must("`spacing`", Rule::FiniteNumber))
        }
        Some((s, _)) => s,
    };
    let res = Resolution::read(p)?;
    let spec = TextSpec {
        text: string(p, "text", "")?,
        size,
        spacing,
        font: string(p, "font", "")?,
        direction: string(p, "direction", "")?,
        language: string(p, "language", "en")?,
        script: string(p, "script", "")?,
        halign: string(p, "halign", "left")?,
        valign: string(p, "valign", "baseline")?,
        segments: segments(size, res.fn_, res.fa, res.fs),
    };
    // Drawing holds far more than the points drawn: each is charged as several vertices,
    // within the budget less the process's own memory (a text is the one primitive whose
    // drawing can outgrow the rest of a small run).
    let process = (crate::PROCESS_BYTES / crate::BYTES_PER_SCENE_VERTEX) as usize;
    let budget = budget.saturating_sub(process);
    let points = budget / TEXT_POINT_VERTICES;
    let poly = (drawn.render(&spec, fonts, points, notes)).map_err(|problem| Fail {
        pos: p.pos,
        problem,
    })?;
    check_budget(charged_vertices(poly.points().count()), budget, p.pos)?;
    Ok(poly)
}

/// The `text()`s a scene has drawn, by their arguments: a text met again (a module called
/// again, a shadow drawn beside its letters) is drawn once in a reading. The font lookup is
/// the reader's for the whole scene, so the same arguments give the same outline.
#[derive(Default)]
pub(crate) struct Drawn {
    texts: std::collections::HashMap<TextKey, Drawing>,
    /// The bytes the outlines kept hold ([`csgpix_scene::solid::CsgScene::reading_bytes`]).
    pub(crate) bytes: u64,
}

/// A text's arguments, its numbers by their bits.
#[derive(PartialEq, Eq, Hash)]
struct TextKey {
    words: [String; 7],
    numbers: [u64; 2],
    segments: usize,
}

impl TextKey {
    fn of(s: &TextSpec) -> TextKey {
        let words = [
            &s.text,
            &s.font,
            &s.direction,
            &s.language,
            &s.script,
            &s.halign,
            &s.valign,
        ];
        TextKey {
            words: words.map(String::clone),
            numbers: [s.size.to_bits(), s.spacing.to_bits()],
            segments: s.segments,
        }
    }
}

/// A text drawn: its outline, the notes the font lookup gave, and the outline points its
/// glyphs made (which a smaller `max_points` refuses).
struct Drawing {
    poly: Poly2,
    notes: Vec<String>,
    points: usize,
}

impl Drawn {
    /// [`render_noting`] of `spec`, or, for a text drawn before, what it gave then: the same
    /// outline and notes, or the error drawing it again gives where its points pass
    /// `max_points`.
    fn render(
        &mut self,
        spec: &TextSpec,
        fonts: &Fonts,
        max_points: usize,
        notes: &mut Vec<String>,
    ) -> csgpix_scene::Result<Poly2> {
        let key = TextKey::of(spec);
        if let Some(d) = self.texts.get(&key) {
            if d.points > max_points {
                return Err(Error::TextTooDetailed { limit: max_points });
            }
            notes.extend(d.notes.iter().cloned());
            return Ok(d.poly.clone());
        }
        let (id, note) = fonts.find_or_substitute(&spec.font)?;
        notes.extend(note.clone());
        let (poly, points) = render_counted(spec, fonts, id, max_points)?;
        self.bytes += crate::extrude::poly_bytes(&poly);
        let notes = note.into_iter().collect();
        let drawing = Drawing {
            poly: poly.clone(),
            notes,
            points,
        };
        self.texts.insert(key, drawing);
        Ok(poly)
    }
}

/// The scene vertices a text outline of `points` points is charged while drawn
/// ([`TEXT_POINT_VERTICES`] a point): against the reader's budget, and in the run's estimate
/// ([`csgpix_scene::solid::CsgScene::reading_bytes`]).
pub(crate) fn charged_vertices(points: usize) -> usize {
    points.saturating_mul(TEXT_POINT_VERTICES)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extrude::signed_area;

    fn fonts() -> Fonts {
        Fonts::new(&[bundled_font_dir().expect("vectors/fonts")], false)
    }

    fn strict() -> crate::ReadOptions {
        crate::ReadOptions {
            strict: true,
            ..Default::default()
        }
    }

    /// A font no font file has: fontconfig's match, the one OpenSCAD draws (DejaVu Sans on
    /// Debian, fontconfig's default), with a warning; refused under `strict`.
    #[test]
    fn a_missing_font_is_fontconfigs_match_with_a_warning() {
        let Some(m) = fontconfig_match("Arial Black") else {
            eprintln!("fc-match is not on PATH: skipped");
            return;
        };
        let text = "linear_extrude(height = 1)\n  text(text = \"csg\", font = \"Arial Black\");\n";
        let s = crate::parse_csg(text, "t.csg").unwrap();
        assert_eq!(s.warnings.len(), 1);
        let w = s.warnings[0].to_string();
        assert!(
            w.starts_with("t.csg:2:3: font `Arial Black` not found"),
            "{w}"
        );
        assert!(w.contains("fontconfig's match"), "{w}");
        // The same outline as the matched face named directly.
        let named = format!(
            "linear_extrude(height = 1)\n  text(text = \"csg\", font = \"{}:style={}\");\n",
            m.family, m.style
        );
        let direct = crate::parse_csg(&named, "t.csg").unwrap();
        assert!(direct.warnings.is_empty(), "{:?}", direct.warnings);
        assert_eq!(s.imports, direct.imports);
        assert_eq!(s.solids, direct.solids);
    }

    /// A text drawn again ([`Drawn`]) is what drawing it afresh gives: the same outline,
    /// and under a point limit its points pass, the same error; other arguments are drawn
    /// anew.
    #[test]
    fn a_text_drawn_again_is_the_text_drawn_afresh() {
        let f = fonts();
        let spec = TextSpec::new("Björn", 10.0);
        let mut drawn = Drawn::default();
        let fresh = render(&spec, &f, usize::MAX).unwrap();
        assert_eq!(
            drawn.render(&spec, &f, usize::MAX, &mut vec![]),
            Ok(fresh.clone())
        );
        assert_eq!(
            drawn.render(&spec, &f, usize::MAX, &mut vec![]),
            Ok(fresh.clone())
        );
        assert_eq!(drawn.texts.len(), 1);
        let points = drawn.texts.values().next().unwrap().points;
        assert!(points > fresh.points().count() / 2, "{points}");
        for limit in [points - 1, points] {
            let again = drawn.render(&spec, &f, limit, &mut vec![]);
            assert_eq!(again, render(&spec, &f, limit), "{limit}");
        }
        assert!(drawn.render(&spec, &f, points - 1, &mut vec![]).is_err());
        let larger = TextSpec::new("Björn", 11.0);
        let other = drawn.render(&larger, &f, usize::MAX, &mut vec![]).unwrap();
        assert_eq!(other, render(&larger, &f, usize::MAX).unwrap());
        assert_ne!(other, fresh);
        assert_eq!(drawn.texts.len(), 2);
    }

    /// A missing font named by three `text()`s: fontconfig is asked once (each ask starts an
    /// `fc-match`), and each `text()` warns and is drawn in the match.
    #[test]
    fn a_missing_font_is_asked_of_fontconfig_once() {
        let name = "Csgpix Absent Sans Thrice";
        if fontconfig_match(name).is_none() {
            eprintln!("fc-match is not on PATH: skipped");
            return;
        }
        let one = format!("linear_extrude(height = 1) text(text = \"ab\", font = \"{name}\");\n");
        let s = crate::parse_csg(&one.repeat(3), "t.csg").unwrap();
        assert_eq!(s.warnings.len(), 3, "{:?}", s.warnings);
        assert!(s
            .warnings
            .iter()
            .all(|w| w.to_string().contains("fontconfig's match")));
        let asked = ASKED_FONTCONFIG.lock().unwrap();
        assert_eq!(asked.iter().filter(|p| *p == name).count(), 1, "{asked:?}");
    }

    /// Times [`later`] was asked for its set.
    static LATER_ASKED: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

    /// The bundled fonts, as a set after [`sans_alone`].
    fn later() -> &'static Fonts {
        static SET: OnceLock<Fonts> = OnceLock::new();
        LATER_ASKED.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        SET.get_or_init(fonts)
    }

    /// One bundled font file alone, then [`later`], lazily or not.
    fn alone(file: &str, lazy: bool) -> Fonts {
        let dir = bundled_font_dir().expect("vectors/fonts");
        let data = std::fs::read(dir.join(file)).unwrap();
        Fonts {
            then: Some(Then { set: later, lazy }),
            ..Fonts::of_data(data)
        }
    }

    /// A set made only when needed is asked for only where the sets before it leave the
    /// answer open, and every answer is the one of the whole lookup order.
    #[test]
    fn a_lazy_set_is_made_only_when_a_lookup_needs_it() {
        use std::sync::atomic::Ordering::SeqCst;
        let sans = "LiberationSans-Regular.ttf";
        let (lazy, eager) = (alone(sans, true), alone(sans, false));
        let asked = |name: &str| {
            let before = LATER_ASKED.load(SeqCst);
            let face = lazy.find(name).unwrap();
            let made = LATER_ASKED.load(SeqCst) > before;
            assert_eq!(face, eager.find(name).unwrap(), "{name}");
            (face.layer, made)
        };
        // Found, of the weight asked, before the lazy set: it is not made.
        assert_eq!(asked("Liberation Sans"), (0, false));
        assert_eq!(asked("Liberation Sans:style=Regular"), (0, false));
        // A style, a weight or a family only the lazy set has.
        assert_eq!(asked("Liberation Sans:style=Bold"), (1, true));
        assert_eq!(asked("Liberation Sans:bold"), (1, true));
        assert_eq!(asked("Liberation Serif"), (1, true));
        // A family named first that the sets before lack: the lazy set may have it.
        assert_eq!(asked("Liberation Serif,Liberation Sans"), (1, true));
        let e = lazy.find("Csgpix Nowhere").unwrap_err().to_string();
        assert!(e.contains("not found"), "{e}");
        // The bold face alone is not the regular one asked: the lazy set has a nearer.
        let bold = alone("LiberationSans-Bold.ttf", true);
        let face = bold.find("Liberation Sans").unwrap();
        assert_eq!(
            face,
            fonts()
                .find("Liberation Sans")
                .map(|f| FaceId { layer: 1, ..f })
                .unwrap()
        );
    }

    fn draw(spec: &TextSpec) -> Poly2 {
        render(spec, &fonts(), MAX_SCENE_VERTICES).unwrap()
    }

    fn bounds(p: &Poly2) -> (DVec2, DVec2) {
        p.points().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), q| (lo.min(q), hi.max(q)),
        )
    }

    fn area(p: &Poly2) -> f64 {
        p.paths.iter().map(|c| signed_area(c)).sum::<f64>().abs()
    }

    /// Even-odd: inside when a ray to +x crosses the outlines an odd number of times.
    fn inside(p: &Poly2, q: DVec2) -> bool {
        let mut odd = false;
        for c in &p.paths {
            for i in 0..c.len() {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x)
                {
                    odd = !odd;
                }
            }
        }
        odd
    }

    /// A collection whose header counts 2^31 faces in a 16-byte file adds no face (fontdb
    /// reserved 33 GB for it and aborted, or walked 2^31 indices), from a scene's file or
    /// from bytes; a real collection's count fits.
    #[test]
    fn a_collection_counting_more_faces_than_it_holds_adds_none() {
        let bad = [
            b"ttcf".as_slice(),
            &[0, 1, 0, 0],
            &[0x7f, 0xff, 0xff, 0xff],
            &[0; 4],
        ]
        .concat();
        assert!(!collection_fits(&bad));
        assert!(Fonts::of_data(bad.clone()).families().is_empty());
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("bad.ttc");
        std::fs::write(&file, &bad).unwrap();
        let fonts = Fonts::scene(&[file]);
        assert!(fonts.families().is_empty());
        let two = [b"ttcf".as_slice(), &[0, 1, 0, 0], &[0, 0, 0, 2], &[0; 8]].concat();
        assert!(collection_fits(&two));
        let sans = std::fs::read(magiera()).unwrap();
        assert!(collection_fits(&sans));
        assert_eq!(Fonts::of_data(sans).families().len(), 1);
    }

    #[test]
    fn fonts_are_found_by_fontconfig_names() {
        let f = fonts();
        let regular = f.find("").unwrap();
        assert_eq!(f.find("Liberation Sans").unwrap(), regular);
        assert_eq!(f.find("Liberation Sans:style=Regular").unwrap(), regular);
        let bold = f.find("Liberation Sans:style=Bold").unwrap();
        assert_ne!(bold, regular);
        assert_eq!(f.find("liberation sans:bold").unwrap(), bold);
        assert!(f.find("Liberation Serif").is_ok());
        let e = f.find("Nope Sans").unwrap_err();
        assert!(e.to_string().contains("`Nope Sans` not found"), "{e}");
        let e = f.find("Liberation Serif:style=Bold").unwrap_err();
        assert!(e.to_string().contains("no such style"), "{e}");
        // A fallback list takes the first family present.
        assert_eq!(
            f.find("Nope Sans,Liberation Sans:style=Bold").unwrap(),
            bold
        );
    }

    #[test]
    fn a_missing_font_is_an_error_at_the_node() {
        let text = "linear_extrude(height = 1)\n  text(text = \"a\", font = \"No Such Font:style=Bold\");\n";
        let e = crate::parse_csg_with(text, "t.csg", &strict())
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("t.csg:2:3: "), "{e}");
        assert!(e.to_string().contains("No Such Font"), "{e}");
        let text = "linear_extrude(height = 1) text(text = \"a\", halign = \"middle\");";
        let e = crate::parse_csg(text, "t.csg").unwrap_err().to_string();
        assert!(e.starts_with("t.csg:1:28: ") && e.contains("halign"), "{e}");
        // 400 glyphs of at least 50,000 points each (the scene's guard is 20 million).
        let many = "o".repeat(400);
        let text = format!("linear_extrude(height = 1) text(text = \"{many}\", $fn = 1e9);");
        let text = text.as_str();
        let e = crate::parse_csg(text, "t.csg").unwrap_err().to_string();
        assert!(e.starts_with("t.csg:1:28: ") && e.contains("points"), "{e}");
    }

    /// A font in none of the standard places: the one birthday-heart uses (public domain).
    fn magiera() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../vectors/designs/birthday-heart/Magiera Script.ttf")
    }

    const MAGIERA: &str =
        "linear_extrude(height = 1)\n  text(\"Hi\", font = \"Magiera:style=Script\");\n";

    /// openscad on PATH, or the test is skipped (a failure with `CSGPIX_OPENSCAD=require`).
    fn have_openscad() -> bool {
        let found = std::process::Command::new("openscad")
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success());
        if !found {
            assert_ne!(
                std::env::var("CSGPIX_OPENSCAD").as_deref(),
                Ok("require"),
                "CSGPIX_OPENSCAD=require but openscad is not on PATH"
            );
            eprintln!("openscad is not on PATH: skipped");
        }
        found
    }

    #[test]
    fn a_font_beside_a_csg_file_is_found_for_that_scene_only() {
        let with = tempfile::tempdir().unwrap();
        std::fs::copy(magiera(), with.path().join("Magiera Script.ttf")).unwrap();
        let csg = with.path().join("t.csg");
        std::fs::write(&csg, MAGIERA).unwrap();
        let scene = crate::read_scene(&csg).unwrap();
        assert_eq!(scene.imports.len() + scene.solids.len(), 1);
        // The same scene elsewhere, read after it in this process: the font is not kept.
        let without = tempfile::tempdir().unwrap();
        let csg = without.path().join("t.csg");
        std::fs::write(&csg, MAGIERA).unwrap();
        let e = crate::read_scene_with(&csg, &strict())
            .unwrap_err()
            .to_string();
        let at = format!(
            "{}:2:3: font `Magiera:style=Script` not found",
            csg.display()
        );
        assert!(e.starts_with(&at), "{e}");
        assert!(!e.contains('\n'), "{e}");
        // With a font file beside it that is not the one asked, the message says it looked.
        std::fs::copy(
            bundled_font_dir()
                .unwrap()
                .join("LiberationSerif-Regular.ttf"),
            without.path().join("LiberationSerif-Regular.ttf"),
        )
        .unwrap();
        let e = crate::read_scene_with(&csg, &strict())
            .unwrap_err()
            .to_string();
        assert!(e.starts_with(&at), "{e}");
        assert!(
            e.contains("(searched the scene's font files, CSGPIX_FONT_PATH"),
            "{e}"
        );
        // The standard fonts never see it.
        assert!(Fonts::standard().find("Magiera:style=Script").is_err());
        // Scene fonts come first and the standard ones stay behind them.
        let f = Fonts::scene(&[magiera()]);
        assert_eq!(f.find("Magiera:style=Script").unwrap().layer, 0);
        assert_eq!(f.find("Liberation Sans").unwrap().layer, 1);
        let e = f.find("Magiera:style=Bold").unwrap_err();
        assert!(e.to_string().contains("no such style"), "{e}");
    }

    #[test]
    fn a_font_a_scad_file_uses_is_found() {
        if !have_openscad() {
            return;
        }
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        std::fs::create_dir_all(root.join("fonts")).unwrap();
        std::fs::create_dir_all(root.join("lib")).unwrap();
        std::fs::copy(magiera(), root.join("fonts/Magiera Script.ttf")).unwrap();
        // Directly, relative to the .scad.
        let main = root.join("main.scad");
        std::fs::write(&main, format!("use <fonts/Magiera Script.ttf>\n{MAGIERA}")).unwrap();
        crate::read_scene(&main).unwrap();
        // Through an include, relative to the included file.
        std::fs::write(
            root.join("lib/fonts.scad"),
            "use <../fonts/Magiera Script.ttf>\n",
        )
        .unwrap();
        let inc = root.join("inc.scad");
        std::fs::write(&inc, format!("include <lib/fonts.scad>\n{MAGIERA}")).unwrap();
        crate::read_scene(&inc).unwrap();
        // Not used: OpenSCAD substitutes a font, csgpix too with a warning (or without
        // fontconfig refuses), at the text() call; `strict` refuses.
        let bare = root.join("bare.scad");
        std::fs::write(&bare, MAGIERA).unwrap();
        let e = crate::read_scene_with(&bare, &strict())
            .unwrap_err()
            .to_string();
        let at = format!(
            "{}:2:3: font `Magiera:style=Script` not found",
            bare.display()
        );
        assert!(e.starts_with(&at), "{e}");
    }

    #[test]
    fn alignment_offsets_follow_openscad() {
        let at = |h: &str, v: &str| {
            let mut s = TextSpec::new("HHH", 10.0);
            s.halign = h.into();
            s.valign = v.into();
            bounds(&draw(&s)).0
        };
        let base = at("left", "baseline");
        let (right, center) = (at("right", "baseline"), at("center", "baseline"));
        // The width is the sum of the advances (hmtx: "HHH" has no kerning), scaled by
        // 1/1.024e5 per (unhinted) 26.6 unit where the outlines are scaled by 1/1e5.
        let width = base.x - right.x;
        let f = fonts();
        let expect = f
            .with_face_data(f.find("").unwrap(), |data, index| {
                let face = ttf_parser::Face::parse(data, index).unwrap();
                let h = face.glyph_index('H').unwrap();
                let adv26 = (face.glyph_hor_advance(h).unwrap() as f64
                    * units_26_6_positions(&face))
                .round();
                3.0 * 10.0 * adv26 / UNSCALE
            })
            .unwrap();
        assert!((width - expect).abs() < 1e-9, "{width} {expect}");
        assert!((base.x - center.x - width / 2.0).abs() < 1e-9);
        let (top, bottom, middle) = (
            at("left", "top"),
            at("left", "bottom"),
            at("left", "center"),
        );
        let (asc, desc) = (base.y - top.y, bottom.y - base.y);
        assert!(asc > 9.0 && asc < 11.0, "{asc}");
        assert!(desc.abs() < 1e-9, "{desc}"); // H has no descent
        let g = |v: &str| {
            let mut s = TextSpec::new("g", 10.0);
            s.valign = v.into();
            bounds(&draw(&s)).0.y
        };
        assert!((middle.y - base.y - (desc - asc) / 2.0).abs() < 1e-9);
        let g_desc = g("bottom") - g("baseline");
        assert!(g_desc > 1.5 && g_desc < 3.5, "{g_desc}");
    }

    #[test]
    fn holes_are_holes_and_overlaps_unite() {
        for ch in ["o", "A"] {
            let p = draw(&TextSpec::new(ch, 10.0));
            assert_eq!(p.paths.len(), 2, "{ch}");
            let (lo, hi) = bounds(&p);
            let mid = (lo + hi) / 2.0;
            // 'o': the centre is in the hole; 'A': the hole is above its middle.
            let hole = if ch == "o" {
                mid
            } else {
                DVec2::new(mid.x, lo.y + (hi.y - lo.y) * 0.45)
            };
            assert!(!inside(&p, hole), "{ch}");
            let ink = if ch == "o" {
                DVec2::new(lo.x + 0.3, mid.y)
            } else {
                DVec2::new(mid.x, hi.y - 0.3)
            };
            assert!(inside(&p, ink), "{ch}");
        }
        // Two glyphs drawn over each other (no spacing) are their union (nonzero), not
        // cancelled (even-odd).
        let one = area(&draw(&TextSpec::new("o", 10.0)));
        let mut two = TextSpec::new("oo", 10.0);
        two.spacing = 0.0;
        assert!((area(&draw(&two)) - one).abs() < 1e-6 * one, "{one}");
    }

    #[test]
    fn fn_sets_the_segments_per_curve_as_openscad() {
        // max(floor(f / 8) + 1, 2), f from get_fragments_from_r(size, $fn, $fs, $fa).
        assert_eq!(segments(10.0, 0.0, 12.0, 2.0), 4); // f = 30
        assert_eq!(segments(1.0, 0.0, 12.0, 2.0), 2); // f = 5
        assert_eq!(segments(10.0, 16.0, 12.0, 2.0), 3);
        assert_eq!(segments(10.0, 64.0, 12.0, 2.0), 9);
        assert_eq!(segments(10.0, 3.0, 12.0, 2.0), 2);
        let points = |n: usize| {
            let mut s = TextSpec::new("o", 10.0);
            s.segments = n;
            draw(&s).points().count()
        };
        // 'o' is all quadratic curves: the points grow with the segments per curve.
        let (a, b) = (points(2), points(9));
        assert!(b > 4 * a - 8 && b > a, "{a} {b}");
    }
}
