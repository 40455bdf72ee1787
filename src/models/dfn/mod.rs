//! Doyle-Fuller-Newman (pseudo-two-dimensional) model.
//!
//! States, in order: negative particle shells (x-node major), positive particle shells,
//! electrolyte concentration `c_e` over all x volumes (mol/m^3), then the algebraic
//! potentials `phi_e` over all x volumes, `phi_s` in the negative and in the positive
//! electrode (V), with an SEI submodel the SEI concentration (mol/m^3) and the (algebraic)
//! total interfacial current density `j_tot` (A/m^2) of each negative volume, with a plating
//! submodel the plated and the dead lithium concentration (mol/m^3) of each negative volume,
//! with a loss-of-active-material submodel the active material volume fraction of each
//! electrode volume and the lithium lost with each electrode's (the particle states then hold
//! `eps c`, see [`LamLayer`]), and `T` (K) when the thermal submodel is on.
//!
//! Equations (x through the cell, r in each particle, SI units):
//! - particles: `dc_s/dt = 1/r^2 d/dr (r^2 D_s dc_s/dr)`, `-D_s dc_s/dr|_R = j / F`;
//! - electrolyte: `eps dc_e/dt = d/dx (eps^b D_e dc_e/dx) + (1 - t+) a j / F`, no flux at
//!   the current collectors;
//! - `d i_e/dx = a j`, `i_e = -kappa_eff (dphi_e/dx - 2 (1 - t+) chi R T / F dln c_e/dx)`;
//! - `d i_s/dx = -a j`, `i_s = -sigma_eff dphi_s/dx`, `phi_s(0) = 0`, `i_s(L) = I / A`;
//! - `j = 2 j0 sinh(alpha F (phi_s - phi_e - U) / (R T))`;
//! - with SEI growth (PyBaMM's "distributed" film, "total interfacial current density as a
//!   state"): in each negative volume `j = 2 j0 sinh(alpha F (phi_s - phi_e - U - j_tot L
//!   R_sei) / (R T))` into the particle, the side reaction `j_sei` of
//!   [`crate::models::submodels::SeiLayer`] at `phi_s - phi_e` with the film carrying `j`,
//!   `0 = j_tot - (j + j_sei)`, and `a j_tot` the source of the electrolyte and the
//!   potentials (docs/ageing.md, section 1);
//! - with lithium plating: in each negative volume the plating current `j_Li` of
//!   [`crate::models::submodels::PlatingLayer`] at `phi_s - phi_e - j_tot L R_sei` joins the
//!   sum (docs/ageing.md, section 4.4; [`interface`]);
//! - with loss of active material: each electrode volume's `eps_s` falls with its particle's
//!   surface stress or its SEI current, and its surface area density `a = 3 eps_s / R`
//!   follows (docs/ageing.md, section 2.3; [`active`]).
//!
//! Voltage: `phi_s(L) - phi_s(0) - I R_contact`, `phi_s(L)` extrapolated linearly from the
//! last two volumes as PyBaMM does.

use super::electrochem::{Electrochem, Side};
use super::electrolyte::ElectrolyteOp;
use super::kinetics::{butler_volmer, exchange_current};
use super::submodels::{LamDrivers, LamLayer, PlatingLayer, SeiLayer};
use super::submodels::thermal::bernardi_heat_of_power;
use super::{Model, PhysicsModel, push_tridiagonal};
use crate::params::ParameterSet;

mod active;
mod interface;
mod layout;
use interface::Surface;
pub use layout::Layout;

#[derive(Clone, Debug)]
pub struct Dfn {
    pub ec: Electrochem,
    /// Index ranges of the state blocks.
    pub layout: Layout,
    electrolyte: ElectrolyteOp,
    sei: SeiLayer,
    plating: PlatingLayer,
    lam: LamLayer,
    /// Effective solid conductivities of the negative and positive electrodes (S/m).
    sigma: [f64; 2],
    mass: Vec<f64>,
    scale: Vec<f64>,
}

impl Dfn {
    pub fn new(ec: Electrochem) -> Self {
        let layout = Layout::new(&ec);
        let mut mass = vec![0.0; layout.len];
        mass[..layout.phie].iter_mut().for_each(|m| *m = 1.0);
        let p = &ec.params;
        let mut scale = vec![0.0; layout.len];
        scale[layout.ce..layout.phie].iter_mut().for_each(|s| *s = p.electrolyte.initial_concentration);
        scale[layout.phie..layout.phis_p + layout.nxp].iter_mut().for_each(|s| *s = 1.0);
        if let Some(t) = layout.temp {
            mass[t] = 1.0;
            scale[t] = p.thermal.ambient_temperature;
        }
        if let Some(s) = layout.sei {
            let n = layout.nxn;
            mass[s..s + n].fill(1.0);
            scale[s..s + n].fill(SeiLayer::initial_concentration(&ec));
            scale[s + n..s + 2 * n].fill(ec.mean_interfacial_current(Side::Negative, p.cell.nominal_capacity).abs());
        }
        let sei = SeiLayer::new(ec.submodels.sei, layout.sei.unwrap_or(0), layout.nxn);
        let plating = PlatingLayer::new(ec.submodels.plating, layout.plating.unwrap_or(0), layout.nxn);
        for k in plating.indices() {
            mass[k] = 1.0;
            scale[k] = p.plating.typical_concentration;
        }
        let lam = LamLayer::new(ec.submodels.lam, layout.lam.unwrap_or(0), [layout.nxn, layout.nxp]);
        mass[lam.indices()].fill(1.0);
        let mut lam_scale = Vec::new();
        lam.push_scale(&ec, &mut lam_scale);
        scale[lam.indices()].copy_from_slice(&lam_scale);
        scale[layout.cs_n..layout.cs_p].fill(lam.shell_scale(&ec, Side::Negative));
        scale[layout.cs_p..layout.ce].fill(lam.shell_scale(&ec, Side::Positive));
        let electrolyte = ElectrolyteOp::new(&ec);
        let sigma = Self::solid_conductivities(&ec);
        Self { ec, layout, electrolyte, sei, plating, lam, sigma, mass, scale }
    }

    fn temp(&self, y: &[f64]) -> f64 {
        match self.layout.temp {
            Some(t) => y[t],
            None => self.ec.params.thermal.ambient_temperature,
        }
    }
}

impl Dfn {
    fn solid_conductivities(ec: &Electrochem) -> [f64; 2] {
        [Side::Negative, Side::Positive].map(|side| ec.effective_conductivity(side))
    }
}

impl Model for Dfn {
    fn name(&self) -> String {
        "DFN".into()
    }

    fn len(&self) -> usize {
        self.layout.len
    }

    fn mass(&self) -> &[f64] {
        &self.mass
    }

    fn scale(&self) -> &[f64] {
        &self.scale
    }

    fn rows_reading_current(&self) -> Vec<usize> {
        // The applied current enters as the solid current at the positive collector and in
        // the heat source; with loss of active material also in its drivers, whose rates every
        // particle row reads (a row left out there breaks the Newton updates' lithium balance).
        let l = &self.layout;
        if self.lam.len() > 0 {
            return (0..l.len).collect();
        }
        std::iter::once(l.phis(Side::Positive, l.nxp - 1)).chain(l.temp).collect()
    }

    fn accumulating_states(&self) -> Vec<usize> {
        crate::models::submodels::accumulating_states(&self.sei, &self.lam, &self.plating)
    }

    fn jacobian_pattern(&self) -> Vec<(usize, usize)> {
        let l = &self.layout;
        let nx = l.nx();
        let mut p = Vec::new();
        let neighbours = |i: usize| i.saturating_sub(1)..(i + 2).min(nx);
        for i in 0..nx {
            let kinetics: Vec<usize> = match l.electrode_of(i) {
                Some((side, k, start)) => {
                    let nr = l.nr(side);
                    let mut c = vec![start + nr - 2, start + nr - 1, l.ce + i, l.phie + i, l.phis(side, k)];
                    // The volume fraction under loss of active material (through `a` and `n / eps`).
                    c.extend(self.lam.fraction_index(side, k));
                    // The side states of a negative volume (SEI concentration and total current,
                    // plated and dead lithium), whose rows read the same.
                    if side == Side::Negative {
                        let states = self.side_states(k);
                        c.extend(&states);
                        for row in states {
                            p.extend(c.iter().map(|&col| (row, col)));
                        }
                    }
                    self.push_lam_pattern(&mut p, side, k, start, &c);
                    c
                }
                None => Vec::new(),
            };
            // electrolyte concentration and potential rows
            for m in neighbours(i) {
                p.push((l.ce + i, l.ce + m));
                p.push((l.phie + i, l.phie + m));
                p.push((l.phie + i, l.ce + m));
            }
            for &c in &kinetics {
                p.push((l.ce + i, c));
                p.push((l.phie + i, c));
            }
            if let Some((side, k, start)) = l.electrode_of(i) {
                let nr = l.nr(side);
                push_tridiagonal(&mut p, start, nr);
                for &c in &kinetics {
                    p.push((start + nr - 1, c));
                    p.push((l.phis(side, k), c));
                }
                let ne = if side == Side::Negative { l.nxn } else { l.nxp };
                for m in k.saturating_sub(1)..(k + 2).min(ne) {
                    p.push((l.phis(side, k), l.phis(side, m)));
                }
            }
        }
        if let Some(t) = l.temp {
            for r in 0..l.len {
                p.push((r, t));
            }
        }
        p
    }

    fn initial_state(&self) -> Vec<f64> {
        let l = &self.layout;
        let p = &self.ec.params;
        let mut y = vec![0.0; l.len];
        y[l.cs_n..l.cs_p].fill(self.lam.initial_shell(&self.ec, Side::Negative));
        y[l.cs_p..l.ce].fill(self.lam.initial_shell(&self.ec, Side::Positive));
        y[l.ce..l.phie].iter_mut().for_each(|v| *v = p.electrolyte.initial_concentration);
        if let Some(t) = l.temp {
            y[t] = p.thermal.initial_temperature;
        }
        // Potentials at open circuit: phi_s_n = 0, phi_e = -U_n, phi_s_p = U_p - U_n.
        let t0 = self.temp(&y);
        let un = self.ec.ocp(Side::Negative, p.negative.initial_concentration, t0);
        let up = self.ec.ocp(Side::Positive, p.positive.initial_concentration, t0);
        y[l.phie..l.phis_n].iter_mut().for_each(|v| *v = -un);
        y[l.phis_p..l.phis_p + l.nxp].iter_mut().for_each(|v| *v = up - un);
        if let Some(s) = l.sei {
            y[s..s + l.nxn].fill(SeiLayer::initial_concentration(&self.ec));
        }
        if let Some(s) = l.plating {
            y[s..s + l.nxn].fill(p.plating.initial_concentration);
        }
        let mut lam = Vec::new();
        self.lam.push_initial(&self.ec, &mut lam);
        y[self.lam.indices()].copy_from_slice(&lam);
        y
    }

    fn rhs(&self, y: &[f64], current: f64, out: &mut [f64]) {
        let l = &self.layout;
        let ec = &self.ec;
        let nx = l.nx();
        let temp = self.temp(y);
        let i_app = current / ec.area();
        let vols = &self.electrolyte.vols;
        let (out_cs, rest) = out.split_at_mut(l.ce);
        let (out_ce, rest) = rest.split_at_mut(nx);
        let (out_phie, out_phis) = rest.split_at_mut(nx);

        // Interfacial current a*j per x volume (A/m^3), held in the phi_e rows until the
        // divergence of the ionic current is subtracted at the end, and particles.
        out_phie[l.nxn..l.nxn + l.nxs].fill(0.0);
        // For the heat source, per unit plate area (W/m^2): the reactions' open-circuit power
        // `-sum a j_tot U dx` and the heat of the side reactions that the cell balance counts
        // and PyBaMM does not.
        let mut ocv_power = 0.0;
        let mut uncounted_heat = 0.0;
        // `sum a j_tot dU/dT dx` (W/(m^2 K)): the reversible heat per kelvin, PyBaMM's
        // `Q_rev / T` with the entropic change at each particle surface.
        let mut entropic_power = 0.0;
        self.clear_lam_losses(out_phis);
        for (side, first, n, cs) in [(Side::Negative, 0, l.nxn, l.cs_n), (Side::Positive, l.nxn + l.nxs, l.nxp, l.cs_p)] {
            let e = ec.electrode(side);
            let sphere = ec.sphere(side);
            let nr = l.nr(side);
            let (rate, diff) = (ec.rate_constant(side, temp), ec.diffusivity(side, temp));
            let c_e_ref = ec.params.electrolyte.initial_concentration;
            for k in 0..n {
                let (i, start) = (first + k, cs + k * nr);
                let shells = &y[start..start + nr];
                let c = self.lam.concentrations(side, y, shells, k);
                let c_s = sphere.surface(&c);
                let ocp = ec.ocp(side, c_s, temp);
                let j0 = exchange_current(rate, y[l.ce + i], c_e_ref, c_s, e.max_concentration);
                let delta_phi = y[l.phis(side, k)] - y[l.phie + i];
                let a = self.lam.fraction_index(side, k).map_or(vols[i].a, |_| self.lam.surface_area_density(ec, side, y, k));
                let (j, j_sei) = match side {
                    Side::Negative if self.side_reactions() => {
                        let (j, j_sei, site) = self.negative_interface(y, Surface { k, i, j0, delta_phi, ocp, a, temp }, out_phis);
                        out_phie[i] = a * site.total_current;
                        uncounted_heat += vols[i].dx * site.uncounted_heat(temp, ec.entropic_change(side, c_s));
                        (j, j_sei)
                    }
                    _ => {
                        let j = butler_volmer(j0, delta_phi - ocp, e.charge_transfer_coefficient, temp);
                        out_phie[i] = a * j;
                        (j, 0.0)
                    }
                };
                ocv_power -= vols[i].dx * out_phie[i] * ocp;
                if l.temp.is_some() {
                    entropic_power += vols[i].dx * out_phie[i] * ec.entropic_change(side, c_s);
                }
                let flux = Electrochem::molar_flux(j);
                let out_particle = &mut out_cs[start..start + nr];
                match self.lam.fraction_index(side, k) {
                    None => sphere.diffusion(shells, diff, flux, out_particle),
                    Some(_) => {
                        let drivers = LamDrivers { a_j_sei: a * j_sei, current_density: current / ec.area() };
                        self.lose_active_material(y, (side, k, i), &c, flux, drivers, temp, (out_particle, out_phis))
                    }
                }
            }
        }
        let aj: &[f64] = out_phie;

        // Electrolyte concentration.
        let ce = &y[l.ce..l.phie];
        self.electrolyte.concentration_rhs(ec, ce, |i| aj[i], None, temp, out_ce);

        // Solid potentials: d i_s/dx = -a j with phi_s = 0 at x = 0 and i_s = I/A at x = L.
        for (slot, side, n, first) in [(0, Side::Negative, l.nxn, 0), (1, Side::Positive, l.nxp, l.nxn + l.nxs)] {
            let phis = &y[l.phis(side, 0)..l.phis(side, 0) + n];
            let out = &mut out_phis[l.phis(side, 0) - l.phis_n..][..n];
            let inv_dx = 1.0 / vols[first].dx;
            let g = self.sigma[slot] * inv_dx;
            // current density i_s (A/m^2) at the left face of volume k, 0 <= k <= n
            let face = |k: usize| match (k, side) {
                (0, Side::Negative) => -2.0 * g * phis[0],
                (0, Side::Positive) => 0.0,
                (k, Side::Negative) if k == n => 0.0,
                (k, Side::Positive) if k == n => i_app,
                (k, _) => -g * (phis[k] - phis[k - 1]),
            };
            for k in 0..n {
                out[k] = -(face(k + 1) - face(k)) * inv_dx - aj[first + k];
            }
        }

        // Electrolyte charge conservation: d i_e/dx = a j.
        self.electrolyte.subtract_current_divergence(ec, ce, &y[l.phie..l.phis_n], temp, out_phie);

        if let Some(t) = l.temp {
            let v = self.voltage(y, current);
            let heat = bernardi_heat_of_power(ocv_power * ec.area(), current, v, temp * entropic_power * ec.area()) - uncounted_heat * ec.area();
            out_phis[t - l.phis_n] = ec.thermal.rate(heat, temp);
        }
    }

    fn voltage(&self, y: &[f64], current: f64) -> f64 {
        let l = &self.layout;
        let last = l.phis_p + l.nxp - 1;
        // phi_s at x = L by linear extrapolation of the last two volumes (uniform widths),
        // PyBaMM's boundary value: it does not use the boundary current I / A, and differs
        // from `phi_N - (I / A) dx / (2 sigma)` by the reaction current of the last half
        // volume (0.025-0.03 mV at 1C on 20 volumes, O(dx^2)).
        let phi_l = 1.5 * y[last] - 0.5 * y[last - 1];
        phi_l - current * self.ec.contact_resistance()
    }

    fn temperature_state(&self) -> Option<usize> {
        self.layout.temp
    }

    fn temperature(&self, y: &[f64]) -> f64 {
        self.temp(y)
    }

    fn plating_margin(&self, y: &[f64], _current: f64) -> Option<f64> {
        let l = &self.layout;
        (0..l.nxn).map(|i| y[l.phis_n + i] - y[l.phie + i]).reduce(f64::min)
    }

    fn solid_lithium(&self, y: &[f64]) -> f64 {
        let l = &self.layout;
        let mut total = 0.0;
        for i in 0..l.nx() {
            if let Some((side, _, start)) = l.electrode_of(i) {
                let c = &y[start..start + l.nr(side)];
                total += self.lam.particle_lithium(&self.ec, side, c, self.electrolyte.vols[i].dx);
            }
        }
        total
    }

    fn sei_lithium(&self, y: &[f64]) -> f64 {
        self.sei.lithium(&self.ec, y)
    }

    fn plated_lithium(&self, y: &[f64]) -> Option<super::submodels::plating::PlatedLithium> {
        self.plating.lithium(&self.ec, y)
    }

    fn sei_thickness(&self, y: &[f64]) -> Option<f64> {
        let l = &self.layout;
        l.sei?;
        let a = |k| self.lam.surface_area_density(&self.ec, Side::Negative, y, k);
        Some((0..l.nxn).map(|k| self.sei.volume_thickness(&self.ec, y, k, a(k))).sum::<f64>() / l.nxn as f64)
    }

    fn active_material(&self, y: &[f64]) -> Option<super::submodels::lam::ActiveMaterial> {
        self.lam.summary(&self.ec, y)
    }

    fn fields(&self, y: &[f64]) -> Vec<super::Field> {
        use super::Field;
        let l = &self.layout;
        let x = self.ec.x_centres();
        let surfaces = |side: Side| -> Vec<f64> {
            (0..l.nx())
                .filter_map(|i| l.electrode_of(i))
                .filter(|&(s, _, _)| s == side)
                .map(|(_, k, start)| self.ec.sphere(side).surface(&self.lam.concentrations(side, y, &y[start..start + l.nr(side)], k)))
                .collect()
        };
        let (xn, xp) = (self.ec.electrode_x_centres(Side::Negative), self.ec.electrode_x_centres(Side::Positive));
        vec![
            Field::concentration_x("electrolyte concentration", x.clone(), y[l.ce..l.phie].to_vec()),
            Field::potential_x("electrolyte potential", x, y[l.phie..l.phis_n].to_vec()),
            Field::potential_x("negative solid potential", xn.clone(), y[l.phis_n..l.phis_n + l.nxn].to_vec()),
            Field::potential_x("positive solid potential", xp.clone(), y[l.phis_p..l.phis_p + l.nxp].to_vec()),
            Field::concentration_x("negative particle surface concentration", xn, surfaces(Side::Negative)),
            Field::concentration_x("positive particle surface concentration", xp, surfaces(Side::Positive)),
        ]
    }

    fn output_states(&self) -> Vec<usize> {
        let l = &self.layout;
        [l.phis_p + l.nxp - 2, l.phis_p + l.nxp - 1].into_iter().chain(l.temp).collect()
    }

    fn open_circuit_voltage(&self, y: &[f64]) -> f64 {
        let l = &self.layout;
        let mut mean = [0.0; 2];
        for i in 0..l.nx() {
            if let Some((side, k, start)) = l.electrode_of(i) {
                let c = self.ec.sphere(side).average(&self.lam.concentrations(side, y, &y[start..start + l.nr(side)], k));
                let (slot, n) = if side == Side::Negative { (0, l.nxn) } else { (1, l.nxp) };
                mean[slot] += c / n as f64;
            }
        }
        let temp = self.temp(y);
        self.ec.ocp(Side::Positive, mean[1], temp) - self.ec.ocp(Side::Negative, mean[0], temp)
    }
}

impl PhysicsModel for Dfn {
    fn electrochem(&self) -> &Electrochem {
        &self.ec
    }
    fn set_params(&mut self, params: ParameterSet) {
        self.ec.set_params(params);
        self.electrolyte.refresh(&self.ec);
        self.sigma = Self::solid_conductivities(&self.ec);
    }
}
