//! Model-discrepancy diagnosis: locate a mismatch, name what the model left out (missing
//! physics) or got wrong (a parameter mismatch), add it, refit, and show the fit improve.
//!
//! 1. Check: the recording against the cell (charge moved vs capacity, voltage swing vs
//!    charge, peak C-rate): likely unit errors stop the diagnosis with the reason.
//! 2. Baseline: the user's model replays the recorded current without cut-offs; its initial
//!    state of charge is a nuisance fitted with it (a recording may start part-way through a
//!    discharge or under load). If the model fails part-way, the recording is diagnosed up
//!    to that point and the report says where it broke down.
//! 3. Locate: the residual `r = V_model - V_data` (the fits' convention) is analysed ([`locate`]): where in time,
//!    after which current steps, at rest or under load, and whether noise explains it.
//! 4. Candidates: every identifiable candidate of the [`candidates`] library is added to the
//!    model and fitted by Levenberg-Marquardt on a training part of the recording, in
//!    parallel; the model always runs through the whole recording.
//! 5. Select ([`select`]): ΔBIC with effective point counts and honest parameter counts, a
//!    Laplace Bayes factor, the hold-out RMSE cut, the RMS removed against the noise, and
//!    plausible fitted values decide the verdict: found, a tie (with the experiment that
//!    separates the two), unexplained structure, or nothing beyond noise.
//!
//! [`diagnose_rounds`] repeats the diagnosis on the augmented model to find a second effect.

mod ageing;
pub mod at_rest;
pub mod backward;
mod baseline;
mod breakdown;
mod heat_balance;
mod holdout;
pub use baseline::Breakdown;
pub mod candidates;
pub mod features;
pub mod locate;
mod pairs;
mod plating_gate;
mod refine;
mod refit_candidate;
pub mod refit;
pub mod report;
pub mod select;
pub mod synthetic;
pub mod tolerance;

use rayon::prelude::*;
use serde::Serialize;

pub use ageing::Load;
pub use candidates::{Candidate, Class, read_by_a_candidate};
use features::Features;
pub use locate::ResidualAnalysis;
pub use refit::{FitOutcome, FitSettings, Split};
pub use select::{Comparison, Margins, Verdict};

use crate::data::Recording;
use crate::error::Error;
use crate::params::ParameterSet;
use refit_candidate::refit_candidate;
use crate::problem::fitting::{FitParameter, ModelSpec};

/// Hold-out RMSE of the best named single effect, in multiples of the size floor, above which
/// pairs are tried against it.
const PAIR_TRIGGER: f64 = 3.0;

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
    /// Parameters fitted in the user's model and in every candidate (may be empty).
    pub fitted: Vec<FitParameter>,
    /// Fit the initial state of charge as a nuisance (unless the user fits the initial
    /// concentrations or starts at rest).
    pub estimate_initial_soc: bool,
    /// The recording is cut into this many blocks of consecutive points, equal in number ...
    pub blocks: usize,
    /// ... of which every `holdout_every`-th is held out for validation, ...
    pub holdout_every: usize,
    /// ... starting at this block (0-based; `None`: `holdout_every / 2`, or another when
    /// those blocks miss the misfit: [`holdout::representative_phase`]).
    pub holdout_phase: Option<usize>,
    /// Candidates refitted at most (all identifiable ones by default).
    pub max_refits: usize,
    pub margins: Margins,
    pub fit: FitSettings,
    /// The user's model already fitted on this recording (e.g. by the previous round).
    pub fitted_baseline: Option<FitOutcome>,
    /// Refit pairs of candidates when no single one explains the recording. Rounds after
    /// the first do not: their model already holds a named effect, so a pair there would be
    /// a third and fourth effect (none was named in 71 PyBaMM-made cases), and its search is
    /// the costliest part of a round (45 pairs of DFN fits, 460 s of blind j8's 807 s).
    pub pairs: bool,
    /// Wall time (s) after which no further round starts (`None`: no limit). A round in
    /// progress finishes; the last round says the diagnosis stopped on the budget.
    pub time_budget: Option<f64>,
    /// Where the user's model broke down on the whole recording (found by the first round;
    /// later rounds diagnose the same cut recording).
    pub broke_down: Option<Breakdown>,
}

impl DiagnoseOptions {
    /// Defaults: 8 blocks with every 4th held out (25 %), every candidate refitted, the
    /// margins of [`Margins::default`], the initial state of charge estimated.
    pub fn new(spec: ModelSpec) -> Self {
        Self {
            spec,
            fitted: Vec::new(),
            estimate_initial_soc: true,
            blocks: 8,
            holdout_every: 4,
            holdout_phase: None,
            max_refits: Candidate::ALL.len(),
            margins: Margins::default(),
            fit: FitSettings::default(),
            fitted_baseline: None,
            pairs: true,
            time_budget: None,
            broke_down: None,
        }
    }

    /// The first held-out block (0-based).
    fn phase(&self) -> usize {
        self.holdout_phase.unwrap_or(self.holdout_every.max(2) / 2)
    }

    /// The training and held-out points of a recording whose usable points are `valid`.
    fn split(&self, valid: &[bool]) -> Split {
        Split::blocks(valid, self.blocks, self.holdout_every, self.phase())
    }

    fn validate(&self) -> Result<(), Error> {
        if self.blocks < 2 {
            return Err(Error::invalid("blocks", self.blocks as f64, "must be at least 2"));
        }
        let m = &self.margins;
        if !(m.min_holdout_gain >= 0.0 && m.min_holdout_gain < 1.0) {
            return Err(Error::invalid("min_holdout_gain", m.min_holdout_gain, "must lie in [0, 1)"));
        }
        if !m.min_delta_bic.is_finite() {
            return Err(Error::invalid("min_delta_bic", m.min_delta_bic, "must be finite"));
        }
        if let Some(b) = self.time_budget.filter(|b| !(b.is_finite() && *b > 0.0)) {
            return Err(Error::invalid("time_budget", b, "must be a positive number of seconds"));
        }
        Ok(())
    }
}

/// What a round's candidates are fitted against: the user's model of the round, fitted.
pub(super) struct Round<'a> {
    pub options: &'a DiagnoseOptions,
    pub base: &'a ParameterSet,
    pub data: &'a Recording,
    pub split: &'a Split,
    pub baseline: &'a FitOutcome,
    pub fitted_paths: &'a [String],
    /// The user's fitted parameters at their fitted values, and the points their fit
    /// started from.
    pub warm: &'a [FitParameter],
    pub restarts: &'a [Vec<f64>],
    pub noise: f64,
    pub load: Load,
}

/// One candidate: its fit, comparison and standing.
#[derive(Clone, Debug, Serialize)]
pub struct CandidateOutcome {
    pub candidate: Candidate,
    /// The second effect, when this outcome is a pair refitted together.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub partner: Option<Candidate>,
    pub name: String,
    pub class: Class,
    pub signature: String,
    pub plausible_range: String,
    /// How the model was changed.
    pub change: String,
    /// The fit, when the candidate was refitted and the fit ran.
    pub fit: Option<FitOutcome>,
    /// Why it was not refitted, why the fit failed, or why it is not named.
    pub note: Option<String>,
    pub comparison: Comparison,
    /// Whether it clears the margins (ΔBIC, hold-out cut, size against noise).
    pub clears_margins: bool,
    /// Why its fitted values are not physically plausible.
    pub implausible: Option<String>,
    /// Clears the margins with plausible values.
    pub named: bool,
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

/// The outcome of a diagnosis.
#[derive(Clone, Debug, Serialize)]
pub struct Diagnosis {
    pub model: String,
    /// The user's model of this round.
    #[serde(skip)]
    pub spec: ModelSpec,
    pub points: usize,
    pub train_points: usize,
    pub holdout_points: usize,
    /// Time blocks of the recording, and every how many one is held out.
    pub blocks: usize,
    pub holdout_every: usize,
    /// The first held-out block (0-based).
    pub holdout_phase: usize,
    pub margins: Margins,
    /// Noise level of the recording (V), from first differences of the user's residual.
    pub noise: f64,
    /// The solver's rtol = atol in every fit of this round ([`tolerance::choose`]).
    pub tolerance: f64,
    /// The user's model, fitted as asked (with the nuisance initial state).
    pub baseline: FitOutcome,
    pub residual: ResidualAnalysis,
    /// Named candidates first (by ΔBIC), then the other refitted ones, then the rest.
    pub candidates: Vec<CandidateOutcome>,
    pub verdict: Verdict,
    /// Whether a candidate is named (found or tied).
    pub found: bool,
    /// The residual with the first-ranked refitted candidate.
    pub residual_after: Option<ResidualAnalysis>,
    /// Checks and events worth knowing (unit checks, truncation, temperature used).
    pub notes: Vec<String>,
    /// Where the user's model broke down on the recording, when it did: only the part before
    /// was diagnosed, and the verdict is never "no missing physics".
    pub broke_down: Option<Breakdown>,
    /// The whole recording, when the user's model broke down on it and a named candidate
    /// follows it: the next round diagnoses it whole.
    #[serde(skip)]
    pub whole: Option<Recording>,
    /// On the last round: effects named in earlier rounds that the final model does not need.
    pub superseded: Vec<backward::Superseded>,
    /// Why no further round ran although this one named an effect (the round limit or the
    /// time budget); `None` when the diagnosis ended on its own.
    pub cut_short: Option<String>,
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
    let (data_given, base_given) = (data, base);
    let mut notes = Vec::new();
    notes.extend(data.refuse_unit_errors("the recording", base)?);
    let mut data = data.clone();
    // The cell's temperature is part of the recording: an isothermal model runs at the
    // first recorded temperature, a thermal one starts there.
    let mut base = base.clone();
    if let Some(t0) = data.temperature.as_ref().and_then(|t| t.first().copied()) {
        base.thermal.ambient_temperature = t0;
        base.thermal.initial_temperature = t0;
    }
    let base = &base;
    let tolerance = options.fit.tolerance.unwrap_or_else(|| {
        let c = tolerance::choose(&data, base, options.spec, &options.fit);
        notes.push(format!("The fits solve at rtol = atol = {:.0e}: {}.", c.tolerance, c.reason));
        c.tolerance
    });
    let temperature_weight = options.fit.temperature_weight.or_else(|| refit::temperature_weight(&data));
    let options = &DiagnoseOptions { fit: FitSettings { tolerance: Some(tolerance), temperature_weight, ..options.fit.clone() }, ..options.clone() };
    // Where the round's time goes (wall seconds), for the report.
    let mut timing: Vec<String> = Vec::new();
    let (baseline, split, warm, restarts, cut_here) = match &options.fitted_baseline {
        Some(b) if b.voltage.len() == data.time.len() && b.names.len() == options.fitted.len() => {
            let features = Features::of(&data);
            (b.clone(), options.split(&features.valid), options.fitted.clone(), Vec::new(), None)
        }
        _ => {
            let b = baseline::fit_baseline(&mut data, base, options, &mut notes)?;
            timing.push(format!("the user's model's fit {:.0} s", b.fit.seconds));
            (b.fit, b.split, b.fitted, b.starts, b.broke_down)
        }
    };
    let broke_down = cut_here.as_ref().map(|(b, _)| b.clone()).or_else(|| options.broke_down.clone());
    let data = data;
    let features = Features::of(&data);
    let mut warm = warm;
    for (p, v) in warm.iter_mut().zip(&baseline.values) {
        p.initial = v.clamp(p.lower, p.upper);
    }
    let residual: Vec<f64> = data.voltage.iter().zip(&baseline.voltage).map(|(d, m)| m - d).collect();
    let q = base.cell.nominal_capacity;
    let analysis = locate::analyse(&data, &features, &residual, q);
    let noise = analysis.noise;
    let fitted_paths: Vec<String> = warm.iter().map(|p| p.path.clone()).collect();
    let n_train = split.train_points();
    let load = Load::of(&data);

    // The most any candidate can remove is what lies above the noise: when that is below
    // the size floor, nothing can be named and no candidate is refitted.
    let room = (baseline.rmse_holdout.powi(2) - noise * noise).max(0.0).sqrt();
    let no_room = room < options.margins.size_floor(noise);
    // So in a later round (its baseline the last round's fit, refitted here on the moved
    // blocks): the effect found may leave the rest of the misfit where the blocks do not look.
    // Once per round: the refit on the moved blocks has a phase and no baseline given.
    let later_round = options.fitted_baseline.is_some();
    if no_room && (later_round || options.holdout_phase.is_none()) {
        if let Some((phase, why)) = holdout::representative_phase(options, &features.valid, &residual, noise, options.margins.size_floor(noise)) {
            let moved = DiagnoseOptions { holdout_phase: Some(phase), fitted_baseline: None, ..options.clone() };
            let mut d = diagnose(data_given, base_given, &moved)?;
            d.notes.insert(0, why);
            d.summary = report::plain_words(&d);
            d.seconds = start.elapsed().as_secs_f64();
            return Ok(d);
        }
    }
    // Plating within one charge, where the fitted model itself plates (few cycles otherwise
    // identify no plating).
    let plating_seen = ageing::too_few_cycles(&features)
        .and_then(|_| plating_gate::plating_in_a_charge(options.spec, base, &warm, &baseline.values, &data, &options.fit));
    if let Some(seen) = &plating_seen {
        notes.push(seen.note());
    }
    let plan: Vec<(Candidate, Result<candidates::Augmentation, String>)> = Candidate::ALL
        .iter()
        .take(options.max_refits)
        .map(|&c| {
            let aug = match c.not_identifiable(&data, &features, q).filter(|_| !(c.plates() && plating_seen.is_some())) {
                _ if c == Candidate::UnrelaxedStart && options.fit.start_at_rest => Err("not refitted: the recording is taken to start at rest (--start-at-rest)".to_string()),
                _ if no_room => Err(format!("not refitted: the user's model leaves {} RMS above the noise, less than the {} a named effect must remove", report::mv(room), report::mv(options.margins.size_floor(noise)))),
                Some(why) => Err(format!("not identifiable from this recording: {why}")),
                None => c.augment(&options.spec, base, &fitted_paths, &load).ok_or_else(|| "not applicable to this model".to_string()),
            };
            (c, aug)
        })
        .collect();
    let round = Round { options, base, data: &data, split: &split, baseline: &baseline, fitted_paths: &fitted_paths, warm: &warm, restarts: &restarts, noise, load };
    let singles_start = std::time::Instant::now();
    let progress = crate::progress::bar("diagnose", plan.len() as u64, "{msg} {bar:30} {pos}/{len} [{elapsed}]");
    progress.set_message(format!("refitting candidates on {}", options.spec));
    let mut outcomes: Vec<CandidateOutcome> = plan
        .into_par_iter()
        .map(|(c, aug)| {
            let out = refit_candidate::judge(c, aug, &round);
            progress.inc(1);
            out
        })
        .collect();
    progress.finish_and_clear();
    let refitted = outcomes.iter().filter(|c| c.fit.is_some()).count();
    if refitted > 0 {
        timing.push(format!("{refitted} candidates refitted {:.0} s", singles_start.elapsed().as_secs_f64()));
    }
    heat_balance::read_only_if_unpredicted(&mut outcomes, &[], &baseline, &data);
    // Named candidates first, compared with one another at common effective points; the
    // others by their gain over the user's model.
    let n_common = select::common_effective_points(outcomes.iter().filter(|c| c.named).map(|c| &c.comparison));
    outcomes.sort_by(|a, b| {
        let key = |c: &CandidateOutcome| (c.named, c.fit.is_some());
        key(b).cmp(&key(a)).then_with(|| match a.named && b.named {
            true => a.comparison.bic_at(n_common).total_cmp(&b.comparison.bic_at(n_common)),
            false => b.comparison.delta_bic.total_cmp(&a.comparison.delta_bic),
        })
    });
    // Structure: the whiteness tests reject noise, or the residual is twice the noise level,
    // and what lies above the noise exceeds the size floor.
    let structured = (analysis.structured || baseline.rmse_all > 2.0 * noise) && !no_room;
    let separate = |a: Candidate, b: Candidate| a.separating_experiment(b, &features);
    let mut verdict = select::verdict(&standings(&outcomes), structured, options.margins.min_delta_bic, separate);
    let after = |outcomes: &[CandidateOutcome]| {
        outcomes.first().and_then(|c| c.fit.as_ref()).map(|f| {
            let r: Vec<f64> = data.voltage.iter().zip(&f.voltage).map(|(d, m)| m - d).collect();
            locate::analyse(&data, &features, &r, q)
        })
    };
    // A named single whose fit still leaves structure: its secondary properties refitted
    // before any pair is tried, so that a pair must beat the effect at its best description
    // (an asymmetric charge transfer is the kinetics candidate with its transfer coefficients
    // free, not kinetics plus a stand-in).
    notes.extend(lead_tie_by_holdout(&mut verdict, &mut outcomes, &options.margins, noise));
    let structure = if verdict.found() { after(&outcomes) } else { None };
    if let (Some(structure), Some(first)) = (structure, outcomes.first_mut()) {
        if let Some((false, record)) = refine::refine(first, &structure, &round) {
            notes.push(format!("The named {} was {record}.", first.name));
        }
    }
    // No single effect: two may be hiding each other. One effect named that leaves far more
    // than the noise on held-out points may be standing in for two: a pair that beats it by
    // the same margins (against it, not the user's model) replaces it.
    let best_single = outcomes.first().filter(|c| c.named).and_then(|c| c.fit.as_ref());
    // A tie between two singles that both leave far more than the noise may be two effects
    // that each explain part of the recording.
    let far_from_noise = verdict.found() && best_single.is_some_and(|f| f.rmse_holdout > PAIR_TRIGGER * options.margins.size_floor(noise));
    if options.pairs && (matches!(verdict, Verdict::Unexplained) || far_from_noise) {
        let beats_single = |pair: &CandidateOutcome| match (best_single, pair.fit.as_ref()) {
            (Some(single), Some(fit)) if far_from_noise => options.margins.cleared_by(&select::compare(single, fit, n_train), noise),
            _ => true,
        };
        // Pairs that fit alike are a tie, as singles are: one pair's parameter may stand in
        // for the other's (in the SPMe a conductivity factor acts as a series resistance).
        let pairs_start = std::time::Instant::now();
        let (mut named, work) = pairs::named_pairs(&outcomes, &round);
        timing.push(format!("{} {:.0} s", work.in_words(), pairs_start.elapsed().as_secs_f64()));
        heat_balance::read_only_if_unpredicted(&mut named, &outcomes, &baseline, &data);
        named.retain(|pair| pair.named && beats_single(pair));
        if !named.is_empty() {
            let n_pairs = select::common_effective_points(named.iter().map(|c| &c.comparison));
            named.sort_by(|a, b| a.comparison.bic_at(n_pairs).total_cmp(&b.comparison.bic_at(n_pairs)));
            verdict = select::verdict(&standings(&named), true, options.margins.min_delta_bic, separate);
            outcomes.splice(0..0, named);
            notes.extend(lead_tie_by_holdout(&mut verdict, &mut outcomes, &options.margins, noise));
        }
    }
    // A model that broke down here and nothing named before: the candidate that lets it
    // follow the whole recording is the missing effect; the next round diagnoses it whole.
    let mut whole = None;
    if let Some((b, recorded)) = cut_here.filter(|_| !verdict.found()) {
        let followers = breakdown::followers(&recorded, &round, b.at_s);
        if followers.verdict.found() {
            verdict = followers.verdict;
            whole = Some(recorded);
        }
        outcomes.splice(0..0, followers.candidates);
    }
    // A model that broke down did not follow the rest of the recording: whatever the part
    // before it shows, that is a mismatch left unexplained, not an absence of one.
    if broke_down.is_some() && matches!(verdict, Verdict::NoMissingPhysics) {
        verdict = Verdict::BrokeDown;
    }
    let residual_after = after(&outcomes);
    let current_noise = data.current_noise();
    if current_noise > 0.0 {
        notes.push(format!(
            "The current channel carries {:.1} mA RMS of white noise; stretches constant within it are driven at their mean current, not sample by sample.",
            current_noise * 1e3
        ));
    }
    if data.temperature.is_some() {
        notes.push(format!("The model runs at (or starts from) the recording's first temperature, {:.2} K.", base.thermal.ambient_temperature));
    }
    if !timing.is_empty() {
        notes.push(format!("Time: {}; {:.0} s in all.", timing.join(", "), start.elapsed().as_secs_f64()));
    }
    let mut diagnosis = Diagnosis {
        model: options.spec.to_string(),
        spec: options.spec,
        points: features.valid.iter().filter(|v| **v).count(),
        train_points: n_train,
        holdout_points: split.holdout_points(),
        blocks: options.blocks,
        holdout_every: options.holdout_every,
        holdout_phase: options.phase(),
        margins: options.margins,
        noise,
        tolerance,
        baseline,
        residual: analysis,
        candidates: outcomes,
        found: verdict.found(),
        verdict,
        residual_after,
        notes,
        broke_down,
        whole,
        superseded: Vec::new(),
        cut_short: None,
        summary: String::new(),
        seconds: 0.0,
        data,
        split,
    };
    diagnosis.summary = report::plain_words(&diagnosis);
    diagnosis.seconds = start.elapsed().as_secs_f64();
    Ok(diagnosis)
}

/// A tie between `outcomes[0]` and `outcomes[1]` whose second predicts the held-out points
/// clearly better ([`select::leads_on_holdout`]) put in the other order, and a note saying why.
fn lead_tie_by_holdout(verdict: &mut Verdict, outcomes: &mut [CandidateOutcome], margins: &select::Margins, noise: f64) -> Option<String> {
    let Verdict::Tie { .. } = verdict else { return None };
    let [a, b, ..] = outcomes else { return None };
    let (Some(fa), Some(fb)) = (a.fit.as_ref(), b.fit.as_ref()) else { return None };
    if !select::leads_on_holdout(fa, fb, margins, noise) {
        return None;
    }
    let why = format!(
        "{} and {} fit the training points alike; {} is named first, and the next round builds on it, as it predicts the held-out points clearly better ({} against {} RMS).",
        a.name,
        b.name,
        b.name,
        report::mv(fb.rmse_holdout),
        report::mv(fa.rmse_holdout)
    );
    verdict.swap_tie(b.class);
    outcomes.swap(0, 1);
    Some(why)
}

/// Whether every one of `paths` (at least one) is fitted within two standard errors of its
/// value in `base`: the candidate changed nothing the recording can see.
fn keeps_set_values(f: &FitOutcome, paths: &[String], base: &ParameterSet) -> bool {
    !paths.is_empty()
        && paths.iter().all(|path| {
            let k = f.names.iter().position(|n| n == path);
            let v0 = base.get(path).ok();
            k.zip(v0).is_some_and(|(k, v0)| (f.values[k] - v0).abs() <= 2.0 * f.std_errors[k])
        })
}

/// The outcomes' standings for [`select::verdict`], in their order.
fn standings(outcomes: &[CandidateOutcome]) -> Vec<select::Standing> {
    outcomes.iter().map(|c| select::Standing { candidate: c.candidate, partner: c.partner, class: c.class, comparison: c.comparison, named: c.named }).collect()
}

/// Diagnoses repeatedly: after a round names an effect, the next round starts from the model
/// with that effect added (its fitted values as starting values), until a round names
/// nothing or `max_rounds` rounds ran. Returns every round.
pub fn diagnose_rounds(data: &Recording, base: &ParameterSet, options: &DiagnoseOptions, max_rounds: usize) -> Result<Vec<Diagnosis>, Error> {
    diagnose_rounds_with(data, base, options, max_rounds, |_| {})
}

/// As [`diagnose_rounds`], handing each round to `on_round` as soon as it is done (a report
/// can show it while the next round runs). The superseded effects are found after the last
/// round, so the last round's `superseded` and summary may still grow after `on_round`.
pub fn diagnose_rounds_with(data: &Recording, base: &ParameterSet, options: &DiagnoseOptions, max_rounds: usize, mut on_round: impl FnMut(&Diagnosis)) -> Result<Vec<Diagnosis>, Error> {
    let start = std::time::Instant::now();
    let mut rounds: Vec<Diagnosis> = Vec::new();
    let (mut base, mut options, mut data) = (base.clone(), options.clone(), data.clone());
    while rounds.len() < max_rounds.max(1) {
        let mut d = diagnose(&data, &base, &options)?;
        let mut next = if d.found { d.best().and_then(|c| c.next.clone().zip(c.fit.clone())) } else { None };
        let spent = start.elapsed().as_secs_f64();
        if let Some(budget) = options.time_budget.filter(|b| next.is_some() && rounds.len() + 1 < max_rounds && spent > *b) {
            d.notes.push(format!(
                "Truncated: the diagnosis stopped after round {} because its time budget of {budget:.0} s was spent ({spent:.0} s); a further effect may remain (rerun with a larger --time-budget to go on).",
                rounds.len() + 1
            ));
            d.cut_short = Some(format!("its time budget of {budget:.0} s was spent"));
            next = None;
        }
        if next.is_some() && rounds.len() + 1 >= max_rounds.max(1) {
            d.cut_short = Some(format!("it reached its round limit (--max-rounds {})", max_rounds.max(1)));
        }
        let rescued = d.whole.is_some();
        data = d.whole.clone().unwrap_or_else(|| d.data.clone());
        on_round(&d);
        rounds.push(d);
        let Some((next, fit)) = next else { break };
        base = next.base;
        options.spec = next.spec;
        options.fitted = next.fitted;
        options.fitted_baseline = Some(fit);
        // The blocks the last round held out (moved there, or in round 1, when the default
        // ones missed the misfit): the fit handed on was scored on them.
        options.holdout_phase = Some(rounds.last().expect("a round").holdout_phase);
        options.broke_down = if rescued { None } else { rounds[0].broke_down.clone() };
        options.pairs = false;
        options.fit.tolerance = Some(rounds[0].tolerance);
    }
    if rounds.iter().filter(|d| d.found).count() >= 2 {
        let last = rounds.last().expect("two rounds");
        let (spec, fitted, fit) = match last.best().filter(|_| last.found).and_then(|c| c.next.clone().zip(c.fit.clone())) {
            Some((next, fit)) => (next.spec, next.fitted, fit),
            None => (options.spec, options.fitted.clone(), last.baseline.clone()),
        };
        let model_base = last.best().filter(|_| last.found).and_then(|c| c.next.as_ref()).map_or(base.clone(), |n| n.base.clone());
        let model = backward::FinalModel { spec, base: &model_base, fitted: &fitted, fit: &fit };
        let superseded = backward::superseded(&rounds, &model, &options);
        let last = rounds.last_mut().expect("two rounds");
        last.summary.push_str(&report::superseded(&superseded));
        last.superseded = superseded;
    }
    Ok(rounds)
}
