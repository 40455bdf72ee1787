//! SEI growth on the negative electrode of the single-particle models, as PyBaMM's SPM and
//! SPMe do it: the SEI concentration `c_sei` (mol per m^3 of electrode), one state for the
//! whole electrode in the SPM ("x-average side reactions" true) and one per negative x volume
//! in the SPMe (PyBaMM's default "false" there), with the parameters of
//! [`crate::params::Sei`]. See docs/ageing.md.
//!
//! - thickness `L = c_sei V_bar / a` (m), `a = 3 eps_s / R` the negative surface area density
//!   (which follows `eps_s` under loss of active material: the model passes it in, with the
//!   total interfacial current density `j_tot`);
//! - film overpotential: the x-averaged `phi_s - phi_e` of the negative electrode gains
//!   `j_tot L_av R_sei` (V, `L_av` the x-averaged thickness), `j_tot` the total interfacial
//!   current density (A/m^2, the applied current over `a L_n A`);
//! - side-reaction current density `j_sei` (A/m^2, negative while SEI grows), times
//!   `exp(E_sei / R (1/T_ref - 1/T))`:
//!   reaction limited `-j0_sei exp(-0.5 F eta_sei / (R T))` with
//!   `eta_sei = phi_s - phi_e - U_sei - j_tot L R_sei` with the local `phi_s - phi_e` and `L`;
//!   solvent-diffusion limited `-D_sol c_sol F / L`;
//!   electron-migration limited `kappa_inner min(delta_phi - U_sei, 0) / L`;
//!   interstitial-diffusion limited `-(D_li c_li_0 F / L) exp(-F delta_phi / (R T))`;
//!   EC reaction limited `-F c_ec_0 k / (1 + L k / D_ec)` with
//!   `k = k_sei exp(-0.5 F eta_sei / (R T))`;
//! - `d c_sei / dt = -a j_sei / (F z_sei)`; the particles carry the intercalation current
//!   `j_tot - j_sei` (`j_sei` x-averaged), so the lithium the SEI takes comes out of the negative particles and
//!   the applied current is unchanged.

use serde::{Deserialize, Serialize};

use crate::models::Electrochem;
use crate::models::kinetics::arrhenius;
use crate::params::{FARADAY, GAS_CONSTANT};

/// Which SEI growth law, by PyBaMM's option names.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum SeiModel {
    /// No SEI growth (no state, no film).
    #[default]
    #[serde(rename = "none")]
    None,
    /// Growth limited by the side reaction's (symmetric) Butler-Volmer kinetics.
    #[serde(rename = "reaction limited")]
    ReactionLimited,
    /// Growth limited by the solvent's diffusion through the layer.
    #[serde(rename = "solvent-diffusion limited")]
    SolventDiffusionLimited,
    /// Growth limited by electrons migrating through the layer (a film conductor).
    #[serde(rename = "electron-migration limited")]
    ElectronMigrationLimited,
    /// Growth limited by lithium interstitials diffusing through the layer.
    #[serde(rename = "interstitial-diffusion limited")]
    InterstitialDiffusionLimited,
    /// Ethylene carbonate reacting at the surface after diffusing through the layer
    /// (Yang 2017): kinetics and diffusion in series.
    #[serde(rename = "ec reaction limited")]
    EcReactionLimited,
}

/// The SEI layer of a single-particle model: off, or `count` states from `start`, one per
/// negative x volume (one for the whole electrode when x-averaged).
#[derive(Clone, Copy, Debug)]
pub struct SeiLayer {
    model: SeiModel,
    start: Option<usize>,
    count: usize,
}

impl SeiLayer {
    /// The layer for `model`, its `count` states (if on) from `start`.
    pub fn new(model: SeiModel, start: usize, count: usize) -> Self {
        let on = model != SeiModel::None;
        Self { model, start: on.then_some(start), count: if on { count } else { 0 } }
    }

    /// Number of states it adds.
    pub fn len(&self) -> usize {
        self.count
    }

    /// Indices of its states (empty when off).
    pub fn indices(&self) -> std::ops::Range<usize> {
        self.start.map_or(0..0, |s| s..s + self.count)
    }

    /// Initial SEI concentration `L_sei_0 a / V_bar` (mol/m^3), also its typical size.
    pub fn initial_concentration(ec: &Electrochem) -> f64 {
        let s = &ec.params.sei;
        s.initial_thickness * ec.params.negative.surface_area_density() / s.partial_molar_volume
    }

    /// Thickness (m) for SEI concentration `c` (mol/m^3) on surface area density `a` (1/m).
    fn thickness_of(ec: &Electrochem, c: f64, a: f64) -> f64 {
        c * ec.params.sei.partial_molar_volume / a
    }

    /// Mean SEI concentration over its states (mol/m^3).
    fn mean_concentration(&self, y: &[f64]) -> f64 {
        y[self.indices()].iter().sum::<f64>() / self.count as f64
    }

    /// x-averaged SEI thickness (m) on negative surface area density `a` (1/m), `None` when
    /// off.
    pub fn thickness(&self, ec: &Electrochem, y: &[f64], a: f64) -> Option<f64> {
        self.start.map(|_| Self::thickness_of(ec, self.mean_concentration(y), a))
    }

    /// Film overpotential `j_tot L R_sei` (V) with the x-averaged thickness `L`, that the
    /// x-averaged `phi_s - phi_e` of the negative electrode gains at total interfacial
    /// current density `j_tot` (A/m^2) on surface area density `a` (1/m); zero when off.
    pub fn film(&self, ec: &Electrochem, y: &[f64], j_tot: f64, a: f64) -> f64 {
        self.thickness(ec, y, a).map_or(0.0, |l| j_tot * l * ec.params.sei.resistivity)
    }

    /// Side-reaction current density `j_sei` (A/m^2, negative while the SEI grows) of a
    /// layer of thickness `l` (m) at its `phi_s - phi_e` = `delta_phi` (V).
    fn current_at(&self, ec: &Electrochem, l: f64, delta_phi: f64, j_tot: f64, temp: f64) -> f64 {
        let s = &ec.params.sei;
        let f_rt = FARADAY / (GAS_CONSTANT * temp);
        // The side reaction's overpotential, past the film's drop.
        let eta_sei = || delta_phi - s.open_circuit_potential - j_tot * l * s.resistivity;
        let j = match self.model {
            SeiModel::None => 0.0,
            SeiModel::ReactionLimited => -s.exchange_current * (-0.5 * f_rt * eta_sei()).exp(),
            SeiModel::SolventDiffusionLimited => -s.solvent_diffusivity * s.solvent_concentration * FARADAY / l,
            SeiModel::ElectronMigrationLimited => {
                let eta_inner = delta_phi - s.open_circuit_potential;
                if eta_inner < 0.0 { s.electron_conductivity * eta_inner / l } else { 0.0 }
            }
            SeiModel::InterstitialDiffusionLimited => {
                -s.interstitial_diffusivity * s.interstitial_concentration * FARADAY / l * (-f_rt * delta_phi).exp()
            }
            SeiModel::EcReactionLimited => {
                let k = s.kinetic_rate_constant * (-0.5 * f_rt * eta_sei()).exp();
                -FARADAY * s.ec_concentration * k / (1.0 + l / s.ec_diffusivity * k)
            }
        };
        j * arrhenius(s.activation_energy, ec.t_ref(), temp)
    }

    /// Thickness (m) of the layer in state `k` (an index into `y`) on surface area density
    /// `a` (1/m).
    pub fn local_thickness(ec: &Electrochem, y: &[f64], k: usize, a: f64) -> f64 {
        Self::thickness_of(ec, y[k], a)
    }

    /// Thickness (m) of the layer of negative x volume `i` (of the whole electrode when
    /// x-averaged) on surface area density `a` (1/m); `L_sei_0` when off (PyBaMM's
    /// "constant" SEI, which its partially reversible plating reads).
    pub fn volume_thickness(&self, ec: &Electrochem, y: &[f64], i: usize, a: f64) -> f64 {
        self.start.map_or(ec.params.sei.initial_thickness, |s| Self::thickness_of(ec, y[s + i], a))
    }

    /// Side-reaction current density `j_sei` (A/m^2) of the layer in state `k` (an index
    /// into `y`) at `phi_s - phi_e` = `delta_phi` (V), with the film carrying current density
    /// `j_film` (A/m^2: the total in the single-particle models, the intercalation current in
    /// the DFN, as PyBaMM's), on surface area density `a` (1/m) at temperature `temp` (K).
    pub fn side_current(&self, ec: &Electrochem, y: &[f64], k: usize, delta_phi: f64, j_film: f64, a: f64, temp: f64) -> f64 {
        self.current_at(ec, Self::thickness_of(ec, y[k], a), delta_phi, j_film, temp)
    }

    /// `d c_sei / dt` (mol/(m^3 s)) of side-reaction current density `j_sei` (A/m^2) on
    /// surface area density `a` (1/m).
    pub fn growth_rate(ec: &Electrochem, a: f64, j_sei: f64) -> f64 {
        -a * j_sei / (FARADAY * ec.params.sei.lithium_per_sei)
    }

    /// Writes `d c_sei / dt` (mol/(m^3 s)) of each state into `out`, given `phi_s - phi_e`
    /// (V) at each (one per state, film included), the total interfacial current density
    /// `j_tot` (A/m^2) and surface area density `a` (1/m), and returns the x-averaged
    /// side-reaction current density (A/m^2) that the negative particle's intercalation
    /// current loses; zero when off.
    pub fn rhs(&self, ec: &Electrochem, y: &[f64], delta_phi: impl Iterator<Item = f64>, j_tot: f64, a: f64, temp: f64, out: &mut [f64]) -> f64 {
        if self.start.is_none() {
            return 0.0;
        }
        let mut sum = 0.0;
        for (k, d) in self.indices().zip(delta_phi) {
            let j = self.side_current(ec, y, k, d, j_tot, a, temp);
            out[k] = Self::growth_rate(ec, a, j);
            sum += j;
        }
        sum / self.count as f64
    }

    /// Lithium bound in the SEI (mol): `z_sei c_sei L_n A` with `c_sei` x-averaged; zero
    /// when off.
    pub fn lithium(&self, ec: &Electrochem, y: &[f64]) -> f64 {
        self.start.map_or(0.0, |_| ec.params.sei.lithium_per_sei * self.mean_concentration(y) * ec.params.negative.thickness * ec.area())
    }

    /// Appends its initial states (when on) to `y`.
    pub fn push_initial(&self, ec: &Electrochem, y: &mut Vec<f64>) {
        y.extend(self.indices().map(|_| Self::initial_concentration(ec)));
    }

    /// Appends its Jacobian pattern: each of its rows reads the negative particle's last two
    /// shells `surface` (through `phi_s - phi_e`), all its states (the film), and `extra`
    /// states (the electrolyte or the temperature); the last shell's row reads them and the
    /// `extra` states (the side reaction's flux).
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
