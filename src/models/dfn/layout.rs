//! Where each block of the DFN state vector starts (see the module above for the order).

use crate::models::electrochem::{Electrochem, Side};

/// Where each block of the DFN state vector starts.
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    pub nxn: usize,
    pub nxs: usize,
    pub nxp: usize,
    pub nrn: usize,
    pub nrp: usize,
    pub cs_n: usize,
    pub cs_p: usize,
    pub ce: usize,
    pub phie: usize,
    pub phis_n: usize,
    pub phis_p: usize,
    /// With SEI growth: the SEI concentrations of the negative volumes from here, then their
    /// total interfacial current densities.
    pub sei: Option<usize>,
    /// With lithium plating: the plated lithium concentrations of the negative volumes from
    /// here, then their dead lithium concentrations.
    pub plating: Option<usize>,
    /// With loss of active material: the volume fractions of the negative then the positive
    /// volumes from here, then the lithium lost with each electrode's active material.
    pub lam: Option<usize>,
    pub temp: Option<usize>,
    pub len: usize,
}

impl Layout {
    pub(super) fn new(ec: &Electrochem) -> Self {
        let d = &ec.disc;
        let (nxn, nxs, nxp) = (d.x_n.len(), d.x_s.len(), d.x_p.len());
        let (nrn, nrp) = (d.sphere_n.len(), d.sphere_p.len());
        let nx = nxn + nxs + nxp;
        let cs_n = 0;
        let cs_p = cs_n + nxn * nrn;
        let ce = cs_p + nxp * nrp;
        let phie = ce + nx;
        let phis_n = phie + nx;
        let phis_p = phis_n + nxn;
        let mut end = phis_p + nxp;
        let mut block = |on: bool, len: usize| {
            let start = on.then_some(end);
            end += if on { len } else { 0 };
            start
        };
        let sei = block(ec.submodels.sei != crate::models::submodels::SeiModel::None, 2 * nxn);
        let plating = block(ec.submodels.plating != crate::models::submodels::PlatingModel::None, 2 * nxn);
        let lam = block(ec.submodels.lam != crate::models::submodels::LamModel::None, nxn + nxp + 2);
        let temp = block(ec.submodels.thermal, 1);
        Self { nxn, nxs, nxp, nrn, nrp, cs_n, cs_p, ce, phie, phis_n, phis_p, sei, plating, lam, temp, len: end }
    }

    pub fn nx(&self) -> usize {
        self.nxn + self.nxs + self.nxp
    }

    /// For x volume `i`: the electrode it lies in, its index within that electrode, and the
    /// start of its particle shells.
    pub fn electrode_of(&self, i: usize) -> Option<(Side, usize, usize)> {
        if i < self.nxn {
            Some((Side::Negative, i, self.cs_n + i * self.nrn))
        } else if i >= self.nxn + self.nxs {
            let k = i - self.nxn - self.nxs;
            Some((Side::Positive, k, self.cs_p + k * self.nrp))
        } else {
            None
        }
    }

    pub(super) fn nr(&self, side: Side) -> usize {
        match side {
            Side::Negative => self.nrn,
            Side::Positive => self.nrp,
        }
    }

    pub(super) fn phis(&self, side: Side, k: usize) -> usize {
        match side {
            Side::Negative => self.phis_n + k,
            Side::Positive => self.phis_p + k,
        }
    }
}
