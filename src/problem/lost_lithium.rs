//! The lithium that leaves with lost active material. A set aged the way PyBaMM ages one (a
//! smaller active volume fraction at the same initial concentrations) loses the lithium the
//! lost volume held at the set's initial state; a cell loses material at whatever state it is
//! in (Birkl et al. 2017): a delithiated negative's loss keeps its lithium cyclable (it moves
//! to the positive), a lithiated one's takes it along. The fit path [`LOSS_SOC`] names that
//! state, a state of charge of the unaged set's window (0 at its lower cut-off, 1 at its
//! upper, beyond them to where an electrode empties or fills): the cyclable lithium becomes
//! the unaged set's minus what the lost volume of each electrode held there.

use crate::error::Error;
use crate::params::ParameterSet;
use crate::params::soc::{LithiumLine, StoichiometryWindow};

/// Fit path of the state of charge (-) at which the active material was lost: not a field of
/// the parameter set.
pub const LOSS_SOC: &str = "active_material.loss_soc";

/// Whether `path` is the loss state's fit path.
pub fn is_loss_soc(path: &str) -> bool {
    path == LOSS_SOC
}

/// The state of charge of `base`'s initial state (where PyBaMM's way of ageing a set loses the
/// material) and the range of states its lithium reaches (one electrode empty or full at
/// either end), all on `base`'s window: `(start, lower, upper)`, the start within the range.
pub fn loss_soc_range(base: &ParameterSet) -> (f64, f64, f64) {
    let w = StoichiometryWindow::within_reach(base);
    let line = LithiumLine::of(base);
    let soc = |x: f64| (x - w.x0) / (w.x100 - w.x0);
    let (lo, hi) = line.negative_range();
    let (lower, upper) = (soc(lo), soc(hi));
    (soc(line.x_n0).clamp(lower, upper), lower, upper)
}

/// The negative and positive stoichiometries (-) of material lost at state of charge `soc` of
/// `base`'s window.
pub fn lost_stoichiometries(base: &ParameterSet, soc: f64) -> (f64, f64) {
    let (x, y) = StoichiometryWindow::within_reach(base).at(soc);
    (x.clamp(0.0, 1.0), y.clamp(0.0, 1.0))
}

/// Sets the cyclable lithium of `p`, an aged copy of `base` (smaller active fractions), to
/// `base`'s minus what the lost volume held at state of charge `soc` of `base`'s window, and
/// moves `p`'s initial concentrations onto that lithium (its negative stoichiometry as close
/// to its own as the new lithium allows). A gained volume brings lithium at that state.
pub fn take_lost_lithium(base: &ParameterSet, p: &mut ParameterSet, soc: f64) -> Result<(), Error> {
    let (x, y) = lost_stoichiometries(base, soc);
    let unaged = LithiumLine::of(base);
    let ((bn, bp), (qn, qp)) = (unaged.capacities(), LithiumLine::of(p).capacities());
    let lithium = unaged.lithium() - (bn - qn) * x - (bp - qp) * y;
    let (lo, hi) = (((lithium - qp) / qn).max(0.0), (lithium / qn).min(1.0));
    if !(lo <= hi) {
        return Err(Error::invalid(LOSS_SOC, soc, "leaves more lithium than the aged electrodes hold"));
    }
    let x_n = (p.negative.initial_concentration / p.negative.max_concentration).clamp(lo, hi);
    p.negative.initial_concentration = x_n * p.negative.max_concentration;
    p.positive.initial_concentration = (lithium - qn * x_n) / qp * p.positive.max_concentration;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::chen2020;

    fn aged(base: &ParameterSet, negative: f64, positive: f64) -> ParameterSet {
        let mut p = base.clone();
        p.negative.active_fraction *= 1.0 - negative;
        p.positive.active_fraction *= 1.0 - positive;
        p
    }

    /// At the set's own initial state the loss is PyBaMM's (the concentrations stay); at the
    /// negative's empty end a negative loss keeps every mole of lithium; at the full end a
    /// negative loss takes the lost volume's lithium there.
    #[test]
    fn the_lost_lithium_follows_the_state_of_the_loss() {
        let base = chen2020();
        let (start, lower, upper) = loss_soc_range(&base);
        assert!(lower < 0.0 && upper > 1.0 && (lower..=upper).contains(&start), "{lower} {start} {upper}");
        let plain = aged(&base, 0.07, 0.05);
        let mut p = plain.clone();
        take_lost_lithium(&base, &mut p, start).unwrap();
        let lithium = |q: &ParameterSet| LithiumLine::of(q).lithium();
        assert!((lithium(&p) / lithium(&plain) - 1.0).abs() < 1e-12, "{} {}", lithium(&p), lithium(&plain));

        let w = StoichiometryWindow::within_reach(&base);
        let negative_only = aged(&base, 0.07, 0.0);
        let mut kept = negative_only.clone();
        let empty = -w.x0 / (w.x100 - w.x0);
        assert!((empty - lower).abs() < 1e-12, "Chen's positive takes all the lithium: the range starts at an empty negative");
        take_lost_lithium(&base, &mut kept, lower).unwrap();
        assert!((lithium(&kept) / lithium(&base) - 1.0).abs() < 1e-12);

        let mut full = negative_only.clone();
        take_lost_lithium(&base, &mut full, 1.0).unwrap();
        let (bn, _) = LithiumLine::of(&base).capacities();
        assert!(((lithium(&base) - lithium(&full)) / (0.07 * bn * w.x100) - 1.0).abs() < 1e-12);
    }
}
