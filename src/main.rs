//! The `csgpix` command line: clap parses the flags into a command of the run layer
//! (`csgpix-run`), which runs it; this file turns its outcome into an exit status.

mod cli;

use std::process::ExitCode;

use clap::Parser;
use csgpix_output::OneLine;

/// A failed allocation ends the run with a one-line error and exit status 2, its staged
/// outputs removed, never an abort (crates/output, docs/memory.md).
#[global_allocator]
static ALLOC: csgpix_output::ExitOnOom = csgpix_output::ExitOnOom;

fn main() -> ExitCode {
    // A child started to hold an old output until this process ends exits here
    // (crates/output/src/release.rs).
    csgpix_output::hold_if_asked();
    csgpix_output::one_arena_under_address_limit();
    let args = match cli::Cli::try_parse() {
        Ok(args) => args,
        Err(e) if !e.use_stderr() => {
            // --help and --version: clap's own output, exit 0.
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) if e.kind() == clap::error::ErrorKind::InvalidUtf8 => {
            // clap does not say which argument: name it.
            let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
            let msg = cli::args_utf8::message(&args)
                .unwrap_or_else(|| "an argument is not UTF-8".to_string());
            eprintln!("csgpix: {} (see --help)", OneLine(msg));
            return ExitCode::from(2);
        }
        Err(e) => {
            // One line: clap's message up to its usage hint, lines joined.
            let text = e.render().to_string();
            let msg: Vec<&str> = text
                .lines()
                .map(str::trim)
                .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more"))
                .filter(|l| !l.is_empty())
                .collect();
            let msg = msg.join(" ");
            let msg = msg.trim_start_matches("error: ");
            eprintln!("csgpix: {} (see --help)", OneLine(msg));
            return ExitCode::from(2);
        }
    };
    // Staged outputs are removed if the run is interrupted (crates/output).
    if let Err(e) = csgpix_output::install_signal_cleanup() {
        eprintln!("csgpix: cannot watch for signals: {e}");
        return ExitCode::from(2);
    }
    // The old files of replaced outputs are freed after this process ends, not during it.
    if let Ok(exe) = std::env::current_exe() {
        csgpix_output::release_after_exit(exe);
    }
    let code = match cli::run(args) {
        Ok(code) => code,
        Err(e) => {
            // The libraries escape what they echo; this is the last resort for the rest.
            eprintln!("csgpix: {}", OneLine(e));
            ExitCode::from(2)
        }
    };
    // A signal that came first ends the process instead (crates/output).
    csgpix_output::finish(code)
}
