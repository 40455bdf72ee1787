//! Fits of the user's model and of each augmented model on the training points, scored on
//! the training points (information criteria) and on the held-out points (RMSE).

use serde::Serialize;

use crate::cost::CostKind;
use crate::data::Recording;
use crate::error::Error;
use crate::optim::OptimOptions;
use crate::params::ParameterSet;
use crate::problem::fit::fit;
use crate::problem::fitting::{FitParameter, FittingProblem, ModelSpec};

/// Which points train and which validate.
#[derive(Clone, Debug)]
pub struct Split {
    /// Weight 1 on training points, 0 elsewhere (repeated-time points are in neither).
    pub train: Vec<f64>,
    /// Held-out points.
    pub holdout: Vec<bool>,
}

impl Split {
    /// Cuts the recording's time span into `blocks` equal blocks and holds out every block
    /// `b` with `b % every == every / 2` (e.g. blocks 2 and 6 of 8 for `every = 4`), so
    /// hold-out points lie early and late in the recording. `valid` marks usable points.
    pub fn blocks(time: &[f64], valid: &[bool], blocks: usize, every: usize) -> Self {
        let (t0, t1) = (time[0], time[time.len() - 1]);
        let span = (t1 - t0).max(f64::MIN_POSITIVE);
        let every = every.max(2);
        let holdout: Vec<bool> = time
            .iter()
            .zip(valid)
            .map(|(t, v)| {
                let b = (((t - t0) / span * blocks as f64) as usize).min(blocks - 1);
                *v && b % every == every / 2
            })
            .collect();
        let train = holdout.iter().zip(valid).map(|(h, v)| if *v && !*h { 1.0 } else { 0.0 }).collect();
        Self { train, holdout }
    }

    pub fn train_points(&self) -> usize {
        self.train.iter().filter(|w| **w > 0.0).count()
    }

    pub fn holdout_points(&self) -> usize {
        self.holdout.iter().filter(|h| **h).count()
    }
}

/// How to fit.
#[derive(Clone, Debug)]
pub struct FitSettings {
    /// Optimiser name for `crate::optim::by_name`.
    pub optimiser: String,
    pub max_evaluations: usize,
    pub seed: u64,
    /// Start every model from the rest state whose OCV is the first recorded voltage
    /// (keeping each parameter set's cyclable lithium); needs a recording that starts at rest.
    pub start_at_rest: bool,
}

/// One fitted model, scored.
#[derive(Clone, Debug, Serialize)]
pub struct FitOutcome {
    /// What was fitted, e.g. "SPM as-is" or "SPM + contact-resistance submodel on".
    pub model: String,
    /// Fitted parameter paths, values and standard errors (parameter units).
    pub names: Vec<String>,
    pub values: Vec<f64>,
    pub std_errors: Vec<f64>,
    /// RMS residual (V) over training, held-out and all usable points.
    pub rmse_train: f64,
    pub rmse_holdout: f64,
    pub rmse_all: f64,
    /// Gaussian information criteria on the training points with the noise level estimated
    /// from the residuals: `n ln(SSE/n) + k ln n` and `n ln(SSE/n) + 2k`.
    pub bic: f64,
    pub aic: f64,
    pub evaluations: usize,
    /// Wall time (s).
    pub seconds: f64,
    /// Model voltage (V) at every recorded point.
    #[serde(skip)]
    pub voltage: Vec<f64>,
}

fn rms_where(r: &[f64], keep: impl Fn(usize) -> bool) -> f64 {
    let (s, n) = r.iter().enumerate().filter(|(k, _)| keep(*k)).fold((0.0, 0usize), |(s, n), (_, v)| (s + v * v, n + 1));
    if n == 0 { f64::NAN } else { (s / n as f64).sqrt() }
}

/// Fits `parameters` of the model `spec` on the training points of `data` (or, with no
/// parameters, simulates once) and scores the result.
pub fn fit_and_score(
    label: String,
    spec: ModelSpec,
    base: ParameterSet,
    parameters: Vec<FitParameter>,
    data: &Recording,
    split: &Split,
    settings: &FitSettings,
) -> Result<FitOutcome, Error> {
    let start = std::time::Instant::now();
    let k = parameters.len();
    let mut problem = FittingProblem::new(spec, base, parameters, data.clone())?.with_weights(split.train.clone())?;
    if settings.start_at_rest {
        problem = problem.starting_at_rest()?;
    }
    let (names, values, std_errors, voltage, evaluations) = if k == 0 {
        (Vec::new(), Vec::new(), Vec::new(), problem.simulate(&[])?, 1)
    } else {
        let options = OptimOptions::default().with_seed(settings.seed).with_max_evaluations(settings.max_evaluations)?;
        let r = fit(&problem, CostKind::Sse, &settings.optimiser, options)?;
        (r.names, r.x, r.std_errors, r.voltage, r.evaluations + r.gradient_evaluations)
    };
    let r: Vec<f64> = data.voltage.iter().zip(&voltage).map(|(d, m)| d - m).collect();
    let n = split.train_points() as f64;
    let sse: f64 = r.iter().zip(&split.train).map(|(r, w)| w * r * r).sum();
    let ll = n * (sse / n).max(f64::MIN_POSITIVE).ln();
    Ok(FitOutcome {
        model: label,
        names,
        values,
        std_errors,
        rmse_train: (sse / n).sqrt(),
        rmse_holdout: rms_where(&r, |i| split.holdout[i]),
        rmse_all: rms_where(&r, |i| split.holdout[i] || split.train[i] > 0.0),
        bic: ll + k as f64 * n.ln(),
        aic: ll + 2.0 * k as f64,
        evaluations,
        seconds: start.elapsed().as_secs_f64(),
        voltage,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_hold_out_early_and_late_points() {
        let time: Vec<f64> = (0..80).map(f64::from).collect();
        let mut valid = vec![true; 80];
        valid[21] = false;
        let s = Split::blocks(&time, &valid, 8, 4);
        // Blocks of 10 points; blocks 2 and 6 are held out.
        assert!(s.holdout[20] && s.holdout[29] && s.holdout[60] && !s.holdout[19] && !s.holdout[30]);
        assert!(!s.holdout[21] && s.train[21] == 0.0);
        assert_eq!(s.holdout_points(), 19);
        assert_eq!(s.train_points(), 60);
    }
}
