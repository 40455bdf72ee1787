//! The backward check after the rounds: an effect named early may only have stood in for
//! effects named later (a loss of active material mimics a lithium loss plus part of a
//! resistance). Each earlier effect is taken out of the final model, the rest refitted, and
//! the effect is reported as superseded when the final model does not beat the reduced one by
//! the naming margins (ΔBIC and the Laplace evidence).

use serde::Serialize;

use super::{Diagnosis, DiagnoseOptions, FitOutcome, describe, refit, select};
use crate::params::ParameterSet;
use crate::problem::fitting::{FitParameter, ModelSpec};

/// An effect named in an earlier round that the later ones make redundant.
#[derive(Clone, Debug, Serialize)]
pub struct Superseded {
    /// Round (from 1) that named it, and its name.
    pub round: usize,
    pub name: String,
    /// How much better the final model is than the final model without it.
    pub delta_bic: f64,
    pub ln_bayes_factor: f64,
    /// RMSE (V) of the final model without it, and with it.
    pub rmse_without: f64,
    pub rmse_with: f64,
}

/// The final model of the rounds: specification, base parameters, fitted parameters, fit.
pub struct FinalModel<'a> {
    pub spec: ModelSpec,
    pub base: &'a ParameterSet,
    pub fitted: &'a [FitParameter],
    pub fit: &'a FitOutcome,
}

/// The effects of `rounds` (all but the last named) that the final model does not need.
pub fn superseded(rounds: &[Diagnosis], model: &FinalModel, options: &DiagnoseOptions) -> Vec<Superseded> {
    let Some(last) = rounds.last() else { return Vec::new() };
    let named: Vec<usize> = (0..rounds.len()).filter(|&i| rounds[i].found).collect();
    let n = last.train_points;
    let mut out = Vec::new();
    // Every named effect but the last one named (each has a later round).
    for &i in named.iter().take(named.len().saturating_sub(1)) {
        let (d, after) = (&rounds[i], &rounds[i + 1]);
        let Some(c) = d.best() else { continue };
        let Some(f) = c.fit.as_ref() else { continue };
        let added: Vec<&String> = f.names.iter().filter(|p| !d.baseline.names.contains(p)).collect();
        let replaced = d.baseline.names.iter().any(|p| !f.names.contains(p));
        // A changed model kind or a replaced parameter cannot simply be taken out again.
        if replaced || d.spec.kind != after.spec.kind {
            continue;
        }
        let mut spec = model.spec;
        let (b, a) = (d.spec.submodels, after.spec.submodels);
        if b.contact_resistance != a.contact_resistance {
            spec.submodels.contact_resistance = b.contact_resistance;
        }
        if b.thermal != a.thermal {
            spec.submodels.thermal = b.thermal;
        }
        if b.rc != a.rc {
            spec.submodels.rc = b.rc;
        }
        if b.hysteresis != a.hysteresis {
            spec.submodels.hysteresis = b.hysteresis;
        }
        let fitted: Vec<FitParameter> = model.fitted.iter().filter(|p| !added.contains(&&p.path)).cloned().collect();
        let start: Vec<f64> = fitted.iter().map(|p| p.initial).collect();
        let structural = model.fit.parameters - model.fit.names.len();
        let label = format!("{} without {}", describe(&model.spec), c.name);
        let Ok(reduced) = refit::fit_and_score(label, spec, model.base.clone(), fitted, structural, &refit::Starts::at(vec![start]), &last.data, &last.split, &options.fit) else {
            continue;
        };
        let cmp = select::compare(&reduced, model.fit, n);
        if cmp.delta_bic <= options.margins.min_delta_bic || cmp.ln_bayes_factor <= 0.0 {
            out.push(Superseded {
                round: i + 1,
                name: c.name.clone(),
                delta_bic: cmp.delta_bic,
                ln_bayes_factor: cmp.ln_bayes_factor,
                rmse_without: reduced.rmse_all,
                rmse_with: model.fit.rmse_all,
            });
        }
    }
    out
}
