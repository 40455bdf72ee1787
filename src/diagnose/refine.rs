//! Refining a named effect: the property a candidate leaves fixed (its secondary parameters,
//! [`super::Candidate::refinements`]) refitted beside its own, after the verdict.
//!
//! A candidate is fitted with the parameters that identify its effect (the electrolyte's
//! diffusivity and conductivity). When the named fit still leaves structure, the same effect
//! may be better described with one more of its properties free (the transference number,
//! the third of the Newman triplet). That refines a name; it adds none: the verdict is already
//! given, so only the tests of a nested model apply (ΔBIC with effective points and the
//! Laplace evidence against the named fit, and a held-out RMSE that does not rise), not the
//! margins a new name must clear. Refining inside the candidate, rather than offering a
//! three-parameter candidate to every recording, leaves the ties between candidates as they
//! were.

use super::locate::ResidualAnalysis;
use super::refit_candidate::{own_values, refit_candidate};
use super::{CandidateOutcome, Round, select};
use crate::problem::fitting::FitParameter;

/// Refits `named` (the first-ranked outcome) with its candidate's secondary parameters free,
/// when it is a single named effect that has them and its residual `after` is structured, and
/// keeps the refined fit when the nested tests support it. Returns `None` when no refinement
/// was tried, else whether it was kept and what was found, in words.
pub(super) fn refine(named: &mut CandidateOutcome, after: &ResidualAnalysis, round: &Round) -> Option<(bool, String)> {
    let c = named.candidate;
    let secondary = c.refinements();
    let Some(fit) = named.fit.as_ref().filter(|_| named.named && named.partner.is_none() && !secondary.is_empty() && after.structured) else {
        return None;
    };
    let mut aug = c.augment(&round.options.spec, round.base, round.fitted_paths, &round.load)?;
    if aug.extra.iter().any(|p| secondary.iter().any(|s| p.path == s.0)) {
        return None;
    }
    aug.extra.extend(secondary.iter().map(|&(path, lower, upper)| {
        let v = aug.base.get(path).unwrap_or(0.5 * (lower + upper)).clamp(lower, upper);
        FitParameter::linear(path, v, lower, upper)
    }));
    let change = aug.change.clone();
    // One start: where the named fit ended, the secondary parameters at the set's values.
    let paths: Vec<&str> = secondary.iter().map(|s| s.0).collect();
    let (refined, failed, next) = refit_candidate(aug, round.warm, None, Some(fit), round.options, round.data, round.split);
    let (Some(refined), Some(next)) = (refined, next) else {
        return Some((false, format!("refined with {} free: {}; not kept", paths.join(", "), failed.unwrap_or_default())));
    };
    let n_train = round.split.train_points();
    let nested = select::compare(fit, &refined, n_train);
    let on_bound = refined.names.iter().zip(&refined.on_bound).any(|(n, b)| *b && secondary.iter().any(|s| s.0 == n));
    // The candidate's own values must stay plausible with the secondary ones free.
    let (names, values) = own_values(&refined, round.baseline);
    let implausible = c.implausible(&names, &values, round.base, &round.load);
    let kept = nested.delta_bic > round.options.margins.min_delta_bic && nested.ln_bayes_factor > 0.0 && nested.holdout_gain > 0.0 && !on_bound && implausible.is_none() && refined.converged;
    let record = format!(
        "refined with {} free: ΔBIC {:.1} against the named fit, held-out RMSE {:.2} -> {:.2} mV{}",
        paths.join(", "),
        nested.delta_bic,
        fit.rmse_holdout * 1e3,
        refined.rmse_holdout * 1e3,
        match (kept, on_bound, &implausible) {
            (true, ..) => "; kept".to_string(),
            (false, true, _) => "; not kept: a refined value lies on its search bound".to_string(),
            (false, false, Some(why)) => format!("; not kept: {why}"),
            (false, false, None) if !refined.converged => "; not kept: its search stopped before converging".to_string(),
            (false, false, None) => "; not kept: the nested tests do not support it".to_string(),
        }
    );
    if kept {
        named.change = format!("{change}; {record}");
        named.comparison = select::compare(round.baseline, &refined, n_train);
        named.fit = Some(refined);
        named.next = Some(next);
    }
    Some((kept, record))
}
