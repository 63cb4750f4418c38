//! What a render draws: display-list files (§5.2) with an optional clipping function, or one
//! OpenSCAD `.csg` file projected onto the array with its tree as the clipping function
//! (§5.2.1). The `render` and `export-verilog` commands and the Python binding load scenes
//! here, so a compile error points into the file it came from the same way in each.

use std::path::{Path, PathBuf};

use crate::compile::CompileError;
use crate::project::{project, Projected, View};
use csgpix_scene::clip_expr::Clip;
use csgpix_scene::display_list::{field_position, DisplayList};
use csgpix_scene::solid::CsgScene;
use rtl_model::ArrayConfig;

/// Why a scene could not be loaded.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LoadError {
    /// A `.csg` scene was given with other scene files.
    #[error("a .csg scene must be the only SCENE (its tree combines its solids)")]
    CsgNotAlone,
    /// A clipping function was given with a `.csg` scene.
    #[error("--clip applies to display lists; a .csg scene's tree is its clipping function")]
    ClipWithCsg,
    /// A scene file could not be read (its `file:line:col` kept in the error).
    #[error(transparent)]
    Scene(#[from] csgpix_scene::Error),
    /// Projecting the `.csg` scene at `path` failed (a caller may word
    /// [`crate::Error::DeeperThanMaxdepth`] in terms of its own options).
    #[error("{}: {error}", csgpix_scene::OneLine(path))]
    Draw {
        /// The scene file.
        path: String,
        /// What went wrong.
        error: crate::Error,
    },
}

/// Where a display list came from, so a compile error can point into the file.
enum Origin {
    /// A display-list file and its text.
    List { path: PathBuf, text: String },
    /// A solid of a `.csg` file, made by the node on `line`.
    Solid { path: PathBuf, line: usize },
}

/// Display lists ready to compile, and what to do with them.
pub struct Scene {
    /// The objects, one display list each.
    pub lists: Vec<DisplayList>,
    /// The clipping function: the one given, or the `.csg` tree (None: compose every list).
    pub clip: Option<Clip>,
    /// True when a `.csg` tree evaluates to nothing: the image is background.
    pub empty: bool,
    /// The `.csg` scene itself (None for display lists), for drawing it on panels.
    pub csg: Option<CsgScene>,
    origins: Vec<Origin>,
}

impl Scene {
    /// Read the scene files `paths` for an array of configuration `cfg`: display lists
    /// clipped by `clip` (objects named A, B, … in order), or one `.csg`/`.scad` file.
    pub fn load(
        paths: &[PathBuf],
        clip: Option<&str>,
        view: View,
        cfg: &ArrayConfig,
    ) -> Result<Scene, LoadError> {
        let options = csgpix_openscad::ReadOptions::default();
        Self::load_with(paths, clip, view, cfg, &options)
    }

    /// [`Scene::load`] with the `.csg`/`.scad` reader's options (openscad's time limit).
    pub fn load_with(
        paths: &[PathBuf],
        clip: Option<&str>,
        view: View,
        cfg: &ArrayConfig,
        options: &csgpix_openscad::ReadOptions,
    ) -> Result<Scene, LoadError> {
        let is_csg = |p: &PathBuf| {
            p.extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("csg") || e.eq_ignore_ascii_case("scad"))
        };
        match paths.iter().position(is_csg) {
            None => Self::load_lists(paths, clip),
            Some(_) if paths.len() > 1 => Err(LoadError::CsgNotAlone),
            Some(_) if clip.is_some() => Err(LoadError::ClipWithCsg),
            Some(_) => Self::load_csg(&paths[0], view, cfg, options),
        }
    }

    fn load_lists(paths: &[PathBuf], clip: Option<&str>) -> Result<Scene, LoadError> {
        let (mut lists, mut origins) = (vec![], vec![]);
        for p in paths {
            let text = read(p)?;
            lists.push(DisplayList::parse(&text, &p.display().to_string())?);
            origins.push(Origin::List {
                path: p.clone(),
                text,
            });
        }
        let clip = match clip {
            None => None,
            Some(text) => {
                let names: Vec<String> = (0..lists.len()).map(object_name).collect();
                let e = Clip::parse(text, &names).map_err(|e| e.in_file("--clip"))?;
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

    fn load_csg(
        path: &Path,
        view: View,
        cfg: &ArrayConfig,
        options: &csgpix_openscad::ReadOptions,
    ) -> Result<Scene, LoadError> {
        let scene = csgpix_openscad::read_scene_with(path, &options.clone().for_the_array())?;
        scene.require_convex(&path.display().to_string(), "the array")?;
        let (w, h) = (cfg.width, cfg.height);
        let Projected { lists, clip } =
            project(&scene, view, w, h, &cfg.fmt).map_err(|error| LoadError::Draw {
                path: path.display().to_string(),
                error,
            })?;
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
        self.locate_error(i, e).to_string()
    }

    /// A compile error on list `i`, placed in its file: an [`csgpix_scene::Error::At`] where
    /// it has a line there, else a context (`--clip` or the file) before the message.
    pub fn locate_error(&self, i: usize, e: &CompileError) -> csgpix_scene::Error {
        use crate::compile::{WHOLE_LIST, WHOLE_PROGRAM};
        use csgpix_scene::Error;
        let problem = Error::Compile {
            reason: e.msg.clone(),
        };
        match (&self.origins[i], e.field) {
            // Display lists are clipped by --clip: the whole program is its.
            (Origin::List { .. }, WHOLE_PROGRAM) => return problem.context("--clip"),
            (
                Origin::List { path, .. } | Origin::Solid { path, .. },
                WHOLE_PROGRAM | WHOLE_LIST,
            ) => return problem.context(path.display()),
            _ => {}
        }
        match &self.origins[i] {
            Origin::List { path, text } => {
                let (line, col) = field_position(text, e.plane, e.field).unwrap_or((1, 1));
                problem.located(path.display().to_string(), line, col)
            }
            Origin::Solid { path, line } => problem
                .context(format_args!("face {} of this solid", e.plane + 1))
                .located(path.display().to_string(), *line, 1),
        }
    }
}

fn read(p: &Path) -> Result<String, LoadError> {
    Ok(csgpix_scene::input::read_text(p)?)
}

/// The name `--clip` uses for the `i`-th object: A … Z, then O26, O27, …
pub fn object_name(i: usize) -> String {
    match u8::try_from(i) {
        Ok(n) if n < 26 => ((b'A' + n) as char).to_string(),
        _ => format!("O{i}"),
    }
}
