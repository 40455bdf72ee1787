//! The optimisation problem: objective, bounds, linear constraints and transforms.

use serde::{Deserialize, Serialize};

use super::Objective;
use super::projection::LinearConstraints;
use crate::error::{Error, Result};

/// Box bounds `lower <= x <= upper` in model space. Infinite values mean unbounded.
#[derive(Clone, Debug, PartialEq)]
pub struct Bounds {
    lower: Vec<f64>,
    upper: Vec<f64>,
}

impl Bounds {
    /// Checks equal lengths, no `NaN`, `lower <= upper`, `lower < +inf`, `upper > -inf`.
    pub fn new(lower: Vec<f64>, upper: Vec<f64>) -> Result<Self> {
        if lower.len() != upper.len() {
            return Err(Error::InvalidSetting {
                field: "bounds".into(),
                reason: format!("lower has {} entries, upper has {}", lower.len(), upper.len()),
            });
        }
        for (i, (&l, &u)) in lower.iter().zip(&upper).enumerate() {
            if l.is_nan() || u.is_nan() || l > u || l == f64::INFINITY || u == f64::NEG_INFINITY {
                return Err(Error::InvalidSetting {
                    field: format!("bounds[{i}]"),
                    reason: format!("need lower <= upper with lower < inf and upper > -inf, got [{l}, {u}]"),
                });
            }
        }
        Ok(Bounds { lower, upper })
    }

    /// No bounds on `dim` variables.
    pub fn unbounded(dim: usize) -> Self {
        Bounds { lower: vec![f64::NEG_INFINITY; dim], upper: vec![f64::INFINITY; dim] }
    }

    pub fn dim(&self) -> usize {
        self.lower.len()
    }
    pub fn lower(&self) -> &[f64] {
        &self.lower
    }
    pub fn upper(&self) -> &[f64] {
        &self.upper
    }
    /// `upper - lower` of variable `i` (may be infinite).
    pub fn range(&self, i: usize) -> f64 {
        self.upper[i] - self.lower[i]
    }
    pub fn contains(&self, x: &[f64]) -> bool {
        x.len() == self.dim() && x.iter().enumerate().all(|(i, &v)| v >= self.lower[i] && v <= self.upper[i])
    }
    /// Nearest point of the box.
    pub fn clamp(&self, x: &[f64]) -> Vec<f64> {
        x.iter().enumerate().map(|(i, &v)| v.max(self.lower[i]).min(self.upper[i])).collect()
    }
}

/// How a variable is searched: as it is, by its natural logarithm (for positive quantities
/// spanning decades, e.g. diffusivities and rate constants; needs a positive lower bound), or
/// affinely rescaled `z = (x - offset) / scale` (e.g. thicknesses in micrometres).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Transform {
    #[default]
    Identity,
    Log,
    Affine { scale: f64, offset: f64 },
}

impl Transform {
    /// Model value -> search value.
    pub fn to_search(self, x: f64) -> f64 {
        match self {
            Transform::Identity => x,
            Transform::Log => x.ln(),
            Transform::Affine { scale, offset } => (x - offset) / scale,
        }
    }
    /// Search value -> model value.
    pub fn to_model(self, z: f64) -> f64 {
        match self {
            Transform::Identity => z,
            Transform::Log => z.exp(),
            Transform::Affine { scale, offset } => offset + scale * z,
        }
    }
    /// `dx/dz` at model value `x`.
    pub fn derivative(self, x: f64) -> f64 {
        match self {
            Transform::Identity => 1.0,
            Transform::Log => x,
            Transform::Affine { scale, .. } => scale,
        }
    }
}

/// Objective + feasible set + transforms. Built with [`Problem::new`] and the validating
/// `with_*` methods.
pub struct Problem<'a> {
    objective: &'a dyn Objective,
    bounds: Bounds,
    constraints: Option<LinearConstraints>,
    transforms: Vec<Transform>,
    search_bounds: Bounds,
    /// Model-space length scale of each variable used by the projection metric: the bound
    /// range when finite and positive, else 1.
    metric: Vec<f64>,
}

impl<'a> Problem<'a> {
    /// Checks that the bounds have the objective's dimension. Transforms default to identity.
    pub fn new(objective: &'a dyn Objective, bounds: Bounds) -> Result<Self> {
        if objective.dim() != bounds.dim() {
            return Err(Error::InvalidSetting {
                field: "bounds".into(),
                reason: format!("objective has {} variables, bounds have {}", objective.dim(), bounds.dim()),
            });
        }
        let n = bounds.dim();
        let metric = (0..n)
            .map(|i| {
                let r = bounds.range(i);
                if r.is_finite() && r > 0.0 { r } else { 1.0 }
            })
            .collect();
        Ok(Problem {
            objective,
            search_bounds: bounds.clone(),
            bounds,
            constraints: None,
            transforms: vec![Transform::Identity; n],
            metric,
        })
    }

    /// Adds linear constraints (model space). Checks dimensions and feasibility together with
    /// the bounds, so an empty feasible set is reported here, before any search.
    pub fn with_constraints(mut self, constraints: LinearConstraints) -> Result<Self> {
        constraints.check_feasible(&self.bounds)?;
        self.constraints = if constraints.is_empty() { None } else { Some(constraints) };
        Ok(self)
    }

    /// Sets one transform per variable; `Log` needs a positive lower bound.
    pub fn with_transforms(mut self, transforms: Vec<Transform>) -> Result<Self> {
        if transforms.len() != self.dim() {
            return Err(Error::InvalidSetting {
                field: "transforms".into(),
                reason: format!("{} transforms for {} variables", transforms.len(), self.dim()),
            });
        }
        let mut lower = Vec::with_capacity(self.dim());
        let mut upper = Vec::with_capacity(self.dim());
        for (i, t) in transforms.iter().enumerate() {
            let (l, u) = (self.bounds.lower[i], self.bounds.upper[i]);
            if let Transform::Affine { scale, offset } = *t {
                if !(scale.is_finite() && scale > 0.0 && offset.is_finite()) {
                    return Err(Error::InvalidSetting {
                        field: format!("transforms[{i}]"),
                        reason: format!("affine transform needs a finite positive scale, got {scale} (offset {offset})"),
                    });
                }
            }
            if *t == Transform::Log && l <= 0.0 {
                return Err(Error::InvalidSetting {
                    field: format!("transforms[{i}]"),
                    reason: format!("log transform needs a positive lower bound, got {l}"),
                });
            }
            lower.push(t.to_search(l));
            upper.push(t.to_search(u));
        }
        self.search_bounds = Bounds::new(lower, upper)?;
        self.transforms = transforms;
        Ok(self)
    }

    pub fn dim(&self) -> usize {
        self.bounds.dim()
    }
    pub fn objective(&self) -> &dyn Objective {
        self.objective
    }
    pub fn bounds(&self) -> &Bounds {
        &self.bounds
    }
    pub fn constraints(&self) -> Option<&LinearConstraints> {
        self.constraints.as_ref()
    }
    pub fn transforms(&self) -> &[Transform] {
        &self.transforms
    }
    /// Bounds in the transformed (search) space.
    pub fn search_bounds(&self) -> &Bounds {
        &self.search_bounds
    }

    /// Nearest feasible point to `x` (model space). Bounds alone: exact clamping. With linear
    /// constraints: the QP projection in coordinates normalised by the bound ranges (plain
    /// Euclidean when all ranges are equal), skipped when `x` is already feasible.
    pub fn project(&self, x: &[f64]) -> Result<Vec<f64>> {
        match &self.constraints {
            None => Ok(self.bounds.clamp(x)),
            Some(c) => {
                if self.bounds.contains(x) && c.is_satisfied(x, 1e-10) {
                    Ok(x.to_vec())
                } else {
                    c.project_scaled(x, &self.bounds, &self.metric)
                }
            }
        }
    }

    /// Whether `x` is within the bounds and satisfies the constraints to relative tolerance
    /// `tol`.
    pub fn is_feasible(&self, x: &[f64], tol: f64) -> bool {
        self.bounds.contains(x) && self.constraints.as_ref().is_none_or(|c| c.is_satisfied(x, tol))
    }
}
