//! Progress of long runs (optimisations, sweeps, sampling, landscapes, diagnosis): an
//! indicatif bar, drawn on stderr only when that is a terminal, which [`bar`] also makes the
//! process's current bar. Another thread can poll its [`snapshot`]: the Python package draws
//! it with tqdm in a notebook, where a terminal's stderr is not shown.

use std::sync::Mutex;

use indicatif::{ProgressBar, ProgressStyle};

/// The current bar and its label.
static CURRENT: Mutex<Option<(String, ProgressBar)>> = Mutex::new(None);

/// A bar of `len` steps named `label`, drawn with indicatif's `template`; it becomes the
/// current bar.
pub fn bar(label: &str, len: u64, template: &str) -> ProgressBar {
    let bar = ProgressBar::new(len);
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style);
    }
    if let Ok(mut current) = CURRENT.lock() {
        *current = Some((label.to_string(), bar.clone()));
    }
    bar
}

/// Label, position and length of the current bar while it runs (`None` when none runs).
pub fn snapshot() -> Option<(String, u64, u64)> {
    let current = CURRENT.lock().ok()?;
    let (label, bar) = current.as_ref()?;
    (!bar.is_finished()).then(|| (label.clone(), bar.position(), bar.length().unwrap_or(0)))
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_current_bar_is_seen_until_it_finishes() {
        let bar = super::bar("fit", 10, "{bar} {pos}/{len}");
        bar.set_position(3);
        assert_eq!(super::snapshot(), Some(("fit".to_string(), 3, 10)));
        bar.finish_and_clear();
        assert_eq!(super::snapshot(), None);
    }
}
