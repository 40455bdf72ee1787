//! Arbitrary text given to the cycler readers returns a recording or an error, never a panic.

use cellstudio::data::cycler::{read_str, steps};
use proptest::prelude::*;

/// Headers of every vendor, so that generated rows reach the row readers.
const HEADERS: [&str; 8] = [
    "time_s,current_A,voltage_V,temperature_K",
    "~Time[s]\tLine\tU[V]\tI[A]\tT1[°C]",
    "Step,Status,Step Time,Prog Time,Voltage,Current,LogTempMid,\n[],[],[ss.xxx],[ss.xxx],[V],[A],[T1],",
    "time/s\tEcell/V\tI/mA\tNs\tTemperature/°C",
    "Rec,Step,Test Time (sec),Current,Voltage,Temp 1",
    "Rec#\tStep\tTest (Sec)\tAmps\tVolts\tState",
    "Record ID,Total Time,Step Index,Current(mA),Voltage(V),T1(℃)",
    "Data Point,Test Time (s),Step Index,Current (A),Voltage (V)",
];

fn check(text: &str) {
    if let Ok(d) = read_str("generated", text) {
        let st = steps(&d.recording, d.step.as_deref());
        assert!(!st.is_empty());
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn any_text(text in "\\PC{0,400}") {
        check(&text);
    }

    #[test]
    fn any_rows_under_a_real_header(h in 0..HEADERS.len(), rows in prop::collection::vec("[-0-9.:eE,\\t DCR]{0,40}", 0..20)) {
        check(&format!("{}\n{}", HEADERS[h], rows.join("\n")));
    }

    #[test]
    fn numeric_rows_under_a_real_header(
        h in 0..HEADERS.len(),
        rows in prop::collection::vec(prop::collection::vec(-1e4f64..1e4, 6), 0..30),
    ) {
        let d = if HEADERS[h].contains('\t') { "\t" } else { "," };
        let body: Vec<String> = rows.iter().map(|r| r.iter().map(|v| v.to_string()).collect::<Vec<_>>().join(d)).collect();
        check(&format!("{}\n{}", HEADERS[h], body.join("\n")));
    }
}
