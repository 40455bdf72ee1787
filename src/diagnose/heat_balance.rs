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
/// recorded temperature (as a voltage residual within twice the noise is no structure); a
/// recorded temperature that stays this close to its first value is where the model already runs.
pub(super) const PREDICTED_WITHIN_NOISE: f64 = 2.0;

/// Takes every outcome that reads the recorded temperature (alone or in a pair) out of the
/// naming, and out of pairs and later rounds, when a heat balance reproduces the recorded
/// temperature of `data` within [`PREDICTED_WITHIN_NOISE`] times its noise: the fit of an
/// outcome in `outcomes` or `others` with the self-heating or heat-balance candidate (alone or
/// in a pair), or the user's thermal model `baseline`. Says so in their notes.
pub(super) fn read_only_if_unpredicted(outcomes: &mut [CandidateOutcome], others: &[CandidateOutcome], baseline: &FitOutcome, data: &Recording) {
    let Some(recorded) = &data.temperature else { return };
    let noise = temperature_noise(recorded, &data.time);
    let heats = |c: &&CandidateOutcome| involves(c, Candidate::Thermal) || involves(c, Candidate::HeatBalance);
    let balances = outcomes.iter().chain(others).filter(heats).filter_map(|c| c.fit.as_ref());
    let Some(best) = balances.chain([baseline]).filter_map(|f| f.temperature_rmse).min_by(f64::total_cmp) else { return };
    if best > PREDICTED_WITHIN_NOISE * noise {
        return;
    }
    for c in outcomes.iter_mut().filter(|c| involves(c, Candidate::RecordedTemperature) && c.fit.is_some()) {
        c.named = false;
        c.next = None;
        c.note = Some(format!("not named: a heat balance predicts the recorded temperature ({best:.3} K RMS, noise {noise:.3} K), so reading it adds no effect beyond self-heating"));
    }
}

/// Whether outcome `c` holds candidate `which`, alone or in a pair.
fn involves(c: &CandidateOutcome, which: Candidate) -> bool {
    c.candidate == which || c.partner == Some(which)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::candidates::Class;
    use crate::diagnose::select::Comparison;

    /// A named candidate whose fit leaves `temperature_rmse` (K) on the recorded temperature.
    fn outcome(candidate: Candidate, temperature_rmse: Option<f64>) -> CandidateOutcome {
        CandidateOutcome {
            candidate,
            partner: None,
            name: candidate.name().into(),
            class: Class::MissingPhysics,
            signature: String::new(),
            plausible_range: String::new(),
            change: String::new(),
            fit: Some(FitOutcome { temperature_rmse, ..FitOutcome::default() }),
            note: None,
            comparison: Comparison::default(),
            clears_margins: true,
            implausible: None,
            named: true,
            next: None,
        }
    }

    /// A temperature recorded every 10 s rising from 298 to 308 K, within its 0.1 K resolution
    /// (its noise is credited at the resolution: 0.2 K is twice it).
    fn warming() -> Recording {
        let time: Vec<f64> = (0..200).map(|k| 10.0 * k as f64).collect();
        let temperature = Some(time.iter().map(|t| 298.0 + t / 200.0).collect());
        Recording { current: vec![1.0; time.len()], voltage: vec![3.7; time.len()], time, temperature }
    }

    fn read(outcomes: &[CandidateOutcome]) -> &CandidateOutcome {
        outcomes.iter().find(|c| c.candidate == Candidate::RecordedTemperature).unwrap()
    }

    #[test]
    fn a_read_temperature_is_named_only_where_no_heat_balance_predicts_it() {
        let isothermal = FitOutcome::default();
        // Self-heating reproduces the temperature within twice its noise: reading it names nothing.
        let mut predicted = vec![outcome(Candidate::Thermal, Some(0.15)), outcome(Candidate::RecordedTemperature, None)];
        read_only_if_unpredicted(&mut predicted, &[], &isothermal, &warming());
        let r = read(&predicted);
        assert!(!r.named && r.note.as_deref().is_some_and(|n| n.contains("0.150 K RMS, noise 0.100 K")), "{:?}", r.note);
        // It misses by more (an ambient that changed): the read temperature stays named.
        let mut missed = vec![outcome(Candidate::Thermal, Some(0.25)), outcome(Candidate::RecordedTemperature, None)];
        read_only_if_unpredicted(&mut missed, &[], &isothermal, &warming());
        assert!(read(&missed).named && read(&missed).note.is_none());
        // A thermal user model's own heat balance counts as well.
        let thermal_user = FitOutcome { temperature_rmse: Some(0.1), ..FitOutcome::default() };
        let mut alone = vec![outcome(Candidate::RecordedTemperature, None)];
        read_only_if_unpredicted(&mut alone, &[], &thermal_user, &warming());
        assert!(!read(&alone).named);
        // A pair that reads the temperature beside a resistance gives way where the
        // resistance paired with self-heating predicts it (the resistance's heat was missing
        // from self-heating alone).
        let paired = |c: Candidate, rmse: Option<f64>| CandidateOutcome { partner: Some(Candidate::SeriesResistance), ..outcome(c, rmse) };
        let singles = vec![outcome(Candidate::Thermal, Some(0.33))];
        let mut pairs = vec![paired(Candidate::Thermal, Some(0.06)), paired(Candidate::RecordedTemperature, None)];
        read_only_if_unpredicted(&mut pairs, &singles, &isothermal, &warming());
        assert!(pairs[0].named && !pairs[1].named, "{:?}", pairs[1].note);
    }
}
