//! Initial particle concentrations from a measured open-circuit voltage.

use super::ParameterSet;
use super::soc::LithiumLine;
use crate::error::Error;

impl ParameterSet {
    /// Sets the initial particle concentrations so that the open-circuit voltage is `v` (V),
    /// keeping the set's cyclable lithium. Errors name `initial_ocv` when `v` is out of reach.
    pub fn set_initial_ocv(&mut self, v: f64) -> Result<(), Error> {
        let line = LithiumLine::of(self);
        let x_n = line.negative_at_ocv(self, v);
        let x_p = line.positive(x_n);
        let reached = line.ocv(self, x_n);
        if !((reached - v).abs() < 1e-6) || !(x_n > 0.0 && x_n < 1.0 && x_p > 0.0 && x_p < 1.0) {
            return Err(Error::invalid(
                "initial_ocv",
                v,
                format!("is out of reach of the cell's cyclable lithium (closest {reached:.4} V)"),
            ));
        }
        self.negative.initial_concentration = x_n * self.negative.max_concentration;
        self.positive.initial_concentration = x_p * self.positive.max_concentration;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::params::chen2020;

    #[test]
    fn initial_ocv_is_reached_with_lithium_conserved() {
        let mut p = chen2020();
        let lithium = |p: &crate::params::ParameterSet| {
            p.negative.active_fraction * p.negative.thickness * p.negative.initial_concentration
                + p.positive.active_fraction * p.positive.thickness * p.positive.initial_concentration
        };
        let before = lithium(&p);
        p.set_initial_ocv(3.7).unwrap();
        let ocv = p.positive.ocp.eval(p.positive.initial_concentration / p.positive.max_concentration)
            - p.negative.ocp.eval(p.negative.initial_concentration / p.negative.max_concentration);
        assert!((ocv - 3.7).abs() < 1e-9, "{ocv}");
        assert!((lithium(&p) / before - 1.0).abs() < 1e-12);
        let e = p.set_initial_ocv(5.5).unwrap_err().to_string();
        assert!(e.contains("initial_ocv") && e.contains("5.5"), "{e}");
    }
}
