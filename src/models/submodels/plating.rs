//! Lithium plating on the negative electrode of the single-particle models, as PyBaMM's
//! `Plating` submodel (O'Kane 2020, 2022) in its SPM (x-averaged: one plated and one dead
//! lithium concentration for the whole electrode) and SPMe ("x-average side reactions"
//! false: one of each per negative x volume), with the parameters of
//! [`crate::params::Plating`]. See docs/ageing.md.
//!
//! - plating overpotential `eta_pl = phi_s - phi_e - j_tot L_sei R_sei` (V): the local
//!   `phi_s - phi_e` less the SEI film's drop (zero without SEI), PyBaMM's "lithium plating
//!   overpotential" (its stripping overpotential; plating is favoured below 0);
//! - exchange-current densities `j0_pl = F k c_e`, `j0_st = F k c_Li` (A/m^2), `c_Li` the
//!   plated (reversible) lithium concentration (mol per m^3 of electrode);
//! - net stripping current density `j_Li` (A/m^2, negative while plating):
//!   irreversible `-j0_pl exp(-alpha F eta_pl / (R T))`; reversible and partially reversible
//!   `j0_st exp((1 - alpha) F eta_pl / (R T)) - j0_pl exp(-alpha F eta_pl / (R T))`;
//! - `d c_Li / dt = -a j_Li / F` (reversible), `d c_dead / dt = -a j_Li / F` (irreversible:
//!   all plated lithium is dead); partially reversible `d c_Li / dt = -a j_Li / F - gamma
//!   c_Li`, `d c_dead / dt = gamma c_Li` with `gamma = gamma_0 L_sei_0 / L_sei` (1/s);
//! - the particles carry `j_tot - j_sei - j_Li` (x-averaged), so plated lithium comes out of
//!   the negative particles and the applied current is unchanged.

use std::ops::Range;

use serde::{Deserialize, Serialize};

use crate::models::Electrochem;
use crate::params::{FARADAY, GAS_CONSTANT};

/// Which plating law, by PyBaMM's option names ("lithium plating").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum PlatingModel {
    /// No plating (no states).
    #[default]
    #[serde(rename = "none")]
    None,
    /// Plating only, no stripping: all plated lithium is dead.
    #[serde(rename = "irreversible")]
    Irreversible,
    /// Plating and stripping, no dead lithium.
    #[serde(rename = "reversible")]
    Reversible,
    /// Plating and stripping; plated lithium turns dead at rate `gamma`.
    #[serde(rename = "partially reversible")]
    PartiallyReversible,
}

/// Lithium plated on the negative electrode at one state (mol), PyBaMM's "Loss of lithium
/// to negative lithium plating [mol]" being their sum.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PlatedLithium {
    /// Reversible (strippable) plated lithium `c_Li L_n A` (mol).
    pub plated_mol: f64,
    /// Dead lithium `c_dead L_n A` (mol).
    pub dead_mol: f64,
}

impl PlatedLithium {
    /// All lithium lost to plating (mol).
    pub fn total_mol(&self) -> f64 {
        self.plated_mol + self.dead_mol
    }
}

/// Where the plating reaction runs: one negative x volume (or the whole electrode).
#[derive(Clone, Copy, Debug)]
pub struct Site {
    /// `phi_s - phi_e` (V) there, with the SEI film's drop.
    pub delta_phi: f64,
    /// Electrolyte concentration (mol/m^3) there.
    pub electrolyte_concentration: f64,
    /// SEI thickness (m) there: `L_sei_0` without an SEI submodel (PyBaMM's "constant" SEI).
    pub sei_thickness: f64,
}

/// The plating layer of a single-particle model: off, or `count` plated-lithium states from
/// `start` (one per negative x volume, one for the whole electrode when x-averaged), then
/// `count` dead-lithium states.
#[derive(Clone, Copy, Debug)]
pub struct PlatingLayer {
    model: PlatingModel,
    start: Option<usize>,
    count: usize,
}

impl PlatingLayer {
    /// The layer for `model`, its `2 count` states (if on) from `start`.
    pub fn new(model: PlatingModel, start: usize, count: usize) -> Self {
        let on = model != PlatingModel::None;
        Self { model, start: on.then_some(start), count: if on { count } else { 0 } }
    }

    /// Number of states it adds.
    pub fn len(&self) -> usize {
        2 * self.count
    }

    /// Indices of its states (empty when off).
    pub fn indices(&self) -> Range<usize> {
        self.start.map_or(0..0, |s| s..s + 2 * self.count)
    }

    /// Net stripping current density `j_Li` (A/m^2, negative while plating) at plated
    /// lithium concentration `c_li` (mol/m^3), plating overpotential `eta` (V) and
    /// electrolyte concentration `c_e` (mol/m^3), temperature `temp` (K).
    ///
    /// Stripping is linear in `c_li` on both sides of zero. PyBaMM clips it at zero
    /// (`max(c_Li, 0)`), so a state that the integrator takes a little below zero stays
    /// there, and near the end of a discharge, where the stripping rate grows as
    /// `exp((1 - alpha) F eta / RT)`, the kink made the SPMe's steps collapse (1C from full
    /// to 2.5 V failed at 3,543 s at rtol 1e-6). Unclipped, a negative excursion decays back
    /// as a positive one does; above zero nothing changes.
    pub fn current(&self, ec: &Electrochem, c_li: f64, eta: f64, c_e: f64, temp: f64) -> f64 {
        let p = &ec.params.plating;
        let f = FARADAY / (GAS_CONSTANT * temp);
        let plating = FARADAY * p.kinetic_rate_constant * c_e.max(0.0) * (-p.transfer_coefficient * f * eta).exp();
        match self.model {
            PlatingModel::None => 0.0,
            PlatingModel::Irreversible => -plating,
            PlatingModel::Reversible | PlatingModel::PartiallyReversible => {
                let stripping = FARADAY * p.kinetic_rate_constant * c_li * ((1.0 - p.transfer_coefficient) * f * eta).exp();
                stripping - plating
            }
        }
    }

    /// The stripping current density `j_Li` (A/m^2) and the rates `[d c_Li / dt, d c_dead /
    /// dt]` (mol/(m^3 s)) at `site` whose plated lithium concentration is `c_li` (mol/m^3),
    /// with the SEI film overpotential `film` (V, `j_tot L_sei R_sei`, zero without SEI),
    /// surface area density `a` (1/m) and temperature `temp` (K).
    pub fn site_rates(&self, ec: &Electrochem, c_li: f64, site: Site, film: f64, a: f64, temp: f64) -> (f64, [f64; 2]) {
        let j = self.current(ec, c_li, site.delta_phi - film, site.electrolyte_concentration, temp);
        let plated = -a * j / FARADAY;
        let rates = match self.model {
            PlatingModel::None => [0.0, 0.0],
            PlatingModel::Irreversible => [0.0, plated],
            PlatingModel::Reversible => [plated, 0.0],
            PlatingModel::PartiallyReversible => {
                let p = &ec.params.plating;
                let decay = p.dead_lithium_decay_constant * ec.params.sei.initial_thickness / site.sei_thickness * c_li;
                [plated - decay, decay]
            }
        };
        (j, rates)
    }

    /// Indices of the plated and the dead lithium state of site `k` (`0..count`), `None`
    /// when off.
    pub fn site_indices(&self, k: usize) -> Option<[usize; 2]> {
        self.start.map(|s| [s + k, s + self.count + k])
    }

    /// Writes the rates of its states into `out` (mol/(m^3 s)), one site per plated-lithium
    /// state, with the SEI film overpotential `film` (V, `j_tot L_sei R_sei`, zero without
    /// SEI), surface area density `a` (1/m) and temperature `temp` (K), and returns the
    /// x-averaged stripping current density `j_Li` (A/m^2) that the negative particle's
    /// intercalation current loses; zero when off.
    pub fn rhs(&self, ec: &Electrochem, y: &[f64], sites: impl Iterator<Item = Site>, film: f64, a: f64, temp: f64, out: &mut [f64]) -> f64 {
        let Some(start) = self.start else { return 0.0 };
        let mut sum = 0.0;
        for (k, site) in (start..start + self.count).zip(sites) {
            let (j, [d_plated, d_dead]) = self.site_rates(ec, y[k], site, film, a, temp);
            out[k] = d_plated;
            out[k + self.count] = d_dead;
            sum += j;
        }
        sum / self.count as f64
    }

    /// Plated and dead lithium (mol): their x-averaged concentrations times `L_n A`; `None`
    /// when off.
    pub fn lithium(&self, ec: &Electrochem, y: &[f64]) -> Option<PlatedLithium> {
        let start = self.start?;
        let volume = ec.params.negative.thickness * ec.area();
        let mean = |r: Range<usize>| y[r].iter().sum::<f64>() / self.count as f64 * volume;
        Some(PlatedLithium { plated_mol: mean(start..start + self.count), dead_mol: mean(start + self.count..start + 2 * self.count) })
    }

    /// Appends its initial states (when on): `c_Li_0` plated, no dead lithium.
    pub fn push_initial(&self, ec: &Electrochem, y: &mut Vec<f64>) {
        y.extend(std::iter::repeat_n(ec.params.plating.initial_concentration, self.count));
        y.extend(std::iter::repeat_n(0.0, self.count));
    }

    /// Appends the typical sizes of its states, `c_Li_typ` (mol/m^3).
    pub fn push_scale(&self, ec: &Electrochem, scale: &mut Vec<f64>) {
        scale.extend(self.indices().map(|_| ec.params.plating.typical_concentration));
    }

    /// Appends its Jacobian pattern: each of its rows reads the negative particle's last two
    /// shells `surface` (through `phi_s - phi_e`), all its states, and `extra` states (the
    /// electrolyte, the SEI, the volume fraction, the temperature); the last shell's row
    /// reads all its states and `extra` (the reaction's flux). (Leaving out the last shell's
    /// dependence on the electrolyte, through `j0_pl = F k c_e`, costs the integrator's
    /// exact conservation of lithium in the SPMe: 7e-11.)
    pub fn push_pattern(&self, pattern: &mut Vec<(usize, usize)>, surface: [usize; 2], extra: &[usize]) {
        if self.start.is_none() {
            return;
        }
        for k in self.indices() {
            pattern.extend(surface.iter().chain(extra).copied().chain(self.indices()).map(|c| (k, c)));
        }
        pattern.extend(self.indices().chain(extra.iter().copied()).map(|c| (surface[1], c)));
    }
}
