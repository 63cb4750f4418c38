//! The SCENE arguments of `render`: display-list files (§5.2) with an optional `--clip`
//! function, or one OpenSCAD `.csg` file projected onto the array with its tree as the
//! clipping function.

use std::path::{Path, PathBuf};

use csgpix::clip_expr::Clip;
use csgpix::compile::CompileError;
use csgpix::display_list::{field_position, DisplayList};
use csgpix::project::{project, Projected, View};
use csgpix::scad::parse_csg;
use csgpix::solid::CsgScene;
use rtl_model::ArrayConfig;

/// Where a display list came from, so a compile error can point into the file.
enum Origin {
    /// A display-list file and its text.
    List { path: PathBuf, text: String },
    /// A solid of a `.csg` file, made by the node on `line`.
    Solid { path: PathBuf, line: usize },
}

/// Display lists ready to compile, and what to do with them.
pub struct Scene {
    pub lists: Vec<DisplayList>,
    /// The clipping function: `--clip`, or the `.csg` tree (None: compose every list).
    pub clip: Option<Clip>,
    /// True when a `.csg` tree evaluates to nothing: the image is background.
    pub empty: bool,
    /// The `.csg` scene itself (None for display lists), for drawing it on panels.
    pub csg: Option<CsgScene>,
    origins: Vec<Origin>,
}

impl Scene {
    /// Read the SCENE arguments for an array of configuration `cfg`.
    pub fn load(
        paths: &[PathBuf],
        clip: Option<&str>,
        view: View,
        cfg: &ArrayConfig,
    ) -> Result<Scene, String> {
        let is_csg = |p: &PathBuf| {
            p.extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("csg") || e.eq_ignore_ascii_case("scad"))
        };
        match paths.iter().position(is_csg) {
            None => Self::load_lists(paths, clip),
            Some(_) if paths.len() > 1 => {
                Err("a .csg scene must be the only SCENE (its tree combines its solids)".into())
            }
            Some(_) if clip.is_some() => Err(
                "--clip applies to display lists; a .csg scene's tree is its clipping function"
                    .into(),
            ),
            Some(_) => Self::load_csg(&paths[0], view, cfg),
        }
    }

    fn load_lists(paths: &[PathBuf], clip: Option<&str>) -> Result<Scene, String> {
        let (mut lists, mut origins) = (vec![], vec![]);
        for p in paths {
            let text = read(p)?;
            lists.push(
                DisplayList::parse(&text, &p.display().to_string()).map_err(|e| e.to_string())?,
            );
            origins.push(Origin::List {
                path: p.clone(),
                text,
            });
        }
        let clip = match clip {
            None => None,
            Some(text) => {
                let names: Vec<String> = (0..lists.len()).map(object_name).collect();
                let e = Clip::parse(text, &names).map_err(|e| e.in_file("--clip").to_string())?;
                Some(e)
            }
        };
        Ok(Scene {
            lists,
            clip,
            empty: false,
            csg: None,
            origins,
        })
    }

    fn load_csg(path: &Path, view: View, cfg: &ArrayConfig) -> Result<Scene, String> {
        let text = csgpix::scad::scene_text(path)?;
        let scene = parse_csg(&text, &path.display().to_string()).map_err(|e| e.to_string())?;
        scene.require_convex(&path.display().to_string(), "the array")?;
        let (w, h) = (cfg.width, cfg.height);
        let Projected { lists, clip } = project(&scene, view, w, h, &cfg.fmt)
            .map_err(|e| format!("{}: {}", path.display(), super::lib_errors::draw(e)))?;
        let origins = scene
            .solids
            .iter()
            .map(|s| Origin::Solid {
                path: path.to_path_buf(),
                line: s.line,
            })
            .collect();
        Ok(Scene {
            empty: clip.is_none(),
            lists,
            clip,
            csg: Some(scene),
            origins,
        })
    }

    /// A compile error on list `i`, as `file:line:col: message`.
    pub fn locate(&self, i: usize, e: &CompileError) -> String {
        use csgpix::compile::{WHOLE_LIST, WHOLE_PROGRAM};
        match (&self.origins[i], e.field) {
            // Display lists are clipped by --clip: the whole program is its.
            (Origin::List { .. }, WHOLE_PROGRAM) => return format!("--clip: {}", e.msg),
            (
                Origin::List { path, .. } | Origin::Solid { path, .. },
                WHOLE_PROGRAM | WHOLE_LIST,
            ) => return format!("{}: {}", path.display(), e.msg),
            _ => {}
        }
        match &self.origins[i] {
            Origin::List { path, text } => {
                let (line, col) = field_position(text, e.plane, e.field).unwrap_or((1, 1));
                format!("{}:{line}:{col}: {}", path.display(), e.msg)
            }
            Origin::Solid { path, line } => {
                format!(
                    "{}:{line}:1: face {} of this solid: {}",
                    path.display(),
                    e.plane + 1,
                    e.msg
                )
            }
        }
    }
}

fn read(p: &Path) -> Result<String, String> {
    Ok(csgpix::input::read_text(p)?)
}

/// The name `--clip` uses for the `i`-th object: A … Z, then O26, O27, …
pub fn object_name(i: usize) -> String {
    match u8::try_from(i) {
        Ok(n) if n < 26 => ((b'A' + n) as char).to_string(),
        _ => format!("O{i}"),
    }
}
