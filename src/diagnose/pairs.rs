//! Two effects at once: when no single candidate explains a structured residual, two
//! effects may be hiding each other (a lost electrode capacity and self-heating pull the
//! voltage opposite ways). Every pair of candidates whose own fit lowered the training error
//! at all (or was fitted to a recorded temperature) is refitted together, the second added
//! to the first's model, and counted and judged as a single candidate is (both effects'
//! parameters and structural changes count). Every pair is screened with a few iterations
//! from no effect (as a single starts; a second effect's ageing rates from its single fit's
//! decade screen); the three best by training error continue to
//! convergence from there (and as many of the next that could be named as screened as those
//! three hold that could not), and the three best whose fit is doubtful are refitted from every
//! start.

use rayon::prelude::*;

use super::refit::SCREEN_ITERATIONS;
use super::refit_candidate::at_soc;
use super::{Candidate, CandidateOutcome, FitOutcome, Round, refit_candidate, select};
use crate::problem::fitting::INITIAL_SOC;
use crate::problem::lost_lithium::is_loss_soc;
use crate::problem::least_squares::LmSettings;

/// How many pairs were fitted, and how: where a round's time goes.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct PairWork {
    pub screened: usize,
    pub continued: usize,
    pub refitted: usize,
}

impl PairWork {
    pub fn in_words(&self) -> String {
        format!("{} pairs screened ({} continued, {} refitted from every start)", self.screened, self.continued, self.refitted)
    }
}

/// Every named pair of `singles` (refitted candidates), each as one candidate outcome named
/// "A together with B" (its best fit when it was fitted twice); empty when no pair clears
/// the margins with plausible values. Also how many pairs were fitted.
pub(super) fn named_pairs(singles: &[CandidateOutcome], round: &Round) -> (Vec<CandidateOutcome>, PairWork) {
    // A thermal candidate fitted to a recorded temperature has evidence of its own even
    // when alone it does not lower the voltage's error (a second effect may hide it).
    let own_evidence = |c: &CandidateOutcome| matches!(c.candidate, Candidate::Thermal | Candidate::HeatBalance) && round.data.temperature.is_some();
    let useful: Vec<&CandidateOutcome> = singles
        .iter()
        .filter(|c| c.next.is_some() && c.fit.as_ref().is_some_and(|f| f.rmse_train < round.baseline.rmse_train || own_evidence(c)))
        .collect();
    let pairs: Vec<(&CandidateOutcome, &CandidateOutcome)> = useful
        .iter()
        .enumerate()
        .flat_map(|(i, a)| useful[i + 1..].iter().map(move |b| (*a, *b)))
        .filter(|(a, b)| !one_physics(a.candidate, b.candidate))
        .collect();
    // Every pair screened from its first start with a few iterations; the few best by
    // training error that had not converged by then continue from where they stopped; the few
    // best whose fit is doubtful (it stopped on its cap or ended on a bound) are refitted from
    // every start, as the singles are.
    let full = round.options.fit.lm;
    let screen = LmSettings { max_iterations: SCREEN_ITERATIONS.min(full.max_iterations), ..full };
    let progress = crate::progress::bar("diagnose", pairs.len() as u64, "{msg} {bar:30} {pos}/{len} [{elapsed}]");
    progress.set_message("screening pairs of candidates");
    let mut first: Vec<(usize, CandidateOutcome)> = pairs
        .par_iter()
        .enumerate()
        .filter_map(|(k, (a, b))| {
            let screened = fit_pair(a, b, round, PairStart::Screen(screen));
            progress.inc(1);
            Some((k, screened?))
        })
        .collect();
    progress.finish_and_clear();
    let mut best_first: Vec<usize> = (0..first.len()).collect();
    best_first.sort_by(|i, j| rmse_train(&first[*i].1).total_cmp(&rmse_train(&first[*j].1)));
    let unconverged_screen = |i: &usize| first[*i].1.fit.as_ref().is_some_and(|f| !f.converged);
    let top = &best_first[..CONTINUED_PAIRS.min(best_first.len())];
    let mut unconverged: Vec<usize> = top.iter().copied().filter(unconverged_screen).collect();
    // A slot held by a screen that could not be named as screened is matched by the next
    // best screen that could: one dominant effect's implausible pairs need not crowd out the
    // truth (n4: a second positive material on the edge of its range, paired with anything,
    // took all three from positive LAM + lithium, whose screen already stood at 1 mV; f5: a
    // heavier coating beside two implausible second materials pushed negative LAM + lithium
    // to fifth).
    let implausible_slots = top.iter().filter(|i| first[**i].1.implausible.is_some()).count();
    unconverged.extend(best_first[top.len()..].iter().copied().filter(|i| first[*i].1.implausible.is_none() && unconverged_screen(i)).take(implausible_slots));
    let continued: Vec<(usize, Option<CandidateOutcome>)> = unconverged
        .par_iter()
        .map(|&i| {
            let (k, screened) = &first[i];
            (i, continue_pair(pairs[*k].0, pairs[*k].1, round, screened))
        })
        .collect();
    let mut fitted: Vec<bool> = first.iter().map(|(_, p)| p.fit.as_ref().is_some_and(|f| f.converged)).collect();
    for (i, pair) in continued {
        if let Some(pair) = pair {
            first[i].1 = pair;
            fitted[i] = true;
        }
    }
    // A screen that stopped on its few iterations and was not continued is not a fit: it
    // cannot be named.
    let mut keep = fitted.into_iter();
    first.retain(|_| keep.next().unwrap_or(false));
    let mut doubtful: Vec<&(usize, CandidateOutcome)> =
        first.iter().filter(|(_, p)| p.fit.as_ref().is_some_and(|f| !f.converged || f.on_bound.iter().any(|b| *b))).collect();
    doubtful.sort_by(|(_, p), (_, q)| rmse_train(p).total_cmp(&rmse_train(q)));
    let work = PairWork { screened: pairs.len(), continued: unconverged.len(), refitted: doubtful.len().min(REFIT_DOUBTFUL_PAIRS) };
    let again: Vec<CandidateOutcome> = doubtful
        .into_iter()
        .take(REFIT_DOUBTFUL_PAIRS)
        .collect::<Vec<_>>()
        .into_par_iter()
        .filter_map(|(k, _)| fit_pair(pairs[*k].0, pairs[*k].1, round, PairStart::Every))
        .collect();
    let mut named: Vec<CandidateOutcome> = Vec::new();
    for p in first.into_iter().map(|(_, p)| p).chain(again).filter(|p| p.named) {
        match named.iter_mut().find(|q| (q.candidate, q.partner) == (p.candidate, p.partner)) {
            Some(q) if rmse_train(&p) < rmse_train(q) => *q = p,
            Some(_) => {}
            None => named.push(p),
        }
    }
    (named, work)
}

/// Screened pairs, the best by training error first, that continue to convergence.
const CONTINUED_PAIRS: usize = 3;

/// Doubtful pairs refitted from every start, the best by training error first.
const REFIT_DOUBTFUL_PAIRS: usize = 3;

/// Stretches of a fit's iteration cap a continued pair may run, and the share of its squared
/// training error a stretch that stops on the cap must remove for the next to run.
const CONTINUED_STRETCHES: usize = 3;
const STRETCH_GAIN: f64 = 0.1;

/// A screened pair continued from where its screen stopped: stretch after stretch of the
/// fit's iteration cap while a stretch stops on the cap and still removes a tenth of the
/// squared error (two effects that trade against each other, as a lost electrode capacity
/// and its lithium, crawl along a narrow valley); `None` when a stretch fails. Its
/// simulations and seconds count every stretch and the screen.
fn continue_pair(a: &CandidateOutcome, b: &CandidateOutcome, round: &Round, screened: &CandidateOutcome) -> Option<CandidateOutcome> {
    let mut pair = screened.clone();
    let (mut sims, mut secs) = (0, 0.0);
    for _ in 0..CONTINUED_STRETCHES {
        let from = pair.fit.as_ref().expect("a pair outcome holds its fit");
        (sims, secs) = (sims + from.simulations, secs + from.seconds);
        let next = fit_pair(a, b, round, PairStart::Continue(from))?;
        let fit = next.fit.as_ref().expect("a pair outcome holds its fit");
        let falling = fit.rmse_train.powi(2) < (1.0 - STRETCH_GAIN) * from.rmse_train.powi(2);
        let done = fit.converged || !falling;
        pair = next;
        if done {
            break;
        }
    }
    let fit = pair.fit.as_mut().expect("a pair outcome holds its fit");
    fit.simulations += sims;
    fit.seconds += secs;
    Some(pair)
}

fn rmse_train(p: &CandidateOutcome) -> f64 {
    p.fit.as_ref().map_or(f64::INFINITY, |f| f.rmse_train)
}

/// Where a pair's fit starts and how far it goes.
enum PairStart<'a> {
    /// From the first start, with these settings.
    Screen(LmSettings),
    /// From the values of an earlier fit of the same pair, to convergence.
    Continue(&'a FitOutcome),
    /// From every start, to convergence.
    Every,
}

/// Candidate `b` added to `a`'s fitted model, refitted from `start`, and judged as a single
/// candidate is; `None` when `b` cannot be added or the fit fails.
fn fit_pair(a: &CandidateOutcome, b: &CandidateOutcome, round: &Round, start: PairStart) -> Option<CandidateOutcome> {
    let n_train = round.split.train_points();
    let next_a = a.next.as_ref()?;
    let paths: Vec<String> = next_a.fitted.iter().map(|p| p.path.clone()).collect();
    let mut aug = b.candidate.augment(&next_a.spec, &next_a.base, &paths, &round.load)?;
    // A second effect's ageing rates (known only to within decades) start where its single
    // fit ended, after that fit's decade screen: a pair is not screened again, and a few
    // iterations from the candidate's default do not reach a rate decades away (c1: SEI
    // growth beside a contact screened at 15.1 mV from the default, 0.98 mV from its single
    // fit). Its other parameters start at their defaults.
    if let Some(fb) = b.fit.as_ref().filter(|_| aug.screened) {
        for p in aug.extra.iter_mut().filter(|p| p.log) {
            if let Some(k) = fb.names.iter().position(|n| *n == p.path) {
                p.initial = fb.values[k].clamp(p.lower, p.upper);
            }
        }
    }
    // A pair refits the plain loss of active material: the state at which it was lost is a
    // single candidate's (a lithiated loss is a delithiated one with lithium lost, which the
    // pair with lithium inventory holds), and beside other effects it stood in for their
    // partner (f5, negative LAM with lithium lost: LAM with its state beside an entropic
    // change, a leak or an unrelaxed start screened below LAM + LLI, which was not continued).
    aug.extra.retain(|p| !is_loss_soc(&p.path));
    let partner: Vec<String> = aug.extra.iter().map(|p| p.path.clone()).collect();
    // The first effect's fixed structural parameters count too.
    let structural_a = a.candidate.augment(&round.options.spec, round.base, round.fitted_paths, &round.load).map_or(0, |x| x.structural_parameters);
    let change = format!("{}; {}", a.change, aug.change);
    // Both effects start from no effect (the user's parameters at their fitted values, the
    // candidates' at the set's), as a single does: the first effect's own fit may be a
    // compromise that stood in for the second (a lost negative capacity for lost lithium)
    // and would hold the pair in that false minimum.
    // A first effect that frees the stoichiometry window starts it at the user's model's
    // fitted state of charge (the set's concentrations may lie far from it and break the
    // model: a recording that starts empty).
    let soc = round.baseline.names.iter().position(|n| n == INITIAL_SOC).map(|k| round.baseline.values[k]);
    let no_effect = at_soc(&next_a.base, soc);
    let mut warm: Vec<_> = next_a.fitted.iter().filter(|p| !is_loss_soc(&p.path)).cloned().collect();
    for p in warm.iter_mut() {
        let start = match round.baseline.names.iter().position(|n| *n == p.path) {
            Some(k) => round.baseline.values[k],
            // The first effect's base: the set's values, or no effect where the candidate
            // sets one (the progressive LAM's terms).
            None => no_effect.get(&p.path).unwrap_or(p.initial),
        };
        p.initial = start.clamp(p.lower, p.upper);
    }
    let mut options = round.options.clone();
    let (restarts, resume): (Option<&[Vec<f64>]>, _) = match start {
        PairStart::Screen(lm) => {
            options.fit.lm = lm;
            (None, None)
        }
        PairStart::Continue(earlier) => (None, Some(earlier)),
        PairStart::Every => (Some(&[]), None),
    };
    let (fit, _, next) = refit_candidate(aug, &warm, restarts, resume, &options, round.data, round.split);
    let mut fit = fit?;
    fit.parameters += structural_a;
    let comparison = select::compare(round.baseline, &fit, n_train);
    let clears = round.options.margins.cleared_by(&comparison, round.noise);
    let (names, values): (Vec<String>, Vec<f64>) =
        fit.names.iter().zip(&fit.values).filter(|(n, _)| !round.baseline.names.contains(n)).map(|(n, v)| (n.clone(), *v)).unzip();
    // Twice the parameters: each must also be determined by the recording, its standard
    // error within its value; for a signed parameter (its search range spans zero, as an
    // initial hysteresis state does) within half its range: near zero is a value there.
    let scale = |n: &str, v: f64| {
        let signed = next.as_ref().and_then(|m| m.fitted.iter().find(|p| p.path == n)).filter(|p| p.lower < 0.0 && p.upper > 0.0);
        signed.map_or(v.abs(), |p| 0.5 * (p.upper - p.lower))
    };
    let undetermined = names.iter().zip(&values).filter_map(|(n, v)| {
        let se = fit.std_errors[fit.names.iter().position(|m| m == n)?];
        let relative = se / scale(n, *v).max(f64::MIN_POSITIVE);
        (!(relative <= crate::problem::verdict::MAX_RELATIVE_ERROR)).then(|| format!("{n} is not determined by this recording (±{:.0} %)", 100.0 * relative))
    });
    // A parameter-mismatch partner whose fitted values are the set's own (within two
    // standard errors) adds nothing: the pair is the first effect alone. (A submodel
    // switched on adds its physics whatever its parameters.)
    let unchanged = b.class == super::Class::ParameterMismatch && super::keeps_set_values(&fit, &partner, round.base);
    let implausible = [a.candidate, b.candidate]
        .iter()
        .find_map(|c| c.implausible(&names, &values, round.base, &round.load).or_else(|| c.unresolved(&names, &values, round.data)))
        .or_else(|| super::at_rest::stands_in_for_the_ocv(&[a.candidate, b.candidate], &fit, round))
        .or_else(|| undetermined.into_iter().next())
        .or_else(|| unchanged.then(|| format!("{} keeps the set's values: it adds nothing", b.candidate.name())));
    // Named by the pair's own values (e.g. the share of capacity lost).
    let name = format!("{} together with {}", a.candidate.named_by_values(&fit.names, &fit.values, round.base, &round.load), b.candidate.named_by_values(&fit.names, &fit.values, round.base, &round.load));
    Some(CandidateOutcome {
        candidate: a.candidate,
        partner: Some(b.candidate),
        name,
        class: pair_class(a.class, b.class),
        signature: format!("{}; {}", a.signature, b.signature),
        plausible_range: format!("{}; {}", a.plausible_range, b.plausible_range),
        change,
        fit: Some(fit),
        note: Some("two effects refitted together: neither alone explains the recording".into()),
        comparison,
        clears_margins: clears,
        named: clears && implausible.is_none(),
        implausible,
        next,
    })
}

/// The class of a pair: its members' when they share one; the cell's member's beside a
/// recording condition; else missing physics (a parameter off together with physics missing).
fn pair_class(a: super::Class, b: super::Class) -> super::Class {
    use super::Class::*;
    match (a, b) {
        _ if a == b => a,
        (RecordingCondition, c) | (c, RecordingCondition) => c,
        _ => MissingPhysics,
    }
}

/// Whether two candidates describe one physics (the electrolyte model and its properties, two
/// laws of SEI growth, of lithium plating or of progressive loss of active material, the
/// voltage channel's offset and gain, an electrode's capacity lost or gained (or the current
/// channel's gain, which scales both alike), or a particle
/// radius and what it sets: the particles' diffusion, their surface's kinetics, their sizes):
/// a pair of them is one effect, not two.
fn one_physics(a: Candidate, b: Candidate) -> bool {
    use Candidate::*;
    let radius = |c: Candidate| matches!(c, RadiusNegative | RadiusPositive);
    let set_by_radius = |c: Candidate| matches!(c, Kinetics | SolidDiffusion | SizeDistribution);
    if (radius(a) && set_by_radius(b)) || (radius(b) && set_by_radius(a)) {
        return true;
    }
    let family = |c: Candidate| match c {
        Electrolyte | ElectrolyteComposite | ElectrolyteTransport | ElectrolyteConcentration => Some(0),
        LithiumPlating | LithiumPlatingPartial => Some(1),
        ActiveMaterialGrowth | ActiveMaterialThroughput => Some(2),
        SeiGrowth | SeiGrowthSeries => Some(3),
        VoltageOffset | VoltageGain => Some(4),
        Thermal | HeatBalance | RecordedTemperature => Some(5),
        // Both electrodes' capacity scaled alike is, without an electrolyte, a current gain.
        ActiveMaterial | ElectrodeLoading | CurrentGain => Some(6),
        _ => None,
    };
    family(a).is_some() && family(a) == family(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_laws_of_one_physics_are_not_a_pair() {
        use Candidate::*;
        assert!(one_physics(LithiumPlating, LithiumPlatingPartial));
        assert!(one_physics(Electrolyte, ElectrolyteTransport));
        assert!(one_physics(SeiGrowth, SeiGrowthSeries));
        assert!(one_physics(VoltageOffset, VoltageGain));
        assert!(one_physics(Thermal, RecordedTemperature));
        assert!(!one_physics(LithiumPlating, SeiGrowth));
        assert!(one_physics(ActiveMaterial, ElectrodeLoading));
        assert!(one_physics(ElectrolyteConcentration, ElectrolyteTransport));
        assert!(one_physics(RadiusNegative, Kinetics) && one_physics(SolidDiffusion, RadiusPositive));
        assert!(!one_physics(Kinetics, SolidDiffusion) && !one_physics(RadiusNegative, RadiusPositive));
        assert!(!one_physics(SeriesResistance, LithiumInventory));
    }
}
