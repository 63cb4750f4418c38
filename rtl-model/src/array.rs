//! What both models of the array offer, and the clock accounting they share.

use crate::probe::Recorder;
use crate::program::{stack_effect, Op, ProgramError, Window};
use crate::state::{ArchState, ArrayConfig, Pixel};

/// A model of the pixel-processor array.
pub trait Array {
    /// The array's size, word format, colour width and stack depth.
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

    /// Every register of pixel (x, y): what a reader of one or two registers over the whole
    /// array asks for, without a copy of every pixel.
    fn pixel(&self, x: usize, y: usize) -> Pixel;

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
    /// Clipping stack pointer: levels in use, shared by every pixel.
    pub sp: usize,
    /// The transfer the latched select code will carry out in the next window, if any.
    pub pending: Option<crate::program::Transfer>,
    /// Clocks so far, DEPGEN's fill included.
    pub cycles: u64,
    streamed: bool,
}

impl Sequencer {
    /// Validate `op` against the stack and the latch.
    pub fn admit(&self, op: &Op, index: usize, depth: usize) -> Result<(), ProgramError> {
        admit(self.sp, self.pending.is_some(), op, index, depth).map(|_| ())
    }

    /// Clocks of a streaming window: N_D, plus DEPGEN's fill before the first one that streams.
    pub fn window_clocks(&mut self, cfg: &ArrayConfig, w: &Window) -> u64 {
        self.clocks(cfg, w.stream.is_some())
    }

    /// [`Sequencer::window_clocks`] of a window that streams or not.
    fn clocks(&mut self, cfg: &ArrayConfig, streams: bool) -> u64 {
        let mut c = cfg.fmt.bits() as u64;
        if streams && !self.streamed {
            self.streamed = true;
            c += cfg.depgen_latency();
        }
        c
    }
}

/// The clocks a program takes on an array of configuration `cfg`, without simulating a pixel:
/// the windows' N_D clocks (with DEPGEN's fill before the first that streams), one clock per
/// stack operation, and a last window for a transfer still latched at the end. Equal to
/// [`Array::cycles`] after [`Array::run`] (tested against both models).
/// Only the windows' shapes count ([`Window::shape`]): the select equations are not built.
pub fn program_cycles(cfg: &ArrayConfig, ops: &[Op]) -> u64 {
    let mut seq = Sequencer::default();
    let mut pending = false;
    for op in ops {
        match Window::shape(op) {
            Some(w) => {
                seq.cycles += seq.clocks(cfg, w.streams);
                pending = w.transfers;
            }
            None => {
                seq.cycles += 1;
                pending |= matches!(op, Op::ClipApply);
            }
        }
    }
    if pending {
        seq.cycles += cfg.fmt.bits() as u64;
    }
    seq.cycles
}

/// The stack pointer after `op`, or why `op` cannot run: it would pop an empty stack, push
/// past `depth`, or (`ClipApply`) overwrite a select code still waiting to be carried out.
fn admit(
    sp: usize,
    busy: bool,
    op: &Op,
    index: usize,
    depth: usize,
) -> Result<usize, ProgramError> {
    let (pop, push) = stack_effect(op);
    let after = sp
        .checked_sub(pop)
        .ok_or(ProgramError::StackUnderflow { op: index })?
        + push;
    if after > depth {
        return Err(ProgramError::StackOverflow { op: index, depth });
    }
    if matches!(op, Op::ClipApply) && busy {
        return Err(ProgramError::LatchBusy { op: index });
    }
    Ok(after)
}

/// Check a whole program before running it: the stack stays within `depth` and `ClipApply`
/// never overwrites a select code still waiting to be carried out. Returns the stack depth used.
pub fn check_program(ops: &[Op], depth: usize) -> Result<usize, ProgramError> {
    let (mut sp, mut busy, mut need) = (0, false, 0);
    for (i, op) in ops.iter().enumerate() {
        sp = admit(sp, busy, op, i, depth)?;
        need = need.max(sp);
        // Windows that latch a code leave it waiting; a clipping plane's window carries the
        // previous one out and latches none; the stack operators leave the latch alone.
        busy = match op {
            Op::ClipAnd | Op::ClipOr | Op::ClipNot => busy,
            Op::ClipPlane { .. } => false,
            _ => true,
        };
    }
    Ok(need)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::program::Coeffs;

    fn clip() -> Op {
        Op::ClipPlane {
            coeffs: Coeffs {
                c0: 0,
                dx: 0,
                dy: 0,
            },
            h: true,
            y: false,
            x: false,
        }
    }

    #[test]
    fn programs_that_break_the_stack_or_the_latch_are_refused() {
        let close = Op::Close { l: false };
        assert_eq!(
            check_program(&[clip(), clip(), Op::ClipAnd, Op::ClipApply], 2),
            Ok(2)
        );
        assert_eq!(
            check_program(&[clip(), clip(), clip()], 2),
            Err(ProgramError::StackOverflow { op: 2, depth: 2 })
        );
        assert_eq!(
            check_program(&[clip(), Op::ClipOr], 4),
            Err(ProgramError::StackUnderflow { op: 1 })
        );
        assert_eq!(
            check_program(&[clip(), close.clone(), Op::ClipApply], 4),
            Err(ProgramError::LatchBusy { op: 2 })
        );
        assert_eq!(
            check_program(&[close, clip(), Op::ClipNot, Op::ClipApply], 4),
            Ok(1)
        );
    }
}
