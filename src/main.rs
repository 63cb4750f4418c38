//! The `csgpix` command line: a thin layer over the `csgpix` and `rtl-model` libraries.

mod cli;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let args = cli::Cli::parse();
    match cli::run(args) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("csgpix: {e}");
            ExitCode::from(2)
        }
    }
}
