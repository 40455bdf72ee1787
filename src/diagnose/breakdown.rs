//! A user's model that breaks down part-way through a recording (a concentration at its
//! limit): which candidate lets it follow the whole recording. Past the breakdown the user's
//! model has no error to compare with, so a candidate refitted on the whole recording is held
//! to the standard the user's model set where it could follow: on held-out points it may
//! leave no more than the user's model left before the breakdown plus the size floor (in
//! quadrature: what it leaves beyond that level is less than a named effect must remove),
//! with plausible values. Those that do are ranked by BIC among themselves, a tie within the
//! margin as elsewhere.

use rayon::prelude::*;

use super::ageing::Load;
use super::select::{self, Comparison, Verdict};
use super::{Candidate, CandidateOutcome, Features, Round, refit_candidate, standings};
use crate::data::Recording;

/// The candidates refitted on the whole recording, best first, and the verdict they support
/// (found or tied, else `Unexplained`).
pub(super) struct Followers {
    pub candidates: Vec<CandidateOutcome>,
    pub verdict: Verdict,
}

/// Every identifiable candidate refitted on `whole` (the recording before it was cut at the
/// breakdown) on top of `round`'s user's model; `at_s` is where that model broke down (s).
pub(super) fn followers(whole: &Recording, round: &Round, at_s: f64) -> Followers {
    let options = round.options;
    let features = Features::of(whole);
    let split = options.split(&features.valid);
    let n_train = split.train_points();
    let q = round.base.cell.nominal_capacity;
    let whole_round = Round { data: whole, split: &split, load: Load::of(whole), ..*round };
    let level = round.baseline.rmse_holdout.hypot(options.margins.size_floor(round.noise));
    let plan: Vec<Candidate> = Candidate::ALL
        .iter()
        .take(options.max_refits)
        .copied()
        .filter(|&c| !(c == Candidate::UnrelaxedStart && options.fit.start_at_rest) && c.not_identifiable(whole, &features, q).is_none())
        .collect();
    let progress = crate::progress::bar("diagnose", plan.len() as u64, "{msg} {bar:30} {pos}/{len} [{elapsed}]");
    progress.set_message(format!("the user's model broke down at {at_s:.0} s: refitting candidates on the whole recording"));
    let mut candidates: Vec<CandidateOutcome> = plan
        .into_par_iter()
        .filter_map(|c| {
            let out = refit_on_whole(c, &whole_round, level, n_train, at_s);
            progress.inc(1);
            out
        })
        .collect();
    progress.finish_and_clear();
    let n_common = select::common_effective_points(candidates.iter().filter(|c| c.named).map(|c| &c.comparison));
    candidates.sort_by(|a, b| {
        let key = |c: &CandidateOutcome| c.named;
        key(b).cmp(&key(a)).then_with(|| match a.named && b.named {
            true => a.comparison.bic_at(n_common).total_cmp(&b.comparison.bic_at(n_common)),
            false => rmse_holdout(a).total_cmp(&rmse_holdout(b)),
        })
    });
    let separate = |a: Candidate, b: Candidate| a.separating_experiment(b, &features);
    let verdict = select::verdict(&standings(&candidates), true, options.margins.min_delta_bic, separate);
    Followers { candidates, verdict }
}

/// Candidate `c` refitted on the whole recording of `round` (its user's model broke down at
/// `at_s`, s), named when it leaves at most `level` (V) on held-out points; `None` when it
/// does not apply or its fit fails (it breaks down too).
fn refit_on_whole(c: Candidate, round: &Round, level: f64, n_train: usize, at_s: f64) -> Option<CandidateOutcome> {
    let options = round.options;
    let mut aug = c.augment(&options.spec, round.base, round.fitted_paths, &round.load)?;
    // No effect is the user's model, which breaks down: each of the candidate's rates
    // and factors is screened a decade apart for a start that follows the recording.
    aug.screened = true;
    let mut out = refit_candidate::assess(c, Ok(aug), round, |f| {
        let comparison = Comparison {
            delta_bic: f64::NAN,
            ln_bayes_factor: f64::NAN,
            holdout_gain: f64::NAN,
            explained: f64::NAN,
            effective_points: f.effective_points(n_train),
            rmse_train: f.rmse_train,
            parameters: f.parameters as f64,
        };
        (comparison, f.rmse_holdout <= level)
    });
    out.fit.as_ref()?;
    out.note = Some(format!(
        "refitted on the whole recording, which the user's model cannot follow past {at_s:.0} s: named when it leaves at most {} RMS on held-out points (the user's model's {} before the breakdown and the size floor, in quadrature)",
        super::report::mv(level),
        super::report::mv(round.baseline.rmse_holdout)
    ));
    Some(out)
}

fn rmse_holdout(c: &CandidateOutcome) -> f64 {
    c.fit.as_ref().map_or(f64::INFINITY, |f| f.rmse_holdout)
}
