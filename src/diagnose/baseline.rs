//! The user's model fitted to the recording before any candidate: the initial state of charge
//! as a nuisance, and a recording cut where the model breaks down.

use serde::Serialize;

use super::{DiagnoseOptions, FitOutcome, Features, Split, refit};
use crate::data::Recording;
use crate::error::Error;
use crate::params::{ParameterSet, stoichiometry_window};
use crate::problem::fitting::{FitParameter, INITIAL_SOC};

/// The state of charge (-) of `p`'s initial concentrations on its stoichiometry window, and
/// the one whose open-circuit voltage is `v` (V); both within [0, 1].
fn soc_starts(p: &ParameterSet, v: f64) -> Vec<f64> {
    let Ok(w) = stoichiometry_window(p) else { return vec![1.0] };
    let x = p.negative.initial_concentration / p.negative.max_concentration;
    let of_set = ((x - w.x0) / (w.x100 - w.x0)).clamp(0.0, 1.0);
    let line = crate::params::soc::LithiumLine::of(p);
    let x_v = line.negative_at_ocv(p, v);
    let of_voltage = ((x_v - w.x0) / (w.x100 - w.x0)).clamp(0.0, 1.0);
    if (of_set - of_voltage).abs() < 0.02 { vec![of_set] } else { vec![of_set, of_voltage] }
}

/// Where the user's model broke down on the recording: the recording is diagnosed only up to
/// a little before.
#[derive(Clone, Debug, Serialize)]
pub struct Breakdown {
    /// Time into the recording (s) at which the model broke down.
    pub at_s: f64,
    /// Why, as the solver said.
    pub reason: String,
    /// The last diagnosed time (s) and the points kept of the recording's.
    pub diagnosed_to_s: f64,
    pub kept_points: usize,
    pub recorded_points: usize,
}

/// The user's model fitted to a recording.
pub(super) struct BaselineFit {
    pub fit: FitOutcome,
    pub split: Split,
    /// The fitted parameters: the user's, then the nuisance initial state of charge.
    pub fitted: Vec<FitParameter>,
    /// The starting points the fit tried (values of `fitted`, in order): a candidate's refit
    /// may need them where the user's fitted values compensated for the missing effect.
    pub starts: Vec<Vec<f64>>,
    /// Where the model broke down on the whole recording, when it did, and that recording
    /// (before it was cut).
    pub broke_down: Option<(Breakdown, Recording)>,
}

/// The user's model fitted (with the nuisance initial state): on failure part-way, the
/// recording is cut where the model broke down and the fit repeated once.
pub(super) fn fit_baseline(data: &mut Recording, base: &ParameterSet, options: &DiagnoseOptions, notes: &mut Vec<String>) -> Result<BaselineFit, Error> {
    let mut fitted = options.fitted.clone();
    let user_sets_state = fitted.iter().any(|p| p.path.ends_with("initial_concentration") || p.path == INITIAL_SOC);
    let mut starts: Vec<Vec<f64>> = Vec::new();
    if options.estimate_initial_soc && !user_sets_state && !options.fit.start_at_rest {
        let socs = soc_starts(base, data.voltage[0]);
        fitted.push(FitParameter::linear(INITIAL_SOC, socs[0], 0.0, 1.0));
        let user: Vec<f64> = options.fitted.iter().map(|p| p.initial).collect();
        starts = socs.iter().map(|s| user.iter().copied().chain([*s]).collect()).collect();
    }
    const ATTEMPTS: usize = 3;
    let mut broke_down: Option<(Breakdown, Recording)> = None;
    for attempt in 0..ATTEMPTS {
        let features = Features::of(data);
        let split = options.split(&features.valid);
        if split.train_points() <= fitted.len() + 10 || split.holdout_points() == 0 {
            return Err(Error::InvalidSetting {
                field: "data".into(),
                reason: format!("too few points: {} training, {} held out", split.train_points(), split.holdout_points()),
            });
        }
        let label = format!("{} as given", options.spec);
        match refit::fit_and_score(label, options.spec, base.clone(), fitted.clone(), 0, &refit::Starts::at(starts.clone()), data, &split, &options.fit) {
            Ok(fit) => {
                let starts = if starts.is_empty() { vec![fitted.iter().map(|p| p.initial).collect()] } else { starts };
                return Ok(BaselineFit { fit, split, fitted, starts, broke_down });
            }
            Err(Error::Solver { t, reason }) if attempt + 1 < ATTEMPTS && t > 0.0 => {
                // Cut with a margin: the fit of the initial state explores around the start.
                let t_cut = data.time[0] + 0.95 * t;
                let keep = data.time.iter().position(|x| *x >= t_cut - 1e-9).unwrap_or(data.time.len());
                let to = data.time[keep.saturating_sub(1).min(data.time.len() - 1)];
                notes.push(format!(
                    "The user's model broke down {t:.0} s into the recording ({reason}); the first {keep} of {} points (to {to:.0} s) are diagnosed. A model that cannot follow the recording is itself evidence of a mismatch there.",
                    data.time.len(),
                ));
                // The first breakdown is the recording's; a later one only cuts further.
                let (first, recorded) = match broke_down.take() {
                    Some((b, recorded)) => (Breakdown { at_s: b.at_s.min(t), diagnosed_to_s: to, kept_points: keep, ..b }, recorded),
                    None => (Breakdown { at_s: t, reason, diagnosed_to_s: to, kept_points: keep, recorded_points: data.time.len() }, data.clone()),
                };
                broke_down = Some((first, recorded));
                data.time.truncate(keep);
                data.current.truncate(keep);
                data.voltage.truncate(keep);
                if let Some(temp) = data.temperature.as_mut() {
                    temp.truncate(keep);
                }
            }
            Err(e) => return Err(e),
        }
    }
    unreachable!("the loop returns")
}

