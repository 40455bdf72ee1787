//! The diagnosis in words: the verdict sentence first, where the residual lies, the conclusion
//! over the rounds, and the Markdown report of a round (files: `crate::report::diagnosis_files`).

use std::fmt::Write;

use super::{Candidate, CandidateOutcome, Class, Diagnosis, FitOutcome, ResidualAnalysis, Verdict};
use crate::problem::fitting::INITIAL_SOC;

/// What a fit says about one value besides the value itself.
#[derive(Clone, Copy, Debug)]
pub struct ValueNote {
    /// Standard error (parameter units; infinite when the data do not determine it).
    pub std_error: f64,
    /// The value does not move the voltage of this recording (a rate on its no-effect bound).
    pub no_effect: bool,
    /// The value ended on its search bound: the optimum may lie beyond it.
    pub on_bound: bool,
}

/// A fitted value with its standard error in readable units, and a note when it sits on its
/// search bound or has no effect on the recording.
pub fn format_parameter(path: &str, value: f64, note: ValueNote) -> String {
    let ValueNote { std_error, no_effect, on_bound } = note;
    let name = path.rsplit('.').next().unwrap_or(path);
    let bound = if on_bound { ", on its search bound" } else { "" };
    let spread = |e: String| {
        if no_effect {
            format!(" (no effect on this recording{bound})")
        } else if std_error.is_finite() {
            format!(" ± {e}{}", if on_bound { " (on its search bound)" } else { "" })
        } else {
            format!(" (not identifiable{bound})")
        }
    };
    let se = |scale: f64, digits: usize| spread(format!("{:.*}", digits, std_error * scale));
    let scientific = |unit: &str| format!("{path} = {value:.3e}{}{unit}", spread(format!("{std_error:.2e}")));
    match name {
        "contact_resistance" | "rc_resistance" => format!("{path} = {:.2}{} mOhm", value * 1e3, se(1e3, 2)),
        "hysteresis_voltage" => format!("{path} = {:.2}{} mV", value * 1e3, se(1e3, 2)),
        "rc_capacitance" => format!("{path} = {value:.4e}{} F", se(1.0, 1)),
        "diffusivity" => scientific(" m^2/s"),
        "initial_concentration" => format!("{path} = {value:.0}{} mol/m^3", se(1.0, 0)),
        "heat_transfer_coefficient" => format!("{path} = {value:.3}{} W/(m^2 K)", se(1.0, 3)),
        "ambient_temperature" => format!("{path} = {value:.2}{} K", se(1.0, 2)),
        "exchange_current" => scientific(" A/m^2"),
        _ if value != 0.0 && !(1e-2..1e4).contains(&value.abs()) => scientific(""),
        _ => format!("{path} = {value:.4}{}", se(1.0, 4)),
    }
}

/// Millivolts with two decimals, or "none" for a value the recording does not give (e.g.
/// the mean residual in rests after a charge when it has no charge).
pub(super) fn mv(v: f64) -> String {
    if v.is_finite() { format!("{:.2} mV", v * 1e3) } else { "none".into() }
}

/// Where the residual lies, in sentences.
pub fn locate_in_words(a: &ResidualAnalysis) -> String {
    let mut s = String::new();
    if !a.structured {
        let _ = write!(
            s,
            "The residual (RMSE {}) is consistent with noise: point-to-point noise {}, lag-1 autocorrelation {:.2}, Ljung-Box p = {:.2e}, runs-test p = {:.2e}.",
            mv(a.rmse),
            mv(a.noise),
            a.lag1_autocorrelation,
            a.ljung_box.p_value,
            a.runs.p_value
        );
        return s;
    }
    let _ = write!(
        s,
        "The residual (RMSE {}, {:.1}x the point-to-point noise of {}) has structure noise cannot explain (lag-1 autocorrelation {:.2}, Ljung-Box p = {:.1e}, runs z = {:.1}).",
        mv(a.rmse),
        a.structure_ratio,
        mv(a.noise),
        a.lag1_autocorrelation,
        a.ljung_box.p_value,
        a.runs.statistic
    );
    let w = &a.step_response.windows;
    if let Some(top) = w
        .iter()
        .filter(|w| w.to.is_finite() && w.total_share > 0.2)
        .max_by(|x, y| x.concentration().total_cmp(&y.concentration()))
        && top.concentration() > 2.0
    {
        let when = if top.from == 0.0 { format!("the first {:.1} s", top.to) } else { format!("{:.1} to {:.0} s", top.from, top.to) };
        let _ = write!(
            s,
            " It is concentrated in {when} after current steps {} ({:.0} % of the squared error there on {:.0} % of the points).",
            if top.load { "under load" } else { "in rests" },
            100.0 * top.error_share,
            100.0 * top.point_share
        );
    }
    let sr = &a.step_response;
    if sr.steps >= 2 && sr.r2 > 0.8 && sr.instantaneous_resistance.abs() > 1e-4 {
        let _ = write!(
            s,
            " At the {} current steps it jumps by {:.2} mOhm times the current change (R² = {:.2}).",
            sr.steps,
            sr.instantaneous_resistance * 1e3,
            sr.r2
        );
    }
    if let Some(r) = a.vs_current
        && r.r2 > 0.5
    {
        let _ = write!(s, " It scales with current ({:.2} mV/A, R² = {:.2}).", r.slope * 1e3, r.r2);
    }
    if a.rest_rms > 0.0 && a.load_rms > 0.0 {
        let _ = write!(s, " RMS under load {}, at rest {}.", mv(a.load_rms), mv(a.rest_rms));
    }
    let (dis, cha) = (a.rest_after_discharge, a.rest_after_charge);
    if dis.is_finite() && cha.is_finite() && dis * cha < 0.0 && (dis - cha).abs() > 3.0 * a.noise {
        let _ = write!(
            s,
            " At rest it is {} after discharges and {} after charges: its sign follows the direction of the last current.",
            mv(dis),
            mv(cha)
        );
    }
    if let Some(r) = a.vs_capacity
        && r.r2 > 0.5
    {
        let _ = write!(s, " It grows with discharged capacity ({:.1} mV per A h, R² = {:.2}).", r.slope * 1e3, r.r2);
    }
    if let Some(r) = a.vs_temperature
        && r.r2 > 0.5
    {
        let _ = write!(s, " It follows the temperature rise ({:.2} mV/K, R² = {:.2}).", r.slope * 1e3, r.r2);
    }
    if let Some(r) = a.vs_heating
        && r.r2 > 0.5
    {
        let _ = write!(s, " It follows temperature rise times current ({:.3} mV/(K A), R² = {:.2}): the cell warms and its losses fall.", r.slope * 1e3, r.r2);
    }
    if let Some(seg) = a.segments.first() {
        let _ = write!(
            s,
            " The largest mismatch is at {:.0}-{:.0} s ({:.0} % of the squared error, mean residual {} at {:.2} A).",
            seg.start,
            seg.end,
            100.0 * seg.error_share,
            mv(seg.mean_residual),
            seg.mean_current
        );
    }
    s
}

fn parameters_in_words(f: &FitOutcome, only: &[String]) -> String {
    f.names
        .iter()
        .zip(&f.values)
        .enumerate()
        .filter(|(_, (n, _))| only.is_empty() || only.contains(n))
        .map(|(i, (n, v))| format_parameter(n, *v, ValueNote { std_error: f.std_errors[i], no_effect: !f.informed[i], on_bound: f.on_bound[i] }))
        .collect::<Vec<_>>()
        .join(", ")
}

fn class_words(class: Class) -> &'static str {
    match class {
        Class::MissingPhysics => "Missing physics",
        Class::ParameterMismatch => "Parameter mismatch",
        // Read as a verdict beside the other two (a report reader, or a tool that looks for
        // "Missing physics"), while saying the cell itself lacks nothing.
        Class::RecordingCondition => "Missing physics of the test, not of the cell (a recording condition)",
    }
}

/// The candidate's own fitted values (not the baseline's), in words.
fn candidate_values(d: &Diagnosis, c: &CandidateOutcome) -> String {
    let Some(f) = &c.fit else { return String::new() };
    let extra: Vec<String> = f.names.iter().filter(|n| !d.baseline.names.contains(n)).cloned().collect();
    if extra.is_empty() {
        return String::new();
    }
    let params = parameters_in_words(f, &extra);
    if params.is_empty() { String::new() } else { format!(": {params}") }
}

fn truncated(f: &FitOutcome) -> &'static str {
    if f.converged { "" } else { " (its search stopped on the iteration cap, not on convergence)" }
}

/// Share of the squared residual that a stretch at the very start of the recording must hold,
/// and the least time (s) it must last, for an unexplained verdict to point at an unrelaxed
/// start: the particles relax over minutes (a shorter stretch is the first step's fast
/// dynamics, as at a pulse that opens a recording).
const AT_THE_START: f64 = 0.5;
const START_RELAXATION_S: f64 = 60.0;

/// Where the user's model broke down and how much of the recording it followed.
fn breakdown_words(d: &Diagnosis) -> String {
    d.broke_down.as_ref().map_or(String::new(), |b| {
        format!("The user's model breaks down {:.0} s into the recording and follows only the {:.0} % before it.", b.at_s, 100.0 * b.kept_points as f64 / b.recorded_points.max(1) as f64)
    })
}

/// The candidate refitted on the whole recording that leaves the least on held-out points,
/// when the user's model broke down and one was: what came closest to following it.
fn closest_follower(d: &Diagnosis) -> Option<String> {
    let whole = |c: &&CandidateOutcome| c.fit.as_ref().is_some_and(|f| f.voltage.len() > d.data.time.len());
    let best = d.candidates.iter().filter(whole).min_by(|a, b| a.fit.as_ref().map(|f| f.rmse_holdout).unwrap_or(f64::INFINITY).total_cmp(&b.fit.as_ref().map(|f| f.rmse_holdout).unwrap_or(f64::INFINITY)))?;
    let f = best.fit.as_ref()?;
    Some(format!(
        " Refitted on the whole recording, {} lets the model follow it but leaves {} RMS on held-out points{}.",
        best.name,
        mv(f.rmse_holdout),
        best.implausible.as_ref().map_or(String::new(), |why| format!(" ({why})"))
    ))
}

/// Why nothing is named: what the user's model leaves is noise, or below the size floor.
fn no_missing_physics_why(d: &Diagnosis) -> String {
    let b = &d.baseline;
    if d.residual.structured || b.rmse_all > 1.5 * d.noise {
        format!("what remains (RMSE {}, noise {}) is below the {} a named effect must remove", mv(b.rmse_all), mv(d.noise), mv(d.margins.size_floor(d.noise)))
    } else {
        format!("the residual (RMSE {}) is consistent with noise ({})", mv(b.rmse_all), mv(d.noise))
    }
}

/// The verdict sentence(s), first in the summary.
pub fn verdict_in_words(d: &Diagnosis) -> String {
    let b = &d.baseline;
    let find = |c: Candidate, partner: Option<Candidate>| d.candidates.iter().find(|o| (o.candidate, o.partner) == (c, partner));
    let floor = d.margins.size_floor(d.noise);
    match &d.verdict {
        Verdict::Found { candidate, partner, class } => {
            let c = find(*candidate, *partner).expect("named candidate");
            let f = c.fit.as_ref().expect("named candidate has a fit");
            // Refitted on the whole recording past the user's breakdown, it has no cut or
            // ΔBIC against the user's model.
            let evidence = match d.whole {
                Some(_) => format!(
                    "{} With it the model follows the whole recording, leaving {} RMS (hold-out {}) against a noise level of {}, about what the user's model left before the breakdown ({}).",
                    breakdown_words(d),
                    mv(f.rmse_all),
                    mv(f.rmse_holdout),
                    mv(d.noise),
                    mv(b.rmse_all)
                ),
                None => format!(
                    "Adding it cuts the RMSE from {} to {} (hold-out {} -> {}), removing {} RMS against a noise level of {}; ΔBIC = {:.0} with {:.0} effective points, Laplace ln Bayes factor {:.0}{}.",
                    mv(b.rmse_all),
                    mv(f.rmse_all),
                    mv(b.rmse_holdout),
                    mv(f.rmse_holdout),
                    mv(c.comparison.explained),
                    mv(d.noise),
                    c.comparison.delta_bic,
                    c.comparison.effective_points,
                    c.comparison.ln_bayes_factor,
                    truncated(f)
                ),
            };
            format!("{}: {} ({}){}. {evidence}", class_words(*class), c.name, c.change, candidate_values(d, c))
        }
        Verdict::Tie { first, first_partner, second, second_partner, class, experiment } => {
            let (a, c2) = (find(*first, *first_partner).expect("tied"), find(*second, *second_partner).expect("tied"));
            let (fa, fb) = (a.fit.as_ref().expect("tied fit"), c2.fit.as_ref().expect("tied fit"));
            // Refitted on the whole recording past the user's breakdown, they have no ΔBIC
            // against it.
            let (evidence, after) = match d.whole {
                Some(_) => (String::new(), format!("With either the model follows the whole recording. {}", breakdown_words(d))),
                None => (
                    format!(", ΔBIC {:.0} vs {:.0}", a.comparison.delta_bic, c2.comparison.delta_bic),
                    format!("Either cuts the RMSE from {} to about {}.", mv(b.rmse_all), mv(fa.rmse_all)),
                ),
            };
            format!(
                "{}: {}{} or {}{}: the recording cannot tell them apart (hold-out RMSE {} vs {}{evidence}); {experiment} would separate them. {after}",
                class_words(*class),
                a.name,
                candidate_values(d, a),
                c2.name,
                candidate_values(d, c2),
                mv(fa.rmse_holdout),
                mv(fb.rmse_holdout),
            )
        }
        Verdict::BrokeDown => {
            let b = d.broke_down.as_ref().expect("a breakdown verdict has its breakdown");
            format!(
                "Unexplained: the user's model breaks down {:.0} s into the recording and cannot follow the rest; only the {} of {} points before it (to {:.0} s, {:.0} % of the recording) were diagnosed, and there {}. A model that cannot follow the recording is itself evidence of a mismatch after {:.0} s, which this diagnosis could not reach.",
                b.at_s,
                b.kept_points,
                b.recorded_points,
                b.diagnosed_to_s,
                100.0 * b.kept_points as f64 / b.recorded_points.max(1) as f64,
                no_missing_physics_why(d),
                b.at_s
            ) + &closest_follower(d).unwrap_or_default()
        }
        Verdict::Unexplained => {
            let windows: Vec<String> = d.residual.segments.iter().take(3).map(|s| format!("{:.0}-{:.0} s", s.start, s.end)).collect();
            let best = d.best().map(|c| {
                let why = c.implausible.clone().unwrap_or_else(|| {
                    let (m, k) = (&d.margins, &c.comparison);
                    let mut short = Vec::new();
                    if k.delta_bic <= m.min_delta_bic {
                        short.push(format!("ΔBIC {:.1} (needed > {})", k.delta_bic, m.min_delta_bic));
                    }
                    if k.ln_bayes_factor <= 0.0 {
                        short.push(format!("Laplace ln Bayes factor {:.1} (needed > 0)", k.ln_bayes_factor));
                    }
                    if k.holdout_gain < m.min_holdout_gain {
                        short.push(format!("hold-out cut {:.0} % (needed {:.0} %)", 100.0 * k.holdout_gain, 100.0 * m.min_holdout_gain));
                    }
                    if k.explained < floor {
                        short.push(format!("removes {} (needed {})", mv(k.explained), mv(floor)));
                    }
                    format!("falls short: {}", short.join(", "))
                });
                format!(" The closest, {}, {why}.", c.name)
            });
            // A cell whose own open-circuit voltage differs from the set's is off at rest as
            // much as under load, which no dynamic candidate changes.
            let r = &d.residual;
            let ocv = super::at_rest::off_at_rest(r.rest_rms, r.load_rms, d.noise).then(|| {
                format!(
                    " At rest the model is off by {} RMS (under load {}): the cell's open-circuit voltage differs from the set's (its electrodes' OCP curves or their balance); a pseudo-OCV at C/20 both ways and `cellstudio parameterise` fit that before a diagnosis.",
                    mv(r.rest_rms),
                    mv(r.load_rms)
                )
            });
            let start = unrelaxed_start(d);
            format!(
                "Unexplained structure in {}: the user's model misses by {} RMS (noise {}), and no plausible candidate removes it on held-out data; see the residual plot.{}{}{}",
                if windows.is_empty() { "the recording".to_string() } else { windows.join(", ") },
                mv(b.rmse_all),
                mv(d.noise),
                best.unwrap_or_default(),
                ocv.unwrap_or_default(),
                start.unwrap_or_default()
            )
        }
        Verdict::NoMissingPhysics => {
            let above_noise = d.residual.structured || b.rmse_all > 1.5 * d.noise;
            let why = no_missing_physics_why(d);
            // Below the floor on held-out points, a remainder at the start still says how the
            // recording began.
            let start = above_noise.then(|| unrelaxed_start(d)).flatten();
            format!("No missing physics: {why}.{}", start.unwrap_or_default())
        }
    }
}

/// A pointer to an unrelaxed start when the largest mismatch sits at the very start (from the
/// first point, at least [`START_RELAXATION_S`] long, at least [`AT_THE_START`] of the squared
/// error): a cell still relaxing from a load before the recording began leaves the model,
/// started relaxed, off there only.
fn unrelaxed_start(d: &Diagnosis) -> Option<String> {
    let t0 = d.data.time.first().copied().unwrap_or(0.0);
    d.residual.segments.first().filter(|seg| seg.start <= t0 && seg.end - t0 >= START_RELAXATION_S && seg.error_share >= AT_THE_START).map(|seg| {
        format!(
            " The mismatch sits at the start ({:.0}-{:.0} s, {:.0} % of the squared error): the cell was likely not at rest when the recording began (a load just before it left gradients in the particles and electrolyte that the model, started relaxed, lacks); diagnose a recording that begins with a rest.",
            seg.start,
            seg.end,
            100.0 * seg.error_share
        )
    })
}

/// The effects of earlier rounds the final model does not need, one sentence each (each
/// starting with a space; empty when there are none).
pub fn superseded(superseded: &[super::backward::Superseded]) -> String {
    superseded
        .iter()
        .map(|s| {
            format!(
                " Superseded: {} (round {}{}) is not needed once the later effects are in the model: without it the RMSE is {:.2} mV (with it {:.2} mV), ΔBIC {:.1}, Laplace ln Bayes factor {:.1}.",
                s.name,
                s.round,
                s.kept.as_ref().map_or(String::new(), |k| format!("; its pair's {k} stays")),
                s.rmse_without * 1e3,
                s.rmse_with * 1e3,
                s.delta_bic,
                s.ln_bayes_factor
            )
        })
        .collect()
}

/// The conclusion over all rounds: the effects named and kept (not superseded), and the fit
/// they reach; "part of the recording" when the last round leaves structure unexplained.
pub fn conclusion(rounds: &[Diagnosis]) -> String {
    let Some(last) = rounds.last() else { return String::new() };
    let named: Vec<(usize, &CandidateOutcome)> = rounds.iter().enumerate().filter(|(_, d)| d.found).filter_map(|(k, d)| d.best().map(|c| (k + 1, c))).collect();
    if named.is_empty() {
        return format!("Conclusion: nothing named; the user's model stays at RMSE {} (noise {}).", mv(rounds[0].baseline.rmse_all), mv(rounds[0].noise));
    }
    // A tied round is named by both candidates.
    let name_of = |k: usize, c: &CandidateOutcome| match &rounds[k - 1].verdict {
        Verdict::Tie { second, second_partner, .. } => {
            let other = rounds[k - 1]
                .candidates
                .iter()
                .find(|o| (o.candidate, o.partner) == (*second, *second_partner))
                .map_or(second.name().to_string(), |o| o.name.clone());
            format!("({} or {})", c.name, other)
        }
        _ => c.name.clone(),
    };
    // A round whose pair lost one effect keeps the other.
    let kept: Vec<String> = named
        .iter()
        .filter_map(|(k, c)| match last.superseded.iter().find(|s| s.round == *k) {
            None => Some(name_of(*k, c)),
            Some(s) => s.kept.clone(),
        })
        .collect();
    let dropped: Vec<String> = last.superseded.iter().map(|s| format!("{} (round {})", s.name, s.round)).collect();
    let final_rmse = last.best().filter(|_| last.found).and_then(|c| c.fit.as_ref()).map_or(last.baseline.rmse_all, |f| f.rmse_all);
    let rmse = last.superseded.iter().map(|s| s.rmse_without).fold(final_rmse, f64::min);
    // A last round that leaves structure no candidate removes: the named effects are only
    // part of the story. So are they when the rounds stopped at their limit (or the time
    // budget) with more than twice the noise left: the rest was never diagnosed.
    let undiagnosed = last.cut_short.as_ref().filter(|_| last.found && rmse > 2.0 * rounds[0].noise);
    let rest = match undiagnosed {
        Some(why) => Some(format!(" The rest ({}, {:.0} times the noise) was not diagnosed: the run stopped after round {} because {why}.", mv(rmse), rmse / rounds[0].noise, rounds.len())),
        None => (!last.found && matches!(last.verdict, Verdict::Unexplained | Verdict::BrokeDown)).then(|| format!(" The rest is unexplained (round {}).", rounds.len())),
    };
    let mut out = format!(
        "Conclusion: {} explain{} {}, RMSE {} -> {} (noise {}).{}",
        kept.join(" + "),
        if kept.len() == 1 { "s" } else { "" },
        if rest.is_some() { "part of the recording" } else { "the recording" },
        mv(rounds[0].baseline.rmse_all),
        mv(rmse),
        mv(rounds[0].noise),
        rest.unwrap_or_default()
    );
    if !dropped.is_empty() {
        out.push_str(&format!(" Superseded by the later effects: {}.", dropped.join(", ")));
    }
    out
}

/// The verdict in plain words: the verdict first, then where the mismatch is, then notes.
pub fn plain_words(d: &Diagnosis) -> String {
    let mut s = verdict_in_words(d);
    s.push(' ');
    s.push_str(&locate_in_words(&d.residual));
    if let Some(soc) = d.baseline.names.iter().position(|n| n == INITIAL_SOC) {
        let _ = write!(s, " Initial state of charge estimated at {:.1} %.", 100.0 * d.baseline.values[soc]);
    }
    for n in &d.notes {
        s.push(' ');
        s.push_str(n);
    }
    s
}

fn candidate_row(c: &CandidateOutcome, rank: usize) -> String {
    let kind = match c.class {
        Class::MissingPhysics => "physics",
        Class::ParameterMismatch => "parameter",
        Class::RecordingCondition => "recording",
    };
    match &c.fit {
        Some(f) => format!(
            "| {rank} | {} | {kind} | {} | {} / {} | {:.2} | {:.2} | {:.2} | {:.1} | {:.1} | {:.0} % | {:.2} | {} | {} | {:.1} |",
            c.name,
            c.change,
            f.names.len(),
            f.parameters,
            f.rmse_train * 1e3,
            f.rmse_holdout * 1e3,
            f.rmse_all * 1e3,
            c.comparison.delta_bic,
            c.comparison.ln_bayes_factor,
            100.0 * c.comparison.holdout_gain,
            c.comparison.explained * 1e3,
            c.implausible.clone().unwrap_or_else(|| "yes".into()),
            if c.named { "yes" } else if c.clears_margins { "no (implausible)" } else { "no" },
            f.seconds
        ),
        None => format!("| - | {} | {kind} | {} | | | | | | | | | | {} | |", c.name, c.change, c.note.clone().unwrap_or_default()),
    }
}

/// The report as Markdown; `plots` are file names relative to the report.
pub fn markdown(d: &Diagnosis, plots: &[(String, String)]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# Model-discrepancy diagnosis ({})\n", d.model);
    let _ = writeln!(s, "{}\n", d.summary);
    let b = &d.baseline;
    let _ = writeln!(s, "## Fits\n");
    let _ = writeln!(
        s,
        "{} usable points: {} for training, {} held out (blocks {} of {} blocks of consecutive points). The user's model: {} fitted parameter(s), RMSE {:.2} mV (training {:.2}, hold-out {:.2}).{}\n",
        d.points,
        d.train_points,
        d.holdout_points,
        super::holdout::blocks_in_words(d.blocks, d.holdout_every, d.holdout_phase),
        d.blocks,
        b.names.len(),
        b.rmse_all * 1e3,
        b.rmse_train * 1e3,
        b.rmse_holdout * 1e3,
        if b.names.is_empty() { String::new() } else { format!(" Fitted: {}.", parameters_in_words(b, &[])) }
    );
    let _ = writeln!(
        s,
        "A candidate is named when ΔBIC (with effective points and structural parameters counted) exceeds {} and the Laplace Bayes factor favours it, it cuts the hold-out RMSE by at least {:.0} %, it removes at least {} RMS on held-out points ({}x the noise of {}, at least {}), and its fitted values are plausible.\n",
        d.margins.min_delta_bic,
        100.0 * d.margins.min_holdout_gain,
        mv(d.margins.size_floor(d.noise)),
        d.margins.noise_multiple,
        mv(d.noise),
        mv(d.margins.voltage_floor)
    );
    let _ = writeln!(
        s,
        "| rank | candidate | kind | change | fitted / counted | RMSE train (mV) | RMSE hold-out (mV) | RMSE all (mV) | ΔBIC | ln BF | hold-out cut | removed (mV) | plausible | named | time (s) |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut rank = 0;
    for c in &d.candidates {
        rank += usize::from(c.fit.is_some());
        let _ = writeln!(s, "{}", candidate_row(c, rank));
    }
    let _ = writeln!(s, "\nFitted values:\n");
    for c in d.candidates.iter().filter(|c| c.fit.is_some()) {
        let f = c.fit.as_ref().expect("filtered");
        let _ = writeln!(s, "- {}: {}", c.name, if f.names.is_empty() { "(no parameters)".into() } else { parameters_in_words(f, &[]) });
    }
    let _ = writeln!(s, "\n## Candidate signatures and plausible ranges\n");
    for c in &d.candidates {
        let _ = writeln!(s, "- **{}**: {}. Plausible: {}.", c.name, c.signature, c.plausible_range);
    }
    let _ = writeln!(s, "\n## Residual of the user's model\n");
    residual_section(&mut s, &d.residual);
    if let (Some(a), Some(best)) = (&d.residual_after, d.best()) {
        let _ = writeln!(s, "\n## Residual with {}\n", best.name);
        residual_section(&mut s, a);
    }
    if !plots.is_empty() {
        let _ = writeln!(s, "\n## Plots\n");
        for (title, file) in plots {
            let _ = writeln!(s, "![{title}]({file})\n");
        }
    }
    s
}

fn residual_section(s: &mut String, a: &ResidualAnalysis) {
    let _ = writeln!(s, "| statistic | value |\n|---|---|");
    let _ = writeln!(s, "| RMSE / mean / max abs | {} / {} / {} (at {:.0} s) |", mv(a.rmse), mv(a.mean), mv(a.max_abs), a.time_of_max);
    let _ = writeln!(s, "| noise (first differences) | {} (RMSE/noise = {:.2}) |", mv(a.noise), a.structure_ratio);
    let _ = writeln!(s, "| lag-1 autocorrelation | {:.3} |", a.lag1_autocorrelation);
    let _ = writeln!(s, "| Ljung-Box Q, p | {:.1}, {:.2e} |", a.ljung_box.statistic, a.ljung_box.p_value);
    let _ = writeln!(s, "| runs test z, p | {:.2}, {:.2e} |", a.runs.statistic, a.runs.p_value);
    let _ = writeln!(s, "| structure noise cannot explain | {} |", if a.structured { "yes" } else { "no" });
    for (label, r, unit) in [
        ("r vs current", a.vs_current, "mV/A"),
        ("r vs discharged capacity", a.vs_capacity, "mV/(A h)"),
        ("r vs temperature rise", a.vs_temperature, "mV/K"),
        ("r vs temperature rise x current", a.vs_heating, "mV/(K A)"),
    ] {
        if let Some(r) = r {
            let _ = writeln!(s, "| {label} | slope {:.3} {unit}, R² = {:.3} |", r.slope * 1e3, r.r2);
        }
    }
    let sr = &a.step_response;
    let _ = writeln!(s, "| jump at {} current steps | {:.3} mOhm x ΔI, R² = {:.3} |", sr.steps, sr.instantaneous_resistance * 1e3, sr.r2);
    let _ = writeln!(s, "| RMS under load / at rest | {} / {} |", mv(a.load_rms), mv(a.rest_rms));
    let _ = writeln!(s, "| mean at rest after discharge / after charge | {} / {} |", mv(a.rest_after_discharge), mv(a.rest_after_charge));
    let _ = writeln!(s, "\n| time after a current step | share of load/rest points | share of their squared error | share of all squared error |\n|---|---|---|---|");
    for w in &sr.windows {
        let _ = writeln!(
            s,
            "| {} {:.1} - {} s | {:.1} % | {:.1} % | {:.1} % |",
            if w.load { "load" } else { "rest" },
            w.from,
            if w.to.is_finite() { format!("{:.0}", w.to) } else { "...".into() },
            100.0 * w.point_share,
            100.0 * w.error_share,
            100.0 * w.total_share
        );
    }
    let _ = writeln!(s, "\n| band | points | mean (mV) | RMS (mV) |\n|---|---|---|---|");
    for (label, bands, unit) in [("current", &a.current_bands, " A"), ("SOC change", &a.soc_bands, "")] {
        for (k, b) in bands.iter().enumerate() {
            let range = if label == "current" && k == 0 { "rest".to_string() } else { format!("{label} {:.3} to {:.3}{unit}", b.lower, b.upper) };
            let _ = writeln!(s, "| {range} | {} | {:.2} | {:.2} |", b.points, b.mean * 1e3, b.rms * 1e3);
        }
    }
    if !a.segments.is_empty() {
        let _ = writeln!(s, "\n| mismatching segment | mean current (A) | mean residual (mV) | share of squared error |\n|---|---|---|---|");
        for g in &a.segments {
            let _ = writeln!(s, "| {:.0} - {:.0} s | {:.2} | {:.2} | {:.1} % |", g.start, g.end, g.mean_current, g.mean_residual * 1e3, 100.0 * g.error_share);
        }
    }
}
