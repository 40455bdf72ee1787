//! The backward check after the rounds: an effect named early may only have stood in for
//! effects named later (a loss of active material mimics a lithium loss plus part of a
//! resistance). Each earlier effect is taken out of the final model, the rest refitted, and
//! the effect is reported as superseded when the final model does not beat the reduced one by
//! the naming margins (ΔBIC and the Laplace evidence). A pair named together is taken out
//! whole, and when the final model needs it, each of its two effects on its own: one may
//! have stood in for a later effect while the other is needed.

use serde::Serialize;

use super::{CandidateOutcome, Diagnosis, DiagnoseOptions, FitOutcome, refit, select};
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
    /// When one effect of a pair is superseded: the other's name, which the round keeps.
    pub kept: Option<String>,
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
        let spec = reverted(model.spec, &d.spec, &after.spec);
        let whole = take_out(model, spec, &added, &c.name, i, last, options);
        if whole.is_some() || c.partner.is_none() {
            out.extend(whole);
            continue;
        }
        // A pair the final model needs: is one of its effects not needed?
        let members = [(c.candidate, c.partner), (c.partner.expect("a pair"), Some(c.candidate))];
        let load = super::ageing::Load::of(&last.data);
        let mut parts = members.into_iter().filter_map(|(member, other)| {
            let aug = member.augment(&d.spec, model.base, &d.baseline.names, &load)?;
            if aug.spec.kind != d.spec.kind {
                return None;
            }
            let own: Vec<&String> = added.iter().copied().filter(|p| aug.extra.iter().any(|e| &e.path == *p)).collect();
            let spec = reverted(model.spec, &d.spec, &aug.spec);
            let mut s = take_out(model, spec, &own, &member.named_by_values(&f.names, &f.values, model.base, &load), i, last, options)?;
            s.kept = other.map(|o| own_name(c, o, model.base, &load));
            Some(s)
        });
        // At most one: the other then stays named.
        out.extend(parts.next());
    }
    out
}

/// `spec` with the submodels (and the recorded temperature's use) that `after` turned on over
/// `before` turned off again.
fn reverted(mut spec: ModelSpec, before: &ModelSpec, after: &ModelSpec) -> ModelSpec {
    if before.recorded_temperature != after.recorded_temperature {
        spec.recorded_temperature = before.recorded_temperature;
    }
    let (before, after) = (before.submodels, after.submodels);
    if before.contact_resistance != after.contact_resistance {
        spec.submodels.contact_resistance = before.contact_resistance;
    }
    if before.thermal != after.thermal {
        spec.submodels.thermal = before.thermal;
    }
    if before.rc != after.rc {
        spec.submodels.rc = before.rc;
    }
    if before.hysteresis != after.hysteresis {
        spec.submodels.hysteresis = before.hysteresis;
    }
    // The ageing candidates' submodels (SEI, plating, progressive LAM with its diffusion).
    if before.sei != after.sei {
        spec.submodels.sei = before.sei;
    }
    if before.plating != after.plating {
        spec.submodels.plating = before.plating;
    }
    if (before.lam, before.stress_induced_diffusion) != (after.lam, after.stress_induced_diffusion) {
        (spec.submodels.lam, spec.submodels.stress_induced_diffusion) = (before.lam, before.stress_induced_diffusion);
    }
    spec
}

/// The name of a pair's member `member` by the pair's fitted values.
fn own_name(c: &CandidateOutcome, member: super::Candidate, base: &ParameterSet, load: &super::ageing::Load) -> String {
    c.fit.as_ref().map_or(member.name().to_string(), |f| member.named_by_values(&f.names, &f.values, base, load))
}

/// The final model refitted with `spec` and without the fitted `paths` (at the set's values),
/// as a superseded effect `name` of round `round` (from 0) when the final model does not beat
/// it by the naming margins.
fn take_out(model: &FinalModel, spec: ModelSpec, paths: &[&String], name: &str, round: usize, last: &Diagnosis, options: &DiagnoseOptions) -> Option<Superseded> {
    let fitted: Vec<FitParameter> = model.fitted.iter().filter(|p| !paths.contains(&&p.path)).cloned().collect();
    let start: Vec<f64> = fitted.iter().map(|p| p.initial).collect();
    let structural = model.fit.parameters - model.fit.names.len();
    let label = format!("{} without {name}", model.spec);
    let reduced = refit::fit_and_score(label, spec, model.base.clone(), fitted, structural, &refit::Starts::at(vec![start]), &last.data, &last.split, &options.fit).ok()?;
    let cmp = select::compare(&reduced, model.fit, last.train_points);
    (cmp.delta_bic <= options.margins.min_delta_bic || cmp.ln_bayes_factor <= 0.0).then(|| Superseded {
        round: round + 1,
        name: name.to_string(),
        delta_bic: cmp.delta_bic,
        ln_bayes_factor: cmp.ln_bayes_factor,
        rmse_without: reduced.rmse_all,
        rmse_with: model.fit.rmse_all,
        kept: None,
    })
}
