//! Command-line interface (thin: parsing and printing only).

use std::process::ExitCode;

use clap::Parser;

mod cli;
use cli::{Cli, Command, DataCommand, Overrides};

use cellstudio::models::Submodels;
use cellstudio::models::submodels::{ParticleSize, refuse_unread, refuse_unread_overrides};
use cellstudio::output::OutputDir;
use cellstudio::params::{ParameterSet, apply_overrides};
use cellstudio::Error;
use cellstudio::study::Study;
use cellstudio::study::cycle::CycleStudy;
use cellstudio::study::design::run_design;
use cellstudio::study::fit::{FitStudy, parameter_table};
use cellstudio::study::fit_run::run_fit;
use cellstudio::study::sample::run_sample;
use cellstudio::study::eis;
use cellstudio::study::pareto::run_pareto;
use cellstudio::study::simulate::{ProtocolSource, SimulateRun, run_simulate};
use cellstudio::study::sweep::run_sweep;
use cellstudio::problem::design::Metric;

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The parameter set from `--params` (or the embedded default) with `--set` overrides.
fn load_parameters(params: Option<&std::path::Path>, overrides: &Overrides) -> Result<ParameterSet, Error> {
    let mut p = ParameterSet::from_file_or_default(params).map_err(|e| e.input("--params"))?;
    apply_overrides(&mut p, &overrides.set)?;
    Ok(p)
}

/// `--contact-resistance` (ohm), checked and applied.
fn set_contact_resistance(p: &mut ParameterSet, r: Option<f64>) -> Result<(), Error> {
    if let Some(r) = r {
        if !(r >= 0.0 && r.is_finite()) {
            return Err(Error::invalid("--contact-resistance", r, "must be a non-negative resistance (ohm)"));
        }
        p.cell.contact_resistance = r;
    }
    Ok(())
}

fn note(notes: &[String]) {
    for n in notes {
        eprintln!("note: {n}");
    }
}

fn warn(warnings: &[String]) {
    for w in warnings {
        eprintln!("warning: {w}");
    }
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Diagnose { overrides, model, data, params, contact_resistance, thermal, fit, refits, start_at_rest, max_rounds, time_budget, out } => {
            use cellstudio::diagnose::{DiagnoseOptions, default_fit_parameter, diagnose_rounds_with, read_by_a_candidate, report};
            use std::io::Write;
            if refits == Some(0) {
                return Err(Error::invalid("--refits", 0.0, "must be at least 1: with no candidate refitted nothing can be named or ruled out"));
            }
            if max_rounds == 0 {
                return Err(Error::invalid("--max-rounds", 0.0, "must be at least 1"));
            }
            if let Some(b) = time_budget.filter(|b| !(b.is_finite() && *b > 0.0)) {
                return Err(Error::invalid("--time-budget", b, "must be a positive number of seconds"));
            }
            let p = load_parameters(params.as_deref(), &overrides)?;
            // A contact resistance set switches its submodel on, as for `simulate`. A `--set` or
            // `--fit` that neither the model nor a candidate reads would change nothing.
            let contact_resistance = overrides.contact_resistance(contact_resistance);
            let submodels = Submodels { contact_resistance, thermal, ..Default::default() };
            let settings = overrides.set.iter().map(|o| (format!("--set {}", o.path), o.path.as_str())).chain(fit.iter().map(|q| (format!("--fit {q}"), q.as_str())));
            refuse_unread(&submodels, settings.filter(|(_, path)| !read_by_a_candidate(path))).map_err(|e| match e {
                Error::InvalidSetting { field, reason } => Error::InvalidSetting { field, reason: format!("{reason}; the candidate that adds it fits it from its own start") },
                other => other,
            })?;
            let staged = OutputDir::create(&out, &[Some(data.as_path()), params.as_deref()].into_iter().flatten().collect::<Vec<_>>())?;
            let rec = cellstudio::data::cycler::read_recording(&data, &Default::default()).map_err(|e| e.input("--data"))?;
            let mut options = DiagnoseOptions::new(cellstudio::problem::fitting::ModelSpec::new(model, submodels));
            options.fitted = fit.iter().map(|path| default_fit_parameter(path, &p)).collect::<Result<_, _>>()?;
            if let Some(n) = refits {
                options.max_refits = n;
            }
            options.fit.start_at_rest = start_at_rest;
            options.time_budget = time_budget;
            // Each round is printed as soon as it is done: a run stopped part-way still shows
            // the rounds it finished. The files below are written only when all are done.
            let mut printed = 0;
            let rounds = diagnose_rounds_with(&rec, &p, &options, max_rounds, |d| {
                printed += 1;
                println!("{}# Round {printed} (of at most {max_rounds})\n\n{}", if printed > 1 { "\n" } else { "" }, report::markdown(d, &[]));
                let _ = std::io::stdout().flush();
            })?;
            let superseded = rounds.last().map_or(String::new(), |d| report::superseded(&d.superseded));
            if !superseded.is_empty() {
                println!("\n{}", superseded.trim_start());
            }
            println!("\n{}\n", report::conclusion(&rounds));
            let written = cellstudio::report::diagnosis_files::write(&rounds, staged.path())?;
            for f in staged.commit(&written)? {
                println!("wrote            {}", f.display());
            }
            Ok(())
        }
        Command::Data { action: DataCommand::Inspect { overrides, file, params, json } } => {
            use cellstudio::data::cycler::{inspect_json, inspect_text, read_checked};
            // Read and checked as `fit` and `diagnose` read and check a recording.
            let p = load_parameters(params.as_deref(), &overrides)?;
            let (data, notes) = read_checked(&file, &Default::default(), &p).map_err(|e| e.input("FILE"))?;
            note(&notes);
            if json { println!("{}", inspect_json(&file, &data)) } else { print!("{}", inspect_text(&file, &data)) }
            Ok(())
        }
        Command::Design { overrides, study } => {
            let study = Study::from_file(&study)?.with_overrides(overrides.set)?;
            let out = run_design(&study)?;
            warn(&out.warnings);
            let m = out.metric;
            println!("study            {}", study.name);
            println!("objective        maximise {}", m.label());
            println!("initial          {:.2} at {:?}", out.initial.get(m), out.initial_x);
            println!("optimised        {:.2} at {:?} ({:+.2} %)", out.optimised.get(m), out.result.x, out.improvement());
            if !out.active_limits.is_empty() {
                println!("active limits    {}", out.active_limits.join(", "));
            }
            println!("search           {:?} after {} iterations, {} evaluations, {} model builds, {:.2} s ({:.0} evaluations/s)",
                out.result.stop, out.result.iterations, out.result.evaluations, out.rebuilds, out.seconds, out.result.evaluations as f64 / out.seconds);
            for f in &out.files {
                println!("wrote            {}", f.display());
            }
            Ok(())
        }
        Command::Cycle { overrides, study } => {
            let study = CycleStudy::from_file(&study)?.with_overrides(overrides.set)?;
            let out = study.run(&mut |_| {})?;
            let (first, last) = (&out.summaries[0], &out.summaries[out.summaries.len() - 1]);
            println!("study            {}", study.name);
            println!("cycles           {} in {:.2} s ({:.3} s per cycle)", out.summaries.len(), out.seconds, out.seconds / out.summaries.len() as f64);
            println!("discharge        {:.6} A h (cycle 1) -> {:.6} A h (cycle {}), retention {:.4} %", first.discharge_capacity_ah, last.discharge_capacity_ah, last.cycle, 100.0 * last.capacity_retention);
            println!("lithium lost     {:.4e} mol to the SEI, {:.4} % of the inventory", last.lithium_lost_to_sei_mol, 100.0 * last.lithium_inventory_lost);
            if let Some(l) = last.sei_thickness_m {
                println!("SEI thickness    {:.4} nm", l * 1e9);
            }
            if let (Some(am), Some(li)) = (last.active_material_lost, last.lithium_lost_to_lam_mol) {
                println!("active material  {:.4} % lost (negative), {:.4} % (positive), with {:.4e} / {:.4e} mol of lithium", 100.0 * am[0], 100.0 * am[1], li[0], li[1]);
            }
            if let (Some(lost), Some(dead)) = (last.lithium_lost_to_plating_mol, last.dead_lithium_mol) {
                println!("plated lithium   {lost:.4e} mol lost to plating, {dead:.4e} mol of it dead");
            }
            if let Some(fade) = &out.fade {
                warn(&fade.warnings());
                println!("fade fit         RMSE {:.3} mA h (start {:.3} mA h), {} iterations, {} simulations", fade.rmse_fitted_ah * 1e3, fade.rmse_start_ah * 1e3, fade.iterations, fade.simulations);
                for line in fade.lines() {
                    println!("                 {line}");
                }
            }
            for f in &out.files {
                println!("wrote            {}", f.display());
            }
            Ok(())
        }
        Command::Fit { overrides, study, data } => {
            let study = FitStudy::from_file(&study)?.with_overrides(overrides.set)?;
            let out = run_fit(&study, data.as_deref())?;
            note(&out.notes);
            warn(&out.warnings);
            let r = &out.result;
            println!("{}", study.name);
            println!(
                "RMSE {:.3} mV (initial {:.3} mV); {} evaluations, {} gradients, {:.2} s; stop: {:?}",
                r.rmse * 1e3,
                out.initial_rmse * 1e3,
                r.evaluations,
                r.gradient_evaluations,
                r.seconds,
                r.stop
            );
            for e in &out.experiments {
                println!("  {}: RMSE {:.3} mV (initial {:.3} mV), {} points, weight {}", e.name, e.rmse * 1e3, e.initial_rmse * 1e3, e.points, e.weight);
            }
            println!("{}", parameter_table(r));
            for f in &out.files {
                println!("wrote {}", f.display());
            }
            // Written for inspection to NAME.rejected, but not an estimate: exit non-zero.
            out.rejection.map_or(Ok(()), Err)
        }
        Command::Parameterise { overrides, study } => {
            use cellstudio::study::parameterise::{ParameterisationStudy, run_parameterisation};
            let study = ParameterisationStudy::from_file(&study)?.with_overrides(overrides.set)?;
            let out = run_parameterisation(&study)?;
            note(&out.notes);
            warn(&out.warnings);
            println!("{}", study.name);
            for line in &out.summary {
                println!("  {line}");
            }
            for f in &out.files {
                println!("wrote {}", f.display());
            }
            Ok(())
        }
        Command::Sample { overrides, study, data } => {
            let study = FitStudy::from_file(&study)?.with_overrides(overrides.set)?;
            let out = run_sample(&study, data.as_deref())?;
            note(&out.notes);
            warn(&out.warnings);
            println!("{}: {} draws per chain in {:.1} s", study.name, out.result.options.iterations, out.seconds);
            println!("{}", out.summary.table());
            for f in &out.files {
                println!("wrote {}", f.display());
            }
            Ok(())
        }
        Command::Eis { overrides, model, soc, params, contact_resistance, frequencies, fit, parameters, optimiser, out } => {
            if !(0.0..=1.0).contains(&soc) {
                return Err(Error::invalid("--soc", soc, "must lie in 0..=1"));
            }
            let frequencies = eis::frequency_grid(&frequencies)?;
            cellstudio::optim::by_name(&optimiser, Default::default())?;
            let mut p = load_parameters(params.as_deref(), &overrides)?;
            set_contact_resistance(&mut p, contact_resistance)?;
            // A contact resistance given, set or fitted switches its submodel on.
            let fits_contact = fit.is_some() && parameters.iter().any(|q| q == "cell.contact_resistance");
            let submodels = Submodels { contact_resistance: overrides.contact_resistance(contact_resistance.is_some()) || fits_contact, ..Default::default() };
            refuse_unread_overrides(&submodels, &overrides.set)?;
            if fit.is_some() {
                refuse_unread(&submodels, parameters.iter().map(|q| (format!("--parameters {q}"), q.as_str())))?;
            }
            let run = eis::EisRun {
                kind: model,
                submodels,
                params: p,
                soc,
                frequencies,
                fit: fit.map(|data| eis::EisFitRequest { data, parameters }),
                optimiser,
                out,
                inputs: params.into_iter().collect(),
            };
            let outcome = eis::run_eis(&run)?;
            warn(&outcome.warnings);
            if let Some(fitted) = &outcome.fit {
                let result = &fitted.result;
                println!("fit: {} evaluations in {:.2} s, cost {:.3e}, stop {:?}", result.evaluations, fitted.seconds, result.f, result.stop);
                for (n, v) in fitted.names.iter().zip(&fitted.values) {
                    println!("  {n} = {v:.5e}");
                }
            }
            for f in &outcome.files {
                println!("wrote {}", f.display());
            }
            Ok(())
        }
        Command::Pareto { overrides, study } => {
            let study = Study::from_file(&study)?.with_overrides(overrides.set)?;
            let out = run_pareto(&study)?;
            warn(&out.warnings);
            println!("study            {}", study.name);
            println!(
                "designs          {} evaluated ({} failed, {} stopped early: off the front; {} projected onto the constraints) in {:.2} s, {} model builds",
                out.evaluated, out.failed, out.stopped_early, out.repaired, out.seconds, out.rebuilds
            );
            println!("baseline         {:?}", out.baseline);
            println!("front            {} non-dominated designs", out.front.len());
            for ind in &out.front {
                println!("                 x = {:?} -> {:?}", ind.x, ind.f);
            }
            for f in &out.files {
                println!("wrote            {}", f.display());
            }
            Ok(())
        }
        Command::Sweep { overrides, study, shard, merge } => {
            let study = Study::from_file(&study)?.with_overrides(overrides.set)?;
            if let Some(shard) = shard {
                let (file, points, seconds) = cellstudio::study::shard::run_shard(&study, shard)?;
                println!("shard            {}/{}: {points} designs in {seconds:.2} s", shard.k, shard.n);
                println!("wrote            {}", file.display());
                return Ok(());
            }
            let out = if merge.is_empty() { run_sweep(&study)? } else { cellstudio::study::shard::merge_shards(&study, &merge)? };
            warn(&out.warnings);
            use cellstudio::problem::sweep::Status;
            println!("study            {}", study.name);
            println!(
                "designs          {} points: {} evaluated ({} failed, {} stopped early), {} infeasible skipped, in {:.2} s ({:.0} designs/s on {} threads), {} model builds",
                out.points.len(),
                out.points.len() - out.count(Status::Infeasible),
                out.count(Status::Failed),
                out.count(Status::StoppedEarly),
                out.count(Status::Infeasible),
                out.seconds,
                (out.points.len() - out.count(Status::Infeasible)) as f64 / out.seconds,
                rayon::current_num_threads(),
                out.rebuilds
            );
            println!("baseline         {:.1} W h/kg, {:.1} W h/L", out.baseline.gravimetric_energy_density, out.baseline.volumetric_energy_density);
            for (label, metric) in [("best W h/kg", Metric::GravimetricEnergyDensity), ("best W h/L", Metric::VolumetricEnergyDensity)] {
                if let Some((p, m)) = out.best(metric) {
                    println!("{label:16} {:.1} W h/kg, {:.1} W h/L at {:?}", m.gravimetric_energy_density, m.volumetric_energy_density, p.x);
                }
            }
            for f in &out.files {
                println!("wrote            {}", f.display());
            }
            Ok(())
        }
        Command::Simulate { overrides, model, c_rate, protocol, experiment, params, contact_resistance, thermal, size_distribution, mesh, out, repeat, json } => {
            let mut p = load_parameters(params.as_deref(), &overrides)?;
            set_contact_resistance(&mut p, contact_resistance)?;
            let protocol = match protocol {
                Some(path) => ProtocolSource::File(path),
                None if !experiment.is_empty() => ProtocolSource::Experiment(experiment),
                None => ProtocolSource::Discharge { c_rate },
            };
            // `--size-distribution`, or a `--set` of a relative spread, switches it on.
            let spread = ["negative.radius_relative_std", "positive.radius_relative_std"].into_iter().find(|p| overrides.sets(p));
            let switch = if size_distribution { Some("--size-distribution".to_string()) } else { spread.map(|p| format!("--set {p}")) };
            let particle_size = if switch.is_some() { ParticleSize::Distribution } else { ParticleSize::Single };
            let submodels = Submodels { contact_resistance: overrides.contact_resistance(contact_resistance.is_some()), thermal, particle_size, ..Default::default() };
            submodels.check_for(model).map_err(|e| match (e, &switch) {
                (Error::InvalidSetting { reason, .. }, Some(field)) => Error::InvalidSetting { field: field.clone(), reason },
                (other, _) => other,
            })?;
            refuse_unread_overrides(&submodels, &overrides.set)?;
            let run = SimulateRun { model, submodels, params: p, protocol, mesh, repeat, out, inputs: params.into_iter().collect() };
            let outcome = run_simulate(&run)?;
            warn(&outcome.warnings);
            let sol = &outcome.solution;
            if json {
                println!("{}", outcome.summary_json(model));
            } else {
                println!("model            {model} ({})", run.params.name);
                println!("capacity         {:.4} A h", sol.final_capacity());
                println!("energy           {:.4} W h", sol.final_energy());
                println!("final voltage    {:.4} V at t = {:.1} s", sol.final_voltage(), sol.time.last().copied().unwrap_or(0.0));
                println!("build time       {:.3} ms", outcome.build_time * 1e3);
                println!("solve time       {:.3} ms (median of {})", outcome.solve_time_median * 1e3, outcome.repeats);
                println!("solver steps     {} ({} Jacobians, {} rhs evaluations)", sol.stats.steps, sol.stats.jacobian_evals, sol.stats.rhs_evals);
                println!("wrote            {} and {}", outcome.csv.display(), outcome.svg.display());
                if let Some(f) = outcome.fields.first() {
                    println!("fields           {} (+ {} profile plots)", f.display(), outcome.fields.len() - 1);
                }
            }
            Ok(())
        }
    }
}
