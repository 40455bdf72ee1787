//! Model-discrepancy diagnosis: locate a mismatch, name the missing physics, refit.
//!
//! 1. Locate: the user's model (optionally with some parameters fitted) is run through the
//!    recorded current; the residual `r = V_data - V_model` is analysed ([`locate`]): where
//!    in time, after which current steps, in which band of state of charge, at rest or under
//!    load, how it scales with current, and whether noise can explain it (Ljung-Box, runs
//!    test, a noise level from first differences).
//! 2. Name: each effect of the [`candidates`] library has a residual signature; its
//!    regressors are fitted to the residual to screen the library.
//! 3. Model: the best-screened candidates are added to the model (a model-kind change, a
//!    submodel, or refitted parameters) and fitted on a training part of the recording; they
//!    are ranked by ΔBIC on the training points and judged by the RMSE on held-out blocks of
//!    the recording (the model always runs through the whole recording).
//! 4. Report: plain words, numbers and plots ([`report`], `crate::report::diagnosis_plot`).
//!
//! "Missing physics found" needs the first-ranked candidate to beat the user's model by
//! `min_delta_bic` on the training points, and on the held-out points to cut the RMSE by at
//! least `min_holdout_gain` with a Gaussian log-likelihood ratio
//! `n_h ln(MSE_user / MSE_candidate)` above `min_holdout_llr` (the second guards a small
//! relative cut on a long recording, the first a large ratio near the noise floor).
//! [`diagnose_rounds`] repeats the diagnosis on the augmented model to find a second effect.

pub mod candidates;
pub mod features;
pub mod locate;
pub mod refit;
pub mod report;
pub mod stats;
pub mod synthetic;

use rayon::prelude::*;
use serde::Serialize;

pub use candidates::Candidate;
use features::Features;
pub use locate::ResidualAnalysis;
pub use refit::{FitOutcome, FitSettings, Split};

use crate::data::Recording;
use crate::error::Error;
use crate::params::ParameterSet;
use crate::problem::fitting::{FitParameter, ModelSpec};

/// A fit parameter for `path` around its value in `base`: log-scaled between a tenth and ten
/// times a positive value, linear within ±1 around a zero or negative one.
pub fn default_fit_parameter(path: &str, base: &ParameterSet) -> Result<FitParameter, Error> {
    let v = base.get(path)?;
    Ok(if v > 0.0 { FitParameter::log(path, v, v / 10.0, v * 10.0) } else { FitParameter::linear(path, v, v - 1.0, v + 1.0) })
}

/// Settings of a diagnosis.
#[derive(Clone, Debug)]
pub struct DiagnoseOptions {
    /// The user's model.
    pub spec: ModelSpec,
    /// Parameters fitted in the user's model and in every candidate (may be empty: the
    /// user's model is then taken as it is).
    pub fitted: Vec<FitParameter>,
    /// The recording is cut into this many equal time blocks ...
    pub blocks: usize,
    /// ... of which every `holdout_every`-th is held out for validation.
    pub holdout_every: usize,
    /// Candidates refitted, best screening scores first.
    pub max_refits: usize,
    /// Least BIC improvement over the user's model for "missing physics found".
    pub min_delta_bic: f64,
    /// Least relative cut of the hold-out RMSE for "missing physics found" (-).
    pub min_holdout_gain: f64,
    /// Least hold-out log-likelihood ratio `n_h ln(MSE_user / MSE_candidate)` (-).
    pub min_holdout_llr: f64,
    pub fit: FitSettings,
    /// The user's model already fitted on this recording with these settings (e.g. by the
    /// previous round): used as it is instead of fitting it again.
    pub fitted_baseline: Option<FitOutcome>,
}

impl DiagnoseOptions {
    /// Defaults: 8 blocks with every 4th held out (25 %), 5 refits, ΔBIC > 10, a hold-out
    /// RMSE cut by at least 10 % with a hold-out log-likelihood ratio above 10, L-BFGS-B with
    /// sensitivity gradients.
    pub fn new(spec: ModelSpec) -> Self {
        Self {
            spec,
            fitted: Vec::new(),
            blocks: 8,
            holdout_every: 4,
            max_refits: 5,
            min_delta_bic: 10.0,
            min_holdout_gain: 0.1,
            min_holdout_llr: 10.0,
            fit: FitSettings { optimiser: "lbfgsb".into(), max_evaluations: 300, seed: 0, start_at_rest: false },
            fitted_baseline: None,
        }
    }

    fn validate(&self) -> Result<(), Error> {
        if self.blocks < 2 {
            return Err(Error::InvalidSetting { field: "blocks".into(), reason: format!("must be at least 2, got {}", self.blocks) });
        }
        if !(self.min_holdout_gain >= 0.0 && self.min_holdout_gain < 1.0) {
            return Err(Error::invalid("min_holdout_gain", self.min_holdout_gain, "must lie in [0, 1)"));
        }
        if !self.min_delta_bic.is_finite() {
            return Err(Error::invalid("min_delta_bic", self.min_delta_bic, "must be finite"));
        }
        Ok(())
    }
}

/// One candidate: its screening score and, when refitted, its fit and verdict.
#[derive(Clone, Debug, Serialize)]
pub struct CandidateOutcome {
    pub candidate: Candidate,
    pub name: String,
    pub signature: String,
    /// `R²` of the user's residual on the candidate's signature regressors (-).
    pub screen_score: f64,
    /// How the model was changed.
    pub change: String,
    /// The fit, when the candidate was refitted and the fit ran.
    pub fit: Option<FitOutcome>,
    /// Why it was not refitted or why the fit failed.
    pub note: Option<String>,
    /// `BIC_user - BIC_candidate` and the same for AIC (positive: the candidate is better).
    pub delta_bic: f64,
    pub delta_aic: f64,
    /// `1 - RMSE_holdout(candidate) / RMSE_holdout(user)` (-).
    pub holdout_gain: f64,
    /// `n_h ln(MSE_holdout(user) / MSE_holdout(candidate))` (-).
    pub holdout_llr: f64,
    /// Whether it clears the margins.
    pub clears_margins: bool,
    /// The augmented model with its fitted values as starting values, for a next round.
    #[serde(skip)]
    pub next: Option<NextModel>,
}

/// A model to diagnose further: the accepted candidate added to the previous model.
#[derive(Clone, Debug)]
pub struct NextModel {
    pub spec: ModelSpec,
    pub base: ParameterSet,
    pub fitted: Vec<FitParameter>,
}

/// The model in words, e.g. "SPM + contact resistance + RC".
pub fn describe(spec: &ModelSpec) -> String {
    let s = spec.submodels;
    let mut out = spec.kind.to_string();
    for (on, name) in [(s.contact_resistance, "contact resistance"), (s.thermal, "thermal"), (s.rc, "RC"), (s.hysteresis, "hysteresis")] {
        if on {
            out.push_str(" + ");
            out.push_str(name);
        }
    }
    out
}

/// The outcome of a diagnosis.
#[derive(Clone, Debug, Serialize)]
pub struct Diagnosis {
    pub model: String,
    pub points: usize,
    pub train_points: usize,
    pub holdout_points: usize,
    /// Time blocks of the recording, and every how many one is held out.
    pub blocks: usize,
    pub holdout_every: usize,
    pub min_delta_bic: f64,
    pub min_holdout_gain: f64,
    pub min_holdout_llr: f64,
    /// The user's model, fitted as asked.
    pub baseline: FitOutcome,
    /// Its residual.
    pub residual: ResidualAnalysis,
    /// Refitted candidates ranked (margins cleared first, then by ΔBIC), then the others by
    /// screening score.
    pub candidates: Vec<CandidateOutcome>,
    /// Whether the first-ranked candidate is named as the missing physics.
    pub found: bool,
    /// The residual with the first-ranked refitted candidate.
    pub residual_after: Option<ResidualAnalysis>,
    /// The verdict in plain words.
    pub summary: String,
    /// Wall time (s).
    pub seconds: f64,
    #[serde(skip)]
    pub data: Recording,
    #[serde(skip)]
    pub split: Split,
}

impl Diagnosis {
    /// The first-ranked refitted candidate.
    pub fn best(&self) -> Option<&CandidateOutcome> {
        self.candidates.first().filter(|c| c.fit.is_some())
    }
}

/// Diagnoses the mismatch between the model of `options` (on parameters `base`) and `data`.
pub fn diagnose(data: &Recording, base: &ParameterSet, options: &DiagnoseOptions) -> Result<Diagnosis, Error> {
    let start = std::time::Instant::now();
    options.validate()?;
    let features = Features::of(data);
    let split = Split::blocks(&data.time, &features.valid, options.blocks, options.holdout_every);
    if split.train_points() <= options.fitted.len() + 10 || split.holdout_points() == 0 {
        return Err(Error::InvalidSetting {
            field: "data".into(),
            reason: format!("too few points: {} training, {} held out", split.train_points(), split.holdout_points()),
        });
    }
    let spec = options.spec;
    let baseline = match &options.fitted_baseline {
        Some(b) if b.voltage.len() == data.time.len() && b.names.len() == options.fitted.len() => b.clone(),
        _ => refit::fit_and_score(
            format!("{} as given", describe(&spec)),
            spec,
            base.clone(),
            options.fitted.clone(),
            data,
            &split,
            &options.fit,
        )?,
    };
    // The baseline's fitted values start every candidate fit.
    let mut warm = options.fitted.clone();
    for (p, v) in warm.iter_mut().zip(&baseline.values) {
        p.initial = v.clamp(p.lower, p.upper);
    }
    let residual: Vec<f64> = data.voltage.iter().zip(&baseline.voltage).map(|(d, m)| d - m).collect();
    let q = base.cell.nominal_capacity;
    let analysis = locate::analyse(data, &features, &residual, q);
    let train_mask: Vec<bool> = split.train.iter().map(|w| *w > 0.0).collect();
    let fitted_paths: Vec<String> = options.fitted.iter().map(|p| p.path.clone()).collect();

    // Screen, then refit the best-screened candidates in parallel.
    let mut screened: Vec<(Candidate, f64, Option<candidates::Augmentation>)> = Candidate::ALL
        .iter()
        .map(|&c| (c, c.screen(data, &features, &residual, &train_mask, q), c.augment(&spec, base, data, &fitted_paths)))
        .collect();
    screened.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut refits = 0;
    let plan: Vec<(Candidate, f64, Option<candidates::Augmentation>, bool)> = screened
        .into_iter()
        .map(|(c, s, aug)| {
            let refit = aug.is_some() && refits < options.max_refits;
            refits += usize::from(refit);
            (c, s, aug, refit)
        })
        .collect();
    let mut outcomes: Vec<CandidateOutcome> = plan
        .into_par_iter()
        .map(|(c, score, aug, refit)| {
            let mut out = CandidateOutcome {
                candidate: c,
                name: c.name().into(),
                signature: c.signature().into(),
                screen_score: score,
                change: aug.as_ref().map(|a| a.change.clone()).unwrap_or_default(),
                fit: None,
                note: None,
                delta_bic: f64::NAN,
                delta_aic: f64::NAN,
                holdout_gain: f64::NAN,
                holdout_llr: f64::NAN,
                clears_margins: false,
                next: None,
            };
            let Some(aug) = aug else {
                out.note = Some("not applicable to this model".into());
                return out;
            };
            if !refit {
                out.note = Some("not refitted: weaker signature than the refitted candidates".into());
                return out;
            }
            let label = describe(&aug.spec);
            // From the user's fitted values and, when they were fitted, also from the user's
            // starting values (a fit that compensated a missing effect can mislead); the
            // lower training error wins.
            let starts: Vec<&Vec<FitParameter>> = if options.fitted.is_empty() { vec![&warm] } else { vec![&warm, &options.fitted] };
            let fits = starts.into_iter().map(|start| {
                let mut params = start.clone();
                params.extend(aug.extra.iter().cloned());
                refit::fit_and_score(label.clone(), aug.spec, aug.base.clone(), params, data, &split, &options.fit)
            });
            let best = fits.reduce(|a, b| match (a, b) {
                (Ok(a), Ok(b)) => Ok(if b.rmse_train < a.rmse_train { b } else { a }),
                (Ok(a), Err(_)) | (Err(_), Ok(a)) => Ok(a),
                (Err(e), Err(_)) => Err(e),
            });
            match best.expect("at least one start") {
                Ok(f) => {
                    out.delta_bic = baseline.bic - f.bic;
                    out.delta_aic = baseline.aic - f.aic;
                    out.holdout_gain = 1.0 - f.rmse_holdout / baseline.rmse_holdout;
                    out.holdout_llr = 2.0 * split.holdout_points() as f64 * (baseline.rmse_holdout / f.rmse_holdout).ln();
                    out.clears_margins = out.delta_bic > options.min_delta_bic
                        && out.holdout_gain >= options.min_holdout_gain
                        && out.holdout_llr > options.min_holdout_llr;
                    let fitted = f
                        .names
                        .iter()
                        .zip(&f.values)
                        .map(|(name, v)| {
                            let mut p = warm.iter().chain(&aug.extra).find(|p| &p.path == name).expect("fitted parameter").clone();
                            p.initial = v.clamp(p.lower, p.upper);
                            p
                        })
                        .collect();
                    out.next = Some(NextModel { spec: aug.spec, base: aug.base.clone(), fitted });
                    out.fit = Some(f);
                }
                Err(e) => out.note = Some(format!("fit failed: {e}")),
            }
            out
        })
        .collect();
    outcomes.sort_by(|a, b| {
        let key = |c: &CandidateOutcome| (c.fit.is_some(), c.clears_margins);
        key(b).cmp(&key(a)).then_with(|| {
            if a.fit.is_some() { b.delta_bic.total_cmp(&a.delta_bic) } else { b.screen_score.total_cmp(&a.screen_score) }
        })
    });
    let found = outcomes.first().is_some_and(|c| c.clears_margins);
    let residual_after = outcomes.first().and_then(|c| c.fit.as_ref()).map(|f| {
        let r: Vec<f64> = data.voltage.iter().zip(&f.voltage).map(|(d, m)| d - m).collect();
        locate::analyse(data, &features, &r, q)
    });
    let mut diagnosis = Diagnosis {
        model: describe(&spec),
        points: features.valid.iter().filter(|v| **v).count(),
        train_points: split.train_points(),
        holdout_points: split.holdout_points(),
        blocks: options.blocks,
        holdout_every: options.holdout_every,
        min_delta_bic: options.min_delta_bic,
        min_holdout_gain: options.min_holdout_gain,
        min_holdout_llr: options.min_holdout_llr,
        baseline,
        residual: analysis,
        candidates: outcomes,
        found,
        residual_after,
        summary: String::new(),
        seconds: 0.0,
        data: data.clone(),
        split,
    };
    diagnosis.summary = report::plain_words(&diagnosis);
    diagnosis.seconds = start.elapsed().as_secs_f64();
    Ok(diagnosis)
}

/// Diagnoses repeatedly: after a round names a missing effect, the next round starts from
/// the model with that effect added (its fitted values as starting values), until a round
/// finds nothing or `max_rounds` rounds ran. Returns every round.
pub fn diagnose_rounds(data: &Recording, base: &ParameterSet, options: &DiagnoseOptions, max_rounds: usize) -> Result<Vec<Diagnosis>, Error> {
    let mut rounds: Vec<Diagnosis> = Vec::new();
    let (mut base, mut options) = (base.clone(), options.clone());
    while rounds.len() < max_rounds.max(1) {
        let d = diagnose(data, &base, &options)?;
        let next = if d.found { d.best().and_then(|c| c.next.clone().zip(c.fit.clone())) } else { None };
        rounds.push(d);
        let Some((next, fit)) = next else { break };
        base = next.base;
        options.spec = next.spec;
        options.fitted = next.fitted;
        options.fitted_baseline = Some(fit);
    }
    Ok(rounds)
}
