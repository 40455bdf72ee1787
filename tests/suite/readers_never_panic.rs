//! Property tests of the readers a user feeds (issue 12): arbitrary or mutated recordings,
//! study files and BPX documents never panic, and every refusal says where (a line, a
//! column or a key).

use cellstudio::data::Recording;
use cellstudio::params::bpx::from_bpx_json;
use cellstudio::study::Study;
use proptest::prelude::*;

const REPO: &str = env!("CARGO_MANIFEST_DIR");

/// Cell values a cycler export or a hand edit could hold.
fn cell() -> impl Strategy<Value = String> {
    prop_oneof![
        (-10.0f64..10.0).prop_map(|v| format!("{v}")),
        (0.0f64..1e5).prop_map(|v| format!("{v:.3}")),
        Just(String::new()),
        Just("nan".into()),
        Just("inf".into()),
        Just("-0".into()),
        Just("1e400".into()),
        Just("3,7".into()),
        Just("\"4.1\"".into()),
        "[a-zA-Z_ .;:-]{0,8}",
    ]
}

/// A CSV with a header of 0-5 columns (usually the expected ones) and 0-30 rows of
/// 0-6 cells.
fn csv_text() -> impl Strategy<Value = String> {
    let header = prop_oneof![
        Just("time_s,current_A,voltage_V".to_string()),
        Just("time_s,current_A,voltage_V,temperature_K".to_string()),
        Just("time_s;current_A;voltage_V".to_string()),
        "[a-z_,]{0,30}",
    ];
    (header, prop::collection::vec(prop::collection::vec(cell(), 0..6), 0..30)).prop_map(|(h, rows)| {
        let mut text = h;
        for r in rows {
            text.push('\n');
            text.push_str(&r.join(","));
        }
        text
    })
}

/// Says where: a line, a column, a key or the file as a whole (empty, too short).
fn names_a_place(message: &str) -> bool {
    ["line", "column", "header", "`", "points", "empty", "time", "record"].iter().any(|w| message.contains(w))
}


/// `text` with the byte range `at..at+len` (clamped to char boundaries) replaced by `with`.
fn splice(text: &str, at: usize, len: usize, with: &str) -> String {
    let mut a = at.min(text.len());
    while !text.is_char_boundary(a) {
        a -= 1;
    }
    let mut b = (a + len).min(text.len());
    while !text.is_char_boundary(b) {
        b += 1;
    }
    format!("{}{}{}", &text[..a], with, &text[b..])
}

fn replacement() -> impl Strategy<Value = String> {
    prop_oneof![cell(), Just("-1".into()), Just("1e308".into()), Just("[]".into()), Just("{".into()), Just("\n[x]\n".into())]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn recordings_never_panic_and_refusals_say_where(text in csv_text()) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("recording.csv");
        std::fs::write(&path, &text).unwrap();
        if let Err(e) = Recording::from_csv(&path) {
            let message = e.to_string();
            prop_assert!(names_a_place(&message), "{message}\n--- input ---\n{text}");
        }
    }

    #[test]
    fn study_files_never_panic_and_refusals_say_where(at in 0usize..1200, len in 0usize..12, with in replacement()) {
        let seed = std::fs::read_to_string(format!("{REPO}/designs/gravimetric_chen2020.toml")).unwrap();
        let text = splice(&seed, at, len, &with);
        if let Err(e) = Study::from_toml(&text, "mutated.toml") {
            let message = e.to_string();
            prop_assert!(names_a_place(&message), "{message}\n--- input ---\n{text}");
        }
    }

    #[test]
    fn bpx_documents_never_panic_and_refusals_say_where(at in 0usize..20000, len in 0usize..16, with in replacement()) {
        let seed = std::fs::read_to_string(format!("{REPO}/tests/data/bpx_example.json")).unwrap();
        let text = splice(&seed, at, len, &with);
        if let Err(e) = from_bpx_json(&text) {
            let message = e.to_string();
            prop_assert!(names_a_place(&message), "{message}");
        }
    }
}
