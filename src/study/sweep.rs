//! Running a study's sweep: grid evaluation, CSV/JSON and density plots.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use serde::Serialize;

use super::Study;
use crate::error::Error;
use crate::problem::design::{DesignMetrics, Metric};
use super::SweepDesign;
use crate::problem::sweep::{Status, SweepPoint, evaluate_all, grid, latin_hypercube};
use crate::report::plot::{Overlay, Series, heat_map, line_plot};

/// What a sweep produced.
pub struct SweepOutcome {
    pub points: Vec<SweepPoint>,
    pub baseline: DesignMetrics,
    pub rebuilds: usize,
    pub seconds: f64,
    pub files: Vec<PathBuf>,
    /// Warnings also written into `sweep.json` (designs that failed, stopped early or were
    /// skipped as infeasible).
    pub warnings: Vec<String>,
}

impl SweepOutcome {
    /// Points with a given status.
    pub fn count(&self, status: Status) -> usize {
        self.points.iter().filter(|p| p.status == status).count()
    }

    /// The valid point (feasible, evaluated, not stopped early) with the largest `metric`.
    pub fn best(&self, metric: Metric) -> Option<(&SweepPoint, DesignMetrics)> {
        best(&self.points, metric)
    }
}

/// The valid point of `points` with the largest `metric`.
fn best(points: &[SweepPoint], metric: Metric) -> Option<(&SweepPoint, DesignMetrics)> {
    points
        .iter()
        .filter(|p| p.status == Status::Valid)
        .filter_map(|p| p.metrics.map(|m| (p, m)))
        .max_by(|a, b| a.1.get(metric).total_cmp(&b.1.get(metric)))
}

/// The sweep's candidate points.
fn candidates(study: &Study, sweep: &super::Sweep) -> Result<Vec<Vec<f64>>, Error> {
    let lower: Vec<f64> = study.variables.iter().map(|v| v.lower).collect();
    let upper: Vec<f64> = study.variables.iter().map(|v| v.upper).collect();
    Ok(match sweep.design {
        SweepDesign::Grid => grid(&lower, &upper, &sweep.points),
        SweepDesign::LatinHypercube => {
            let n = sweep.samples.ok_or_else(|| Error::InvalidSetting {
                field: "sweep.samples".into(),
                reason: "a latin_hypercube sweep needs `samples`".into(),
            })?;
            latin_hypercube(&lower, &upper, n, sweep.seed)
        }
    })
}

/// The study's `[sweep]` table.
pub(super) fn sweep_table(study: &Study) -> Result<&super::Sweep, Error> {
    study.sweep.as_ref().ok_or_else(|| Error::InvalidSetting { field: "sweep".into(), reason: "the study has no [sweep] table".into() })
}

/// The study's sweep candidates, in order.
pub(super) fn sweep_candidates(study: &Study) -> Result<Vec<Vec<f64>>, Error> {
    candidates(study, sweep_table(study)?)
}

/// Evaluates the study's feasible grid points in parallel (points outside the linear
/// constraints are skipped) and writes `sweep.csv`, `sweep.json` and plots of gravimetric and
/// volumetric energy density into the output folder.
pub fn run_sweep(study: &Study) -> Result<SweepOutcome, Error> {
    let candidates = sweep_candidates(study)?;
    let out = study.output_dir()?;
    let problem = study.problem()?;
    let start = Instant::now();
    let baseline = problem.evaluate(&study.baseline()?)?;
    let points = evaluate_points(study, &problem, &baseline, candidates)?;
    write_sweep(study, out, baseline, points, problem.rebuild_count(), start.elapsed().as_secs_f64())
}

/// Evaluates `candidates` of the study's problem in parallel and gives each its status
/// (infeasible ones are skipped, not evaluated).
pub(super) fn evaluate_points(study: &Study, problem: &crate::problem::design::DesignProblem, baseline: &DesignMetrics, candidates: Vec<Vec<f64>>) -> Result<Vec<SweepPoint>, Error> {
    let feasibility = super::constraints::Feasibility::of(study)?;
    let feasible: Vec<Vec<f64>> = candidates.iter().filter(|x| feasibility.is_feasible(x)).cloned().collect();
    let mut evaluated = evaluate_all(problem, &feasible).into_iter();
    let min_u = study.operating.min_utilisation();
    Ok(candidates
        .into_iter()
        .map(|x| {
            if !feasibility.is_feasible(&x) {
                return SweepPoint { x, metrics: None, error: None, status: Status::Infeasible };
            }
            let mut p = evaluated.next().expect("one result per feasible point");
            p.status = match p.metrics {
                None => Status::Failed,
                Some(m) if super::degenerate(&m, baseline) => Status::Degenerate,
                Some(m) if m.stopped_early(min_u) => Status::StoppedEarly,
                Some(m) if !super::limits::all_hold(&study.limits, &m) => Status::OutsideLimits,
                Some(_) => Status::Valid,
            };
            p
        })
        .collect())
}

/// Writes a sweep's evaluated `points` (every candidate, in order) into the staged folder
/// `out` and moves it into place: `sweep.csv`, `sweep.json`, plots. `rebuilds` and `seconds`
/// are reported, not written, so a merged sweep writes what one run writes.
pub(super) fn write_sweep(study: &Study, out: crate::output::OutputDir, baseline: DesignMetrics, points: Vec<SweepPoint>, rebuilds: usize, seconds: f64) -> Result<SweepOutcome, Error> {
    let sweep = sweep_table(study)?;
    let baseline_x = study.baseline()?;
    let min_u = study.operating.min_utilisation();
    let n = points.len();
    let count = |s: Status| points.iter().filter(|p| p.status == s).count();
    let (failed, degenerate, early, infeasible) = (count(Status::Failed), count(Status::Degenerate), count(Status::StoppedEarly), count(Status::Infeasible));
    if count(Status::Valid) == 0 {
        let reason = points.iter().find_map(|p| p.error.as_ref().map(|e| format!("; the first failure, at {:?}: {e}", p.x))).unwrap_or_default();
        return Err(Error::InvalidSetting {
            field: "sweep".into(),
            reason: format!(
                "no valid design (nothing written): {failed} of {n} designs failed, {degenerate} store less than {} of the baseline's energy, {early} stopped early and {infeasible} violate the constraints{reason}",
                super::DEGENERATE_ENERGY_FRACTION
            ),
        });
    }
    let mut warnings = study.warnings();
    if failed > 0 {
        warnings.push(format!("{failed} of {n} designs failed (error column of sweep.csv; blank in the plots)"));
    }
    if degenerate > 0 {
        warnings.push(format!("{degenerate} of {n} designs store less than {} of the baseline's energy (degenerate)", super::DEGENERATE_ENERGY_FRACTION));
    }
    if early > 0 {
        warnings.push(format!("{early} of {n} designs stopped early (delivered less than {:.0} % of their theoretical capacity; not a best design)", 100.0 * min_u));
    }
    if infeasible > 0 {
        warnings.push(format!("{infeasible} of {n} designs violate the linear constraints and were skipped (blank in the plots)"));
    }
    let outside = count(Status::OutsideLimits);
    if outside > 0 {
        let limits: Vec<String> = study.limits.iter().map(super::limits::Limit::describe).collect();
        warnings.push(format!("{outside} of {n} designs lie outside the limits ({}; not a best design)", limits.join(", ")));
    }
    if let Some((p, _)) = best(&points, study.objective.maximise[0]) {
        let names: Vec<String> = study.variables.iter().map(|v| v.path.clone()).collect();
        let (lower, upper): (Vec<f64>, Vec<f64>) = study.variables.iter().map(|v| (v.lower, v.upper)).unzip();
        warnings.extend(super::at_bound_warnings("the sweep's best design", &names, &p.x, &lower, &upper));
    }
    let dir = out.path();
    let mut files = Vec::new();

    let names: Vec<&str> = study.variables.iter().map(|v| v.path.as_str()).collect();
    // The study's other metrics (objectives and limits) after the fixed columns.
    let fixed = [Metric::GravimetricEnergyDensity, Metric::VolumetricEnergyDensity, Metric::GravimetricPowerDensity, Metric::VolumetricPowerDensity];
    let mut extra: Vec<Metric> = Vec::new();
    for m in study.metrics().filter(|m| !fixed.contains(m)) {
        if !extra.contains(&m) {
            extra.push(m);
        }
    }
    let mut csv = names.join(",");
    csv.push_str(",energy_Wh,mass_kg,volume_m3,gravimetric_energy_density_Wh_kg,volumetric_energy_density_Wh_L,gravimetric_power_density_W_kg,volumetric_power_density_W_L,utilisation");
    for m in &extra {
        let _ = write!(csv, ",{}", m.key());
    }
    csv.push_str(",status,error\n");
    for p in &points {
        let xs: Vec<String> = p.x.iter().map(|v| format!("{v:e}")).collect();
        let m = p.metrics.unwrap_or_default();
        let nan = p.metrics.is_none();
        let f = |v: f64| if nan { "nan".to_string() } else { format!("{v}") };
        let extra: Vec<String> = extra.iter().map(|&e| format!(",{}", f(m.get(e)))).collect();
        let _ = writeln!(
            csv,
            "{},{},{},{},{},{},{},{},{}{},{},{}",
            xs.join(","),
            f(m.energy),
            f(m.mass),
            f(m.volume),
            f(m.gravimetric_energy_density),
            f(m.volumetric_energy_density),
            f(m.gravimetric_power_density),
            f(m.volumetric_power_density),
            f(m.utilisation),
            extra.concat(),
            p.status.name(),
            p.error.clone().unwrap_or_default().replace(',', ";")
        );
    }
    let csv_path = dir.join("sweep.csv");
    crate::error::write_file(&csv_path, csv)?;
    files.push(csv_path);
    let json_path = dir.join("sweep.json");
    // Streamed from borrowed data: a json! tree of 10^5 points took 0.4 GB.
    #[derive(Serialize)]
    struct SweepJson<'a, B: Serialize> {
        study: &'a str,
        variables: &'a [&'a str],
        baseline: B,
        warnings: &'a [String],
        points: &'a [SweepPoint],
    }
    let file = std::fs::File::create(&json_path).map_err(Error::io(&json_path))?;
    let mut writer = std::io::BufWriter::new(file);
    let doc = SweepJson { study: &study.name, variables: &names, baseline: &baseline, warnings: &warnings, points: &points };
    serde_json::to_writer_pretty(&mut writer, &doc).map_err(|e| Error::Io { path: json_path.display().to_string(), source: e.into() })?;
    std::io::Write::flush(&mut writer).map_err(Error::io(&json_path))?;
    files.push(json_path);

    let value = |p: &SweepPoint, grav: bool| {
        p.metrics.map_or(f64::NAN, |m| if grav { m.gravimetric_energy_density } else { m.volumetric_energy_density })
    };
    let axes: Vec<(f64, String)> = names.iter().map(|n| axis(n)).collect();
    for (grav, stem, unit) in [(true, "gravimetric_energy_density", "W h/kg"), (false, "volumetric_energy_density", "W h/L")] {
        let path = dir.join(format!("sweep_{stem}.svg"));
        let title = format!("{} ({unit})", stem.replace('_', " "));
        match (sweep.design, sweep.points.len()) {
            (SweepDesign::Grid, 1) => {
                let x: Vec<f64> = points.iter().map(|p| p.x[0] * axes[0].0).collect();
                let y: Vec<f64> = points.iter().map(|p| value(p, grav)).collect();
                line_plot(&path, &title, &axes[0].1, unit, &[Series { label: stem.into(), x: &x, y: &y }])?;
            }
            (SweepDesign::Grid, 2) => {
                let (n0, n1) = (sweep.points[0], sweep.points[1]);
                let x: Vec<f64> = (0..n0).map(|i| points[i * n1].x[0] * axes[0].0).collect();
                let y: Vec<f64> = (0..n1).map(|j| points[j].x[1] * axes[1].0).collect();
                let z: Vec<Vec<f64>> = (0..n0).map(|i| (0..n1).map(|j| value(&points[i * n1 + j], grav)).collect()).collect();
                let shown = |p: &[f64]| (p[0] * axes[0].0, p[1] * axes[1].0);
                let mut marks = vec![("baseline".to_string(), shown(&baseline_x))];
                let metric = if grav { Metric::GravimetricEnergyDensity } else { Metric::VolumetricEnergyDensity };
                if let Some((p, _)) = best(&points, metric) {
                    marks.push(("best valid design".to_string(), shown(&p.x)));
                }
                let box_ = ((x[0], x[x.len() - 1]), (y[0], y[y.len() - 1]));
                let boundaries = constraint_segments(study, &names, (axes[0].0, axes[1].0), box_);
                heat_map(&path, &title, (&axes[0].1, &axes[1].1), &x, &y, &z, &Overlay { marks: &marks, trace: &[], boundaries: &boundaries })?;
            }
            _ => {
                // Scattered samples: density against the first variable.
                let pts: Vec<(f64, f64)> = points.iter().map(|p| (p.x[0] * axes[0].0, value(p, grav))).collect();
                crate::report::plot::scatter_plot(&path, &title, (&axes[0].1, unit), &[(stem.into(), pts)], None)?;
            }
        }
        files.push(path);
    }
    let files = out.commit(&files)?;
    Ok(SweepOutcome { points, baseline, rebuilds, seconds, files, warnings })
}

/// Plot scale and axis label of a decision variable: lengths in micrometres, volume fractions
/// in per cent, anything else as it is (SI).
fn axis(path: &str) -> (f64, String) {
    let name = path.rsplit('.').next().unwrap_or(path);
    if name.ends_with("thickness") || name.ends_with("radius") {
        (1e6, format!("{path} (µm)"))
    } else if name.ends_with("fraction") || name == "porosity" {
        (100.0, format!("{path} (%)"))
    } else {
        (1.0, path.to_string())
    }
}

/// The parts of the study's linear-constraint boundaries (`sum a_k x_k = b` for each bound of
/// a constraint on the two plotted variables `names`) inside the plotted box, in the axes'
/// units (`scale`: shown value per SI unit).
fn constraint_segments(study: &Study, names: &[&str], scale: (f64, f64), ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64))) -> Vec<((f64, f64), (f64, f64))> {
    let mut out = Vec::new();
    for c in &study.constraints {
        let a = |k: usize| c.terms.get(names[k]).copied().unwrap_or(0.0);
        // In shown units: (a0 / s0) x + (a1 / s1) y = b.
        let (ax, ay) = (a(0) / scale.0, a(1) / scale.1);
        if c.terms.keys().any(|k| !names.contains(&k.as_str())) || (ax == 0.0 && ay == 0.0) {
            continue;
        }
        for b in [c.upper, c.lower, c.equals].into_iter().flatten() {
            let mut ends: Vec<(f64, f64)> = Vec::new();
            if ay != 0.0 {
                ends.extend([x0, x1].into_iter().map(|x| (x, (b - ax * x) / ay)).filter(|p| (y0..=y1).contains(&p.1)));
            }
            if ax != 0.0 {
                ends.extend([y0, y1].into_iter().map(|y| ((b - ay * y) / ax, y)).filter(|p| (x0..=x1).contains(&p.0)));
            }
            ends.sort_by(|p, q| p.0.total_cmp(&q.0).then(p.1.total_cmp(&q.1)));
            ends.dedup_by(|p, q| (p.0 - q.0).abs() <= 1e-12 * (x1 - x0).abs() && (p.1 - q.1).abs() <= 1e-12 * (y1 - y0).abs());
            if let (Some(&first), Some(&last)) = (ends.first(), ends.last()) {
                if ends.len() >= 2 {
                    out.push((first, last));
                }
            }
        }
    }
    out
}
