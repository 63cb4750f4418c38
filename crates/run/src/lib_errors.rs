//! The libraries' errors in the command line's words: where an error says what to change,
//! these name the option that changes it.

use csgpix_draw::Error as DrawError;
use csgpix_sculpt::Error as SculptError;

/// A drawing error; a scene too deep for the word names `--word` and `--size`.
pub fn draw(e: DrawError) -> String {
    match e {
        DrawError::DeeperThanMaxdepth { detail, suggested } => format!(
            "{detail}: use --word {}/{}/{} or a smaller --size",
            suggested.frac, suggested.int, suggested.ovf
        ),
        e => e.to_string(),
    }
}

/// A scene that could not be loaded for drawing: a projection too deep for the word names
/// `--word` and `--size` as [`draw`] does.
pub fn load(e: csgpix_draw::scenes::LoadError) -> String {
    use csgpix_draw::scenes::LoadError;
    match e {
        LoadError::Draw { path, error } => format!("{path}: {}", draw(error)),
        e => e.to_string(),
    }
}

/// A voxel store's or sculpting's error; a store over its budget names `--res` and
/// `--max-memory`, a bad tool `--tool`, a bad stiffness `--stiffness`.
pub fn sculpt(e: SculptError) -> String {
    match e {
        SculptError::OverBudget { .. } => format!("{e}: lower --res or raise --max-memory"),
        SculptError::BadTool { spec, reason } => format!("--tool {spec:?}: {reason}"),
        SculptError::BadStiffness => "--stiffness must be a finite number >= 0".into(),
        e => e.to_string(),
    }
}
