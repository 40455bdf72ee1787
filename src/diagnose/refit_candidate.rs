//! Fitting one candidate on top of the previous model: where its fits start, and how it
//! stands against the user's model.

use super::{Candidate, CandidateOutcome, Comparison, DiagnoseOptions, NextModel, Round, candidates, keeps_set_values, refit, select};
use crate::data::Recording;
use crate::params::{ParameterSet, set_initial_soc};
use crate::problem::fitting::{FitParameter, INITIAL_SOC};
use crate::problem::delay::VOLTAGE_DELAY;
use crate::problem::lost_lithium::is_loss_soc;
use refit::{FitOutcome, Split};

/// Fits one candidate on top of the baseline; `warm` holds the baseline's fitted parameters
/// at their fitted values, `restarts` the points (values of `warm`) the baseline's fit
/// started from, or `None` to fit from the first start only (pairs: a budget, as a pair that
/// needs restarts, ending on a bound, is not plausible anyway); `resume`, an earlier fit of
/// the same parameters (a screened pair's) that this one continues from where it stopped.
pub(super) fn refit_candidate(
    aug: candidates::Augmentation,
    warm: &[FitParameter],
    restarts: Option<&[Vec<f64>]>,
    resume: Option<&FitOutcome>,
    options: &DiagnoseOptions,
    data: &Recording,
    split: &Split,
) -> (Option<FitOutcome>, Option<String>, Option<NextModel>) {
    let mut params: Vec<FitParameter> = warm.iter().filter(|p| !aug.replaces.contains(&p.path)).cloned().collect();
    // A candidate that frees the initial concentrations in place of the initial state of
    // charge starts them at the baseline's fitted initial state.
    let frees_window = aug.replaces.iter().any(|r| r == INITIAL_SOC);
    if frees_window {
        let p = at_soc(&aug.base, warm.iter().find(|p| p.path == INITIAL_SOC).map(|p| p.initial));
        params.extend(aug.extra.iter().cloned().map(|mut e| {
            e.initial = p.get(&e.path).unwrap_or(e.initial).clamp(e.lower, e.upper);
            e
        }));
    } else {
        params.extend(aug.extra.iter().cloned());
    }
    // A resumed fit starts every parameter, the freed window's too, where the earlier stopped.
    if let Some(earlier) = resume {
        for p in params.iter_mut() {
            if let Some(k) = earlier.names.iter().position(|n| *n == p.path) {
                p.initial = earlier.values[k].clamp(p.lower, p.upper);
            }
        }
    }
    // A start that breaks the model is pulled toward the previous model (the user's
    // parameters at their fitted values, the candidate's at no effect: the set's values),
    // which runs.
    let runs_at: Vec<f64> = params
        .iter()
        .map(|p| match warm.iter().find(|w| w.path == p.path) {
            Some(w) => w.initial,
            None if frees_window => p.initial,
            None => aug.base.get(&p.path).unwrap_or(p.initial).clamp(p.lower, p.upper),
        })
        .collect();
    // Starts: the candidate's own parameters at their initial values or a third of the way to
    // their lower bounds (in the search coordinates), so no fit starts only at one point; the
    // user's parameters at their fitted values or where the baseline's fit started (its fitted
    // values, e.g. an initial state of charge, may have absorbed the missing effect and hold
    // the candidate's fit in a false minimum); for a candidate with several parameters, each
    // of them moved alone (the others at no effect: one electrode's loss is not a compromise
    // between both). The first is tried alone; the others only when it fails, stops on its
    // cap, ends on a bound or holds a parameter (`refit::fit_and_score`).
    let toward_lower = |p: &FitParameter| match p.log {
        true => (p.initial.ln() + (p.lower.ln() - p.initial.ln()) / 3.0).exp(),
        false => p.initial + (p.lower - p.initial) / 3.0,
    };
    // The state at which material was lost refines the plain loss (its start): it is held
    // there in a first fit from every start, and is not moved alone.
    let staged = params.iter().position(|p| is_loss_soc(&p.path));
    let own: Vec<usize> = (0..params.len()).filter(|&k| !warm.iter().any(|w| w.path == params[k].path)).collect();
    let mut starts: Vec<Vec<f64>> = vec![params.iter().map(|p| p.initial).collect()];
    let moved: Vec<usize> = own.iter().copied().filter(|&k| Some(k) != staged).collect();
    if moved.len() >= 2 {
        starts.extend(moved.iter().map(|&k| {
            let mut s = runs_at.clone();
            s[k] = toward_lower(&params[k]);
            s
        }));
    }
    for user in std::iter::once(None).chain(restarts.unwrap_or_default().iter().map(Some)) {
        for lower in [false, true] {
            let s: Vec<f64> = params
                .iter()
                .enumerate()
                .map(|(k, p)| match warm.iter().position(|w| w.path == p.path) {
                    Some(i) => user.map_or(p.initial, |r| r[i].clamp(p.lower, p.upper)),
                    None if lower && Some(k) != staged => toward_lower(p),
                    None => p.initial,
                })
                .collect();
            if !starts.contains(&s) {
                starts.push(s);
            }
        }
    }
    // An ageing rate is screened first: its cost can rise between the set's value and the
    // optimum (it is known only to within decades). So is a voltage channel's delay, over its
    // range: under a load with a rhythm of its own (a drive's gear changes) its cost has a
    // valley at every echo, and from zero the fit slid to the bound (blind aq5, 3 s late,
    // fitted 10 s). Not for pairs (a budget).
    let delay: Vec<usize> = own.iter().copied().filter(|&k| params[k].path == VOLTAGE_DELAY).collect();
    let screen: Vec<usize> = match restarts {
        Some(_) if aug.screened => own.iter().copied().filter(|&k| params[k].log).chain(delay).collect(),
        Some(_) => delay,
        None => {
            starts.truncate(1);
            Vec::new()
        }
    };
    let starts = refit::Starts { points: starts, runs_at: Some(runs_at), screen, staged };
    match refit::fit_and_score(aug.spec.to_string(), aug.spec, aug.base.clone(), params.clone(), aug.structural_parameters, &starts, data, split, &options.fit) {
        Ok(f) => {
            let fitted = params
                .into_iter()
                .zip(&f.values)
                .map(|(mut p, v)| {
                    p.initial = v.clamp(p.lower, p.upper);
                    p
                })
                .collect();
            let next = NextModel { spec: aug.spec, base: aug.base, fitted };
            (Some(f), None, Some(next))
        }
        Err(e) => (None, Some(format!("fit failed: {e}")), None),
    }
}

/// `base` with its initial concentrations at state of charge `soc` (when there is one and it
/// lies in [0, 1]): where a candidate that frees the stoichiometry window starts, the
/// previous model's state (no effect).
pub(super) fn at_soc(base: &ParameterSet, soc: Option<f64>) -> ParameterSet {
    let mut p = base.clone();
    if let Some(soc) = soc {
        let _ = set_initial_soc(&mut p, soc);
    }
    p
}

/// One candidate refitted (when `aug` is its augmentation; `Err` says why it was not) and
/// judged against the round's user's model: the margins, plausible values, its name by them.
pub(super) fn judge(c: Candidate, aug: Result<candidates::Augmentation, String>, round: &Round) -> CandidateOutcome {
    let n_train = round.split.train_points();
    assess(c, aug, round, |f| {
        let comparison = select::compare(round.baseline, f, n_train);
        (comparison, round.options.margins.cleared_by(&comparison, round.noise))
    })
}

/// As [`judge`], with the comparison and whether it clears the margins given by `standard`
/// from the candidate's fit.
pub(super) fn assess(c: Candidate, aug: Result<candidates::Augmentation, String>, round: &Round, standard: impl Fn(&FitOutcome) -> (Comparison, bool)) -> CandidateOutcome {
    let mut out = CandidateOutcome {
        candidate: c,
        partner: None,
        name: c.name().into(),
        class: c.class(),
        signature: c.signature().into(),
        plausible_range: c.plausible_range().into(),
        change: aug.as_ref().map(|a| a.change.clone()).unwrap_or_default(),
        fit: None,
        note: None,
        comparison: Comparison::default(),
        clears_margins: false,
        implausible: None,
        named: false,
        next: None,
    };
    let aug = match aug {
        Err(why) => {
            out.note = Some(why);
            return out;
        }
        Ok(aug) => aug,
    };
    let (options, base, baseline) = (round.options, round.base, round.baseline);
    let (fit, note, next) = refit_candidate(aug, round.warm, Some(round.restarts), None, options, round.data, round.split);
    (out.note, out.next) = (note, next);
    let Some(f) = fit else { return out };
    (out.comparison, out.clears_margins) = standard(&f);
    // Plausibility of the candidate's own values, not the baseline's.
    let (names, values) = own_values(&f, baseline);
    // A candidate that makes another's structural change and keeps the set's values is that
    // other candidate: not named twice.
    let alias = c.structural_alias(options.spec.kind).filter(|_| keeps_set_values(&f, &names, base));
    out.implausible = c
        .implausible(&names, &values, base, &round.load)
        .or_else(|| c.unresolved(&names, &values, round.data))
        .or_else(|| super::at_rest::stands_in_for_the_ocv(&[c], &f, round))
        .or_else(|| alias.map(|a| format!("its values are the set's: it is {} alone", a.name())));
    out.named = out.clears_margins && out.implausible.is_none();
    out.name = c.named_by_values(&f.names, &f.values, base, &round.load);
    out.fit = Some(f);
    out
}

/// The candidate's own fitted parameters in `f` (names, values): those the user's model
/// `baseline` does not fit.
pub(super) fn own_values(f: &FitOutcome, baseline: &FitOutcome) -> (Vec<String>, Vec<f64>) {
    f.names.iter().zip(&f.values).filter(|(n, _)| !baseline.names.contains(n)).map(|(n, v)| (n.clone(), *v)).unzip()
}
