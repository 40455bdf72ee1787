//! The stoichiometry windows a BPX document carries (each electrode's minimum and maximum
//! stoichiometry), in BPX's order, with the state of charge of a set's initial state between
//! them. The windows are [`params::soc`](crate::params::soc)'s: one solve, one set of errors.

use super::super::ParameterSet;
use super::super::soc::stoichiometry_window;
use crate::error::Error;

/// Stoichiometry windows of a cell and the state of charge of its initial state.
#[derive(Clone, Copy, Debug)]
pub struct StoichiometryWindows {
    /// Negative (min, max) stoichiometry: at the lower and the upper cut-off.
    pub negative: (f64, f64),
    /// Positive (min, max) stoichiometry: at the upper and the lower cut-off.
    pub positive: (f64, f64),
    /// State of charge of the initial particle concentrations within the windows.
    pub soc: f64,
}

/// The particle stoichiometries at which the open-circuit voltage equals the voltage cut-offs
/// with the cyclable lithium of the initial state, and the initial state of charge between
/// them. The windows are [`stoichiometry_window`](crate::params::stoichiometry_window)'s, and
/// so are the errors: a cut-off out of reach of the cell's lithium is refused, not clamped.
///
/// ```
/// use cellstudio::params::{bpx::stoichiometry_windows, chen2020, stoichiometry_window};
/// let p = chen2020();
/// let (w, soc) = (stoichiometry_windows(&p).unwrap(), stoichiometry_window(&p).unwrap());
/// assert_eq!((w.negative, w.positive), ((soc.x0, soc.x100), (soc.y100, soc.y0)));
/// let mut low = chen2020();
/// low.cell.lower_cutoff = 1.0;
/// let err = stoichiometry_windows(&low).unwrap_err().to_string();
/// assert!(err.contains("cell.lower_cutoff") && err.contains("not reachable"), "{err}");
/// ```
pub fn stoichiometry_windows(p: &ParameterSet) -> Result<StoichiometryWindows, Error> {
    let w = stoichiometry_window(p)?;
    if !(w.x100 > w.x0) {
        return Err(Error::InvalidSetting {
            field: "cell.upper_cutoff".into(),
            reason: format!(
                "no stoichiometry window: the open-circuit voltage does not rise from {} V to {} V over the \
                 cyclable lithium of the initial state",
                p.cell.lower_cutoff, p.cell.upper_cutoff
            ),
        });
    }
    let x_n0 = p.negative.initial_concentration / p.negative.max_concentration;
    Ok(StoichiometryWindows {
        negative: (w.x0, w.x100),
        positive: (w.y100, w.y0),
        soc: (x_n0 - w.x0) / (w.x100 - w.x0),
    })
}
