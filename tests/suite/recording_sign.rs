//! The recording check that catches a charge-positive current: silent on every PyBaMM-made
//! recording in `tests/data/` (bench and extra cases: discharges, charges, CC-CV, pulses,
//! GITT, drive cycles with regeneration), and a unit error on each of them with the current's
//! sign flipped.

use std::path::Path;

use cellstudio::data::Recording;

#[test]
fn sign_check_is_silent_on_every_case_and_catches_each_flipped() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut cases = 0;
    for folder in ["diagnosis-bench", "diagnosis-extra"] {
        for entry in std::fs::read_dir(root.join(folder)).unwrap() {
            let file = entry.unwrap().path().join("recording.csv");
            let Ok(mut rec) = Recording::from_csv(&file) else { continue };
            assert_eq!(rec.sign_finding(), None, "{}", file.display());
            rec.current.iter_mut().for_each(|i| *i = -*i);
            let f = rec.sign_finding().unwrap_or_else(|| panic!("flipped {} not caught", file.display()));
            assert!(f.unit_error && f.message.contains("charge-positive"), "{}: {f:?}", file.display());
            cases += 1;
        }
    }
    assert!(cases >= 50, "only {cases} recordings read");
}
