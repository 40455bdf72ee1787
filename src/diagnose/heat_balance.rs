//! A recorded temperature predicted or only read: the self-heating candidate's heat balance
//! predicts the cell's temperature from its losses, the recorded-temperature candidate reads
//! it. Both fit the voltage alike when the heat balance is right, and the one that reads it,
//! with no fitted parameters, would win on counts alone; it names an effect beyond self-heating
//! (an ambient that changed, heating or cooling from outside) only when no heat balance
//! reproduces the recorded temperature.

use super::{Candidate, CandidateOutcome, FitOutcome};
use crate::data::Recording;
use crate::stats::noise::temperature_noise;

/// How many times its noise a heat balance's temperature residual may be and still predict the
/// recorded temperature (as a voltage residual within twice the noise is no structure).
const PREDICTED_WITHIN_NOISE: f64 = 2.0;

/// Takes the recorded-temperature candidate out of the naming (and of pairs and later rounds)
/// when a heat balance, the self-heating candidate's or the user's thermal model `baseline`,
/// reproduces the recorded temperature of `data` within [`PREDICTED_WITHIN_NOISE`] times its
/// noise; says so in its note.
pub(super) fn read_only_if_unpredicted(outcomes: &mut [CandidateOutcome], baseline: &FitOutcome, data: &Recording) {
    let Some(recorded) = &data.temperature else { return };
    let noise = temperature_noise(recorded, &data.time);
    let self_heating = outcomes.iter().find(|c| c.candidate == Candidate::Thermal).and_then(|c| c.fit.as_ref()).and_then(|f| f.temperature_rmse);
    let Some(best) = [self_heating, baseline.temperature_rmse].into_iter().flatten().min_by(f64::total_cmp) else { return };
    if best > PREDICTED_WITHIN_NOISE * noise {
        return;
    }
    for c in outcomes.iter_mut().filter(|c| c.candidate == Candidate::RecordedTemperature && c.fit.is_some()) {
        c.named = false;
        c.next = None;
        c.note = Some(format!("not named: a heat balance predicts the recorded temperature ({best:.3} K RMS, noise {noise:.3} K), so reading it adds no effect beyond self-heating"));
    }
}
