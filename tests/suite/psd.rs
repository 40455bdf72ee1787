//! The particle-size distribution submodel (`Submodels::particle_size`) on its own: the
//! single-size limit, lithium conservation across the sizes, the Jacobian pattern, how it is
//! switched on and how bad input is refused. Against PyBaMM: `psd_reference.rs`.

use std::collections::HashSet;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::{ParticleSize, SeiModel};
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::{ParameterSet, chen2020};
use cellstudio::protocol::{Protocol, Step};
use cellstudio::simulation::{SimOptions, States, Solution, simulate};

const DISTRIBUTION: Submodels = Submodels {
    contact_resistance: false,
    thermal: false,
    rc: false,
    hysteresis: false,
    leak: false,
    voltage_offset: false,
    voltage_gain: false,
    current_gain: false,
    ocv_correction: false,
    sei: SeiModel::None,
    lam: cellstudio::models::submodels::LamModel::None,
    plating: cellstudio::models::submodels::PlatingModel::None,
    stress_induced_diffusion: None,
    particle_size: ParticleSize::Distribution,
};

fn with_std(std: f64) -> ParameterSet {
    let mut p = chen2020();
    (p.negative.radius_relative_std, p.positive.radius_relative_std) = (std, std);
    p
}

fn run(submodels: Submodels, p: &ParameterSet, protocol: &Protocol, t_eval: Option<Vec<f64>>) -> Solution {
    let mut b = ModelBuilder::new(ModelKind::Spm, submodels, MeshSizes::default());
    let built = b.build(p).unwrap();
    let opts = SimOptions { t_eval, states: States::Kept, ..crate::common::tight_options(p) };
    simulate(built.model.as_ref(), &mut built.workspace, protocol, &opts, None).unwrap()
}

/// As the spread goes to zero the distribution approaches the single particle: at relative
/// std 0 (every size the mean) the curves agree to the solver's tolerance, at 1e-3 to
/// O(std^2), and the gap grows with the spread. Achieved (largest gap over a 1C discharge):
/// 2.3e-5 mV at std 0, 5.7e-4 mV at 1e-3, 5.8 mV at 0.1.
#[test]
fn a_narrow_distribution_is_the_single_particle_model() {
    let t: Vec<f64> = (0..=34).map(|k| 100.0 * f64::from(k)).collect();
    let protocol = Protocol::discharge(1.0);
    let plain = run(Submodels::default(), &chen2020(), &protocol, Some(t.clone())).voltage;
    let gap = |std: f64| {
        let v = run(DISTRIBUTION, &with_std(std), &protocol, Some(t.clone())).voltage;
        assert_eq!(v.len(), plain.len());
        v.iter().zip(&plain).map(|(a, b)| (a - b).abs() * 1e3).fold(0.0, f64::max)
    };
    let (zero, narrow, wide) = (gap(0.0), gap(1e-3), gap(0.1));
    println!("largest gap to the SPM (mV): std 0 {zero:.2e}, 1e-3 {narrow:.2e}, 0.1 {wide:.2e}");
    assert!(zero < 1e-4, "std 0: {zero} mV");
    assert!(narrow < 2.5e-3, "std 1e-3: {narrow} mV");
    assert!(wide > 100.0 * narrow, "std 0.1: {wide} mV, 1e-3: {narrow} mV");
}

/// The sizes trade lithium through the shared potential, but the particles' total (the
/// volume-weighted mean concentration) changes only by the applied charge: conserved to
/// round-off over pulses and rests.
#[test]
fn lithium_is_conserved_across_the_sizes() {
    let p = with_std(0.3);
    let steps: Vec<Step> = (0..3).flat_map(|_| [Step::Current { current: 10.0, duration: 180.0, until_voltage: None }, Step::Rest { duration: 1200.0 }]).collect();
    let sol = run(DISTRIBUTION, &p, &Protocol { steps }, None);
    let mut b = ModelBuilder::new(ModelKind::Spm, DISTRIBUTION, MeshSizes::default());
    let model = &b.build(&p).unwrap().model;
    let total = model.solid_lithium(&sol.states[0]);
    for y in &sol.states {
        let drift = (model.solid_lithium(y) - total).abs() / total;
        assert!(drift < 1e-12, "lithium moved by {drift:e} of the total");
    }
}

/// Every state the right-hand side reads is in the Jacobian pattern (perturb each state,
/// see which rows move), and the pattern stays sparse: the sizes couple only through their
/// surface shells.
#[test]
fn the_jacobian_pattern_covers_the_couplings() {
    let p = with_std(0.3);
    for submodels in [DISTRIBUTION, Submodels { thermal: true, ..DISTRIBUTION }] {
        let mut b = ModelBuilder::new(ModelKind::Spm, submodels, MeshSizes { size_n: 7, size_p: 5, ..Default::default() });
        let model = &b.build(&p).unwrap().model;
        let n = model.len();
        assert_eq!(n, (7 + 5) * 20 + usize::from(submodels.thermal));
        let pattern: HashSet<(usize, usize)> = model.jacobian_pattern().into_iter().collect();
        assert!(pattern.len() < n * n / 10, "{} entries of {}", pattern.len(), n * n);
        let mut y = model.initial_state();
        for (k, v) in y.iter_mut().enumerate() {
            *v *= 1.0 - 0.2 * ((k * 37 % 11) as f64) / 11.0; // non-uniform, so that every shell couples
        }
        let (mut f0, mut f1) = (vec![0.0; n], vec![0.0; n]);
        model.rhs(&y, 5.0, &mut f0);
        for col in 0..n {
            let mut z = y.clone();
            z[col] *= 1.0 + 1e-6;
            model.rhs(&z, 5.0, &mut f1);
            for row in 0..n {
                if f1[row] != f0[row] {
                    assert!(pattern.contains(&(row, col)), "d f[{row}] / d y[{col}] is not in the pattern");
                }
            }
        }
    }
}

/// Off by default; on from a study's TOML (`submodels = { particle_size = "distribution" }`);
/// built on the SPM only, and not with the SEI, LAM or plating submodels.
#[test]
fn the_distribution_is_switched_on_and_refused_where_not_built() {
    assert_eq!(Submodels::default().particle_size, ParticleSize::Single);
    let s: Submodels = toml::from_str("particle_size = \"distribution\"\nthermal = true").unwrap();
    assert_eq!((s.particle_size, s.thermal), (ParticleSize::Distribution, true));
    let e = toml::from_str::<Submodels>("particle_size = \"lognormal\"").unwrap_err().to_string();
    assert!(e.contains("lognormal") && e.contains("distribution"), "{e}");
    let p = chen2020();
    let b = ModelBuilder::new(ModelKind::Spm, DISTRIBUTION, MeshSizes::default()).build(&p).map(|b| b.model.name()).unwrap();
    assert_eq!(b, "SPM+size distribution");
    for kind in [ModelKind::Spme, ModelKind::Dfn] {
        let e = ModelBuilder::new(kind, DISTRIBUTION, MeshSizes::default()).build(&p).err().unwrap().to_string();
        assert!(e.contains("model.submodels.particle_size") && e.contains("SPM only"), "{e}");
    }
    let e = ModelBuilder::new(ModelKind::Spm, Submodels { sei: SeiModel::ReactionLimited, ..DISTRIBUTION }, MeshSizes::default()).build(&p).err().unwrap().to_string();
    assert!(e.contains("model.submodels.particle_size") && e.contains("sei"), "{e}");
}

/// A negative or too wide spread and a mesh without sizes are errors naming the field and
/// value.
#[test]
fn bad_spreads_and_size_counts_are_refused() {
    for (path, value) in [("negative.radius_relative_std", -0.1), ("positive.radius_relative_std", 1.5)] {
        let mut p = chen2020();
        p.set(path, value).unwrap();
        let e = p.validate().unwrap_err().to_string();
        assert!(e.contains(path) && e.contains(&value.to_string()), "{e}");
        let e = cellstudio::params::apply_overrides(&mut chen2020(), &[format!("{path}={value}").parse().unwrap()]).unwrap_err().to_string();
        assert!(e.contains(&format!("{path} (from --set)")), "{e}");
    }
    let e = ModelBuilder::new(ModelKind::Spm, DISTRIBUTION, MeshSizes { size_p: 0, ..Default::default() }).build(&chen2020()).err().unwrap().to_string();
    assert!(e.contains("mesh.size_p") && e.contains('0'), "{e}");
}
