//! `.scad` files through `openscad`.

use std::path::{Path, PathBuf};

use csgpix_scene::solid::CsgScene;
use csgpix_scene::Error;

use crate::subprocess::Ran;

/// The `.csg` text of a scene file: a `.csg` file as it is; a `.scad` file exported to CSG by
/// OpenSCAD (`openscad -o scene.csg FILE.scad` into a temporary directory, removed after),
/// when `openscad` is on PATH, within [`crate::DEFAULT_OPENSCAD_TIMEOUT`]. Errors are one
/// line naming the file.
pub fn scene_text(path: &std::path::Path) -> csgpix_scene::Result<String> {
    scene_text_with(path, Some(crate::DEFAULT_OPENSCAD_TIMEOUT))
}

/// [`scene_text`] with openscad's time limit (None: none): past it openscad is killed and
/// the error is [`Error::TimedOut`].
pub fn scene_text_with(
    path: &std::path::Path,
    timeout: Option<std::time::Duration>,
) -> csgpix_scene::Result<String> {
    let name = path.display();
    let scad = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("scad"));
    if !scad {
        return csgpix_scene::input::read_text(path);
    }
    if !path.is_file() {
        let missing = csgpix_scene::IoError {
            kind: std::io::ErrorKind::NotFound,
            message: "no such file".into(),
        };
        return Err(Error::Io(missing).context(path.display()));
    }
    let dir = tempfile::tempdir()
        .map_err(|e| Error::io("a temporary directory", &e).context(path.display()))?;
    let _scratch = csgpix_output::scratch(dir.path());
    let out = dir.path().join("scene.csg");
    // `$preview = false`: the tree OpenSCAD renders (F6, STL export), not its preview (a CSG
    // export evaluates `$preview` as true): the voxels are the parts a design prints.
    let mut cmd = std::process::Command::new("openscad");
    cmd.args(["-D", "$preview=false"])
        .arg("-o")
        .arg(&out)
        .arg(path);
    let run = crate::subprocess::run(&mut cmd, timeout);
    let (status, stderr) = match run {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(Error::NoOpenscad { scad: true }.context(name))
        }
        Err(e) => return Err(Error::io("running openscad", &e).context(path.display())),
        Ok(Ran::TimedOut) => return Err(timed_out(timeout).context(path.display())),
        Ok(Ran::Done { status, stderr }) => (status, stderr),
    };
    let text = std::fs::read_to_string(&out)
        .ok()
        .filter(|_| status.success());
    text.ok_or_else(|| {
        let line = stderr
            .lines()
            .find(|l| l.contains("ERROR"))
            .or_else(|| stderr.lines().rfind(|l| !l.trim().is_empty()))
            .unwrap_or("no output");
        Error::OpenscadFailed {
            action: "export",
            why: line.trim().to_string(),
        }
        .context(name)
    })
}

/// openscad killed at its time limit.
pub(crate) fn timed_out(limit: Option<std::time::Duration>) -> Error {
    Error::TimedOut {
        program: "openscad".into(),
        limit: limit.unwrap_or_default(),
    }
}

/// A scene file read whole: a `.csg` file parsed as it is; a `.scad` file exported by
/// openscad ([`scene_text`]) and parsed, its errors and warnings placed in the `.scad`
/// ([`in_scad`]). The loader every command and the Python package use.
pub fn read_scene(path: &Path) -> csgpix_scene::Result<CsgScene> {
    read_scene_with(path, &crate::ReadOptions::default())
}

/// [`read_scene`] with [`crate::ReadOptions`].
pub fn read_scene_with(
    path: &Path,
    options: &crate::ReadOptions,
) -> csgpix_scene::Result<CsgScene> {
    let text = scene_text_with(path, options.openscad_timeout)?;
    let name = path.display().to_string();
    let mut options = options.clone();
    if options.dir.is_none() {
        options.dir = path.parent().map(Path::to_path_buf);
    }
    options.fonts.extend(match is_scad(path) {
        true => used_fonts(path),
        false => fonts_beside(path),
    });
    let parsed = crate::parse_csg_with(&text, &name, &options);
    let mut scene = match is_scad(path) {
        false => parsed?,
        true => parsed.map_err(|e| in_scad(e, &text, path))?,
    };
    if is_scad(path) {
        for w in &mut scene.warnings {
            *w = in_scad(std::mem::replace(w, Error::NeedsBounds), &text, path);
        }
    }
    Ok(scene)
}

/// The font files a `.scad` file and the files it includes or uses name in `use <x.ttf>` or
/// `use <x.otf>`, which OpenSCAD registers with fontconfig (`FileModule::registerUse`), in the
/// order met; each found as OpenSCAD looks for a used file ([`resolve`]). A name not found is
/// left out: a `text()` asking for its font is then an error naming the font.
fn used_fonts(scad: &Path) -> Vec<PathBuf> {
    let mut fonts = vec![];
    let mut seen = vec![];
    walk_fonts(scad, &mut fonts, &mut seen);
    fonts
}

fn walk_fonts(path: &Path, fonts: &mut Vec<PathBuf>, seen: &mut Vec<PathBuf>) {
    if seen.len() >= 256 || seen.iter().any(|p| p == path) {
        return;
    }
    seen.push(path.to_path_buf());
    let Ok(text) = std::fs::read_to_string(path) else {
        return;
    };
    let dir = path.parent().unwrap_or(Path::new("."));
    let found = scan(&text, "");
    for name in found.fonts {
        if let Some(f) = resolve(dir, &name).filter(|f| !fonts.contains(f)) {
            fonts.push(f);
        }
    }
    for name in found.includes {
        if let Some(f) = resolve(dir, &name) {
            walk_fonts(&f, fonts, seen);
        }
    }
}

/// A file named in `include <…>` or `use <…>` as OpenSCAD 2021.01 finds it
/// (`find_valid_path`): relative to the naming file's directory, then to each directory of
/// `OPENSCADPATH`.
fn resolve(dir: &Path, name: &str) -> Option<PathBuf> {
    let name = Path::new(name.trim());
    let here = dir.join(name);
    if here.is_file() {
        return Some(here);
    }
    let path = std::env::var_os("OPENSCADPATH")?;
    std::env::split_paths(&path)
        .filter(|d| !d.as_os_str().is_empty())
        .map(|d| d.join(name))
        .find(|p| p.is_file())
}

/// The `*.ttf` and `*.otf` files beside a `.csg` file, by name: csgpix's stand-in for the
/// `use <x.ttf>` lines the CSG export drops (OpenSCAD writes no `use` into it).
fn fonts_beside(csg: &Path) -> Vec<PathBuf> {
    let dir = match csg.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let Ok(entries) = std::fs::read_dir(dir) else {
        return vec![];
    };
    let mut fonts: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| is_font_file(p) && p.is_file())
        .collect();
    fonts.sort();
    fonts
}

/// A name ending in `.ttf` or `.otf` (any case), as OpenSCAD tells a used font from a
/// used library.
fn is_font_file(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("ttf") || e.eq_ignore_ascii_case("otf"))
}

fn is_scad(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("scad"))
}

/// An error located in the CSG that openscad exported from `scad`, placed where the user
/// wrote it. The export keeps no positions, so the node is found by name: the statement at
/// the error's line of the export names a node (`minkowski`, `polyhedron`, …); when the
/// `.scad` file and the files it includes call that node at exactly one place, the error is
/// put there. Otherwise no line of the `.scad` is claimed: the message says it is in the CSG
/// openscad exported, at which line and node.
pub fn in_scad(e: Error, export: &str, scad: &Path) -> Error {
    let Some(at) = e.location().cloned() else {
        return e;
    };
    let file = scad.display().to_string();
    let line = export.lines().nth(at.line.saturating_sub(1)).unwrap_or("");
    let Some(node) = statement_node(line) else {
        return unplaced(e, &file, at.line, None);
    };
    let mut sites = vec![];
    call_sites(scad, &node, &mut sites, 0);
    match sites.as_slice() {
        [(path, l, c)] => e.problem().clone().located(path.clone(), *l, *c),
        _ => unplaced(e, &file, at.line, Some(&node)),
    }
}

fn unplaced(e: Error, file: &str, line: usize, node: Option<&str>) -> Error {
    let what = match node {
        Some(n) => format!("line {line}, `{n}(…)`"),
        None => format!("line {line}"),
    };
    let problem = e.problem().clone();
    problem
        .context(format!("in the CSG openscad exported from it ({what})"))
        .context(file)
}

/// The node a line of openscad's export opens: its first name after the modifiers.
fn statement_node(line: &str) -> Option<String> {
    let s = line
        .trim_start()
        .trim_start_matches(['%', '#', '*', '!', ' ']);
    let name: String = s
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect();
    (!name.is_empty() && s[name.len()..].trim_start().starts_with('(')).then_some(name)
}

/// Where `node(` is called in `path` and, through `include <…>` and `use <…>` with paths
/// relative to it, the files it reads (comments and strings skipped, `module node(` and
/// `function node(` left out); a file that cannot be read adds a site no one can match, so
/// the error is not placed.
fn call_sites(path: &Path, node: &str, out: &mut Vec<(String, usize, usize)>, depth: usize) {
    let Ok(text) = std::fs::read_to_string(path) else {
        out.extend([(String::new(), 0, 0), (String::new(), 0, 0)]);
        return;
    };
    let dir = path.parent().unwrap_or(Path::new("."));
    let Scanned {
        calls, includes, ..
    } = scan(&text, node);
    let file = path.display().to_string();
    out.extend(calls.into_iter().map(|(l, c)| (file.clone(), l, c)));
    for inc in includes {
        if depth < 16 {
            call_sites(&dir.join(inc), node, out, depth + 1);
        }
    }
}

/// What [`scan`] finds in a `.scad` text.
struct Scanned {
    /// The calls of the node (line and column, 1-based, in characters).
    calls: Vec<(usize, usize)>,
    /// The files it includes or uses, fonts left out.
    includes: Vec<String>,
    /// The font files it uses (`use <x.ttf>`, `use <x.otf>`).
    fonts: Vec<String>,
}

/// The calls of `node` in a `.scad` text, the files it includes or uses and the fonts it
/// uses.
fn scan(text: &str, node: &str) -> Scanned {
    let chars: Vec<char> = text.chars().collect();
    let (mut calls, mut includes, mut fonts) = (vec![], vec![], vec![]);
    let mut at = Cursor {
        chars: &chars,
        i: 0,
        line: 1,
        col: 1,
    };
    let mut prev_word = String::new();
    while at.i < chars.len() {
        let c = chars[at.i];
        let next = chars.get(at.i + 1).copied();
        if c == '/' && next == Some('/') {
            at.skip_line_comment();
        } else if c == '/' && next == Some('*') {
            at.skip_block_comment();
        } else if c == '"' {
            at.skip_string();
        } else if c == '<' && matches!(prev_word.as_str(), "include" | "use") {
            let name = at.file_name();
            if prev_word == "use" && is_font_file(Path::new(name.trim())) {
                fonts.push(name);
            } else {
                includes.push(name);
            }
            prev_word.clear();
        } else if c.is_ascii_alphabetic() || c == '_' || c == '$' {
            let (l0, c0) = (at.line, at.col);
            let word = at.word();
            let defined = matches!(prev_word.as_str(), "module" | "function");
            if !node.is_empty() && word == node && at.called() && !defined {
                calls.push((l0, c0));
            }
            prev_word = word;
        } else {
            if !c.is_whitespace() {
                prev_word.clear();
            }
            at.step();
        }
    }
    Scanned {
        calls,
        includes,
        fonts,
    }
}

/// A place in a `.scad` text: its index among the characters, and its line and column.
struct Cursor<'a> {
    chars: &'a [char],
    i: usize,
    line: usize,
    col: usize,
}

impl Cursor<'_> {
    /// One character on.
    fn step(&mut self) {
        if self.chars[self.i] == '\n' {
            self.line += 1;
            self.col = 1;
        } else {
            self.col += 1;
        }
        self.i += 1;
    }

    /// Past a `//` comment, to its line's end.
    fn skip_line_comment(&mut self) {
        while self.i < self.chars.len() && self.chars[self.i] != '\n' {
            self.step();
        }
    }

    /// Past a `/* … */` comment (to the text's end when it is not closed).
    fn skip_block_comment(&mut self) {
        let chars = self.chars;
        self.step();
        self.step();
        while self.i < chars.len() && !(chars[self.i] == '*' && chars.get(self.i + 1) == Some(&'/'))
        {
            self.step();
        }
        for _ in 0..2.min(chars.len() - self.i) {
            self.step();
        }
    }

    /// Past a string literal, its escapes included.
    fn skip_string(&mut self) {
        let chars = self.chars;
        self.step();
        while self.i < chars.len() && chars[self.i] != '"' {
            if chars[self.i] == '\\' && self.i + 1 < chars.len() {
                self.step();
            }
            self.step();
        }
        if self.i < chars.len() {
            self.step();
        }
    }

    /// The file name of `include <…>` or `use <…>`, the cursor at the `<`: up to the `>`
    /// (or the line's end), where the cursor stops.
    fn file_name(&mut self) -> String {
        let start = self.i + 1;
        while self.i < self.chars.len() && self.chars[self.i] != '>' && self.chars[self.i] != '\n' {
            self.step();
        }
        self.chars[start..self.i].iter().collect()
    }

    /// The identifier starting at the cursor, which moves past it.
    fn word(&mut self) -> String {
        let start = self.i;
        self.step();
        while self.i < self.chars.len()
            && (self.chars[self.i].is_ascii_alphanumeric() || self.chars[self.i] == '_')
        {
            self.step();
        }
        self.chars[start..self.i].iter().collect()
    }

    /// Whether the next character but white space is `(` (a call).
    fn called(&self) -> bool {
        let mut j = self.i;
        while j < self.chars.len() && self.chars[j].is_whitespace() {
            j += 1;
        }
        self.chars.get(j) == Some(&'(')
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn calls_are_found_outside_comments_strings_and_definitions() {
        let text =
            "// minkowski(\n/* minkowski() */ x = \"minkowski()\";\nmodule minkowski(a) {}\n  \
                    translate([1, 0, 0]) minkowski () { cube(1); }\ninclude <lib/a.scad>\n";
        let found = scan(text, "minkowski");
        assert_eq!(
            scan("sphere($fn = 8, r = 1);", "sphere").calls,
            vec![(1, 1)]
        );
        assert_eq!(found.calls, vec![(4, 24)]);
        assert_eq!(found.includes, vec!["lib/a.scad".to_string()]);
        assert!(found.fonts.is_empty());
        assert_eq!(scan(text, "cube").calls, vec![(4, 39)]);
        let fonts = scan(
            "use <A b.TTF>\nuse <lib.scad>\n// use <c.otf>\nuse<d.otf>",
            "",
        );
        assert_eq!(
            fonts.fonts,
            vec!["A b.TTF".to_string(), "d.otf".to_string()]
        );
        assert_eq!(fonts.includes, vec!["lib.scad".to_string()]);
    }

    #[test]
    fn an_error_is_placed_at_the_one_call_or_said_to_be_in_the_export() {
        let dir = tempfile::tempdir().unwrap();
        let scad = dir.path().join("p.scad");
        std::fs::write(
            &scad,
            "a = 1;\n\n\nmodule m() {\n  surface(\"x.dat\");\n}\nm(); cube(1); cube(2);\n",
        )
        .unwrap();
        let export = "group() {\n\tsurface(file = \"x.dat\");\n\tcube(size = [1, 1, 1]);\n}\n";
        let e = Error::at("p.scad", 2, 2, Error::HullTooFewPoints);
        let placed = in_scad(e, export, &scad);
        let at = placed.location().cloned().expect("placed");
        assert_eq!((at.line, at.col), (5, 3), "{placed}");
        assert!(at.file.ends_with("p.scad"));
        // cube is called twice: no line of the .scad is claimed.
        let e = Error::at("p.scad", 3, 2, Error::MixedXSign);
        let unplaced = in_scad(e, export, &scad);
        assert!(unplaced.location().is_none());
        let text = unplaced.to_string();
        assert!(
            text.contains(
                "in the CSG openscad exported from it (line 3, `cube(…)`): all points for \
                 rotate_extrude() must have the same X coordinate sign"
            ),
            "{text}"
        );
    }
}
