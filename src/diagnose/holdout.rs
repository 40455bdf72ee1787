//! Which blocks of the recording are held out. The default blocks are fixed in advance; when
//! they happen to miss where the user's model fails (a misfit confined to one stretch of the
//! recording, such as a charge at its end, that falls in training blocks only), nothing could
//! ever be confirmed on them, and the diagnosis would call a clear misfit noise. Another phase
//! of the same pattern is then held out, the one whose held-out misfit is most like the
//! whole recording's.

use super::{DiagnoseOptions, Split};
use crate::stats::weighted_rms;

/// The blocks held out of `blocks`, every `every`-th from `phase` (1-based numbers, for a
/// reader), e.g. "3 and 7".
pub(super) fn blocks_in_words(blocks: usize, every: usize, phase: usize) -> String {
    let every = every.max(2);
    let numbers: Vec<String> = (0..blocks).filter(|b| b % every == phase % every).map(|b| (b + 1).to_string()).collect();
    match numbers.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => numbers.join(""),
    }
}

/// When the default held-out blocks leave less than `floor` (V) of the user's model's misfit
/// above the `noise` (V) but the whole recording leaves at least `floor`, the phase (and a
/// note saying why) whose held-out root-mean-square `residual` (V) is closest, in ratio, to the
/// whole recording's among those that leave at least `floor`; otherwise `None`.
pub(super) fn representative_phase(options: &DiagnoseOptions, valid: &[bool], residual: &[f64], noise: f64, floor: f64) -> Option<(usize, String)> {
    let every = options.holdout_every.max(2);
    let default = options.phase();
    let held_rms = |phase: usize| {
        let w: Vec<f64> = Split::blocks(valid, options.blocks, every, phase).holdout.iter().map(|h| f64::from(u8::from(*h))).collect();
        weighted_rms(residual, &w)
    };
    let excess = |rms: f64| (rms * rms - noise * noise).max(0.0).sqrt();
    let all = weighted_rms(residual, &valid.iter().map(|v| f64::from(u8::from(*v))).collect::<Vec<_>>());
    let at_default = held_rms(default);
    if excess(at_default) >= floor || excess(all) < floor || all <= 0.0 {
        return None;
    }
    let (phase, rms) = (0..every)
        .filter(|&p| p != default)
        .map(|p| (p, held_rms(p)))
        .filter(|(_, rms)| excess(*rms) >= floor)
        .min_by(|a, b| (a.1 / all).ln().abs().total_cmp(&(b.1 / all).ln().abs()))?;
    Some((
        phase,
        format!(
            "The default held-out blocks ({} of {}) hold {:.2} mV RMS of the user's model's misfit (noise {:.2} mV), too little above the noise to confirm any effect on, against {:.2} mV over the whole recording: they miss where the model fails, so blocks {} are held out instead ({:.2} mV).",
            blocks_in_words(options.blocks, every, default),
            options.blocks,
            at_default * 1e3,
            noise * 1e3,
            all * 1e3,
            blocks_in_words(options.blocks, every, phase),
            rms * 1e3
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::{ModelKind, Submodels};
    use crate::problem::fitting::ModelSpec;

    /// 800 points in 8 blocks of 100, alternating ±1 mV of noise, and 5 mV of misfit on `misfit`.
    fn residual(misfit: impl Fn(usize) -> bool) -> Vec<f64> {
        (0..800).map(|k| if k % 2 == 0 { 1e-3 } else { -1e-3 } + if misfit(k / 100) { 5e-3 } else { 0.0 }).collect()
    }

    #[test]
    fn a_misfit_in_training_blocks_only_moves_the_held_out_blocks_onto_it() {
        let options = DiagnoseOptions::new(ModelSpec::new(ModelKind::Spm, Submodels::default()));
        let valid = vec![true; 800];
        // The default holds out blocks 3 and 7; the misfit lies in block 8 only.
        let (phase, why) = representative_phase(&options, &valid, &residual(|b| b == 7), 1e-3, 1e-3).expect("moved");
        assert_eq!(phase, 3, "{why}");
        assert!(why.contains("blocks 4 and 8"), "{why}");
        assert_eq!(blocks_in_words(8, 4, options.phase()), "3 and 7");
    }

    #[test]
    fn a_misfit_the_default_blocks_see_or_no_misfit_keeps_them() {
        let options = DiagnoseOptions::new(ModelSpec::new(ModelKind::Spm, Submodels::default()));
        let valid = vec![true; 800];
        assert!(representative_phase(&options, &valid, &residual(|_| true), 1e-3, 1e-3).is_none());
        assert!(representative_phase(&options, &valid, &residual(|b| b == 6), 1e-3, 1e-3).is_none());
        assert!(representative_phase(&options, &valid, &residual(|_| false), 1e-3, 1e-3).is_none());
    }
}
