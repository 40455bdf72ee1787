//! State of charge: the electrode stoichiometry window of a cell and initial particle
//! concentrations at a chosen state of charge, as PyBaMM's electrode state-of-health
//! (`ElectrodeSOHSolver`) and `set_initial_stoichiometries` compute them.
//!
//! The cyclable lithium `n_Li = eps_n L_n A c_n0 + eps_p L_p A c_p0` (mol) is taken from the
//! set's initial concentrations and conserved. With the electrode capacities
//! `Q_k = eps_k c_max,k L_k A` (mol per unit stoichiometry), the window ends solve
//!
//! - `U_p(y100) - U_n(x100) = upper_cutoff`, `Q_n x100 + Q_p y100 = n_Li` (100 % SOC),
//! - `U_p(y0) - U_n(x0) = lower_cutoff`, `Q_n x0 + Q_p y0 = n_Li` (0 % SOC),
//!
//! and a state of charge `s` maps to `x = x0 + s (x100 - x0)`, `y = y0 - s (y0 - y100)`.

use serde::{Deserialize, Serialize};

use super::ParameterSet;
use crate::error::Error;

/// Stoichiometry limits (-) of both electrodes between the voltage cut-offs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct StoichiometryWindow {
    /// Negative-electrode stoichiometry at 0 % SOC (lower cut-off).
    pub x0: f64,
    /// Negative-electrode stoichiometry at 100 % SOC (upper cut-off).
    pub x100: f64,
    /// Positive-electrode stoichiometry at 0 % SOC.
    pub y0: f64,
    /// Positive-electrode stoichiometry at 100 % SOC.
    pub y100: f64,
}

impl StoichiometryWindow {
    /// Negative and positive stoichiometries (-) at state of charge `soc` in [0, 1].
    pub fn at(&self, soc: f64) -> (f64, f64) {
        (self.x0 + soc * (self.x100 - self.x0), self.y0 - soc * (self.y0 - self.y100))
    }
}

/// Lithium per unit stoichiometry of each electrode, `eps c_max L A` (mol), and the
/// cyclable lithium held in the particles at the set's initial concentrations (mol).
fn capacities(p: &ParameterSet) -> (f64, f64, f64) {
    let a = p.cell.area();
    let (n, q) = (&p.negative, &p.positive);
    let qn = n.active_fraction * n.max_concentration * n.thickness * a;
    let qp = q.active_fraction * q.max_concentration * q.thickness * a;
    let li = n.active_fraction * n.initial_concentration * n.thickness * a
        + q.active_fraction * q.initial_concentration * q.thickness * a;
    (qn, qp, li)
}

/// The stoichiometry window between `cell.lower_cutoff` and `cell.upper_cutoff` with the
/// set's cyclable lithium conserved. Errors when a cut-off voltage cannot be reached inside
/// stoichiometries (0, 1) with that lithium.
pub fn stoichiometry_window(p: &ParameterSet) -> Result<StoichiometryWindow, Error> {
    p.validate()?;
    let (qn, qp, li) = capacities(p);
    // x range where both x and y = (li - qn x) / qp lie strictly inside (0, 1).
    let margin = 1e-10;
    let lo = ((li - qp) / qn).max(0.0) + margin;
    let hi = (li / qn).min(1.0) - margin;
    let y_of = |x: f64| (li - qn * x) / qp;
    // OCV as a function of x; increasing in x (U_p falls with y, y falls with x; U_n falls with x).
    let ocv = |x: f64| p.positive.ocp.eval(y_of(x)) - p.negative.ocp.eval(x);
    let solve = |field: &str, v: f64| -> Result<f64, Error> {
        let (mut a, mut b) = (lo, hi);
        let (fa, fb) = (ocv(a) - v, ocv(b) - v);
        if !(hi > lo) || !(fa <= 0.0 && fb >= 0.0) {
            return Err(Error::invalid(
                field,
                v,
                format!(
                    "not reachable with the cell's lithium: the OCV spans {:.4} V to {:.4} V over the usable stoichiometries",
                    ocv(lo),
                    ocv(hi)
                ),
            ));
        }
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if ocv(m) - v < 0.0 { a = m } else { b = m }
            if b - a <= 1e-15 {
                break;
            }
        }
        Ok(0.5 * (a + b))
    };
    let x100 = solve("cell.upper_cutoff", p.cell.upper_cutoff)?;
    let x0 = solve("cell.lower_cutoff", p.cell.lower_cutoff)?;
    Ok(StoichiometryWindow { x0, x100, y0: y_of(x0), y100: y_of(x100) })
}

/// Sets the initial particle concentrations of `p` to state of charge `soc` in [0, 1]
/// (0 at the lower cut-off, 1 at the upper), conserving the cyclable lithium. Returns the
/// window used.
///
/// ```
/// let mut p = cellstudio::params::chen2020();
/// let w = cellstudio::params::set_initial_soc(&mut p, 0.5).unwrap();
/// let x = p.negative.initial_concentration / p.negative.max_concentration;
/// assert!((x - 0.5 * (w.x0 + w.x100)).abs() < 1e-12);
/// let err = cellstudio::params::set_initial_soc(&mut p, 1.5).unwrap_err();
/// assert!(err.to_string().contains("`soc` = 1.5"));
/// ```
pub fn set_initial_soc(p: &mut ParameterSet, soc: f64) -> Result<StoichiometryWindow, Error> {
    if !(0.0..=1.0).contains(&soc) {
        return Err(Error::invalid("soc", soc, "state of charge must lie in [0, 1]"));
    }
    let w = stoichiometry_window(p)?;
    let (x, y) = w.at(soc);
    p.negative.initial_concentration = x * p.negative.max_concentration;
    p.positive.initial_concentration = y * p.positive.max_concentration;
    Ok(w)
}
