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
    pub fn new(cfg: ArrayConfig, probes: Vec<(usize, usize)>) -> Result<Recorder, ProbeOutside> {
        if let Some(&probe) = probes
            .iter()
            .find(|p| p.0 >= cfg.width || p.1 >= cfg.height)
        {
            return Err(ProbeOutside {
                probe,
                width: cfg.width,
                height: cfg.height,
            });
        }
        Ok(Recorder {
            cfg,
            probes,
            samples: vec![],
            globals: vec![],
        })
    }

    /// The probed pixels, (x, y), in probe index order.
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

/// One row of the SVG timing diagram: its label, bit width and (time, value) changes.
struct Trace {
    name: String,
    width: u32,
    changes: Vec<(u64, u64)>,
}

impl Recorder {
    fn traces(&self, probe: usize) -> Vec<Trace> {
        let sigs = pixel_signals(&self.cfg);
        let mut rows: Vec<Trace> = [("stage", 3u32), ("bit", 6)]
            .iter()
            .map(|(n, w)| Trace {
                name: n.to_string(),
                width: *w,
                changes: vec![],
            })
            .chain(sigs.iter().map(|(n, w)| Trace {
                name: n.to_string(),
                width: *w,
                changes: vec![],
            }))
            .collect();
        let push = |t: &mut Trace, at: u64, v: u64| {
            if t.changes.last().is_none_or(|l| l.1 != v) {
                t.changes.push((at, v));
            }
        };
        for (t, s, b) in &self.globals {
            push(&mut rows[0], *t, *s as u64);
            push(&mut rows[1], *t, *b as u64);
        }
        for (t, _, p) in self.samples.iter().filter(|s| s.1 == probe) {
            for (j, v) in pixel_values(p).into_iter().enumerate() {
                push(&mut rows[2 + j], *t, v);
            }
        }
        rows
    }

    /// A timing diagram of probe `probe` over clocks `t0..=t1` as SVG: one row per signal,
    /// one-bit signals as waves, wider ones as buses labelled where there is room.
    pub fn write_svg<W: Write>(
        &self,
        mut out: W,
        probe: usize,
        t0: u64,
        t1: u64,
    ) -> io::Result<()> {
        let (label, px, row_h) = (70.0, 10.0, 26.0);
        let rows = self.traces(probe);
        let width = label + (t1 - t0 + 1) as f64 * px + 10.0;
        let height = rows.len() as f64 * row_h + 44.0;
        let x = |t: u64| label + (t.clamp(t0, t1 + 1) - t0) as f64 * px;
        let (xp, yp) = self.probes.get(probe).copied().unwrap_or((0, 0));
        writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height:.0}\" \
             font-family=\"monospace\" font-size=\"10\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n\
             <text x=\"4\" y=\"14\">pixel ({xp},{yp}), clocks {t0}..{t1}</text>"
        )?;
        for t in (t0..=t1).filter(|t| t % 8 == 0) {
            writeln!(
                out,
                "<line x1=\"{0:.1}\" y1=\"20\" x2=\"{0:.1}\" y2=\"{1:.0}\" stroke=\"#eee\"/>",
                x(t),
                height - 14.0
            )?;
            if t % 32 == 0 {
                let (tx, ty) = (x(t) - 4.0, height - 3.0);
                writeln!(out, "<text x=\"{tx:.1}\" y=\"{ty:.0}\">{t}</text>")?;
            }
        }
        for (i, r) in rows.iter().enumerate() {
            let (top, bot) = (
                24.0 + i as f64 * row_h,
                24.0 + i as f64 * row_h + row_h - 8.0,
            );
            writeln!(
                out,
                "<text x=\"4\" y=\"{:.1}\">{}</text>",
                bot - 4.0,
                r.name
            )?;
            let spans: Vec<(u64, u64, u64)> = r
                .changes
                .iter()
                .enumerate()
                .map(|(k, (t, v))| (*t, r.changes.get(k + 1).map_or(t1 + 1, |n| n.0), *v))
                .filter(|(a, b, _)| *b > t0 && *a <= t1)
                .collect();
            for (a, b, v) in spans {
                let (xa, xb) = (x(a), x(b));
                if r.width == 1 {
                    let y = if v == 1 { top } else { bot };
                    writeln!(out, "<line x1=\"{xa:.1}\" y1=\"{y}\" x2=\"{xb:.1}\" y2=\"{y}\" stroke=\"#06c\"/>")?;
                    writeln!(out, "<line x1=\"{xa:.1}\" y1=\"{top}\" x2=\"{xa:.1}\" y2=\"{bot}\" stroke=\"#06c\" stroke-width=\"0.3\"/>")?;
                } else {
                    writeln!(
                        out,
                        "<rect x=\"{xa:.1}\" y=\"{top}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"#f4f8ff\" stroke=\"#06c\" stroke-width=\"0.6\"/>",
                        xb - xa,
                        bot - top
                    )?;
                    let text = self.show(&r.name, v);
                    if (xb - xa) > 7.0 * text.len() as f64 {
                        writeln!(
                            out,
                            "<text x=\"{:.1}\" y=\"{:.1}\">{text}</text>",
                            xa + 2.0,
                            bot - 5.0
                        )?;
                    }
                }
            }
        }
        writeln!(out, "</svg>")
    }

    /// A value as a reader wants it: depth registers in depth units, others in decimal.
    fn show(&self, name: &str, v: u64) -> String {
        let fmt = self.cfg.fmt;
        if !["A", "F", "B", "C"].contains(&name) {
            return v.to_string();
        }
        let raw = fmt.wrap(v as i64);
        if raw == fmt.max_word() {
            "max".into()
        } else {
            format!("{:.2}", fmt.to_real(raw))
        }
    }
}

/// A probe on a pixel outside the array ([`Recorder::new`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ProbeOutside {
    /// The pixel, (x, y).
    pub probe: (usize, usize),
    /// The array's width.
    pub width: usize,
    /// The array's height.
    pub height: usize,
}

impl std::fmt::Display for ProbeOutside {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (x, y) = self.probe;
        write!(
            f,
            "probe {x},{y} lies outside the {}x{} array",
            self.width, self.height
        )
    }
}

impl std::error::Error for ProbeOutside {}
