//! The `csgpix` command line: clap parses the flags into a command of the run layer
//! (`csgpix-run`), which runs it; this file turns its outcome into an exit status.

use csgpix_run as cli;

use std::process::ExitCode;

use clap::Parser;

/// A failed allocation ends the run with a one-line error and exit status 2, its staged
/// outputs removed, never an abort (crates/output, docs/memory.md).
#[global_allocator]
static ALLOC: csgpix_output::ExitOnOom = csgpix_output::ExitOnOom;

fn main() -> ExitCode {
    csgpix_output::one_arena_under_address_limit();
    let args = match cli::Cli::try_parse() {
        Ok(args) => args,
        Err(e) if !e.use_stderr() => {
            // --help and --version: clap's own output, exit 0.
            let _ = e.print();
            return ExitCode::SUCCESS;
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
            eprintln!("csgpix: {} (see --help)", msg.trim_start_matches("error: "));
            return ExitCode::from(2);
        }
    };
    // Staged outputs are removed if the run is interrupted (crates/output).
    if let Err(e) = csgpix_output::install_signal_cleanup() {
        eprintln!("csgpix: cannot watch for signals: {e}");
        return ExitCode::from(2);
    }
    match cli::run(args) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("csgpix: {e}");
            ExitCode::from(2)
        }
    }
}
