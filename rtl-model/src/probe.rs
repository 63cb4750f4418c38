//! Waveform probes: chosen pixels' registers, flags, select code and stack, written as VCD.
//!
//! The `cycle` model samples its probes after every clock; the `word` model, which has no
//! clock, after every operation. One time unit is one clock of the thesis's 10 MHz array
//! (timescale 100 ns). Each probed pixel is a scope `px_X_Y`; the scope `array` carries the
//! stage selector position and the index of the bit being streamed.

use std::io::{self, Write};

use vcd::{IdCode, TimescaleUnit, Value};

use crate::state::{ArrayConfig, Pixel};

/// Samples of the probed pixels, in the order they were taken.
#[derive(Clone, Debug)]
pub struct Recorder {
    cfg: ArrayConfig,
    probes: Vec<(usize, usize)>,
    samples: Vec<(u64, usize, Pixel)>,
    globals: Vec<(u64, u8, u32)>,
}

/// The signals of one probed pixel, in VCD order: (name, width).
fn pixel_signals(cfg: &ArrayConfig) -> Vec<(&'static str, u32)> {
    let (nd, cb) = (cfg.fmt.bits(), cfg.colour_bits);
    vec![
        ("A", nd),
        ("F", nd),
        ("B", nd),
        ("C", nd),
        ("D", cb),
        ("E", cb),
        ("G", cb),
        ("S_hi", 1),
        ("S_lo", 1),
        ("N", 1),
        ("J", 1),
        ("T", 1),
        ("M", 1),
        ("stack", cfg.stack_depth.max(1) as u32),
    ]
}

fn pixel_values(p: &Pixel) -> Vec<u64> {
    let f = p.flags;
    let mut v: Vec<u64> = p.depth.iter().map(|d| *d as u64).collect();
    v.extend(p.colour.iter().map(|c| *c as u64));
    v.extend([p.sel.0, p.sel.1, f.n, f.j, f.t, f.m].map(u64::from));
    v.push(p.stack);
    v
}

fn bits(v: u64, width: u32) -> impl Iterator<Item = Value> {
    (0..width).rev().map(move |k| {
        if v >> k & 1 == 1 {
            Value::V1
        } else {
            Value::V0
        }
    })
}

impl Recorder {
    /// A recorder for the pixels `probes` of an array `cfg`; refuses pixels outside it.
    pub fn new(cfg: ArrayConfig, probes: Vec<(usize, usize)>) -> Result<Recorder, String> {
        if let Some(p) = probes
            .iter()
            .find(|p| p.0 >= cfg.width || p.1 >= cfg.height)
        {
            return Err(format!(
                "probe {},{} lies outside the {}x{} array",
                p.0, p.1, cfg.width, cfg.height
            ));
        }
        Ok(Recorder {
            cfg,
            probes,
            samples: vec![],
            globals: vec![],
        })
    }

    pub fn probes(&self) -> &[(usize, usize)] {
        &self.probes
    }

    /// The state of probe `i` after clock `t`.
    pub fn sample(&mut self, t: u64, i: usize, p: Pixel) {
        self.samples.push((t, i, p));
    }

    /// The stage position and bit index during clock `t`.
    pub fn global(&mut self, t: u64, position: u8, bit: u32) {
        self.globals.push((t, position, bit));
    }

    /// Write the VCD: definitions, then for each time only the signals that changed.
    pub fn write_vcd<W: Write>(&self, out: W) -> io::Result<()> {
        let mut w = vcd::Writer::new(out);
        w.timescale(100, TimescaleUnit::NS)?;
        w.comment("csgpix cycle model probes")?;
        w.add_module("array")?;
        let stage = w.add_wire(3, "stage")?;
        let bit = w.add_wire(6, "bit")?;
        w.upscope()?;
        let sigs = pixel_signals(&self.cfg);
        let mut ids: Vec<Vec<IdCode>> = vec![];
        for (x, y) in &self.probes {
            w.add_module(&format!("px_{x}_{y}"))?;
            ids.push(
                sigs.iter()
                    .map(|(n, wd)| w.add_wire(*wd, n))
                    .collect::<io::Result<_>>()?,
            );
            w.upscope()?;
        }
        w.enddefinitions()?;
        let mut events: Vec<(u64, usize, Vec<u64>)> = self
            .globals
            .iter()
            .map(|(t, s, b)| (*t, usize::MAX, vec![*s as u64, *b as u64]))
            .collect();
        events.extend(
            self.samples
                .iter()
                .map(|(t, i, p)| (*t, *i, pixel_values(p))),
        );
        events.sort_by_key(|e| (e.0, e.1));
        let mut last: Vec<Option<Vec<u64>>> = vec![None; self.probes.len() + 1];
        let mut now = None;
        for (t, who, vals) in events {
            let slot = if who == usize::MAX {
                self.probes.len()
            } else {
                who
            };
            let prev = last[slot].take();
            let (ids, widths): (Vec<IdCode>, Vec<u32>) = if who == usize::MAX {
                (vec![stage, bit], vec![3, 6])
            } else {
                (ids[who].clone(), sigs.iter().map(|s| s.1).collect())
            };
            for (j, v) in vals.iter().enumerate() {
                if prev.as_ref().is_some_and(|p| p[j] == *v) {
                    continue;
                }
                if now != Some(t) {
                    w.timestamp(t)?;
                    now = Some(t);
                }
                w.change_vector(ids[j], bits(*v, widths[j]))?;
            }
            last[slot] = Some(vals);
        }
        w.flush()
    }
}
