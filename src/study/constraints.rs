//! A study's linear constraints on its decision variables: the optimiser's form, the check
//! that skips an infeasible sweep point, and the projection that repairs an infeasible
//! Pareto candidate.

use super::Study;
use crate::error::Error;
use crate::optim::{Bounds, LinearConstraints};

/// Relative tolerance of the feasibility check (see [`LinearConstraints::is_satisfied`]).
pub const FEASIBILITY_TOLERANCE: f64 = 1e-9;

/// Linear constraints of the study in the optimiser's form.
pub fn linear_constraints(study: &Study) -> LinearConstraints {
    let mut out = LinearConstraints::new();
    for c in &study.constraints {
        let a: Vec<f64> = study.variables.iter().map(|v| c.terms.get(&v.path).copied().unwrap_or(0.0)).collect();
        if let Some(u) = c.upper {
            out = out.inequality(a.clone(), u);
        }
        if let Some(l) = c.lower {
            out = out.inequality(a.iter().map(|v| -v).collect(), -l);
        }
        if let Some(e) = c.equals {
            out = out.equality(a.clone(), e);
        }
    }
    out
}

/// Feasibility of points against the study's constraints, and their repair.
pub struct Feasibility {
    constraints: LinearConstraints,
    bounds: Bounds,
}

impl Feasibility {
    /// The study's constraints within its bounds; an empty feasible set is an error.
    pub fn of(study: &Study) -> Result<Self, Error> {
        let bounds = Bounds::new(study.variables.iter().map(|v| v.lower).collect(), study.variables.iter().map(|v| v.upper).collect())?;
        let constraints = linear_constraints(study);
        if !constraints.is_empty() {
            constraints.check_feasible(&bounds)?;
        }
        Ok(Self { constraints, bounds })
    }

    /// Whether the study has any constraint.
    pub fn is_constrained(&self) -> bool {
        !self.constraints.is_empty()
    }

    /// Whether `x` satisfies every constraint.
    pub fn is_feasible(&self, x: &[f64]) -> bool {
        self.constraints.is_satisfied(x, FEASIBILITY_TOLERANCE)
    }

    /// `x` itself when feasible, else its projection onto the feasible set, each variable
    /// measured in units of its bound range (so micrometres and fractions weigh alike).
    pub fn repair(&self, x: &[f64]) -> Result<Vec<f64>, Error> {
        if self.is_feasible(x) {
            return Ok(x.to_vec());
        }
        let scale: Vec<f64> = (0..self.bounds.dim()).map(|i| self.bounds.range(i)).collect();
        Ok(self.constraints.project_scaled(x, &self.bounds, &scale)?)
    }
}
