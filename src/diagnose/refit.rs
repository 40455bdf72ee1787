//! Fits of the user's model and of each augmented model on the training points, scored on
//! the training points (information criteria) and on the held-out points (RMSE).

use serde::Serialize;

use rayon::prelude::*;

use super::features::Features;
use crate::data::Recording;
use crate::error::Error;
use crate::params::ParameterSet;
use crate::problem::fitting::{FitParameter, FittingProblem, ModelSpec};
use crate::problem::least_squares::{LeastSquares, LeastSquaresFit, LmSettings, levenberg_marquardt, sse};
use crate::stats::{lag1, weighted_rms};

/// Which points train and which validate.
#[derive(Clone, Debug)]
pub struct Split {
    /// Weight 1 on training points, 0 elsewhere (repeated-time points are in neither).
    pub train: Vec<f64>,
    /// Held-out points.
    pub holdout: Vec<bool>,
}

impl Split {
    /// Cuts the recording into `blocks` blocks of consecutive points, equal in number, and
    /// holds out every block `b` with `b % every == phase % every` (e.g. blocks 2 and 6 of 8
    /// for `every = 4`, `phase = 2`, the default), so hold-out points lie early and late in
    /// the recording. Blocks of points,
    /// not of time: a recording logged sparsely through a long rest (a storage period, a
    /// cycler that logs on voltage change) would otherwise hold out only the rest.
    /// `valid` marks usable points.
    pub fn blocks(valid: &[bool], blocks: usize, every: usize, phase: usize) -> Self {
        let n = valid.len().max(1);
        let every = every.max(2);
        let phase = phase % every;
        let holdout: Vec<bool> = valid
            .iter()
            .enumerate()
            .map(|(k, v)| {
                let b = (k * blocks / n).min(blocks - 1);
                *v && b % every == phase
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
    /// Levenberg-Marquardt settings (each iteration costs one simulation per parameter).
    pub lm: LmSettings,
    /// Start every model from the rest state whose OCV is the first recorded voltage
    /// (keeping each parameter set's cyclable lithium); needs a recording that starts at rest.
    pub start_at_rest: bool,
    /// The solver's rtol = atol in every fit; `None`: [`super::diagnose`] chooses it from the
    /// recording's noise ([`super::tolerance::choose`]), and a fit without it uses the solver's
    /// default.
    pub tolerance: Option<f64>,
    /// Weight of the recorded temperature beside the voltage where a heat balance is fitted
    /// (V/K); `None`: read from the recording in each fit ([`temperature_weight`]). A
    /// diagnosis reads it once, as it chooses the tolerance.
    pub temperature_weight: Option<f64>,
}

impl Default for FitSettings {
    fn default() -> Self {
        Self { lm: LmSettings::default(), start_at_rest: false, tolerance: None, temperature_weight: None }
    }
}

/// Where fits start: `points` (values in parameter order; empty: the parameters' initial
/// values; the first is tried, the others only when it fails, stops on its cap, ends on a
/// bound or holds a parameter), and a point where the model is known to run (the previous
/// model: its fitted values with the candidate's parameters at no effect) toward which a
/// start that breaks the model is pulled until it runs.
///
/// `screen` lists parameters whose cost can rise between the first start and the optimum:
/// log-scaled ones (ageing rates, known only to within decades) are screened a decade apart
/// across their range, linear ones (a voltage channel's delay, whose cost has a valley for
/// every echo of the load's own rhythm) in [`LINEAR_SCREEN_STEPS`] equal steps; the others at
/// the first start, and the best point found is fitted beside the first.
///
/// `staged` is a parameter that refines a model held at its start value (the state at which
/// active material was lost, held where the plain loss puts it): every start is fitted with
/// it held there first, then freed from that optimum (see [`staged_fit`]).
#[derive(Clone, Debug, Default)]
pub struct Starts {
    pub points: Vec<Vec<f64>>,
    pub runs_at: Option<Vec<f64>>,
    pub screen: Vec<usize>,
    pub staged: Option<usize>,
}

impl Starts {
    /// Starts at these points only.
    pub fn at(points: Vec<Vec<f64>>) -> Self {
        Self { points, runs_at: None, screen: Vec::new(), staged: None }
    }
}

/// Relative drop of the squared error (-) below which a held fit explains nothing beyond the
/// previous model.
const HELD_NO_GAIN: f64 = 1e-3;

/// Levenberg-Marquardt iterations of a screening fit: every pair's first, and each of a
/// single's remaining starts when its first ones disagree.
pub(super) const SCREEN_ITERATIONS: usize = 4;

/// Levenberg-Marquardt from `x0`; with a parameter `staged`, first with it held at its value
/// in `x0`, then freed from that optimum (so the refined fit ends no worse than the held
/// model). Only when the held fit explains nothing beyond the previous model (its squared
/// error `previous`) is
/// the refinement also fitted directly from `x0`, and the lower kept: a delithiated negative's
/// loss fits to no effect held at the plain loss's state, where the state no longer moves the
/// voltage. Freed directly beside a plain loss that already explains the recording, the state
/// took up other mismatch (k2, a current gain, became an unequal loss with its lithium kept).
/// The simulations count every fit.
fn staged_fit(problem: &FittingProblem, x0: &[f64], staged: Option<usize>, previous: Option<f64>, lm: LmSettings) -> Result<LeastSquaresFit, Error> {
    let Some(k) = staged else { return levenberg_marquardt(problem, x0, lm) };
    let held = problem.pinned(k, x0[k])?;
    let mut rest = x0.to_vec();
    rest.remove(k);
    let first = levenberg_marquardt(&held, &rest, lm)?;
    let mut x = first.x.clone();
    x.insert(k, x0[k]);
    let mut fit = levenberg_marquardt(problem, &x, lm)?;
    fit.simulations += first.simulations;
    if previous.is_some_and(|p| first.sse >= (1.0 - HELD_NO_GAIN) * p) {
        if let Ok(direct) = levenberg_marquardt(problem, x0, lm) {
            let simulations = fit.simulations + direct.simulations;
            if direct.sse < fit.sse {
                fit = direct;
            }
            fit.simulations = simulations;
        }
    }
    Ok(fit)
}

/// Equal steps over a linear parameter's range in a screen: a delay searched over ±10 s is
/// tried every second.
const LINEAR_SCREEN_STEPS: usize = 20;

/// The point `x0` with each of the `screen` parameters moved to the value of its grid (a
/// decade grid for a log-scaled parameter, [`LINEAR_SCREEN_STEPS`] equal steps for a linear
/// one; bounds included) that lowers the cost most with the others at `x0`, and the
/// simulations it took; `None` when no grid value beats `x0` (or every run fails). Where the
/// model breaks down at `x0`, any grid value it follows the recording at beats it.
fn screen_grid<P: LeastSquares>(problem: &P, x0: &[f64], screen: &[usize]) -> (Option<Vec<f64>>, usize) {
    let cost = |x: &[f64]| problem.run(x).ok().map(|r| sse(&problem.weighted_residuals(&r)));
    let c0 = cost(x0).unwrap_or(f64::INFINITY);
    let trials: Vec<(usize, f64)> = screen
        .iter()
        .flat_map(|&i| {
            let p = &problem.parameters()[i];
            let steps = if p.log { (p.upper / p.lower).log10().ceil().max(1.0) as usize } else { LINEAR_SCREEN_STEPS };
            (0..=steps).map(move |d| {
                let share = d as f64 / steps as f64;
                (i, if p.log { (p.lower.ln() + (p.upper / p.lower).ln() * share).exp() } else { p.lower + (p.upper - p.lower) * share })
            })
        })
        .collect();
    let costs: Vec<Option<f64>> = trials
        .par_iter()
        .map(|&(i, v)| {
            let mut x = x0.to_vec();
            x[i] = v;
            cost(&x)
        })
        .collect();
    let mut best = x0.to_vec();
    let mut moved = false;
    for &i in screen {
        let found = trials.iter().zip(&costs).filter_map(|((j, v), c)| c.filter(|c| *j == i && *c < c0).map(|c| (*v, c))).min_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((v, _)) = found {
            best[i] = v;
            moved = true;
        }
    }
    (moved.then_some(best), 1 + trials.len())
}

/// Weight (V/K) of a recorded temperature's residuals beside the voltage's
/// ([`crate::stats::noise::temperature_weight`]) over the usable points, as the diagnosis reads
/// the noise: at current steps the voltage's jumps, and across short steps logged only at
/// their ends its slope, are no noise (blind ap7, 20 s logging of 10-25 s steps: the voltage's
/// "noise" read 185 mV against its 1 mV, and the temperature outweighed the voltage by as
/// much); `None` without a recorded temperature.
pub fn temperature_weight(data: &Recording) -> Option<f64> {
    let temperature = data.temperature.as_ref()?;
    let f = Features::of(data);
    crate::stats::noise::temperature_weight(&f.usable(&data.voltage), &f.usable(temperature), &f.usable(&data.time))
}

/// Halvings of the way back from a start that breaks the model toward one that runs.
const PULL_HALVINGS: usize = 6;

/// A point on the way from `start` to `runs_at` at which the model runs, when it does not
/// run at `start`: the distance is halved (in the search coordinates: logarithmically for
/// log-scaled parameters) until it runs, and once more; `None` when it runs at `start` or
/// nowhere on the way.
fn pulled_into_model(problem: &FittingProblem, start: &[f64], runs_at: &[f64]) -> Option<Vec<f64>> {
    if problem.simulate(start).is_ok() {
        return None;
    }
    let toward = |share: f64| -> Vec<f64> {
        problem
            .parameters
            .iter()
            .zip(start.iter().zip(runs_at))
            .map(|(p, (a, b))| match p.log && *a > 0.0 && *b > 0.0 {
                true => (a.ln() + share * (b.ln() - a.ln())).exp(),
                false => a + share * (b - a),
            })
            .collect()
    };
    // The first point that runs lies near the edge of where the model runs, where a
    // finite-difference step may break it: one more halving inward.
    (1..=PULL_HALVINGS).find(|&k| problem.simulate(&toward(1.0 - 0.5f64.powi(k as i32))).is_ok()).map(|k| toward(1.0 - 0.5f64.powi(k as i32 + 1)))
}

/// Whether the converged fit `b` ended where `a` did: the same parameters on a bound and the
/// same SSE within ten times the relative tolerance `sse_tolerance` the fits converged to.
fn same_optimum(a: &LeastSquaresFit, b: &LeastSquaresFit, sse_tolerance: f64) -> bool {
    b.converged && a.on_bound == b.on_bound && (a.sse - b.sse).abs() <= 10.0 * sse_tolerance * a.sse.max(b.sse)
}

/// Whether the starts tried so far settle the fit without the rest: the lowest of them is an
/// interior optimum (converged, no parameter on a bound) and every other start that reached
/// an interior optimum reached the same one. A first start that stopped on its cap or on a
/// bound, beside two probes that agree on a lower interior optimum, no longer sends every
/// remaining start to run (blind g1's SPM -> DFN electrolyte fit ran 469 simulations so).
fn settled(fits: &[Result<LeastSquaresFit, Error>], sse_tolerance: f64) -> bool {
    let interior = |f: &LeastSquaresFit| f.converged && !f.on_bound.iter().any(|b| *b);
    let ok: Vec<&LeastSquaresFit> = fits.iter().filter_map(|f| f.as_ref().ok()).collect();
    let Some(best) = ok.iter().copied().min_by(|a, b| a.sse.total_cmp(&b.sse)) else { return false };
    interior(best) && ok.iter().copied().filter(|f| interior(f)).all(|f| same_optimum(best, f, sse_tolerance))
}

/// One fitted model, scored.
#[derive(Clone, Debug, Default, Serialize)]
pub struct FitOutcome {
    /// What was fitted, e.g. "SPM as given" or "SPM + contact resistance".
    pub model: String,
    /// Fitted parameter paths, values and standard errors (parameter units).
    pub names: Vec<String>,
    pub values: Vec<f64>,
    pub std_errors: Vec<f64>,
    /// Which fitted values ended on a search bound.
    pub on_bound: Vec<bool>,
    /// Which fitted values move the voltage at all (false: no effect on this recording at
    /// the fitted value, e.g. a rate on its no-effect bound; left out of the evidence).
    pub informed: Vec<bool>,
    /// Parameters counted in the information criteria: fitted plus the fixed ones a
    /// structural change brings in.
    pub parameters: usize,
    /// RMS residual (V) over training, held-out and all usable points.
    pub rmse_train: f64,
    pub rmse_holdout: f64,
    pub rmse_all: f64,
    /// RMS residual (K) of the recorded temperature over all usable points, when a heat
    /// balance was fitted to it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub temperature_rmse: Option<f64>,
    /// Lag-1 autocorrelation of the training residual (-).
    pub lag1: f64,
    /// Gaussian log-likelihood of the training points (white noise, `σ` at its maximum).
    pub log_likelihood: f64,
    /// For a Laplace evidence: `ln det` of the Fisher information in the search coordinates
    /// over the `information_rank` directions the data determine, and the `ln` of the uniform
    /// prior's volume over as many directions (`Σ ln(width)` of the informed parameters,
    /// scaled by the rank over their number: a direction the data leave free integrates its
    /// prior to 1).
    pub ln_det_information: f64,
    pub information_rank: usize,
    pub ln_prior_volume: f64,
    /// Whether the search converged (false: it stopped on its iteration cap).
    pub converged: bool,
    /// Model runs of the fit over all the starts tried (finite-difference columns included).
    pub simulations: usize,
    /// Wall time (s) of all the starts.
    pub seconds: f64,
    /// Model voltage (V) at every recorded point.
    #[serde(skip)]
    pub voltage: Vec<f64>,
}

impl FitOutcome {
    /// Points that count as independent: `n (1 - ρ)/(1 + ρ)` for the training residual's
    /// lag-1 autocorrelation `ρ` (AR(1) noise), at least 10.
    pub fn effective_points(&self, n: usize) -> f64 {
        let rho = self.lag1.clamp(0.0, 0.995);
        (n as f64 * (1.0 - rho) / (1.0 + rho)).max(10.0)
    }
}

/// Weights 1 at the points `keep` selects, 0 elsewhere.
fn indicator(n: usize, keep: impl Fn(usize) -> bool) -> Vec<f64> {
    (0..n).map(|i| if keep(i) { 1.0 } else { 0.0 }).collect()
}

/// The problem that replays `data` with the model `spec` at `parameters`, solved and started
/// as `settings` say.
pub fn replay_problem(spec: ModelSpec, base: ParameterSet, parameters: Vec<FitParameter>, data: &Recording, settings: &FitSettings) -> Result<FittingProblem, Error> {
    let mut problem = FittingProblem::new(spec, base, parameters, data.clone())?;
    if let Some(tol) = settings.tolerance {
        problem.solver.set_tolerance(tol);
    }
    if settings.start_at_rest {
        problem = problem.starting_at_rest()?;
    }
    Ok(problem)
}

/// Fits `parameters` of the model `spec` on the training points of `data` from each of
/// `starts` and scores the best. `structural` counts fixed parameters a structural change
/// brought in.
#[allow(clippy::too_many_arguments)]
pub fn fit_and_score(
    label: String,
    spec: ModelSpec,
    base: ParameterSet,
    parameters: Vec<FitParameter>,
    structural: usize,
    starts: &Starts,
    data: &Recording,
    split: &Split,
    settings: &FitSettings,
) -> Result<FitOutcome, Error> {
    let start = std::time::Instant::now();
    let k = parameters.len();
    let mut problem = replay_problem(spec, base, parameters, data, settings)?.with_weights(split.train.clone())?;
    // A heat balance is fitted to the recorded temperature too; a model that reads it has
    // nothing to fit there.
    let temperature_fitted = problem.spec.submodels.thermal && !problem.spec.recorded_temperature;
    if let Some(w) = settings.temperature_weight.or_else(|| temperature_weight(data)).filter(|_| temperature_fitted) {
        problem = problem.fitting_temperature(w)?;
    }
    let mut points = if starts.points.is_empty() { vec![problem.initial()] } else { starts.points.clone() };
    let (screened, screen_runs) = if starts.screen.is_empty() { (None, 0) } else { screen_grid(&problem, &points[0], &starts.screen) };
    // The screened point is fitted beside the first start, always.
    let lead = if let Some(x) = screened { points.insert(1, x); 2 } else { 1 };
    // A staged refinement is judged against the previous model (where the model is known to run).
    let previous = starts.staged.and(starts.runs_at.as_ref()).and_then(|r| problem.run(r).ok()).map(|run| sse(&problem.weighted_residuals(&run)));
    // A start that fails is pulled toward where the model runs and tried again.
    let fit_with = |x0: &[f64], lm: LmSettings| {
        staged_fit(&problem, x0, starts.staged, previous, lm).or_else(|e| match starts.runs_at.as_ref().and_then(|r| pulled_into_model(&problem, x0, r)) {
            Some(x) => staged_fit(&problem, &x, starts.staged, previous, lm),
            None => Err(e),
        })
    };
    let fit_from = |x0: &Vec<f64>| fit_with(x0, settings.lm);
    // The first start; when it fails, stops on its cap, ends on a bound or holds a parameter
    // (`converged` is false then), the second and the last as well; the rest only when those
    // do not end where the first did (a bound can be where the optimum lies: a candidate with
    // no effect in the recording ends on its no-effect bound from every start).
    let mut fits: Vec<Result<LeastSquaresFit, Error>> = points[..lead].par_iter().map(fit_from).collect();
    if lead == 2 && fits[1].as_ref().is_ok_and(|b| fits[0].as_ref().is_err() || fits[0].as_ref().is_ok_and(|a| b.sse < a.sse)) {
        fits.swap(0, 1);
    }
    let doubtful = match &fits[0] {
        Ok(f) => !f.converged || f.on_bound.iter().any(|b| *b),
        Err(_) => true,
    };
    if doubtful && points.len() > lead {
        let last = points.len() - 1;
        let probe: Vec<usize> = if last > lead { vec![lead, last] } else { vec![lead] };
        let probed: Vec<Result<LeastSquaresFit, Error>> = probe.par_iter().map(|&i| fit_from(&points[i])).collect();
        let agree = fits[0].as_ref().is_ok_and(|first| first.converged && probed.iter().all(|f| f.as_ref().is_ok_and(|f| same_optimum(first, f, settings.lm.sse_tolerance))));
        fits.extend(probed);
        if !agree && !settled(&fits, settings.lm.sse_tolerance) {
            // The rest are screened with a few iterations each and only the best is taken to
            // convergence, as pairs are: running every start to convergence made a refit whose
            // optimum lies on a bound (a one-electrode loss leaves the other electrode's
            // fraction on its no-loss bound) cost most of a long DFN diagnosis.
            let rest: Vec<usize> = (lead + 1..last).collect();
            let screen = LmSettings { max_iterations: SCREEN_ITERATIONS.min(settings.lm.max_iterations), ..settings.lm };
            let screened: Vec<Result<LeastSquaresFit, Error>> = rest.par_iter().map(|&i| fit_with(&points[i], screen)).collect();
            let screen_runs: usize = screened.iter().filter_map(|f| f.as_ref().ok()).map(|f| f.simulations).sum();
            if let Some(b) = screened.into_iter().filter_map(Result::ok).min_by(|a, b| a.sse.total_cmp(&b.sse)) {
                fits.push(levenberg_marquardt(&problem, &b.x, settings.lm).map(|mut f| {
                    f.simulations += screen_runs;
                    f
                }));
            }
        }
    }
    // Work of every start, not only the best one's.
    let simulations: usize = screen_runs + usize::from(previous.is_some()) + fits.iter().filter_map(|f| f.as_ref().ok()).map(|f| f.simulations).sum::<usize>();
    let mut best: Option<LeastSquaresFit> = None;
    let mut error = None;
    for f in fits {
        match f {
            Ok(f) if best.as_ref().is_none_or(|b| f.sse < b.sse) => best = Some(f),
            Ok(_) => {}
            Err(e) => error = Some(e),
        }
    }
    let fit = match (best, error) {
        (Some(f), _) => f,
        (None, Some(e)) => return Err(e),
        (None, None) => unreachable!("at least one start"),
    };
    let r: Vec<f64> = data.voltage.iter().zip(&fit.voltage).map(|(d, m)| m - d).collect();
    let all_points = indicator(r.len(), |i| split.holdout[i] || split.train[i] > 0.0);
    let temperature_rmse = match (&data.temperature, temperature_fitted) {
        (Some(recorded), true) => {
            let modelled = problem.simulate_outputs(&fit.x)?.temperature;
            let dt: Vec<f64> = modelled.iter().zip(recorded).map(|(m, d)| m - d).collect();
            Some(weighted_rms(&dt, &all_points))
        }
        _ => None,
    };
    let n = split.train_points() as f64;
    let sse: f64 = r.iter().zip(&split.train).map(|(r, w)| w * r * r).sum();
    let sigma2 = (sse / n).max(f64::MIN_POSITIVE);
    let informed_widths: Vec<f64> = problem
        .parameters
        .iter()
        .zip(&fit.informed)
        .filter(|(_, informed)| **informed)
        .map(|(p, _)| if p.log { (p.upper / p.lower).ln() } else { 1.0f64.ln() })
        .collect();
    let ln_prior_volume = informed_widths.iter().sum::<f64>() * fit.information_rank as f64 / informed_widths.len().max(1) as f64;
    Ok(FitOutcome {
        model: label,
        names: problem.parameters.iter().map(|p| p.path.clone()).collect(),
        values: fit.x.clone(),
        std_errors: fit.std_errors.clone(),
        on_bound: fit.on_bound.clone(),
        informed: fit.informed.clone(),
        parameters: k + structural,
        rmse_train: sigma2.sqrt(),
        rmse_holdout: weighted_rms(&r, &indicator(r.len(), |i| split.holdout[i])),
        rmse_all: weighted_rms(&r, &all_points),
        temperature_rmse,
        lag1: lag1(&r, &split.train),
        log_likelihood: -0.5 * n * ((2.0 * std::f64::consts::PI * sigma2).ln() + 1.0),
        ln_det_information: fit.ln_det_information,
        information_rank: fit.information_rank,
        ln_prior_volume,
        converged: fit.converged,
        simulations,
        seconds: start.elapsed().as_secs_f64(),
        voltage: fit.voltage,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::least_squares::tests::Line;

    #[test]
    fn blocks_hold_out_early_and_late_points() {
        let mut valid = vec![true; 80];
        valid[21] = false;
        let s = Split::blocks(&valid, 8, 4, 2);
        // Blocks of 10 points; blocks 2 and 6 are held out.
        assert!(s.holdout[20] && s.holdout[29] && s.holdout[60] && !s.holdout[19] && !s.holdout[30]);
        assert!(!s.holdout[21] && s.train[21] == 0.0);
        assert_eq!(s.holdout_points(), 19);
        assert_eq!(s.train_points(), 60);
    }

    #[test]
    fn a_rate_screened_a_decade_apart_escapes_the_local_minimum_at_its_start() {
        // A line of slope 2 fitted by a slope that peaks at 1.5 at k = 1 (a local minimum of
        // the cost) and reaches 2 at k = 1e3, with a valley between.
        let humped = |x: &[f64]| {
            let l = x[0].ln();
            1.5 * (-l * l).exp() + 2.0 * (-(l - 1e3f64.ln()).powi(2) / 2.0).exp()
        };
        let problem = Line::new(vec![FitParameter::log("k", 1.0, 1e-3, 1e6)], humped);
        let stalled = levenberg_marquardt(&problem, &[1.0], LmSettings::default()).unwrap();
        assert!((stalled.x[0] - 1.0).abs() < 0.1, "the start is a local minimum: {:?}", stalled.x);
        let (start, runs) = screen_grid(&problem, &[1.0], &[0]);
        assert_eq!(runs, 11, "the start and the ten decade points 1e-3 to 1e6");
        let start = start.expect("a decade beats the start");
        assert!((start[0] / 1e3 - 1.0).abs() < 1e-9, "{start:?}");
        let found = levenberg_marquardt(&problem, &start, LmSettings::default()).unwrap();
        // At the optimum only the data's ±0.01 noise is left: 50 x 1e-4.
        assert!((found.x[0] / 1e3 - 1.0).abs() < 1e-3 && (found.sse / 5e-3 - 1.0).abs() < 1e-3, "{:?} {}", found.x, found.sse);
    }

    fn fit(sse: f64, converged: bool, on_bound: bool) -> Result<LeastSquaresFit, Error> {
        Ok(LeastSquaresFit {
            x: vec![1.0],
            std_errors: vec![0.1],
            informed: vec![true],
            sse,
            points: 100,
            ln_det_information: 0.0,
            information_rank: 1,
            on_bound: vec![on_bound],
            converged,
            iterations: 10,
            simulations: 20,
            voltage: Vec::new(),
        })
    }

    #[test]
    fn a_lowest_interior_optimum_that_the_other_interior_starts_share_settles_the_fit() {
        let tol = 1e-8;
        // The first stopped on its cap; two probes agree on a lower interior optimum.
        assert!(settled(&[fit(2.0, false, false), fit(1.0, true, false), fit(1.0 + 1e-9, true, false)], tol));
        // A start on a bound with a higher error does not unsettle it.
        assert!(settled(&[fit(3.0, true, true), fit(1.0, true, false)], tol));
        // Two interior optima: the rest must run.
        assert!(!settled(&[fit(1.0, true, false), fit(1.5, true, false)], tol));
        // The lowest on a bound, or not converged: the rest must run.
        assert!(!settled(&[fit(0.5, true, true), fit(1.0, true, false)], tol));
        assert!(!settled(&[fit(0.5, false, false), fit(1.0, true, false)], tol));
        assert!(!settled(&[Err(Error::invalid("x", 0.0, "failed"))], tol));
    }
}
