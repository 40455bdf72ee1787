//! The diagnosis's solver tolerance follows the recording's noise (`diagnose::tolerance`):
//! its fits solve at the looser tolerance only where the set's replay at it stays within a
//! tenth of the noise of the replay at the tight one.

use std::path::Path;

use cellstudio::data::Recording;
use cellstudio::diagnose::FitSettings;
use cellstudio::diagnose::tolerance::{Chosen, LOOSE, TIGHT, choose};
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::problem::fitting::ModelSpec;

fn chosen(recording: &str, kind: ModelKind) -> Chosen {
    let rec = Recording::from_csv(&Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(recording)).unwrap();
    choose(&rec, &chen2020(), ModelSpec::new(kind, Submodels::default()), &FitSettings::default())
}

/// PyBaMM's DFN under 1C GITT pulses with 1 mV of noise (bench b1): the DFN's replay at 1e-5
/// lies 0.007 mV from the one at 1e-6.
#[test]
fn a_noisy_gitt_is_fitted_at_the_looser_tolerance() {
    let c = chosen("diagnosis-bench/b1_contact_gitt/recording.csv", ModelKind::Dfn);
    assert_eq!(c.tolerance, LOOSE, "{}", c.reason);
}

/// PyBaMM's noise-free DFN discharge at 1C: nothing to spare.
#[test]
fn a_noise_free_discharge_keeps_the_tight_tolerance() {
    let c = chosen("dfn_1C.csv", ModelKind::Dfn);
    assert_eq!(c.tolerance, TIGHT, "{}", c.reason);
}

/// Blind am5's 2 s drive with 1 mV of noise given to the SPM, whose replay at 1e-5 is
/// 0.44 mV off (a 1e-10 replay) where the DFN's is 0.06 mV: the SPM stays tight, the DFN
/// loosens.
#[test]
fn a_drive_loosens_the_dfn_but_not_the_spm() {
    let drive = "diagnosis-extra/am5_tortuosity_negative_bruggeman1p8_mini_excavator_trench_10C_2s_1mV_dfn/recording.csv";
    let spm = chosen(drive, ModelKind::Spm);
    assert_eq!(spm.tolerance, TIGHT, "{}", spm.reason);
    let dfn = chosen(drive, ModelKind::Dfn);
    assert_eq!(dfn.tolerance, LOOSE, "{}", dfn.reason);
}
