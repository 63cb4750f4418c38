//! `csgpix man`: the manual page (roff, section 1) of the command and its subcommands, from
//! the same clap definition as the parser and `--help`, so it cannot fall behind.

use std::process::ExitCode;

use clap::CommandFactory;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix man | man -l -\n  \
    csgpix man > ~/.local/share/man/man1/csgpix.1")]
pub struct Args {}

pub fn run(_: Args) -> csgpix_run::Result<ExitCode> {
    let mut page = Vec::new();
    clap_mangen::Man::new(super::Cli::command())
        .render(&mut page)
        .map_err(|source| csgpix_run::Error::Io {
            path: "man page".into(),
            source,
        })?;
    super::common::stdout(&page)?;
    Ok(ExitCode::SUCCESS)
}
