//! Output files, whole or not at all.
//!
//! A command names every file it will write before it computes anything ([`Outputs`]): each
//! path is checked then (its extension, its directory, what it is), and a temporary file is
//! created beside it, so a run that cannot write its outputs fails before it starts. The
//! command stages each output into its temporary file as it goes and commits them all at its
//! end; a run that fails on the way leaves nothing behind, and none of its earlier outputs.
//!
//! What a path names decides how it is written:
//! - a regular file, or a new one: staged beside it, renamed over it at the commit. Symlinks
//!   are followed, so the file a symlink names is replaced and the symlink stays.
//! - a FIFO, a pipe named through `/dev/fd` or a character device (`/dev/null`, a terminal,
//!   `/dev/stdout`): written through at the commit, never replaced.
//! - `-`: standard output, where the format allows it.
//! - a directory, a block device or a socket: refused.
//!
//! A directory output is either a directory of files ([`Outputs::dir`]: its files renamed
//! in one by one, other files there kept) or written whole ([`Outputs::tree`] for a store
//! such as Zarr's, [`Outputs::series`] for numbered files such as `--slices`): staged as a
//! new directory that replaces the old one at the commit, so that no file of an earlier run
//! stays among the new ones. A directory is replaced only when csgpix could have written
//! it (empty, holding the format's marker file, or holding only the series' files); any
//! other is refused when it is named, before anything is computed. A tree is synced to the
//! disk before it replaces anything ([`sync_tree`]).
//!
//! SIGINT, SIGTERM and SIGHUP remove every staged file and directory, end the child processes
//! and remove the scratch files a run registered ([`scratch`], [`child`]), before the process
//! dies of the signal ([`install_signal_cleanup`]); they wait for a commit's renames, never for
//! an output written through. A signal that comes after some outputs are in place says which
//! ones; a signal that comes after the run has ended ([`finish`]) is not acted on, and a
//! report whose standard output fails ends in one line ([`stdout_failed`]). SIGKILL cannot be
//! caught: what it leaves beside an output is cleared (or, for a replaced directory,
//! restored) by the next run that names that output (`leftover`).

use std::fs::File;
use std::io::{Seek, Write};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, RwLock, RwLockReadGuard};

mod ending;
mod error;
mod leftover;
mod oom;
mod release;
mod replace;
mod scratch;
mod sparse;

pub use ending::{finish, stdout_failed};
pub use error::{Error, IoError, OneLine, Refusal, Result};
pub use oom::{fallible, one_arena_under_address_limit, try_zeroed, AllocFailed, ExitOnOom};
pub use release::{hold_if_asked, release_after_exit, HOLD, WORTH_A_CHILD};
pub use replace::sync_outputs;
pub use scratch::{child, scratch, Child, Scratch};
pub use sparse::{Sparse, BLOCK};

/// Staged paths a signal must remove: temporary files and directories not yet committed.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Held through a commit, and by the signal cleanup: a commit is never cut in half.
static COMMIT: Mutex<()> = Mutex::new(());

/// Set once a signal's cleanup has begun: no write into a staged directory starts after it
/// ([`staged_write`]).
static STOPPING: RwLock<bool> = RwLock::new(false);

/// Held while a file is written by path inside a staged directory by a writer that also
/// creates missing parent directories (a Zarr store's chunks: zarrs's filesystem store makes
/// a chunk's directories as it writes it). A signal's cleanup waits for the writes in flight
/// and none starts after it (`None`: the run is being stopped), so that no directory is made
/// again once the cleanup has removed the staging directory. Cheap when no signal comes; a
/// process without [`install_signal_cleanup`] always gets a guard.
pub fn staged_write() -> Option<StagedWrite> {
    let held = STOPPING.read().unwrap_or_else(|e| e.into_inner());
    (!*held).then_some(StagedWrite { _held: held })
}

/// A write into a staged directory in flight ([`staged_write`]).
pub struct StagedWrite {
    _held: RwLockReadGuard<'static, bool>,
}

fn pending() -> MutexGuard<'static, Vec<PathBuf>> {
    PENDING.lock().unwrap_or_else(|e| e.into_inner())
}

fn forget(path: &Path) {
    pending().retain(|p| p != path);
}

/// On SIGINT, SIGTERM or SIGHUP remove every staged output, kill the registered children's
/// process groups and remove the registered scratch paths ([`scratch`], [`child`]), then die
/// of the signal as its default action would (the shell sees the signal). Call once, from
/// `main`.
pub fn install_signal_cleanup() -> Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])
        .map_err(|e| Error::Io(e.into()))?;
    INSTALLED.store(true, std::sync::atomic::Ordering::SeqCst);
    std::thread::spawn(move || {
        if let Some(sig) = signals.forever().next() {
            if !ending::claim() {
                // The run has ended first, with its own status and report.
                return;
            }
            // Held to the end: a commit in progress finishes first, and none starts after.
            let _commit = COMMIT.lock().unwrap_or_else(|e| e.into_inner());
            // Writes in flight end first; none starts after (held to the end too).
            let mut stopping = STOPPING.write().unwrap_or_else(|e| e.into_inner());
            *stopping = true;
            let mut staged = pending();
            for p in staged.drain(..) {
                remove_staged(&p);
            }
            scratch::clear();
            if let Some(line) = ending::written_line(sig) {
                ending::say(line);
            }
            let _ = signal_hook::low_level::emulate_default_handler(sig);
            std::process::exit(128 + sig);
        }
    });
    Ok(())
}

static INSTALLED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Whether [`install_signal_cleanup`] runs in this process: a child process may then lead its
/// own process group, which the cleanup ends ([`child`]); otherwise it stays in the caller's,
/// so that a terminal's Ctrl-C reaches it (a library user's process, Python).
pub fn signal_cleanup_installed() -> bool {
    INSTALLED.load(std::sync::atomic::Ordering::SeqCst)
}

/// Remove every staged output now, for a process about to end without unwinding (out of
/// memory, [`ExitOnOom`]). The list is skipped if another thread holds it (it is then
/// adding to it, and a lock could wait forever on this very thread).
pub(crate) fn remove_all_staged() {
    if let Ok(mut staged) = PENDING.try_lock() {
        for p in staged.drain(..) {
            remove_staged(&p);
        }
    }
}

/// Remove a staged file, or a staged directory and its files. The run is still going while
/// a signal's cleanup runs, and may be creating files in a staging directory by path (one
/// slice after another): the directory is renamed first, so that nothing new can appear in
/// it, then removed.
fn remove_staged(p: &Path) {
    if std::fs::symlink_metadata(p).is_ok_and(|m| !m.is_dir()) {
        let _ = std::fs::remove_file(p);
        return;
    }
    let doomed = p.with_extension("csgpix-rm");
    let dir = match std::fs::rename(p, &doomed) {
        Ok(()) => doomed,
        Err(_) => p.to_path_buf(),
    };
    for _ in 0..100 {
        match std::fs::remove_dir_all(&dir) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => continue,
            _ => return,
        }
    }
}

/// A staged file: a named temporary file beside its target, removed on drop or on a signal.
struct Staged {
    file: Option<tempfile::NamedTempFile>,
}

impl Staged {
    fn new_in(dir: &Path, name: &str) -> std::io::Result<Staged> {
        // Held from before the file exists: a signal's cleanup cannot miss it.
        let mut staged = pending();
        let file = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .rand_bytes(leftover::RANDOM)
            .suffix(".csgpix-tmp")
            .tempfile_in(dir)?;
        // Marks it as this live run's: another run naming the output leaves it alone.
        leftover::lock(file.as_file());
        staged.push(file.path().to_path_buf());
        Ok(Staged { file: Some(file) })
    }

    fn file(&mut self) -> &mut File {
        self.file
            .as_mut()
            .expect("staged file present")
            .as_file_mut()
    }

    /// Rename over `target` with `mode`.
    fn persist(mut self, target: &Path, mode: u32) -> Result<()> {
        let file = self.file.take().expect("staged file present");
        let tmp = file.path().to_path_buf();
        // The file is moved by path from here: its name is no longer removed on drop.
        let (file, path) = file.into_parts();
        let r = set_mode(&file, mode)
            .and_then(|()| replace::put_file(&path, target))
            .map_err(|e| Error::io(target.display(), &e));
        if r.is_err() {
            let _ = std::fs::remove_file(&path);
        }
        let _ = path.keep();
        forget(&tmp);
        r
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if let Some(f) = self.file.take() {
            let p = f.path().to_path_buf();
            drop(f);
            forget(&p);
        }
    }
}

#[cfg(unix)]
fn set_mode(f: &File, mode: u32) -> std::io::Result<()> {
    use std::os::unix::fs::PermissionsExt;
    f.set_permissions(std::fs::Permissions::from_mode(mode))
}

#[cfg(not(unix))]
fn set_mode(_: &File, _: u32) -> std::io::Result<()> {
    Ok(())
}

/// Write `path` with the bytes `fill` produces, whole or not at all (one output alone; a
/// command with several uses [`Outputs`]).
pub fn write_atomic(
    path: &Path,
    fill: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<()> {
    let mut outs = Outputs::new();
    let out = outs.file("output", path, &[])?;
    outs.write(out, fill)?;
    outs.commit()
}

/// Where an output goes, found when it is named.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Target {
    /// A regular file, or a new one (symlinks resolved), and the mode it gets.
    File(PathBuf, u32),
    /// A FIFO or a character device: opened and written at the commit.
    Through(PathBuf),
    /// Standard output.
    Stdout,
    /// A directory of files, new or existing (symlinks resolved).
    Dir(PathBuf),
    /// A directory written whole (symlinks resolved), replacing an existing one that is
    /// empty or shows it is csgpix's as said here.
    Tree(PathBuf, Owned),
}

/// What shows that an existing directory is csgpix's to replace whole.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Owned {
    /// It holds this file, which names the format (`zarr.json`).
    Marker(String),
    /// It holds regular files named `prefix`, decimal digits, `suffix` (`slice-0012.png`)
    /// and nothing else: the files csgpix writes there, and no other.
    Series { prefix: String, suffix: String },
}

impl Owned {
    /// Whether `name` is one of the series' files.
    fn in_series(&self, name: &str) -> bool {
        let Owned::Series { prefix, suffix } = self else {
            return true;
        };
        let digits = name
            .strip_prefix(prefix.as_str())
            .and_then(|n| n.strip_suffix(suffix.as_str()));
        digits.is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
    }
}

enum Stage {
    /// Staged beside a regular file.
    Named(Staged),
    /// Staged in an unnamed temporary file, copied out at the commit.
    Unnamed(File),
    /// A staging directory beside the target directory, and the names written into it.
    Dir(StagedDir, Vec<String>),
}

/// A staging directory, removed on drop or on a signal; and the directory opened, locked
/// as a live run's for as long as it is held (`leftover`).
struct StagedDir {
    path: PathBuf,
    _held: Option<File>,
}

impl StagedDir {
    /// A new staging directory `.NAME.XXXXXX.csgpix-tmp` in `base`, locked.
    fn new_in(base: &Path, name: &str) -> std::io::Result<StagedDir> {
        // Held from before the directory exists: a signal's cleanup cannot miss it.
        let mut staged = pending();
        let dir = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .rand_bytes(leftover::RANDOM)
            .suffix(".csgpix-tmp")
            .tempdir_in(base)?
            .keep();
        staged.push(dir.clone());
        drop(staged);
        let held = File::open(&dir).ok().filter(leftover::lock);
        Ok(StagedDir {
            path: dir,
            _held: held,
        })
    }
}

impl Drop for StagedDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.path);
        forget(&self.path);
    }
}

struct Slot {
    shown: String,
    target: Target,
    stage: Stage,
}

/// A handle to one output of an [`Outputs`] set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Out(usize);

/// The outputs of one run: named first, staged while it runs, committed together.
#[derive(Default)]
pub struct Outputs {
    slots: Vec<Slot>,
}

impl Outputs {
    /// No outputs yet.
    pub fn new() -> Outputs {
        Outputs::default()
    }

    /// Name a file output of option `flag`: its extension must be one of `exts` (any case;
    /// none checked when `exts` is empty, or when the path is a FIFO or a device).
    pub fn file(&mut self, flag: &str, path: &Path, exts: &[&str]) -> Result<Out> {
        self.named(flag, path, exts, false)
    }

    /// As [`Outputs::file`], and `-` means standard output.
    pub fn file_or_stdout(&mut self, flag: &str, path: &Path, exts: &[&str]) -> Result<Out> {
        self.named(flag, path, exts, true)
    }

    /// Name a directory output of option `flag` (created at the commit, with its parents).
    pub fn dir(&mut self, flag: &str, path: &Path) -> Result<Out> {
        self.dir_slot(flag, path, None)
    }

    /// Name a directory output of option `flag` that is written whole, such as a Zarr store
    /// (its name must end in one of `exts`, as for [`Outputs::file`]): staged as a new
    /// directory and renamed into place at the commit, with its parents. A directory already
    /// at the path is replaced whole, so that no file of an earlier run stays among the new
    /// ones; but only when it is empty or holds `marker` (a file that names the format, e.g.
    /// `zarr.json`), so that a mistyped path never removes a directory of other files: any
    /// other is refused here, before anything is computed. The replaced directory is renamed
    /// aside, the new one renamed in, the old one removed.
    pub fn tree(&mut self, flag: &str, path: &Path, exts: &[&str], marker: &str) -> Result<Out> {
        let shown = path.display().to_string();
        check_extension(path, exts).map_err(|e| e.context(format!("{flag} {shown}")))?;
        self.dir_slot(flag, path, Some(Owned::Marker(marker.to_string())))
    }

    /// Name a directory output of option `flag` that holds a numbered series of files and
    /// nothing else: `prefix`, decimal digits, `suffix` (`--slices`: `slice-0000.png`, …).
    /// Written whole as [`Outputs::tree`] is, so that a run writing fewer files than an
    /// earlier one leaves none of the earlier ones; a directory already at the path is
    /// replaced only when it is empty or holds nothing but such files (no subdirectory, no
    /// other name, no symlink), so a mistyped path never removes a directory of other
    /// files: any other is refused here, before anything is computed. Only names of the
    /// series may be written into it ([`Outputs::write_in`]).
    pub fn series(&mut self, flag: &str, path: &Path, prefix: &str, suffix: &str) -> Result<Out> {
        let owned = Owned::Series {
            prefix: prefix.to_string(),
            suffix: suffix.to_string(),
        };
        self.dir_slot(flag, path, Some(owned))
    }

    fn dir_slot(&mut self, flag: &str, path: &Path, whole: Option<Owned>) -> Result<Out> {
        let shown = path.display().to_string();
        let err = |e: Error| e.context(format!("{flag} {shown}"));
        if path.as_os_str() == "-" {
            return Err(err(Refusal::DirectoryToStdout.into()));
        }
        let resolved = resolve(path).map_err(err)?;
        let (base, name) = existing_ancestor(&resolved).map_err(err)?;
        // Before anything is looked at: a directory an interrupted commit renamed aside is
        // back in place first.
        leftover::clear(&base, &name);
        match std::fs::metadata(&resolved) {
            Ok(m) if !m.is_dir() => return Err(err(Refusal::ExistsNotDirectory.into())),
            Ok(_) => {}
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => return Err(err(Error::Io(e.into()))),
        }
        let target = match whole {
            None => Target::Dir(resolved.clone()),
            Some(owned) => {
                let named = replaced_name(&resolved).map_err(err)?;
                replaceable(&named, &owned).map_err(err)?;
                Target::Tree(named, owned)
            }
        };
        self.check_unique(&target, &shown)?;
        let staged = StagedDir::new_in(&base, &name).map_err(|e| {
            err(Error::io(
                format_args!("cannot write in {}", base.display()),
                &e,
            ))
        })?;
        self.slots.push(Slot {
            shown,
            target,
            stage: Stage::Dir(staged, Vec::new()),
        });
        Ok(Out(self.slots.len() - 1))
    }

    /// Does any output go to standard output? (Then reports go to standard error.)
    pub fn uses_stdout(&self) -> bool {
        self.slots.iter().any(|s| s.target == Target::Stdout)
    }

    /// The path an output was named by, for messages.
    pub fn shown(&self, out: Out) -> &str {
        &self.slots[out.0].shown
    }

    /// A file output's staged file, emptied and rewound, and its path for messages.
    fn emptied(&mut self, out: Out) -> Result<(&mut File, &str)> {
        let slot = &mut self.slots[out.0];
        let shown = slot.shown.as_str();
        let err = |e: std::io::Error| Error::io(shown, &e);
        let file = match &mut slot.stage {
            Stage::Named(s) => s.file(),
            Stage::Unnamed(f) => f,
            Stage::Dir(..) => return Err(Error::from(Refusal::DirectoryOutput).context(shown)),
        };
        // A new staged file is empty: truncating it would make ext4 flush it on close
        // (`replace`).
        if file.metadata().map_err(err)?.len() > 0 {
            file.set_len(0).map_err(err)?;
        }
        file.rewind().map_err(err)?;
        Ok((file, shown))
    }

    /// Stage the whole content of a file output.
    pub fn write(
        &mut self,
        out: Out,
        fill: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
    ) -> Result<()> {
        let (file, shown) = self.emptied(out)?;
        let err = |e: std::io::Error| Error::io(shown, &e);
        let mut buf = std::io::BufWriter::new(file);
        fill(&mut buf).map_err(err)?;
        buf.flush().map_err(err)
    }

    /// Stage the whole content of a file output, its runs of zeros of at least `hole` bytes
    /// left as holes ([`Sparse`]): the same bytes read back, fewer written. For volumes,
    /// which are mostly empty space. Returns the bytes written and skipped.
    pub fn write_sparse(
        &mut self,
        out: Out,
        hole: u64,
        fill: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
    ) -> Result<(u64, u64)> {
        let (file, shown) = self.emptied(out)?;
        let err = |e: std::io::Error| Error::io(shown, &e);
        let mut sparse = Sparse::new(file, hole).map_err(err)?;
        fill(&mut sparse).map_err(err)?;
        sparse.finish().map_err(err)
    }

    /// Stage file `name` of a directory output with the bytes `fill` produces.
    pub fn write_in(
        &mut self,
        out: Out,
        name: &str,
        fill: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
    ) -> Result<()> {
        let path = self.stage_path(out, name)?;
        let err = |e: std::io::Error| Error::io(path.display(), &e);
        let mut buf = std::io::BufWriter::new(File::create(&path).map_err(err)?);
        fill(&mut buf).map_err(err)?;
        buf.flush().map_err(err)
    }

    /// The staging directory of a directory output, for writers that lay out a tree of
    /// their own in it (a [`Outputs::tree`] output: the whole directory is committed).
    pub fn stage_root(&self, out: Out) -> Result<PathBuf> {
        let slot = &self.slots[out.0];
        match &slot.stage {
            Stage::Dir(dir, _) => Ok(dir.path.clone()),
            _ => Err(Refusal::NotDirectoryOutput {
                shown: slot.shown.clone(),
            }
            .into()),
        }
    }

    /// Where file `name` of a directory output is staged, for writers that take a path.
    pub fn stage_path(&mut self, out: Out, name: &str) -> Result<PathBuf> {
        let slot = &mut self.slots[out.0];
        let Stage::Dir(dir, names) = &mut slot.stage else {
            return Err(Refusal::NotDirectoryOutput {
                shown: slot.shown.clone(),
            }
            .into());
        };
        let foreign = matches!(&slot.target, Target::Tree(_, owned) if !owned.in_series(name));
        if name.contains('/') || name.starts_with('.') || name.is_empty() || foreign {
            return Err(Refusal::BadFileName {
                shown: slot.shown.clone(),
                name: name.to_string(),
            }
            .into());
        }
        if !names.iter().any(|n| n == name) {
            names.push(name.to_string());
        }
        Ok(dir.path.join(name))
    }

    /// Put every staged output in place: renames first, then the outputs written through.
    /// After a failure the outputs not yet committed are removed.
    ///
    /// The renames hold off a signal's cleanup, so that a set of files is never half
    /// renamed. Writing through does not: it can wait on a FIFO without a reader or a full
    /// pipe for as long as it likes, and SIGINT must still end the run (nothing of it is
    /// staged under a name by then).
    pub fn commit(mut self) -> Result<()> {
        let slots = std::mem::take(&mut self.slots);
        let (late, early): (Vec<Slot>, Vec<Slot>) = slots
            .into_iter()
            .partition(|s| matches!(s.target, Target::Through(_) | Target::Stdout));
        {
            let _commit = COMMIT.lock().unwrap_or_else(|e| e.into_inner());
            early.into_iter().try_for_each(commit_slot)?;
        }
        late.into_iter().try_for_each(commit_slot)
    }

    fn named(&mut self, flag: &str, path: &Path, exts: &[&str], stdout: bool) -> Result<Out> {
        let shown = path.display().to_string();
        let target = if path.as_os_str() == "-" || names_stdout(path) {
            if !stdout {
                let flag = flag.to_string();
                return Err(Refusal::NotToStdout { flag }.into());
            }
            Target::Stdout
        } else {
            classify(path).map_err(|e| e.context(format!("{flag} {shown}")))?
        };
        if let Target::File(..) = target {
            check_extension(path, exts).map_err(|e| e.context(format!("{flag} {shown}")))?;
        }
        self.check_unique(&target, &shown)?;
        let stage = match &target {
            Target::File(p, _) => {
                let (dir, name) = split(p);
                leftover::clear(&dir, &name);
                Stage::Named(Staged::new_in(&dir, &name).map_err(|e| {
                    Error::io(format_args!("cannot write in {}", dir.display()), &e)
                        .context(format!("{flag} {shown}"))
                })?)
            }
            _ => Stage::Unnamed(
                tempfile::tempfile().map_err(|e| Error::io(format_args!("{flag} {shown}"), &e))?,
            ),
        };
        self.slots.push(Slot {
            shown,
            target,
            stage,
        });
        Ok(Out(self.slots.len() - 1))
    }

    fn check_unique(&self, target: &Target, shown: &str) -> Result<()> {
        match self.slots.iter().find(|s| same_target(&s.target, target)) {
            Some(s) if *target == Target::Stdout => Err(Refusal::TwoStdout {
                first: s.shown.clone(),
                second: shown.to_string(),
            }
            .into()),
            Some(s) => Err(Refusal::SameFile {
                first: s.shown.clone(),
                second: shown.to_string(),
            }
            .into()),
            None => Ok(()),
        }
    }
}

fn same_target(a: &Target, b: &Target) -> bool {
    match (a, b) {
        (
            Target::File(p, _) | Target::Dir(p) | Target::Tree(p, _),
            Target::File(q, _) | Target::Dir(q) | Target::Tree(q, _),
        ) => p == q,
        (Target::Through(p), Target::Through(q)) => p == q,
        (Target::Stdout, Target::Stdout) => true,
        _ => false,
    }
}

fn commit_slot(slot: Slot) -> Result<()> {
    let shown = match slot.target {
        Target::Stdout => "standard output".to_string(),
        _ => slot.shown.clone(),
    };
    put_in_place(slot)?;
    ending::written(&shown);
    Ok(())
}

fn put_in_place(slot: Slot) -> Result<()> {
    let err = |e: std::io::Error| Error::io(&slot.shown, &e);
    match (slot.target, slot.stage) {
        (Target::File(p, mode), Stage::Named(s)) => s.persist(&p, mode),
        (Target::Through(p), Stage::Unnamed(mut f)) => {
            let mut dest = std::fs::OpenOptions::new()
                .write(true)
                .open(&p)
                .map_err(err)?;
            f.rewind().map_err(err)?;
            std::io::copy(&mut f, &mut dest).map_err(err)?;
            dest.flush().map_err(err)
        }
        (Target::Stdout, Stage::Unnamed(mut f)) => {
            f.rewind().map_err(err)?;
            let mut out = std::io::stdout().lock();
            std::io::copy(&mut f, &mut out).map_err(err)?;
            out.flush().map_err(err)
        }
        (Target::Dir(p), Stage::Dir(dir, names)) => commit_dir(&p, &dir.path, &names).map_err(err),
        (Target::Tree(p, owned), Stage::Dir(dir, _)) => {
            commit_tree(&p, &dir.path, &owned).map_err(err)
        }
        _ => unreachable!("stage made for its target"),
    }
}

/// Rename the staging directory into place, or its files into an existing directory.
fn commit_dir(target: &Path, dir: &Path, names: &[String]) -> std::io::Result<()> {
    if !target.exists() {
        if let Some(parent) = target.parent().filter(|p| !p.as_os_str().is_empty()) {
            std::fs::create_dir_all(parent)?;
        }
        set_dir_mode(dir)?;
        if replace::durable() {
            sync_tree(dir)?;
        }
        std::fs::rename(dir, target)?;
        if replace::durable() {
            replace::sync_parent(target)?;
        }
        return Ok(());
    }
    for name in names {
        replace::put_file(&dir.join(name), &target.join(name))?;
    }
    Ok(())
}

/// The path of a directory written whole, without `.` components: it must end in a name
/// (not `.`, `..` or `/`), which the commit renames.
fn replaced_name(p: &Path) -> Result<PathBuf> {
    let clean: PathBuf = p.components().collect();
    match clean.components().next_back() {
        Some(std::path::Component::Normal(_)) => Ok(clean),
        _ => Err(Refusal::NoName.into()),
    }
}

/// Whether an existing directory at `p` may be replaced whole: it is empty or shows it is
/// csgpix's as `owned` says (nothing there is fine too).
fn replaceable(p: &Path, owned: &Owned) -> Result<()> {
    let mut entries = match std::fs::read_dir(p) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(Error::Io(e.into())),
        Ok(entries) => entries.peekable(),
    };
    if entries.peek().is_none() {
        return Ok(());
    }
    match owned {
        Owned::Marker(marker) if p.join(marker).is_file() => Ok(()),
        Owned::Marker(marker) => Err(Refusal::NotReplaceable {
            marker: marker.clone(),
        }
        .into()),
        Owned::Series { prefix, suffix } => {
            for e in entries {
                let e = e.map_err(|e| Error::Io(e.into()))?;
                let name = e.file_name().to_string_lossy().into_owned();
                let file = e.file_type().is_ok_and(|t| t.is_file());
                if !(file && owned.in_series(&name)) {
                    let series = format!("{prefix}N{suffix}");
                    return Err(Refusal::NotSeries {
                        entry: name,
                        series,
                    }
                    .into());
                }
            }
            Ok(())
        }
    }
}

/// Rename the staging directory into place, replacing a directory there whole (renamed
/// aside, beside the staging directory, then removed once the new one is in). The new tree
/// is on the disk first ([`sync_tree`]), so that a power cut after the old one is removed
/// cannot lose both; a kill between the two renames leaves the old one renamed aside, which
/// the next run naming the output puts back (`leftover`).
fn commit_tree(target: &Path, dir: &Path, owned: &Owned) -> std::io::Result<()> {
    if let Some(parent) = target.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent)?;
    }
    set_dir_mode(dir)?;
    sync_tree(dir)?;
    match std::fs::symlink_metadata(target) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return std::fs::rename(dir, target),
        Err(e) => return Err(e),
        Ok(_) => {}
    }
    // Checked again: the run may have been long, and the directory changed meanwhile.
    replaceable(target, owned).map_err(std::io::Error::other)?;
    // Locked as this live run's while it is aside (`leftover`).
    let _held = File::open(target).ok().filter(leftover::lock);
    let old = dir.with_extension("csgpix-old");
    std::fs::rename(target, &old)?;
    if let Err(e) = std::fs::rename(dir, target) {
        let _ = std::fs::rename(&old, target);
        return Err(e);
    }
    std::fs::remove_dir_all(&old)
}

/// Put the files and directories under `dir` on the disk, once for the whole tree rather
/// than once per file (a Zarr store of 1³ chunks has tens of thousands of files, and one
/// `fsync` each took most of a run's time). On Linux one `syncfs(2)` of the filesystem
/// `dir` is on; elsewhere every file and directory under it synced in turn.
pub fn sync_tree(dir: &Path) -> std::io::Result<()> {
    #[cfg(target_os = "linux")]
    {
        use std::os::fd::AsRawFd;
        let d = File::open(dir)?;
        // SAFETY: syncfs(2) on a descriptor this File owns.
        match unsafe { libc::syncfs(d.as_raw_fd()) } {
            0 => Ok(()),
            _ => Err(std::io::Error::last_os_error()),
        }
    }
    #[cfg(not(target_os = "linux"))]
    {
        sync_each(dir)
    }
}

/// Every file and directory under `dir` synced, the directory last.
#[cfg(not(target_os = "linux"))]
fn sync_each(dir: &Path) -> std::io::Result<()> {
    for e in std::fs::read_dir(dir)? {
        let e = e?;
        match e.file_type()? {
            t if t.is_dir() => sync_each(&e.path())?,
            t if t.is_file() => File::open(e.path())?.sync_all()?,
            _ => {}
        }
    }
    replace::sync_dir(dir)
}

#[cfg(unix)]
fn set_dir_mode(dir: &Path) -> std::io::Result<()> {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(dir, std::fs::Permissions::from_mode(0o755))
}

#[cfg(not(unix))]
fn set_dir_mode(_: &Path) -> std::io::Result<()> {
    Ok(())
}

/// The directory and file name of a resolved file path.
fn split(p: &Path) -> (PathBuf, String) {
    let dir = match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let name = p
        .file_name()
        .map_or("output".into(), |n| n.to_string_lossy().into_owned());
    (dir, name)
}

/// The deepest existing directory on the way to `p`, and the first name below it.
fn existing_ancestor(p: &Path) -> Result<(PathBuf, String)> {
    let mut cur = p.to_path_buf();
    loop {
        let (dir, name) = split(&cur);
        match std::fs::metadata(&dir) {
            Ok(m) if m.is_dir() => return Ok((dir, name)),
            Ok(_) => {
                return Err(Error::NotADirectory {
                    path: dir.display().to_string(),
                })
            }
            Err(_) if dir != cur && dir.parent().is_some() => cur = dir,
            Err(e) => return Err(Error::io(dir.display(), &e)),
        }
    }
}

/// Follow symlinks (dangling ones too, up to 40) to the path that is written. A trailing
/// slash after a symlink (`-o LINK/`) names the same link: the system would follow it to the
/// directory, whose replacement (a store written whole) would then replace the link.
fn resolve(path: &Path) -> Result<PathBuf> {
    let mut p = path.to_path_buf();
    let bare: PathBuf = path.components().collect();
    if bare.as_os_str() != p.as_os_str()
        && std::fs::symlink_metadata(&bare).is_ok_and(|m| m.file_type().is_symlink())
    {
        p = bare;
    }
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let link = std::fs::read_link(&p).map_err(|e| Error::Io(e.into()))?;
                p = match p.parent() {
                    Some(dir) if link.is_relative() => dir.join(link),
                    _ => link,
                };
            }
            _ => return Ok(p),
        }
    }
    Err(Refusal::SymlinkLoop.into())
}

/// The names of standard output a shell user writes: the same as `-`.
fn names_stdout(path: &Path) -> bool {
    ["/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"]
        .iter()
        .any(|p| path == Path::new(p))
}

/// What a file output's path names, and so how it is written.
fn classify(path: &Path) -> Result<Target> {
    // What the kernel finds at the end of every link decides first: /proc's links to pipes
    // (`-o /dev/fd/3`, `-o >(gzip > v.nrrd.gz)`, `-o /dev/stderr` into a pipe) name no path
    // that can be followed by hand, and are opened as they are named.
    if let Ok(meta) = std::fs::metadata(path) {
        if !meta.is_file() && !meta.is_dir() {
            return special(path, &meta);
        }
    }
    let p = resolve(path)?;
    let meta = match std::fs::metadata(&p) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            let (dir, _) = split(&p);
            return match std::fs::metadata(&dir) {
                Ok(m) if m.is_dir() => Ok(Target::File(p, 0o644)),
                Ok(_) => Err(Error::NotADirectory {
                    path: dir.display().to_string(),
                }),
                Err(e) => Err(Error::io(format_args!("directory {}", dir.display()), &e)),
            };
        }
        Err(e) => return Err(Error::Io(e.into())),
    };
    let ft = meta.file_type();
    if ft.is_dir() {
        return Err(Refusal::IsDirectory.into());
    }
    if ft.is_file() {
        // A shell's redirection seen through /dev/stdout or /proc/self/fd: write through.
        if path.starts_with("/dev") || path.starts_with("/proc") {
            return Ok(Target::Through(p));
        }
        return Ok(Target::File(p, mode_of(&meta)));
    }
    special(&p, &meta)
}

#[cfg(unix)]
fn mode_of(meta: &std::fs::Metadata) -> u32 {
    use std::os::unix::fs::PermissionsExt;
    meta.permissions().mode() & 0o7777
}

#[cfg(not(unix))]
fn mode_of(_: &std::fs::Metadata) -> u32 {
    0o644
}

#[cfg(unix)]
fn special(p: &Path, meta: &std::fs::Metadata) -> Result<Target> {
    use std::os::unix::fs::FileTypeExt;
    let ft = meta.file_type();
    if ft.is_fifo() || ft.is_char_device() {
        Ok(Target::Through(p.to_path_buf()))
    } else if ft.is_block_device() {
        Err(Refusal::BlockDevice.into())
    } else {
        Err(Refusal::SpecialFile.into())
    }
}

#[cfg(not(unix))]
fn special(_: &Path, _: &std::fs::Metadata) -> Result<Target> {
    Err(Refusal::NotRegularFile.into())
}

/// The name must end in one of `exts` (case-insensitive), so that `x.jpg` is not PNG bytes.
fn check_extension(path: &Path, exts: &[&str]) -> Result<()> {
    if exts.is_empty() {
        return Ok(());
    }
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    if ext.as_deref().is_some_and(|e| exts.contains(&e)) {
        return Ok(());
    }
    let expected = exts.iter().map(|e| e.to_string()).collect();
    Err(Refusal::Extension { expected }.into())
}

#[cfg(test)]
mod tests;

/// Bytes free to an unprivileged writer on the filesystem that holds `dir` (`statvfs`'s
/// `f_bavail`), or `None` where the system does not say: for a run that knows its outputs'
/// size before it writes them, to refuse rather than fill the disk.
#[cfg(unix)]
pub fn free_bytes(dir: &Path) -> Option<u64> {
    use std::os::unix::ffi::OsStrExt;
    let c = std::ffi::CString::new(dir.as_os_str().as_bytes()).ok()?;
    let mut st = std::mem::MaybeUninit::<libc::statvfs>::uninit();
    // SAFETY: statvfs(3) with a NUL-terminated path and a buffer of its type.
    if unsafe { libc::statvfs(c.as_ptr(), st.as_mut_ptr()) } != 0 {
        return None;
    }
    // SAFETY: statvfs returned 0, so it filled the buffer.
    let st = unsafe { st.assume_init() };
    // The fields' types differ between systems (u32 on some 32-bit ones).
    #[allow(clippy::unnecessary_cast)]
    Some((st.f_bavail as u64).saturating_mul(st.f_frsize as u64))
}

/// Bytes free on the filesystem that holds `dir`: not known on this system.
#[cfg(not(unix))]
pub fn free_bytes(_: &Path) -> Option<u64> {
    None
}
