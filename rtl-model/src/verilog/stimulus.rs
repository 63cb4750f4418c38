//! What `tb_array` runs and what it must see (docs/verilog.md, "Running tb_array from the
//! CLI"): the Verilog files it is built from for an array configuration ([`array_files`]), the
//! expected state of every pixel after every clock, taken from the `cycle` model clock by clock
//! ([`expected_states`], through [`CycleArray::observe`]), and a script that builds and runs
//! it ([`run_script`]). The stimulus itself is [`super::pixel::control_stream`]. A testbench
//! that follows the cycle model itself (the Python package's `ArrayModel`) takes a pixel's
//! `state` word from [`state_bits`] and the comparator's counter from [`BitCounter`].

use std::cell::RefCell;
use std::io::Write;
use std::rc::Rc;

use super::hex;
use super::pixel::{self, state_fields, state_width};
use crate::array::{check_program, Array};
use crate::cycle::{Clock, Internal};
use crate::program::{CReg, Op, ProgramError};
use crate::select::{EquationSet, Equations};
use crate::state::{ArchState, ArrayConfig, Pixel};
use crate::CycleArray;

/// Build and run `tb_array` under Icarus Verilog, in the directory of the files.
pub const ICARUS: &str =
    "iverilog -g2005 -o tb_array.vvp -f pixel_array.f tb_array.v && vvp -n tb_array.vvp";

/// Build and run `tb_array` under Verilator, in the directory of the files (Verilator's
/// default warnings: none from these files).
pub const VERILATOR: &str = "verilator --binary --timing -j 2 --top-module tb_array \
    -f pixel_array.f tb_array.v && obj_dir/Vtb_array";

/// The files `tb_array` is built from for `cfg`, `(name, text)`: the synthesizable modules
/// with the derived SGENE (`pixel_array.f` lists them, leaves first), the testbench and the
/// filelist. For the 16×16 thesis array they are the checked-in files.
pub fn array_files(cfg: &ArrayConfig) -> Vec<(String, String)> {
    let set = Equations::Derived.set();
    [
        ("sgene_derived.v", super::sgene::module(&set)),
        ("comparator.v", super::comparator::module(&cfg.fmt)),
        ("depgen.v", super::depgen::module()),
        ("pixel.v", pixel::pixel_module(cfg, &set)),
        ("pixel_array.v", pixel::array_module(cfg)),
        ("tb_array.v", pixel::testbench(cfg)),
        ("pixel_array.f", super::filelist()),
    ]
    .into_iter()
    .map(|(n, t)| (n.to_string(), t))
    .collect()
}

/// Build and run `tb_machine` (the controller reading `program.hex`) under Icarus Verilog.
pub const MACHINE_ICARUS: &str =
    "iverilog -g2005 -o tb_machine.vvp -f machine.f tb_machine.v && vvp -n tb_machine.vvp";

/// Build and run `tb_machine` under Verilator.
pub const MACHINE_VERILATOR: &str = "verilator --binary --timing -j 2 -Wno-WIDTH \
    --top-module tb_machine -f machine.f tb_machine.v && obj_dir/Vtb_machine";

/// What `tb_machine` needs beside [`array_files`] for `ops` on `cfg`: the controller, the
/// machine (its program memory as large as the program needs), the testbench, the filelist
/// and the memory image `program.hex`.
pub fn machine_files(
    cfg: &ArrayConfig,
    ops: &[Op],
) -> Result<Vec<(String, String)>, super::controller::RecordError> {
    use super::controller as c;
    let aw = c::addr_bits(ops.len());
    Ok([
        ("controller.v", c::module(cfg)),
        ("machine.v", c::machine_module(cfg, aw)),
        ("tb_machine.v", c::testbench(cfg, aw)),
        ("machine.f", c::filelist()),
        ("program.hex", c::program_hex(cfg, ops)?),
    ]
    .into_iter()
    .map(|(n, t)| (n.to_string(), t))
    .collect())
}

/// The most clocks a control stream may have: `tb_array` holds 2^20 words, the idle clock
/// that carries `last` included.
pub const MAX_CYCLES: u64 = (1 << pixel::MAX_CLOCKS_LOG2) - 1;

/// Bytes of one line of the expected-state file: a pixel's `state` in hex and a newline.
pub fn line_bytes(cfg: &ArrayConfig) -> u64 {
    state_width(cfg).div_ceil(4) as u64 + 1
}

/// Bytes of the expected-state file of a program of `cycles` clocks: one line per pixel for
/// every clock and for the idle clock after them.
pub fn expected_bytes(cfg: &ArrayConfig, cycles: u64) -> u64 {
    (cycles + 1)
        .saturating_mul(cfg.pixels() as u64)
        .saturating_mul(line_bytes(cfg))
}

/// What tb_array must see: every pixel's `state` after every clock, from the cycle model.
/// `T` holds the expected-state text: a `String` ([`expected_states`]), or the sink it was
/// written to ([`write_expected_states`]).
pub struct Expected<T = String> {
    /// One hex line per pixel (row-major) per clock, clocks 1 ..= cycles + 1 (the idle clock
    /// that carries `last` changes nothing).
    pub text: T,
    /// The clock each operation ends with.
    pub ends: Vec<u64>,
    /// Clocks of the whole program, flush window included.
    pub cycles: u64,
    /// The architectural state after the program (its G registers are the image).
    pub last: ArchState,
}

/// Why the expected states could not be written.
#[derive(Debug)]
pub enum StatesError {
    /// The program does not run on the array.
    Program(ProgramError),
    /// The sink refused a write.
    Io(std::io::Error),
}

impl From<ProgramError> for StatesError {
    fn from(e: ProgramError) -> Self {
        StatesError::Program(e)
    }
}

impl<T> Expected<T> {
    /// The line `tb_array` prints when every register matched: the program's clocks and the
    /// idle one, its operations and the flush window when there is one.
    pub fn summary(&self) -> String {
        let flush = self.ends.last().is_some_and(|&e| self.cycles > e) as usize;
        format!(
            "CLOCKS {} OPS {} MISMATCHES 0",
            self.cycles + 1,
            self.ends.len() + flush
        )
    }

    /// The colour code (G) of every pixel after the program, row-major: the image.
    pub fn image(&self) -> Vec<u32> {
        self.last.pixels.iter().map(|p| p.creg(CReg::G)).collect()
    }
}

/// A pixel's `state` word (fields of [`state_fields`], LSB first) from the cycle model's
/// registers, as bits, LSB first: bit i is bit i of the Verilog `pixel`'s `state` port. `k`
/// is the comparator's bit counter (bits taken of the current word, [`BitCounter`]). The
/// Verilog registers circulate (bit k of the word at bit 0 in clock k), so after clock `bit`
/// of a window they hold the model's word rotated right by `bit + 1` (colour registers: by
/// the colour bits moved so far); `bit` is `None` outside windows ([`Clock::bit`]).
pub fn state_bits(
    cfg: &ArrayConfig,
    p: &Pixel,
    i: &Internal,
    k: u64,
    bit: Option<u32>,
) -> Vec<bool> {
    let mut bits: Vec<bool> = vec![];
    for (name, w) in state_fields(cfg) {
        let v = field_value(cfg, Field::of(name), p, i, k, bit);
        bits.extend((0..w).map(|b| b < 64 && v >> b & 1 == 1));
    }
    bits
}

/// A field of `state` ([`state_fields`]) by the cycle-model register it reads, resolved from
/// its name once rather than at every pixel.
#[derive(Clone, Copy, Debug)]
enum Field {
    /// A depth register: A, F, B, C (§2.3).
    Depth(usize),
    /// A colour register: D, E, G.
    Colour(usize),
    SHi,
    SLo,
    N,
    J,
    T,
    M,
    Lt,
    Eq,
    Ovf,
    Sign,
    K,
    Carry,
    Stack,
}

impl Field {
    fn of(name: &str) -> Field {
        if let Some(r) = ["A", "F", "B", "C"].iter().position(|r| *r == name) {
            return Field::Depth(r);
        }
        if let Some(r) = ["D", "E", "G"].iter().position(|r| *r == name) {
            return Field::Colour(r);
        }
        match name {
            "S_hi" => Field::SHi,
            "S_lo" => Field::SLo,
            "N" => Field::N,
            "J" => Field::J,
            "T" => Field::T,
            "M" => Field::M,
            "lt" => Field::Lt,
            "eq" => Field::Eq,
            "ovf" => Field::Ovf,
            "sign" => Field::Sign,
            "k" => Field::K,
            "carry" => Field::Carry,
            "stack" => Field::Stack,
            other => panic!("state field {other} has no cycle-model register"),
        }
    }
}

/// The value of `state` field `f` ([`state_fields`]) for [`state_bits`].
fn field_value(
    cfg: &ArrayConfig,
    f: Field,
    p: &Pixel,
    i: &Internal,
    k: u64,
    bit: Option<u32>,
) -> u64 {
    let (nd, cb) = (cfg.fmt.bits() as usize, cfg.colour_bits as usize);
    let moved = bit.map_or(0, |b| b as usize + 1);
    match f {
        Field::Depth(r) => rotate(p.depth[r] as u64, nd, moved),
        Field::Colour(r) => rotate(p.colour[r] as u64, cb, moved.min(cb)),
        Field::SHi => p.sel.0 as u64,
        Field::SLo => p.sel.1 as u64,
        Field::N => p.flags.n as u64,
        Field::J => p.flags.j as u64,
        Field::T => p.flags.t as u64,
        Field::M => p.flags.m as u64,
        Field::Lt => i.lt as u64,
        Field::Eq => i.eq as u64,
        Field::Ovf => i.ovf as u64,
        Field::Sign => i.sign as u64,
        Field::K => k,
        Field::Carry => i.carry as u64,
        Field::Stack => p.stack,
    }
}

/// Lines of the expected-state file written straight from the fields' values, without
/// [`state_bits`]'s vector of bools and [`state_hex`]'s string per pixel: the same digits
/// (`hex_lines_are_state_hex` checks it clock by clock).
struct HexLines {
    fields: Vec<(Field, usize)>,
    words: Vec<u64>,
    digits: usize,
}

impl HexLines {
    fn new(cfg: &ArrayConfig) -> HexLines {
        let fields: Vec<(Field, usize)> = state_fields(cfg)
            .into_iter()
            .map(|(name, w)| (Field::of(name), w))
            .collect();
        let width: usize = fields.iter().map(|f| f.1).sum();
        HexLines {
            fields,
            words: vec![0; width / 64 + 2],
            digits: width.div_ceil(4),
        }
    }

    /// Append pixel `p`'s line (digits and a newline) to `out`.
    fn push(
        &mut self,
        cfg: &ArrayConfig,
        px: (&Pixel, &Internal),
        k: u64,
        bit: Option<u32>,
        out: &mut String,
    ) {
        self.words.fill(0);
        let mut at = 0;
        for &(f, w) in &self.fields {
            let v = field_value(cfg, f, px.0, px.1, k, bit);
            // Bits past 64 of a wider field are 0, as in `state_bits`.
            let v = if w >= 64 { v } else { v & ((1u64 << w) - 1) };
            let (q, r) = (at / 64, at % 64);
            self.words[q] |= v << r;
            if r != 0 && r + w.min(64) > 64 {
                self.words[q + 1] |= v >> (64 - r);
            }
            at += w;
        }
        for d in (0..self.digits).rev() {
            let nibble = (self.words[d * 4 / 64] >> (d * 4 % 64)) & 0xF;
            out.push(char::from_digit(nibble as u32, 16).expect("a nibble"));
        }
        out.push('\n');
    }
}

/// [`state_bits`] in hex, most significant digit first: a line of the expected-state file.
pub fn state_hex(cfg: &ArrayConfig, p: &Pixel, i: &Internal, k: u64, bit: Option<u32>) -> String {
    hex(&state_bits(cfg, p, i, k, bit))
}

/// The comparator's bit counter, the `k` field of `state`, followed clock by clock from
/// reset: it moves only in clocks where the comparator takes a bit, to the bits taken of the
/// current word, modulo the next power of two of N_D (5 bits for the thesis word).
#[derive(Clone, Copy, Debug)]
pub struct BitCounter {
    k: u64,
    modulo: u64,
}

impl BitCounter {
    /// The counter after reset (0) of a `cfg` array.
    pub fn new(cfg: &ArrayConfig) -> BitCounter {
        BitCounter {
            k: 0,
            modulo: cfg.fmt.bits().next_power_of_two() as u64,
        }
    }

    /// Take clock `c` ([`CycleArray::observe`]) and return the counter after it.
    pub fn clock(&mut self, c: &Clock) -> u64 {
        if c.compared {
            self.k = (c.bit.expect("a compared clock has a bit") as u64 + 1) % self.modulo;
        }
        self.k
    }

    /// The counter now.
    pub fn k(&self) -> u64 {
        self.k
    }
}

/// The low `w` bits of `v` rotated right by `moved` (modulo `w`).
fn rotate(v: u64, w: usize, moved: usize) -> u64 {
    let r = moved % w;
    let mask = if w == 64 { !0 } else { (1u64 << w) - 1 };
    let v = v & mask;
    if r == 0 {
        v
    } else {
        (v >> r | v << (w - r)) & mask
    }
}

/// Every pixel's `state` line, row-major, into `text` (emptied first).
fn clock_lines(
    lines: &mut HexLines,
    cfg: &ArrayConfig,
    a: &CycleArray,
    (k, bit): (u64, Option<u32>),
    text: &mut String,
) {
    text.clear();
    for y in 0..cfg.height {
        for x in 0..cfg.width {
            let px = (&a.gather(x, y), &a.internal(x, y));
            lines.push(cfg, px, k, bit, text);
        }
    }
}

/// The sink of [`write_expected_states`] as its observer holds it: the comparator's bit
/// counter, one clock's lines, and the first write that failed (nothing is written after it).
struct Sink<W> {
    out: W,
    counter: BitCounter,
    hex: HexLines,
    lines: String,
    failed: Option<std::io::Error>,
}

impl<W: Write> Sink<W> {
    fn clock(&mut self, cfg: &ArrayConfig, a: &CycleArray, k: u64, bit: Option<u32>) {
        if self.failed.is_none() {
            clock_lines(&mut self.hex, cfg, a, (k, bit), &mut self.lines);
            self.failed = self.out.write_all(self.lines.as_bytes()).err();
        }
    }
}

/// Run `ops` on the cycle model with equations `set`, clock by clock
/// ([`CycleArray::observe`]), and write down every register of every pixel after every clock
/// and after the idle clock that follows. The text is [`expected_bytes`] long: check that
/// first.
pub fn expected_states(
    cfg: ArrayConfig,
    ops: &[Op],
    set: &EquationSet,
) -> Result<Expected, ProgramError> {
    match write_expected_states(cfg, ops, set, Vec::new()) {
        Ok(e) => Ok(Expected {
            text: String::from_utf8(e.text).expect("hex lines are ASCII"),
            ends: e.ends,
            cycles: e.cycles,
            last: e.last,
        }),
        Err(StatesError::Program(e)) => Err(e),
        Err(StatesError::Io(e)) => unreachable!("a Vec takes every write: {e}"),
    }
}

/// [`expected_states`] written to `out` a clock at a time as the model runs (one clock's
/// lines held, not the file's), returned with the run. A file of [`expected_bytes`] this way
/// costs memory for one clock only.
pub fn write_expected_states<W: Write + 'static>(
    cfg: ArrayConfig,
    ops: &[Op],
    set: &EquationSet,
    out: W,
) -> Result<Expected<W>, StatesError> {
    check_program(ops, cfg.stack_depth)?;
    let mut arr = CycleArray::new(cfg, set.clone());
    let sink = Rc::new(RefCell::new(Sink {
        out,
        counter: BitCounter::new(&cfg),
        hex: HexLines::new(&cfg),
        lines: String::new(),
        failed: None,
    }));
    let seen = Rc::clone(&sink);
    let mut next = 1;
    arr.observe(Box::new(move |a: &CycleArray, c: Clock| {
        assert_eq!(c.t, next, "the observer sees every clock once, in order");
        next += 1;
        let mut s = seen.borrow_mut();
        let k = s.counter.clock(&c);
        s.clock(&cfg, a, k, c.bit);
    }));
    let mut ends = vec![];
    for op in ops {
        arr.step(op)?;
        ends.push(arr.cycles());
    }
    arr.finish();
    let k = sink.borrow().counter.k();
    sink.borrow_mut().clock(&cfg, &arr, k, None);
    let (cycles, last) = (arr.cycles(), arr.state());
    drop(arr);
    let sink = Rc::try_unwrap(sink)
        .ok()
        .expect("the array and its observer are gone")
        .into_inner();
    match sink.failed {
        Some(e) => Err(StatesError::Io(e)),
        None => Ok(Expected {
            text: sink.out,
            ends,
            cycles,
            last,
        }),
    }
}

/// `run.sh`: build and run `tb_array` in the script's directory under Icarus (`sh run.sh`)
/// or Verilator (`sh run.sh verilator`), the output also in `tb_array.log`; exit 0 only when
/// the testbench prints `summary` ([`Expected::summary`]).
pub fn run_script(summary: &str) -> String {
    format!(
        "#!/bin/sh
# Run tb_array on control.hex and expected.hex in this directory (csgpix export-verilog
# --scene): sh run.sh [icarus|verilator]. Exit 0 only when it prints:
# {summary}
set -e
cd \"$(dirname \"$0\")\"
want='{summary}'
case \"${{1:-icarus}}\" in
    icarus) ( {ICARUS} ) | tee tb_array.log ;;
    verilator) ( {VERILATOR} ) | tee tb_array.log ;;
    *) echo \"usage: sh run.sh [icarus|verilator]\" >&2; exit 2 ;;
esac
if grep -qx \"$want\" tb_array.log; then
    echo \"PASS: $want\"
else
    echo \"FAIL: expected $want\" >&2
    exit 1
fi
"
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::array::program_cycles;
    use crate::fixtures::program;

    /// The size `export-verilog --scene` bounds before simulating is the file's to the byte,
    /// a line per pixel per clock and for the idle clock; the stream has as many words; the
    /// summary counts the flush window that carries out Compose's code.
    #[test]
    fn expected_bytes_is_the_length_of_the_expected_states() {
        let cfg = ArrayConfig::new(5, 3);
        let (ops, set) = (program(), Equations::Derived.set());
        let e = expected_states(cfg, &ops, &set).unwrap();
        let cycles = program_cycles(&cfg, &ops);
        assert_eq!(e.cycles, cycles);
        assert_eq!(e.text.len() as u64, expected_bytes(&cfg, cycles));
        assert_eq!(e.text.lines().count() as u64, (cycles + 1) * 15);
        let stream = pixel::control_stream(&cfg, &set, &ops);
        assert_eq!(stream.lines().count() as u64, cycles + 1);
        let want = format!("CLOCKS {} OPS {} MISMATCHES 0", cycles + 1, ops.len() + 1);
        assert_eq!(e.summary(), want);
        assert!(run_script(&want).contains(&format!("want='{want}'")));
    }

    /// The expected-state lines are [`state_hex`]'s, pixel by pixel, after every clock of
    /// a program, on arrays whose `state` words straddle 64-bit boundaries differently (the
    /// thesis word, a short one, a deep stack).
    #[test]
    fn hex_lines_are_state_hex() {
        let shapes = [
            (5, 3, None, None),
            (
                4,
                2,
                Some(crate::WordFormat::new(3, 4, 2).unwrap()),
                Some(9),
            ),
        ];
        for (w, h, fmt, stack) in shapes {
            let mut cfg = ArrayConfig::new(w, h);
            if let Some(fmt) = fmt {
                cfg.fmt = fmt;
                cfg.colour_bits = cfg.colour_bits.min(fmt.bits());
            }
            if let Some(depth) = stack {
                cfg.stack_depth = depth;
            }
            let (ops, set) = (program(), Equations::Derived.set());
            let mut arr = CycleArray::new(cfg, set);
            let seen = Rc::new(RefCell::new((
                0usize,
                BitCounter::new(&cfg),
                HexLines::new(&cfg),
            )));
            let check = Rc::clone(&seen);
            arr.observe(Box::new(move |a: &CycleArray, c: Clock| {
                let mut s = check.borrow_mut();
                let k = s.1.clock(&c);
                let mut fast = String::new();
                clock_lines(&mut s.2, &cfg, a, (k, c.bit), &mut fast);
                let mut slow = String::new();
                for y in 0..cfg.height {
                    for x in 0..cfg.width {
                        slow += &state_hex(&cfg, &a.gather(x, y), &a.internal(x, y), k, c.bit);
                        slow.push('\n');
                    }
                }
                assert_eq!(fast, slow, "clock {}", c.t);
                s.0 += 1;
            }));
            for op in &ops {
                arr.step(op).unwrap();
            }
            arr.finish();
            assert!(seen.borrow().0 > 50, "{} clocks checked", seen.borrow().0);
        }
    }

    /// `pixel_array` takes every control field but the testbench's bookkeeping and `is_ovf`:
    /// the broadcast ports but `rst`, and DEPGEN's four root inputs.
    #[test]
    fn array_inputs_are_the_ports_of_pixel_array() {
        let inputs = pixel::array_inputs();
        assert_eq!(inputs.len(), pixel::FIELDS.len() - 3);
        let text = pixel::array_module(&ArrayConfig::new(4, 4));
        for n in &inputs {
            let decl = [format!(" {n},"), format!("] {n},"), format!(" {n}, ")];
            assert!(decl.iter().any(|d| text.contains(d.as_str())), "{n}");
        }
        for n in ["last", "op_end", "is_ovf"] {
            assert!(!inputs.contains(&n));
        }
    }
}
