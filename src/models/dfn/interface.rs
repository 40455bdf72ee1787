//! The reactions at the surface of a negative x volume of the DFN with side reactions on
//! (PyBaMM's DFN with "x-average side reactions" false): intercalation, SEI growth and
//! lithium plating, each at the volume's own `phi_s - phi_e`. See docs/ageing.md, sections
//! 1.3 and 4.4.
//!
//! - film overpotential `j_tot L_sei R_sei` (V) with the total interfacial current density
//!   `j_tot` (an algebraic state with SEI, PyBaMM's "distributed" film) and the local SEI
//!   thickness; zero without SEI;
//! - intercalation `j` = [`butler_volmer`]`(j0, phi_s - phi_e - U - film)` into the
//!   particle (surface flux `j / F`);
//! - SEI `j_sei` at `phi_s - phi_e` with the film carrying `j` (PyBaMM's SEI reads the
//!   intercalation current);
//! - plating `j_Li` at the plating overpotential `phi_s - phi_e - film` with the local `c_e`
//!   and SEI thickness;
//! - `0 = j_tot - (j + j_sei + j_Li)`; the electrolyte and the potentials take
//!   `a (j + j_sei + j_Li)`.

use super::Dfn;
use crate::models::electrochem::Side;
use crate::models::kinetics::butler_volmer;
use crate::models::submodels::SeiLayer;
use crate::models::submodels::plating::Site;
use crate::models::submodels::thermal::SideReactionSite;

/// The intercalation inputs of one negative x volume.
#[derive(Clone, Copy, Debug)]
pub(super) struct Surface {
    /// Index of the volume within the negative electrode.
    pub k: usize,
    /// Index of the volume over the whole cell.
    pub i: usize,
    /// Exchange-current density of intercalation (A/m^2).
    pub j0: f64,
    /// `phi_s - phi_e` (V).
    pub delta_phi: f64,
    /// Open-circuit potential at the particle surface (V).
    pub ocp: f64,
    /// Surface area density (1/m).
    pub a: f64,
    /// Temperature (K).
    pub temp: f64,
}

impl Dfn {
    /// Whether a negative volume has reactions beside intercalation.
    pub(super) fn side_reactions(&self) -> bool {
        self.layout.sei.is_some() || self.layout.plating.is_some()
    }

    /// The reactions of negative volume `s`: writes the rates of its SEI and plating states
    /// and the residual of its total current into `out_phis` (the outputs from the negative
    /// solid potential's first row on), and returns the intercalation current density `j`,
    /// the SEI's `j_sei` (A/m^2) and all its reactions, for their sum and the heat.
    pub(super) fn negative_interface(&self, y: &[f64], s: Surface, out_phis: &mut [f64]) -> (f64, f64, SideReactionSite) {
        let (l, ec) = (&self.layout, &self.ec);
        let row = |index: usize| index - l.phis_n;
        let sei = l.sei.map(|start| (start + s.k, start + l.nxn + s.k));
        let film = sei.map_or(0.0, |(c_sei, j_tot)| y[j_tot] * SeiLayer::local_thickness(ec, y, c_sei, s.a) * ec.params.sei.resistivity);
        let alpha = ec.electrode(Side::Negative).charge_transfer_coefficient;
        let j = butler_volmer(s.j0, s.delta_phi - s.ocp - film, alpha, s.temp);
        let j_sei = sei.map_or(0.0, |(c_sei, _)| {
            let j_sei = self.sei.side_current(ec, y, c_sei, s.delta_phi, j, s.a, s.temp);
            out_phis[row(c_sei)] = SeiLayer::growth_rate(ec, s.a, j_sei);
            j_sei
        });
        let j_li = self.plating.site_indices(s.k).map_or(0.0, |[plated, dead]| {
            let site = Site { delta_phi: s.delta_phi, electrolyte_concentration: y[l.ce + s.i], sei_thickness: self.sei.volume_thickness(ec, y, s.k, s.a) };
            let (j_li, rates) = self.plating.site_rates(ec, y[plated], site, film, s.a, s.temp);
            (out_phis[row(plated)], out_phis[row(dead)]) = (rates[0], rates[1]);
            j_li
        });
        let total = j + j_sei + j_li;
        if let Some((_, j_tot)) = sei {
            out_phis[row(j_tot)] = y[j_tot] - total;
        }
        (j, j_sei, SideReactionSite { a: s.a, total_current: total, side_current: j_sei + j_li, delta_phi: s.delta_phi, ocp: s.ocp, film })
    }

    /// The side states of negative volume `k` that its reactions read and write: its SEI
    /// concentration and total current, its plated and dead lithium (those that are on).
    pub(super) fn side_states(&self, k: usize) -> Vec<usize> {
        let l = &self.layout;
        let sei = l.sei.map(|s| [s + k, s + l.nxn + k]);
        sei.into_iter().chain(self.plating.site_indices(k)).flatten().collect()
    }
}
