//! Loss of active material (LAM), as PyBaMM's `LossActiveMaterial` submodel: with
//! x-averaged states in the single-particle models (its SPM and SPMe), one volume fraction
//! per electrode x volume in the DFN; with the parameters of [`crate::params::Lam`]. See
//! docs/ageing.md.
//!
//! States (when on), after the SEI's: the active material volume fractions `eps_n` of each
//! negative volume and `eps_p` of each positive volume (one each when x-averaged) (-), then
//! the lithium lost with the active material of each electrode (mol), PyBaMM's "Loss of
//! lithium due to loss of active material in negative/positive electrode [mol]". The particle
//! states then hold `n_k = eps c_k`, the lithium per unit electrode volume in shell `k`
//! (mol/m^3), so that particle lithium + lost lithium + SEI lithium is a linear function of
//! the states: the integrator conserves it to round-off.
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
//! - current-driven (throughput-driven), both electrodes: `d eps / dt = -k_I |i|` with the
//!   applied current density `i = I / A` (A/m^2); PyBaMM's "current-driven" option with the
//!   "current-driven LAM rate" function `f(i, T) = -k_I |i|`;
//! - lithium lost: `d Q / dt = -A sum_x dx c_av d eps / dt` (mol/s) over the electrode's
//!   volumes (`-L A c_av d eps / dt` when x-averaged);
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
    /// Proportional to the applied current's magnitude (charge throughput), both electrodes.
    #[serde(rename = "current-driven")]
    CurrentDriven,
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

    /// Whether the applied current drives it.
    pub fn current(self) -> bool {
        self == Self::CurrentDriven
    }
}

/// What drives loss of active material besides the particle's surface stress.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LamDrivers {
    /// Volumetric SEI current `a j_sei` (A/m^3, negative while the SEI grows).
    pub a_j_sei: f64,
    /// Applied current density `I / A` (A/m^2) over the electrode area.
    pub current_density: f64,
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

/// The LAM states of a model: off, or from `start` the volume fractions of `counts[0]`
/// negative and `counts[1]` positive x volumes (one each when x-averaged), then the two
/// electrodes' lithium losses. Methods taking `k` mean the electrode's x volume `k` (0 when
/// x-averaged).
#[derive(Clone, Copy, Debug)]
pub struct LamLayer {
    model: LamModel,
    start: Option<usize>,
    counts: [usize; 2],
}

fn slot(side: Side) -> usize {
    match side {
        Side::Negative => 0,
        Side::Positive => 1,
    }
}

impl LamLayer {
    /// The layer for `model`, its states (if on) from `start`, with `counts` x volumes in
    /// the negative and positive electrodes (`[1, 1]` when x-averaged).
    pub fn new(model: LamModel, start: usize, counts: [usize; 2]) -> Self {
        Self { model, start: (model != LamModel::None).then_some(start), counts }
    }

    /// Number of states it adds.
    pub fn len(&self) -> usize {
        if self.start.is_some() { self.counts[0] + self.counts[1] + 2 } else { 0 }
    }

    /// Indices of its states (empty when off).
    pub fn indices(&self) -> Range<usize> {
        self.start.map_or(0..0, |s| s..s + self.len())
    }

    /// Index of the volume fraction state of an electrode's x volume `k`.
    pub fn fraction_index(&self, side: Side, k: usize) -> Option<usize> {
        self.start.map(|s| s + if side == Side::Negative { k } else { self.counts[0] + k })
    }

    /// Indices of an electrode's volume fraction states (empty when off).
    pub fn fraction_indices(&self, side: Side) -> Range<usize> {
        self.fraction_index(side, 0).map_or(0..0, |s| s..s + self.counts[slot(side)])
    }

    /// Index of the state of the lithium lost with an electrode's active material.
    pub fn loss_index(&self, side: Side) -> Option<usize> {
        self.start.map(|s| s + self.counts[0] + self.counts[1] + slot(side))
    }

    fn params(ec: &Electrochem, side: Side) -> &LamElectrode {
        match side {
            Side::Negative => &ec.params.lam.negative,
            Side::Positive => &ec.params.lam.positive,
        }
    }

    /// Active material volume fraction `eps_s` (-) of an electrode's x volume `k` at state `y`.
    pub fn active_fraction(&self, ec: &Electrochem, side: Side, y: &[f64], k: usize) -> f64 {
        self.fraction_index(side, k).map_or(ec.electrode(side).active_fraction, |i| y[i])
    }

    /// Surface area density `a = 3 eps_s / R` (1/m) of an electrode's x volume `k` at state `y`.
    pub fn surface_area_density(&self, ec: &Electrochem, side: Side, y: &[f64], k: usize) -> f64 {
        match self.fraction_index(side, k) {
            None => ec.electrode(side).surface_area_density(),
            Some(i) => 3.0 * y[i] / ec.electrode(side).particle_radius,
        }
    }

    /// Electrode-averaged total interfacial current density `I / (a L A)` (A/m^2, positive
    /// in the negative electrode on discharge) of an x-averaged model at state `y` and
    /// applied current `current` (A).
    pub fn interfacial_current(&self, ec: &Electrochem, side: Side, y: &[f64], current: f64) -> f64 {
        let j = ec.mean_interfacial_current(side, current);
        self.fraction_index(side, 0).map_or(j, |i| j * ec.electrode(side).active_fraction / y[i])
    }

    /// Shell concentrations `c_k` (mol/m^3) of the particle of an electrode's x volume `k`
    /// whose states are `shells`: the states themselves when off, `n_k / eps` when on.
    pub fn concentrations<'a>(&self, side: Side, y: &[f64], shells: &'a [f64], k: usize) -> Cow<'a, [f64]> {
        match self.fraction_index(side, k) {
            None => Cow::Borrowed(shells),
            Some(i) => Cow::Owned(shells.iter().map(|n| n / y[i]).collect()),
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

    /// Lithium (mol) in the particles of an electrode's slab of thickness `thickness` (m,
    /// the electrode's when x-averaged) whose states are `shells`.
    pub fn particle_lithium(&self, ec: &Electrochem, side: Side, shells: &[f64], thickness: f64) -> f64 {
        match self.start {
            None => ec.particle_lithium(side, shells, thickness),
            Some(_) => ec.sphere(side).average(shells) * thickness * ec.area(),
        }
    }

    /// Lithium lost with the active material of an electrode since the start (mol); zero off.
    pub fn lithium_lost(&self, side: Side, y: &[f64]) -> f64 {
        self.loss_index(side).map_or(0.0, |i| y[i])
    }

    /// The electrodes' active material at state `y` (the volume fractions averaged over the
    /// electrode's uniform x volumes, as the initial value plus the mean change, so that an
    /// electrode that lost nothing reports its initial fraction exactly); `None` when off.
    pub fn summary(&self, ec: &Electrochem, y: &[f64]) -> Option<ActiveMaterial> {
        self.start?;
        let sides = [Side::Negative, Side::Positive];
        let fraction = sides.map(|side| {
            let eps_0 = ec.electrode(side).active_fraction;
            eps_0 + y[self.fraction_indices(side)].iter().map(|eps| eps - eps_0).sum::<f64>() / self.counts[slot(side)] as f64
        });
        let capacity_ah = sides.map(|side| {
            let e = ec.electrode(side);
            fraction[slot(side)] * e.thickness * ec.area() * e.max_concentration * FARADAY / 3600.0
        });
        Some(ActiveMaterial { fraction, capacity_ah, lithium_lost_mol: sides.map(|side| self.lithium_lost(side, y)) })
    }

    /// `d eps_s / dt` (1/s) of an electrode's particle with shell concentrations `c`
    /// (mol/m^3), driven also by `drivers`.
    fn fraction_rate(&self, ec: &Electrochem, side: Side, c: &[f64], drivers: LamDrivers) -> f64 {
        let p = Self::params(ec, side);
        let mut rate = 0.0;
        if self.model.stress() {
            let sphere = ec.sphere(side);
            let hydrostatic = 2.0 * p.surface_tangential_stress(sphere.average(c), sphere.surface(c)) / 3.0;
            rate -= p.proportional_term * (hydrostatic.max(0.0) / p.critical_stress).powf(p.exponential_term);
        }
        if self.model.reaction() && side == Side::Negative {
            rate += p.reaction_factor * drivers.a_j_sei / FARADAY;
        }
        if self.model.current() {
            rate -= p.current_rate * drivers.current_density.abs();
        }
        rate
    }

    /// Writes the rates of the states of an x-averaged model into `out` from the two
    /// electrodes' shell concentrations `c` (mol/m^3) and `drivers` (with the x-averaged
    /// volumetric SEI current), and returns `d eps_s / dt` of each electrode (zeros when off).
    pub fn rhs(&self, ec: &Electrochem, c: [&[f64]; 2], drivers: LamDrivers, out: &mut [f64]) -> [f64; 2] {
        [Side::Negative, Side::Positive].map(|side| {
            let (Some(fraction), Some(loss)) = (self.fraction_index(side, 0), self.loss_index(side)) else { return 0.0 };
            let (rate, lost) = self.volume_rates(ec, side, c[slot(side)], drivers, ec.electrode(side).thickness);
            (out[fraction], out[loss]) = (rate, lost);
            rate
        })
    }

    /// `d eps_s / dt` (1/s) of an electrode's x volume of thickness `dx` (m) from its
    /// particle's shell concentrations `c` (mol/m^3) and `drivers` (with its own volumetric
    /// SEI current), and the rate (mol/s) at which it loses lithium with its active material,
    /// `-dx A c_av d eps_s / dt`.
    pub fn volume_rates(&self, ec: &Electrochem, side: Side, c: &[f64], drivers: LamDrivers, dx: f64) -> (f64, f64) {
        let rate = self.fraction_rate(ec, side, c, drivers);
        (rate, -dx * ec.area() * ec.sphere(side).average(c) * rate)
    }

    /// Writes the particle states' rates of an electrode into `out`: diffusion of the shell
    /// concentrations `c` (mol/m^3) at temperature `temp` (K) with outward molar surface
    /// flux `flux` (mol/(m^2 s)), stress-induced when the submodels say so; then, when on, the
    /// rates of `n = eps c` with `d eps / dt` = `rate` (1/s) of x volume `k` at state `y`.
    #[allow(clippy::too_many_arguments)]
    pub fn particle_rhs(&self, ec: &Electrochem, side: Side, k: usize, y: &[f64], c: &[f64], flux: f64, rate: f64, temp: f64, out: &mut [f64]) {
        let p = Self::params(ec, side);
        let stress = ec.submodels.stressed_diffusion().then(|| (p.stress_diffusion_coefficient(temp), p.reference_concentration));
        ec.sphere(side).stressed_diffusion(c, ec.diffusivity(side, temp), stress, flux, out);
        if let Some(i) = self.fraction_index(side, k) {
            let eps = y[i];
            for (o, c) in out.iter_mut().zip(c) {
                *o = eps * *o + c * rate;
            }
        }
    }

    /// Its states (when on) in order, from each electrode's `fraction` (the volume fractions)
    /// and `lithium` (the losses).
    fn states(&self, ec: &Electrochem, fraction: impl Fn(&crate::params::Electrode) -> f64, lithium: impl Fn(&crate::params::Electrode) -> f64) -> Vec<f64> {
        if self.start.is_none() {
            return Vec::new();
        }
        let (n, p) = (&ec.params.negative, &ec.params.positive);
        let mut v = vec![fraction(n); self.counts[0]];
        v.extend(std::iter::repeat_n(fraction(p), self.counts[1]));
        v.extend([lithium(n), lithium(p)]);
        v
    }

    /// Appends its initial states (when on) to `y`: the parameter set's volume fractions and
    /// no lithium lost.
    pub fn push_initial(&self, ec: &Electrochem, y: &mut Vec<f64>) {
        y.extend(self.states(ec, |e| e.active_fraction, |_| 0.0));
    }

    /// Appends the typical sizes of its states: the volume fractions, and each electrode's
    /// initial particle lithium (mol) for its loss.
    pub fn push_scale(&self, ec: &Electrochem, scale: &mut Vec<f64>) {
        scale.extend(self.states(ec, |e| e.active_fraction, |e| e.active_fraction * e.initial_concentration * e.thickness * ec.area()));
    }

    /// Appends its Jacobian pattern, given each electrode's particle states `shells` and
    /// `extra` states its rates read (the SEI's states and inputs, the temperature): its
    /// rows and its electrode's particle rows (through `c_k d eps / dt`) read all that
    /// electrode's shells, its volume fraction and `extra`. (Leaving out the weak couplings
    /// of `c_k d eps / dt` costs the integrator's exact conservation of lithium: 6e-10.)
    pub fn push_pattern(&self, pattern: &mut Vec<(usize, usize)>, shells: [Range<usize>; 2], extra: &[usize]) {
        for (side, range) in [Side::Negative, Side::Positive].into_iter().zip(shells) {
            let (Some(fraction), Some(loss)) = (self.fraction_index(side, 0), self.loss_index(side)) else { return };
            let columns: Vec<usize> = range.clone().chain([fraction]).chain(extra.iter().copied()).collect();
            for row in range.chain([fraction, loss]) {
                pattern.extend(columns.iter().map(|&c| (row, c)));
            }
        }
    }
}
