//! Loss of active material (LAM) in the single-particle models, as PyBaMM's
//! `LossActiveMaterial` submodel with x-averaged states (its SPM and SPMe), with the
//! parameters of [`crate::params::Lam`]. See docs/ageing.md.
//!
//! States (when on), after the SEI's: the active material volume fractions `eps_n`, `eps_p`
//! (-), then the lithium lost with the active material of each electrode (mol), PyBaMM's
//! "Loss of lithium due to loss of active material in negative/positive electrode [mol]".
//! The particle states then hold `n_k = eps c_k`, the lithium per unit electrode volume in
//! shell `k` (mol/m^3), so that particle lithium + lost lithium + SEI lithium is a linear
//! function of the states: the integrator conserves it to round-off.
//!
//! - surface area density `a = 3 eps / R` (1/m) and total interfacial current density
//!   `j_tot = I / (a L A)` (A/m^2) follow `eps`;
//! - stress-driven: `d eps / dt = -beta_LAM (max(sigma_h, 0) / sigma_c)^m_LAM`, with the
//!   hydrostatic surface stress `sigma_h = 2 sigma_t / 3` (the radial one is zero at the
//!   surface), `sigma_t = Omega E (c_av - c_surf) / (3 (1 - nu))`; the particle diffusivity
//!   becomes `D (1 + theta_M (c - c_0))`, `theta_M = Omega / (R T) 2 Omega E / (9 (1 - nu))`
//!   (PyBaMM's "stress-induced diffusion", on by default with stress-driven LAM, off with
//!   `stress_induced_diffusion = false`);
//! - reaction-driven (negative electrode, needs an SEI submodel):
//!   `d eps_n / dt = beta_LAM_sei a j_sei / F` (`j_sei` < 0 while the SEI grows);
//! - lithium lost: `d Q / dt = -L A c_av d eps / dt` (mol/s);
//! - particles: `d n_k / dt = eps (d c_k / dt)_diffusion + c_k d eps / dt` with `c = n / eps`
//!   and the surface flux `(j_tot - j_side) / F`.

use std::borrow::Cow;
use std::ops::Range;

use serde::{Deserialize, Serialize};

use crate::models::Electrochem;
use crate::models::electrochem::Side;
use crate::params::{FARADAY, LamElectrode};

/// Which LAM law, by PyBaMM's option names ("loss of active material").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum LamModel {
    /// No loss of active material (no states).
    #[default]
    #[serde(rename = "none")]
    None,
    /// Driven by the particles' surface stress, both electrodes; with stress-induced diffusion
    /// unless `Submodels::stress_induced_diffusion` is `Some(false)`.
    #[serde(rename = "stress-driven")]
    StressDriven,
    /// Driven by the SEI side reaction, negative electrode (needs an SEI submodel).
    #[serde(rename = "reaction-driven")]
    ReactionDriven,
    /// The sum of both.
    #[serde(rename = "stress and reaction-driven")]
    StressAndReactionDriven,
}

impl LamModel {
    /// Whether the surface stress drives it.
    pub fn stress(self) -> bool {
        matches!(self, Self::StressDriven | Self::StressAndReactionDriven)
    }

    /// Whether the SEI reaction drives it.
    pub fn reaction(self) -> bool {
        matches!(self, Self::ReactionDriven | Self::StressAndReactionDriven)
    }
}

/// What loss of active material has done to the electrodes, at one state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ActiveMaterial {
    /// Active material volume fractions `eps_s` of the negative and positive electrodes (-).
    pub fraction: [f64; 2],
    /// Electrode capacities `eps_s L A c_max F / 3600` (A h), PyBaMM's "Negative/Positive
    /// electrode capacity [A.h]".
    pub capacity_ah: [f64; 2],
    /// Lithium lost with each electrode's active material since the start (mol).
    pub lithium_lost_mol: [f64; 2],
}

/// Number of states when on: two volume fractions, two lithium losses.
const STATES: usize = 4;

/// The LAM states of a single-particle model: off, or [`STATES`] states from `start`.
#[derive(Clone, Copy, Debug)]
pub struct LamLayer {
    model: LamModel,
    start: Option<usize>,
}

fn slot(side: Side) -> usize {
    match side {
        Side::Negative => 0,
        Side::Positive => 1,
    }
}

impl LamLayer {
    /// The layer for `model`, its states (if on) from `start`.
    pub fn new(model: LamModel, start: usize) -> Self {
        Self { model, start: (model != LamModel::None).then_some(start) }
    }

    /// Number of states it adds.
    pub fn len(&self) -> usize {
        if self.start.is_some() { STATES } else { 0 }
    }

    /// Indices of its states (empty when off).
    pub fn indices(&self) -> Range<usize> {
        self.start.map_or(0..0, |s| s..s + STATES)
    }

    /// Index of an electrode's volume fraction state.
    fn fraction_index(&self, side: Side) -> Option<usize> {
        self.start.map(|s| s + slot(side))
    }

    fn params(ec: &Electrochem, side: Side) -> &LamElectrode {
        match side {
            Side::Negative => &ec.params.lam.negative,
            Side::Positive => &ec.params.lam.positive,
        }
    }

    /// Active material volume fraction `eps_s` (-) of an electrode at state `y`.
    pub fn active_fraction(&self, ec: &Electrochem, side: Side, y: &[f64]) -> f64 {
        self.fraction_index(side).map_or(ec.electrode(side).active_fraction, |k| y[k])
    }

    /// Surface area density `a = 3 eps_s / R` (1/m) of an electrode at state `y`.
    pub fn surface_area_density(&self, ec: &Electrochem, side: Side, y: &[f64]) -> f64 {
        match self.fraction_index(side) {
            None => ec.electrode(side).surface_area_density(),
            Some(k) => 3.0 * y[k] / ec.electrode(side).particle_radius,
        }
    }

    /// Electrode-averaged total interfacial current density `I / (a L A)` (A/m^2, positive
    /// in the negative electrode on discharge) at state `y` and applied current `current` (A).
    pub fn interfacial_current(&self, ec: &Electrochem, side: Side, y: &[f64], current: f64) -> f64 {
        let j = ec.mean_interfacial_current(side, current);
        self.fraction_index(side).map_or(j, |k| j * ec.electrode(side).active_fraction / y[k])
    }

    /// Shell concentrations `c_k` (mol/m^3) of an electrode's particle whose states are
    /// `shells`: the states themselves when off, `n_k / eps` when on.
    pub fn concentrations<'a>(&self, side: Side, y: &[f64], shells: &'a [f64]) -> Cow<'a, [f64]> {
        match self.fraction_index(side) {
            None => Cow::Borrowed(shells),
            Some(k) => Cow::Owned(shells.iter().map(|n| n / y[k]).collect()),
        }
    }

    /// Initial particle states of an electrode: `c_0` (mol/m^3) when off, `eps_0 c_0` on.
    pub fn initial_shell(&self, ec: &Electrochem, side: Side) -> f64 {
        let e = ec.electrode(side);
        if self.start.is_some() { e.active_fraction * e.initial_concentration } else { e.initial_concentration }
    }

    /// Typical size of an electrode's particle states (mol/m^3): `c_max`, times `eps_0` on.
    pub fn shell_scale(&self, ec: &Electrochem, side: Side) -> f64 {
        let e = ec.electrode(side);
        if self.start.is_some() { e.active_fraction * e.max_concentration } else { e.max_concentration }
    }

    /// Lithium (mol) in an electrode's particles whose states are `shells`.
    pub fn particle_lithium(&self, ec: &Electrochem, side: Side, shells: &[f64]) -> f64 {
        let e = ec.electrode(side);
        match self.start {
            None => ec.particle_lithium(side, shells, e.thickness),
            Some(_) => ec.sphere(side).average(shells) * e.thickness * ec.area(),
        }
    }

    /// Lithium lost with the active material of an electrode since the start (mol); zero off.
    pub fn lithium_lost(&self, side: Side, y: &[f64]) -> f64 {
        self.start.map_or(0.0, |s| y[s + 2 + slot(side)])
    }

    /// The electrodes' active material at state `y`; `None` when off.
    pub fn summary(&self, ec: &Electrochem, y: &[f64]) -> Option<ActiveMaterial> {
        self.start?;
        let sides = [Side::Negative, Side::Positive];
        let fraction = sides.map(|side| self.active_fraction(ec, side, y));
        let capacity_ah = sides.map(|side| {
            let e = ec.electrode(side);
            self.active_fraction(ec, side, y) * e.thickness * ec.area() * e.max_concentration * FARADAY / 3600.0
        });
        Some(ActiveMaterial { fraction, capacity_ah, lithium_lost_mol: sides.map(|side| self.lithium_lost(side, y)) })
    }

    /// `d eps_s / dt` (1/s) of an electrode with shell concentrations `c` (mol/m^3), and
    /// x-averaged volumetric SEI current `a_j_sei` (A/m^3, negative while the SEI grows).
    fn fraction_rate(&self, ec: &Electrochem, side: Side, c: &[f64], a_j_sei: f64) -> f64 {
        let p = Self::params(ec, side);
        let mut rate = 0.0;
        if self.model.stress() {
            let sphere = ec.sphere(side);
            let hydrostatic = 2.0 * p.surface_tangential_stress(sphere.average(c), sphere.surface(c)) / 3.0;
            rate -= p.proportional_term * (hydrostatic.max(0.0) / p.critical_stress).powf(p.exponential_term);
        }
        if self.model.reaction() && side == Side::Negative {
            rate += p.reaction_factor * a_j_sei / FARADAY;
        }
        rate
    }

    /// Writes the rates of its states into `out` from the two electrodes' shell
    /// concentrations `c` (mol/m^3) and the x-averaged volumetric SEI current `a_j_sei`
    /// (A/m^3), and returns `d eps_s / dt` of each electrode (zeros when off).
    pub fn rhs(&self, ec: &Electrochem, c: [&[f64]; 2], a_j_sei: f64, out: &mut [f64]) -> [f64; 2] {
        let Some(start) = self.start else { return [0.0; 2] };
        let mut rates = [0.0; 2];
        for (k, side) in [Side::Negative, Side::Positive].into_iter().enumerate() {
            let rate = self.fraction_rate(ec, side, c[k], a_j_sei);
            out[start + k] = rate;
            out[start + 2 + k] = -ec.electrode(side).thickness * ec.area() * ec.sphere(side).average(c[k]) * rate;
            rates[k] = rate;
        }
        rates
    }

    /// Writes the particle states' rates of an electrode into `out`: diffusion of the shell
    /// concentrations `c` (mol/m^3) at temperature `temp` (K) with outward molar surface
    /// flux `flux` (mol/(m^2 s)), stress-induced when the submodels say so; then, when on, the
    /// rates of `n = eps c` with `d eps / dt` = `rate` (1/s) at state `y`.
    pub fn particle_rhs(&self, ec: &Electrochem, side: Side, y: &[f64], c: &[f64], flux: f64, rate: f64, temp: f64, out: &mut [f64]) {
        let p = Self::params(ec, side);
        let stress = ec.submodels.stressed_diffusion().then(|| (p.stress_diffusion_coefficient(temp), p.reference_concentration));
        ec.sphere(side).stressed_diffusion(c, ec.diffusivity(side, temp), stress, flux, out);
        if let Some(k) = self.fraction_index(side) {
            let eps = y[k];
            for (o, c) in out.iter_mut().zip(c) {
                *o = eps * *o + c * rate;
            }
        }
    }

    /// Appends its initial states (when on) to `y`: the parameter set's volume fractions and
    /// no lithium lost.
    pub fn push_initial(&self, ec: &Electrochem, y: &mut Vec<f64>) {
        if self.start.is_some() {
            y.extend([ec.params.negative.active_fraction, ec.params.positive.active_fraction, 0.0, 0.0]);
        }
    }

    /// Appends the typical sizes of its states: the volume fractions, and each electrode's
    /// initial particle lithium (mol) for its loss.
    pub fn push_scale(&self, ec: &Electrochem, scale: &mut Vec<f64>) {
        if self.start.is_some() {
            let p = &ec.params;
            let lithium = |e: &crate::params::Electrode| e.active_fraction * e.initial_concentration * e.thickness * ec.area();
            scale.extend([p.negative.active_fraction, p.positive.active_fraction, lithium(&p.negative), lithium(&p.positive)]);
        }
    }

    /// Appends its Jacobian pattern, given each electrode's particle states `shells` and
    /// `extra` states its rates read (the SEI's states and inputs, the temperature): its
    /// rows and its electrode's particle rows (through `c_k d eps / dt`) read all that
    /// electrode's shells, its volume fraction and `extra`. (Leaving out the weak couplings
    /// of `c_k d eps / dt` costs the integrator's exact conservation of lithium: 6e-10.)
    pub fn push_pattern(&self, pattern: &mut Vec<(usize, usize)>, shells: [Range<usize>; 2], extra: &[usize]) {
        let Some(start) = self.start else { return };
        for (k, range) in shells.into_iter().enumerate() {
            let fraction = start + k;
            let columns: Vec<usize> = range.clone().chain([fraction]).chain(extra.iter().copied()).collect();
            for row in range.chain([fraction, start + 2 + k]) {
                pattern.extend(columns.iter().map(|&c| (row, c)));
            }
        }
    }
}
