//! GITT: the particle diffusivity of one electrode fitted to each pulse and its relaxation
//! separately, each from the rest state at the voltage recorded before the pulse, so that the
//! diffusivity comes out against the electrode's stoichiometry; beside it the Weppner-Huggins
//! estimate. The fits are bounded Levenberg-Marquardt on plain simulations
//! ([`super::least_squares`]): the forward-sensitivity system of a DFN through a pulse's
//! current steps may fail to integrate where the plain model runs. Where the fitted
//! electrode's OCP is flat (graphite's plateaus) the voltage hardly depends on its
//! diffusivity and the cost has local minima, so each fit starts from the best of a scan of
//! [`SCAN_POINTS`] values over the search range (and the given start).

use rayon::prelude::*;
use serde::Serialize;

use super::fitting::{FitParameter, FittingProblem, ModelSpec};
use super::least_squares::{LmSettings, levenberg_marquardt};
use crate::data::{Pulse, Recording};
use crate::error::Error;
use crate::params::ParameterSet;

/// Values of the scan that picks each fit's start, spread evenly over the search range (on a
/// log scale for a log parameter): about two per decade over the usual 1e-16 to 1e-11 m^2/s.
pub const SCAN_POINTS: usize = 11;

/// The scan's value (of [`SCAN_POINTS`]) with the lowest SSE, or `parameter.initial` if
/// lower; a value whose simulation fails is skipped.
fn scanned_start(problem: &FittingProblem, parameter: &FitParameter) -> f64 {
    let (lo, hi) = (parameter.lower, parameter.upper);
    let at = |k: usize| {
        let f = k as f64 / (SCAN_POINTS - 1) as f64;
        if parameter.log { (lo.ln() + f * (hi.ln() - lo.ln())).exp() } else { lo + f * (hi - lo) }
    };
    let sse = |v: f64| problem.simulate(&[v]).map(|u| problem.residuals(&u).iter().zip(&problem.weights).map(|(r, w)| w * r * r).sum::<f64>()).unwrap_or(f64::INFINITY);
    std::iter::once(parameter.initial).chain((0..SCAN_POINTS).map(at)).map(|v| (sse(v), v)).min_by(|a, b| a.0.total_cmp(&b.0)).map_or(parameter.initial, |(_, v)| v)
}

/// One pulse's diffusivity.
#[derive(Clone, Debug, Serialize)]
pub struct PulseDiffusivity {
    /// Step number of the pulse in its recording.
    pub step: usize,
    /// Charge discharged before the pulse (A h), mean current (A), duration (s).
    pub discharged_before: f64,
    pub current: f64,
    pub duration: f64,
    /// Stoichiometries (-) of the negative and positive electrode at the pulse's midpoint, on
    /// the set's lithium line from the rested voltage before it.
    pub negative_stoichiometry: f64,
    pub positive_stoichiometry: f64,
    /// Slope of the fitted electrode's OCP at its midpoint stoichiometry (V per unit
    /// stoichiometry): where it is near zero the voltage hardly depends on the diffusivity.
    pub ocp_slope: f64,
    /// Weppner-Huggins estimate (m^2/s) with the fitted electrode's particle radius.
    pub weppner_huggins: Option<f64>,
    /// Fitted diffusivity (m^2/s), its standard error (m^2/s), and the fit's RMSE (V); NaN
    /// when the fit failed.
    pub fitted: f64,
    pub std_error: f64,
    pub rmse: f64,
    /// Whether the fit converged (`None` when it failed).
    pub converged: Option<bool>,
    /// Why the fit failed (e.g. the model could not run the pulse from the starting value).
    pub failure: Option<String>,
}

/// Fits `parameter` (a `negative.` or `positive.diffusivity`) to every pulse of `rec` in
/// parallel, the model `spec` on `base`. A pulse whose fit fails is reported with its
/// failure; a pulse the model cannot start from is an error.
pub fn fit_pulses(spec: ModelSpec, base: &ParameterSet, rec: &Recording, pulses: &[Pulse], parameter: &FitParameter) -> Result<Vec<PulseDiffusivity>, Error> {
    let (electrode, negative) = match parameter.path.split('.').next() {
        Some("negative") => (&base.negative, true),
        Some("positive") => (&base.positive, false),
        _ => return Err(Error::InvalidSetting { field: "gitt.parameter.path".into(), reason: format!("`{}` is not a negative or positive electrode parameter", parameter.path) }),
    };
    let (radius, ocp) = (electrode.particle_radius, &electrode.ocp);
    let (q_n, q_p) = super::balancing::electrode_capacities(base);
    pulses
        .par_iter()
        .map(|pulse| {
            let problem = FittingProblem::new(spec, base.clone(), vec![parameter.clone()], pulse.window(rec))?.starting_at_rest()?;
            let start = problem.parameters_at(&problem.initial())?;
            let half = 0.5 * pulse.current * pulse.duration / 3600.0;
            let x = start.negative.initial_concentration / start.negative.max_concentration - half / q_n;
            let y = start.positive.initial_concentration / start.positive.max_concentration + half / q_p;
            let r = levenberg_marquardt(&problem, &[scanned_start(&problem, parameter)], LmSettings::default());
            let (fitted, std_error, rmse) = r.as_ref().map_or((f64::NAN, f64::NAN, f64::NAN), |r| (r.x[0], r.std_errors[0], (r.sse / r.points.max(1) as f64).sqrt()));
            Ok(PulseDiffusivity {
                step: pulse.step,
                discharged_before: pulse.discharged_before,
                current: pulse.current,
                duration: pulse.duration,
                negative_stoichiometry: x,
                positive_stoichiometry: y,
                ocp_slope: super::balancing::ocp_slope(ocp, if negative { x } else { y }),
                weppner_huggins: pulse.weppner_huggins(radius),
                fitted,
                std_error,
                rmse,
                converged: r.as_ref().ok().map(|r| r.converged),
                failure: r.err().map(|e| e.to_string()),
            })
        })
        .collect()
}
