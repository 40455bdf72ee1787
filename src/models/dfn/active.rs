//! Loss of active material in the DFN (PyBaMM's `LossActiveMaterial` with "x-average side
//! reactions" false): a volume fraction `eps_s` per electrode x volume, driven by that
//! volume's particle surface stress and (negative electrode) its SEI current; the particle
//! states hold `eps_s c`. See docs/ageing.md, section 2.3, and
//! [`crate::models::submodels::LamLayer`].

use super::Dfn;
use crate::models::electrochem::Side;
use crate::models::submodels::LamDrivers;

impl Dfn {
    /// Zeroes the rates of the lithium lost with each electrode's active material in
    /// `out_phis` (the outputs from the negative solid potential's first row on), which the
    /// volumes then accumulate; nothing without loss of active material.
    pub(super) fn clear_lam_losses(&self, out_phis: &mut [f64]) {
        for side in [Side::Negative, Side::Positive] {
            if let Some(loss) = self.lam.loss_index(side) {
                out_phis[loss - self.layout.phis_n] = 0.0;
            }
        }
    }

    /// Loss of active material in electrode volume `(side, k, i)` (`k` within the
    /// electrode, `i` over the cell) whose particle has shell concentrations `c` (mol/m^3),
    /// outward molar surface flux `flux` (mol/(m^2 s)) and `drivers` (with its volumetric SEI
    /// current), at temperature `temp` (K): writes the rates of its particle states (`eps c`)
    /// into `out.0` and of its volume fraction into `out.1` (the outputs from the negative
    /// solid potential's first row on), and adds the lithium it loses to its electrode's.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn lose_active_material(&self, y: &[f64], (side, k, i): (Side, usize, usize), c: &[f64], flux: f64, drivers: LamDrivers, temp: f64, out: (&mut [f64], &mut [f64])) {
        let (out_particle, out_phis) = out;
        let (fraction, loss) = match (self.lam.fraction_index(side, k), self.lam.loss_index(side)) {
            (Some(f), Some(l)) => (f - self.layout.phis_n, l - self.layout.phis_n),
            _ => return,
        };
        let (rate, lost) = self.lam.volume_rates(&self.ec, side, c, drivers, self.electrolyte.vols[i].dx);
        out_phis[fraction] = rate;
        out_phis[loss] += lost;
        self.lam.particle_rhs(&self.ec, side, k, y, c, flux, rate, temp, out_particle);
    }

    /// Appends the Jacobian pattern of loss of active material in electrode volume
    /// `(side, k)` whose particle states start at `start`, given the columns its kinetics
    /// read (`kinetics`, with its volume fraction and side states): its particle rows, its
    /// volume fraction's row and its electrode's lithium-loss row read the whole particle
    /// and `kinetics` (through `c_k d eps / dt`, the stress and the SEI current); nothing
    /// without loss of active material.
    pub(super) fn push_lam_pattern(&self, p: &mut Vec<(usize, usize)>, side: Side, k: usize, start: usize, kinetics: &[usize]) {
        let (Some(fraction), Some(loss)) = (self.lam.fraction_index(side, k), self.lam.loss_index(side)) else { return };
        let particle = start..start + self.layout.nr(side);
        let columns: Vec<usize> = particle.clone().chain(kinetics.iter().copied()).collect();
        for row in particle.chain([fraction, loss]) {
            p.extend(columns.iter().map(|&c| (row, c)));
        }
    }
}
