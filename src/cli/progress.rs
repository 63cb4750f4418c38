//! A job's progress on the terminal: one indicatif bar per stage on standard error (drawn
//! only when it is a terminal), warnings and notes as `csgpix: warning: …` lines.

use std::sync::Mutex;

use csgpix_output::OneLine;
use csgpix_run::progress::Progress;
use indicatif::{ProgressBar, ProgressStyle};

/// The command line's progress sink.
#[derive(Default)]
pub struct Bars {
    bar: Mutex<Option<ProgressBar>>,
}

impl Bars {
    /// Print `line` above the bar (if any), on standard error.
    fn say(&self, line: String) {
        let bar = self.bar.lock().unwrap_or_else(|e| e.into_inner());
        match bar.as_ref() {
            Some(b) => b.suspend(|| eprintln!("{line}")),
            None => eprintln!("{line}"),
        }
    }
}

impl Progress for Bars {
    fn stage(&self, what: &str, total: u64) {
        let bar = ProgressBar::new(total);
        // The time left is indicatif's estimate from the steps' rate so far.
        let template =
            format!("{{elapsed_precise}} [{{bar:40}}] {{pos}}/{{len}} {what}, {{eta}} left");
        if let Ok(style) = ProgressStyle::with_template(&template) {
            bar.set_style(style);
        }
        let old = self
            .bar
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .replace(bar);
        if let Some(old) = old {
            old.finish_and_clear();
        }
    }

    fn advance(&self, n: u64) {
        if let Some(b) = self.bar.lock().unwrap_or_else(|e| e.into_inner()).as_ref() {
            b.inc(n);
        }
    }

    fn finish(&self) {
        if let Some(b) = self.bar.lock().unwrap_or_else(|e| e.into_inner()).take() {
            b.finish_and_clear();
        }
    }

    fn warning(&self, line: &str) {
        self.say(format!("csgpix: warning: {}", OneLine(line)));
    }

    fn note(&self, line: &str) {
        self.say(format!("csgpix: note: {}", OneLine(line)));
    }
}
