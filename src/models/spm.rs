//! Single particle model: one representative particle per electrode, uniform interfacial
//! current, electrolyte at its initial concentration.
//!
//! States: negative shells `c_n` (mol/m^3), positive shells `c_p`, the SEI concentration
//! (mol/m^3) when an SEI submodel is on, the LAM states when a loss-of-active-material
//! submodel is on (the shells then hold `eps c`, see [`LamLayer`]), the plated and dead
//! lithium concentrations (mol/m^3) when a plating submodel is on, then `T` (K) when the
//! thermal submodel is on.

use std::borrow::Cow;

use super::electrochem::{Electrochem, Side};
use super::kinetics::{overpotential, particle_factor};
use super::submodels::plating::Site;
use super::submodels::{LamDrivers, LamLayer, PlatingLayer, SeiLayer};
use super::submodels::thermal::{SideReactionSite, bernardi_heat};
use super::{Model, PhysicsModel, push_tridiagonal};
use crate::params::ParameterSet;

#[derive(Clone, Debug)]
pub struct Spm {
    pub ec: Electrochem,
    sei: SeiLayer,
    lam: LamLayer,
    plating: PlatingLayer,
    mass: Vec<f64>,
    scale: Vec<f64>,
}

impl Spm {
    pub fn new(ec: Electrochem) -> Self {
        let (nn, np) = (ec.disc.sphere_n.len(), ec.disc.sphere_p.len());
        let sei = SeiLayer::new(ec.submodels.sei, nn + np, 1);
        let lam = LamLayer::new(ec.submodels.lam, nn + np + sei.len(), [1, 1]);
        let plating = PlatingLayer::new(ec.submodels.plating, nn + np + sei.len() + lam.len(), 1);
        let n = nn + np + sei.len() + lam.len() + plating.len() + usize::from(ec.submodels.thermal);
        let mut scale = vec![lam.shell_scale(&ec, Side::Negative); nn];
        scale.extend(std::iter::repeat_n(lam.shell_scale(&ec, Side::Positive), np));
        scale.extend(sei.indices().map(|_| SeiLayer::initial_concentration(&ec)));
        lam.push_scale(&ec, &mut scale);
        plating.push_scale(&ec, &mut scale);
        if ec.submodels.thermal {
            scale.push(ec.params.thermal.ambient_temperature);
        }
        Self { ec, sei, lam, plating, mass: vec![1.0; n], scale }
    }

    fn split<'a>(&self, y: &'a [f64]) -> (&'a [f64], &'a [f64]) {
        let nn = self.ec.disc.sphere_n.len();
        let np = self.ec.disc.sphere_p.len();
        (&y[..nn], &y[nn..nn + np])
    }

    /// Shell concentrations (mol/m^3) of the negative and positive particles.
    fn particles<'a>(&self, y: &'a [f64]) -> (Cow<'a, [f64]>, Cow<'a, [f64]>) {
        let (n, p) = self.split(y);
        (self.lam.concentrations(Side::Negative, y, n, 0), self.lam.concentrations(Side::Positive, y, p, 0))
    }

    /// Surface concentrations (mol/m^3) of the negative and positive particles.
    pub fn surface_concentrations(&self, y: &[f64]) -> (f64, f64) {
        let (cn, cp) = self.particles(y);
        self.ec.single_particle_surfaces(&cn, &cp)
    }
}

impl Spm {
    /// `phi_s - phi_e` (V) at an electrode's particle surface `c_s` (mol/m^3): its OCP plus
    /// the reaction overpotential of the applied current (PyBaMM's inverse kinetics: of the
    /// total interfacial current), plus the SEI film's drop in the negative electrode.
    fn surface_potential_difference(&self, side: Side, c_s: f64, y: &[f64], current: f64) -> f64 {
        let ec = &self.ec;
        let temp = self.temperature(y);
        let e = ec.electrode(side);
        let j = self.lam.interfacial_current(ec, side, y, current);
        // PyBaMM 26.10's SPM regularises the particle factors of j0 but not the constant
        // sqrt(c_e) (2.5e-7 of j0, 1e-5 mV): see docs/pybamm_equations.md, section 1.
        let c_in = c_s.clamp(0.0, e.max_concentration);
        let j0 = ec.rate_constant(side, temp) * ec.params.electrolyte.initial_concentration.sqrt() * particle_factor(c_in, e.max_concentration);
        let film = if side == Side::Negative { self.sei.film(ec, y, j, self.lam.surface_area_density(ec, side, y, 0)) } else { 0.0 };
        ec.ocp(side, c_s, temp) + overpotential(j, j0, e.charge_transfer_coefficient, temp) + film
    }

    /// Writes the SEI and plating states' rates into `out` and returns the side-reaction
    /// current densities (A/m^2) of the SEI and of plating; zeros without them.
    fn side_rhs(&self, y: &[f64], sn: f64, current: f64, out: &mut [f64]) -> [f64; 2] {
        if self.sei.len() + self.plating.len() == 0 {
            return [0.0; 2];
        }
        let delta_phi = self.surface_potential_difference(Side::Negative, sn, y, current);
        let (ec, side, temp) = (&self.ec, Side::Negative, self.temperature(y));
        let (j, a) = (self.lam.interfacial_current(ec, side, y, current), self.lam.surface_area_density(ec, side, y, 0));
        let j_sei = self.sei.rhs(ec, y, std::iter::once(delta_phi), j, a, temp, out);
        let site = Site { delta_phi, electrolyte_concentration: ec.params.electrolyte.initial_concentration, sei_thickness: self.sei.volume_thickness(ec, y, 0, a) };
        let j_plating = self.plating.rhs(ec, y, std::iter::once(site), self.sei.film(ec, y, j, a), a, temp, out);
        [j_sei, j_plating]
    }

    /// Heat (W) that [`bernardi_heat`] counts and PyBaMM does not with side reactions of
    /// current density `j_side` (A/m^2) on the negative particle of surface concentration
    /// `sn` (mol/m^3); zero without them. See [`SideReactionSite::uncounted_heat`].
    fn uncounted_side_heat(&self, y: &[f64], sn: f64, current: f64, j_side: f64) -> f64 {
        if self.sei.len() + self.plating.len() == 0 {
            return 0.0;
        }
        let (ec, side) = (&self.ec, Side::Negative);
        let (j, a) = (self.lam.interfacial_current(ec, side, y, current), self.lam.surface_area_density(ec, side, y, 0));
        let delta_phi = self.surface_potential_difference(side, sn, y, current);
        let temp = self.temperature(y);
        let site = SideReactionSite { a, total_current: j, side_current: j_side, delta_phi, ocp: ec.ocp(side, sn, temp), film: self.sei.film(ec, y, j, a) };
        site.uncounted_heat(temp, ec.entropic_change(side, sn)) * ec.area() * ec.params.negative.thickness
    }
}

impl Model for Spm {
    fn name(&self) -> String {
        "SPM".into()
    }

    fn len(&self) -> usize {
        self.mass.len()
    }

    fn mass(&self) -> &[f64] {
        &self.mass
    }

    fn scale(&self) -> &[f64] {
        &self.scale
    }

    fn accumulating_states(&self) -> Vec<usize> {
        super::submodels::accumulating_states(&self.sei, &self.lam, &self.plating)
    }

    fn jacobian_pattern(&self) -> Vec<(usize, usize)> {
        let nn = self.ec.disc.sphere_n.len();
        let np = self.ec.disc.sphere_p.len();
        let mut p = Vec::new();
        for (start, len) in [(0, nn), (nn, np)] {
            push_tridiagonal(&mut p, start, len);
        }
        let t = nn + np + self.sei.len() + self.lam.len() + self.plating.len();
        // The SEI reads the temperature and the negative volume fraction (its surface area);
        // plating reads them and the SEI (its film and thickness).
        let sei_reads: Vec<usize> = self.ec.submodels.thermal.then_some(t).into_iter().chain(self.lam.indices().take(1)).collect();
        self.sei.push_pattern(&mut p, [nn - 2, nn - 1], &sei_reads);
        let plating_reads: Vec<usize> = sei_reads.iter().copied().chain(self.sei.indices()).collect();
        self.plating.push_pattern(&mut p, [nn - 2, nn - 1], &plating_reads);
        let lam_reads: Vec<usize> = self.sei.indices().chain(self.ec.submodels.thermal.then_some(t)).collect();
        self.lam.push_pattern(&mut p, [0..nn, nn..nn + np], &lam_reads);
        if self.ec.submodels.thermal {
            for i in 0..t {
                p.push((i, t));
            }
            for i in [nn - 2, nn - 1, nn + np - 2, nn + np - 1, t].into_iter().chain(self.sei.indices()).chain(self.lam.indices()).chain(self.plating.indices()) {
                p.push((t, i));
            }
        }
        p
    }

    fn initial_state(&self) -> Vec<f64> {
        let p = &self.ec.params;
        let mut y = vec![self.lam.initial_shell(&self.ec, Side::Negative); self.ec.disc.sphere_n.len()];
        y.extend(std::iter::repeat_n(self.lam.initial_shell(&self.ec, Side::Positive), self.ec.disc.sphere_p.len()));
        self.sei.push_initial(&self.ec, &mut y);
        self.lam.push_initial(&self.ec, &mut y);
        self.plating.push_initial(&self.ec, &mut y);
        if self.ec.submodels.thermal {
            y.push(p.thermal.initial_temperature);
        }
        y
    }

    fn rhs(&self, y: &[f64], current: f64, out: &mut [f64]) {
        let ec = &self.ec;
        let nn = ec.disc.sphere_n.len();
        let np = ec.disc.sphere_p.len();
        let temp = self.temperature(y);
        let (cn, cp) = self.particles(y);
        let (sn, _) = ec.single_particle_surfaces(&cn, &cp);
        let [j_sei, j_plating] = self.side_rhs(y, sn, current, out);
        let a_j_sei = self.lam.surface_area_density(ec, Side::Negative, y, 0) * j_sei;
        let rates = self.lam.rhs(ec, [&cn, &cp], LamDrivers { a_j_sei, current_density: current / ec.area() }, out);
        for (side, c, range, side_reaction, rate) in [(Side::Negative, &cn, 0..nn, j_sei + j_plating, rates[0]), (Side::Positive, &cp, nn..nn + np, 0.0, rates[1])] {
            let flux = Electrochem::molar_flux(self.lam.interfacial_current(ec, side, y, current) - side_reaction);
            self.lam.particle_rhs(ec, side, 0, y, c, flux, rate, temp, &mut out[range]);
        }
        if ec.submodels.thermal {
            let (sn, sp) = self.surface_concentrations(y);
            let ocv = ec.ocp(Side::Positive, sp, temp) - ec.ocp(Side::Negative, sn, temp);
            let v = self.voltage(y, current);
            let heat = bernardi_heat(current, ocv, v, temp, ec.docv_dt(sn, sp)) - self.uncounted_side_heat(y, sn, current, j_sei + j_plating);
            out[self.len() - 1] = ec.thermal.rate(heat, temp);
        }
    }

    fn voltage(&self, y: &[f64], current: f64) -> f64 {
        let ec = &self.ec;
        let (sn, sp) = self.surface_concentrations(y);
        self.surface_potential_difference(Side::Positive, sp, y, current) - self.surface_potential_difference(Side::Negative, sn, y, current)
            - current * ec.contact_resistance()
    }

    fn plating_margin(&self, y: &[f64], current: f64) -> Option<f64> {
        let (sn, _) = self.surface_concentrations(y);
        Some(self.surface_potential_difference(Side::Negative, sn, y, current))
    }

    fn temperature_state(&self) -> Option<usize> {
        self.ec.submodels.thermal.then(|| self.len() - 1)
    }

    fn temperature(&self, y: &[f64]) -> f64 {
        self.temperature_state().map_or(self.ec.params.thermal.ambient_temperature, |k| y[k])
    }

    fn solid_lithium(&self, y: &[f64]) -> f64 {
        let (n, p) = self.split(y);
        self.lam.particle_lithium(&self.ec, Side::Negative, n, self.ec.params.negative.thickness) + self.lam.particle_lithium(&self.ec, Side::Positive, p, self.ec.params.positive.thickness)
    }

    fn sei_lithium(&self, y: &[f64]) -> f64 {
        self.sei.lithium(&self.ec, y)
    }

    fn sei_thickness(&self, y: &[f64]) -> Option<f64> {
        self.sei.thickness(&self.ec, y, self.lam.surface_area_density(&self.ec, Side::Negative, y, 0))
    }

    fn active_material(&self, y: &[f64]) -> Option<super::submodels::lam::ActiveMaterial> {
        self.lam.summary(&self.ec, y)
    }

    fn plated_lithium(&self, y: &[f64]) -> Option<super::submodels::plating::PlatedLithium> {
        self.plating.lithium(&self.ec, y)
    }

    fn fields(&self, y: &[f64]) -> Vec<super::Field> {
        let (cn, cp) = self.particles(y);
        self.ec.single_particle_fields(&cn, &cp)
    }

    fn output_states(&self) -> Vec<usize> {
        let mut out = self.ec.single_particle_surface_states();
        out.extend(self.sei.indices());
        out.extend(self.lam.indices().take(2));
        out.extend(self.ec.submodels.thermal.then(|| self.len() - 1));
        out
    }

    fn open_circuit_voltage(&self, y: &[f64]) -> f64 {
        let (cn, cp) = self.particles(y);
        self.ec.single_particle_ocv(&cn, &cp, self.temperature(y))
    }
}

impl PhysicsModel for Spm {
    fn electrochem(&self) -> &Electrochem {
        &self.ec
    }
    fn set_params(&mut self, params: ParameterSet) {
        self.ec.set_params(params);
    }
}
