//! Finite-volume electrolyte transport through negative electrode, separator and positive
//! electrode, shared by SPMe and DFN.

use super::electrochem::{Electrochem, Side};
use super::kinetics::arrhenius;
use crate::params::{FARADAY, GAS_CONSTANT};

/// Concentrations (mol/m^3) below which the electrolyte's functions are held at their value
/// there, as PyBaMM's `settings.tolerances` do: where a high-rate discharge empties the
/// electrolyte, the fitted polynomials of diffusivity and conductivity (the conductivity has
/// a `c^1.5` term) stay defined, and the diffusion potential `1 / c_e` stays finite. Above
/// them nothing changes.
pub const TRANSPORT_FLOOR: f64 = 10.0;
/// As [`TRANSPORT_FLOOR`], for `chi R T / (F c_e)` (PyBaMM's `chi__c_e`).
pub const DIFFUSION_POTENTIAL_FLOOR: f64 = 1e-2;
/// As [`TRANSPORT_FLOOR`], for `ln c_e` in the composite (SPMe) electrolyte potential
/// (PyBaMM's `macinnes__c_e`).
pub const LOG_FLOOR: f64 = 1e-15;

/// Per-x-volume material properties.
#[derive(Clone, Debug)]
pub struct Volume {
    /// Electrode the volume lies in (`None` in the separator).
    pub side: Option<Side>,
    /// Porosity (-).
    pub eps: f64,
    /// Transport factor eps^b (-).
    pub tortuosity: f64,
    /// Specific interfacial area (1/m), zero in the separator.
    pub a: f64,
    /// Width (m).
    pub dx: f64,
}

/// The x-direction operator of the electrolyte.
#[derive(Clone, Debug)]
pub struct ElectrolyteOp {
    pub vols: Vec<Volume>,
    /// Centre-to-centre distances between neighbouring volumes (m), `n_x - 1` of them.
    pub gaps: Vec<f64>,
    /// Width fraction `dx_i / (dx_i + dx_{i+1})` (-) of the left volume at each interior face.
    weights: Vec<f64>,
    /// `1 / gaps` (1/m).
    inv_gaps: Vec<f64>,
    /// `1 / dx` (1/m) and `1 / eps` (-) of each volume: the loops multiply instead of divide.
    inv_dx: Vec<f64>,
    inv_eps: Vec<f64>,
}

impl ElectrolyteOp {
    pub fn new(ec: &Electrochem) -> Self {
        let centres = ec.disc.x_centres();
        let gaps: Vec<f64> = centres.windows(2).map(|w| w[1] - w[0]).collect();
        let inv_gaps = gaps.iter().map(|g| 1.0 / g).collect();
        let mut op = Self { vols: Vec::new(), gaps, weights: Vec::new(), inv_gaps, inv_dx: Vec::new(), inv_eps: Vec::new() };
        op.refresh(ec);
        op
    }

    /// Recomputes the material properties after a parameter change.
    pub fn refresh(&mut self, ec: &Electrochem) {
        let p = &ec.params;
        let d = &ec.disc;
        let widths = d.x_widths();
        let (nxn, nxs) = (d.x_n.len(), d.x_s.len());
        self.vols = widths
            .iter()
            .enumerate()
            .map(|(i, &dx)| {
                let side = if i < nxn {
                    Some(Side::Negative)
                } else if i >= nxn + nxs {
                    Some(Side::Positive)
                } else {
                    None
                };
                let (eps, b, a) = match side {
                    Some(s) => {
                        let e = ec.electrode(s);
                        (e.porosity, e.bruggeman_electrolyte, e.surface_area_density())
                    }
                    None => (p.separator.porosity, p.separator.bruggeman, 0.0),
                };
                Volume { side, eps, tortuosity: eps.powf(b), a, dx }
            })
            .collect();
        self.weights = self.vols.windows(2).map(|w| w[0].dx / (w[0].dx + w[1].dx)).collect();
        self.inv_dx = self.vols.iter().map(|v| 1.0 / v.dx).collect();
        self.inv_eps = self.vols.iter().map(|v| 1.0 / v.eps).collect();
    }

    pub fn len(&self) -> usize {
        self.vols.len()
    }

    /// Width-weighted harmonic mean of node values `a`, `b` at the face between volumes `i`
    /// and `i + 1`: the series resistance of the two half-volumes. PyBaMM uses it for a
    /// coefficient multiplying a gradient (fluxes).
    pub fn harmonic(&self, i: usize, a: f64, b: f64) -> f64 {
        harmonic_mean(self.weights[i], a, b)
    }

    /// Width-weighted arithmetic mean of node values at the face between volumes `i` and
    /// `i + 1` (linear interpolation to the face).
    pub fn arithmetic(&self, i: usize, a: f64, b: f64) -> f64 {
        let w = self.weights[i];
        (1.0 - w) * a + w * b
    }

    /// `dc_e/dt` (mol/(m^3 s)) for concentrations `ce` and volumetric reaction currents
    /// `aj(i)` (A/m^3) at temperature `temp` (K).
    ///
    /// With `ionic_current = (shape, i_app)` — the ionic current at the `n_x - 1` interior
    /// faces is `shape * i_app` (A/m^2) — the migration flux
    /// `t+ i_e / F` is added to the face fluxes and the source is `a j / F`, as PyBaMM writes
    /// the SPMe with its prescribed current; without it the two are folded into the source
    /// `(1 - t+) a j / F`, exact when `d i_e/dx = a j` holds discretely (DFN).
    pub fn concentration_rhs(
        &self,
        ec: &Electrochem,
        ce: &[f64],
        aj: impl Fn(usize) -> f64,
        ionic_current: Option<(&[f64], f64)>,
        temp: f64,
        out: &mut [f64],
    ) {
        let p = &ec.params.electrolyte;
        let arr = arrhenius(p.activation_energy, ec.t_ref(), temp);
        let n = self.len();
        let (ce, out, vols) = (&ce[..n], &mut out[..n], &self.vols[..n]);
        let (inv_dx, inv_eps) = (&self.inv_dx[..n], &self.inv_eps[..n]);
        let (weights, inv_gaps) = (&self.weights[..n - 1], &self.inv_gaps[..n - 1]);
        let t_plus = p.transference_number;
        // molar source per unit a*j, and migration flux per unit `shape`
        let (source, migration) = match ionic_current {
            Some((shape, i_app)) => (1.0 / FARADAY, Some((&shape[..n - 1], t_plus * i_app / FARADAY))),
            None => ((1.0 - t_plus) / FARADAY, None),
        };
        // 1 / (eps^b D(c_e)) (s/m^2) at each node: the face's harmonic mean is one division.
        let resistivity = |i: usize| 1.0 / (vols[i].tortuosity * p.diffusivity.eval(ce[i].max(TRANSPORT_FLOOR)) * p.diffusivity_factor * arr);
        let rate = |i: usize, flux_left: f64, flux_right: f64| ((flux_left - flux_right) * inv_dx[i] + source * aj(i)) * inv_eps[i];
        let (mut r_left, mut flux_left) = (resistivity(0), 0.0);
        for i in 0..n - 1 {
            let (r_right, w) = (resistivity(i + 1), weights[i]);
            let mut flux = -(ce[i + 1] - ce[i]) * inv_gaps[i] / (w * r_left + (1.0 - w) * r_right);
            if let Some((shape, m)) = migration {
                flux += m * shape[i];
            }
            out[i] = rate(i, flux_left, flux);
            (r_left, flux_left) = (r_right, flux);
        }
        out[n - 1] = rate(n - 1, flux_left, 0.0);
    }

    /// Subtracts the divergence of the ionic current `d i_e/dx` (A/m^3) from `out`, for
    /// concentrations `ce` (mol/m^3) and potentials `phie` (V) at temperature `temp` (K),
    /// with no current through the current collectors.
    ///
    /// `i_e = kappa_eff (coef dc_e/dx - dphi_e/dx)` at each interior face, as PyBaMM
    /// discretises it: the effective conductivity `eps^b kappa(c_e)` (S/m) interpolated
    /// arithmetically, the diffusion-potential coefficient `2 (1 - t+) chi R T / (F c_e)`
    /// (V m^3/mol) harmonically, i.e. the factor over the width-weighted mean of `c_e`.
    pub fn subtract_current_divergence(&self, ec: &Electrochem, ce: &[f64], phie: &[f64], temp: f64, out: &mut [f64]) {
        let p = &ec.params.electrolyte;
        let arr = arrhenius(p.activation_energy, ec.t_ref(), temp);
        let factor = 2.0 * (1.0 - p.transference_number) * p.thermodynamic_factor * GAS_CONSTANT * temp / FARADAY;
        let n = self.len();
        let (ce, phie, out, vols, inv_dx) = (&ce[..n], &phie[..n], &mut out[..n], &self.vols[..n], &self.inv_dx[..n]);
        let (weights, inv_gaps) = (&self.weights[..n - 1], &self.inv_gaps[..n - 1]);
        let kappa = |i: usize| vols[i].tortuosity * p.conductivity.eval(ce[i].max(TRANSPORT_FLOOR)) * p.conductivity_factor * arr;
        let (mut kappa_left, mut c_left, mut i_left) = (kappa(0), ce[0].max(DIFFUSION_POTENTIAL_FLOOR), 0.0);
        for i in 0..n - 1 {
            let (kappa_right, c_right, w) = (kappa(i + 1), ce[i + 1].max(DIFFUSION_POTENTIAL_FLOOR), weights[i]);
            let coef = factor / (w * c_left + (1.0 - w) * c_right);
            let face = (1.0 - w) * kappa_left + w * kappa_right;
            let i_right = face * (coef * (ce[i + 1] - ce[i]) - (phie[i + 1] - phie[i])) * inv_gaps[i];
            out[i] -= (i_right - i_left) * inv_dx[i];
            (kappa_left, c_left, i_left) = (kappa_right, c_right, i_right);
        }
        out[n - 1] -= (0.0 - i_left) * inv_dx[n - 1];
    }
}

/// `1 / (w / a + (1 - w) / b)`: the harmonic mean of `a` and `b` with weight `w` on `a`.
fn harmonic_mean(w: f64, a: f64, b: f64) -> f64 {
    1.0 / (w / a + (1.0 - w) / b)
}
