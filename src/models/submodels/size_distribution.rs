//! Particle-size distribution, as PyBaMM's option "particle size" = "distribution" (its
//! many-particle model, MPM, Kirk et al. 2020) in the single-particle models.
//!
//! Each electrode's particle radii follow the area-weighted lognormal distribution that
//! `pybamm.get_size_distribution_parameters` builds: area-weighted mean `R` (the electrode's
//! `particle_radius`, m), standard deviation `s R` (`radius_relative_std` = `s`), radii from
//! `R_min = max(0, 1 - 5 s) R` to `R_max = (1 + 5 s) R`, discretised as PyBaMM's uniform
//! "particle size" mesh: the centres `R_i` of `n` equal bins (`mesh.size_n`, `mesh.size_p`,
//! PyBaMM's 30). On that mesh:
//! - area-weighted fractions `w_a,i = f_a(R_i) / sum f_a` (PyBaMM normalises the discrete
//!   integral), volume-weighted `w_v,i = R_i w_a,i / sum R w_a`, the surface area density
//!   `a = 3 eps_s / R_a` with the area-weighted mean radius `R_a = sum w_a,i R_i`;
//! - each class has its own spherical particle (`shells` shells of width `R_i / shells`, the
//!   same [`SphereMesh`] as the single particle);
//! - all classes share the electrode's potential difference `delta = phi_s - phi_e` (V),
//!   each reacts by Butler-Volmer at its own surface concentration, and the area-weighted
//!   mean current is the electrode's: `sum w_a,i j_i = I / (a L A)`. PyBaMM holds `delta` as
//!   an algebraic state ("surface form" = "algebraic"); here it is solved inside the
//!   right-hand side ([`shared_potential`]), which is the same equation, so the model stays an
//!   ODE;
//! - the terminal voltage is `delta_p - delta_n` (minus the contact resistance's drop).
//!
//! With `s = 0` every class has the mean radius and equal weight: the single-particle model.

use serde::{Deserialize, Serialize};

use crate::geometry::SphereMesh;
use crate::models::Electrochem;
use crate::models::electrochem::Side;
use crate::models::kinetics::{particle_factor, shared_potential};

/// Whether the electrodes' particles have one size or a distribution of sizes (PyBaMM's
/// "particle size" option).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum ParticleSize {
    /// One particle radius per electrode.
    #[default]
    #[serde(rename = "single")]
    Single,
    /// A lognormal distribution of radii per electrode (`radius_relative_std`), `mesh.size_n`
    /// and `mesh.size_p` classes.
    #[serde(rename = "distribution")]
    Distribution,
}

/// The particle size classes of one electrode and their particles.
#[derive(Clone, Debug)]
pub struct SizeClasses {
    /// Class radii `R_i` (m).
    pub radii: Vec<f64>,
    /// Area-weighted fractions `w_a,i` (-), summing to 1.
    pub area_weights: Vec<f64>,
    /// Volume-weighted fractions `w_v,i` (-), summing to 1.
    pub volume_weights: Vec<f64>,
    /// Area-weighted mean radius `R_a` (m).
    pub mean_radius: f64,
    /// Each class's particle.
    spheres: Vec<SphereMesh>,
    /// Shells per particle.
    shells: usize,
}

impl SizeClasses {
    /// PyBaMM's lognormal distribution of area-weighted mean `mean` (m) and standard deviation
    /// `relative_std * mean` on `classes` bins, with `shells` shells per particle; with
    /// `relative_std = 0`, `classes` equal particles of radius `mean`.
    pub fn lognormal(mean: f64, relative_std: f64, classes: usize, shells: usize) -> Self {
        let n = classes as f64;
        let (radii, area): (Vec<f64>, Vec<f64>) = if relative_std == 0.0 {
            (vec![mean; classes], vec![1.0 / n; classes])
        } else {
            let (r_min, r_max) = ((1.0 - 5.0 * relative_std).max(0.0) * mean, (1.0 + 5.0 * relative_std) * mean);
            let dr = (r_max - r_min) / n;
            let radii: Vec<f64> = (0..classes).map(|i| r_min + (i as f64 + 0.5) * dr).collect();
            // ln R ~ N(mu, sigma^2) with mean `mean` and standard deviation `s mean` of R.
            let sigma2 = (1.0 + relative_std * relative_std).ln();
            let mu = (mean / (1.0 + relative_std * relative_std).sqrt()).ln();
            let f: Vec<f64> = radii.iter().map(|r| (-(r.ln() - mu).powi(2) / (2.0 * sigma2)).exp() / r).collect();
            (radii, f)
        };
        let total: f64 = area.iter().sum();
        let area_weights: Vec<f64> = area.iter().map(|f| f / total).collect();
        let mean_radius: f64 = radii.iter().zip(&area_weights).map(|(r, w)| r * w).sum();
        let volume_weights = radii.iter().zip(&area_weights).map(|(r, w)| r * w / mean_radius).collect();
        let spheres = radii.iter().map(|&r| SphereMesh::new(r, shells)).collect();
        Self { radii, area_weights, volume_weights, mean_radius, spheres, shells }
    }

    /// The classes of an electrode of the model: its radius and relative standard deviation,
    /// the mesh's size and shell counts.
    pub fn of(ec: &Electrochem, side: Side) -> Self {
        let e = ec.electrode(side);
        let sizes = ec.disc.geometry.sizes;
        let classes = if side == Side::Negative { sizes.size_n } else { sizes.size_p };
        Self::lognormal(e.particle_radius, e.radius_relative_std, classes, ec.sphere(side).len())
    }

    /// Number of classes.
    pub fn len(&self) -> usize {
        self.radii.len()
    }

    /// Number of states: shells of every class, class by class.
    pub fn states(&self) -> usize {
        self.len() * self.shells
    }

    /// The shells of class `i` in the electrode's block of states `c`.
    fn class<'a>(&self, c: &'a [f64], i: usize) -> &'a [f64] {
        &c[i * self.shells..(i + 1) * self.shells]
    }

    /// Surface concentration (mol/m^3) of each class (PyBaMM's linear extrapolation).
    pub fn surfaces(&self, c: &[f64]) -> Vec<f64> {
        self.spheres.iter().enumerate().map(|(i, s)| s.surface(self.class(c, i))).collect()
    }

    /// Volume-weighted mean concentration (mol/m^3) of the electrode's particles: its lithium
    /// per unit volume of active material.
    pub fn average(&self, c: &[f64]) -> f64 {
        self.spheres.iter().enumerate().map(|(i, s)| self.volume_weights[i] * s.average(self.class(c, i))).sum()
    }

    /// Area-weighted mean of `values` over the classes.
    pub fn area_mean(&self, values: &[f64]) -> f64 {
        values.iter().zip(&self.area_weights).map(|(v, w)| v * w).sum()
    }

    /// Writes `dc/dt` of every class for diffusivity `diff` (m^2/s) and interfacial current
    /// densities `currents` (A/m^2, positive out of the particle).
    pub fn diffusion(&self, c: &[f64], diff: f64, currents: &[f64], out: &mut [f64]) {
        for (i, (s, j)) in self.spheres.iter().zip(currents).enumerate() {
            let range = i * self.shells..(i + 1) * self.shells;
            s.diffusion(&c[range.clone()], diff, Electrochem::molar_flux(*j), &mut out[range]);
        }
    }

    /// Indices, within the block, of the states the surface concentrations read: the last two
    /// shells of each class.
    pub fn surface_states(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.len()).flat_map(move |i| [(i + 1) * self.shells - 2, (i + 1) * self.shells - 1])
    }

    /// Appends the Jacobian pattern of the block starting at `start`: each particle's
    /// three-point stencil, and every class's outer shell reading every class's surface
    /// (through the shared potential difference).
    pub fn push_pattern(&self, p: &mut Vec<(usize, usize)>, start: usize) {
        for i in 0..self.len() {
            crate::models::push_tridiagonal(p, start + i * self.shells, self.shells);
        }
        for i in 0..self.len() {
            let row = start + (i + 1) * self.shells - 1;
            p.extend(self.surface_states().map(|k| (row, start + k)));
        }
    }
}

/// One electrode's reaction at one state.
#[derive(Clone, Debug)]
pub struct Reaction {
    /// Potential difference `phi_s - phi_e` (V) shared by the classes.
    pub delta: f64,
    /// Each class's interfacial current density (A/m^2).
    pub currents: Vec<f64>,
    /// Area-weighted mean open-circuit potential (V) of the class surfaces.
    pub mean_ocp: f64,
    /// Area-weighted mean entropic change dU/dT (V/K) of the class surfaces.
    pub mean_entropic_change: f64,
}

impl Electrochem {
    /// The reaction of an electrode whose classes `sizes` hold the block `c` (mol/m^3) at cell
    /// current `current` (A) and temperature `temp` (K): exchange currents as the SPM's
    /// (PyBaMM's MPM regularises the particle factors, not the constant `sqrt(c_e)`), OCPs
    /// with PyBaMM's end asymptotes ([`Electrochem::bounded_ocp`]: the small particles
    /// fill or empty first).
    pub fn size_reaction(&self, side: Side, sizes: &SizeClasses, c: &[f64], current: f64, temp: f64) -> Reaction {
        let e = self.electrode(side);
        let j = current / (self.area() * 3.0 * e.active_fraction / sizes.mean_radius * e.thickness);
        let j = if side == Side::Negative { j } else { -j };
        let k = self.rate_constant(side, temp) * self.params.electrolyte.initial_concentration.sqrt();
        let surfaces = sizes.surfaces(c);
        let j0: Vec<f64> = surfaces.iter().map(|&s| k * particle_factor(s.clamp(0.0, e.max_concentration), e.max_concentration)).collect();
        let ocp: Vec<f64> = surfaces.iter().map(|&s| self.bounded_ocp(side, s, temp)).collect();
        let entropic: Vec<f64> = surfaces.iter().map(|&s| self.entropic_change(side, s.clamp(0.0, e.max_concentration))).collect();
        let mut currents = vec![0.0; sizes.len()];
        let delta = shared_potential(&sizes.area_weights, &j0, &ocp, j, e.charge_transfer_coefficient, temp, &mut currents);
        Reaction { delta, currents, mean_ocp: sizes.area_mean(&ocp), mean_entropic_change: sizes.area_mean(&entropic) }
    }
}

#[cfg(test)]
mod tests {
    use super::SizeClasses;

    /// PyBaMM 26.10's MPM on Chen 2020 (relative std 0.3, 30 sizes): the negative radii run
    /// from 2.441667e-7 to 1.4405833e-5 m.
    #[test]
    fn classes_are_pybamms_mesh() {
        let s = SizeClasses::lognormal(5.86e-6, 0.3, 30, 20);
        assert!((s.radii[0] / 2.44166667e-7 - 1.0).abs() < 1e-8 && (s.radii[29] / 1.44058333e-5 - 1.0).abs() < 1e-8);
        assert!((s.area_weights.iter().sum::<f64>() - 1.0).abs() < 1e-15 && (s.volume_weights.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        assert!((s.mean_radius / 5.86e-6 - 1.0).abs() < 1e-3, "{}", s.mean_radius);
        let narrow = SizeClasses::lognormal(5.86e-6, 0.01, 30, 20);
        assert!((narrow.radii[0] / (0.95 * 5.86e-6) - 1.0).abs() < 2e-3);
        let one = SizeClasses::lognormal(5.86e-6, 0.0, 4, 20);
        assert_eq!((one.radii[3], one.area_weights[0]), (5.86e-6, 0.25));
        assert!((one.mean_radius / 5.86e-6 - 1.0).abs() < 1e-15);
    }
}
