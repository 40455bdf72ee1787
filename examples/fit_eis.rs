//! Fits the SPM's positive particle radius and contact resistance to a synthetic impedance
//! spectrum (known parameters, 1 % noise) from a start twice too large, and writes the data,
//! the start and the fit as a Nyquist plot to `out/eis/nyquist.svg` (data as
//! `out/eis/data.csv`).
//!
//! `cargo run --release --example fit_eis [-- OPTIMISER]` (default nelder-mead)

use std::path::Path;
use std::time::Instant;

use cellstudio::eis::{EisFit, Spectrum, log_frequencies};
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::optim::{Bounds, NoObserver, OptimOptions, Problem, Transform, by_name};
use cellstudio::params::{chen2020, set_initial_soc};
use cellstudio::report::nyquist::nyquist_plot;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

fn main() -> Result<(), cellstudio::Error> {
    let optimiser = std::env::args().nth(1).unwrap_or_else(|| "nelder-mead".into());
    let mut base = chen2020();
    set_initial_soc(&mut base, 0.5)?;
    let variables = vec!["positive.particle_radius".to_string(), "cell.contact_resistance".to_string()];
    let truth = [5.22e-6, 0.01];
    let start = [2.0 * truth[0], 2.0 * truth[1]];
    let submodels = Submodels { contact_resistance: true, ..Default::default() };
    let f = log_frequencies(1e-4, 1e3, 40)?;

    // Synthetic measurement: the model at the truth plus 1 % complex Gaussian noise.
    let placeholder = Spectrum::new(f.clone(), vec![1.0; f.len()], vec![0.0; f.len()])?;
    let clean = EisFit::new(base.clone(), variables.clone(), placeholder, ModelKind::Spm)?.with_submodels(submodels).model_spectrum(&truth)?;
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    let unit = Normal::new(0.0, 1.0).expect("unit normal");
    let mut data = clean.clone();
    for k in 0..f.len() {
        let sd = 0.01 * clean.magnitude(k);
        data.z_re[k] += sd * unit.sample(&mut rng);
        data.z_im[k] += sd * unit.sample(&mut rng);
    }

    let objective = EisFit::new(base, variables.clone(), data.clone(), ModelKind::Spm)?.with_submodels(submodels);
    let bounds = Bounds::new(truth.iter().map(|t| t / 10.0).collect(), truth.iter().map(|t| t * 10.0).collect())?;
    let problem = Problem::new(&objective, bounds)?.with_transforms(vec![Transform::Log; 2])?;
    let options = OptimOptions::default().with_seed(5).with_max_evaluations(1000)?.with_f_tolerance(1e-12)?;
    let t = Instant::now();
    let result = by_name(&optimiser, options)?.minimise(&problem, &start, &mut NoObserver)?;
    let elapsed = t.elapsed();
    println!("{optimiser}: {} evaluations, {} model builds, {:.2} s, stop {:?}", result.evaluations, objective.rebuild_count(), elapsed.as_secs_f64(), result.stop);
    println!("| parameter | truth | start | fitted | error |");
    println!("|---|---|---|---|---|");
    for i in 0..variables.len() {
        println!("| {} | {:.4e} | {:.4e} | {:.4e} | {:+.2} % |", variables[i], truth[i], start[i], result.x[i], 100.0 * (result.x[i] / truth[i] - 1.0));
    }

    let dir = Path::new("out/eis");
    std::fs::create_dir_all(dir).map_err(|source| cellstudio::Error::Io { path: dir.display().to_string(), source })?;
    data.write_csv(&dir.join("data.csv"))?;
    let dense = log_frequencies(1e-4, 1e4, 200)?;
    let line = |x: &[f64]| -> Result<Spectrum, cellstudio::Error> {
        let fit = EisFit::new(objective.base.clone(), variables.clone(), Spectrum::new(dense.clone(), vec![1.0; dense.len()], vec![0.0; dense.len()])?, ModelKind::Spm)?;
        fit.with_submodels(submodels).model_spectrum(x)
    };
    let (fitted, initial) = (line(&result.x)?, line(&start)?);
    let path = dir.join("nyquist.svg");
    nyquist_plot(
        &path,
        "SPM impedance at 50 % SOC: synthetic data and fit",
        Some(("synthetic data (1 % noise)", &data)),
        &[("start (2x radius and contact resistance)", &initial), ("fitted SPM", &fitted)],
    )?;
    println!("wrote {}", path.display());
    Ok(())
}
