//! Impedance spectroscopy: state-of-charge setting against PyBaMM, the linearised impedance
//! against time-domain sinusoidal simulations and analytic limits, spectrum CSV checks, and
//! parameter identification from a synthetic spectrum.

use cellstudio::params::{chen2020, set_initial_soc, stoichiometry_window};

/// Chen2020 stoichiometry window from PyBaMM 26.10.1.1:
/// `pybamm.lithium_ion.get_min_max_stoichiometries(pybamm.ParameterValues("Chen2020"))`,
/// and the initial concentrations of `ParameterValues.set_initial_state(0.5)`.
const PYBAMM_X0: f64 = 0.02634579027064577;
const PYBAMM_X100: f64 = 0.9106180466524094;
const PYBAMM_Y0: f64 = 0.853974674630047;
const PYBAMM_Y100: f64 = 0.2638452245913298;
const PYBAMM_CN_HALF: f64 = 15522.211404385793;
const PYBAMM_CP_HALF: f64 = 35269.45346023288;

#[test]
fn chen2020_window_matches_pybamm() {
    let p = chen2020();
    let w = stoichiometry_window(&p).unwrap();
    println!("{w:?}");
    for (ours, theirs) in [(w.x0, PYBAMM_X0), (w.x100, PYBAMM_X100), (w.y0, PYBAMM_Y0), (w.y100, PYBAMM_Y100)] {
        assert!((ours - theirs).abs() < 1e-9, "{ours} vs PyBaMM {theirs}");
    }
    let mut q = p.clone();
    set_initial_soc(&mut q, 0.5).unwrap();
    assert!((q.negative.initial_concentration - PYBAMM_CN_HALF).abs() < 1e-4, "{}", q.negative.initial_concentration);
    assert!((q.positive.initial_concentration - PYBAMM_CP_HALF).abs() < 1e-4, "{}", q.positive.initial_concentration);
    // Lithium conserved, window unchanged by the move.
    let w2 = stoichiometry_window(&q).unwrap();
    assert!((w2.x0 - w.x0).abs() < 1e-12 && (w2.y100 - w.y100).abs() < 1e-12);
    for bad in [-0.1, 1.2, f64::NAN] {
        let err = set_initial_soc(&mut q, bad).unwrap_err().to_string();
        assert!(err.contains("`soc`") && err.contains(&format!("{bad}")), "{err}");
    }
}

mod impedance {
    use cellstudio::eis::{SineOptions, Spectrum, impedance, linearise, log_frequencies, model_impedance, rest_state, sine_response};
    use cellstudio::geometry::MeshSizes;
    use cellstudio::models::ModelBuilder;
    use cellstudio::models::{ModelKind, Submodels};
    use cellstudio::params::{FARADAY, GAS_CONSTANT, ParameterSet, chen2020, set_initial_soc};

    fn half_charged() -> ParameterSet {
        let mut p = chen2020();
        set_initial_soc(&mut p, 0.5).unwrap();
        p
    }

    fn spectrum(kind: ModelKind, submodels: Submodels, p: &ParameterSet, f: &[f64]) -> Spectrum {
        let mut b = ModelBuilder::new(kind, submodels, MeshSizes::default());
        let built = b.build(p).unwrap();
        model_impedance(built.model.as_ref(), &mut built.workspace, f).unwrap()
    }

    /// Drives the model with a C/100 sinusoid from the same rest state and compares the fitted
    /// impedance with the linearised one at each `(frequency, settle time)`.
    fn time_domain_agrees(kind: ModelKind, cases: &[(f64, f64)]) {
        let p = half_charged();
        let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
        let built = b.build(&p).unwrap();
        let (model, ws) = (built.model.as_ref(), &mut built.workspace);
        let y0 = rest_state(model, ws).unwrap();
        let lin = linearise(model, &y0).unwrap();
        let amplitude = p.cell.nominal_capacity / 100.0;
        for &(f, settle_time) in cases {
            let z = impedance(&lin, &[f]).unwrap();
            let opts = SineOptions { amplitude, settle_time, ..SineOptions::default() };
            let td = sine_response(model, ws, &y0, f, &opts).unwrap();
            let (mag_fd, mag_td) = (z.magnitude(0), td.z_re.hypot(td.z_im));
            let (ph_fd, ph_td) = (z.phase(0), td.z_im.atan2(td.z_re));
            let (e_mag, e_ph) = ((mag_td / mag_fd - 1.0).abs(), (ph_td / ph_fd - 1.0).abs());
            println!(
                "{kind} f = {f} Hz: |Z| {mag_fd:.6e} vs {mag_td:.6e} ohm (rel {e_mag:.1e}), phase {ph_fd:.6e} vs {ph_td:.6e} rad (rel {e_ph:.1e}), {} steps",
                td.stats.steps
            );
            // Achieved at most 2.3e-4 (magnitude) and 2.8e-4 (phase).
            assert!(e_mag < 1e-3 && e_ph < 1e-3, "{kind} at {f} Hz");
        }
    }

    #[test]
    fn spm_matches_time_domain() {
        time_domain_agrees(ModelKind::Spm, &[(1e-3, 4000.0), (0.1, 200.0), (10.0, 5.0)]);
    }

    #[test]
    fn spme_matches_time_domain() {
        time_domain_agrees(ModelKind::Spme, &[(1e-3, 4000.0), (0.1, 200.0), (10.0, 5.0)]);
    }

    #[test]
    fn dfn_matches_time_domain() {
        time_domain_agrees(ModelKind::Dfn, &[(1e-3, 4000.0), (0.1, 200.0), (10.0, 5.0)]);
    }

    /// SPM without double layer: at high frequency the particles cannot respond and the
    /// impedance is the linearised Butler-Volmer resistance of each electrode,
    /// `R_ct = R T / (F j0) / (A a L)` whatever the transfer coefficient (the negative's is
    /// asymmetric here), plus the contact resistance.
    #[test]
    fn spm_high_frequency_limit_is_charge_transfer_plus_contact() {
        let mut p = half_charged();
        p.cell.contact_resistance = 0.0123;
        p.negative.charge_transfer_coefficient = 0.4;
        let t = p.thermal.ambient_temperature;
        let ce = p.electrolyte.initial_concentration;
        let r_ct = |e: &cellstudio::params::Electrode| {
            let cs = e.initial_concentration;
            // the model's exchange current (PyBaMM's regularised square roots, 1.5e-6 below
            // the plain product here)
            let j0 = cellstudio::models::kinetics::exchange_current(e.rate_constant, ce, ce, cs, e.max_concentration);
            let a = 3.0 * e.active_fraction / e.particle_radius;
            GAS_CONSTANT * t / (FARADAY * j0) / (p.cell.area() * a * e.thickness)
        };
        let expected = r_ct(&p.negative) + r_ct(&p.positive) + p.cell.contact_resistance;
        let z = spectrum(ModelKind::Spm, Submodels { contact_resistance: true, ..Default::default() }, &p, &[1e6]);
        println!("Z(1 MHz) = {} {} ohm, analytic {expected}", z.z_re[0], z.z_im[0]);
        assert!((z.z_re[0] / expected - 1.0).abs() < 1e-6);
        assert!(z.z_im[0].abs() < 1e-6 * expected);
    }

    /// Contact resistance is a series element: it shifts the whole spectrum by exactly R.
    #[test]
    fn contact_resistance_shifts_every_model_by_r() {
        let mut p = half_charged();
        p.cell.contact_resistance = 0.02;
        let f = log_frequencies(1e-4, 1e4, 9).unwrap();
        for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
            let off = spectrum(kind, Submodels::default(), &p, &f);
            let on = spectrum(kind, Submodels { contact_resistance: true, ..Default::default() }, &p, &f);
            for k in 0..f.len() {
                assert!((on.z_re[k] - off.z_re[k] - 0.02).abs() < 1e-9, "{kind} {}: {} {}", f[k], on.z_re[k], off.z_re[k]);
                assert!((on.z_im[k] - off.z_im[k]).abs() < 1e-9);
            }
        }
    }

    /// At low frequency the cell is a capacitor of the OCV slope: `Im Z -> -1/(w C_eff)` with
    /// `C_eff = dQ/dOCV`, the OCV slope from the electrode OCPs and capacities.
    #[test]
    fn low_frequency_is_a_capacitor_of_the_ocv_slope() {
        let p = half_charged();
        let area = p.cell.area();
        let (n, q) = (&p.negative, &p.positive);
        let x = n.initial_concentration / n.max_concentration;
        let y = q.initial_concentration / q.max_concentration;
        let h = 1e-6;
        let du_n = (n.ocp.eval(x + h) - n.ocp.eval(x - h)) / (2.0 * h);
        let du_p = (q.ocp.eval(y + h) - q.ocp.eval(y - h)) / (2.0 * h);
        // Discharging charge q (C): dx/dq = -1/(F eps c_max L A), dy/dq = +1/(...).
        let dx_dq = -1.0 / (FARADAY * n.active_fraction * n.max_concentration * n.thickness * area);
        let dy_dq = 1.0 / (FARADAY * q.active_fraction * q.max_concentration * q.thickness * area);
        let docv_dq = du_p * dy_dq - du_n * dx_dq;
        let c_eff = 1.0 / docv_dq.abs();
        println!("C_eff = {c_eff:.1} F");
        let f = [1e-7, 1e-8];
        for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
            let z = spectrum(kind, Submodels::default(), &p, &f);
            for k in 0..f.len() {
                let w = 2.0 * std::f64::consts::PI * f[k];
                let c_model = -1.0 / (w * z.z_im[k]);
                println!("{kind} f = {} Hz: C = {c_model:.1} F", f[k]);
                assert!((c_model / c_eff - 1.0).abs() < 1e-3, "{kind}: {c_model} vs {c_eff}");
            }
        }
    }

    #[test]
    fn spectra_are_passive_and_tend_to_a_resistance() {
        let p = half_charged();
        let f = log_frequencies(1e-4, 1e5, 40).unwrap();
        for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
            let z = spectrum(kind, Submodels::default(), &p, &f);
            assert!(z.z_re.iter().all(|&r| r > 0.0) && z.z_im.iter().all(|&i| i < 0.0), "{kind}: {z:?}");
            // Re Z falls with frequency towards the ohmic limit (frequencies run downwards).
            assert!(z.z_re.windows(2).all(|w| w[1] >= w[0] * (1.0 - 1e-12)), "{kind}: {:?}", z.z_re);
        }
    }
}

mod csv {
    use cellstudio::eis::Spectrum;
    use std::path::Path;

    fn read(dir: &Path, name: &str, text: &str) -> Result<Spectrum, String> {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        Spectrum::from_csv(&path).map_err(|e| e.to_string())
    }

    #[test]
    fn round_trip() {
        let s = Spectrum::new(vec![1e3, 1.0, 1e-3], vec![0.03, 0.031, 0.05], vec![-1e-6, -2e-4, -0.02]).unwrap();
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("round.csv");
        s.write_csv(&path).unwrap();
        assert_eq!(Spectrum::from_csv(&path).unwrap(), s);
        // Columns are found by name, in any order, extra columns ignored.
        let t = read(dir.path(), "order.csv", "z_im_ohm,note,frequency_Hz,z_re_ohm\n-0.5,a,2,0.25\n").unwrap();
        assert_eq!((t.frequency[0], t.z_re[0], t.z_im[0]), (2.0, 0.25, -0.5));
    }

    #[test]
    fn bad_files_name_the_line_and_value() {
        let dir = tempfile::tempdir().unwrap();
        let err = read(dir.path(), "nan.csv", "frequency_Hz,z_re_ohm,z_im_ohm\n1,0.1,-0.1\n2,NaN,-0.1\n").unwrap_err();
        assert!(err.contains("line 3") && err.contains("z_re_ohm") && err.contains("NaN"), "{err}");
        let err = read(dir.path(), "empty.csv", "frequency_Hz,z_re_ohm,z_im_ohm\n").unwrap_err();
        assert!(err.contains("no data rows"), "{err}");
        let err = read(dir.path(), "missing.csv", "frequency_Hz,z_re_ohm\n1,0.1\n").unwrap_err();
        assert!(err.contains("missing column `z_im_ohm`"), "{err}");
        let err = read(dir.path(), "zero.csv", "frequency_Hz,z_re_ohm,z_im_ohm\n1,0.1,-0.1\n0,0.1,-0.1\n").unwrap_err();
        assert!(err.contains("line 3") && err.contains("frequency_Hz") && err.contains("= 0"), "{err}");
        let err = read(dir.path(), "neg.csv", "frequency_Hz,z_re_ohm,z_im_ohm\n-5,0.1,-0.1\n").unwrap_err();
        assert!(err.contains("line 2") && err.contains("-5"), "{err}");
        let err = read(dir.path(), "text.csv", "frequency_Hz,z_re_ohm,z_im_ohm\n1,abc,-0.1\n").unwrap_err();
        assert!(err.contains("line 2") && err.contains("`abc`"), "{err}");
        assert!(Spectrum::new(vec![1.0], vec![0.1, 0.2], vec![0.0]).is_err());
        assert!(Spectrum::new(vec![1.0], vec![f64::INFINITY], vec![0.0]).unwrap_err().to_string().contains("z_re[0]"));
    }
}

mod fit {
    use cellstudio::eis::{EisFit, Spectrum, log_frequencies};
    use cellstudio::models::{ModelKind, Submodels};
    use cellstudio::optim::{Bounds, NoObserver, Objective, OptimOptions, Problem, Transform, by_name};
    use cellstudio::params::{chen2020, set_initial_soc};
    use rand::SeedableRng;
    use rand_distr::{Distribution, Normal};

    /// Fits `variables` of `kind` (contact resistance on) to a synthetic spectrum made at
    /// `truth` with 1 % Gaussian noise on the real and imaginary parts (standard deviation 1 %
    /// of |Z|), starting at twice the truth; returns (fitted x, evaluations, rebuilds).
    fn recover(kind: ModelKind, variables: &[&str], truth: &[f64], optimiser: &str) -> (Vec<f64>, usize, usize) {
        let mut base = chen2020();
        set_initial_soc(&mut base, 0.5).unwrap();
        let variables: Vec<String> = variables.iter().map(|v| v.to_string()).collect();
        let f = log_frequencies(1e-4, 1e3, 40).unwrap();
        let submodels = Submodels { contact_resistance: true, ..Default::default() };
        let placeholder = Spectrum::new(f.clone(), vec![1.0; f.len()], vec![0.0; f.len()]).unwrap();
        let clean = EisFit::new(base.clone(), variables.clone(), placeholder, kind)
            .unwrap()
            .with_submodels(submodels)
            .model_spectrum(truth)
            .unwrap();
        let mut rng = rand::rngs::StdRng::seed_from_u64(11);
        let unit = Normal::new(0.0, 1.0).unwrap();
        let mut noisy = clean.clone();
        for k in 0..f.len() {
            let sd = 0.01 * clean.magnitude(k);
            noisy.z_re[k] += sd * unit.sample(&mut rng);
            noisy.z_im[k] += sd * unit.sample(&mut rng);
        }
        let objective = EisFit::new(base, variables, noisy, kind).unwrap().with_submodels(submodels);
        let lower: Vec<f64> = truth.iter().map(|t| t / 10.0).collect();
        let upper: Vec<f64> = truth.iter().map(|t| t * 10.0).collect();
        let problem = Problem::new(&objective, Bounds::new(lower, upper).unwrap())
            .unwrap()
            .with_transforms(vec![Transform::Log; truth.len()])
            .unwrap();
        let options = OptimOptions::default().with_seed(5).with_max_evaluations(1000).unwrap().with_f_tolerance(1e-12).unwrap();
        let start: Vec<f64> = truth.iter().map(|t| 2.0 * t).collect();
        let t = std::time::Instant::now();
        let result = by_name(optimiser, options).unwrap().minimise(&problem, &start, &mut NoObserver).unwrap();
        println!(
            "{kind} {optimiser}: x = {:?} (truth {truth:?}), cost {:.3e} (at truth {:.3e}), {} evaluations, {} rebuilds, {:?}, stop {:?}",
            result.x,
            result.f,
            objective.evaluate(truth),
            result.evaluations,
            objective.rebuild_count(),
            t.elapsed(),
            result.stop
        );
        for (x, t) in result.x.iter().zip(truth) {
            assert!((x / t - 1.0).abs() < 0.05, "{x} vs {t}");
        }
        (result.x, result.evaluations, objective.rebuild_count())
    }

    /// A geometric parameter: every new radius rebuilds the model. (The negative radius is
    /// not identifiable this way at 50 % SOC: on the graphite plateau its diffusion impedance
    /// is negligible and its charge-transfer resistance, proportional to the radius, trades
    /// off exactly against the contact resistance.)
    #[test]
    fn recovers_positive_radius_and_contact_resistance_with_nelder_mead() {
        let (_, evaluations, rebuilds) =
            recover(ModelKind::Spm, &["positive.particle_radius", "cell.contact_resistance"], &[5.22e-6, 0.01], "nelder-mead");
        assert!(rebuilds > 1 && rebuilds <= evaluations + 1);
    }

    /// Non-geometric parameters: the one build is re-used throughout.
    #[test]
    fn recovers_diffusivity_and_contact_resistance_with_cmaes_without_rebuilds() {
        let (_, _, rebuilds) =
            recover(ModelKind::Spme, &["positive.diffusivity", "cell.contact_resistance"], &[4e-15, 0.01], "cmaes");
        assert!(rebuilds <= rayon::current_num_threads() + 1, "{rebuilds} builds");
    }
}

#[test]
fn a_state_away_from_rest_is_refused() {
    use cellstudio::geometry::MeshSizes;
    use cellstudio::models::ModelBuilder;
    use cellstudio::models::{ModelKind, Submodels};
    let mut p = chen2020();
    p.thermal.initial_temperature = p.thermal.ambient_temperature + 10.0;
    let mut b = ModelBuilder::new(ModelKind::Spm, Submodels { thermal: true, ..Default::default() }, MeshSizes::default());
    let built = b.build(&p).unwrap();
    let err = cellstudio::eis::rest_state(built.model.as_ref(), &mut built.workspace).unwrap_err().to_string();
    assert!(err.contains("not at rest"), "{err}");
    // At the ambient temperature the thermal model is at rest and has an impedance.
    p.thermal.initial_temperature = p.thermal.ambient_temperature;
    let built = b.build(&p).unwrap();
    let z = cellstudio::eis::model_impedance(built.model.as_ref(), &mut built.workspace, &[1e-3, 1.0]).unwrap();
    assert!(z.z_re.iter().all(|&r| r > 0.0));
}
