//! `csgpix completions SHELL`: the shell's completion script for every subcommand and option,
//! generated from the same clap definition as the parser, so it cannot fall behind.

use std::process::ExitCode;

use clap::CommandFactory;
use clap_complete::Shell;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix completions bash > ~/.local/share/bash-completion/completions/csgpix\n  \
    csgpix completions zsh > ~/.zfunc/_csgpix          # a directory on $fpath\n  \
    csgpix completions fish > ~/.config/fish/completions/csgpix.fish")]
pub struct Args {
    /// The shell the script is for.
    #[arg(value_enum)]
    shell: Shell,
}

pub fn run(a: Args) -> csgpix_run::Result<ExitCode> {
    let mut cmd = super::Cli::command();
    // Into memory first: clap_complete panics on a failed write, and a closed pipe
    // (`| head`) is an error to report, not a crash.
    let mut script = Vec::new();
    clap_complete::generate(a.shell, &mut cmd, "csgpix", &mut script);
    super::common::stdout(&script)?;
    Ok(ExitCode::SUCCESS)
}
