//! Font folders scanned for their faces' names and styles, reading of each file only what
//! fontdb parses.
//!
//! A `text()` whose font is not bundled makes csgpix look through the system's fonts
//! ([`crate::text::Fonts`]): about 110 files on the measuring machine. fontdb's own scan
//! maps each file, parses its table directory and its `name`, `OS/2` and `post` tables,
//! and unmaps it; the mapping, its page faults and the unmapping cost more than the
//! parsing (3.6 ms for the scan in all, more than a fifth of a small text design's run).
//!
//! Here a single font is read in small pieces: its table directory, then the tables fontdb
//! parses and those [`style_names`] needs (`name`, `OS/2`, `post`; `head`, `hhea` and `maxp`,
//! which a face must have to parse). They are laid after the directory in one buffer, each
//! record of theirs moved to its copy, and fontdb parses that buffer. fontdb reads nothing
//! else of a face ([`fontdb`] 0.24, `parse_face_info`), so it finds the faces it finds in the
//! whole file; each is then named by the file, as fontdb's scan names it. The face's style
//! names are read from the same buffer, so that a lookup by style (`Inter:style=Bold`) need
//! not open and parse each face of the family again. A collection (`ttcf`), rare among
//! system fonts, is left to fontdb whole. The files are read in parallel, and their faces
//! added in the order of fontdb's own walk of the folders.

use std::collections::{HashMap, HashSet};
use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::path::{Path, PathBuf};

use fontdb::{Database, FaceInfo, Source, ID};
use rayon::prelude::*;
use ttf_parser::Tag;

/// The tables of a face that fontdb and [`style_names`] read.
const READ: [Tag; 6] = [
    Tag::from_bytes(b"name"),
    Tag::from_bytes(b"OS/2"),
    Tag::from_bytes(b"post"),
    Tag::from_bytes(b"head"),
    Tag::from_bytes(b"hhea"),
    Tag::from_bytes(b"maxp"),
];

/// A table directory's header: the magic, the table count and three fields fontdb skips.
const HEADER: usize = 12;
/// One table record: tag, checksum, offset, length.
const RECORD: usize = 16;

/// The style names of the faces a scan read, by their ID in its database (a face of a
/// collection is not among them).
pub(crate) type Styles = HashMap<ID, Vec<String>>;

/// A face's style names (typographic subfamily and subfamily, every language), from its
/// font data; none when the face does not parse.
pub(crate) fn style_names(data: &[u8], index: u32) -> Vec<String> {
    let Ok(face) = ttf_parser::Face::parse(data, index) else {
        return vec![];
    };
    face.names()
        .into_iter()
        .filter(|n| {
            n.name_id == ttf_parser::name_id::SUBFAMILY
                || n.name_id == ttf_parser::name_id::TYPOGRAPHIC_SUBFAMILY
        })
        .filter_map(|n| n.to_string())
        .collect()
}

/// The faces of the font files under `dir`, as `Database::load_fonts_dir` adds them.
pub(crate) fn load_dir(db: &mut Database, styles: &mut Styles, dir: &Path) {
    let mut files = vec![];
    walk(dir, &mut HashSet::new(), &mut files);
    push_faces(db, styles, &files);
}

/// The system's fonts, as `Database::load_system_fonts` adds them.
pub(crate) fn load_system(db: &mut Database, styles: &mut Styles) {
    #[cfg(all(
        unix,
        not(any(target_os = "macos", target_os = "ios", target_os = "android"))
    ))]
    {
        // fontdb's folders without fontconfig (`load_no_fontconfig`), one `seen` for all.
        let mut dirs = vec![
            PathBuf::from("/usr/share/fonts/"),
            PathBuf::from("/usr/local/share/fonts/"),
        ];
        if let Ok(home) = std::env::var("HOME") {
            let home = Path::new(&home);
            dirs.extend([home.join(".fonts"), home.join(".local/share/fonts")]);
        }
        let (mut seen, mut files) = (HashSet::new(), vec![]);
        for d in &dirs {
            walk(d, &mut seen, &mut files);
        }
        push_faces(db, styles, &files);
    }
    #[cfg(not(all(
        unix,
        not(any(target_os = "macos", target_os = "ios", target_os = "android"))
    )))]
    {
        let _ = styles;
        db.load_system_fonts();
    }
}

/// The faces of `files`, read in parallel, added in order.
fn push_faces(db: &mut Database, styles: &mut Styles, files: &[PathBuf]) {
    let faces: Vec<Vec<Face>> = files.par_iter().map(|f| faces_of(f)).collect();
    for face in faces.into_iter().flatten() {
        let id = db.push_face_info(face.info);
        if let Some(names) = face.styles {
            styles.insert(id, names);
        }
    }
}

/// A face a file holds, and its style names when they were read with it.
struct Face {
    info: FaceInfo,
    styles: Option<Vec<String>>,
}

/// The font files under `dir` in the order fontdb's `load_fonts_dir_impl` loads them:
/// entries in the order the folder lists them, folders entered where they come, a linked
/// entry followed to its canonical path once. (fontdb also seeds `seen` with the faces
/// loaded so far where a linked entry's own type is a folder; an entry's own type is never
/// a folder when it is a link, so that never happens.)
fn walk(dir: &Path, seen: &mut HashSet<PathBuf>, files: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let Some((path, kind)) = followed(entry, seen) else {
            continue;
        };
        if kind.is_file() {
            let font = path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
                matches!(
                    e,
                    "ttf" | "ttc" | "TTF" | "TTC" | "otf" | "otc" | "OTF" | "OTC"
                )
            });
            if font {
                files.push(path);
            }
        } else if kind.is_dir() {
            walk(&path, seen, files);
        }
    }
}

/// An entry's path and type (fontdb's `canonicalize`): a link's target by its canonical
/// path, skipped when seen before; another entry as it is, skipped when seen before once
/// `seen` holds anything.
fn followed(
    entry: std::fs::DirEntry,
    seen: &mut HashSet<PathBuf>,
) -> Option<(PathBuf, std::fs::FileType)> {
    let path = entry.path();
    let kind = entry.file_type().ok()?;
    if !kind.is_symlink() {
        if !seen.is_empty() && !seen.insert(path.clone()) {
            return None;
        }
        return Some((path, kind));
    }
    let stat = std::fs::metadata(&path).ok()?;
    let canon = std::fs::canonicalize(path).ok()?;
    seen.insert(canon.clone())
        .then_some((canon, stat.file_type()))
}

/// The faces fontdb finds in the font file `path`, named by it.
fn faces_of(path: &Path) -> Vec<Face> {
    let mut db = Database::new();
    let read = match read_tables(path) {
        Ok(Some(data)) => {
            db.load_font_data(data);
            true
        }
        Ok(None) => {
            let _ = db.load_font_file(path);
            false
        }
        Err(_) => return vec![],
    };
    db.faces()
        .map(|f| Face {
            styles: read.then(|| db.with_face_data(f.id, style_names)).flatten(),
            info: FaceInfo {
                source: Source::File(path.to_path_buf()),
                ..f.clone()
            },
        })
        .collect()
}

/// Of a single font, its table directory followed by the [`READ`] tables, each record of
/// theirs moved to its copy; a table that does not lie within the file is moved where it
/// cannot be read, as it cannot in the file. None for a collection (or a file too large for
/// a table's new offset), which is read whole.
fn read_tables(path: &Path) -> std::io::Result<Option<Vec<u8>>> {
    let mut file = File::open(path)?;
    let len = file.metadata()?.len();
    let mut buf = read_at(&mut file, 0, HEADER as u64, len)?;
    if buf.starts_with(b"ttcf") {
        return Ok(None);
    }
    if buf.len() < HEADER {
        return Ok(Some(buf));
    }
    let tables = u16::from_be_bytes([buf[4], buf[5]]) as u64;
    buf.extend(read_at(
        &mut file,
        HEADER as u64,
        tables * RECORD as u64,
        len,
    )?);
    let read: Vec<(usize, u64, u64)> = match ttf_parser::RawFace::parse(&buf, 0) {
        Ok(raw) => (raw.table_records.into_iter().enumerate())
            .filter(|(_, r)| READ.contains(&r.tag))
            .map(|(i, r)| (i, u64::from(r.offset), u64::from(r.length)))
            .collect(),
        // fontdb finds no face in the file either: it parses the same directory.
        Err(_) => return Ok(Some(buf)),
    };
    for (i, offset, length) in read {
        let at = HEADER + RECORD * i + 8;
        let moved = if offset + length <= len {
            let Ok(moved) = u32::try_from(buf.len()) else {
                return Ok(None);
            };
            buf.extend(read_at(&mut file, offset, length, len)?);
            moved
        } else {
            u32::MAX
        };
        buf[at..at + 4].copy_from_slice(&moved.to_be_bytes());
    }
    Ok(Some(buf))
}

/// Up to `n` bytes of the file from `offset`, as many as it holds there (it is `len` long).
fn read_at(file: &mut File, offset: u64, n: u64, len: u64) -> std::io::Result<Vec<u8>> {
    let n = n.min(len.saturating_sub(offset));
    let mut out = Vec::with_capacity(n as usize);
    file.seek(SeekFrom::Start(offset))?;
    file.take(n).read_to_end(&mut out)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// What a scan found, face by face in order, every field but the ID, and the face's
    /// style names: those read with the scan (`styles`), else read from the whole file.
    fn found(db: &Database, styles: &Styles) -> Vec<String> {
        db.faces()
            .map(|f| {
                let FaceInfo {
                    id,
                    source,
                    index,
                    families,
                    post_script_name,
                    style,
                    weight,
                    stretch,
                    monospaced,
                } = f;
                let file = match source {
                    Source::File(p) => p.display().to_string(),
                    _ => "not a file".to_string(),
                };
                let names =
                    (styles.get(id).cloned()).or_else(|| db.with_face_data(*id, style_names));
                format!(
                    "{file} {index} {families:?} {post_script_name} {style:?} {weight:?} \
                     {stretch:?} {monospaced} {names:?}"
                )
            })
            .collect()
    }

    fn scanned(dir: &Path) -> Vec<String> {
        let (mut db, mut styles) = (Database::new(), Styles::new());
        load_dir(&mut db, &mut styles, dir);
        found(&db, &styles)
    }

    fn fontdb_scanned(dir: &Path) -> Vec<String> {
        let mut db = Database::new();
        db.load_fonts_dir(dir);
        found(&db, &Styles::new())
    }

    fn bundled() -> PathBuf {
        crate::text::bundled_font_dir().expect("vectors/fonts")
    }

    #[test]
    fn the_bundled_and_the_system_fonts_are_those_fontdb_finds() {
        let faces = scanned(&bundled());
        assert_eq!(faces.len(), 3, "{faces:#?}");
        let (mut db, mut styles) = (Database::new(), Styles::new());
        load_dir(&mut db, &mut styles, &bundled());
        let bold = db
            .faces()
            .find(|f| f.post_script_name == "LiberationSans-Bold");
        assert_eq!(styles[&bold.unwrap().id], ["Bold"], "read with the scan");
        assert_eq!(faces, fontdb_scanned(&bundled()));
        let (mut ours, mut styles, mut theirs) = (Database::new(), Styles::new(), Database::new());
        load_system(&mut ours, &mut styles);
        theirs.load_system_fonts();
        assert_eq!(found(&ours, &styles), found(&theirs, &Styles::new()));
    }

    #[test]
    fn a_linked_folder_and_file_are_followed_once() {
        let dir = tempfile::tempdir().unwrap();
        let fonts = dir.path().join("fonts");
        std::fs::create_dir(&fonts).unwrap();
        for f in ["LiberationSans-Bold.ttf", "LiberationSerif-Regular.ttf"] {
            std::fs::copy(bundled().join(f), fonts.join(f)).unwrap();
        }
        #[cfg(unix)]
        {
            use std::os::unix::fs::symlink;
            symlink(&fonts, dir.path().join("again")).unwrap();
            symlink(
                fonts.join("LiberationSans-Bold.ttf"),
                dir.path().join("bold.TTF"),
            )
            .unwrap();
        }
        let faces = scanned(dir.path());
        assert!(faces.len() >= 2, "{faces:#?}");
        assert_eq!(faces, fontdb_scanned(dir.path()));
    }

    /// A font file damaged in one of the ways `damage` picks.
    #[derive(Clone, Debug)]
    enum Damage {
        /// Cut at this fraction of its length.
        Cut(f64),
        /// A byte of the directory (header and records) set.
        Directory(usize, u8),
        /// A read table's record pointed at this offset (a fraction of the file's length,
        /// past its end above 1), with this length.
        Moved(usize, f64, u32),
        /// A byte of a read table set.
        InTable(usize, usize, u8),
        /// A record's tag made that of a read table (which it then has twice).
        Tagged(usize, usize),
        /// Made to read as a collection.
        Collection,
    }

    fn damage() -> impl Strategy<Value = Damage> {
        prop_oneof![
            (0.0..1.0f64).prop_map(Damage::Cut),
            (0..12 + 16 * 20usize, any::<u8>()).prop_map(|(i, b)| Damage::Directory(i, b)),
            (
                0..3usize,
                0.0..1.2f64,
                prop_oneof![Just(0u32), 0..4096u32, Just(u32::MAX)]
            )
                .prop_map(|(t, at, n)| Damage::Moved(t, at, n)),
            (0..6usize, 0..64usize, any::<u8>()).prop_map(|(t, i, b)| Damage::InTable(t, i, b)),
            (0..20usize, 0..6usize).prop_map(|(r, t)| Damage::Tagged(r, t)),
            Just(Damage::Collection),
        ]
    }

    /// Where the record of read table `t` lies in `font`'s directory, if it has one.
    fn record_of(font: &[u8], t: usize) -> Option<usize> {
        let raw = ttf_parser::RawFace::parse(font, 0).ok()?;
        let (i, _) = (raw.table_records).binary_search_by(|r| r.tag.cmp(&READ[t]))?;
        Some(HEADER + RECORD * i as usize)
    }

    fn damaged(mut font: Vec<u8>, damage: &[Damage]) -> Vec<u8> {
        for d in damage {
            match *d {
                Damage::Cut(f) => font.truncate((f * font.len() as f64) as usize),
                Damage::Directory(i, b) => {
                    if let Some(x) = font.get_mut(i) {
                        *x = b;
                    }
                }
                Damage::Moved(t, at, n) => {
                    if let Some(r) = record_of(&font, t) {
                        let offset = (at * font.len() as f64) as u32;
                        font[r + 8..r + 12].copy_from_slice(&offset.to_be_bytes());
                        font[r + 12..r + 16].copy_from_slice(&n.to_be_bytes());
                    }
                }
                Damage::InTable(t, i, b) => {
                    if let Some(r) = record_of(&font, t) {
                        let start = u32::from_be_bytes(font[r + 8..r + 12].try_into().unwrap());
                        if let Some(x) = font.get_mut(start as usize + i) {
                            *x = b;
                        }
                    }
                }
                Damage::Tagged(r, t) => {
                    let at = HEADER + RECORD * r;
                    if let Some(x) = font.get_mut(at..at + 4) {
                        x.copy_from_slice(&READ[t].to_bytes());
                    }
                }
                Damage::Collection => {
                    if let Some(x) = font.get_mut(..4) {
                        x.copy_from_slice(b"ttcf");
                    }
                }
            }
        }
        font
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]
        /// A damaged font gives the faces it gives fontdb read whole: none, or the same.
        #[test]
        fn a_damaged_font_gives_what_fontdb_finds_in_it(
            which in 0..3usize,
            damage in proptest::collection::vec(damage(), 1..4),
        ) {
            let file = ["LiberationSans-Regular.ttf", "LiberationSans-Bold.ttf",
                "LiberationSerif-Regular.ttf"][which];
            let font = std::fs::read(bundled().join(file)).unwrap();
            let dir = tempfile::tempdir().unwrap();
            std::fs::write(dir.path().join("damaged.ttf"), damaged(font, &damage)).unwrap();
            prop_assert_eq!(scanned(dir.path()), fontdb_scanned(dir.path()));
        }
    }
}
