//! Battery models sharing one state/output interface: SPM, SPMe, DFN and a Thevenin ECM,
//! with switchable submodels (contact resistance, lumped thermal, SEI growth, loss of active
//! material, lithium plating).

pub mod builder;
pub mod dfn;
pub mod ecm;

pub mod electrochem;
pub mod electrolyte;
pub mod fields;
pub mod kinetics;
pub mod mpm;
pub mod pool;
pub mod spm;
pub mod spme;
pub mod submodels;

use serde::{Deserialize, Serialize};

pub use builder::ModelBuilder;
pub use electrochem::Electrochem;
pub use fields::Field;
pub use pool::BuilderPool;

use crate::params::ParameterSet;

/// Which physics-based model to build.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ModelKind {
    /// Single particle model.
    Spm,
    /// Single particle model with electrolyte.
    Spme,
    /// Doyle-Fuller-Newman pseudo-two-dimensional model.
    Dfn,
}

impl std::str::FromStr for ModelKind {
    type Err = crate::error::Error;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "spm" => Ok(ModelKind::Spm),
            "spme" => Ok(ModelKind::Spme),
            "dfn" => Ok(ModelKind::Dfn),
            other => Err(crate::error::Error::InvalidSetting {
                field: "model".into(),
                reason: format!("unknown model `{other}` (expected spm, spme or dfn)"),
            }),
        }
    }
}

impl std::fmt::Display for ModelKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ModelKind::Spm => "SPM",
            ModelKind::Spme => "SPMe",
            ModelKind::Dfn => "DFN",
        })
    }
}

/// Optional submodels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Submodels {
    /// Series contact resistance `cell.contact_resistance` (ohm).
    pub contact_resistance: bool,
    /// Lumped (0-D) thermal model with Arrhenius-dependent diffusivities and rate constants.
    pub thermal: bool,
    /// Series RC element (`cell.rc_resistance`, `cell.rc_capacitance`): one extra state.
    pub rc: bool,
    /// One-state OCV hysteresis (`cell.hysteresis_voltage`, `cell.hysteresis_rate`,
    /// `cell.hysteresis_initial`): one extra state.
    pub hysteresis: bool,
    /// A leak (`cell.leakage_current`): the model's electrochemistry carries the recorded
    /// current plus the leak, the cycler sees only the former; no extra state.
    pub leak: bool,
    /// A constant `cell.voltage_offset` added to the terminal voltage; no extra state.
    pub voltage_offset: bool,
    /// The voltage channel's scale error `cell.voltage_gain`: the terminal voltage is read
    /// `1 + g` times the cell's; no extra state.
    pub voltage_gain: bool,
    /// The current channel's scale error `cell.current_gain`: the cell carries the recorded
    /// current over `1 + g`; no extra state.
    pub current_gain: bool,
    /// The correction `cell.ocv_correction` to the open-circuit voltage, against the charge
    /// passed: one extra state (that charge).
    pub ocv_correction: bool,
    /// SEI growth on the negative electrode (`sei` parameters): one extra state in the SPM,
    /// one per negative x volume in the SPMe, two per negative x volume in the DFN (with the
    /// total interfacial current density).
    pub sei: submodels::SeiModel,
    /// Loss of active material (`lam` parameters): four extra states (volume fraction and
    /// lithium lost per electrode) in the SPM and SPMe, a volume fraction per electrode x
    /// volume and the two losses in the DFN; "reaction-driven" needs `sei`.
    pub lam: submodels::LamModel,
    /// Lithium plating on the negative electrode (`plating` parameters): two extra states
    /// (plated and dead lithium) in the SPM, two per negative x volume in the SPMe and DFN.
    pub plating: submodels::PlatingModel,
    /// PyBaMM's "stress-induced diffusion" under stress-driven LAM: `None` follows PyBaMM (on
    /// with stress-driven LAM), `Some(false)` keeps the particle diffusivities unstressed.
    pub stress_induced_diffusion: Option<bool>,
    /// PyBaMM's "particle size": `Distribution` gives each electrode a lognormal
    /// distribution of particle radii (`negative.radius_relative_std`,
    /// `positive.radius_relative_std`; `mesh.size_n`, `mesh.size_p` classes), each class its
    /// own particle, all sharing the electrode's potential (PyBaMM's MPM). SPM only.
    pub particle_size: submodels::ParticleSize,
}

impl Submodels {
    /// Checks the submodels go together; the error names `model.submodels.NAME`. (Every
    /// submodel but the particle-size distribution is built on the SPM, SPMe and DFN; the
    /// builder refuses that one on another model.)
    pub fn check(&self) -> Result<(), crate::error::Error> {
        use submodels::SeiModel;
        let invalid = |name: &str, reason: String| crate::error::Error::InvalidSetting { field: format!("model.submodels.{name}"), reason };
        if self.stress_induced_diffusion == Some(true) && !self.lam.stress() {
            return Err(invalid("stress_induced_diffusion", format!("true needs a stress-driven loss of active material (lam = \"stress-driven\"), not {:?}", self.lam)));
        }
        if self.particle_size == submodels::ParticleSize::Distribution {
            let others = [("sei", self.sei != SeiModel::None), ("lam", self.lam != submodels::LamModel::None), ("plating", self.plating != submodels::PlatingModel::None)];
            if let Some((name, _)) = others.iter().find(|(_, on)| *on) {
                return Err(invalid("particle_size", format!("\"distribution\" is not built with the {name} submodel (only with contact resistance, thermal and the voltage-level submodels)")));
            }
        }
        if self.lam.reaction() && self.sei == SeiModel::None {
            return Err(invalid("lam", format!("{:?} loss of active material is driven by the SEI reaction: it needs an SEI submodel (e.g. sei = \"reaction limited\")", self.lam)));
        }
        Ok(())
    }

    /// [`Self::check`], and that they are built on `kind` (the particle-size distribution on
    /// the SPM only); the error names `model.submodels.NAME`.
    pub fn check_for(&self, kind: ModelKind) -> Result<(), crate::error::Error> {
        self.check()?;
        if self.particle_size == submodels::ParticleSize::Distribution && kind != ModelKind::Spm {
            return Err(crate::error::Error::InvalidSetting { field: "model.submodels.particle_size".into(), reason: format!("\"distribution\" is built on the SPM only, not the {kind}") });
        }
        Ok(())
    }

    /// Whether the particle diffusivities are stress-induced (`D (1 + theta_M (c - c_0))`):
    /// stress-driven LAM without `stress_induced_diffusion = false`.
    pub fn stressed_diffusion(&self) -> bool {
        self.lam.stress() && self.stress_induced_diffusion != Some(false)
    }

    /// Whether a submodel that wraps the model in [`submodels::Augmented`] is on.
    pub fn augments(&self) -> bool {
        self.rc || self.hysteresis || self.leak || self.voltage_offset || self.voltage_gain || self.current_gain || self.ocv_correction
    }
}

/// The state/output interface every model offers to the solver and to reports.
///
/// States are laid out by the model; `current` is the applied current (A, discharge
/// positive) at the time of the call.
pub trait Model: Send + Sync {
    /// Short name, e.g. "DFN".
    fn name(&self) -> String;
    /// Number of states.
    fn len(&self) -> usize;
    /// Mass-matrix diagonal: 1 for differential states, 0 for algebraic ones.
    fn mass(&self) -> &[f64];
    /// Typical magnitude of each state (for tolerances and difference steps).
    fn scale(&self) -> &[f64];
    /// Magnitude below which a finite-difference Jacobian's step in each state stops
    /// shrinking (the step is `sqrt(eps)` of it or of the state): the state scale, unless the
    /// right-hand side is linear in the state (forward sensitivities), where a larger step
    /// keeps the difference well above rounding at no loss.
    fn difference_scale(&self) -> &[f64] {
        self.scale()
    }
    /// Structural non-zeros `(row, col)` of `df/dy` (may omit weak dense couplings).
    fn jacobian_pattern(&self) -> Vec<(usize, usize)>;
    /// Initial state; algebraic states hold a guess that `consistent_initialisation` refines.
    fn initial_state(&self) -> Vec<f64>;
    /// Right-hand side `f` of `M y' = f(y)`.
    fn rhs(&self, y: &[f64], current: f64, out: &mut [f64]);
    /// Terminal voltage (V).
    fn voltage(&self, y: &[f64], current: f64) -> f64;
    /// Cell temperature (K).
    fn temperature(&self, y: &[f64]) -> f64;
    /// Index of the temperature state (a lumped thermal submodel), `None` when isothermal.
    fn temperature_state(&self) -> Option<usize> {
        None
    }
    /// Rows that follow a recorded temperature `T_rec` when one is given, each with its
    /// target's weight `w`: `dz/dt = (w T_rec(t) - z) / lag` in place of the model's equation
    /// (`w = 1` for the temperature itself, `0` for a sensitivity of it, which the recording
    /// does not depend on).
    fn temperature_rows(&self) -> Vec<(usize, f64)> {
        self.temperature_state().map(|k| (k, 1.0)).into_iter().collect()
    }
    /// Lithium held in the solid phases (mol).
    fn solid_lithium(&self, y: &[f64]) -> f64;
    /// Lithium bound in the SEI (mol); zero without an SEI submodel.
    fn sei_lithium(&self, _y: &[f64]) -> f64 {
        0.0
    }
    /// SEI thickness (m), x-averaged; `None` without an SEI submodel.
    fn sei_thickness(&self, _y: &[f64]) -> Option<f64> {
        None
    }
    /// The electrodes' active material (volume fractions, capacities, lithium lost with
    /// it); `None` without a loss-of-active-material submodel.
    fn active_material(&self, _y: &[f64]) -> Option<submodels::lam::ActiveMaterial> {
        None
    }
    /// Lithium plated on the negative electrode, reversible and dead (mol); `None` without a
    /// plating submodel.
    fn plated_lithium(&self, _y: &[f64]) -> Option<submodels::plating::PlatedLithium> {
        None
    }
    /// Open-circuit voltage at the particles' average stoichiometries (V).
    fn open_circuit_voltage(&self, y: &[f64]) -> f64;
    /// The lithium-plating margin (V): the smallest `phi_s - phi_e` in the negative electrode,
    /// the overpotential of lithium deposition against Li/Li+ (plating is favoured below 0),
    /// x-averaged in the SPM and SPMe as PyBaMM's, the least over the volumes in the DFN;
    /// `None` for a model without electrodes.
    fn plating_margin(&self, _y: &[f64], _current: f64) -> Option<f64> {
        None
    }
    /// Rows of [`Model::rhs`] that read the applied current (all of them unless a model says
    /// fewer): a voltage hold, where the current is an unknown, puts its Jacobian column on
    /// these rows only. A row left out only slows the hold's Newton iteration.
    fn rows_reading_current(&self) -> Vec<usize> {
        (0..self.len()).collect()
    }
    /// Indices of the states that only integrate an ageing rate (SEI, plated lithium, lost
    /// active material): see [`crate::solver::Dae::accumulating_states`].
    fn accumulating_states(&self) -> Vec<usize> {
        Vec::new()
    }
    /// Indices of the states that [`Model::voltage`] and [`Model::temperature`] read: the
    /// energy quadrature interpolates only these (all states unless a model says fewer).
    fn output_states(&self) -> Vec<usize> {
        (0..self.len()).collect()
    }
    /// Named spatial fields of the state `y` (concentrations and potentials against
    /// position); none for a model without spatial structure.
    fn fields(&self, _y: &[f64]) -> Vec<Field> {
        Vec::new()
    }
}

/// Appends the pattern of a tridiagonal block (a 1-D three-point stencil) on states
/// `start..start + len` to `pattern`.
pub(crate) fn push_tridiagonal(pattern: &mut Vec<(usize, usize)>, start: usize, len: usize) {
    for k in 0..len {
        for m in k.saturating_sub(1)..(k + 2).min(len) {
            pattern.push((start + k, start + m));
        }
    }
}

/// A physics-based model built on a parameter set, whose non-geometric parameters can be
/// replaced without rebuilding it.
pub trait PhysicsModel: Model {
    fn electrochem(&self) -> &Electrochem;
    /// Replaces the parameters; the caller guarantees the geometry is unchanged.
    fn set_params(&mut self, params: ParameterSet);
}
