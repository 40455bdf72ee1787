//! The `eis` run: a model's impedance spectrum at a state of charge, and optionally a fit of
//! named parameters to a measured spectrum, with CSV output and a Nyquist plot.

use std::path::PathBuf;

use crate::eis::{EisFit, Spectrum, log_frequencies};
use crate::error::Error;
use crate::models::{ModelKind, Submodels};
use crate::optim::{Bounds, OptimOptions, OptimResult, Problem, ProgressObserver, Transform, by_name};
use crate::params::{ParameterSet, set_initial_soc};
use crate::report::nyquist::nyquist_plot;

/// What to compute.
pub struct EisRun {
    pub kind: ModelKind,
    pub submodels: Submodels,
    pub params: ParameterSet,
    /// State of charge (-) of the rest state.
    pub soc: f64,
    /// Frequency range (Hz) and points of the model spectrum when no data are given.
    pub frequencies: (f64, f64, usize),
    /// Measured spectrum to fit, when fitting.
    pub fit: Option<EisFitRequest>,
    pub optimiser: String,
    pub out: PathBuf,
    /// Other files the run reads (the parameter set), which no output may overwrite.
    pub inputs: Vec<PathBuf>,
}

/// Most frequencies of a model spectrum.
pub const MAX_FREQUENCIES: usize = 100_000;

/// The `--frequencies F_MIN F_MAX N` triple checked: positive finite increasing frequencies
/// (Hz) and a whole number of points in `2..=MAX_FREQUENCIES`.
///
/// ```
/// use cellstudio::study::eis::frequency_grid;
/// assert_eq!(frequency_grid(&[1e-4, 1e3, 60.0]).unwrap(), (1e-4, 1e3, 60));
/// assert!(frequency_grid(&[1e-4, 1e3, 2.7]).unwrap_err().to_string().contains("whole number"));
/// assert!(frequency_grid(&[1e-4, 1e3, 1e30]).unwrap_err().to_string().contains("at most"));
/// ```
pub fn frequency_grid(values: &[f64]) -> Result<(f64, f64, usize), Error> {
    let [f0, f1, n] = values else {
        return Err(Error::InvalidSetting { field: "--frequencies".into(), reason: format!("expected F_MIN F_MAX N, got {values:?}") });
    };
    let (f0, f1, n) = (*f0, *f1, *n);
    if !(f0 > 0.0 && f0.is_finite()) {
        return Err(Error::invalid("--frequencies F_MIN", f0, "must be a positive frequency (Hz)"));
    }
    if !(f1 > f0 && f1.is_finite()) {
        return Err(Error::invalid("--frequencies F_MAX", f1, format!("must be finite and exceed F_MIN = {}", crate::error::number(f0))));
    }
    if n.fract() != 0.0 || !n.is_finite() {
        return Err(Error::invalid("--frequencies N", n, "must be a whole number of points"));
    }
    if !(2.0..=MAX_FREQUENCIES as f64).contains(&n) {
        return Err(Error::invalid("--frequencies N", n, format!("must be at least 2 and at most {MAX_FREQUENCIES}")));
    }
    Ok((f0, f1, n as usize))
}

/// The most model spectra an impedance fit evaluates (not a setting of `eis`).
const EIS_FIT_EVALUATIONS: usize = 2000;

/// A measured spectrum and the parameters to fit to it.
pub struct EisFitRequest {
    /// The measured spectrum (CSV).
    pub data: PathBuf,
    /// Dotted parameter paths, searched on a log scale between a tenth and ten times the
    /// parameter set's values.
    pub parameters: Vec<String>,
}

/// The fitted parameters of an `eis` run.
pub struct EisFitted {
    /// Dotted parameter paths and their fitted values (SI).
    pub names: Vec<String>,
    pub values: Vec<f64>,
    /// The optimiser's result (cost, evaluations, stop reason).
    pub result: OptimResult,
    /// Wall time of the fit (s).
    pub seconds: f64,
}

/// What an `eis` run produced.
pub struct EisOutcome {
    pub spectrum: Spectrum,
    /// Fitted values with the optimiser's result, when fitting.
    pub fit: Option<EisFitted>,
    pub files: Vec<PathBuf>,
    /// A fit cut short by its evaluation cap.
    pub warnings: Vec<String>,
}

pub fn run_eis(run: &EisRun) -> Result<EisOutcome, Error> {
    let mut base = run.params.clone();
    set_initial_soc(&mut base, run.soc)?;
    let (f0, f1, n) = run.frequencies;
    let dense = log_frequencies(f0, f1, n)?;
    let inputs: Vec<&std::path::Path> = run.inputs.iter().map(|p| p.as_path()).chain(run.fit.as_ref().map(|f| f.data.as_path())).collect();
    let out = crate::output::OutputDir::create(&run.out, &inputs)?;
    let spectrum_of = |variables: &[String], x: &[f64]| -> Result<Spectrum, Error> {
        let probe = Spectrum::new(dense.clone(), vec![1.0; dense.len()], vec![0.0; dense.len()])?;
        EisFit::new(base.clone(), variables.to_vec(), probe, run.kind)?.with_submodels(run.submodels).model_spectrum(x)
    };
    let mut files = Vec::new();
    let mut warnings = Vec::new();
    let nyquist = out.path().join("nyquist.svg");
    let title = format!("{} impedance at {:.0} % SOC", run.kind, 100.0 * run.soc);
    let (spectrum, fit) = match &run.fit {
        None => {
            let s = spectrum_of(&[], &[])?;
            nyquist_plot(&nyquist, &title, None, &[("model", &s)])?;
            (s, None)
        }
        Some(EisFitRequest { data: data_path, parameters: variables }) => {
            let data = Spectrum::from_csv(data_path).map_err(|e| e.input("--fit"))?;
            // Two numbers (real, imaginary) per frequency; a fit needs more than it has unknowns.
            if data.len() <= variables.len() {
                return Err(Error::InvalidSetting {
                    field: "--fit".into(),
                    reason: format!("{}: {} frequencies cannot determine {} parameters: needs at least {}", data_path.display(), data.len(), variables.len(), variables.len() + 1),
                });
            }
            let objective = EisFit::new(base.clone(), variables.clone(), data.clone(), run.kind)?.with_submodels(run.submodels);
            let x0: Vec<f64> = variables.iter().map(|v| base.get(v)).collect::<Result<_, _>>()?;
            if let Some((v, x)) = variables.iter().zip(&x0).find(|(_, x)| !(**x > 0.0)) {
                return Err(Error::invalid(v.clone(), *x, "must be positive to be fitted on a log scale"));
            }
            let bounds = Bounds::new(x0.iter().map(|x| x / 10.0).collect(), x0.iter().map(|x| x * 10.0).collect())?;
            let problem = Problem::new(&objective, bounds.clone())?.with_transforms(vec![Transform::Log; x0.len()])?;
            let options = OptimOptions::default().with_seed(1).with_max_evaluations(EIS_FIT_EVALUATIONS)?.with_f_tolerance(1e-12)?;
            let start = std::time::Instant::now();
            let mut progress = ProgressObserver::new("EIS fit", options.max_iterations, |f| format!("cost {f:.4e}"));
            let result = by_name(&run.optimiser, options)?.minimise(&problem, &x0, &mut progress)?;
            progress.finish();
            let seconds = start.elapsed().as_secs_f64();
            // The search box is one decade either side of the set's value: an end on its edge
            // is no estimate (nothing is written, as for a fit).
            let on_bound = super::at_bound_warnings("the impedance fit", variables, &result.x, bounds.lower(), bounds.upper());
            if !on_bound.is_empty() {
                return Err(Error::InvalidSetting {
                    field: "--parameters".into(),
                    reason: format!("{}; it searches one decade either side of the set's value: set a starting value nearer the data with --set (nothing written)", on_bound.join("; ")),
                });
            }
            let remedy = format!("its cap of {EIS_FIT_EVALUATIONS} evaluations is fixed: fit fewer --parameters or choose another --optimiser");
            warnings.extend(super::truncation_warning_with("the impedance fit", &result.stop, result.iterations, result.evaluations, &remedy));
            let (initial, fitted) = (spectrum_of(variables, &x0)?, spectrum_of(variables, &result.x)?);
            nyquist_plot(&nyquist, &title, Some(("data", &data)), &[("initial", &initial), ("fitted", &fitted)])?;
            // The fitted values on file, with how the search ended: a truncated fit says so.
            let json = serde_json::json!({
                "data": data_path.display().to_string(),
                "parameters": variables.iter().zip(&result.x).map(|(n, v)| (n.clone(), serde_json::json!(v))).collect::<serde_json::Map<_, _>>(),
                "start": variables.iter().zip(&x0).map(|(n, v)| (n.clone(), serde_json::json!(v))).collect::<serde_json::Map<_, _>>(),
                "cost": result.f,
                "stop": format!("{:?}", result.stop),
                "iterations": result.iterations,
                "evaluations": result.evaluations,
                "optimiser": run.optimiser,
                "warnings": warnings,
            });
            super::write_output(out.path(), "fit.json", serde_json::to_string_pretty(&json).unwrap_or_default(), &mut files)?;
            (fitted, Some(EisFitted { names: variables.clone(), values: result.x.clone(), result, seconds }))
        }
    };
    files.push(nyquist);
    let csv = out.path().join("spectrum.csv");
    spectrum.write_csv(&csv)?;
    files.push(csv);
    let files = out.commit(&files)?;
    Ok(EisOutcome { spectrum, fit, files, warnings })
}
