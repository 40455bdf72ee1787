//! What a model leaves at rest against what it leaves under load. A dynamic effect (one that
//! relaxes when the current stops: resistance, kinetics, transport, particle size, heat)
//! cannot explain a model that stays as far off at rest as under load: that is the cell's
//! open-circuit voltage (its electrodes' OCP curves or their balance), and a dynamic candidate
//! fitted to such a recording is bent to stand in for it. Nor can a leak, which is told by
//! what it does in the rests.

use super::{Candidate, FitOutcome, Round};
use crate::data::Recording;

/// Share of the RMS residual under load that the RMS residual at rest must reach for a
/// mismatch to be the open-circuit voltage's (a dynamic effect relaxes at rest) ...
pub const OCV_AT_REST: f64 = 0.5;
/// ... and how many times the noise level it must exceed (-).
pub const OCV_NOISE_MULTIPLE: f64 = 10.0;

/// RMS of `residual` (V) at rest and under load, over the points of `rec` that are not
/// repeated samples; 0 where there are none.
pub fn rest_and_load_rms(rec: &Recording, residual: &[f64]) -> (f64, f64) {
    let (mut sums, mut counts) = ([0.0; 2], [0usize; 2]);
    for (k, r) in residual.iter().enumerate().filter(|(k, _)| !rec.is_repeated(*k)) {
        let g = usize::from(rec.current[k] != 0.0);
        sums[g] += r * r;
        counts[g] += 1;
    }
    let rms = |g: usize| if counts[g] == 0 { 0.0 } else { (sums[g] / counts[g] as f64).sqrt() };
    (rms(0), rms(1))
}

/// Whether a residual with `rest` and `load` RMS (V) at noise level `noise` (V) is off at rest
/// as much as under load: the open-circuit voltage differs.
pub fn off_at_rest(rest: f64, load: f64, noise: f64) -> bool {
    rest >= OCV_AT_REST * load && rest > OCV_NOISE_MULTIPLE * noise
}

/// Why a fit of `members` is not named: one of them relaxes at rest, or is told by the rests
/// (a leak), yet the fit leaves the model off at rest as much as under load, so that one is
/// bent to stand in for the OCV (a partner that moves the relaxed voltage and leaves it off
/// has not fitted the OCV either). `None` when none is either, or the fit leaves no such
/// mismatch.
pub(super) fn stands_in_for_the_ocv(members: &[Candidate], fit: &FitOutcome, round: &Round) -> Option<String> {
    let relaxes = members.iter().any(|c| c.relaxes_at_rest());
    if !relaxes && !members.iter().any(|c| c.told_by_rests()) {
        return None;
    }
    let residual: Vec<f64> = round.data.voltage.iter().zip(&fit.voltage).map(|(d, m)| m - d).collect();
    let (rest, load) = rest_and_load_rms(round.data, &residual);
    let why = if relaxes { "a dynamic effect relaxes at rest" } else { "a leak shows itself in the rests" };
    off_at_rest(rest, load, round.noise).then(|| {
        format!(
            "with it the model is still off by {:.2} mV RMS at rest ({:.2} mV under load): {why}, so that is the cell's open-circuit voltage, which the effect fitted here stands in for; fit the OCV first",
            1e3 * rest,
            1e3 * load
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_residual_off_at_rest_as_under_load_points_to_the_ocv_and_one_that_relaxes_does_not() {
        let rec = Recording { time: vec![0.0, 1.0, 2.0, 3.0], current: vec![1.0, 1.0, 0.0, 0.0], voltage: vec![4.0; 4], temperature: None };
        let (rest, load) = rest_and_load_rms(&rec, &[0.03, 0.04, 0.0, 0.0]);
        assert_eq!(rest, 0.0);
        assert!((load - ((0.03f64.powi(2) + 0.04f64.powi(2)) / 2.0).sqrt()).abs() < 1e-15);
        assert!(!off_at_rest(rest, load, 1e-4));
        let (rest, load) = rest_and_load_rms(&rec, &[0.01, 0.01, 0.01, 0.01]);
        assert!(off_at_rest(rest, load, 1e-4));
        assert!(!off_at_rest(rest, load, 2e-3), "within ten times the noise");
    }
}
