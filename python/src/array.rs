//! The array's models stepped from Python (seed 001 Ch. 2): `ArrayModel` runs a compiled
//! `Program` on the `cycle` or `word` model one operation at a time and shows its registers;
//! on the `cycle` model it also gives, clock by clock, every pixel's `state` word as the
//! Verilog `pixel` has it (`rtl_model::verilog::stimulus::state_bits`), with the control
//! stream that drives `pixel_array` (`pixel::control_stream`) and the Verilog sources
//! (`verilog_files`): the reference model of a cocotb testbench (python/tests/cocotb).

use std::cell::RefCell;
use std::rc::Rc;

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyInt};

use rtl_model::array::check_program;
use rtl_model::cycle::Clock;
use rtl_model::program::{translate, CReg, Op};
use rtl_model::verilog::pixel::{self, control_stream, state_fields};
use rtl_model::verilog::stimulus::{array_files, state_bits, BitCounter};
use rtl_model::{Array, ArrayConfig, CycleArray, EquationSet, WordArray};

use crate::draw::{equation_set, Program};
use crate::errors::text;

/// Module registration: `ArrayModel` and `verilog_files`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ArrayModel>()?;
    m.add_function(wrap_pyfunction!(verilog_files, m)?)?;
    Ok(())
}

/// What the cycle model's observer keeps: the comparator's bit counter, followed every clock,
/// and while `on` every pixel's `state` word after every clock (little-endian bytes,
/// row-major).
struct Tape {
    counter: BitCounter,
    on: bool,
    clocks: Vec<Vec<Vec<u8>>>,
}

/// Bits, LSB first, as little-endian bytes.
fn le_bytes(bits: &[bool]) -> Vec<u8> {
    bits.chunks(8)
        .map(|c| {
            c.iter()
                .enumerate()
                .fold(0u8, |a, (i, &b)| a | (b as u8) << i)
        })
        .collect()
}

/// Every pixel's `state` word, row-major, as little-endian bytes.
fn array_words(cfg: &ArrayConfig, a: &CycleArray, k: u64, bit: Option<u32>) -> Vec<Vec<u8>> {
    (0..cfg.pixels())
        .map(|i| {
            let (x, y) = (i % cfg.width, i / cfg.width);
            le_bytes(&state_bits(cfg, &a.gather(x, y), &a.internal(x, y), k, bit))
        })
        .collect()
}

/// Little-endian bytes as a Python int.
fn py_int<'py>(py: Python<'py>, b: &[u8]) -> PyResult<Bound<'py, PyAny>> {
    py.get_type::<PyInt>()
        .call_method1("from_bytes", (PyBytes::new(py, b), "little"))
}

/// One of the two models.
enum Model {
    Cycle(Box<CycleArray>),
    Word(Box<WordArray>),
}

impl Model {
    fn array(&self) -> &dyn Array {
        match self {
            Model::Cycle(a) => a.as_ref(),
            Model::Word(a) => a.as_ref(),
        }
    }

    fn array_mut(&mut self) -> &mut dyn Array {
        match self {
            Model::Cycle(a) => a.as_mut(),
            Model::Word(a) => a.as_mut(),
        }
    }
}

/// A compiled program on one of the array's models, stepped from Python.
///
/// `ArrayModel(program, model="cycle", equations="derived", *, origin=(0, 0))`: the array of
/// the program's configuration after reset; `origin` moves the program so that the array's
/// pixel (0, 0) shows screen pixel (x0, y0) (`program::translate`, as `csgpix export-verilog
/// --origin` does), refused where a plane would leave the depth word on that window.
#[pyclass(module = "csgpix._native", unsendable)]
pub struct ArrayModel {
    ops: Vec<Op>,
    cfg: ArrayConfig,
    set: EquationSet,
    arr: Model,
    /// The cycle model's observer's record.
    tape: Option<Rc<RefCell<Tape>>>,
    next: usize,
    finished: bool,
}

impl ArrayModel {
    fn tape(&self, what: &str) -> PyResult<&Rc<RefCell<Tape>>> {
        self.tape.as_ref().ok_or_else(|| {
            text(format!(
                "{what}: the word model has no clocks; use ArrayModel(program, model=\"cycle\")"
            ))
        })
    }

    fn step_op(&mut self) -> PyResult<u64> {
        if self.finished {
            return Err(text(
                "step: the program is finished (flush window run)".into(),
            ));
        }
        let Some(op) = self.ops.get(self.next) else {
            return Err(text(format!(
                "step: all {} operations done; finish() runs the flush window",
                self.ops.len()
            )));
        };
        let before = self.arr.array().cycles();
        self.arr
            .array_mut()
            .step(op)
            .map_err(|e| text(e.to_string()))?;
        self.next += 1;
        Ok(self.arr.array().cycles() - before)
    }

    fn finish_op(&mut self) -> PyResult<u64> {
        if self.next < self.ops.len() {
            return Err(text(format!(
                "finish: {} of {} operations left; step() or run() them first",
                self.ops.len() - self.next,
                self.ops.len()
            )));
        }
        if self.finished {
            return Ok(0);
        }
        let before = self.arr.array().cycles();
        self.arr.array_mut().finish();
        self.finished = true;
        Ok(self.arr.array().cycles() - before)
    }

    /// Run `f` with the observer recording, and hand back the states of the clocks it took.
    fn recorded<'py>(
        &mut self,
        py: Python<'py>,
        what: &str,
        f: fn(&mut Self) -> PyResult<u64>,
    ) -> PyResult<Vec<Vec<Bound<'py, PyAny>>>> {
        let tape = Rc::clone(self.tape(what)?);
        tape.borrow_mut().on = true;
        let r = f(self);
        let clocks = {
            let mut t = tape.borrow_mut();
            t.on = false;
            std::mem::take(&mut t.clocks)
        };
        r?;
        clocks
            .iter()
            .map(|c| c.iter().map(|b| py_int(py, b)).collect())
            .collect()
    }
}

/// The program's operations moved to the window at `origin`, each plane checked to stay in
/// the depth word on the whole window (DEPGEN's adders would wrap).
fn windowed(program: &Program, (x0, y0): (usize, usize)) -> PyResult<Vec<Op>> {
    let mut ops = program.ops.clone();
    if (x0, y0) == (0, 0) {
        return Ok(ops);
    }
    translate(&mut ops, x0, y0);
    let (cfg, fmt) = (&program.cfg, &program.cfg.fmt);
    let (xm, ym) = (cfg.width as i128 - 1, cfg.height as i128 - 1);
    for (i, op) in ops.iter().enumerate() {
        if let Op::Plane { coeffs: c, .. } | Op::ClipPlane { coeffs: c, .. } = op {
            for (x, y) in [(0, 0), (xm, 0), (0, ym), (xm, ym)] {
                let v = c.c0 as i128 + x * c.dx as i128 + y * c.dy as i128;
                if v < fmt.min_word() as i128 || v > fmt.max_word() as i128 {
                    return Err(text(format!(
                        "origin {x0},{y0}: operation {i}'s plane is {} at screen pixel ({}, {}), \
                         outside the depth word ({} .. {}): DEPGEN would wrap",
                        fmt.to_real(v as i64),
                        x0 as i128 + x,
                        y0 as i128 + y,
                        fmt.to_real(fmt.min_word()),
                        fmt.to_real(fmt.max_word()),
                    )));
                }
            }
        }
    }
    Ok(ops)
}

#[pymethods]
impl ArrayModel {
    #[new]
    #[pyo3(signature = (program, model="cycle", equations="derived", *, origin=(0, 0)))]
    fn new(
        program: &Program,
        model: &str,
        equations: &str,
        origin: (usize, usize),
    ) -> PyResult<ArrayModel> {
        let set = equation_set(equations)?;
        let cfg = program.cfg;
        let ops = windowed(program, origin)?;
        check_program(&ops, cfg.stack_depth).map_err(|e| text(e.to_string()))?;
        let (arr, tape) = match model {
            "cycle" => {
                let mut a = CycleArray::new(cfg, set.clone());
                let tape = Rc::new(RefCell::new(Tape {
                    counter: BitCounter::new(&cfg),
                    on: false,
                    clocks: vec![],
                }));
                let seen = Rc::clone(&tape);
                a.observe(Box::new(move |a: &CycleArray, c: Clock| {
                    let mut t = seen.borrow_mut();
                    let k = t.counter.clock(&c);
                    if t.on {
                        let words = array_words(&cfg, a, k, c.bit);
                        t.clocks.push(words);
                    }
                }));
                (Model::Cycle(Box::new(a)), Some(tape))
            }
            "word" => (
                Model::Word(Box::new(WordArray::new(cfg, set.clone()))),
                None,
            ),
            m => return Err(text(format!("model {m:?}: `cycle` or `word`"))),
        };
        Ok(ArrayModel {
            ops,
            cfg,
            set,
            arr,
            tape,
            next: 0,
            finished: false,
        })
    }

    /// `cycle` or `word`.
    #[getter]
    fn model(&self) -> &'static str {
        match self.arr {
            Model::Cycle(_) => "cycle",
            Model::Word(_) => "word",
        }
    }

    /// The array's width and height in pixels.
    #[getter]
    fn size(&self) -> (usize, usize) {
        (self.cfg.width, self.cfg.height)
    }

    /// Operations of the program.
    fn __len__(&self) -> usize {
        self.ops.len()
    }

    /// One line per operation, as the models print them (moved to the origin).
    fn ops(&self) -> Vec<String> {
        self.ops.iter().map(|o| format!("{o:?}")).collect()
    }

    /// Index of the next operation `step()` carries out (`len(model)` when all are done).
    #[getter]
    fn position(&self) -> usize {
        self.next
    }

    /// Whether every operation and the flush window have run.
    #[getter]
    fn done(&self) -> bool {
        self.finished
    }

    /// Clocks so far, DEPGEN's fill included.
    #[getter]
    fn cycles(&self) -> u64 {
        self.arr.array().cycles()
    }

    /// Carry out the next operation; returns the clocks it took.
    fn step(&mut self) -> PyResult<u64> {
        self.step_op()
    }

    /// After the last operation, run the flush window that carries out a select code still
    /// latched; returns its clocks (0 when there is none, or when already finished).
    fn finish(&mut self) -> PyResult<u64> {
        self.finish_op()
    }

    /// Step every operation left, then finish; returns the clocks taken.
    fn run(&mut self) -> PyResult<u64> {
        let mut c = 0;
        while self.next < self.ops.len() {
            c += self.step_op()?;
        }
        Ok(c + self.finish_op()?)
    }

    /// The image: every pixel's colour code (G), shape (height, width), uint8.
    fn image<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (w, h) = (self.cfg.width, self.cfg.height);
        let codes: Vec<u8> = (0..w * h)
            .map(|i| self.arr.array().pixel(i % w, i / w).creg(CReg::G) as u8)
            .collect();
        Ok(PyArray1::from_vec(py, codes).reshape([h, w])?.into_any())
    }

    /// Every register of pixel (x, y): depth `A F B C` (signed words, in units of
    /// 2^-fraction), colours `D E G`, the select code `S` = (S_hi, S_lo), the flags `N J T
    /// M` and the clipping `stack` (bit i = level i).
    fn registers<'py>(&self, py: Python<'py>, x: usize, y: usize) -> PyResult<Bound<'py, PyDict>> {
        if x >= self.cfg.width || y >= self.cfg.height {
            return Err(text(format!(
                "pixel ({x}, {y}) is outside the {}x{} array",
                self.cfg.width, self.cfg.height
            )));
        }
        let p = self.arr.array().pixel(x, y);
        let d = PyDict::new(py);
        for (n, v) in ["A", "F", "B", "C"].iter().zip(p.depth) {
            d.set_item(n, v)?;
        }
        for (n, v) in ["D", "E", "G"].iter().zip(p.colour) {
            d.set_item(n, v)?;
        }
        d.set_item("S", p.sel)?;
        d.set_item("N", p.flags.n)?;
        d.set_item("J", p.flags.j)?;
        d.set_item("T", p.flags.t)?;
        d.set_item("M", p.flags.m)?;
        d.set_item("stack", p.stack)?;
        Ok(d)
    }

    /// `cycle` only: carry out the next operation and return, for each of its clocks, every
    /// pixel's `state` word after that clock (row-major: pixel (x, y) at y * width + x), as
    /// the Verilog `pixel`'s `state` port holds it (fields: `state_fields()`, LSB first).
    fn step_clocks<'py>(&mut self, py: Python<'py>) -> PyResult<Vec<Vec<Bound<'py, PyAny>>>> {
        self.recorded(py, "step_clocks", Self::step_op)
    }

    /// `cycle` only: `finish()`, returning every pixel's `state` word after each clock of
    /// the flush window (no clocks when there is none).
    fn finish_clocks<'py>(&mut self, py: Python<'py>) -> PyResult<Vec<Vec<Bound<'py, PyAny>>>> {
        self.recorded(py, "finish_clocks", Self::finish_op)
    }

    /// `cycle` only: every pixel's `state` word now (row-major), e.g. after reset.
    fn state_words<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyAny>>> {
        let k = self.tape("state_words")?.borrow().counter.k();
        let Model::Cycle(a) = &self.arr else {
            unreachable!("only the cycle model has a tape")
        };
        // Between operations every register is aligned: no clock of a window (bit None).
        array_words(&self.cfg, a, k, None)
            .iter()
            .map(|b| py_int(py, b))
            .collect()
    }

    /// The fields of a pixel's `state` word, LSB first: `(name, bits)`.
    fn state_fields(&self) -> Vec<(&'static str, usize)> {
        state_fields(&self.cfg)
    }

    /// The control stream of the whole program (with the equations of this model and its
    /// origin): one control word per clock, the program's `cycles` clocks and then the idle
    /// clock that carries `last`; and `ends`, the clock (counted from 1) each operation ends
    /// with, then the flush window's last clock when there is one (the words' `op_end`).
    fn control_words(&self) -> (Vec<u64>, Vec<u64>) {
        let words: Vec<u64> = control_stream(&self.cfg, &self.set, &self.ops)
            .lines()
            .map(|l| u64::from_str_radix(l, 16).expect("control_stream writes hex words"))
            .collect();
        let (op_end, _) = control_field("op_end");
        let ends = (1..)
            .zip(&words)
            .filter(|(_, w)| *w >> op_end & 1 == 1)
            .map(|(t, _)| t)
            .collect();
        (words, ends)
    }

    /// The control word's fields: `(name, first bit, bits)`.
    #[staticmethod]
    fn control_fields() -> Vec<(&'static str, usize, usize)> {
        pixel::FIELDS.to_vec()
    }

    /// The control fields that are inputs of `pixel_array` (with `clk` and `rst`): a
    /// testbench sets each to its field of the clock's word.
    #[staticmethod]
    fn array_inputs() -> Vec<&'static str> {
        pixel::array_inputs()
    }

    fn __repr__(&self) -> String {
        format!(
            "ArrayModel({} model, {}x{} array, operation {} of {}, {} clocks{})",
            self.model(),
            self.cfg.width,
            self.cfg.height,
            self.next,
            self.ops.len(),
            self.arr.array().cycles(),
            if self.finished { ", finished" } else { "" }
        )
    }
}

fn control_field(name: &str) -> (usize, usize) {
    let f = pixel::FIELDS.iter().find(|f| f.0 == name).expect("field");
    (f.1, f.2)
}

/// The Verilog sources of `pixel_array` for the program's array (`stimulus::array_files`,
/// the derived SGENE): name → text, `pixel_array.f` listing the synthesizable ones, leaves
/// first, and `tb_array.v` the file-driven testbench.
#[pyfunction]
pub fn verilog_files<'py>(py: Python<'py>, program: &Program) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (name, body) in array_files(&program.cfg) {
        d.set_item(name, body)?;
    }
    Ok(d)
}
