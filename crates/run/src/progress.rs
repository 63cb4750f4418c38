//! What a long job says while it runs, to whoever runs it: the binary draws it as progress
//! bars on standard error (indicatif), Python hands it to a callback. A job never prints; a
//! warning or a note goes here, and the report (data) is what the job returns.

/// The sink of a job's progress, warnings and notes.
///
/// `Sync`, and every method takes `&self`: the voxelizer's worker threads advance it while
/// the job runs (a job takes `&dyn Progress`, not `&mut`, for that reason). Every method
/// has a default that does nothing, so a sink implements only what it shows.
pub trait Progress: Sync {
    /// A stage of `total` steps begins; `what` names a step (`slices`, `bricks`, `cells`).
    fn stage(&self, what: &str, total: u64) {
        let _ = (what, total);
    }

    /// `n` more steps of the current stage are done.
    fn advance(&self, n: u64) {
        let _ = n;
    }

    /// The current stage is over (its bar is cleared).
    fn finish(&self) {}

    /// A warning, one line (`FILE:LINE:COL: message`): the job goes on, as OpenSCAD does.
    fn warning(&self, line: &str) {
        let _ = line;
    }

    /// A note: something the job changed of what it was asked (a limit lowered), one line.
    fn note(&self, line: &str) {
        let _ = line;
    }
}

/// A sink that shows nothing: tests, benches, and library callers with no display.
#[derive(Debug, Clone, Copy, Default)]
pub struct Quiet;

impl Progress for Quiet {}

/// Each of `warnings` as one [`Progress::warning`], in order.
pub fn warn_all<W: std::fmt::Display>(progress: &dyn Progress, warnings: &[W]) {
    for w in warnings {
        progress.warning(&w.to_string());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    /// A sink that keeps what it is told.
    #[derive(Default)]
    struct Kept(Mutex<Vec<String>>);

    impl Progress for Kept {
        fn warning(&self, line: &str) {
            self.0.lock().unwrap().push(line.to_string());
        }
    }

    #[test]
    fn warnings_reach_the_sink_in_order() {
        let kept = Kept::default();
        warn_all(&kept, &["a.csg:1:2: first", "a.csg:3:4: second"]);
        assert_eq!(
            *kept.0.lock().unwrap(),
            ["a.csg:1:2: first", "a.csg:3:4: second"]
        );
        // The quiet sink takes anything and keeps nothing.
        warn_all(&Quiet, &["ignored"]);
    }
}
