//! A second active material in one electrode (silicon beside graphite, a blended cathode), as
//! one extra phase that shares the particles' potential: the open-circuit potential of the
//! blend at the electrode's stoichiometry `x`.
//!
//! A share `f` of the electrode's sites belongs to the extra phase, filled as a logistic of
//! the potential around its standard potential `U0` with width `w` (one MSMR gallery):
//! `x = (1 - f) s + f / (1 + exp((U - U0) / w))` with `U = U_host(s)` the set's OCP at the host
//! stoichiometry `s`. Both terms rise with `s` (every OCP falls as its material fills), so `x`
//! is strictly increasing in `s` and the blend's OCP `U(x)` is the set's OCP read through it.

use super::function::interpolate;
use super::set::Electrode;

/// Points of host stoichiometry in a tabulated blend OCP ([`BlendOcp`]): 1e-5 V apart at most
/// on the Chen 2020 graphite's plateaus, 0.4 mV within 0.01 of its empty end.
const TABLE_POINTS: usize = 4001;

/// The blend's OCP tabulated against the electrode's stoichiometry, for the models' hot loops.
#[derive(Clone, Debug)]
pub struct BlendOcp {
    x: Vec<f64>,
    u: Vec<f64>,
}

impl BlendOcp {
    /// The table of `e`'s blend, or `None` when it has no second phase.
    pub fn of(e: &Electrode) -> Option<Self> {
        if !e.has_second_phase() {
            return None;
        }
        let (x, u) = (0..TABLE_POINTS)
            .map(|k| {
                let s = k as f64 / (TABLE_POINTS - 1) as f64;
                let u = e.ocp.eval(s);
                (e.blend_stoichiometry(s, u), u)
            })
            .unzip();
        Some(Self { x, u })
    }

    /// The blend's OCP (V) at stoichiometry `x`, linear between the table's points.
    pub fn eval(&self, x: f64) -> f64 {
        interpolate(&self.x, &self.u, x)
    }
}

impl Electrode {
    /// Whether the electrode holds a second active material.
    pub fn has_second_phase(&self) -> bool {
        self.second_phase_share > 0.0
    }

    /// The electrode's stoichiometry (-) when its host holds `s` at potential `u` (V).
    fn blend_stoichiometry(&self, s: f64, u: f64) -> f64 {
        let f = self.second_phase_share;
        let filled = 1.0 / (1.0 + ((u - self.second_phase_potential) / self.second_phase_width).exp());
        (1.0 - f) * s + f * filled
    }

    /// The open-circuit potential (V) at stoichiometry `x` at the reference temperature: the
    /// set's OCP, or the blend's with a second phase (by bisection on the host stoichiometry;
    /// the models read [`BlendOcp`]'s table instead).
    pub fn open_circuit_potential(&self, x: f64) -> f64 {
        if !self.has_second_phase() {
            return self.ocp.eval(x);
        }
        let (mut a, mut b) = (0.0, 1.0);
        for _ in 0..60 {
            let s = 0.5 * (a + b);
            if self.blend_stoichiometry(s, self.ocp.eval(s)) < x { a = s } else { b = s }
        }
        self.ocp.eval(0.5 * (a + b))
    }
}

#[cfg(test)]
mod tests {
    use super::BlendOcp;
    use crate::params::chen2020;

    /// Without a share the blend is the set's OCP; with one, the table and the bisection agree,
    /// the OCP still falls with x, and the extra phase holds its share of the sites around its
    /// potential (the blend's x at U0 is the host's plus half the share, less the share of it).
    #[test]
    fn a_second_phase_inserts_its_share_of_the_sites_around_its_potential() {
        let mut n = chen2020().negative;
        assert!(BlendOcp::of(&n).is_none());
        assert_eq!(n.open_circuit_potential(0.4), n.ocp.eval(0.4));
        (n.second_phase_share, n.second_phase_potential, n.second_phase_width) = (0.15, 0.35, 0.03);
        let table = BlendOcp::of(&n).unwrap();
        let mut last = f64::INFINITY;
        for k in 1..200 {
            let x = k as f64 / 200.0;
            let (u, v) = (table.eval(x), n.open_circuit_potential(x));
            assert!((u - v).abs() < 2e-4, "x = {x}: table {u}, bisection {v}");
            assert!(v < last, "the blend's OCP must fall with x: {v} at {x}");
            last = v;
        }
        // Where the host sits at 0.35 V the extra phase is half full.
        let s = (0..100_000).map(|k| k as f64 / 1e5).find(|s| n.ocp.eval(*s) < 0.35).unwrap();
        let x = 0.85 * s + 0.15 * 0.5;
        assert!((n.open_circuit_potential(x) - 0.35).abs() < 1e-3, "{}", n.open_circuit_potential(x));
    }
}
