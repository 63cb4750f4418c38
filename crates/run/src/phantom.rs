//! `csgpix phantom`: the project's CT-head phantom as a NRRD dataset (Figure 5.6's stand-in;
//! docs/volume-scenes.md).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::ValueEnum;
use csgpix_output::Outputs;
use csgpix_scene::dataset::phantom;
use csgpix_scene::nrrd::{nrrd_bytes, Encoding, Endian};

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
    /// Output NRRD file (uint16; `-`: standard output).
    #[arg(short = 'o', long)]
    out: PathBuf,
    #[command(flatten)]
    mem: super::memory::MaxMemory,
}

/// An upper bound of the phantom's memory (docs/memory.md): the samples (f32, 4 bytes each),
/// the uint16 data (2 each), the file's bytes (2 each: header and data joined, or gzip's
/// output), a spare 2 for the encoder, the process.
fn memory_estimate(n: u64) -> u64 {
    n.pow(3) * (4 + 2 + 2 + 2) + (16 << 20)
}

#[derive(ValueEnum, Clone, Copy, Debug, Default)]
enum EncodingArg {
    #[default]
    Gzip,
    Raw,
}

pub fn run(a: Args) -> crate::Result<ExitCode> {
    let mut outs = Outputs::new();
    let out = outs.file_or_stdout("-o", &a.out, &["nrrd"])?;
    let n = a.size as usize;
    a.mem
        .check(memory_estimate(n as u64), "this phantom", "lower --size")?;
    let encoding = match a.encoding {
        EncodingArg::Gzip => Encoding::Gzip,
        EncodingArg::Raw => Encoding::Raw,
    };
    let comment = format!(
        "csgpix phantom --size {n}: CT-head phantom after Figure 5.6 (skull 1000, tissue 400, \
         ventricles 100, dense sphere 1200)"
    );
    let bytes = nrrd_bytes(&phantom(n), encoding, Endian::Little, &comment)?;
    outs.write(out, |w| w.write_all(&bytes))?;
    let to_stderr = outs.uses_stdout();
    outs.commit()?;
    let line = format!("wrote {} ({n}x{n}x{n} uint16)", a.out.display());
    super::report_line(&line, to_stderr);
    Ok(ExitCode::SUCCESS)
}
