//! The libraries' errors in the command line's words: where an error says what to change,
//! these name the option that changes it.

use csgpix_draw::Error as DrawError;
use csgpix_sculpt::Error as SculptError;

use crate::Error;
use csgpix_voxel::{BindingProblem, Error as VoxelError};

/// A drawing error; a scene too deep for the word names `--word` and `--size`.
pub fn draw(e: DrawError) -> Error {
    match e {
        DrawError::DeeperThanMaxdepth { detail, suggested } => Error::options(
            "--word",
            format!(
                "{detail}: use --word {}/{}/{} or a smaller --size",
                suggested.frac, suggested.int, suggested.ovf
            ),
        ),
        e => e.into(),
    }
}

/// A scene that could not be loaded for drawing: a projection too deep for the word names
/// `--word` and `--size` as [`draw`] does.
pub fn load(e: csgpix_draw::scenes::LoadError) -> Error {
    use csgpix_draw::scenes::LoadError;
    match e {
        LoadError::Draw { path, error } => draw(error).context(path),
        e => e.into(),
    }
}

/// A voxel store's or sculpting's error; a store over its budget names `--res` and
/// `--max-memory`, a bad tool `--tool`, a bad stiffness `--stiffness`.
pub fn sculpt(e: SculptError) -> Error {
    match e {
        SculptError::OverBudget { .. } => {
            Error::options("--res", format!("{e}: lower --res or raise --max-memory"))
        }
        SculptError::BadTool { spec, reason } => {
            Error::options("--tool", format!("--tool {spec:?}: {reason}"))
        }
        SculptError::BadStiffness => {
            Error::options("--stiffness", "--stiffness must be a finite number >= 0")
        }
        e => e.into(),
    }
}

/// A voxelizer error (loading, grid) in the command line's words: the option that fixes it
/// named (`--bounds`, `--expr`, `--prim`).
pub fn voxel(e: VoxelError) -> Error {
    match e {
        VoxelError::NeedsBounds => Error::options("--bounds", format!("{e}: give --bounds")),
        VoxelError::Expr(m) => Error::options("--expr", format!("--expr:{m}")),
        VoxelError::Unbound { name, col } => Error::options(
            "--expr",
            format!("--expr:1:{col}: primitive `{name}` needs a file: --prim {name}=FILE"),
        ),
        VoxelError::Binding {
            name,
            problem: BindingProblem::NotInExpression,
        } => Error::options(
            "--prim",
            format!("--prim {name}: the expression has no primitive `{name}`"),
        ),
        VoxelError::Binding { name, problem } => {
            Error::options("--prim", format!("--prim {name}: {problem}"))
        }
        e => e.into(),
    }
}
