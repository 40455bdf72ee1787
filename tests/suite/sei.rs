//! SEI growth against PyBaMM 26.10 (`scripts/make_sei_reference.py`, curves in
//! `tests/data/sei/`): the SPM, SPMe and DFN on Chen 2020 with PyBaMM's SEI options "reaction
//! limited", "solvent-diffusion limited", "electron-migration limited", "interstitial-diffusion
//! limited" and "ec reaction limited" (film resistance on, side reaction x-averaged),
//! through 10 CC-CV cycles ("Discharge at 1C until 3.0 V", rest 10 min, "Charge at 1C until
//! 4.1 V", "Hold at 4.1 V until C/20", rest 10 min), the same mesh, PyBaMM's IDAKLU at
//! rtol = atol = 1e-8 and ours at 1e-8. Compared: the voltage outside the holds, the current
//! in the holds, the SEI thickness and the lithium lost to the SEI against time, when each
//! step ends, and the per-cycle summaries of [`run_cycles`]. Lithium (particles plus SEI)
//! is conserved to round-off.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::SeiModel;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::{Protocol, Step, experiment};
use cellstudio::simulation::cycling::run_cycles;
use cellstudio::simulation::{SimOptions, States, simulate};

const CYCLE: [&str; 5] = ["Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes"];
const CYCLES: usize = 10;
const OPTIONS: [(SeiModel, &str); 5] = [
    (SeiModel::ReactionLimited, "reaction_limited"),
    (SeiModel::SolventDiffusionLimited, "solvent_diffusion_limited"),
    (SeiModel::ElectronMigrationLimited, "electron_migration_limited"),
    (SeiModel::InterstitialDiffusionLimited, "interstitial_diffusion_limited"),
    (SeiModel::EcReactionLimited, "ec_reaction_limited"),
];

use crate::common;

/// The limit on the thickness and lithium-lost gaps, relative to their growth over the run:
/// PyBaMM's Chen 2020 rates make the electron-migration and interstitial-diffusion layers
/// grow by only 4 % and 0.2 % of their 5 nm, so there the gap is the solvers' tolerance on
/// the layer itself (achieved up to 5.4e-5 of the growth, 4e-16 m) and the limit is wider.
fn growth_limit(sei: SeiModel, others: f64) -> f64 {
    if barely_grows(sei) { 2e-4 } else { others }
}

/// The laws whose layer grows by only a few per cent at Chen 2020's rates.
fn barely_grows(sei: SeiModel) -> bool {
    matches!(sei, SeiModel::ElectronMigrationLimited | SeiModel::InterstitialDiffusionLimited)
}

fn rows(file: &str) -> Vec<Vec<f64>> {
    common::csv_rows("sei", file)
}

fn options() -> SimOptions {
    let mut opts = SimOptions::for_cell(&chen2020());
    opts.solver.set_tolerance(1e-8);
    opts
}

fn builder(kind: ModelKind, sei: SeiModel) -> ModelBuilder {
    ModelBuilder::new(kind, Submodels { sei, ..Default::default() }, MeshSizes::default())
}

fn cycle() -> Protocol {
    experiment::parse(&CYCLE, chen2020().cell.nominal_capacity).unwrap()
}

/// The differences over the 10 cycles against PyBaMM's curve.
#[derive(Debug)]
struct Gaps {
    /// Voltage RMS and max outside the holds (mV).
    voltage: (f64, f64),
    /// Hold current RMS and max (mA).
    current: (f64, f64),
    /// SEI thickness RMS and max, relative to its growth over the run (-).
    thickness: (f64, f64),
    /// Lithium lost to the SEI, RMS and max relative to the final loss (-).
    lithium: (f64, f64),
    /// Largest step-end difference (s).
    step_end: f64,
}

fn compare(kind: ModelKind, sei: SeiModel, name: &str) -> Gaps {
    let rec = rows(&format!("{}_{name}.csv", kind.to_string().to_lowercase()));
    let steps: Vec<Step> = (0..CYCLES).flat_map(|_| cycle().steps).collect();
    let mut b = builder(kind, sei);
    let built = b.build(&chen2020()).unwrap();
    let model = built.model.as_ref();
    let (l0, l_end) = (rec[0][3], rec[rec.len() - 1][3]);
    let lost_end = rec[rec.len() - 1][4];
    let (mut l, mut li) = (vec![], vec![]);
    let sei0 = model.sei_lithium(&model.initial_state());
    let hold = |s: usize| s % CYCLE.len() == 3;
    // The ten cycles one step at a time hold the SEI as a ten-cycle run does.
    let mut opts = options();
    opts.solver.accumulator_tolerance = 1.0 / CYCLES as f64;
    let run = common::step_by_step(model, &mut built.workspace, &steps, &rec, 5, hold, &opts, |sol, k, r| {
        let y = &sol.states[k];
        l.push((model.sei_thickness(y).unwrap() - r[3]) / (l_end - l0));
        li.push((model.sei_lithium(y) - sei0 - r[4]) / lost_end);
    });
    let (v, i, step_end) = (run.voltage, run.current, run.step_end);
    assert!(v.len() > 800 && i.len() > 200, "{name}: compared {} voltages and {} currents", v.len(), i.len());
    let (rms, max) = (common::rms, common::max_abs);
    let gaps = Gaps { voltage: (rms(&v), max(&v)), current: (rms(&i), max(&i)), thickness: (rms(&l), max(&l)), lithium: (rms(&li), max(&li)), step_end };
    println!("{kind} {name}: {gaps:?}");
    gaps
}

/// Limits about five times the achieved (against PyBaMM at rtol 1e-10 for the SPM and SPMe):
/// voltage RMS / max 6.8e-6-2.3e-5 / 2.4e-5-1.2e-4 mV, hold current RMS / max 1.3e-4-3.3e-4 /
/// 3.8e-4-2.3e-3 mA, thickness and lithium lost max 2.2e-6 (SPM reaction limited; 4.1e-8 to
/// 5.9e-7 otherwise, 4.0e-6 to 6.2e-5 for the electron-migration and interstitial-diffusion
/// laws, which grow the layer by a few per cent: see [`growth_limit`]) of their growth, step ends
/// 1.8e-3-2.5e-3 s (the C/20 end of a hold, as sensitive to either solver's tolerance:
/// ours moves by 1.8e-3 s from rtol 1e-8 to 1e-12).
/// The DFN, its own limits about five times its achieved: voltage RMS / max
/// 8.6e-6-1.0e-5 / 4.4e-5-7.5e-5 mV, hold current 7.6e-5-9.5e-5 / 3.2e-4-3.5e-4 mA,
/// thickness and lithium 2.7e-8-5.5e-8, step ends 1.4e-3-1.6e-3 s.
fn check(kind: ModelKind) {
    // (voltage RMS, max) mV, (current RMS, max) mA, thickness and lithium (-).
    let (voltage, current, growth) = if kind == ModelKind::Dfn { ((5e-5, 4e-4), (5e-4, 2e-3), 3e-7) } else { ((1.5e-4, 6e-4), (1.5e-3, 1e-2), 1e-5) };
    for (sei, name) in OPTIONS {
        let g = compare(kind, sei, name);
        assert!(g.voltage.0 < voltage.0 && g.voltage.1 < voltage.1, "{kind} {name}: voltage {:?} mV", g.voltage);
        assert!(g.current.0 < current.0 && g.current.1 < current.1, "{kind} {name}: hold current {:?} mA", g.current);
        let growth = growth_limit(sei, growth);
        assert!(g.thickness.1 < growth && g.lithium.1 < growth, "{kind} {name}: thickness {:?}, lithium {:?}", g.thickness, g.lithium);
        assert!(g.step_end < 0.012, "{kind} {name}: step ends {} s apart", g.step_end);
    }
}

#[test]
fn sei_spm_matches_pybamm() {
    check(ModelKind::Spm);
}

#[test]
fn sei_spme_matches_pybamm() {
    check(ModelKind::Spme);
}

#[test]
fn sei_dfn_matches_pybamm() {
    check(ModelKind::Dfn);
}

/// The per-cycle summaries (discharge capacity, lithium lost, SEI thickness) of ten
/// cycles run one at a time against PyBaMM's over the same experiment.
#[test]
fn cycle_summaries_match_pybamm() {
    let p = chen2020();
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        for (sei, name) in OPTIONS {
            let reference = rows(&format!("{}_{name}_cycles.csv", kind.to_string().to_lowercase()));
            let mut b = builder(kind, sei);
            let built = b.build(&p).unwrap();
            let mut seen = 0;
            let summaries = run_cycles(built.model.as_ref(), &mut built.workspace, &cycle(), CYCLES, &options(), &mut |s| {
                seen += 1;
                assert_eq!(s.cycle, seen);
            })
            .unwrap();
            let (mut dq, mut dli, mut dl) = (0.0f64, 0.0f64, 0.0f64);
            for (s, r) in summaries.iter().zip(&reference) {
                dq = dq.max((s.discharge_capacity_ah - r[1]).abs() * 1e3);
                dli = dli.max((s.lithium_lost_to_sei_mol / r[2] - 1.0).abs());
                dl = dl.max((s.sei_thickness_m.unwrap() / r[3] - 1.0).abs());
            }
            let fade = |q: &[f64]| q[0] - q[q.len() - 1];
            let ours_fade = fade(&summaries.iter().map(|s| s.discharge_capacity_ah).collect::<Vec<_>>()[1..]);
            let ref_fade = fade(&reference.iter().map(|r| r[1]).collect::<Vec<_>>()[1..]);
            let fade_gap = (ours_fade / ref_fade - 1.0).abs();
            println!(
                "{kind} {name}: discharge capacity within {dq:.2e} mA h, lithium lost {dli:.2e}, thickness {dl:.2e} (relative); fade over cycles 2-{CYCLES}: ours {:.6} mA h, PyBaMM {:.6} mA h ({fade_gap:.1e})",
                ours_fade * 1e3,
                ref_fade * 1e3
            );
            // Achieved (the SEI held to a tenth of rtol 1e-8 over the ten cycles; SPM and SPMe
            // against PyBaMM at 1e-10): 5.7e-6-5.3e-5 mA h, 6.0e-8-2.2e-6 (1.4e-6 to 6.3e-5 for
            // the electron-migration and interstitial-diffusion laws), 7.2e-9-8.4e-7, fade
            // 1.7e-8-1.2e-5 (DFN against PyBaMM at 1e-8: 1.9e-5-3.4e-5 mA h, 4.2e-8-1.3e-7,
            // 4e-11-2.2e-8, 3.8e-9-5.4e-6).
            assert_eq!(summaries.len(), CYCLES);
            assert!(dq < 2e-4 && dli < growth_limit(sei, 1e-5) && dl < 4e-6, "{kind} {name}: {dq} mA h, {dli}, {dl}");
            // Relative 4e-5, with an absolute floor of 1e-4 mA h (below the per-cycle capacity
            // limit) for the two laws that barely grow: the interstitial-diffusion layer fades
            // the cell by only 0.014 mA h.
            let floor = if barely_grows(sei) { 1e-4 } else { 0.0 };
            assert!((ours_fade - ref_fade).abs() * 1e3 < 4e-5 * ref_fade * 1e3 + floor, "{kind} {name}: fade {ours_fade} vs {ref_fade}");
        }
    }
}

/// Lithium in the particles plus in the SEI is conserved to round-off through discharge,
/// rest, charge and a hold, while the SEI takes a measurable amount of it.
#[test]
fn lithium_in_particles_and_sei_is_conserved() {
    let p = chen2020();
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        for (sei, name) in OPTIONS {
            let mut b = builder(kind, sei);
            let built = b.build(&p).unwrap();
            let opts = SimOptions { states: States::Kept, ..options() };
            let sol = simulate(built.model.as_ref(), &mut built.workspace, &cycle(), &opts, None).unwrap();
            let m = built.model.as_ref();
            let total = |y: &[f64]| m.solid_lithium(y) + m.sei_lithium(y);
            let li0 = total(&sol.states[0]);
            let worst = sol.states.iter().map(|y| (total(y) - li0).abs() / li0).fold(0.0, f64::max);
            let taken = m.sei_lithium(&sol.final_state) - m.sei_lithium(&sol.states[0]);
            println!("{kind} {name}: {li0:.6} mol, SEI took {taken:.3e} mol ({:.2e} of it), worst drift {worst:.2e}", taken / li0);
            // Measurable: the two laws that barely grow take 1.9e-7 to 6.2e-6 of it, the others
            // 1.6e-5 to 1.8e-2.
            let least = if barely_grows(sei) { 1e-7 } else { 1e-6 };
            assert!(taken / li0 > least, "{kind} {name}: the SEI took {taken} mol");
            // Achieved 5.9e-16 to 7.8e-16 (1.7e-14 and 2.7e-12 in the SPMe before its SEI
            // Jacobian pattern gave the particle surface the electrolyte its side reaction reads).
            assert!(worst < 4e-15, "{kind} {name}: lithium drift {worst:e}");
        }
    }
}
