//! What both models of the array offer, and the clock accounting they share.

use crate::probe::Recorder;
use crate::program::{stack_effect, Op, ProgramError, Window};
use crate::state::{ArchState, ArrayConfig};

/// A model of the pixel-processor array.
pub trait Array {
    fn config(&self) -> &ArrayConfig;

    /// Carry out one operation. Programs are checked by [`check_program`] first; an operation
    /// that would break the stack or overwrite an unapplied select code is refused here too.
    fn step(&mut self, op: &Op) -> Result<(), ProgramError>;

    /// Run the flush window that carries out the last latched select code, if any.
    fn finish(&mut self);

    /// Clocks so far, DEPGEN's pipeline fill included.
    fn cycles(&self) -> u64;

    /// Every register of every pixel.
    fn state(&self) -> ArchState;

    /// Record the probed pixels from now on (`cycle`: every clock; `word`: every operation).
    fn attach_probe(&mut self, rec: Recorder);

    /// The recorder with everything sampled so far.
    fn take_probe(&mut self) -> Option<Recorder>;

    /// Check and run a whole program, then flush.
    fn run(&mut self, ops: &[Op]) -> Result<(), ProgramError> {
        check_program(ops, self.config().stack_depth)?;
        for op in ops {
            self.step(op)?;
        }
        self.finish();
        Ok(())
    }
}

/// The controller's bookkeeping common to both models: stack pointer, the transfer waiting for
/// the next window, and the clock count.
#[derive(Clone, Debug, Default)]
pub struct Sequencer {
    pub sp: usize,
    pub pending: Option<crate::program::Transfer>,
    pub cycles: u64,
    streamed: bool,
}

impl Sequencer {
    /// Validate `op` against the stack and the latch; returns the stack slot it touches.
    pub fn admit(&self, op: &Op, index: usize, depth: usize) -> Result<(), ProgramError> {
        let (pop, push) = stack_effect(op);
        let after = self
            .sp
            .checked_sub(pop)
            .ok_or(ProgramError::StackUnderflow { op: index })?
            + push;
        if after > depth {
            return Err(ProgramError::StackOverflow { op: index, depth });
        }
        if matches!(op, Op::ClipApply) && self.pending.is_some() {
            return Err(ProgramError::LatchBusy { op: index });
        }
        Ok(())
    }

    /// Clocks of a streaming window: N_D, plus DEPGEN's fill before the first one that streams.
    pub fn window_clocks(&mut self, cfg: &ArrayConfig, w: &Window) -> u64 {
        let mut c = cfg.fmt.bits() as u64;
        if w.stream.is_some() && !self.streamed {
            self.streamed = true;
            c += cfg.depgen_latency();
        }
        c
    }
}

/// Check a whole program before running it: the stack stays within `depth` and `ClipApply`
/// never overwrites a select code still waiting to be carried out. Returns the stack depth used.
pub fn check_program(ops: &[Op], depth: usize) -> Result<usize, ProgramError> {
    let mut seq = Sequencer::default();
    let mut need = 0;
    for (i, op) in ops.iter().enumerate() {
        seq.admit(op, i, depth)?;
        let (pop, push) = stack_effect(op);
        seq.sp = seq.sp - pop + push;
        need = need.max(seq.sp);
        seq.pending = match op {
            Op::ClipApply => Some(crate::program::Transfer::clip_apply()),
            Op::ClipAnd | Op::ClipOr | Op::ClipNot => seq.pending,
            Op::ClipPlane { .. } => None,
            _ => Some(crate::program::Transfer::clip_apply()),
        };
    }
    Ok(need)
}
