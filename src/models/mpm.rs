//! The single particle model with a particle-size distribution in each electrode: PyBaMM's
//! many-particle model (MPM, its SPM with "particle size" = "distribution"), built when
//! `Submodels::particle_size` is `Distribution` on the SPM. See
//! [`super::submodels::size_distribution`].
//!
//! States: the negative classes' shells (mol/m^3, class by class), the positive classes'
//! shells, then `T` (K) when the thermal submodel is on.

use super::electrochem::{Electrochem, Side};
use super::submodels::size_distribution::{Reaction, SizeClasses};
use super::submodels::thermal::bernardi_heat;
use super::{Model, PhysicsModel};
use crate::params::ParameterSet;

#[derive(Clone, Debug)]
pub struct Mpm {
    pub ec: Electrochem,
    /// Size classes of the negative and positive electrodes.
    sizes: [SizeClasses; 2],
    mass: Vec<f64>,
    scale: Vec<f64>,
}

fn slot(side: Side) -> usize {
    match side {
        Side::Negative => 0,
        Side::Positive => 1,
    }
}

impl Mpm {
    pub fn new(ec: Electrochem) -> Self {
        let sizes = [SizeClasses::of(&ec, Side::Negative), SizeClasses::of(&ec, Side::Positive)];
        let mut scale = vec![ec.params.negative.max_concentration; sizes[0].states()];
        scale.extend(std::iter::repeat_n(ec.params.positive.max_concentration, sizes[1].states()));
        if ec.submodels.thermal {
            scale.push(ec.params.thermal.ambient_temperature);
        }
        Self { ec, sizes, mass: vec![1.0; scale.len()], scale }
    }

    /// The size classes of an electrode.
    pub fn sizes(&self, side: Side) -> &SizeClasses {
        &self.sizes[slot(side)]
    }

    /// The states of an electrode's particles.
    fn block<'a>(&self, side: Side, y: &'a [f64]) -> &'a [f64] {
        let nn = self.sizes[0].states();
        match side {
            Side::Negative => &y[..nn],
            Side::Positive => &y[nn..nn + self.sizes[1].states()],
        }
    }

    /// An electrode's reaction at state `y` and current `current` (A).
    pub fn reaction(&self, side: Side, y: &[f64], current: f64) -> Reaction {
        self.ec.size_reaction(side, self.sizes(side), self.block(side, y), current, self.temperature(y))
    }

    /// Surface concentration (mol/m^3) of each class of an electrode.
    pub fn surface_concentrations(&self, side: Side, y: &[f64]) -> Vec<f64> {
        self.sizes(side).surfaces(self.block(side, y))
    }
}

impl Model for Mpm {
    fn name(&self) -> String {
        "SPM+size distribution".into()
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

    fn jacobian_pattern(&self) -> Vec<(usize, usize)> {
        let nn = self.sizes[0].states();
        let mut p = Vec::new();
        self.sizes[0].push_pattern(&mut p, 0);
        self.sizes[1].push_pattern(&mut p, nn);
        if self.ec.submodels.thermal {
            let t = self.len() - 1;
            p.extend((0..t).map(|i| (i, t)));
            p.extend(self.output_states().into_iter().map(|i| (t, i)));
        }
        p
    }

    fn initial_state(&self) -> Vec<f64> {
        let p = &self.ec.params;
        let mut y = vec![p.negative.initial_concentration; self.sizes[0].states()];
        y.extend(std::iter::repeat_n(p.positive.initial_concentration, self.sizes[1].states()));
        if self.ec.submodels.thermal {
            y.push(p.thermal.initial_temperature);
        }
        y
    }

    fn rhs(&self, y: &[f64], current: f64, out: &mut [f64]) {
        let temp = self.temperature(y);
        let nn = self.sizes[0].states();
        let (mut ocv, mut docv_dt) = (0.0, 0.0);
        let mut voltage = -current * self.ec.contact_resistance();
        for (side, range, sign) in [(Side::Negative, 0..nn, -1.0), (Side::Positive, nn..nn + self.sizes[1].states(), 1.0)] {
            let r = self.reaction(side, y, current);
            self.sizes(side).diffusion(&y[range.clone()], self.ec.diffusivity(side, temp), &r.currents, &mut out[range]);
            ocv += sign * r.mean_ocp;
            docv_dt += sign * r.mean_entropic_change;
            voltage += sign * r.delta;
        }
        if self.ec.submodels.thermal {
            // PyBaMM's reaction heat is `a j eta` with the area-weighted mean overpotential
            // `delta - sum w_a U_i`: `I (U - V)` with the area-weighted mean surface OCPs.
            let heat = bernardi_heat(current, ocv, voltage, temp, docv_dt);
            out[self.len() - 1] = self.ec.thermal.rate(heat, temp);
        }
    }

    fn voltage(&self, y: &[f64], current: f64) -> f64 {
        self.reaction(Side::Positive, y, current).delta - self.reaction(Side::Negative, y, current).delta - current * self.ec.contact_resistance()
    }

    fn temperature_state(&self) -> Option<usize> {
        self.ec.submodels.thermal.then(|| self.len() - 1)
    }

    fn temperature(&self, y: &[f64]) -> f64 {
        self.temperature_state().map_or(self.ec.params.thermal.ambient_temperature, |k| y[k])
    }

    fn solid_lithium(&self, y: &[f64]) -> f64 {
        let p = &self.ec.params;
        [(Side::Negative, &p.negative), (Side::Positive, &p.positive)]
            .into_iter()
            .map(|(side, e)| self.sizes(side).average(self.block(side, y)) * e.active_fraction * e.thickness * self.ec.area())
            .sum()
    }

    fn open_circuit_voltage(&self, y: &[f64]) -> f64 {
        let average = |side| self.sizes(side).average(self.block(side, y));
        let temp = self.temperature(y);
        self.ec.ocp(Side::Positive, average(Side::Positive), temp) - self.ec.ocp(Side::Negative, average(Side::Negative), temp)
    }

    fn plating_margin(&self, y: &[f64], current: f64) -> Option<f64> {
        Some(self.reaction(Side::Negative, y, current).delta)
    }

    fn fields(&self, y: &[f64]) -> Vec<super::Field> {
        let field = |name, side| super::Field::concentration_radius(name, self.sizes(side).radii.clone(), self.surface_concentrations(side, y));
        vec![field("negative particle surface concentration", Side::Negative), field("positive particle surface concentration", Side::Positive)]
    }

    fn output_states(&self) -> Vec<usize> {
        let nn = self.sizes[0].states();
        let mut out: Vec<usize> = self.sizes[0].surface_states().collect();
        out.extend(self.sizes[1].surface_states().map(|k| nn + k));
        out.extend(self.ec.submodels.thermal.then(|| self.len() - 1));
        out
    }
}

impl PhysicsModel for Mpm {
    fn electrochem(&self) -> &Electrochem {
        &self.ec
    }

    /// Replaces the parameters and rebuilds the size classes (their radii follow
    /// `radius_relative_std`; their number is the mesh's).
    fn set_params(&mut self, params: ParameterSet) {
        self.ec.set_params(params);
        self.sizes = [SizeClasses::of(&self.ec, Side::Negative), SizeClasses::of(&self.ec, Side::Positive)];
        let (nn, np) = (self.sizes[0].states(), self.sizes[1].states());
        self.scale[..nn].fill(self.ec.params.negative.max_concentration);
        self.scale[nn..nn + np].fill(self.ec.params.positive.max_concentration);
    }
}
