//! `csgpix phantom`: the project's CT-head phantom as a NRRD dataset (Figure 5.6's stand-in;
//! docs/volume-scenes.md).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::ValueEnum;
use csgpix::dataset::phantom;
use csgpix::nrrd::{write_nrrd, Encoding};

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:\n  \
    csgpix phantom -o vectors/scenes/phantom.nrrd          # the file figure-5.6.csg imports\n  \
    csgpix phantom --size 128 --encoding raw -o head.nrrd")]
pub struct Args {
    /// Samples along each axis (the phantom spans -10..10 scene units whatever the size).
    #[arg(long, default_value_t = 48, value_parser = clap::value_parser!(u16).range(1..=1024))]
    size: u16,
    /// Data encoding.
    #[arg(long, value_enum, default_value_t)]
    encoding: EncodingArg,
    /// Output NRRD file (uint16).
    #[arg(short = 'o', long)]
    out: PathBuf,
}

#[derive(ValueEnum, Clone, Copy, Debug, Default)]
enum EncodingArg {
    #[default]
    Gzip,
    Raw,
}

pub fn run(a: Args) -> Result<ExitCode, String> {
    let n = a.size as usize;
    let encoding = match a.encoding {
        EncodingArg::Gzip => Encoding::Gzip,
        EncodingArg::Raw => Encoding::Raw,
    };
    let comment = format!(
        "csgpix phantom --size {n}: CT-head phantom after Figure 5.6 (skull 1000, tissue 400, \
         ventricles 100, dense sphere 1200)"
    );
    write_nrrd(&a.out, &phantom(n), encoding, &comment)?;
    println!("wrote {} ({n}x{n}x{n} uint16)", a.out.display());
    Ok(ExitCode::SUCCESS)
}
