//! The checks of a design study: bounds, paths, settings and limits against the base
//! parameter set, with the field that is wrong named in the error.

use super::{Study, SweepDesign};
use crate::error::Error;
use crate::problem::design::Metric;

impl Study {
    /// Checks bounds, paths and settings against the base parameter set.
    pub fn validate(&self) -> Result<(), Error> {
        self.model.submodels.check_for(self.model.kind)?;
        if !self.model.submodels.thermal && self.metrics().any(|m| m == Metric::TemperatureRise) {
            return Err(Error::InvalidSetting {
                field: "model.submodels".into(),
                reason: "temperature_rise needs the lumped thermal submodel: submodels = { thermal = true }".into(),
            });
        }
        if self.metrics().any(|m| m.needs_life()) {
            if self.operating.life.is_none() {
                return Err(Error::InvalidSetting {
                    field: "operating.life".into(),
                    reason: "capacity_retention needs the cycles it is measured over: life = { cycles = 500, cycle = [...] }".into(),
                });
            }
            if self.model.submodels.sei == crate::models::submodels::SeiModel::None {
                return Err(Error::InvalidSetting {
                    field: "model.submodels".into(),
                    reason: "capacity_retention needs an ageing submodel, or every design keeps all its capacity: submodels = { sei = \"reaction limited\" }".into(),
                });
            }
        }
        let base = self.base_parameters()?;
        if let Some(life) = &self.operating.life {
            life.validate(base.cell.nominal_capacity)?;
        }
        let fixed = self.cell.format_outputs();
        let mut set_paths: Vec<(String, &str)> = self.variables.iter().enumerate().map(|(k, v)| (format!("variables[{k}].path"), v.path.as_str())).collect();
        set_paths.extend(self.ties.iter().enumerate().map(|(k, t)| (format!("ties[{k}].target"), t.target.as_str())));
        set_paths.extend(self.cell.overrides.iter().map(|o| (format!("--set {}", o.path), o.path.as_str())));
        if let Some((field, path)) = set_paths.iter().find(|(_, p)| fixed.contains(p)) {
            return Err(Error::InvalidSetting {
                field: field.clone(),
                reason: format!("`{path}` follows from the stack in cell.format = {}; change the format's dimensions instead", serde_json::to_string(&self.cell.format).unwrap_or_default()),
            });
        }
        crate::models::submodels::refuse_unread(&self.model.submodels, set_paths.iter().map(|(f, p)| (f.clone(), *p)))?;
        if self.variables.is_empty() {
            return Err(Error::InvalidSetting { field: "variables".into(), reason: "at least one is needed".into() });
        }
        for (k, limit) in self.limits.iter().enumerate() {
            limit.validate(k)?;
        }
        for (k, v) in self.variables.iter().enumerate() {
            base.get(&v.path).map_err(|_| Error::InvalidSetting {
                field: format!("variables[{k}].path"),
                reason: format!("`{}` is not a scalar parameter", v.path),
            })?;
            for (side, b) in [("lower", v.lower), ("upper", v.upper)] {
                if !b.is_finite() {
                    return Err(Error::invalid(format!("variables[{k}].{side}"), b, "must be a finite number"));
                }
            }
            if !(v.lower < v.upper) {
                return Err(Error::invalid(format!("variables[{k}].upper"), v.upper, format!("must exceed lower = {}", v.lower)));
            }
            if v.log && (v.scale.is_some() || v.offset.is_some()) {
                return Err(Error::InvalidSetting {
                    field: format!("variables[{k}]"),
                    reason: "`log` and an affine `scale`/`offset` exclude each other".into(),
                });
            }
            if let Some(scale) = v.scale {
                if !(scale > 0.0 && scale.is_finite()) {
                    return Err(Error::invalid(format!("variables[{k}].scale"), scale, "must be positive"));
                }
            }
            if v.log && v.lower <= 0.0 {
                return Err(Error::invalid(format!("variables[{k}].lower"), v.lower, "must be positive for a log variable"));
            }
        }
        match (self.operating.c_rate, self.operating.power) {
            (Some(c), None) if !(c > 0.0 && c.is_finite()) => {
                return Err(Error::invalid("operating.c_rate", c, "must be positive"));
            }
            (Some(_), Some(_)) | (None, None) => {
                return Err(Error::InvalidSetting {
                    field: "operating".into(),
                    reason: "give exactly one of `c_rate` and `power`".into(),
                });
            }
            _ => {}
        }
        if let Some(u) = self.operating.min_utilisation {
            crate::params::check::check("operating.min_utilisation", u, u > 0.0 && u < 1.0, "must lie strictly between 0 and 1")?;
        }
        if self.objective.maximise.is_empty() {
            return Err(Error::InvalidSetting { field: "objective.maximise".into(), reason: "is empty".into() });
        }
        if let Some(s) = &self.sweep {
            if s.design == SweepDesign::LatinHypercube {
                if !s.samples.is_some_and(|n| n >= 2) {
                    return Err(Error::InvalidSetting {
                        field: "sweep.samples".into(),
                        reason: format!("a latin_hypercube sweep needs samples >= 2, got {:?}", s.samples),
                    });
                }
            } else if s.points.len() != self.variables.len() || s.points.iter().any(|&n| n < 2) {
                return Err(Error::InvalidSetting {
                    field: "sweep.points".into(),
                    reason: format!("needs one count >= 2 per variable ({} variables), got {:?}", self.variables.len(), s.points),
                });
            }
            let (field, given, size) = match s.design {
                SweepDesign::Grid => ("sweep.points", format!("{:?}", s.points), s.points.iter().map(|&k| k as f64).product::<f64>()),
                SweepDesign::LatinHypercube => ("sweep.samples", s.samples.unwrap_or(0).to_string(), s.samples.unwrap_or(0) as f64),
            };
            super::check_design_count(field, &given, size)?;
        }
        for (k, c) in self.constraints.iter().enumerate() {
            for path in c.terms.keys() {
                if !self.variables.iter().any(|v| &v.path == path) {
                    return Err(Error::InvalidSetting {
                        field: format!("constraints[{k}].terms"),
                        reason: format!("`{path}` is not a decision variable"),
                    });
                }
            }
            if c.upper.is_none() && c.lower.is_none() && c.equals.is_none() {
                return Err(Error::InvalidSetting {
                    field: format!("constraints[{k}]"),
                    reason: "needs `upper`, `lower` or `equals`".into(),
                });
            }
        }
        // The baseline itself must satisfy the ties and physical ranges, and so must each
        // bound (the other variables at the baseline).
        let (problem, baseline) = (self.problem()?, self.baseline()?);
        problem.parameters(&baseline)?;
        for (k, v) in self.variables.iter().enumerate() {
            for (side, b) in [("lower", v.lower), ("upper", v.upper)] {
                let mut x = baseline.clone();
                x[k] = b;
                if let Err(e) = problem.parameters(&x) {
                    return Err(Error::InvalidSetting {
                        field: format!("variables[{k}].{side}"),
                        reason: format!("{} = {} is outside the physical range: {e}", v.path, crate::error::number(b)),
                    });
                }
            }
        }
        Ok(())
    }
}
