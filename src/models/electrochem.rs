//! What the physics-based models share: the parameter set, the discretisation, and the
//! electrode-level closures (OCP, exchange current, diffusivities with temperature).

use super::Submodels;
use super::kinetics::{arrhenius, exchange_current};
use super::submodels::LumpedThermal;
use crate::geometry::{Discretisation, SphereMesh};
use crate::params::{BlendOcp, Electrode, FARADAY, ParameterSet};

/// Which electrode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    Negative,
    Positive,
}

/// Parameters plus discretisation, shared by SPM, SPMe and DFN.
#[derive(Clone, Debug)]
pub struct Electrochem {
    pub params: ParameterSet,
    pub disc: Discretisation,
    pub submodels: Submodels,
    pub thermal: LumpedThermal,
    /// Each electrode's OCP with a second active material, tabulated (negative, positive);
    /// `None` for an electrode without one.
    blends: [Option<BlendOcp>; 2],
}

impl Electrochem {
    pub fn new(params: ParameterSet, disc: Discretisation, submodels: Submodels) -> Self {
        let thermal = LumpedThermal::new(&params);
        let blends = [BlendOcp::of(&params.negative), BlendOcp::of(&params.positive)];
        Self { params, disc, submodels, thermal, blends }
    }

    /// Replaces the parameters (geometry must be unchanged) and refreshes derived constants.
    pub fn set_params(&mut self, params: ParameterSet) {
        self.thermal = LumpedThermal::new(&params);
        self.blends = [BlendOcp::of(&params.negative), BlendOcp::of(&params.positive)];
        self.params = params;
    }

    pub fn electrode(&self, side: Side) -> &Electrode {
        match side {
            Side::Negative => &self.params.negative,
            Side::Positive => &self.params.positive,
        }
    }

    pub fn sphere(&self, side: Side) -> &SphereMesh {
        match side {
            Side::Negative => &self.disc.sphere_n,
            Side::Positive => &self.disc.sphere_p,
        }
    }

    /// Plate area (m^2).
    pub fn area(&self) -> f64 {
        self.params.cell.area()
    }

    /// Open-circuit potential (V) at particle concentration `c_s` (mol/m^3) and temperature
    /// `t` (K): `U(x) + (t - T_ref) dU/dT(x)` at stoichiometry `x`, PyBaMM's form.
    pub fn ocp(&self, side: Side, c_s: f64, t: f64) -> f64 {
        self.ocp_at_stoichiometry(side, c_s / self.electrode(side).max_concentration, t)
    }

    /// The OCP (V) at stoichiometry `sto` and temperature `t` (K): the set's function, or the
    /// blend's table with a second active material, plus the entropic term.
    fn ocp_at_stoichiometry(&self, side: Side, sto: f64, t: f64) -> f64 {
        let reference = match &self.blends[side as usize] {
            Some(blend) => blend.eval(sto),
            None => self.electrode(side).ocp.eval(sto),
        };
        if t == self.t_ref() { reference } else { reference + (t - self.t_ref()) * self.electrode(side).entropic_change(sto) }
    }

    /// Entropic change dU/dT (V/K) at particle concentration `c_s` (mol/m^3).
    pub fn entropic_change(&self, side: Side, c_s: f64) -> f64 {
        let e = self.electrode(side);
        e.entropic_change(c_s / e.max_concentration)
    }

    /// [`Self::ocp`] as PyBaMM 26 wraps it: the stoichiometry clipped to `[1e-10, 1 - 1e-10]`
    /// inside the function, plus [`ocp_asymptotes`] of the unclipped one, which push the
    /// OCP up near an empty particle and down near a full one (1 mV at a stoichiometry 1e-3
    /// from the end, 1 V at the end). The particle-size distribution uses it (its smallest
    /// particles reach the ends); elsewhere the asymptotes are below 1e-100 V in the tested
    /// ranges and `ocp` leaves them out.
    pub fn bounded_ocp(&self, side: Side, c_s: f64, t: f64) -> f64 {
        let sto = c_s / self.electrode(side).max_concentration;
        self.ocp_at_stoichiometry(side, sto.clamp(1e-10, 1.0 - 1e-10), t) + ocp_asymptotes(sto)
    }

    /// Particle diffusivity (m^2/s) at temperature `t` (K).
    pub fn diffusivity(&self, side: Side, t: f64) -> f64 {
        let e = self.electrode(side);
        e.diffusivity * arrhenius(e.diffusivity_activation_energy, self.t_ref(), t)
    }

    /// Exchange-current density (A/m^2) at electrolyte concentration `c_e` and surface
    /// concentration `c_s` (mol/m^3), temperature `t` (K), all three square roots
    /// regularised (the DFN's form; the SPM and SPMe inline theirs, see their voltages).
    pub fn j0(&self, side: Side, c_e: f64, c_s: f64, t: f64) -> f64 {
        let c_e_ref = self.params.electrolyte.initial_concentration;
        exchange_current(self.rate_constant(side, t), c_e, c_e_ref, c_s, self.electrode(side).max_concentration)
    }

    /// Reaction rate constant at temperature `t` (K), A/m^2 (m^3/mol)^1.5: hoist it out of
    /// loops over x and use [`exchange_current`] there.
    pub fn rate_constant(&self, side: Side, t: f64) -> f64 {
        let e = self.electrode(side);
        e.rate_constant * arrhenius(e.rate_activation_energy, self.t_ref(), t)
    }

    /// Electrode-averaged interfacial current density (A/m^2) for cell current `current` (A):
    /// positive (deintercalation) in the negative electrode on discharge.
    pub fn mean_interfacial_current(&self, side: Side, current: f64) -> f64 {
        let e = self.electrode(side);
        let j = current / (self.area() * e.surface_area_density() * e.thickness);
        match side {
            Side::Negative => j,
            Side::Positive => -j,
        }
    }

    /// Series resistance of the contact-resistance submodel (ohm), zero when it is off.
    pub fn contact_resistance(&self) -> f64 {
        if self.submodels.contact_resistance { self.params.cell.contact_resistance } else { 0.0 }
    }

    pub fn t_ref(&self) -> f64 {
        self.params.thermal.reference_temperature
    }

    /// Lithium (mol) in the particles of one electrode region of thickness `thickness` (m)
    /// whose particles hold shell concentrations `c`.
    pub fn particle_lithium(&self, side: Side, c: &[f64], thickness: f64) -> f64 {
        let e = self.electrode(side);
        self.sphere(side).average(c) * e.active_fraction * thickness * self.area()
    }

    /// Molar flux out of the particle surface (mol/(m^2 s)) for interfacial current `j`.
    pub fn molar_flux(j: f64) -> f64 {
        j / FARADAY
    }

    /// Effective solid-phase conductivity `sigma (1 - eps)^b` (S/m) of an electrode.
    pub fn effective_conductivity(&self, side: Side) -> f64 {
        let e = self.electrode(side);
        e.conductivity * (1.0 - e.porosity).powf(e.bruggeman_solid)
    }

    /// Surface concentrations (mol/m^3) of the two representative particles of a single
    /// particle model, with shell concentrations `cn` and `cp`.
    pub fn single_particle_surfaces(&self, cn: &[f64], cp: &[f64]) -> (f64, f64) {
        (self.disc.sphere_n.surface(cn), self.disc.sphere_p.surface(cp))
    }

    /// Indices that [`Self::single_particle_surfaces`] reads in a state laid out `[cn, cp, ..]`:
    /// the last two shells of each particle.
    pub fn single_particle_surface_states(&self) -> Vec<usize> {
        let (nn, np) = (self.disc.sphere_n.len(), self.disc.sphere_p.len());
        let last_two = |start: usize, n: usize| start + n.saturating_sub(2)..start + n;
        last_two(0, nn).chain(last_two(nn, np)).collect()
    }

    /// Lithium (mol) in both electrodes of a single particle model.
    pub fn single_particle_lithium(&self, cn: &[f64], cp: &[f64]) -> f64 {
        let p = &self.params;
        self.particle_lithium(Side::Negative, cn, p.negative.thickness)
            + self.particle_lithium(Side::Positive, cp, p.positive.thickness)
    }

    /// OCV (V) at the average stoichiometries of the two representative particles, at
    /// temperature `t` (K).
    pub fn single_particle_ocv(&self, cn: &[f64], cp: &[f64], t: f64) -> f64 {
        self.ocp(Side::Positive, self.disc.sphere_p.average(cp), t) - self.ocp(Side::Negative, self.disc.sphere_n.average(cn), t)
    }

    /// Entropic coefficient of the cell's OCV, dU_p/dT - dU_n/dT (V/K), at the particle
    /// surface concentrations `sn`, `sp` (mol/m^3) of an electrode-uniform (single particle)
    /// model: the reversible heat is `-I T` times it.
    pub fn docv_dt(&self, sn: f64, sp: f64) -> f64 {
        self.entropic_change(Side::Positive, sp) - self.entropic_change(Side::Negative, sn)
    }
}

/// PyBaMM 26's `U_asymptotes(sto)` (V): `A(sto) - A(1 - sto)` with the softplus barrier
/// `A(s) = a ln(1 + exp(-b (s - c)))` (`a` = 205.06 V, `b` = 6910.2, `c` = -7.7e-4), continued
/// linearly below the stoichiometry where `1 + exp` rounds to `exp`. Exactly zero (as in
/// PyBaMM's floating point) farther than about 0.0046 from both ends.
pub fn ocp_asymptotes(sto: f64) -> f64 {
    fn barrier(s: f64) -> f64 {
        const A: f64 = 205.0568621937484;
        const B: f64 = 6910.192179565431;
        const C: f64 = -7.7e-4;
        if s > 0.006 {
            return 0.0;
        }
        let limit = C - (2.0 / f64::EPSILON).ln() / B;
        A * ((1.0 + (-B * (s.max(limit) - C)).exp()).ln() - B * (s - limit).min(0.0))
    }
    barrier(sto) - barrier(1.0 - sto)
}
