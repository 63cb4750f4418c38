//! openscad as a subprocess, within a time limit: a `.scad` file can keep it busy for hours
//! (a `minkowski` of fine spheres, a loop of millions), and nothing else would stop it. A
//! signal that ends the run ends the child too (`csgpix_output::child`).

use std::io::{Read, Seek};
use std::process::{Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// How long one openscad run may take unless told otherwise: a `.scad` export or a
/// `--fallback openscad` mesh. Five minutes: far beyond the seconds a design takes to
/// export, short enough that a script waiting on a hung run learns of it.
pub const DEFAULT_OPENSCAD_TIMEOUT: Duration = Duration::from_secs(300);

/// How an openscad run ended.
pub(crate) enum Ran {
    /// By itself: its status and what it wrote on standard error.
    Done {
        /// Its exit status.
        status: ExitStatus,
        /// Its standard error, lossily decoded.
        stderr: String,
    },
    /// Killed at the time limit (and reaped).
    TimedOut,
}

/// Run `cmd` to its end, or until `limit` (None: no limit), when it is killed and reaped.
/// Its standard error goes to an unnamed temporary file, not a pipe, and its standard
/// output nowhere: a process it leaves behind (a wrapper script's child) cannot hold a
/// pipe open and keep this waiting past the limit. Err: it could not be started
/// (`NotFound`: not on PATH).
pub(crate) fn run(cmd: &mut Command, limit: Option<Duration>) -> std::io::Result<Ran> {
    let mut err = tempfile::tempfile()?;
    cmd.stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(err.try_clone()?);
    // Under the binary's signal cleanup the child leads its own process group, which the
    // cleanup kills with the run (a signal sent to csgpix alone reached no child before).
    #[cfg(unix)]
    if csgpix_output::signal_cleanup_installed() {
        std::os::unix::process::CommandExt::process_group(cmd, 0);
    }
    let mut child = cmd.spawn()?;
    let _ended_with_the_run = csgpix_output::child(child.id());
    let Some(status) = wait(&mut child, limit)? else {
        // SIGKILL: openscad has nothing to save, and a busy one may not heed SIGTERM.
        let _ = child.kill();
        child.wait()?;
        return Ok(Ran::TimedOut);
    };
    let mut bytes = vec![];
    err.rewind()?;
    err.read_to_end(&mut bytes)?;
    let stderr = String::from_utf8_lossy(&bytes).into_owned();
    Ok(Ran::Done { status, stderr })
}

/// The child's exit status, or None once `limit` has passed. Polled, from every
/// millisecond up to every 50: a quick export is not held back, a long one costs nothing.
fn wait(
    child: &mut std::process::Child,
    limit: Option<Duration>,
) -> std::io::Result<Option<ExitStatus>> {
    let t0 = Instant::now();
    let mut pause = Duration::from_millis(1);
    loop {
        if let Some(status) = child.try_wait()? {
            return Ok(Some(status));
        }
        let left = limit.map(|l| l.saturating_sub(t0.elapsed()));
        if left == Some(Duration::ZERO) {
            return Ok(None);
        }
        std::thread::sleep(left.map_or(pause, |l| l.min(pause)));
        pause = (pause * 2).min(Duration::from_millis(50));
    }
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn a_run_past_its_limit_is_killed_and_reaped() {
        let t0 = Instant::now();
        // The shell's child `sleep` keeps the shell's standard error open after the kill:
        // nothing here waits for it.
        let mut cmd = Command::new("sh");
        cmd.args(["-c", "sleep 5; true"]);
        let ran = run(&mut cmd, Some(Duration::from_millis(300))).unwrap();
        assert!(matches!(ran, Ran::TimedOut));
        assert!(t0.elapsed() < Duration::from_secs(4), "{:?}", t0.elapsed());
    }

    #[test]
    fn a_run_within_its_limit_gives_its_status_and_stderr() {
        let mut cmd = Command::new("sh");
        cmd.args(["-c", "echo out; echo ERROR: no >&2; exit 3"]);
        let Ran::Done { status, stderr } = run(&mut cmd, Some(Duration::from_secs(60))).unwrap()
        else {
            panic!("timed out")
        };
        assert_eq!(status.code(), Some(3));
        assert_eq!(stderr, "ERROR: no\n");
    }
}
