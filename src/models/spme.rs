//! Single particle model with electrolyte: one representative particle per electrode with
//! uniform interfacial current, plus electrolyte diffusion through the cell; the voltage adds
//! the electrolyte's concentration and ohmic overpotentials (composite form) and the solid
//! phase's ohmic drop.
//!
//! States: negative shells, positive shells (mol/m^3), electrolyte concentration over all x
//! volumes (mol/m^3), the SEI concentration (mol/m^3) when an SEI submodel is on, the LAM
//! states when a loss-of-active-material submodel is on (the shells then hold `eps c`, see
//! [`LamLayer`]), the plated then the dead lithium concentration (mol/m^3) of each negative
//! x volume when a plating submodel is on, then `T` (K) when the thermal submodel is on.

use std::borrow::Cow;

use super::electrochem::{Electrochem, Side};
use super::electrolyte::ElectrolyteOp;
use super::kinetics::{log_mean, mean_overpotential};
use super::submodels::plating::Site;
use super::submodels::{LamDrivers, LamLayer, PlatingLayer, SeiLayer};
use super::submodels::thermal::{SideReactionSite, bernardi_heat};
use super::{Model, PhysicsModel, push_tridiagonal};
use crate::params::{FARADAY, GAS_CONSTANT, ParameterSet};

#[derive(Clone, Debug)]
pub struct Spme {
    pub ec: Electrochem,
    electrolyte: ElectrolyteOp,
    /// Prescribed ionic current at the interior x faces per unit applied current density (-):
    /// the piecewise-linear profile at the volume centres, interpolated to the faces.
    ionic_current_shape: Vec<f64>,
    consts: VoltageConsts,
    sei: SeiLayer,
    lam: LamLayer,
    plating: PlatingLayer,
    mass: Vec<f64>,
    scale: Vec<f64>,
}

/// Parameter-derived constants of the voltage, refreshed with the parameters.
#[derive(Clone, Debug)]
struct VoltageConsts {
    /// x-average of `1 / eps` over the cell (-).
    avg_inv_eps: f64,
    /// Cell thickness (m).
    length: f64,
    /// `L_n / (3 eps_n^b) + L_s / eps_s^b + P_p / eps_p^b` (m): the electrolyte's ohmic
    /// resistance times plate area times bulk conductivity, with `P_p` the mesh value of
    /// `L_p / 3` (see [`composite_lengths`]).
    ohmic_length: f64,
    /// Solid-phase ohmic resistance times plate area (ohm m^2), `S_n / sigma_n + S_p /
    /// sigma_p` with the mesh values of `L / 3` (see [`composite_lengths`]).
    solid_resistance: f64,
    /// The x-average of `x (2 L_n - x) / (2 L_n)` over the negative volumes (m), `L_n / 3`
    /// on the mesh (see [`composite_lengths`]).
    solid_n: f64,
    /// x volumes of the negative and positive electrodes (each of uniform width).
    negative: std::ops::Range<usize>,
    positive: std::ops::Range<usize>,
}

impl VoltageConsts {
    fn new(ec: &Electrochem, op: &ElectrolyteOp) -> Self {
        let p = &ec.params;
        let vols = &op.vols;
        let length: f64 = vols.iter().map(|v| v.dx).sum();
        let avg_inv_eps = vols.iter().map(|v| v.dx / v.eps).sum::<f64>() / length;
        let (n, s, pe) = (&p.negative, &p.separator, &p.positive);
        let lengths = composite_lengths(ec);
        let ohmic_length = n.thickness / (3.0 * n.porosity.powf(n.bruggeman_electrolyte))
            + s.thickness / s.porosity.powf(s.bruggeman)
            + lengths.electrolyte_p / pe.porosity.powf(pe.bruggeman_electrolyte);
        let solid_resistance = lengths.solid_n / ec.effective_conductivity(Side::Negative)
            + lengths.solid_p / ec.effective_conductivity(Side::Positive);
        let range = |side: Side| {
            let first = vols.iter().position(|v| v.side == Some(side)).unwrap_or(0);
            let count = vols.iter().filter(|v| v.side == Some(side)).count();
            debug_assert!(vols[first..first + count].iter().all(|v| v.side == Some(side) && v.dx == vols[first].dx));
            first..first + count
        };
        Self { avg_inv_eps, length, ohmic_length, solid_resistance, solid_n: lengths.solid_n, negative: range(Side::Negative), positive: range(Side::Positive) }
    }

    fn electrode(&self, side: Side) -> std::ops::Range<usize> {
        match side {
            Side::Negative => self.negative.clone(),
            Side::Positive => self.positive.clone(),
        }
    }
}

/// The lengths (m) by which the composite solution's ohmic terms enter the voltage, as
/// PyBaMM evaluates them on the finite-volume mesh. Each is `L / 3` of its electrode
/// analytically; PyBaMM evaluates the quadratic potential profiles at the volume centres and
/// then x-averages them (midpoint rule) or extrapolates them linearly to the current
/// collector, which shifts each by O(dx^2):
/// - `electrolyte_p`: mean over the positive volumes of `(L_p^2 - (L - x)^2) / (2 L_p)`
///   (the x-average of the positive electrolyte potential): `L_p / 3 + dx_p^2 / (24 L_p)`;
/// - `solid_n`: mean over the negative volumes of `x (2 L_n - x) / (2 L_n)` (the x-average
///   of the negative solid potential): `L_n / 3 - dx_n^2 / (24 L_n)`;
/// - `solid_p`: `g(L) - L + L_p / 3` with `g(x) = x + (x - L)^2 / (2 L_p)` extrapolated
///   linearly to `x = L` from the last two positive volumes (the solid potential at the
///   current collector): `L_p / 3 - 3 dx_p^2 / (8 L_p)`.
///
/// On Chen 2020 at 20 volumes per electrode the three together move the 1C voltage by
/// 0.017 mV against the analytic `L / 3` (0.019 mV from `solid_p`); they vanish as dx^2.
struct CompositeLengths {
    electrolyte_p: f64,
    solid_n: f64,
    solid_p: f64,
}

fn composite_lengths(ec: &Electrochem) -> CompositeLengths {
    let g = &ec.disc.geometry;
    let (ln, lp) = (g.negative_thickness, g.positive_thickness);
    let length = ln + g.separator_thickness + lp;
    let (xn, xp) = (ec.electrode_x_centres(Side::Negative), ec.electrode_x_centres(Side::Positive));
    let mean = |x: &[f64], f: &dyn Fn(f64) -> f64| x.iter().map(|&x| f(x)).sum::<f64>() / x.len() as f64;
    let electrolyte_p = mean(&xp, &|x| (lp * lp - (length - x).powi(2)) / (2.0 * lp));
    let solid_n = mean(&xn, &|x| x * (2.0 * ln - x) / (2.0 * ln));
    let gp = |x: f64| x + (x - length).powi(2) / (2.0 * lp);
    let (a, b) = (xp[xp.len() - 2], xp[xp.len() - 1]);
    let g_l = gp(b) + (length - b) / (b - a) * (gp(b) - gp(a));
    CompositeLengths { electrolyte_p, solid_n, solid_p: g_l - length + lp / 3.0 }
}

impl Spme {
    pub fn new(ec: Electrochem) -> Self {
        let electrolyte = ElectrolyteOp::new(&ec);
        let (nn, np, nx) = (ec.disc.sphere_n.len(), ec.disc.sphere_p.len(), electrolyte.len());
        let p = &ec.params;
        let sei = SeiLayer::new(ec.submodels.sei, nn + np + nx, ec.disc.x_n.centres.len());
        let lam = LamLayer::new(ec.submodels.lam, nn + np + nx + sei.len(), [1, 1]);
        let plating = PlatingLayer::new(ec.submodels.plating, nn + np + nx + sei.len() + lam.len(), ec.disc.x_n.centres.len());
        let mut scale = vec![lam.shell_scale(&ec, Side::Negative); nn];
        scale.extend(std::iter::repeat_n(lam.shell_scale(&ec, Side::Positive), np));
        scale.extend(std::iter::repeat_n(p.electrolyte.initial_concentration, nx));
        scale.extend(sei.indices().map(|_| SeiLayer::initial_concentration(&ec)));
        lam.push_scale(&ec, &mut scale);
        plating.push_scale(&ec, &mut scale);
        if ec.submodels.thermal {
            scale.push(p.thermal.ambient_temperature);
        }
        let mass = vec![1.0; scale.len()];
        let ionic_current_shape = Self::ionic_current_shape(&ec, &electrolyte);
        let consts = VoltageConsts::new(&ec, &electrolyte);
        Self { ec, electrolyte, ionic_current_shape, consts, sei, lam, plating, mass, scale }
    }

    /// The leading-order ionic current `x/L_n`, 1, `(L - x)/L_p` at the volume centres,
    /// linearly interpolated to the interior faces (as PyBaMM discretises it).
    fn ionic_current_shape(ec: &Electrochem, op: &ElectrolyteOp) -> Vec<f64> {
        let g = &ec.disc.geometry;
        let (ln, ls, lp) = (g.negative_thickness, g.separator_thickness, g.positive_thickness);
        let node: Vec<f64> = ec
            .disc
            .x_centres()
            .iter()
            .map(|&x| {
                if x < ln {
                    x / ln
                } else if x < ln + ls {
                    1.0
                } else {
                    (ln + ls + lp - x) / lp
                }
            })
            .collect();
        (0..node.len() - 1).map(|i| op.arithmetic(i, node[i], node[i + 1])).collect()
    }

    fn blocks<'a>(&self, y: &'a [f64]) -> (&'a [f64], &'a [f64], &'a [f64]) {
        let nn = self.ec.disc.sphere_n.len();
        let np = self.ec.disc.sphere_p.len();
        let nx = self.electrolyte.len();
        (&y[..nn], &y[nn..nn + np], &y[nn + np..nn + np + nx])
    }

    fn temp(&self, y: &[f64]) -> f64 {
        self.temperature_state().map_or(self.ec.params.thermal.ambient_temperature, |k| y[k])
    }

    /// Volumetric reaction current `a j` (A/m^3) in each x volume, uniform in each electrode,
    /// as a function of the volume's index.
    fn reaction(&self, current: f64) -> impl Fn(usize) -> f64 + '_ {
        let j = [Side::Negative, Side::Positive].map(|side| self.ec.mean_interfacial_current(side, current));
        move |i| {
            let v = &self.electrolyte.vols[i];
            match v.side {
                Some(Side::Negative) => v.a * j[0],
                Some(Side::Positive) => v.a * j[1],
                None => 0.0,
            }
        }
    }

    /// Electrolyte overpotential (V): PyBaMM's composite form, i.e. the concentration
    /// (MacInnes) term `chi R T / F (mean_p ln(c_e / c_av) - mean_n ln(c_e / c_av))` plus
    /// the ohmic drop `-(I/A) (L_n/(3 kappa_n) + L_s/kappa_s + L_p/(3 kappa_p))` with the
    /// effective conductivities at the cell-averaged concentration `c_av` (`L_p / 3` as
    /// evaluated on the mesh, see [`CompositeLengths`]).
    fn electrolyte_overpotential(&self, ce: &[f64], current: f64, temp: f64) -> f64 {
        let k = &self.consts;
        let kappa = self.bulk_conductivity(ce, temp);
        let concentration = self.macinnes_factor(temp) * (self.mean_ln(ce, Side::Positive) - self.mean_ln(ce, Side::Negative));
        concentration - current / self.ec.area() * k.ohmic_length / kappa
    }

    /// Electrolyte conductivity (S/m, before tortuosity) at the cell-averaged concentration.
    fn bulk_conductivity(&self, ce: &[f64], temp: f64) -> f64 {
        let e = &self.ec.params.electrolyte;
        let k = &self.consts;
        // PyBaMM's x-average of c_e in the SPMe is avg(eps c_e) avg(1/eps) (its XAverage pulls
        // the piecewise-constant 1/eps out); it enters only through kappa.
        let avg_eps_c = self.electrolyte.vols.iter().zip(ce).map(|(v, c)| v.dx * v.eps * c).sum::<f64>() / k.length;
        let c_av = avg_eps_c * k.avg_inv_eps;
        let arr = super::kinetics::arrhenius(e.activation_energy, self.ec.t_ref(), temp);
        e.conductivity.eval(c_av.max(super::electrolyte::TRANSPORT_FLOOR)) * e.conductivity_factor * arr
    }

    /// `chi R T / F` (V) of the MacInnes (concentration) term.
    fn macinnes_factor(&self, temp: f64) -> f64 {
        let e = &self.ec.params.electrolyte;
        2.0 * (1.0 - e.transference_number) * e.thermodynamic_factor * GAS_CONSTANT * temp / FARADAY
    }

    /// Mean over an electrode's (equal-width) volumes of `ln c_e` (the `ln c_av` of the
    /// MacInnes terms cancels in their differences).
    fn mean_ln(&self, ce: &[f64], side: Side) -> f64 {
        log_mean(ce[self.consts.electrode(side)].iter().map(|&c| c.max(super::electrolyte::LOG_FLOOR)))
    }

    /// `phi_s - phi_e` (V) at each negative volume's centre: PyBaMM's composite potentials
    /// about the x-average `delta_phi_av` (V), i.e. its solid-phase and electrolyte ohmic
    /// profiles and the MacInnes term, each less its x-average (the electrolyte's ohmic one
    /// less its analytic average `-L_n / 3`). PyBaMM's SPMe evaluates the SEI reaction with it
    /// at each x, then x-averages the reaction current.
    fn negative_potential_profile<'a>(&'a self, delta_phi_av: f64, ce: &'a [f64], current: f64, temp: f64) -> impl Iterator<Item = f64> + 'a {
        let ec = &self.ec;
        let n = &ec.params.negative;
        let i = current / ec.area();
        let ln = n.thickness;
        let solid = i / ec.effective_conductivity(Side::Negative);
        let electrolyte = i / (self.bulk_conductivity(ce, temp) * n.porosity.powf(n.bruggeman_electrolyte));
        let chi_rt_f = self.macinnes_factor(temp);
        let mean_ln = self.mean_ln(ce, Side::Negative);
        let solid_n = self.consts.solid_n;
        ec.disc.x_n.centres.iter().zip(&ce[self.consts.negative.clone()]).map(move |(&x, &c)| {
            delta_phi_av + solid * (solid_n - x * (2.0 * ln - x) / (2.0 * ln)) + chi_rt_f * (mean_ln - c.max(super::electrolyte::LOG_FLOOR).ln())
                + electrolyte * ((x * x - ln * ln) / (2.0 * ln) + ln / 3.0)
        })
    }

    /// `phi_s - phi_e` (V) x-averaged over an electrode with particle surface `c_s`
    /// (mol/m^3): its OCP plus the reaction overpotential x-averaged with the local
    /// electrolyte concentrations `ce` (mol/m^3) in the exchange current (of the total
    /// interfacial current, PyBaMM's inverse kinetics), plus the SEI film's drop in the
    /// negative electrode (read from the state `y`).
    fn surface_potential_difference(&self, side: Side, c_s: f64, y: &[f64], current: f64, temp: f64) -> f64 {
        let (_, _, ce) = self.blocks(y);
        let ec = &self.ec;
        let alpha = ec.electrode(side).charge_transfer_coefficient;
        let j = self.lam.interfacial_current(ec, side, y, current);
        // j0 is the particle factor, once per electrode, times the electrolyte factor.
        // PyBaMM 26.10's SPMe regularises only the electrolyte factor: its regulariser
        // does not recognise the x-averaged surface concentration and falls back to a
        // scale of 1 mol/m^3, which leaves the particle square roots unchanged (2.6e-5
        // of j0 at stoichiometry 0.9), so the plain product is used here.
        let (k, c_max) = (ec.rate_constant(side, temp), ec.electrode(side).max_concentration);
        let c_e_ref = ec.params.electrolyte.initial_concentration;
        let c_in = c_s.clamp(0.0, c_max);
        let j0_particle = k * (c_in * (c_max - c_in)).sqrt();
        let film = if side == Side::Negative { self.sei.film(ec, y, j, self.lam.surface_area_density(ec, side, y, 0)) } else { 0.0 };
        ec.ocp(side, c_s, temp) + mean_overpotential(j, j0_particle, &ce[self.consts.electrode(side)], c_e_ref, alpha, temp) + film
    }

    /// Writes the SEI and plating states' rates into `out` and returns the x-averaged
    /// side-reaction current densities (A/m^2) of the SEI and of plating; zeros without them.
    /// PyBaMM's SPMe does not x-average side reactions: each negative volume grows its own
    /// SEI and plates its own lithium with its own `phi_s - phi_e` (and `c_e`).
    fn side_rhs(&self, y: &[f64], sn: f64, current: f64, temp: f64, out: &mut [f64]) -> [f64; 2] {
        if self.sei.len() + self.plating.len() == 0 {
            return [0.0; 2];
        }
        let (_, _, ce) = self.blocks(y);
        let delta_phi = self.surface_potential_difference(Side::Negative, sn, y, current, temp);
        let (ec, side) = (&self.ec, Side::Negative);
        let (j, a) = (self.lam.interfacial_current(ec, side, y, current), self.lam.surface_area_density(ec, side, y, 0));
        let j_sei = self.sei.rhs(ec, y, self.negative_potential_profile(delta_phi, ce, current, temp), j, a, temp, out);
        let sites = self.negative_potential_profile(delta_phi, ce, current, temp).zip(&ce[self.consts.negative.clone()]).enumerate().map(|(i, (delta_phi, &c_e))| {
            Site { delta_phi, electrolyte_concentration: c_e, sei_thickness: self.sei.volume_thickness(ec, y, i, a) }
        });
        let j_plating = self.plating.rhs(ec, y, sites, self.sei.film(ec, y, j, a), a, temp, out);
        [j_sei, j_plating]
    }

    /// Heat (W) that [`bernardi_heat`] counts and PyBaMM does not with side reactions of
    /// x-averaged current density `j_side` (A/m^2) on the negative particle of surface
    /// concentration `sn` (mol/m^3), at the x-averaged `phi_s - phi_e`; zero without them.
    /// See [`SideReactionSite::uncounted_heat`].
    fn uncounted_side_heat(&self, y: &[f64], sn: f64, current: f64, temp: f64, j_side: f64) -> f64 {
        if self.sei.len() + self.plating.len() == 0 {
            return 0.0;
        }
        let (ec, side) = (&self.ec, Side::Negative);
        let (j, a) = (self.lam.interfacial_current(ec, side, y, current), self.lam.surface_area_density(ec, side, y, 0));
        let delta_phi = self.surface_potential_difference(side, sn, y, current, temp);
        let site = SideReactionSite { a, total_current: j, side_current: j_side, delta_phi, ocp: ec.ocp(side, sn, temp), film: self.sei.film(ec, y, j, a) };
        site.uncounted_heat(temp, ec.entropic_change(side, sn)) * ec.area() * ec.params.negative.thickness
    }

    /// Solid-phase ohmic drop between the x-averaged and current-collector potentials (V).
    fn solid_ohmic(&self, current: f64) -> f64 {
        current / self.ec.area() * self.consts.solid_resistance
    }

    /// Shell concentrations (mol/m^3) of the negative and positive particles.
    fn particles<'a>(&self, y: &'a [f64]) -> (Cow<'a, [f64]>, Cow<'a, [f64]>) {
        let (n, p, _) = self.blocks(y);
        (self.lam.concentrations(Side::Negative, y, n, 0), self.lam.concentrations(Side::Positive, y, p, 0))
    }

    fn surfaces(&self, y: &[f64]) -> (f64, f64) {
        let (cn, cp) = self.particles(y);
        self.ec.single_particle_surfaces(&cn, &cp)
    }
}

impl Model for Spme {
    fn name(&self) -> String {
        "SPMe".into()
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
        let nx = self.electrolyte.len();
        let mut p = Vec::new();
        for (start, len) in [(0, nn), (nn, np), (nn + np, nx)] {
            push_tridiagonal(&mut p, start, len);
        }
        let t = nn + np + nx + self.sei.len() + self.lam.len() + self.plating.len();
        // The SEI reads the electrolyte everywhere (through the conductivity at its mean),
        // and the negative volume fraction (its surface area).
        let electrolyte: Vec<usize> = (nn + np..nn + np + nx).chain(self.ec.submodels.thermal.then_some(t)).collect();
        let sei_reads: Vec<usize> = electrolyte.iter().copied().chain(self.lam.indices().take(1)).collect();
        self.sei.push_pattern(&mut p, [nn - 2, nn - 1], &sei_reads);
        // Plating reads the same and the SEI (its film and thickness).
        let plating_reads: Vec<usize> = sei_reads.iter().copied().chain(self.sei.indices()).collect();
        self.plating.push_pattern(&mut p, [nn - 2, nn - 1], &plating_reads);
        // LAM reads the SEI's states and inputs when reaction-driven, else only the temperature.
        let lam_reads: Vec<usize> = if self.ec.submodels.lam.reaction() { self.sei.indices().chain(electrolyte).collect() } else { self.ec.submodels.thermal.then_some(t).into_iter().collect() };
        self.lam.push_pattern(&mut p, [0..nn, nn..nn + np], &lam_reads);
        if self.ec.submodels.thermal {
            for i in 0..=t {
                p.push((i, t));
            }
        }
        p
    }

    fn initial_state(&self) -> Vec<f64> {
        let p = &self.ec.params;
        let mut y = vec![self.lam.initial_shell(&self.ec, Side::Negative); self.ec.disc.sphere_n.len()];
        y.extend(std::iter::repeat_n(self.lam.initial_shell(&self.ec, Side::Positive), self.ec.disc.sphere_p.len()));
        y.extend(std::iter::repeat_n(p.electrolyte.initial_concentration, self.electrolyte.len()));
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
        let nx = self.electrolyte.len();
        let temp = self.temp(y);
        let (_, _, ce) = self.blocks(y);
        let (cn, cp) = self.particles(y);
        let (sn, _) = ec.single_particle_surfaces(&cn, &cp);
        let [j_sei, j_plating] = self.side_rhs(y, sn, current, temp, out);
        let a_j_sei = self.lam.surface_area_density(ec, Side::Negative, y, 0) * j_sei;
        let rates = self.lam.rhs(ec, [&cn, &cp], LamDrivers { a_j_sei, current_density: current / ec.area() }, out);
        for (side, c, range, side_reaction, rate) in [(Side::Negative, &cn, 0..nn, j_sei + j_plating, rates[0]), (Side::Positive, &cp, nn..nn + np, 0.0, rates[1])] {
            let flux = Electrochem::molar_flux(self.lam.interfacial_current(ec, side, y, current) - side_reaction);
            self.lam.particle_rhs(ec, side, 0, y, c, flux, rate, temp, &mut out[range]);
        }
        let ionic = (self.ionic_current_shape.as_slice(), current / ec.area());
        self.electrolyte.concentration_rhs(ec, ce, self.reaction(current), Some(ionic), temp, &mut out[nn + np..nn + np + nx]);
        if ec.submodels.thermal {
            let (sn, sp) = self.surfaces(y);
            let ocv = ec.ocp(Side::Positive, sp, temp) - ec.ocp(Side::Negative, sn, temp);
            let heat = bernardi_heat(current, ocv, self.voltage(y, current), temp, ec.docv_dt(sn, sp)) - self.uncounted_side_heat(y, sn, current, temp, j_sei + j_plating);
            out[self.len() - 1] = ec.thermal.rate(heat, temp);
        }
    }

    fn voltage(&self, y: &[f64], current: f64) -> f64 {
        let ec = &self.ec;
        let temp = self.temp(y);
        let (_, _, ce) = self.blocks(y);
        let (sn, sp) = self.surfaces(y);
        self.surface_potential_difference(Side::Positive, sp, y, current, temp) - self.surface_potential_difference(Side::Negative, sn, y, current, temp)
            + self.electrolyte_overpotential(ce, current, temp)
            - self.solid_ohmic(current)
            - current * ec.contact_resistance()
    }

    fn plating_margin(&self, y: &[f64], current: f64) -> Option<f64> {
        let (sn, _) = self.surfaces(y);
        Some(self.surface_potential_difference(Side::Negative, sn, y, current, self.temp(y)))
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

    fn temperature_state(&self) -> Option<usize> {
        self.ec.submodels.thermal.then(|| self.len() - 1)
    }

    fn temperature(&self, y: &[f64]) -> f64 {
        self.temp(y)
    }

    fn solid_lithium(&self, y: &[f64]) -> f64 {
        let (n, p, _) = self.blocks(y);
        self.lam.particle_lithium(&self.ec, Side::Negative, n, self.ec.params.negative.thickness) + self.lam.particle_lithium(&self.ec, Side::Positive, p, self.ec.params.positive.thickness)
    }

    fn fields(&self, y: &[f64]) -> Vec<super::Field> {
        let (_, _, ce) = self.blocks(y);
        let (cn, cp) = self.particles(y);
        let mut fields = self.ec.single_particle_fields(&cn, &cp);
        fields.push(super::Field::concentration_x("electrolyte concentration", self.ec.x_centres(), ce.to_vec()));
        fields
    }

    fn output_states(&self) -> Vec<usize> {
        let (nn, np) = (self.ec.disc.sphere_n.len(), self.ec.disc.sphere_p.len());
        let mut out = self.ec.single_particle_surface_states();
        out.extend(nn + np..nn + np + self.electrolyte.len());
        out.extend(self.sei.indices());
        out.extend(self.lam.indices().take(2));
        out.extend(self.ec.submodels.thermal.then(|| self.len() - 1));
        out
    }

    fn open_circuit_voltage(&self, y: &[f64]) -> f64 {
        let (cn, cp) = self.particles(y);
        self.ec.single_particle_ocv(&cn, &cp, self.temp(y))
    }
}

impl PhysicsModel for Spme {
    fn electrochem(&self) -> &Electrochem {
        &self.ec
    }
    fn set_params(&mut self, params: ParameterSet) {
        self.ec.set_params(params);
        self.electrolyte.refresh(&self.ec);
        self.consts = VoltageConsts::new(&self.ec, &self.electrolyte);
    }
}
