//! Probe: a recording replayed by the DFN isothermal, with self-heating at a constant
//! ambient, and with its temperature following the recorded one; RMSE (mV) at the best
//! initial state of charge of each.
//!
//!     cargo run --release --example temperature_input_probe -- RECORDING.csv AMBIENT_K [MODEL]

use cellstudio::data::Recording;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::problem::fitting::{FitParameter, FittingProblem, INITIAL_SOC, ModelSpec};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let rec = Recording::from_csv(std::path::Path::new(&args[1])).expect("recording");
    let ambient: f64 = args[2].parse().expect("ambient K");
    let kind = match args.get(3).map(String::as_str) {
        Some("spme") => ModelKind::Spme,
        Some("spm") => ModelKind::Spm,
        _ => ModelKind::Dfn,
    };
    let mut base = chen2020();
    base.thermal.ambient_temperature = ambient;
    base.thermal.initial_temperature = rec.temperature.as_ref().map_or(ambient, |t| t[0]);
    for (label, thermal, follow) in [("isothermal", false, false), ("self-heating, constant ambient", true, false), ("temperature as recorded", true, true)] {
        let spec = ModelSpec { kind, submodels: Submodels { thermal, ..Submodels::default() }, mesh: Default::default(), recorded_temperature: follow };
        let p = FittingProblem::new(spec, base.clone(), vec![FitParameter::linear(INITIAL_SOC, 0.9, 0.3, 1.0)], rec.clone()).expect("problem");
        let start = std::time::Instant::now();
        let rmse = |soc: f64| {
            // A replay that breaks down (the cell emptied early) scores infinitely badly.
            let Ok(v) = p.simulate(&[soc]) else { return f64::INFINITY };
            // Points at a repeated time (either side of a current step) are left out, as in fits.
            let kept: Vec<f64> = (0..v.len()).filter(|&k| !rec.is_repeated(k)).map(|k| (rec.voltage[k] - v[k]).powi(2)).collect();
            (kept.iter().sum::<f64>() / kept.len() as f64).sqrt()
        };
        // Golden-section search of the initial state of charge.
        let (mut a, mut b) = (0.8, 0.97);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..14 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if rmse(c) < rmse(d) { b = d } else { a = c }
        }
        let soc = 0.5 * (a + b);
        println!("{label:32} SOC {soc:.4}  RMSE {:.3} mV  ({:.1} s)", rmse(soc) * 1e3, start.elapsed().as_secs_f64());
    }
}
