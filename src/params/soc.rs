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

    /// Sets the initial particle concentrations of `p` (mol/m^3) to state of charge `soc`.
    pub fn place(&self, p: &mut ParameterSet, soc: f64) {
        let (x, y) = self.at(soc);
        p.negative.initial_concentration = x * p.negative.max_concentration;
        p.positive.initial_concentration = y * p.positive.max_concentration;
    }

    /// The charge (A h) the window holds: the lithium the negative electrode of `p` takes up
    /// from 0 % to 100 %.
    pub fn capacity(&self, p: &ParameterSet) -> f64 {
        let n = &p.negative;
        (self.x100 - self.x0) * n.active_fraction * n.thickness * n.max_concentration * p.cell.area() * super::FARADAY / 3600.0
    }

    /// The window of `p` between its cut-offs where its lithium reaches them, else where an
    /// electrode fills or empties first (a design whose positive electrode is full before
    /// the OCV falls to the lower cut-off ends its discharge there): defined for any valid
    /// set, unlike [`stoichiometry_window`].
    pub fn within_reach(p: &ParameterSet) -> Self {
        let line = LithiumLine::of(p);
        let (x0, x100) = (line.negative_at_ocv(p, p.cell.lower_cutoff), line.negative_at_ocv(p, p.cell.upper_cutoff));
        Self { x0, x100, y0: line.positive(x0), y100: line.positive(x100) }
    }
}

/// The stoichiometries reachable with the cyclable lithium of a set's initial state: the
/// positive stoichiometry as a function of the negative one (lithium conserved).
pub struct LithiumLine {
    /// Lithium capacity of each electrode per unit area, `eps L c_max` (mol/m^2).
    a_n: f64,
    a_p: f64,
    /// Cyclable lithium per unit area (mol/m^2).
    lithium: f64,
    /// Initial negative stoichiometry.
    pub x_n0: f64,
}

impl LithiumLine {
    pub fn of(p: &ParameterSet) -> Self {
        let (n, q) = (&p.negative, &p.positive);
        let a_n = n.active_fraction * n.thickness * n.max_concentration;
        let a_p = q.active_fraction * q.thickness * q.max_concentration;
        let x_n0 = n.initial_concentration / n.max_concentration;
        let lithium = a_n * x_n0 + a_p * q.initial_concentration / q.max_concentration;
        Self { a_n, a_p, lithium, x_n0 }
    }

    /// Lithium capacities of the negative and positive electrodes per unit area,
    /// `eps L c_max` (mol/m^2).
    pub fn capacities(&self) -> (f64, f64) {
        (self.a_n, self.a_p)
    }

    /// Cyclable lithium per unit area (mol/m^2).
    pub fn lithium(&self) -> f64 {
        self.lithium
    }

    /// Positive stoichiometry at negative stoichiometry `x_n` (clamped to [0, 1]).
    pub fn positive(&self, x_n: f64) -> f64 {
        ((self.lithium - self.a_n * x_n) / self.a_p).clamp(0.0, 1.0)
    }

    /// Negative stoichiometries at which both electrodes stay within [0, 1].
    pub fn negative_range(&self) -> (f64, f64) {
        (((self.lithium - self.a_p) / self.a_n).max(0.0), (self.lithium / self.a_n).min(1.0))
    }

    /// Open-circuit voltage (V) at negative stoichiometry `x_n` on the line.
    pub fn ocv(&self, p: &ParameterSet, x_n: f64) -> f64 {
        p.positive.open_circuit_potential(self.positive(x_n)) - p.negative.open_circuit_potential(x_n)
    }

    /// The negative stoichiometry at which the open-circuit voltage is `v` (V), clamped to the
    /// reachable range when `v` is out of reach. The OCV rises with `x_n`; bisection.
    pub fn negative_at_ocv(&self, p: &ParameterSet, v: f64) -> f64 {
        let (lo, hi) = self.negative_range();
        let ocv = |x_n: f64| self.ocv(p, x_n);
        let (mut a, mut b) = (lo, hi);
        if ocv(a) >= v {
            return a;
        }
        if ocv(b) <= v {
            return b;
        }
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            if ocv(m) < v { a = m } else { b = m }
        }
        0.5 * (a + b)
    }
}

/// The stoichiometry window between `cell.lower_cutoff` and `cell.upper_cutoff` with the
/// set's cyclable lithium conserved. Errors when a cut-off voltage cannot be reached inside
/// stoichiometries (0, 1) with that lithium.
pub fn stoichiometry_window(p: &ParameterSet) -> Result<StoichiometryWindow, Error> {
    p.validate()?;
    let line = LithiumLine::of(p);
    let solve = |field: &str, v: f64| -> Result<f64, Error> {
        let x = line.negative_at_ocv(p, v);
        let y = line.positive(x);
        if (line.ocv(p, x) - v).abs() > 1e-9 || !(x > 0.0 && x < 1.0 && y > 0.0 && y < 1.0) {
            let (lo, hi) = line.negative_range();
            return Err(Error::invalid(
                field,
                v,
                format!(
                    "not reachable with the cell's lithium: the OCV spans {:.4} V to {:.4} V over the usable stoichiometries",
                    line.ocv(p, lo),
                    line.ocv(p, hi)
                ),
            ));
        }
        Ok(x)
    };
    let x100 = solve("cell.upper_cutoff", p.cell.upper_cutoff)?;
    let x0 = solve("cell.lower_cutoff", p.cell.lower_cutoff)?;
    Ok(StoichiometryWindow { x0, x100, y0: line.positive(x0), y100: line.positive(x100) })
}

/// [`set_initial_soc`] with a state of charge outside [0, 1] reported under `field` (the
/// study key it came from, e.g. `cycling.initial_soc`).
pub fn set_initial_soc_from(p: &mut ParameterSet, soc: f64, field: &str) -> Result<StoichiometryWindow, Error> {
    set_initial_soc(p, soc).map_err(|e| match e {
        Error::InvalidParameter { field: f, value, reason } if f == "soc" => Error::InvalidParameter { field: field.into(), value, reason },
        other => other,
    })
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
    w.place(p, soc);
    Ok(w)
}
