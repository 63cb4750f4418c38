//! How a run ends when a signal comes late: either the run finished first (it exits with its
//! own status, its report printed) or the signal did (the process dies of it, and says which
//! outputs were already written whole). Never both, never neither.
//!
//! The run and the signal's cleanup race for one state ([`finish`] against [`claim`]): the
//! winner decides the ending. A signal that comes after the run claimed its end is not acted
//! on; the run has completed and its exit status says so.

use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::Mutex;
use std::time::Duration;

use crate::OneLine;

const RUNNING: u8 = 0;
const FINISHED: u8 = 1;
const SIGNALLED: u8 = 2;

static STATE: AtomicU8 = AtomicU8::new(RUNNING);

/// The outputs already put in place, as the command line named them.
static WRITTEN: Mutex<Vec<String>> = Mutex::new(Vec::new());

/// End the run with `code`, unless a signal's cleanup has begun: then wait for it to end the
/// process (it dies of the signal). Call last, from `main`, after the report is printed.
pub fn finish<T>(code: T) -> T {
    if !crate::signal_cleanup_installed() {
        return code;
    }
    match STATE.compare_exchange(RUNNING, FINISHED, Ordering::SeqCst, Ordering::SeqCst) {
        Ok(_) => code,
        Err(_) => loop {
            std::thread::park();
        },
    }
}

/// Standard output failed under a report (its reader gone, `| head`; a full disk): say so in
/// one line, naming the outputs already in place whole, and exit with status 2. A signal's
/// cleanup already under way ends the process instead.
pub fn stdout_failed(e: &std::io::Error) -> ! {
    if crate::signal_cleanup_installed()
        && STATE
            .compare_exchange(RUNNING, FINISHED, Ordering::SeqCst, Ordering::SeqCst)
            .is_err()
    {
        loop {
            std::thread::park();
        }
    }
    let mut line = format!("csgpix: cannot write to standard output: {}", OneLine(e));
    if let Some(names) = written_names() {
        line += &format!("; already written whole: {names}");
    }
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "{line}");
    std::process::exit(2)
}

/// The signal's cleanup takes the ending: false when the run has already claimed it.
pub(crate) fn claim() -> bool {
    STATE
        .compare_exchange(RUNNING, SIGNALLED, Ordering::SeqCst, Ordering::SeqCst)
        .is_ok()
}

/// `shown` is in place, whole.
pub(crate) fn written(shown: &str) {
    WRITTEN
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push(shown.to_string());
}

/// The line a signal's cleanup prints when outputs were already in place, if any were.
pub(crate) fn written_line(sig: i32) -> Option<String> {
    let names = written_names()?;
    Some(format!(
        "csgpix: interrupted by {}; already written whole: {names}",
        signal_name(sig),
    ))
}

/// The outputs already in place, escaped and comma-separated; None when there are none.
fn written_names() -> Option<String> {
    let written = WRITTEN.lock().unwrap_or_else(|e| e.into_inner());
    let names: Vec<String> = written.iter().map(|s| OneLine(s).to_string()).collect();
    (!names.is_empty()).then(|| names.join(", "))
}

/// Print `line` on standard error, waiting at most a second: a signal must end the run even
/// when standard error is a full pipe nobody reads.
pub(crate) fn say(line: String) {
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        eprintln!("{line}");
        let _ = tx.send(());
    });
    let _ = rx.recv_timeout(Duration::from_secs(1));
}

fn signal_name(sig: i32) -> String {
    match sig {
        libc::SIGINT => "SIGINT".into(),
        libc::SIGTERM => "SIGTERM".into(),
        libc::SIGHUP => "SIGHUP".into(),
        _ => format!("signal {sig}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_names_every_output_written_escaped() {
        written("a.vcd");
        written("b\nc.png");
        let line = written_line(libc::SIGINT).unwrap();
        assert!(line.starts_with("csgpix: interrupted by SIGINT; already written whole: "));
        assert!(line.contains("a.vcd, "), "{line}");
        assert_eq!(line.lines().count(), 1, "{line}");
    }
}
