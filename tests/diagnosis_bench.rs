//! The independent diagnosis bench: eight recordings with a concealed effect made by PyBaMM
//! 26.10 (not by us), copied from `../shared/diagnosis-bench/` into
//! `tests/data/diagnosis-bench/` with their `truth.json`. Each case is judged the way
//! `../shared/tools/diagnosis-bench` judges it (its `judge_verdict.py`, copied beside the
//! data): the first verdict names the concealed effect (for two effects, the rounds together
//! name both), the negative control reports no missing physics, and where an effect exists
//! the named model cuts the RMSE at least 5x (or to within 10 % of the noise, for an effect
//! smaller than five times the noise). For two effects, the conclusion over the rounds
//! must keep both (an earlier stand-in superseded by later rounds does not count).
//!
//! The same judge runs on six more PyBaMM-made cases in `tests/data/diagnosis-extra/`
//! (`scripts/make_unseen_cases.py`, same conventions), made after the method was fixed to
//! check that it is not fitted to the bench: negative particle diffusivity, negative LAM,
//! electrolyte conductivity, a DFN control of pulses, contact resistance at 10 degC, and
//! lithium loss under GITT. Their first run named 5 of 6; the sixth (contact resistance vs
//! electrolyte conductivity, indistinguishable at one rate) is now an honest tie. A second
//! batch (v1-v6: positive diffusivity, kinetics at 1C, self-heating at 1.5C, a C/3 control
//! cycle, resistance from pulses at two rates, lithium loss at C/5 with the DFN) was made
//! after that fix and named 6 of 6 at its first run. A third batch (w1-w6) named 5 of 6 at its
//! first run (negative particle radius x1.6, 8 % positive LAM at C/3, self-heating with SPMe
//! data, a DFN drive-cycle control, a control at 35 degC). The sixth (electrolyte diffusivity
//! x0.3 ending at the cut-off in 3 minutes) was "unexplained" until our DFN followed PyBaMM
//! into electrolyte depletion (PyBaMM's floors on the concentration in the electrolyte's
//! functions) and a fit whose model fails around its point stops there instead of failing.
//! A fourth batch (x1-x6: resistance under a DFN drive cycle, kinetics from a CC-CV charge, 12 % negative LAM at C/2, negative diffusivity under
//! GITT, a cold cell heating up, an SPM control of HPPC pulses) named 5 of 6 at its first run;
//! the sixth (kinetics from the CC-CV charge) was named once kinetics and resistance counted
//! as identifiable from a load whose level changes (the falling current of the voltage hold),
//! not only from current steps, and once candidate refits also started from the baseline's own
//! starting state of charge (its fitted one had absorbed the missing overpotential). A fifth
//! batch (y1-y6: one-state OCV hysteresis of the negative electrode, resistance in a recording
//! with 3 mV noise sampled every 10 s, self-heating without a recorded temperature, the SPM on
//! a DFN drive cycle, lithium loss through a CC-CV charge, a DFN control with 5 mV noise) named
//! 6 of 6 at its first run. A sixth batch (z1-z4) has two effects each, judged as b8: kinetics
//! with a contact resistance (pulses at 1C and 3C), 10 % positive LAM with self-heating, lithium
//! loss with a slow negative diffusivity, and electrolyte transport with a contact resistance
//! (SPM given DFN data). 3 of 4 at the first run; z2 (LAM with self-heating at 1.5C) was
//! "unexplained": after the nuisance initial state the two leave 4.7 mV that no single
//! candidate removes. It is named since a round that explains nothing refits the candidates in
//! pairs (`diagnose::pairs`). A seventh batch (q1-q4:
//! a resistance in a self-heating cell with its temperature recorded, negative LAM under an
//! hour of drive cycle, kinetics and positive diffusion three times faster than the set's)
//! named 4 of 4 at its first run. An eighth batch (r1-r8), made blind by a helper session that
//! never saw the code change, named 8 of 8 at its first run (two as honest ties: 4 mOhm against
//! kinetics from pulses at one rate, and electrolyte conductivity x0.4 at 10 degC against a
//! series resistance under a drive cycle). Six are here; r2 (negative diffusivity from a DFN
//! CC-CV charge) and r3 (4 mOhm in a DFN under C/2 pulses) take about a minute each and are
//! judged by the script only, to keep CI short. A ninth batch (s1-s8), blind in the same way
//! and made to look measured (cycler-like current noise, 0.1 mV resolution, 30-60 s sampling on
//! long stretches, 3 mV noise, 0 and 45 degC, parameters outside the candidate list: a
//! Bruggeman exponent, a particle radius, an electrode thickness, activation energies), named
//! 8 of 8 at its first run (s4, positive exchange current x0.8 near the noise, as a tie with a
//! 0.56 mOhm resistance). s2, s3, s4 and s8 are here; the others take 25-47 s each.
//! A blind batch p (p1-p8) named 6 of 8 at its first run and 7 of 8 with the final binary of
//! that session; its quick cases are here: 7 mOhm under constant power at 5 degC (an honest tie
//! with kinetics), 10 % negative LAM under partial CC-CV cycles, a DFN GITT control at 45 degC
//! and +-15 mV hysteresis from a two-way GITT.
//!
//! The slowest cases (52, 1-5 min each on two cores: pairs of effects, 12-cycle ageing
//! recordings, DFN drives and depletion) are `#[ignore]`d so CI stays well under its 30
//! minutes; every session runs them with
//! `cargo test --release --test diagnosis_bench -- --include-ignored` before it stops.

use std::path::{Path, PathBuf};

use cellstudio::data::Recording;
use cellstudio::diagnose::{Candidate, DiagnoseOptions, Diagnosis, diagnose_rounds, report};
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::problem::fitting::ModelSpec;

/// `name` is `folder/case` under `tests/data/`.
fn case_dir(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name)
}

struct Truth {
    effect: String,
    /// Groups of accepted words; a verdict must contain one word of each group.
    accept: Vec<Vec<String>>,
    model: ModelKind,
    ambient: f64,
}

fn truth(name: &str) -> Truth {
    let text = std::fs::read_to_string(case_dir(name).join("truth.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let effect = v["effect"].as_str().unwrap().to_string();
    let accept = v["accept"].as_array().unwrap().iter().map(|a| a.as_str().unwrap().split('|').map(str::to_lowercase).collect()).collect();
    let model = v["candidate_model"].as_str().unwrap().parse().unwrap();
    Truth { effect, accept, model, ambient: v["ambient_temperature_K"].as_f64().unwrap_or(298.15) }
}

/// Whether the rounds' verdicts pass the bench's judge (see the module doc).
fn judged(t: &Truth, rounds: &[Diagnosis]) -> bool {
    let verdicts: Vec<String> = rounds.iter().map(|d| report::verdict_in_words(d).to_lowercase()).collect();
    // The judge reads only verdicts that open with one of these (a round whose verdict opens
    // otherwise is skipped, and the next round's taken for the first: blind bb6).
    let readable = ["missing physics", "no missing physics", "unexplained", "parameter mismatch"];
    assert!(verdicts.iter().all(|v| readable.iter().any(|r| v.starts_with(r))), "a verdict the judge cannot read: {verdicts:?}");
    // The judge's sentence ends at the first full stop followed by white space (its regex
    // `[^\n]*?(?:\.(?=\s)|$)`): an "e.g. " inside a tie once hid its second name (blind ah5).
    let verdicts: Vec<&str> = verdicts.iter().map(|v| first_sentence(v)).collect();
    let first = verdicts[0];
    if t.effect.contains('+') {
        let all = verdicts.join(" ");
        t.accept.iter().all(|g| g.iter().any(|w| all.contains(w)))
    } else if t.effect == "none" {
        first.starts_with("no missing")
    } else {
        !first.starts_with("no missing") && !first.starts_with("unexplained") && t.accept.iter().flatten().any(|w| first.contains(w))
    }
}

/// `text` up to its first full stop followed by white space (or its first line), as the
/// bench's judge reads a verdict.
fn first_sentence(text: &str) -> &str {
    let line = text.lines().next().unwrap_or_default();
    let stop = line.char_indices().find(|&(i, c)| c == '.' && line[i + 1..].starts_with(char::is_whitespace));
    stop.map_or(line, |(i, _)| &line[..=i])
}

/// A case's truth and its diagnosis (up to 3 rounds) on Chen 2020 at the case's ambient,
/// unjudged.
fn diagnose_case(name: &str) -> (Truth, Vec<Diagnosis>) {
    diagnose_case_with(name, Submodels::default())
}

/// As [`diagnose_case`], the user's model with `submodels`.
fn diagnose_case_with(name: &str, submodels: Submodels) -> (Truth, Vec<Diagnosis>) {
    let t = truth(name);
    let rec = Recording::from_csv(&case_dir(name).join("recording.csv")).unwrap();
    let mut p = chen2020();
    p.thermal.ambient_temperature = t.ambient;
    p.thermal.initial_temperature = t.ambient;
    let options = DiagnoseOptions::new(ModelSpec::new(t.model, submodels));
    let start = std::time::Instant::now();
    let rounds = diagnose_rounds(&rec, &p, &options, 3).unwrap();
    println!("{name}: {:.1} s", start.elapsed().as_secs_f64());
    (t, rounds)
}

fn run_case(name: &str) -> Vec<Diagnosis> {
    let (t, rounds) = diagnose_case(name);
    for (k, d) in rounds.iter().enumerate() {
        println!("  round {}: {}", k + 1, d.summary);
    }
    assert!(judged(&t, &rounds), "{name}: verdict does not name {}: {}", t.effect, report::verdict_in_words(&rounds[0]));
    if t.effect.contains('+') {
        // Stricter than the bench's judge: the effects kept at the end (not superseded by
        // later rounds) name each concealed effect.
        let conclusion = report::conclusion(&rounds).to_lowercase();
        let kept = conclusion.split("superseded").next().unwrap_or_default();
        assert!(t.accept.iter().all(|g| g.iter().any(|w| kept.contains(w))), "{name}: {conclusion}");
    }
    let before = rounds[0].baseline.rmse_all;
    if t.effect == "none" {
        assert!(!rounds[0].found, "{name}: the control names an effect");
    } else {
        let after = rounds.iter().filter_map(|d| d.best().filter(|_| d.found)).filter_map(|c| c.fit.as_ref()).map(|f| f.rmse_all).fold(f64::INFINITY, f64::min);
        // A 5x cut, or down to the noise where the effect is smaller than 5x the noise (the
        // most any model can do): within 10 % of the recording's noise level.
        let goal = (before / 5.0).max(1.1 * rounds[0].noise);
        assert!(after <= goal, "{name}: RMSE cut only {:.2}x ({:.2} -> {:.2} mV, noise {:.2} mV)", before / after, before * 1e3, after * 1e3, rounds[0].noise * 1e3);
    }
    rounds
}

/// The fitted value of `path` in the first round's named candidate.
fn first_fitted(rounds: &[Diagnosis], path: &str) -> f64 {
    let fit = rounds[0].best().and_then(|c| c.fit.as_ref()).expect("a named candidate holds its fit");
    fit.names.iter().position(|n| n == path).map(|i| fit.values[i]).unwrap_or_else(|| panic!("{path} is not fitted: {}", rounds[0].summary))
}

/// The value of `path` in the first round whose named candidate fitted it (a pair's second
/// effect is named in a later round).
fn fitted_in_any_round(rounds: &[Diagnosis], path: &str) -> f64 {
    let mut fits = rounds.iter().filter_map(|d| d.best().and_then(|c| c.fit.as_ref()));
    fits.find_map(|fit| fit.names.iter().position(|n| n == path).map(|i| fit.values[i])).unwrap_or_else(|| panic!("{path} is not fitted in any round: {}", rounds[0].summary))
}

#[test]
fn b1_contact_resistance_gitt_dfn() {
    run_case("diagnosis-bench/b1_contact_gitt");
}

#[test]
fn b2_electrolyte_transport_spm() {
    run_case("diagnosis-bench/b2_electrolyte_2C");
}

#[test]
fn b3_lithium_inventory_spme() {
    run_case("diagnosis-bench/b3_inventory_C2");
}

#[test]
fn b4_self_heating_dfn() {
    let rounds = run_case("diagnosis-bench/b4_selfheating_2C");
    // PyBaMM's h = 20 W/(m^2 K): 20.006 ± 0.004 since the DFN heats as PyBaMM's does (its
    // open-circuit power weighted where the current reacts); 19.6 before.
    let h = first_fitted(&rounds, "thermal.heat_transfer_coefficient");
    assert!((h / 20.0 - 1.0).abs() < 2e-3, "heat-transfer coefficient {h} W/(m^2 K)");
    // The heat balance predicts the recorded temperature: reading it names nothing more.
    let read = rounds[0].candidates.iter().find(|c| c.candidate == Candidate::RecordedTemperature).expect("the recorded temperature is a candidate");
    assert!(!read.named && read.note.as_deref().is_some_and(|n| n.contains("a heat balance predicts the recorded temperature")), "{:?}", read.note);
}

/// The user's model already heats itself, at the set's h = 10 W/(m^2 K) against PyBaMM's 20:
/// its heat balance is refitted (a parameter mismatch), which then predicts the recorded
/// temperature, so reading that temperature is not named.
#[test]
fn b4_a_thermal_model_with_another_heat_transfer_coefficient_dfn() {
    let (_, rounds) = diagnose_case_with("diagnosis-bench/b4_selfheating_2C", Submodels { thermal: true, ..Submodels::default() });
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::HeatBalance), "{}", rounds[0].summary);
    let h = first_fitted(&rounds, "thermal.heat_transfer_coefficient");
    assert!((h / 20.0 - 1.0).abs() < 2e-3, "heat-transfer coefficient {h} W/(m^2 K)");
    let read = rounds[0].candidates.iter().find(|c| c.candidate == Candidate::RecordedTemperature).expect("the recorded temperature is a candidate");
    assert!(!read.named, "{:?}", read.note);
}

#[test]
fn b5_kinetics_pulses_spme() {
    run_case("diagnosis-bench/b5_kinetics_pulses");
}

#[test]
fn b6_positive_active_material_loss_dfn() {
    run_case("diagnosis-bench/b6_lam_positive");
}

#[test]
fn b7_negative_control_drive_cycle_spme() {
    run_case("diagnosis-bench/b7_control_drive");
}

#[test]
fn b8_two_effects_spme() {
    run_case("diagnosis-bench/b8_two_effects");
}

#[test]
fn u1_negative_diffusivity_spme() {
    run_case("diagnosis-extra/u1_diffusivity_negative_C2");
}

#[test]
fn u2_negative_active_material_loss_dfn() {
    run_case("diagnosis-extra/u2_lam_negative_1C");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn u3_electrolyte_conductivity_dfn() {
    run_case("diagnosis-extra/u3_conductivity_2C");
}

#[test]
fn u4_negative_control_pulses_dfn() {
    run_case("diagnosis-extra/u4_control_pulses");
}

#[test]
fn u5_contact_resistance_at_10_degc_spme() {
    run_case("diagnosis-extra/u5_contact_cold_1C");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the eighteenth session (CI ran 34 min); its effect is covered by a faster CI case; run with --include-ignored"]
fn u6_lithium_inventory_gitt_spme() {
    run_case("diagnosis-extra/u6_inventory_gitt");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the eighteenth session (CI ran 34 min); its effect is covered by a faster CI case; run with --include-ignored"]
fn v1_positive_diffusivity_dfn() {
    run_case("diagnosis-extra/v1_diffusivity_positive_1C");
}

#[test]
fn v2_kinetics_constant_current_dfn() {
    run_case("diagnosis-extra/v2_kinetics_1C");
}

#[test]
fn v3_self_heating_dfn() {
    run_case("diagnosis-extra/v3_thermal_1p5C");
}

#[test]
fn v4_negative_control_cycle_spme() {
    run_case("diagnosis-extra/v4_control_cycle");
}

#[test]
fn v5_contact_resistance_two_rates_spm() {
    run_case("diagnosis-extra/v5_contact_two_rates");
}

#[test]
fn v6_lithium_inventory_dfn() {
    run_case("diagnosis-extra/v6_inventory_dfn_C5");
}

#[test]
fn w1_negative_particle_radius_dfn() {
    run_case("diagnosis-extra/w1_radius_negative_1C");
}

#[test]
fn w2_positive_active_material_loss_spme() {
    run_case("diagnosis-extra/w2_lam_positive_C3");
}

#[test]
fn w3_self_heating_spme() {
    run_case("diagnosis-extra/w3_thermal_spme_2C");
}

#[test]
fn w4_negative_control_drive_cycle_dfn() {
    run_case("diagnosis-extra/w4_control_drive_dfn");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn w5_electrolyte_diffusivity_to_depletion_dfn() {
    run_case("diagnosis-extra/w5_electrolyte_diffusivity_1p5C");
}

#[test]
fn w6_negative_control_at_35_degc_spme() {
    run_case("diagnosis-extra/w6_control_warm");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn x1_contact_resistance_drive_cycle_dfn() {
    run_case("diagnosis-extra/x1_contact_drive_dfn");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn x2_kinetics_cccv_charge_spme() {
    run_case("diagnosis-extra/x2_kinetics_cccv_charge");
}

#[test]
fn x3_negative_active_material_loss_c2_dfn() {
    run_case("diagnosis-extra/x3_lam_negative_C2");
}

#[test]
fn x4_negative_diffusivity_gitt_spme() {
    run_case("diagnosis-extra/x4_diffusivity_negative_gitt");
}

#[test]
fn x5_self_heating_cold_cell_dfn() {
    run_case("diagnosis-extra/x5_thermal_cold_1C");
}

#[test]
fn x6_negative_control_hppc_spm() {
    run_case("diagnosis-extra/x6_control_hppc_spm");
}

#[test]
fn y1_ocv_hysteresis_spme() {
    run_case("diagnosis-extra/y1_hysteresis_negative_spme");
}

#[test]
fn y2_contact_resistance_noisy_coarse_spme() {
    run_case("diagnosis-extra/y2_contact_noisy_coarse");
}

#[test]
fn y3_self_heating_without_temperature_dfn() {
    run_case("diagnosis-extra/y3_thermal_unrecorded");
}

#[test]
fn y4_electrolyte_transport_drive_cycle_spm() {
    run_case("diagnosis-extra/y4_electrolyte_drive_spm");
}

#[test]
fn y5_lithium_inventory_cccv_spme() {
    run_case("diagnosis-extra/y5_inventory_cccv");
}

#[test]
fn y6_negative_control_5mv_noise_dfn() {
    run_case("diagnosis-extra/y6_control_noisy_dfn");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the thirty-eighth session (CI ran 1,710 s of its 1,800); run with --include-ignored"]
fn z1_kinetics_and_contact_resistance_spme() {
    run_case("diagnosis-extra/z1_kinetics_and_contact");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the thirty-eighth session (CI ran 1,710 s of its 1,800); run with --include-ignored"]
fn z3_lithium_inventory_and_diffusivity_spme() {
    run_case("diagnosis-extra/z3_inventory_and_diffusivity");
}

#[test]
#[ignore = "slow for CI (43 s alone): contact resistance is named in CI by b1, p2, u5, v5, y2, z1 and the electrolyte by b2; run with --include-ignored"]
fn z4_electrolyte_and_contact_resistance_spm() {
    run_case("diagnosis-extra/z4_electrolyte_and_contact_spm");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn q1_contact_resistance_and_self_heating_dfn() {
    run_case("diagnosis-extra/q1_contact_in_warming_cell");
}

#[test]
fn q2_negative_active_material_drive_cycle_spme() {
    run_case("diagnosis-extra/q2_lam_negative_drive_spme");
}

#[test]
fn q3_faster_kinetics_spme() {
    run_case("diagnosis-extra/q3_faster_kinetics_pulses");
}

#[test]
fn q4_faster_positive_diffusion_dfn() {
    run_case("diagnosis-extra/q4_faster_diffusion_2C_dfn");
}

#[test]
#[ignore = "slow for CI (36 s alone): active-material loss (b6, q2) and self-heating (b4, v3, x5) are named in CI; run with --include-ignored"]
fn z2_active_material_loss_and_self_heating_dfn() {
    run_case("diagnosis-extra/z2_lam_and_thermal");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the eighteenth session (CI ran 34 min); its effect is covered by a faster CI case; run with --include-ignored"]
fn r1_positive_diffusivity_constant_power_at_40_degc_spme() {
    run_case("diagnosis-extra/r1_diffusivity_positive_power_40C");
}

#[test]
fn r4_lithium_inventory_low_soc_pulses_spm() {
    run_case("diagnosis-extra/r4_inventory_low_soc_pulses_spm");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the eighteenth session (CI ran 34 min); its effect is covered by a faster CI case; run with --include-ignored"]
fn r5_electrolyte_conductivity_drive_at_10_degc_spme() {
    run_case("diagnosis-extra/r5_conductivity_urban_drive_10C");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn r6_positive_active_material_loss_gitt_dfn() {
    run_case("diagnosis-extra/r6_lam_positive_gitt_3s");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn r7_kinetics_and_lithium_inventory_hppc_spme() {
    run_case("diagnosis-extra/r7_kinetics_and_inventory_hppc");
}

#[test]
fn r8_negative_control_cccv_then_discharge_dfn() {
    run_case("diagnosis-extra/r8_control_cccv_then_discharge_dfn");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn s2_positive_particle_radius_charge_only_spme() {
    run_case("diagnosis-extra/s2_radius_positive_charge_only");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the eighteenth session (CI ran 34 min); its effect is covered by a faster CI case; run with --include-ignored"]
fn s3_thinner_positive_electrode_3mv_noise_dfn() {
    run_case("diagnosis-extra/s3_thickness_positive_3mV");
}

#[test]
fn s4_positive_kinetics_near_the_noise_spme() {
    run_case("diagnosis-extra/s4_kinetics_positive_near_limit");
}

#[test]
fn s8_negative_control_rpt_dfn() {
    run_case("diagnosis-extra/s8_control_rpt_dfn");
}

#[test]
fn p2_contact_resistance_constant_power_cold_spm() {
    run_case("diagnosis-extra/p2_contact_constant_power_5C_spm");
}

#[test]
fn p3_negative_active_material_partial_cccv_spme() {
    run_case("diagnosis-extra/p3_lam_negative_partial_cccv_0p5mV");
}

#[test]
fn p4_negative_control_gitt_charge_warm_dfn() {
    run_case("diagnosis-extra/p4_control_gitt_charge_45C_dfn");
}

#[test]
fn p8_hysteresis_two_way_gitt_spme() {
    run_case("diagnosis-extra/p8_hysteresis_bidirectional_gitt_15C");
}

// Multi-cycle recordings (`scripts/make_ageing_cases.py`, 12 CC-CV cycles of PyBaMM's SPM):
// SEI growth is named only where the lithium loss drifts from cycle to cycle.

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn g1_sei_growth_over_12_cycles_spm() {
    let rounds = run_case("diagnosis-ageing/g1_sei_growth_12_cycles_spm");
    let k = first_fitted(&rounds, "sei.exchange_current");
    // PyBaMM's Chen 2020 SEI exchange current x20.
    assert!((k / 3.0e-6 - 1.0).abs() < 0.05, "SEI exchange current {k:.4e} vs PyBaMM's 3.0e-6");
}

#[test]
fn g2_negative_control_12_cycles_spm() {
    run_case("diagnosis-ageing/g2_control_12_cycles_spm");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn g3_fixed_inventory_loss_is_not_sei_growth_spm() {
    let rounds = run_case("diagnosis-ageing/g3_fixed_inventory_loss_12_cycles_spm");
    assert!(!report::verdict_in_words(&rounds[0]).contains("SEI"), "{}", rounds[0].summary);
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn g4_progressive_negative_active_material_loss_spm() {
    // Truth: PyBaMM's stress-driven LAM with plain diffusion in the negative electrode only,
    // proportional term 2.78e-5 1/s: the negative loses 2.39 % of its active material over the
    // 12 cycles (PyBaMM's x-averaged volume fraction 0.75 -> 0.7321, the script's setup).
    progressive_negative_lam_named(&run_case("diagnosis-ageing/g4_lam_growth_12_cycles_spm"), 0.0239, (2.78e-5, 0.15));
}

/// Progressive loss of active material named in round 1, in the negative electrode, by either
/// law: over a recording at one rate the stress-driven and the throughput-driven laws differ
/// only in how the loss spreads over each cycle, and the recorded current (the CV holds
/// sampled every 30-60 s) does not hold that apart (our stress-driven law, fitted from
/// PyBaMM's term on g4, leaves 1.09 mV to the throughput law's 1.05; on g9 1.09 to 1.06). The
/// loss the name states is within 20 % of PyBaMM's `loss` (achieved: 9 % on g4, 14 % on g9,
/// by the throughput law); when the stress-driven law is named, its proportional term is
/// within the given share of PyBaMM's too.
fn progressive_negative_lam_named(rounds: &[Diagnosis], loss: f64, (beta, share): (f64, f64)) {
    let cellstudio::diagnose::Verdict::Found { candidate, .. } = rounds[0].verdict else { panic!("not found: {}", rounds[0].summary) };
    assert!(matches!(candidate, Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput), "{}", rounds[0].summary);
    let name = &rounds[0].best().expect("a named candidate").name;
    assert!(name.contains("negative electrode"), "{name}");
    let stated: f64 = name.split("about ").nth(1).and_then(|t| t.split(" %").next()).and_then(|v| v.parse().ok()).unwrap_or_else(|| panic!("no loss in {name}"));
    assert!((stated / 100.0 / loss - 1.0).abs() < 0.2, "{name}: PyBaMM loses {:.2} %", 100.0 * loss);
    if candidate == Candidate::ActiveMaterialGrowth {
        let fitted = first_fitted(rounds, "lam.negative.proportional_term");
        assert!((fitted / beta - 1.0).abs() < share, "negative LAM proportional term {fitted:.4e} vs PyBaMM's {beta:.3e}");
    }
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn g5_irreversible_plating_under_fast_charges_spm() {
    // Truth: PyBaMM's irreversible plating, rate constant 1e-10 m/s, 1.5C charges. Before the
    // plating candidate: "SEI growth together with solid diffusivity" after 40 min (the
    // SPM -> DFN electrolyte candidates on 120,000 s in the pair search). Plating and
    // reaction-limited SEI are both cathodic Tafel side reactions on the same potential
    // difference; here SEI growth leaves 7.1 mV against plating's 1.2 mV (their Tafel slopes
    // differ, and the SEI adds a film drop), so plating is found alone (a tie with SEI would
    // be as honest).
    let rounds = run_case("diagnosis-ageing/g5_plating_12_cycles_spm");
    let named = |c: Candidate| match &rounds[0].verdict {
        cellstudio::diagnose::Verdict::Found { candidate, partner: None, .. } => *candidate == c,
        cellstudio::diagnose::Verdict::Tie { first, second, first_partner: None, second_partner: None, .. } => *first == c || *second == c,
        _ => false,
    };
    assert!(named(Candidate::LithiumPlating), "{}", rounds[0].summary);
    let k = first_fitted(&rounds, "plating.kinetic_rate_constant");
    assert!((k / 1e-10 - 1.0).abs() < 0.15, "plating rate constant {k:.4e} vs PyBaMM's 1e-10");
}

// The same ageing candidates on the DFN (`scripts/make_ageing_cases.py ... dfn`: 4 CC-CV
// cycles of PyBaMM's DFN). Before they were offered on the DFN, g6 was "unexplained"
// (21.21 mV after the nuisance initial state, 496 s).

#[test]
#[ignore = "slow (2-5 min): CI skips it; run with --include-ignored, see the module doc"]
fn g6_sei_growth_over_4_cycles_dfn() {
    let rounds = run_case("diagnosis-ageing/g6_sei_growth_4_cycles_dfn");
    let k = first_fitted(&rounds, "sei.exchange_current");
    // PyBaMM's Chen 2020 SEI exchange current x100.
    assert!((k / 1.5e-5 - 1.0).abs() < 0.01, "SEI exchange current {k:.4e} vs PyBaMM's 1.5e-5");
}

#[test]
fn g7_negative_control_4_cycles_dfn() {
    run_case("diagnosis-ageing/g7_control_4_cycles_dfn");
}

#[test]
#[ignore = "slow (2-5 min): CI skips it; run with --include-ignored, see the module doc"]
fn g8_plating_under_fast_charges_dfn() {
    // Truth: PyBaMM's irreversible plating, rate constant 1e-10 m/s. Over 4 cycles the
    // irreversible and partially reversible laws fit alike (a tie of the two is named).
    let rounds = run_case("diagnosis-ageing/g8_plating_4_cycles_dfn");
    assert!(report::verdict_in_words(&rounds[0]).contains("plating"), "{}", rounds[0].summary);
    let irreversible = rounds[0].candidates.iter().find(|c| c.candidate == Candidate::LithiumPlating && c.partner.is_none() && c.named);
    let fit = irreversible.and_then(|c| c.fit.as_ref()).unwrap_or_else(|| panic!("irreversible plating not named: {}", rounds[0].summary));
    let k = fit.values[fit.names.iter().position(|n| n == "plating.kinetic_rate_constant").expect("the rate constant is fitted")];
    assert!((k / 1e-10 - 1.0).abs() < 0.3, "plating rate constant {k:.4e} vs PyBaMM's 1e-10");
}

#[test]
#[ignore = "slow (2-5 min): CI skips it; run with --include-ignored, see the module doc"]
fn g9_progressive_negative_active_material_loss_dfn() {
    // Truth: PyBaMM's stress-driven LAM with plain diffusion in the negative electrode only,
    // proportional term 8.33e-5 1/s.
    // The negative loses 2.46 % of its active material over the 4 cycles (PyBaMM's x-averaged
    // volume fraction 0.75 -> 0.7315, the script's setup).
    progressive_negative_lam_named(&run_case("diagnosis-ageing/g9_lam_growth_4_cycles_dfn"), 0.0246, (8.33e-5, 0.08));
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn o2_cold_start_warming_in_its_room_dfn() {
    // Blind batch o (scripts/make_unseen_cases.py o): a cell from 10 degC storage in a 25 degC
    // room with its temperature recorded. Missed on its first run (the thermal candidate took
    // the first recorded temperature as the room's and needed h = 0.25 W/(m^2 K)); the
    // candidate now fits the ambient to the recorded temperature.
    let rounds = run_case("diagnosis-extra/o2_cold_start_warming_recorded_dfn");
    let value = |path: &str| first_fitted(&rounds, path);
    // PyBaMM's truth: ambient 298.15 K, h = 5 W/(m^2 K).
    assert!((value("thermal.ambient_temperature") - 298.15).abs() < 0.2, "{}", rounds[0].summary);
    assert!((value("thermal.heat_transfer_coefficient") / 5.0 - 1.0).abs() < 0.03, "{}", rounds[0].summary);
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the thirty-eighth session (CI ran 1,710 s of its 1,800); run with --include-ignored"]
fn o6_conductivity_and_self_heating_tie_with_contact_and_self_heating_spme() {
    // Blind batch o: electrolyte conductivity x0.5 with self-heating (h = 15 W/(m^2 K)) in
    // SPMe data. Chen 2020's conductivity does not depend on temperature, so in the SPMe a
    // conductivity factor is an ohmic term: the true pair and contact resistance with
    // self-heating fit alike. Missed on its first run (one pair named); now a tie of pairs.
    let rounds = run_case("diagnosis-extra/o6_conductivity_and_thermal_interrupted_2C");
    let cellstudio::diagnose::Verdict::Tie { first, first_partner, second, second_partner, .. } = &rounds[0].verdict else {
        panic!("not a tie: {}", rounds[0].summary)
    };
    let pairs = [(*first, *first_partner), (*second, *second_partner)];
    let has = |c: Candidate| pairs.iter().any(|(a, b)| *a == c || *b == Some(c));
    assert!(has(Candidate::SeriesResistance) && has(Candidate::ElectrolyteTransport), "{}", rounds[0].summary);
    assert!(pairs.iter().all(|(a, b)| *a == Candidate::Thermal || *b == Some(Candidate::Thermal)), "{}", rounds[0].summary);
    let electrolyte = rounds[0].candidates.iter().find(|c| c.partner.is_some() && (c.candidate == Candidate::ElectrolyteTransport || c.partner == Some(Candidate::ElectrolyteTransport)));
    let fit = electrolyte.and_then(|c| c.fit.as_ref()).expect("the electrolyte pair holds its fit");
    let value = |path: &str| fit.names.iter().position(|n| n == path).map(|i| fit.values[i]).expect(path);
    // PyBaMM's truth: conductivity x0.5, h = 15 W/(m^2 K).
    assert!((value("electrolyte.conductivity_factor") / 0.5 - 1.0).abs() < 0.01, "{}", rounds[0].summary);
    assert!((value("thermal.heat_transfer_coefficient") / 15.0 - 1.0).abs() < 0.01, "{}", rounds[0].summary);
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn n3_salt_depleted_electrolyte_in_dfn_data_given_to_the_spm() {
    // Blind batch n (scripts/make_unseen_cases.py n): initial salt 700 instead of 1000 mol/m3.
    // Missed on its first run (contact + RC named): an SPM's electrolyte candidates brought
    // the DFN with the set's electrolyte only; the properties candidate now brings it with
    // its diffusivity and conductivity factors refitted.
    run_case("diagnosis-extra/n3_salt_depleted_pulse_train_low_soc_dfn_data_spm");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn n4_positive_active_material_and_lithium_lost_together_spme() {
    // Blind batch n: 8 % positive LAM with 6 % less lithium, 1C then a C/20 tail. Missed on
    // its first run ("unexplained"): the pair's fit started from the LAM single's compromise
    // (a lost negative capacity standing in for the lithium) and stopped there; pairs now
    // start from no effect.
    let rounds = run_case("diagnosis-extra/n4_lam_positive_and_inventory_c20_tail");
    // PyBaMM's truth: positive fraction 0.665 x 0.92 = 0.6118, negative initial
    // concentration 29866 x 0.94 = 28074 mol/m3.
    let fraction = first_fitted(&rounds, "positive.active_fraction");
    let lithium = first_fitted(&rounds, "negative.initial_concentration");
    assert!((fraction / 0.6118 - 1.0).abs() < 1e-3, "positive fraction {fraction}: {}", rounds[0].summary);
    assert!((lithium / 28074.0 - 1.0).abs() < 1e-3, "negative initial concentration {lithium}: {}", rounds[0].summary);
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn m8_a_pair_member_that_stood_in_is_dropped_from_the_conclusion_spme() {
    // Blind batch m (named on its first run): +-12 mV negative hysteresis with 5 % less
    // lithium, C/3 deep cycle with 1 h rests. Round 1 named negative LAM with hysteresis,
    // round 2 the lithium; the final model puts the active fractions back at the set's
    // values, but the conclusion still listed the LAM: a pair's effects are now taken out
    // one at a time by the backward check. Since the tenth session round 1 names the true
    // pair itself (inventory with hysteresis; its initial hysteresis state, near zero, is
    // judged against its range).
    let rounds = run_case("diagnosis-extra/m8_hysteresis_and_inventory_c3_cycle_rests_spme");
    let conclusion = report::conclusion(&rounds).to_lowercase();
    let kept = conclusion.split("superseded").next().unwrap_or_default();
    assert!(!kept.contains("active material"), "{conclusion}");
    let last = rounds.iter().rev().find_map(|d| d.best().filter(|_| d.found)).and_then(|c| c.fit.as_ref()).expect("a named effect");
    let get = |path: &str| last.names.iter().position(|n| n == path).map(|i| last.values[i]).unwrap_or_else(|| panic!("{path} not fitted"));
    // PyBaMM's truth: half-width 12 mV; initial concentrations 25725 (negative) and 20404
    // (positive) mol/m3, PyBaMM's 90 % SOC of the cell with 5 % less lithium.
    let summary = &rounds.last().unwrap().summary;
    assert!((get("cell.hysteresis_voltage") / 0.012 - 1.0).abs() < 0.1, "{summary}");
    assert!((get("negative.initial_concentration") / 25725.0 - 1.0).abs() < 2e-3, "{summary}");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn n5_hysteresis_under_a_drive_with_one_rest_spme() {
    // Blind batch n: +-10 mV hysteresis of the negative OCP under a hill drive with long
    // regenerative charging, one rest. Missed on its first run (hysteresis was not tried:
    // it needed rests after both charge and discharge); a load that swings the hysteresis
    // state into both branches now makes it identifiable.
    let rounds = run_case("diagnosis-extra/n5_hysteresis_hill_regen_drive_35C");
    let half_width = first_fitted(&rounds, "cell.hysteresis_voltage");
    assert!((half_width / 0.010 - 1.0).abs() < 0.15, "half-width {half_width}: {}", rounds[0].summary);
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the thirty-eighth session (CI ran 1,710 s of its 1,800); run with --include-ignored"]
fn l4_internal_leak_through_rests_dfn() {
    // Blind batch l: a 20 mA internal leak (a soft short the cycler does not measure) through
    // a C/3 CC-CV charge, a discharge and hours of rest, DFN data and model. Its first run
    // named a tie of negative LAM and hysteresis (a leak was not a candidate); the leak
    // candidate (`cell.leakage_current` on the leak submodel) now names it.
    let rounds = run_case("diagnosis-extra/l4_internal_leak_20mA_cccv_long_rests_dfn");
    // PyBaMM's truth: 0.02 A of discharge inside the cell.
    let leak = first_fitted(&rounds, "cell.leakage_current");
    assert!((leak / 0.02 - 1.0).abs() < 0.02, "leak {leak} A: {}", rounds[0].summary);
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn l2_partially_reversible_plating_cold_fast_charges_spme() {
    // Blind batch l: partially reversible plating (OKane2022's rate constant 1e-9 m/s, dead-
    // lithium decay 5e-5 1/s) in 1.5C CC-CV charges at 5 degC, cycler-logged, 4 cycles. Its
    // first run named irreversible plating with the rate constant 13x low; the partially
    // reversible law is now a candidate of its own and is named with both values.
    let rounds = run_case("diagnosis-extra/l2_plating_partially_reversible_1p5C_charge_5C_cycler_spme");
    let summary = &rounds[0].summary;
    assert!(summary.to_lowercase().contains("partially reversible"), "{summary}");
    // PyBaMM's truth (truth.json's note).
    assert!((first_fitted(&rounds, "plating.kinetic_rate_constant") / 1e-9 - 1.0).abs() < 0.03, "{summary}");
    assert!((first_fitted(&rounds, "plating.dead_lithium_decay_constant") / 5e-5 - 1.0).abs() < 0.05, "{summary}");
}

#[test]
fn k3_voltage_channel_offset_gitt_spm() {
    // Blind batch k: the voltage channel reads 8 mV high through a GITT at 15 degC. Its first
    // run named lithium inventory (8.12 -> 2.91 mV, noise 1.49), passed only on the accept
    // word "offset"; the voltage-offset candidate now names it.
    let rounds = run_case("diagnosis-extra/k3_voltage_channel_offset_8mV_gitt_15C_spm");
    let offset = first_fitted(&rounds, "cell.voltage_offset");
    assert!((offset / 0.008 - 1.0).abs() < 0.03, "offset {offset} V: {}", rounds[0].summary);
}

#[test]
#[ignore = "slow (1-2 min): CI skips it since the thirty-eighth session (CI ran 1,710 s of its 1,800); run with --include-ignored"]
fn a4_voltage_channel_gain_dst_spm() {
    // Blind batch a: the voltage channel reads 0.3 % high (1.003 times the cell's voltage)
    // through DSTs and a CC-CV at 30 degC. Its first run named an offset of +12.2 mV and left
    // 1.04 mV of structure (noise 0.97); the voltage-gain candidate now names the gain.
    let rounds = run_case("diagnosis-extra/a4_voltage_channel_gain_0p3pct_high_dst_cccv_30C_cycler_spm");
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::VoltageGain), "{}", rounds[0].summary);
    let gain = first_fitted(&rounds, "cell.voltage_gain");
    assert!((gain / 0.003 - 1.0).abs() < 0.02, "gain {gain}: {}", rounds[0].summary);
    // It leaves less than the offset that stood in (1.04 mV), within 5 % of the noise (0.99
    // mV at noise 0.96 when added).
    let rmse = |c: Candidate| rounds[0].candidates.iter().find(|o| o.candidate == c && o.partner.is_none()).and_then(|o| o.fit.as_ref()).unwrap().rmse_all;
    let after = rmse(Candidate::VoltageGain);
    assert!(after < rmse(Candidate::VoltageOffset) && after < 1.05 * rounds[0].noise, "{after} V left: {}", rounds[0].summary);
}

#[test]
fn bb5_voltage_channel_logged_late_wltp_spme() {
    // Blind batch b: a logger stamps the voltage 2 s after the current through a WLTP-like
    // drive and a charge at 18 degC. Its first run stopped before diagnosing: the recording
    // check read the late voltage as a charge-positive current. The check now reads each
    // step's response at its strongest lag, and the voltage-delay candidate names the delay.
    let rounds = run_case("diagnosis-extra/bb5_voltage_logged_2s_late_wltp_drive_18C_spme");
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::VoltageDelay), "{}", rounds[0].summary);
    let delay = first_fitted(&rounds, cellstudio::problem::delay::VOLTAGE_DELAY);
    assert!((delay - 2.0).abs() < 0.01, "delay {delay} s: {}", rounds[0].summary);
}

#[test]
fn bb6_unrelaxed_start_is_read_as_a_verdict_spme() {
    // Blind batch b: the recording begins 1e-13 s after an unrecorded 20 min 1.5C discharge.
    // Its first run named the unrelaxed start, but as "Recording condition: ...", a verdict
    // the judge does not read: it took round 2's "no missing physics" for the first verdict.
    let rounds = run_case("diagnosis-extra/bb6_unrelaxed_start_after_unrecorded_1p5C_discharge_15C_cycler_spme");
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::UnrelaxedStart), "{}", rounds[0].summary);
    // The truth: 7.5 A (1.5C) for 1200 s. A shorter, stronger load leaves nearly the same
    // gradients (7.66 A for 846 s is fitted): its current within 5 % and the charge it moved
    // within 40 % of the truth's 9000 A s (achieved 6476, 28 % short).
    let (current, duration) = (first_fitted(&rounds, "history.current"), first_fitted(&rounds, "history.duration"));
    assert!((current / 7.5 - 1.0).abs() < 0.05 && (current * duration / 9000.0 - 1.0).abs() < 0.4, "{current} A for {duration} s: {}", rounds[0].summary);
}

#[test]
fn k2_current_channel_gain_spme() {
    // Blind batch k: the current channel reads 3 % low (the cell carries 1 / 0.97 of the
    // recorded current). Its first run named positive LAM with both fractions at 0.97; then
    // equal losses of both electrodes were named as the capacity scale they are; since the
    // thirty-sixth session the current-gain candidate names the gain itself (in the SPMe it
    // also scales the overpotentials, which a capacity scale does not).
    let rounds = run_case("diagnosis-extra/k2_current_channel_gain_3pct_low_30C_spme");
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::CurrentGain), "{}", rounds[0].summary);
    let reads = 1.0 + first_fitted(&rounds, "cell.current_gain");
    assert!((reads / 0.97 - 1.0).abs() < 0.002, "the channel reads {reads} times the cell's current (truth 0.97): {}", rounds[0].summary);
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn j5_calendar_ageing_sei_in_storage_spme() {
    // Blind batch j: solvent-diffusion-limited SEI (PyBaMM, solvent diffusivity 300x the
    // set's) through 120 h of storage at full charge and 45 degC between two C/2 capacity
    // checks, half a cycle before the storage. Its first run was "unexplained": SEI growth
    // needed 3 cycles, and equal time blocks held out only storage points. SEI growth is now
    // identifiable from a storage rest of a day or more with a load after it, and the blocks
    // hold equal numbers of points.
    let rounds = run_case("diagnosis-extra/j5_calendar_ageing_sei_storage_5_days_45C_spme");
    let first = report::verdict_in_words(&rounds[0]);
    assert!(first.starts_with("Missing physics: SEI growth"), "{first}");
}

#[test]
fn h5_negative_control_cycler_logged_drive_dfn() {
    // Blind batch h: a DFN control, CC-CV then a hill drive, logged by a cycler (a held
    // current every 30 s, an early sample when it moves). Its first run ended "unexplained"
    // after 941 s: the replay ramped the current across the gaps before each logged jump
    // (33 mAh the cell never saw, 3.51 mV against 1.48 mV of noise). Read as jumps at the
    // end of those gaps, the user's model is at the noise.
    let rounds = run_case("diagnosis-extra/h5_control_cccv_then_drive_30C_cycler_dfn");
    let (rmse, noise) = (rounds[0].baseline.rmse_all, rounds[0].noise);
    assert!(rmse < 1.1 * noise, "user's model {:.2} mV vs noise {:.2} mV", rmse * 1e3, noise * 1e3);
}

#[test]
fn e7_irreversible_plating_over_three_cycles_in_a_narrow_window_spme() {
    // Blind batch e: irreversible plating (4e-10 m/s) at 2 degC, 3 x (1.2C CC-CV to 4.1 V,
    // 1C to 3.0 V) from 10 % state of charge. Its first run never tried plating: the charge
    // throughput made 2.9 full swings of the first (wider) charge, under the 3 cycles an
    // ageing candidate needs, and a leak with lithium inventory stood in (7.31 mV left).
    // Swings between reversals count 3 cycles; plating is named (a tie of its two laws).
    let rounds = run_case("diagnosis-extra/e7_plating_irreversible_1p2C_charges_2C_30s_spme");
    let k = first_fitted(&rounds, "plating.kinetic_rate_constant");
    assert!((k / 4e-10 - 1.0).abs() < 0.05, "plating rate constant {k:.4e} vs PyBaMM's 4e-10");
}

#[test]
#[ignore = "slow for CI (31 s alone): a model breakdown is handled in CI by ab4; run with --include-ignored"]
fn h8_positive_diffusivity_through_a_model_breakdown_spme() {
    // Blind batch h: positive particle diffusivity x0.65 under a highway drive at 10 degC;
    // the user's SPMe (the set's faster diffusivity) breaks down 1739 s in. Its first run
    // stopped with a solver error: the breakdown was reported at the replay's last time
    // (3510 s), so the recording was cut after the breakdown three times over. It is now cut
    // before the breakdown and diagnosed there.
    let rounds = run_case("diagnosis-extra/h8_diffusivity_positive_highway_drive_10C_spme");
    assert!(rounds[0].notes.iter().any(|n| n.contains("broke down 1739 s")), "{:?}", rounds[0].notes);
    let d = first_fitted(&rounds, "positive.diffusivity") / cellstudio::params::chen2020().positive.diffusivity;
    assert!((d / 0.65 - 1.0).abs() < 0.005, "positive diffusivity x{d:.4} vs x0.65");
}

/// Whether the first round's verdict names every group of the case's accepted words (a
/// two-effect case named in one round, not over several).
fn first_names_all(name: &str, rounds: &[Diagnosis]) -> bool {
    let first = report::verdict_in_words(&rounds[0]).to_lowercase();
    truth(name).accept.iter().all(|g| g.iter().any(|w| first.contains(w)))
}

#[test]
fn f5_negative_lam_and_lithium_loss_in_one_round_spme() {
    // Blind batch f: 8 % negative active material and 5 % of the negative's lithium lost, a
    // slow C/10 discharge and C/5 CC-CV charge at 30 degC. Its first run named the LAM alone
    // in round 1 (13 %, 5.36 mV): the pair's continued fit restarted the freed window at the
    // baseline's state of charge, broke the model and was dropped. Resumed where its screen
    // stopped (and run while it still falls), the pair is named in round 1.
    let name = "diagnosis-extra/f5_lam_negative_and_inventory_slow_ica_30C_spme";
    let rounds = run_case(name);
    assert!(first_names_all(name, &rounds), "{}", rounds[0].summary);
    let eps = first_fitted(&rounds, "negative.active_fraction");
    let c0 = first_fitted(&rounds, "negative.initial_concentration");
    let p = chen2020();
    let (eps_true, c0_true) = (0.92 * p.negative.active_fraction, 0.95 * p.negative.initial_concentration);
    assert!((eps / eps_true - 1.0).abs() < 0.02, "negative active fraction {eps:.4} vs {eps_true:.4}");
    assert!((c0 / c0_true - 1.0).abs() < 0.02, "negative initial concentration {c0:.0} vs {c0_true:.0}");
}

#[test]
fn g4_throughput_driven_negative_lam_is_named_by_its_own_law_spm() {
    // Blind batch g: PyBaMM's "current-driven" LAM in the negative electrode, d eps/dt =
    // -3e-8 |i| (i the current density, A/m^2), 4 full 1C CC-CV cycles at 35 degC, 30 s
    // logging. Its first run named it through the stress-driven law (4.2 % of 5.5 %, 3.58 mV
    // left) and a lithium stand-in; the throughput-driven law is now a candidate of its own.
    let rounds = run_case("diagnosis-extra/g4_lam_negative_current_driven_4_cycles_35C_30s_spm");
    let cellstudio::diagnose::Verdict::Found { candidate, .. } = rounds[0].verdict else { panic!("not found: {}", rounds[0].summary) };
    assert_eq!(candidate, Candidate::ActiveMaterialThroughput, "{}", rounds[0].summary);
    let k = first_fitted(&rounds, "lam.negative.current_rate");
    assert!((k / 3e-8 - 1.0).abs() < 0.02, "negative current-driven LAM rate {k:.4e} vs PyBaMM's 3e-8");
    assert!(!rounds.iter().skip(1).any(|d| d.found), "{}", report::conclusion(&rounds));
}

#[test]
fn d3_lithium_loss_and_an_unrelaxed_start_are_named_together_spm() {
    // Blind batch d: 11 % of the negative's lithium lost; the recording begins under C/3 right
    // after an unrecorded 30 min at 1C, the particles not relaxed. Its first run named the
    // lithium loss and left 7.99 mV at the start; a load before the first point is now a
    // candidate (a recording condition), and round 1 names both. The history's current and
    // duration trade against each other and against the concentrations it starts from; what
    // the recording fixes is the negative's lithium at its first point, the truth's 12672
    // mol/m^3 on average there.
    let name = "diagnosis-extra/d3_inventory_11pct_unrelaxed_mid_protocol_start_23C_spm";
    let rounds = run_case(name);
    assert_eq!(rounds[0].best().and_then(|c| c.partner), Some(Candidate::UnrelaxedStart), "{}", rounds[0].summary);
    let p = chen2020();
    let n = &p.negative;
    let charge = first_fitted(&rounds, "history.current") * first_fitted(&rounds, "history.duration");
    let at_start = first_fitted(&rounds, "negative.initial_concentration") - charge / (cellstudio::params::FARADAY * n.active_fraction * n.thickness * p.cell.area());
    assert!((at_start / 12672.0 - 1.0).abs() < 0.002, "negative concentration at the first point {at_start:.0} vs 12672");
    assert!(!rounds.iter().skip(1).any(|d| d.found), "{}", report::conclusion(&rounds));
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn g6_an_aged_electrolyte_under_a_noisy_current_channel_dfn() {
    // Blind batch g: electrolyte diffusivity x0.35 and conductivity x0.7 under a pseudo-random
    // binary current (4 s bits), the current channel carrying 25 mA of white noise. Read
    // sample by sample the noise made every second a table point (259 s, diffusivity 0.3504x,
    // 1.19 mV left); read as constant steps within the measured noise, 99 s, 0.3499x, 1.02 mV.
    let name = "diagnosis-extra/g6_electrolyte_aged_prbs_noisy_current_30C_dfn";
    let rounds = run_case(name);
    let d = first_fitted(&rounds, "electrolyte.diffusivity_factor");
    let k = first_fitted(&rounds, "electrolyte.conductivity_factor");
    assert!((d / 0.35 - 1.0).abs() < 0.005 && (k / 0.7 - 1.0).abs() < 0.005, "factors {d:.4} / {k:.4} vs 0.35 / 0.7");
    assert!(rounds[0].notes.iter().any(|n| n.contains("white noise")), "{:?}", rounds[0].notes);
}

#[test]
#[ignore = "slow for CI (73 s alone): the same pair, contact resistance with lithium loss, is b8 in CI; run with --include-ignored"]
fn g3_contact_and_lithium_loss_charging_from_empty_spme() {
    // Blind batch g: 6 mOhm contact resistance and 7 % of the negative's lithium lost, a
    // 0.5C CC-CV charge from empty at 5 degC. Its first run named the negative LAM alone and
    // then "unexplained": every pair led by lithium inventory started at the set's (full)
    // concentrations and broke the model. Started at the fitted empty state, the pair is
    // named in round 1.
    let name = "diagnosis-extra/g3_contact_and_inventory_charge_only_from_empty_5C_spme";
    let rounds = run_case(name);
    assert!(first_names_all(name, &rounds), "{}", rounds[0].summary);
    let r = first_fitted(&rounds, "cell.contact_resistance");
    assert!((r / 6e-3 - 1.0).abs() < 0.01, "contact resistance {:.3} mOhm vs 6", r * 1e3);
}

#[test]
#[ignore = "slow (3-4 min): CI skips it; run with --include-ignored, see the module doc"]
fn c1_electron_migration_sei_and_a_contact_are_named_together_spm() {
    // Blind batch c: SEI growth limited by electron migration through the film (8000x Chen
    // 2020's conductivity, 0.0053 mol = 0.142 A h of lithium over 4 CC-CV cycles at 43 degC)
    // with a 4 mOhm contact. With only the reaction-limited law its first run went through three
    // rounds of ties and stand-ins and left 5.03 mV; a law with transport through the film (its
    // growth slowing as it thickens, as electron migration's does) names the pair in round 1.
    let name = "diagnosis-extra/c1_sei_electron_migration_and_contact_4_cycles_43C_spm";
    let rounds = run_case(name);
    let best = rounds[0].best().expect("named");
    let pair = [Some(best.candidate), best.partner];
    assert!(pair.contains(&Some(Candidate::SeiGrowthSeries)) && pair.contains(&Some(Candidate::SeriesResistance)), "{}", rounds[0].summary);
    let contact = first_fitted(&rounds, "cell.contact_resistance");
    assert!((contact / 4e-3 - 1.0).abs() < 0.05, "contact {contact:.3e} Ohm vs 4e-3");
}

#[test]
#[ignore = "slow (3-4 min): CI skips it; run with --include-ignored, see the module doc"]
fn a1_ec_reaction_limited_sei_is_fitted_at_its_rates_spme() {
    // Blind batch a: PyBaMM's "ec reaction limited" SEI with both limits acting (rate constant
    // 1e-13 m/s, EC diffusivity 7e-19 m^2/s; 3.7 % of the lithium over 5 CC-CV cycles at 40
    // degC). The reaction-limited law stood in with a hysteresis beside it and left 3.46 mV;
    // the law with reaction and transport in series is named alone and fits both rates.
    let rounds = run_case("diagnosis-extra/a1_sei_ec_reaction_limited_5_cccv_cycles_40C_spme");
    assert_eq!(rounds[0].best().map(|c| (c.candidate, c.partner)), Some((Candidate::SeiGrowthSeries, None)), "{}", rounds[0].summary);
    let k = first_fitted(&rounds, "sei.kinetic_rate_constant");
    let d = first_fitted(&rounds, "sei.ec_diffusivity");
    assert!((k / 1e-13 - 1.0).abs() < 0.03 && (d / 7e-19 - 1.0).abs() < 0.03, "rate constant {k:.4e} vs 1e-13, EC diffusivity {d:.4e} vs 7e-19");
    assert!(!rounds.iter().skip(1).any(|r| r.found), "{}", report::conclusion(&rounds));
}

#[test]
#[ignore = "slow for CI (29 s alone): an unrelaxed start is named in CI by bb6 and d3; run with --include-ignored"]
fn c6_an_unrelaxed_start_left_below_the_floor_is_still_pointed_at_spme() {
    // Blind batch c: a 10 mA current offset and 8 % positive LAM named in round 1, in a
    // recording exported from the end of an unrecorded CC-CV charge. What remains (2.00 mV,
    // noise 1.0) sits at the start (55 % of its square), on training points: the held-out
    // residual leaves less than a named effect must remove, so round 2 names nothing, and says
    // where the remainder sits and what it likely is.
    let rounds = run_case("diagnosis-extra/c6_current_offset_10mA_and_lam_positive_rpt_unrelaxed_start_19C_cycler_spme");
    let last = rounds.last().unwrap();
    assert!(!last.found, "{}", last.summary);
    let words = report::verdict_in_words(last);
    assert!(words.starts_with("No missing physics") && words.contains("not at rest when the recording began"), "{words}");
}

#[test]
fn ab4_a_model_that_breaks_down_early_is_not_called_complete_spme() {
    // Blind batch ab: lumped self-heating (h = 10, recorded) through 3C fast charges from
    // 10 % SOC at 20 degC. The user's isothermal SPMe empties its electrolyte 28 s into the
    // first 3C charge and breaks down 628 s in; only the opening rest (3 % of the recording)
    // was left to diagnose, and its first run said "No missing physics". A model that
    // cannot follow the recording is not complete: the verdict is now unexplained and says
    // where it broke down. (The self-heating itself is not named: see the README.)
    let (t, rounds) = diagnose_case("diagnosis-extra/ab4_thermal_h10_recorded_fast_charge_cycles_20C_spme");
    let d = &rounds[0];
    let b = d.broke_down.as_ref().expect("the breakdown is recorded");
    assert!((b.at_s - 628.0).abs() < 2.0 && b.kept_points < b.recorded_points / 10, "{b:?}");
    assert!(matches!(d.verdict, cellstudio::diagnose::select::Verdict::BrokeDown), "{:?}: {}", d.verdict, d.summary);
    let words = report::verdict_in_words(d);
    assert!(words.starts_with("Unexplained: the user's model breaks down 628 s"), "{words}");
    assert!(!judged(&t, &rounds), "self-heating is not named yet; when it is, turn this into a judged case");
}

#[test]
fn ab8_a_particle_size_distribution_is_named_spm() {
    // Blind batch ab: PyBaMM's MPM (lognormal radii, relative spread 0.4 in both electrodes)
    // in a pulse-relaxation test at 15 degC, handed to the single-size SPM. Missed on its
    // first run (OCV hysteresis named at 24 mV, then 3.68 mV unexplained: the effect was not
    // a candidate); the size distribution is one now (the MPM on the SPM, within 7e-5 mV of
    // PyBaMM's).
    let rounds = run_case("diagnosis-extra/ab8_particle_size_distribution_pulse_relaxation_15C_spm");
    for side in ["negative", "positive"] {
        let s = first_fitted(&rounds, &format!("{side}.radius_relative_std"));
        assert!((s / 0.4 - 1.0).abs() < 0.01, "{side} radius spread {s:.4} vs PyBaMM's 0.4");
    }
}

#[test]
fn ac3_another_graphites_ocp_is_not_called_a_lithium_loss_at_the_stoichiometry_edge_spm() {
    // Blind batch ac: the negative's OCP is another graphite's (PyBaMM's Mohtat 2020), C/5
    // down and up at 30 degC, handed to the SPM with Chen 2020's. Outside the candidates: its
    // first run named lithium inventory with the negative starting at 0.99 of its maximum
    // concentration, the end of the search range. That is where the fit ran out of the OCP
    // curve, not a loss: implausible now. Whatever is named instead leaves tens of mV, and
    // the conclusion says the named effect explains only part of the recording.
    let (_, rounds) = diagnose_case("diagnosis-extra/ac3_negative_ocp_other_graphite_c5_cycle_30C_spm");
    let c_max = chen2020().negative.max_concentration;
    let edge = |c: &cellstudio::diagnose::CandidateOutcome| {
        let f = c.fit.as_ref()?;
        let x = f.values[f.names.iter().position(|n| n == "negative.initial_concentration")?] / c_max;
        Some(x > 0.989)
    };
    for d in &rounds {
        assert!(d.candidates.iter().filter(|c| c.named).all(|c| edge(c) != Some(true)), "an edge inventory is named: {}", d.summary);
    }
    let last = rounds.last().unwrap();
    assert!(!last.found && matches!(last.verdict, cellstudio::diagnose::select::Verdict::Unexplained), "{}", last.summary);
    let conclusion = report::conclusion(&rounds);
    assert!(conclusion.contains("part of the recording") || conclusion.starts_with("Conclusion: nothing named"), "{conclusion}");
}

#[test]
fn ad8_the_ocps_entropic_change_is_named_at_0_degc_spm() {
    // Blind batch ad: O'Regan 2022's dU/dT of the LG M50's graphite and NMC 811, which Chen
    // 2020 leaves at zero, concealed at 0 degC (constant power at low SOC, 0.5 mV noise).
    // Missed on its first run (lithium inventory +0.28 %, then unexplained: the OCP did not
    // depend on temperature here); the entropic change is a candidate now. Achieved: factors
    // 0.998 +- 0.011 and 1.016 +- 0.050 of O'Regan's, 1.69 -> 0.48 mV (noise 0.47).
    let rounds = run_case("diagnosis-extra/ad8_entropic_ocp_term_constant_power_low_soc_0C_spm");
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::EntropicChange));
    let (n, p) = (first_fitted(&rounds, "negative.ocp_entropic_change_factor"), first_fitted(&rounds, "positive.ocp_entropic_change_factor"));
    assert!((n - 1.0).abs() < 0.01 && (p - 1.0).abs() < 0.05, "factors {n:.4}, {p:.4} of the concealed 1, 1");
}

/// The share (-) of the negative's sites that a PyBaMM two-phase electrode's silicon holds:
/// volume fraction times maximum concentration, over both phases'.
fn silicon_share(graphite_fraction: f64, silicon_fraction: f64) -> f64 {
    let (graphite, silicon) = (graphite_fraction * chen2020().negative.max_concentration, silicon_fraction * 278000.0);
    silicon / (graphite + silicon)
}

/// The second material's share and potential (V vs Li) fitted in the first round.
fn second_material(rounds: &[Diagnosis]) -> (f64, f64) {
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::SecondMaterialNegative), "{}", rounds[0].summary);
    (first_fitted(rounds, "negative.second_phase_share"), first_fitted(rounds, "negative.second_phase_potential"))
}

#[test]
fn j7_a_graphite_silicon_negative_is_a_second_material_spme() {
    // Blind batch j: PyBaMM's two-phase negative (graphite at 0.65 with 1.2 % silicon, Chen
    // 2020 composite's Mark 2016 silicon OCP) handed to the graphite-only SPMe, C/5 down and
    // C/2 CC-CV up at 25 degC. Unexplained (106.90 mV) until a second material was a
    // candidate. Silicon's OCP read as one logistic of the potential sits at 0.312 V (92 mV
    // wide). Achieved: share 0.148 (the truth's 0.148), 0.317 V, 106.90 -> 10.04 mV.
    let rounds = run_case("diagnosis-extra/j7_graphite_silicon_composite_negative_c5_spme");
    let (share, u0) = second_material(&rounds);
    let truth = silicon_share(0.65, 0.012);
    assert!((share / truth - 1.0).abs() < 0.25 && (0.25..0.4).contains(&u0), "share {share:.3} (truth {truth:.3}) at {u0:.3} V");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn ae8_a_graphite_silicon_negative_is_a_second_material_at_5_degc_spm() {
    // Blind batch ae: the two-phase negative (graphite at 0.66 with 1.1 % silicon) at 5 degC,
    // 1C then C/5 to 2.6 V, C/3 charge, long rests, handed to the SPM. Missed on its first
    // run (unexplained, 195.88 mV); the candidate was written after it. Achieved: share 0.121
    // (truth 0.135), 0.311 V, 195.88 -> 13.14 mV.
    let rounds = run_case("diagnosis-extra/ae8_graphite_silicon_composite_negative_low_soc_5C_30s_spm");
    let (share, u0) = second_material(&rounds);
    let truth = silicon_share(0.66, 0.011);
    assert!((share / truth - 1.0).abs() < 0.25 && (0.25..0.4).contains(&u0), "share {share:.3} (truth {truth:.3}) at {u0:.3} V");
}

#[test]
#[ignore = "slow (under a minute): CI skips it; run with --include-ignored, see the module doc"]
fn af1_a_contact_in_a_ups_float_with_two_outages_spm() {
    // Blind batch af (eighteenth session, named on its first run): a 3 mOhm contact at 40 degC,
    // a charge held at 4.1 V and two outages (2C then 1C, 1.5C), 5 s, 2 mV noise. A tie with
    // kinetics (11 load levels whose overpotentials stay linear in the current). Achieved:
    // 3.00 +- 0.02 mOhm, 7.83 -> 2.01 mV.
    let rounds = run_case("diagnosis-extra/af1_contact_3mOhm_ups_float_two_outages_40C_5s_2mV_spm");
    let r = first_fitted(&rounds, "cell.contact_resistance");
    assert!((r / 3e-3 - 1.0).abs() < 0.02, "contact resistance {:.3} mOhm vs 3", r * 1e3);
}

#[test]
#[ignore = "slow (1 min): CI skips it; run with --include-ignored, see the module doc"]
fn af3_negative_lam_of_delithiated_material_keeps_its_lithium_dfn() {
    // Blind batch af: 7 % of the negative's material lost with the cyclable lithium kept (moved
    // into the positive), a step-down charge from empty at 12 degC, DFN. Missed on its first run
    // ("unexplained", 7.12 mV, noise 1.00): the LAM candidate took the lost material's lithium
    // along (PyBaMM's plain volume-fraction change, at the set's initial state). Named since
    // the LAM candidate fits the state of charge at which the material was lost: negative
    // fraction 0.6986 (truth 0.6975), lost at -0.029 ± 0.002, the negative empty (the lower
    // end of the range, where the lost material holds no lithium), 7.12 -> 1.04 mV.
    let rounds = run_case("diagnosis-extra/af3_lam_negative_7pct_step_down_charge_from_empty_12C_5s_dfn");
    let eps = first_fitted(&rounds, "negative.active_fraction");
    assert!((eps / 0.6975 - 1.0).abs() < 0.005, "negative active fraction {eps:.4} vs 0.6975");
    let (_, empty, _) = cellstudio::problem::lost_lithium::loss_soc_range(&chen2020());
    let s = first_fitted(&rounds, cellstudio::problem::lost_lithium::LOSS_SOC);
    assert!((s - empty).abs() < 0.01, "lost at state of charge {s:.4}, the negative empty at {empty:.4}");
}

#[test]
#[ignore = "slow (1-2 min): CI skips it; run with --include-ignored, see the module doc"]
fn af7_positive_lam_and_positive_kinetics_are_named_together_spm() {
    // Blind batch af (named on its first run): 7 % of the positive's material lost with its
    // lithium and the positive exchange current halved, a pulsed discharge at 20 degC, SPM.
    // Achieved: positive fraction 0.6184 (truth 0.6185), positive rate 1.694e-6 (truth
    // 1.71e-6), 18.11 -> 1.20 mV (noise 1.20).
    let rounds = run_case("diagnosis-extra/af7_lam_positive_7pct_and_kinetics_positive_x0p5_pulsed_discharge_20C_3s_spm");
    let eps = first_fitted(&rounds, "positive.active_fraction");
    let k = first_fitted(&rounds, "positive.rate_constant");
    let (eps_truth, k_truth) = (0.93 * chen2020().positive.active_fraction, 0.5 * chen2020().positive.rate_constant);
    assert!((eps / eps_truth - 1.0).abs() < 0.003, "positive active fraction {eps:.4} vs {eps_truth:.4}");
    assert!((k / k_truth - 1.0).abs() < 0.05, "positive rate constant {k:.4e} vs {k_truth:.4e}");
}

#[test]
fn a_diagnosis_stopped_at_its_round_limit_says_the_rest_was_not_diagnosed() {
    // ac3 (another graphite's OCP) limited to one round: round 1 names a stand-in that leaves
    // tens of mV; the conclusion must not say it explains the recording.
    let name = "diagnosis-extra/ac3_negative_ocp_other_graphite_c5_cycle_30C_spm";
    let t = truth(name);
    let rec = Recording::from_csv(&case_dir(name).join("recording.csv")).unwrap();
    let mut p = chen2020();
    p.thermal.ambient_temperature = t.ambient;
    p.thermal.initial_temperature = t.ambient;
    let rounds = diagnose_rounds(&rec, &p, &DiagnoseOptions::new(ModelSpec::new(t.model, Submodels::default())), 1).unwrap();
    assert!(rounds[0].found && rounds[0].cut_short.is_some(), "{}", rounds[0].summary);
    let conclusion = report::conclusion(&rounds);
    assert!(conclusion.contains("part of the recording") && conclusion.contains("was not diagnosed") && conclusion.contains("round limit (--max-rounds 1)"), "{conclusion}");
}

// Blind batch ah (twenty-fifth session; a helper made it with `scripts/make_unseen_cases.py
// ah` without reading `src/diagnose`, and judged the binary of 38c2d6d once: 7 of 8). Slow
// (1-7 min each, DFN drives and long duties): CI skips them.

#[test]
#[ignore = "slow (blind batch ah): CI skips it; run with --include-ignored"]
fn ah1_negative_control_circular_saw_cuts_at_minus_3_degc_spm() {
    run_case("diagnosis-extra/ah1_control_circular_saw_cuts_minus3C_1s_spm");
}

#[test]
#[ignore = "slow (blind batch ah): CI skips it; run with --include-ignored"]
fn ah2_negative_hysteresis_under_frequency_regulation_spme() {
    run_case("diagnosis-extra/ah2_hysteresis_negative_12mV_frequency_regulation_27C_5s_spme");
}

#[test]
#[ignore = "slow (blind batch ah): CI skips it; run with --include-ignored"]
fn ah3_positive_active_material_loss_in_a_forklift_shift_dfn() {
    run_case("diagnosis-extra/ah3_lam_positive_10pct_forklift_shift_cold_store_charger_6C_3s_dfn");
}

#[test]
#[ignore = "slow (blind batch ah): CI skips it; run with --include-ignored"]
fn ah4_contact_and_self_heating_in_evtol_hops_spme() {
    run_case("diagnosis-extra/ah4_contact_3mOhm_and_thermal_h8_recorded_evtol_hops_39C_2s_spme");
}

#[test]
#[ignore = "slow (blind batch ah): CI skips it; run with --include-ignored"]
fn ah5_lithium_inventory_in_ferry_crossings_dfn_data_to_spme() {
    run_case("diagnosis-extra/ah5_inventory_8pct_ferry_crossings_shore_charging_9C_10s_dfn_data_spme");
}

#[test]
#[ignore = "slow (blind batch ah): CI skips it; run with --include-ignored"]
fn ah6_kinetics_of_both_electrodes_in_a_dc_fast_charge_dfn() {
    run_case("diagnosis-extra/ah6_kinetics_both_x0p6_ev_dc_fast_charge_highway_34C_1s_2mV_dfn");
}

#[test]
#[ignore = "slow (blind batch ah): CI skips it; run with --include-ignored"]
fn ah7_negative_diffusivity_and_lithium_loss_in_hppc_dfn() {
    run_case("diagnosis-extra/ah7_diffusivity_negative_x0p2_and_inventory_5pct_hppc_seven_soc_19C_2s_dfn");
}

#[test]
#[ignore = "slow (blind batch ah): CI skips it; run with --include-ignored"]
fn ah8_a_voltage_channel_reading_low_at_a_telecom_site_spm() {
    run_case("diagnosis-extra/ah8_voltage_channel_gain_0p4pct_low_telecom_site_constant_power_42C_30s_spm");
}

#[test]
fn ai1_negative_control_underwater_glider_survey_dfn() {
    run_case("diagnosis-extra/ai1_control_underwater_glider_survey_4C_60s_0p3mV_dfn");
}

#[test]
#[ignore = "slow (blind batch ai): CI skips it; run with --include-ignored"]
fn ai2_transference_number_in_a_race_car_stint_dfn() {
    run_case("diagnosis-extra/ai2_transference_number_0p38_race_car_stint_38C_1s_2mV_dfn");
}

#[test]
#[ignore = "slow (blind batch ai): CI skips it; run with --include-ignored"]
fn ai3_positive_electrode_conductivity_in_a_golf_cart_round_spme() {
    run_case("diagnosis-extra/ai3_positive_conductivity_x0p2_golf_cart_round_15C_5s_spme");
}

#[test]
#[ignore = "slow (blind batch ai): CI skips it; run with --include-ignored"]
fn ai4_positive_diffusivity_on_a_snowmobile_trail_dfn_data_to_spme() {
    run_case("diagnosis-extra/ai4_diffusivity_positive_x0p35_snowmobile_trail_minus5C_2s_dfn_data_spme");
}

#[test]
fn ai5_lithium_inventory_over_two_days_of_peak_shaving_spm() {
    run_case("diagnosis-extra/ai5_inventory_6pct_peak_shaving_two_days_30C_30s_1p5mV_spm");
}

#[test]
#[ignore = "slow (blind batch ai): CI skips it; run with --include-ignored"]
fn ai6_self_heating_of_shared_scooter_rides_dfn() {
    run_case("diagnosis-extra/ai6_thermal_h12_recorded_shared_scooter_rides_10C_3s_0p8mV_dfn");
}

#[test]
#[ignore = "slow (blind batch ai): CI skips it; run with --include-ignored"]
fn ai7_sei_film_and_the_lithium_it_took_in_a_city_bus_spm() {
    run_case("diagnosis-extra/ai7_sei_film_and_inventory_5pct_city_bus_pantograph_45C_10s_3mV_spm");
}

#[test]
fn ai8_voltage_offset_and_positive_lam_in_an_oxygen_concentrator_spme() {
    run_case("diagnosis-extra/ai8_voltage_offset_8mV_low_and_lam_positive_7pct_oxygen_concentrator_22C_20s_0p5mV_spme");
}

// Blind batch aj (twenty-seventh session): named 7 of 8 at its first run (binary of 3f3ee7a).

#[test]
fn aj1_control_of_a_sonar_buoy_solar_day_spme() {
    run_case("diagnosis-extra/aj1_control_sonar_buoy_solar_day_8C_20s_0p6mV_spme");
}

#[test]
#[ignore = "slow (blind batch aj): CI skips it; run with --include-ignored"]
fn aj2_contact_resistance_of_a_weeding_robot_spm() {
    run_case("diagnosis-extra/aj2_contact_4mOhm_weeding_robot_trailer_charge_27C_5s_spm");
}

#[test]
fn aj3_lithium_inventory_in_a_rail_signalling_outage_at_minus_8_degc_spme() {
    run_case("diagnosis-extra/aj3_inventory_7pct_rail_signalling_backup_outage_minus8C_30s_spme");
}

#[test]
fn aj4_negative_lam_over_a_tattoo_pen_day_and_cccv_charge_spm() {
    run_case("diagnosis-extra/aj4_lam_negative_10pct_tattoo_pen_day_cccv_23C_cycler_1p5mV_spm");
}

#[test]
#[ignore = "slow: 90 s (the ambient changes during the recording; named as the temperature dependence at the recorded temperature, 14.27 -> 0.97 mV)"]
fn aj5_ambient_temperature_change_on_a_wheelchair_outing_dfn() {
    let rounds = run_case("diagnosis-extra/aj5_ambient_change_wheelchair_outing_in_frost_21C_to_minus4C_recorded_10s_dfn");
    // No constant ambient gives the cell's course: the temperature is read, not predicted.
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::RecordedTemperature), "{}", rounds[0].summary);
}

#[test]
#[ignore = "slow (blind batch aj): CI skips it; run with --include-ignored"]
fn aj6_negative_kinetics_in_a_defibrillator_rescue_dfn() {
    run_case("diagnosis-extra/aj6_kinetics_negative_x0p4_aed_rescue_street_cabinet_3C_1s_2p5mV_dfn");
}

#[test]
#[ignore = "slow (blind batch aj): CI skips it; run with --include-ignored"]
fn aj7_aged_electrolyte_on_an_electric_outboard_trip_dfn() {
    run_case("diagnosis-extra/aj7_electrolyte_aged_diffusivity_x0p6_conductivity_x0p7_electric_outboard_14C_2s_0p3mV_dfn");
}

#[test]
#[ignore = "slow (blind batch aj): CI skips it; run with --include-ignored"]
fn aj8_self_heating_with_slow_positive_diffusion_in_a_cordless_vacuum_spme() {
    run_case("diagnosis-extra/aj8_thermal_h5_recorded_and_diffusivity_positive_x0p5_cordless_vacuum_30C_3s_3mV_spme");
}

// Blind batch ak (twenty-eighth session, judged once on the binary of 38e7b5a: 7 of 8 as
// judged, 6 on substance).

#[test]
fn ak1_negative_control_on_a_telescope_mount_at_minus_10_degc_spm() {
    run_case("diagnosis-extra/ak1_control_telescope_mount_imaging_night_minus10C_60s_0p5mV_spm");
}

#[test]
#[ignore = "slow (blind batch ak): CI skips it; run with --include-ignored"]
fn ak2_negative_diffusivity_under_concert_lighting_spme() {
    run_case("diagnosis-extra/ak2_diffusivity_negative_x0p35_stage_lighting_concert_26C_3s_0p5mV_spme");
}

#[test]
fn ak3_lithium_inventory_over_a_miner_cap_lamp_shift_spm() {
    run_case("diagnosis-extra/ak3_inventory_9pct_miner_cap_lamp_shift_33C_cycler_spm");
}

#[test]
#[ignore = "slow (blind batch ak): CI skips it; run with --include-ignored"]
fn ak4_positive_lam_in_a_drone_light_show_spme() {
    run_case("diagnosis-extra/ak4_lam_positive_12pct_drone_swarm_light_show_12C_1s_2mV_spme");
}

#[test]
#[ignore = "slow (blind batch ak): CI skips it; run with --include-ignored"]
fn ak5_positive_kinetics_over_ventilator_breaths_dfn() {
    run_case("diagnosis-extra/ak5_kinetics_positive_x0p3_ventilator_mains_failure_breaths_18C_1s_1p5mV_dfn");
}

#[test]
#[ignore = "slow (blind batch ak): CI skips it; run with --include-ignored"]
fn ak6_self_heating_of_an_ice_resurfacer_dfn() {
    let rounds = run_case("diagnosis-extra/ak6_thermal_h7_recorded_ice_resurfacer_rink_5C_5s_0p8mV_dfn");
    // The heat balance predicts the recorded temperature: self-heating, not a read temperature.
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::Thermal), "{}", rounds[0].summary);
}

#[test]
#[ignore = "fails (open; a flawed case): besides graphite's charge-transfer coefficient 0.4 the recording holds PyBaMM's algebraic-surface-form SPMe, another model (10.2 mV RMS of its own, see truth.json); kinetics with electrolyte factors stands in (9.27 -> 2.71 mV), round 2 names self-heating at h = 82 without a recorded temperature, round 3 ends unexplained at 2.04 mV (noise 1.07): a 4.5x cut against the 5x goal. The clean remake is ak7d"]
fn ak7_asymmetric_negative_charge_transfer_on_a_paraglider_winch_spme() {
    run_case("diagnosis-extra/ak7_asymmetric_charge_transfer_negative_alpha0p4_paraglider_tow_winch_2C_10s_spme");
}

/// ak7 remade cleanly in the DFN (not blind; see its truth.json and docs/diagnosis-cases.md):
/// graphite's anodic transfer coefficient 0.4. The kinetics candidate, refined with the
/// transfer coefficients free before any pair is tried: 0.3995 +- 0.0012 (the positive's
/// 0.5002 +- 0.0071), 14.14 -> 0.98 mV (noise 1.06 mV), then no missing physics, in 27 s.
/// Without the refinement: kinetics with a contact stand-in, 2.22 mV left, 21 min.
#[test]
#[ignore = "slow (1-2 min): CI skips it since the thirty-eighth session (CI ran 1,710 s of its 1,800); run with --include-ignored"]
fn ak7d_asymmetric_negative_charge_transfer_in_the_dfn() {
    let rounds = run_case("diagnosis-extra/ak7d_asymmetric_charge_transfer_negative_alpha0p4_paraglider_tow_winch_2C_10s_dfn");
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::Kinetics), "{}", rounds[0].summary);
    let alpha = first_fitted(&rounds, "negative.charge_transfer_coefficient");
    assert!((alpha - 0.4).abs() < 0.005, "negative transfer coefficient {alpha} (truth 0.4)");
}

#[test]
#[ignore = "fails (open): a 6 mV voltage offset beside 6 % lithium lost at 3 mV noise; the lithium loss is named (tied with a second negative material) and absorbs most of the offset, leaving 3.36 mV against 3.04 mV noise, below what a second effect must remove; the first judging passed it only because the accept word 'offset' matched 'stoichiometry offset' (now 'voltage offset')"]
fn ak8_voltage_offset_and_lithium_loss_on_a_street_food_cart_spme() {
    run_case("diagnosis-extra/ak8_voltage_offset_6mV_high_and_inventory_6pct_street_food_cart_45C_15s_3mV_spme");
}

// Blind batch al (thirtieth session, judged once on the binary of c79e8e9: 7 of 8; al5 missed,
// named since the held-out blocks follow the misfit).

#[test]
fn al1_negative_control_of_a_home_stairlift_spm() {
    run_case("diagnosis-extra/al1_control_home_stairlift_day_19C_cycler_spm");
}

#[test]
#[ignore = "slow (blind batch al): CI skips it; run with --include-ignored"]
fn al2_contact_resistance_of_an_e_rickshaw_at_44_degc_spm() {
    run_case("diagnosis-extra/al2_contact_5mOhm_erickshaw_fares_midday_charge_44C_5s_2mV_spm");
}

#[test]
#[ignore = "slow (blind batch al): CI skips it; run with --include-ignored"]
fn al3_faster_negative_kinetics_on_a_refuse_truck_round_dfn() {
    run_case("diagnosis-extra/al3_kinetics_negative_x1p6_faster_refuse_truck_round_13C_2s_dfn");
}

#[test]
#[ignore = "slow (blind batch al): CI skips it; run with --include-ignored"]
fn al4_finer_positive_particles_on_mobile_x_ray_rounds_dfn() {
    run_case("diagnosis-extra/al4_radius_positive_x0p75_mobile_xray_ward_rounds_24C_1s_1p5mV_dfn");
}

/// The misfit lies mostly in the closing charge, which the default held-out blocks (3 and 7)
/// miss: they held 0.72 mV against 0.52 mV of noise, and the diagnosis called a 3.73 mV misfit
/// noise. Held-out blocks that see the misfit confirm the electrolyte at its factors.
#[test]
fn al5_a_better_electrolyte_in_a_camper_van_winter_night_spme() {
    let rounds = run_case("diagnosis-extra/al5_electrolyte_conductivity_x1p8_diffusivity_x1p5_camper_van_winter_night_minus1C_10s_0p5mV_spme");
    assert_ne!(rounds[0].holdout_phase, 2, "{}", rounds[0].summary);
    let (d, k) = (first_fitted(&rounds, "electrolyte.diffusivity_factor"), first_fitted(&rounds, "electrolyte.conductivity_factor"));
    assert!((d - 1.5).abs() < 0.015 && (k - 1.8).abs() < 0.03, "diffusivity x{d:.4} (truth 1.5), conductivity x{k:.4} (truth 1.8)");
}

#[test]
fn al6_self_heating_of_a_snow_blower_at_minus_10_degc_spme() {
    run_case("diagnosis-extra/al6_thermal_h12_recorded_snow_blower_frost_minus10C_3s_3mV_spme");
}

#[test]
#[ignore = "slow (blind batch al): CI skips it; run with --include-ignored"]
fn al7_negative_hysteresis_and_positive_diffusivity_on_a_scissor_lift_spm() {
    run_case("diagnosis-extra/al7_hysteresis_negative_10mV_and_diffusivity_positive_x0p6_scissor_lift_shift_6C_20s_0p8mV_spm");
}

#[test]
#[ignore = "slow (blind batch al): CI skips it; run with --include-ignored"]
fn al8_positive_electrode_conductivity_and_lithium_loss_in_a_pool_robot_dfn() {
    run_case("diagnosis-extra/al8_positive_conductivity_x0p25_and_inventory_6pct_pool_robot_32C_60s_1p5mV_dfn");
}

// Blind batch am (thirtieth session, judged once on the binary of ccc3273 under a load of 5-6
// on 2 cores; see docs/diagnosis-cases.md).

#[test]
fn am1_negative_control_of_an_ice_fishing_auger_at_minus_15_degc_spme() {
    run_case("diagnosis-extra/am1_control_ice_fishing_auger_day_minus15C_cycler_spme");
}

#[test]
fn am2_faster_positive_kinetics_in_a_barn_feed_pusher_spm() {
    run_case("diagnosis-extra/am2_kinetics_positive_x1p8_faster_barn_feed_pusher_robot_minus8C_1s_0p5mV_spm");
}

/// A negative radius x2 moves the diffusion time and the surface per volume at once: kinetics
/// and then the diffusivity were named in two rounds until the radius was a candidate.
#[test]
#[ignore = "slow (blind batch am, 2-3 min): CI skips it; run with --include-ignored"]
fn am3_coarser_negative_particles_in_a_patient_hoist_dfn() {
    let rounds = run_case("diagnosis-extra/am3_radius_negative_x2_care_home_patient_hoist_28C_5s_1p5mV_dfn");
    let r = first_fitted(&rounds, "negative.particle_radius") / chen2020().negative.particle_radius;
    assert!((r - 2.0).abs() < 0.03, "negative radius x{r:.4} (truth 2)");
}

/// A positive electrode 8 % thicker is more capacity and more lithium: a gain the loss
/// candidate cannot fit (a leak with the diffusivities stood in, 12.09 -> 5.48 mV) until a
/// heavier coating was a candidate.
#[test]
fn am4_a_heavier_positive_coating_on_a_harvest_trolley_spme() {
    let rounds = run_case("diagnosis-extra/am4_thickness_positive_x1p08_greenhouse_harvest_trolley_36C_30s_2mV_spme");
    // Achieved 81.67 um for the truth's 81.65 (2.6e-4 of the set's 75.6 um).
    let l = first_fitted(&rounds, "positive.thickness");
    assert!((l - 81.65e-6).abs() < 1e-3 * chen2020().positive.thickness, "positive thickness {l:.4e} m (truth 8.165e-5)");
}

#[test]
#[ignore = "slow (blind batch am): no verdict within the judge's 900 s under a load of 5-6; at a load of 2-3 round 1 names the electrolyte transport properties (factors 0.77, 0.82 for the more tortuous negative), 12.70 -> 1.95 mV, within 9 min"]
fn am5_a_more_tortuous_negative_under_a_mini_excavator_dfn() {
    run_case("diagnosis-extra/am5_tortuosity_negative_bruggeman1p8_mini_excavator_trench_10C_2s_1mV_dfn");
}

#[test]
#[ignore = "slow (blind batch am): CI skips it; run with --include-ignored"]
fn am6_lithium_inventory_in_a_solar_vaccine_fridge_at_45_degc_spm() {
    run_case("diagnosis-extra/am6_inventory_6pct_solar_vaccine_fridge_night_45C_60s_3mV_spm");
}

#[test]
#[ignore = "fails (open): the positive electrode's conductivity x0.4 beside self-heating (h = 10, recorded) at 2 degC; round 1 named kinetics with thermal (the electrode's ohmic drop read as kinetics), and the judge's 900 s ran out under a load of 5-6 before a later round"]
fn am7_positive_electrode_conductivity_and_self_heating_in_a_sheep_shearing_handpiece_dfn() {
    run_case("diagnosis-extra/am7_positive_conductivity_x0p4_and_thermal_h10_recorded_sheep_shearing_2C_10s_0p8mV_dfn");
}

/// 30 % less salt beside 6 % lithium lost: kinetics stood in for the salt (the exchange
/// current goes as its square root) until the salt concentration was a candidate.
#[test]
#[ignore = "slow (blind batch am, 2-3 min): CI skips it; run with --include-ignored"]
fn am8_less_salt_and_lithium_loss_in_a_floor_scrubber_spme() {
    let rounds = run_case("diagnosis-extra/am8_electrolyte_salt_x0p7_and_inventory_6pct_floor_scrubber_20C_15s_1p2mV_spme");
    let c = first_fitted(&rounds, "electrolyte.initial_concentration") / chen2020().electrolyte.initial_concentration;
    assert!((c - 0.7).abs() < 0.015, "salt x{c:.4} (truth 0.7)");
}

// Blind batch an (thirty-fourth session, `scripts/make_unseen_cases.py` key "an", made by a
// helper session that did not read the diagnosis code): 7 of 8 named on first sight by the
// shared bench's judge (docs/diagnosis-cases.md).

#[test]
#[ignore = "blind batch an: CI skips it; run with --include-ignored"]
fn an1_negative_control_of_an_airport_baggage_tug_dfn() {
    run_case("diagnosis-extra/an1_control_airport_baggage_tug_16C_5s_dfn");
}

#[test]
#[ignore = "blind batch an: CI skips it; run with --include-ignored"]
fn an2_negative_active_material_loss_on_a_cargo_bike_round_spme() {
    run_case("diagnosis-extra/an2_lam_negative_9pct_cargo_bike_parcel_round_27C_cycler_1p5mV_spme");
}

#[test]
#[ignore = "slow (blind batch an, 6-7 min): CI skips it; run with --include-ignored"]
fn an3_slow_negative_diffusion_in_a_chainsaw_in_the_frost_dfn() {
    run_case("diagnosis-extra/an3_diffusivity_negative_x0p3_arborist_chainsaw_frost_minus5C_2s_0p8mV_dfn");
}

#[test]
#[ignore = "blind batch an: CI skips it; run with --include-ignored"]
fn an4_lithium_inventory_of_a_yacht_house_battery_at_34_degc_spm() {
    run_case("diagnosis-extra/an4_inventory_5pct_yacht_house_battery_anchorage_34C_20s_2mV_spm");
}

#[test]
#[ignore = "blind batch an: CI skips it; run with --include-ignored"]
fn an5_contact_resistance_of_a_hedge_trimmer_at_4_degc_spme() {
    run_case("diagnosis-extra/an5_contact_3mOhm_hedge_trimmer_van_charge_4C_10s_spme");
}

#[test]
#[ignore = "slow (blind batch an, 2 min): CI skips it; run with --include-ignored"]
fn an6_an_aged_electrolyte_in_a_power_barrow_at_40_degc_dfn() {
    run_case("diagnosis-extra/an6_electrolyte_conductivity_x0p4_diffusivity_x0p5_power_barrow_40C_3s_1p2mV_dfn");
}

#[test]
#[ignore = "blind batch an: CI skips it; run with --include-ignored"]
fn an7_voltage_offset_and_self_heating_on_an_efoil_spme() {
    run_case("diagnosis-extra/an7_voltage_offset_5mV_low_and_thermal_h15_recorded_efoil_session_18C_1s_spme");
}

#[test]
#[ignore = "slow for CI (blind batch an, 86 s): the leak is named in CI by l4; run with --include-ignored"]
fn an8_leak_and_slow_negative_kinetics_on_a_mobility_scooter_dfn() {
    // Missed at first sight: the leak fitted 59.5 mA to the noise but was refused beyond C/100.
    // A leak that discharges the cell (a soft short) is now plausible to C/50, and a leak must
    // fit the rests, which keeps it from standing in for the real LG M50 files' OCV mismatch.
    let rounds = run_case("diagnosis-extra/an8_leak_60mA_and_kinetics_negative_x0p35_mobility_scooter_outing_10C_5s_0p8mV_dfn");
    let leak = first_fitted(&rounds, "cell.leakage_current");
    assert!((leak / 0.06 - 1.0).abs() < 0.02, "leak {leak} A: {}", rounds[0].summary);
}

// Blind batch ao (thirty-fifth session, `scripts/make_unseen_cases.py` key "ao", made by a
// helper that did not read the diagnosis code; judged once with `../shared/tools/diagnosis-bench`
// on the binary of 776d669 before anyone read the truths: 7 of 8).

#[test]
#[ignore = "blind batch ao: CI skips it; run with --include-ignored"]
fn ao1_negative_control_of_a_hospital_bed_backup_spm() {
    run_case("diagnosis-extra/ao1_control_hospital_bed_backup_battery_22C_2s_0p5mV_spm");
}

#[test]
#[ignore = "blind batch ao: CI skips it; run with --include-ignored"]
fn ao2_positive_active_material_loss_on_an_electric_kayak_dfn() {
    run_case("diagnosis-extra/ao2_lam_positive_10pct_electric_kayak_14C_5s_dfn");
}

#[test]
#[ignore = "blind batch ao: CI skips it; run with --include-ignored"]
fn ao3_a_large_leak_between_a_robot_mowers_dock_charges_spm() {
    // A 120 mA leak (C/42): named at first sight on the search's bound then, C/50; now searched
    // to C/20 when it discharges the cell.
    let rounds = run_case("diagnosis-extra/ao3_leak_120mA_robot_mower_dock_charges_26C_20s_1p5mV_spm");
    let leak = first_fitted(&rounds, "cell.leakage_current");
    assert!((leak / 0.12 - 1.0).abs() < 0.02, "leak {leak} A: {}", rounds[0].summary);
}

#[test]
#[ignore = "blind batch ao: CI skips it; run with --include-ignored"]
fn ao4_slow_positive_kinetics_on_a_cable_car_recovery_at_minus_10_degc_spme() {
    run_case("diagnosis-extra/ao4_kinetics_positive_x0p3_cable_car_recovery_drive_minus10C_1s_spme");
}

#[test]
#[ignore = "blind batch ao: CI skips it; run with --include-ignored"]
fn ao5_self_heating_of_a_backpack_leaf_blower_spme() {
    run_case("diagnosis-extra/ao5_thermal_h14_recorded_backpack_leaf_blower_8C_2s_0p8mV_spme");
}

#[test]
#[ignore = "blind batch ao: CI skips it; run with --include-ignored"]
fn ao6_leak_and_contact_resistance_in_vaporiser_puffs_spme() {
    run_case("diagnosis-extra/ao6_leak_80mA_and_contact_8mOhm_boxmod_vaporiser_puffs_24C_1s_0p7mV_spme");
}

#[test]
#[ignore = "fails (open): a 6 mV voltage offset beside positive diffusivity x0.3; round 1 names the diffusivities (39.05 -> 1.46 mV, noise 1.25) and the fitted initial state of charge takes up the offset, so what is left is below what a named effect must remove"]
fn ao7_positive_diffusivity_and_voltage_offset_on_a_catenary_free_tram_dfn() {
    run_case("diagnosis-extra/ao7_diffusivity_positive_x0p3_and_voltage_offset_6mV_high_tram_catenary_free_20C_3s_1p2mV_dfn");
}

#[test]
#[ignore = "blind batch ao: CI skips it; run with --include-ignored"]
fn ao8_lithium_inventory_of_home_storage_in_a_heatwave_dfn() {
    run_case("diagnosis-extra/ao8_inventory_7pct_home_storage_evening_peak_heatwave_45C_30s_2mV_dfn");
}

// Blind batch ap (thirty-sixth session, made by a helper that did not read the diagnosis code,
// judged once on the binary of ff69e7f before anyone read the truths: 5 of 8; ap4, ap7 and ap8
// named since, see docs/diagnosis-cases.md).

#[test]
#[ignore = "blind batch ap: CI skips it; run with --include-ignored"]
fn ap1_negative_control_of_a_buffered_fast_charger_on_a_weak_grid_spme() {
    run_case("diagnosis-extra/ap1_control_buffered_ev_fast_charger_weak_grid_41C_5s_spme");
}

#[test]
#[ignore = "blind batch ap: CI skips it; run with --include-ignored"]
fn ap2_negative_active_material_loss_on_a_vineyard_straddle_tractor_spme() {
    run_case("diagnosis-extra/ap2_lam_negative_8pct_vineyard_straddle_tractor_12C_10s_2mV_spme");
}

#[test]
#[ignore = "blind batch ap: CI skips it; run with --include-ignored"]
fn ap3_aged_electrolyte_in_a_rescue_drill_at_minus_5_degc_dfn() {
    run_case("diagnosis-extra/ap3_electrolyte_aged_x0p5_rescue_tools_drill_minus5C_3s_1p2mV_dfn");
}

/// Hysteresis with rests after charges only, the load swinging its state 0.55 down and 0.72
/// up: refused as not identifiable at first sight (a particle-size spread stood in), named
/// since the swing counts each way.
#[test]
fn ap4_negative_hysteresis_under_solar_ramp_rate_control_spm() {
    let rounds = run_case("diagnosis-extra/ap4_hysteresis_negative_10mV_solar_ramp_rate_control_21C_15s_0p8mV_spm");
    let h = first_fitted(&rounds, "cell.hysteresis_voltage");
    assert!((h / 0.01 - 1.0).abs() < 0.05, "hysteresis half-width {h} V (truth 0.01): {}", rounds[0].summary);
}

#[test]
#[ignore = "blind batch ap: CI skips it; run with --include-ignored"]
fn ap5_slow_negative_diffusion_in_a_recycling_yard_wheel_loader_dfn() {
    run_case("diagnosis-extra/ap5_diffusivity_negative_x0p3_recycling_yard_wheel_loader_7C_1s_0p6mV_dfn");
}

#[test]
#[ignore = "blind batch ap: CI skips it; run with --include-ignored"]
fn ap6_unrecorded_self_heating_of_an_indoor_kart_spme() {
    run_case("diagnosis-extra/ap6_thermal_h10_unrecorded_indoor_electric_karting_17C_2s_spme");
}

/// A 100 mA leak beside self-heating, temperature recorded, logged every 20 s over 10-25 s
/// steps: until the temperature's weight was read over the usable points the voltage's "noise"
/// read 185 mV, the temperature outweighed the voltage and the pair fitted 2.49 mV.
#[test]
#[ignore = "blind batch ap (about 90 s): CI skips it; run with --include-ignored"]
fn ap7_leak_and_self_heating_of_a_container_gantry_crane_spm() {
    let rounds = run_case("diagnosis-extra/ap7_leak_100mA_and_thermal_h8_recorded_container_gantry_crane_2C_20s_spm");
    let leak = first_fitted(&rounds, "cell.leakage_current");
    assert!((leak / 0.1 - 1.0).abs() < 0.02, "leak {leak} A (truth 0.1): {}", rounds[0].summary);
}

/// A current channel reading 2.5 % high beside slow negative kinetics: a heavier positive
/// coating stood in for the gain at first sight.
#[test]
#[ignore = "blind batch ap (about 60 s): CI skips it; run with --include-ignored"]
fn ap8_current_gain_and_slow_negative_kinetics_on_a_canal_tour_boat_spm() {
    let rounds = run_case("diagnosis-extra/ap8_current_gain_2p5pct_high_and_kinetics_negative_x0p35_canal_tour_boat_28C_30s_1p5mV_spm");
    let gain = fitted_in_any_round(&rounds, "cell.current_gain");
    assert!((gain / 0.025 - 1.0).abs() < 0.04, "current gain {gain} (truth 0.025): {}", rounds[0].summary);
}

// Blind batch aq (thirty-sixth session, made by a helper that did not read the diagnosis code,
// judged once on the binary of 7339aec before anyone read the truths: 5 of 8; aq5 named since,
// aq7 and aq8 open, see docs/diagnosis-cases.md).

#[test]
#[ignore = "blind batch aq: CI skips it; run with --include-ignored"]
fn aq1_negative_control_of_an_ice_cream_van_round_dfn() {
    run_case("diagnosis-extra/aq1_control_ice_cream_van_round_33C_10s_1p5mV_dfn");
}

#[test]
#[ignore = "blind batch aq: CI skips it; run with --include-ignored"]
fn aq2_larger_positive_particles_on_a_milk_float_round_spme() {
    run_case("diagnosis-extra/aq2_radius_positive_x1p4_milk_float_doorstep_round_15C_5s_spme");
}

#[test]
#[ignore = "blind batch aq: CI skips it; run with --include-ignored"]
fn aq3_voltage_channel_gain_on_an_airport_ground_power_unit_spm() {
    run_case("diagnosis-extra/aq3_voltage_channel_gain_0p35pct_high_airport_ground_power_unit_27C_20s_2mV_spm");
}

#[test]
#[ignore = "blind batch aq (about 90 s): CI skips it; run with --include-ignored"]
fn aq4_thicker_negative_electrode_on_a_school_bus_run_dfn() {
    run_case("diagnosis-extra/aq4_thickness_negative_x1p1_school_bus_morning_run_5C_4s_0p8mV_dfn");
}

/// A voltage channel 3 s late under a trials motorcycle's bursts: from zero the delay's fit
/// slid to its 10 s bound at first sight ("unexplained", 36.46 mV); screened over its range
/// every second it lands on the truth.
#[test]
fn aq5_a_late_voltage_channel_on_a_trials_motorcycle_spme() {
    let rounds = run_case("diagnosis-extra/aq5_voltage_logged_3s_late_trials_motorcycle_40C_1s_0p5mV_spme");
    let tau = first_fitted(&rounds, "data.voltage_delay");
    assert!((tau - 3.0).abs() < 0.05, "delay {tau} s (truth 3): {}", rounds[0].summary);
}

#[test]
#[ignore = "blind batch aq: CI skips it; run with --include-ignored"]
fn aq6_less_salt_in_a_snow_groomer_at_minus_10_degc_dfn() {
    run_case("diagnosis-extra/aq6_electrolyte_salt_x0p7_snow_groomer_night_minus10C_15s_1p5mV_dfn");
}

#[test]
#[ignore = "fails (open): graphite's anodic transfer coefficient 0.4 beside 6 % lithium lost, SPM data and model; round 1 names the lithium loss with the electrolyte's transport properties as the stand-in for the asymmetric kinetics (11.30 -> 2.17 mV, noise 1.03), then unexplained: the kinetics' transfer-coefficient refinement runs only once kinetics is named, not inside a pair"]
fn aq7_asymmetric_negative_charge_transfer_and_lithium_loss_on_a_road_train_spm() {
    run_case("diagnosis-extra/aq7_asymmetric_charge_transfer_negative_alpha0p4_and_inventory_6pct_theme_park_road_train_21C_2s_spm");
}

#[test]
#[ignore = "fails (open): a 6 mOhm contact resistance beside a current channel 2 % low at 2 mV noise and 30 s logging; round 1 names the contact (tied with kinetics), 6.34 -> 2.55 mV against 2.36 mV noise, and the gain's remaining 0.97 mV is below what a named effect must remove (the ao7 and ak8 limit)"]
fn aq8_contact_resistance_and_current_gain_on_an_orchard_platform_spme() {
    run_case("diagnosis-extra/aq8_contact_6mOhm_and_current_gain_2pct_low_orchard_picking_platform_9C_30s_2mV_spme");
}

#[test]
#[ignore = "blind batch ar: CI skips it; run with --include-ignored"]
fn ar1_negative_control_of_a_shunting_locomotive_spm() {
    run_case("diagnosis-extra/ar1_control_shunting_locomotive_rail_yard_36C_5s_spm");
}

#[test]
#[ignore = "blind batch ar, slow (600-1,000 s): CI skips it; run with --include-ignored"]
fn ar2_partially_reversible_plating_in_a_cold_taxi_top_up_dfn() {
    // One cold rapid charge: plating is offered because the fitted model plates in it
    // (src/diagnose/plating_gate.rs). OKane 2022's rate constant, 1e-9 m/s: 1.002e-9 +- 1.2e-11.
    let rounds = run_case("diagnosis-extra/ar2_plating_partially_reversible_taxi_cold_rapid_charge_minus2C_10s_1p5mV_dfn");
    let k = first_fitted(&rounds, "plating.kinetic_rate_constant");
    assert!((k / 1e-9 - 1.0).abs() < 0.03, "plating rate constant {k} m/s");
}

#[test]
#[ignore = "blind batch ar: CI skips it; run with --include-ignored"]
fn ar3_current_channel_offset_on_a_site_battery_hub_spme() {
    run_case("diagnosis-extra/ar3_current_offset_25mA_construction_site_battery_hub_16C_20s_0p8mV_spme");
}

#[test]
#[ignore = "blind batch ar: CI skips it; run with --include-ignored"]
fn ar4_particle_size_spread_in_an_rov_weld_inspection_spm() {
    run_case("diagnosis-extra/ar4_particle_size_distribution_rov_weld_inspection_10C_1s_0p5mV_spm");
}

#[test]
#[ignore = "blind batch ar: CI skips it; run with --include-ignored"]
fn ar5_entropic_change_at_a_polar_field_camp_spme() {
    run_case("diagnosis-extra/ar5_entropic_ocp_term_polar_field_camp_minus12C_30s_0p5mV_spme");
}

#[test]
#[ignore = "blind batch ar: CI skips it; run with --include-ignored"]
fn ar6_unrelaxed_start_after_a_depot_charge_spme() {
    run_case("diagnosis-extra/ar6_unrelaxed_start_airport_shuttle_log_after_depot_charge_23C_2s_spme");
}

#[test]
#[ignore = "blind batch ar: CI skips it; run with --include-ignored"]
fn ar7_positive_active_material_loss_and_conductivity_on_a_tow_boat_dfn() {
    run_case("diagnosis-extra/ar7_lam_positive_6pct_and_positive_conductivity_x0p25_waterski_tow_boat_30C_3s_1p2mV_dfn");
}

#[test]
#[ignore = "blind batch ar: CI skips it; run with --include-ignored"]
fn ar8_silicon_composite_negative_and_lithium_loss_at_a_market_stall_spm() {
    // Missed at first sight (thirty-seventh session): the second material fitted best but its
    // width ran to the 5 mV floor of its search and was refused. On its floor (now 1 mV) a
    // width is a flat plateau; the fit settles at 2.4 +- 1.3 mV and says the lithium lost.
    // Truth: 1.1 % silicon (c_max 278000) beside graphite at 0.66 (33133) holds 12.3 % of
    // the sites; 7 % of the lithium lost from the composite cell's.
    let rounds = run_case("diagnosis-extra/ar8_silicon_composite_negative_and_inventory_7pct_christmas_market_stall_4C_15s_2mV_spm");
    assert_eq!(rounds[0].best().map(|c| c.candidate), Some(Candidate::SecondMaterialNegative), "{}", rounds[0].summary);
    let share = first_fitted(&rounds, "negative.second_phase_share");
    assert!((share - 0.123).abs() < 0.03, "share {share:.3}");
}

// Blind batch as (thirty-eighth session, helper-made with `scripts/make_unseen_cases.py`, judged
// once by `../shared/tools/diagnosis-bench` on the binary of e16dd40 before the truths were
// read): 7 of 8 at first sight; as3 passes since the fortieth session (a tie led by its better held-out member).

#[test]
#[ignore = "blind batch as: CI skips it; run with --include-ignored"]
fn as1_negative_control_of_an_inspection_robot_patrol_spme() {
    run_case("diagnosis-extra/as1_control_quadruped_inspection_robot_patrol_18C_0p5s_0p6mV_spme");
}

#[test]
#[ignore = "blind batch as: CI skips it; run with --include-ignored"]
fn as2_sei_growth_over_eighty_satellite_orbits_spme() {
    run_case("diagnosis-extra/as2_sei_interstitial_diffusion_x8000_80_leo_orbits_life_test_15C_30s_0p8mV_spme");
}

#[test]
#[ignore = "blind batch as, slow (about 800 s): CI skips it; run with --include-ignored"]
fn as3_negative_lam_and_plating_in_a_cold_harbour_tug_charge_dfn() {
    // Round 1 ties lithium loss with a 7 % negative LAM; the LAM predicts the held-out points
    // better (1.43 against 2.90 mV) and leads, and round 2, its held-out blocks moved onto the
    // misfit, names partially reversible plating at 9.87e-10 m/s (OKane 2022's 1e-9).
    let rounds = run_case("diagnosis-extra/as3_lam_negative_8pct_and_plating_harbour_tug_cold_rapid_charge_0C_5s_1p2mV_dfn");
    let k = fitted_in_any_round(&rounds, "plating.kinetic_rate_constant");
    assert!((k / 1e-9 - 1.0).abs() < 0.03, "plating rate constant {k} m/s");
}

#[test]
#[ignore = "blind batch as: CI skips it; run with --include-ignored"]
fn as4_negative_hysteresis_in_a_mountain_hut_spm() {
    run_case("diagnosis-extra/as4_hysteresis_negative_15mV_off_grid_mountain_hut_minus8C_20s_1p2mV_spm");
}

#[test]
#[ignore = "blind batch as: CI skips it; run with --include-ignored"]
fn as5_a_transference_number_in_a_pipeline_welder_dfn() {
    run_case("diagnosis-extra/as5_electrolyte_transference_number_0p38_pipeline_welder_43C_2s_0p4mV_dfn");
}

#[test]
#[ignore = "blind batch as: CI skips it; run with --include-ignored"]
fn as6_unrelaxed_start_and_contact_on_an_ambulance_shift_spme() {
    run_case("diagnosis-extra/as6_unrelaxed_start_and_contact_3mOhm_ambulance_shift_31C_4s_spme");
}

#[test]
#[ignore = "blind batch as: CI skips it; run with --include-ignored"]
fn as7_positive_kinetics_on_a_street_sweeper_route_spm() {
    run_case("diagnosis-extra/as7_exchange_current_positive_x0p5_street_sweeper_early_route_8C_1s_1p8mV_spm");
}

#[test]
#[ignore = "blind batch as: CI skips it; run with --include-ignored"]
fn as8_self_heating_and_current_offset_on_a_rental_jet_ski_spme() {
    run_case("diagnosis-extra/as8_thermal_h12_recorded_and_current_offset_50mA_rental_jet_ski_26C_10s_2mV_spme");
}

#[test]
#[ignore = "blind batch at: CI skips it; run with --include-ignored"]
fn at1_negative_control_of_wind_turbine_pitch_backup_drills_dfn() {
    run_case("diagnosis-extra/at1_control_wind_turbine_pitch_backup_grid_loss_drills_minus4C_2s_dfn");
}

#[test]
#[ignore = "blind batch at: CI skips it; run with --include-ignored"]
fn at2_slow_negative_diffusion_in_a_bascule_bridge_backup_drive_spme() {
    run_case("diagnosis-extra/at2_diffusivity_negative_x0p1_bascule_bridge_backup_drive_outage_6C_5s_spme");
}

#[test]
#[ignore = "blind batch at: CI skips it; run with --include-ignored"]
fn at3_electrolyte_diffusivity_in_a_cave_diver_propulsion_vehicle_dfn() {
    run_case("diagnosis-extra/at3_electrolyte_diffusivity_x0p4_diver_propulsion_vehicle_cave_dive_14C_1s_0p8mV_dfn");
}

#[test]
#[ignore = "blind batch at: CI skips it; run with --include-ignored"]
fn at4_current_channel_gain_on_stadium_cable_camera_winches_spm() {
    run_case("diagnosis-extra/at4_current_gain_3p5pct_high_stadium_cable_camera_winches_20C_2s_0p6mV_spm");
}

#[test]
#[ignore = "blind batch at: CI skips it; run with --include-ignored"]
fn at5_self_heating_of_a_self_launching_sailplane_spme() {
    run_case("diagnosis-extra/at5_thermal_h7_recorded_self_launching_sailplane_two_flights_24C_1s_spme");
}

#[test]
#[ignore = "blind batch at: CI skips it; run with --include-ignored"]
fn at6_silicon_negative_and_contact_on_a_planetary_rover_spm() {
    run_case("diagnosis-extra/at6_silicon_composite_negative_and_contact_5mOhm_planetary_rover_field_trial_35C_8s_2mV_spm");
}

#[test]
#[ignore = "blind batch at: CI skips it; run with --include-ignored"]
fn at7_unrelaxed_start_and_lithium_loss_on_a_sailing_yacht_dfn() {
    run_case("diagnosis-extra/at7_unrelaxed_start_and_inventory_6pct_sailing_yacht_hydrogenerator_passage_17C_4s_1p2mV_dfn");
}

#[test]
#[ignore = "open (slow): SEI growth (solvent diffusion x900) with positive diffusivity x0.5 over 12 delivery rounds in 16.7 h, SPMe, 10 s logging; alone on the machine round 1 names both within the judge's 900 s (fortieth session, judge yes), 79 % of it screening 313 pairs; the later rounds run past it and the whole diagnosis has not been run in the harness"]
fn at8_sei_growth_and_slow_positive_diffusion_of_a_hospital_robot_spme() {
    run_case("diagnosis-extra/at8_sei_solvent_diffusion_x900_and_diffusivity_positive_x0p5_hospital_delivery_robot_12_rounds_22C_10s_0p5mV_spme");
}

// Blind batch au (fortieth session, helper-made with `scripts/make_unseen_cases.py`, judged once
// by `../shared/tools/diagnosis-bench` on the binary of 708b836 before the truths were read): 8 of 8.

#[test]
#[ignore = "blind batch au: CI skips it; run with --include-ignored"]
fn au1_negative_control_of_a_laptop_working_day_spm() {
    run_case("diagnosis-extra/au1_control_laptop_working_day_lunch_charge_27C_8s_0p5mV_spm");
}

#[test]
#[ignore = "blind batch au: CI skips it; run with --include-ignored"]
fn au2_positive_lam_of_heated_apparel_on_a_ski_day_spm() {
    run_case("diagnosis-extra/au2_lam_positive_9pct_heated_apparel_ski_day_minus12C_6s_spm");
}

#[test]
#[ignore = "blind batch au: CI skips it; run with --include-ignored"]
fn au3_negative_lam_and_a_late_voltage_channel_on_a_quarry_dump_truck_spme() {
    run_case("diagnosis-extra/au3_lam_negative_7pct_and_voltage_logged_2s_late_quarry_dump_truck_14C_1s_1p2mV_spme");
}

#[test]
#[ignore = "blind batch au: CI skips it; run with --include-ignored"]
fn au4_unrelaxed_start_and_slow_positive_kinetics_of_a_reefer_delivery_day_dfn() {
    run_case("diagnosis-extra/au4_unrelaxed_start_and_exchange_current_positive_x0p35_reefer_delivery_day_37C_5s_0p8mV_dfn");
}

#[test]
#[ignore = "blind batch au: CI skips it; run with --include-ignored"]
fn au5_current_offset_of_a_sump_pump_backup_in_a_power_cut_spme() {
    run_case("diagnosis-extra/au5_current_offset_30mA_low_sump_pump_backup_storm_power_cut_11C_10s_spme");
}

#[test]
#[ignore = "blind batch au: CI skips it; run with --include-ignored"]
fn au6_unrecorded_self_heating_of_an_electric_skateboard_ride_dfn() {
    run_case("diagnosis-extra/au6_thermal_h9_unrecorded_electric_skateboard_ride_19C_3s_2mV_dfn");
}

#[test]
#[ignore = "blind batch au: CI skips it; run with --include-ignored"]
fn au7_plating_and_contact_of_an_ev_charging_robot_in_frost_spme() {
    run_case("diagnosis-extra/au7_plating_partially_reversible_and_contact_4mOhm_ev_charging_robot_frost_minus6C_4s_0p5mV_spme");
}

#[test]
#[ignore = "blind batch au: CI skips it; run with --include-ignored"]
fn au8_sei_electron_migration_of_a_motorcycle_taxi_day_spm() {
    run_case("diagnosis-extra/au8_sei_electron_migration_x5000_motorcycle_taxi_day_part_top_ups_33C_10s_0p7mV_spm");
}
