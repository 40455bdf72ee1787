//! The theoretical capacity of a cell from its initial state.

use super::{FARADAY, ParameterSet};

impl ParameterSet {
    /// Theoretical capacity (A h) from the initial state: the smaller of the lithium the
    /// negative electrode can release (down to stoichiometry 0) and the positive electrode can
    /// accept (up to stoichiometry 1). No discharge from this state delivers more.
    pub fn theoretical_capacity(&self) -> f64 {
        let a = self.cell.area();
        let (neg, pos) = (&self.negative, &self.positive);
        let releasable = neg.active_fraction * neg.thickness * a * neg.initial_concentration;
        let acceptable = pos.active_fraction * pos.thickness * a * (pos.max_concentration - pos.initial_concentration);
        releasable.min(acceptable) * FARADAY / 3600.0
    }

    /// Longest a constant-current discharge at `rate` C of the nominal capacity can last (s):
    /// 1.5 times the theoretical capacity (or the nominal one, if larger) at that current. A
    /// discharge to the lower cut-off always ends before it; one that reaches it was cut short.
    pub fn discharge_time_limit(&self, rate: f64) -> f64 {
        1.5 * 3600.0 * self.theoretical_capacity().max(self.cell.nominal_capacity) / (rate.abs() * self.cell.nominal_capacity)
    }
}
