//! The solver tolerance of a diagnosis's fits, from the recording's noise.
//!
//! Every fit replays the recording hundreds of times; at rtol = atol = 1e-6 the solver's own
//! error is a hundred times below a cycler's noise of 1 mV, and a DFN drive replay takes
//! twice as long as at 1e-5 (blind am5, 2,968 samples: 522 ms at 1e-6, 0.027 mV from a 1e-10
//! replay; 1e-5: 0.063 mV). The looser tolerance is taken only where it is measured to be
//! harmless: the replay at [`LOOSE`] differs from the one at [`TIGHT`] by less than
//! [`SOLVER_ERROR_IN_NOISE`] of the recording's noise, so it adds at most 1 % to the noise's
//! variance. The SPM's replay of the same drive at 1e-5 is 0.44 mV off, and stays at 1e-6.

use super::features::Features;
use super::refit::FitSettings;
use crate::data::Recording;
use crate::params::ParameterSet;
use crate::problem::fitting::{FittingProblem, ModelSpec};
use crate::stats::{noise_from_dense_differences, rms};

/// Tolerance (rtol = atol) of fits to a recording without noise to spare.
pub const TIGHT: f64 = 1e-6;
/// Tolerance of fits to a recording whose noise dwarfs the solver's error at it.
pub const LOOSE: f64 = 1e-5;
/// Largest solver error, as a share of the recording's noise, at which [`LOOSE`] is used.
pub const SOLVER_ERROR_IN_NOISE: f64 = 0.1;

/// The chosen tolerance and why, in words for the report.
pub struct Chosen {
    pub tolerance: f64,
    pub reason: String,
}

/// The fits' tolerance for `data` on the model `spec` with the set `base`: [`LOOSE`] when
/// the set's replay at it lies within [`SOLVER_ERROR_IN_NOISE`] times the recording's noise
/// (the dense first differences of its residual from the set's replay) of the replay at
/// [`TIGHT`], else [`TIGHT`] (also when either replay fails).
pub fn choose(data: &Recording, base: &ParameterSet, spec: ModelSpec, settings: &FitSettings) -> Chosen {
    let tight = |why: String| Chosen { tolerance: TIGHT, reason: why };
    let replays = || -> Option<(Vec<f64>, Vec<f64>)> {
        let mut problem = FittingProblem::new(spec, base.clone(), Vec::new(), data.clone()).ok()?;
        if settings.start_at_rest {
            problem = problem.starting_at_rest().ok()?;
        }
        let mut replay = |tol: f64| {
            problem.solver.set_tolerance(tol);
            problem.simulate(&[]).ok()
        };
        Some((replay(TIGHT)?, replay(LOOSE)?))
    };
    let Some((fine, coarse)) = replays() else {
        return tight("the set's replay did not run at both tolerances".into());
    };
    // The noise of the set's residual over the usable points, as the diagnosis reads it from
    // the user's: the recording's own first differences would count a sloping voltage as
    // noise, and the points at current steps their jumps (blind ap7, sampled only at the ends
    // of 10-25 s steps: 185 mV against its 1 mV).
    let f = Features::of(data);
    let residual: Vec<f64> = data.voltage.iter().zip(&fine).map(|(v, m)| v - m).collect();
    let noise = noise_from_dense_differences(&f.usable(&residual), &f.usable(&data.time));
    let diff: Vec<f64> = fine.iter().zip(&coarse).map(|(a, b)| a - b).collect();
    let error = rms(&diff);
    let words = format!("the replay at {LOOSE:.0e} is {:.4} mV from the one at {TIGHT:.0e}, against a noise of {:.3} mV", error * 1e3, noise * 1e3);
    if error.is_finite() && noise.is_finite() && error < SOLVER_ERROR_IN_NOISE * noise {
        Chosen { tolerance: LOOSE, reason: words }
    } else {
        tight(words)
    }
}
