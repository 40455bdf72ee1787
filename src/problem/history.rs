//! A load before the recording: a recording exported from part-way through a test begins
//! with the cell still relaxing from the step before it (gradients in the particles and the
//! electrolyte), which a model started at rest lacks whatever its state of charge. The fitted
//! history is a constant current held for a time just before the first recorded point, from
//! the rest state the other fitted values give; the recording's replay starts where it ends.

use super::fitting::FitParameter;
use crate::error::Error;
use crate::models::Model;
use crate::protocol::{Protocol, Step};
use crate::simulation::{SimOptions, States, simulate};
use crate::solver::Workspace;

/// Fit path of the history's current (A, discharge positive): not a field of the parameter set.
pub const HISTORY_CURRENT: &str = "history.current";

/// Fit path of the history's duration (s).
pub const HISTORY_DURATION: &str = "history.duration";

/// Whether `path` is one of the history's fit paths.
pub fn is_history(path: &str) -> bool {
    path == HISTORY_CURRENT || path == HISTORY_DURATION
}

/// The history at the fitted `values` of `parameters` (and of the `pinned` ones): a constant
/// current step, or `None` when neither its current nor its duration is fitted. One without
/// the other is an error naming the missing path.
pub fn history_step(parameters: &[FitParameter], values: &[f64], pinned: &[(FitParameter, f64)]) -> Result<Option<Step>, Error> {
    let find = |path: &str| {
        parameters.iter().zip(values).map(|(p, v)| (p, *v)).chain(pinned.iter().map(|(p, v)| (p, *v))).find(|(p, _)| p.path == path).map(|(_, v)| v)
    };
    match (find(HISTORY_CURRENT), find(HISTORY_DURATION)) {
        (None, None) => Ok(None),
        (Some(current), Some(duration)) if duration > 0.0 => Ok(Some(Step::Current { current, duration, until_voltage: None })),
        (Some(_), Some(duration)) => Err(Error::invalid(HISTORY_DURATION, duration, "must be positive")),
        (Some(_), None) => Err(Error::InvalidSetting { field: HISTORY_DURATION.into(), reason: format!("must be fitted beside {HISTORY_CURRENT}") }),
        (None, Some(_)) => Err(Error::InvalidSetting { field: HISTORY_CURRENT.into(), reason: format!("must be fitted beside {HISTORY_DURATION}") }),
    }
}

/// The state of `model` (from its own initial state) at the end of `step`, run as the replay
/// runs (`opts`, its output times dropped).
pub fn state_after(model: &dyn Model, ws: &mut Workspace, step: &Step, opts: &SimOptions) -> Result<Vec<f64>, Error> {
    let opts = SimOptions { t_eval: None, states: States::ForOutputs, ..opts.clone() };
    Ok(simulate(model, ws, &Protocol { steps: vec![step.clone()] }, &opts, None)?.final_state)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn param(path: &str) -> FitParameter {
        FitParameter::linear(path, 1.0, 0.0, 10.0)
    }

    #[test]
    fn a_history_needs_its_current_and_its_duration() {
        assert_eq!(history_step(&[param("cell.contact_resistance")], &[1.0], &[]).unwrap(), None);
        let both = [param(HISTORY_CURRENT), param(HISTORY_DURATION)];
        assert_eq!(history_step(&both, &[2.5, 60.0], &[]).unwrap(), Some(Step::Current { current: 2.5, duration: 60.0, until_voltage: None }));
        // A held (pinned) duration counts as given.
        assert!(history_step(&both[..1], &[2.5], &[(param(HISTORY_DURATION), 30.0)]).unwrap().is_some());
        let e = history_step(&both[..1], &[2.5], &[]).unwrap_err().to_string();
        assert!(e.contains(HISTORY_DURATION), "{e}");
        let e = history_step(&both, &[2.5, 0.0], &[]).unwrap_err().to_string();
        assert!(e.contains(HISTORY_DURATION) && e.contains("positive"), "{e}");
    }
}
