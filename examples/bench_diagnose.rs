//! Wall time of the whole diagnosis (every round, every candidate refit) on the independent
//! bench's recordings, 1 s sampled, made by PyBaMM: `cargo run --release --example
//! bench_diagnose [repeats]` prints a Markdown table with the time per hour of recording.
//! The DFN cases are the target: one hour of 1 s DFN data in at most 60 s.

use std::path::Path;
use std::time::Instant;

use cellstudio::data::Recording;
use cellstudio::diagnose::{DiagnoseOptions, diagnose_rounds, report};
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::problem::fitting::ModelSpec;

fn main() {
    let repeats: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(1);
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/diagnosis-bench");
    let cases = [
        ("b1_contact_gitt", ModelKind::Dfn),
        ("b4_selfheating_2C", ModelKind::Dfn),
        ("b6_lam_positive", ModelKind::Dfn),
        ("b2_electrolyte_2C", ModelKind::Spm),
        ("b3_inventory_C2", ModelKind::Spme),
        ("b5_kinetics_pulses", ModelKind::Spme),
        ("b7_control_drive", ModelKind::Spme),
        ("b8_two_effects", ModelKind::Spme),
    ];
    println!("| case | model | points | hours | rounds | RMSE before -> after (mV) | median s | s per hour | first verdict |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for (case, kind) in cases {
        let rec = Recording::from_csv(&dir.join(case).join("recording.csv")).expect("recording");
        let hours = (rec.time[rec.time.len() - 1] - rec.time[0]) / 3600.0;
        let options = DiagnoseOptions::new(ModelSpec::new(kind, Submodels::default()));
        let mut times = Vec::new();
        let mut last = None;
        for _ in 0..repeats {
            let t = Instant::now();
            let rounds = diagnose_rounds(&rec, &chen2020(), &options, 3).expect("diagnosis");
            times.push(t.elapsed().as_secs_f64());
            last = Some(rounds);
        }
        times.sort_by(f64::total_cmp);
        let s = times[times.len() / 2];
        let rounds = last.expect("one repeat");
        let verdict: String = report::verdict_in_words(&rounds[0]).chars().take(90).collect();
        let before = rounds[0].baseline.rmse_all;
        // The last round's model, or the effect that round named on top of it.
        let last = rounds.last().expect("one round");
        let after = last.best().filter(|_| last.found).and_then(|c| c.fit.as_ref()).map_or(last.baseline.rmse_all, |f| f.rmse_all);
        println!(
            "| {case} | {kind} | {} | {hours:.2} | {} | {:.2} -> {:.2} | {s:.1} | {:.1} | {verdict}... |",
            rec.time.len(),
            rounds.len(),
            before * 1e3,
            after * 1e3,
            s / hours
        );
    }
}
