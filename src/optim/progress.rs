//! A progress bar over an optimiser's iterations, which also records the trace. indicatif
//! draws it on stderr only when that is a terminal, so logs and tests stay clean.

use indicatif::ProgressBar;

use super::{Observer, TraceObserver};

/// Progress bar and trace of one minimisation.
pub struct ProgressObserver {
    bar: ProgressBar,
    /// Words for the best objective value so far, e.g. "best cost 1.2e-3".
    describe: fn(f64) -> String,
    pub trace: TraceObserver,
}

impl ProgressObserver {
    /// A bar of `max_iterations` steps headed `what` (e.g. "fit").
    pub fn new(what: &str, max_iterations: usize, describe: fn(f64) -> String) -> Self {
        let bar = crate::progress::bar(what, max_iterations as u64, "{prefix} {bar:30} {pos}/{len} iterations [{elapsed}] {msg}");
        bar.set_prefix(what.to_string());
        Self { bar, describe, trace: TraceObserver::default() }
    }

    /// Clears the bar and returns the trace.
    pub fn finish(self) -> TraceObserver {
        self.bar.finish_and_clear();
        self.trace
    }
}

impl Observer for ProgressObserver {
    fn iteration(&mut self, iter: usize, best_f: f64, best_x: &[f64], evaluations: usize) {
        self.bar.set_position(iter as u64);
        self.bar.set_message(format!("{}, {evaluations} evaluations", (self.describe)(best_f)));
        self.trace.iteration(iter, best_f, best_x, evaluations);
    }
}
