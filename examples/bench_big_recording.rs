//! Cost of fitting long recordings: an SPM with contact resistance fitted (D_n and R, L-BFGS-B
//! with forward sensitivities) to synthetic recordings of 10^3 to 10^6 rows of the same
//! 28-hour cycling test (1C discharge, rest, C/2 charge, rest; 9 cycles), sampled ever more
//! densely, with 1 mV voltage and 2 mA current noise. Each fit runs the release binary
//! (`cellstudio fit`, as a user would) and is timed with its peak resident memory.
//!
//! `cargo build --release && cargo run --release --example bench_big_recording [ROWS...]`
//! (default 1000 10000 100000 1000000) prints a Markdown table. Files go to
//! `out/bench_big_recording/`.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::{Protocol, Step};
use cellstudio::simulation::{SimOptions, simulate};
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

const TRUE_DIFFUSIVITY: f64 = 3.3e-14;
const TRUE_RESISTANCE: f64 = 0.01;

fn cycling() -> Protocol {
    let cycle = [
        Step::CRate { rate: 1.0, duration: 2700.0, until_voltage: None },
        Step::Rest { duration: 1800.0 },
        Step::CRate { rate: -0.5, duration: 5400.0, until_voltage: None },
        Step::Rest { duration: 1800.0 },
    ];
    Protocol { steps: (0..9).flat_map(|_| cycle.clone()).collect() }
}

/// Writes the recording of about `rows` points and its fitting study; returns the study's path.
fn write_case(dir: &Path, rows: usize) -> PathBuf {
    let mut p = chen2020();
    p.negative.diffusivity = TRUE_DIFFUSIVITY;
    p.cell.contact_resistance = TRUE_RESISTANCE;
    let protocol = cycling();
    let end: f64 = protocol.steps.iter().map(|s| s.duration()).sum();
    // As cyclers log: a sample 1 ms either side of every current step, so the replayed current
    // steps instead of ramping between samples far apart.
    let mut t_eval: Vec<f64> = (0..rows).map(|k| end * k as f64 / (rows - 1) as f64).collect();
    let mut boundary = 0.0;
    for s in &protocol.steps[..protocol.steps.len() - 1] {
        boundary += s.duration();
        t_eval.extend([boundary - 1e-3, boundary + 1e-3]);
    }
    t_eval.sort_by(f64::total_cmp);
    t_eval.dedup_by(|a, b| *a - *b < 1e-6);
    let mut builder = ModelBuilder::new(ModelKind::Spm, Submodels { contact_resistance: true, ..Default::default() }, MeshSizes::default());
    let built = builder.build(&p).expect("build");
    let mut opts = SimOptions { t_eval: Some(t_eval), cutoffs: (0.0, 100.0), ..SimOptions::for_cell(&p) };
    opts.solver.set_tolerance(1e-8);
    let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).expect("truth");
    let mut rng = rand::rngs::StdRng::seed_from_u64(rows as u64);
    let (dv, di) = (Normal::new(0.0, 1e-3).unwrap(), Normal::new(0.0, 2e-3).unwrap());
    std::fs::create_dir_all(dir).expect("output folder");
    let csv = dir.join("recording.csv");
    let mut f = std::io::BufWriter::new(std::fs::File::create(&csv).expect("csv"));
    writeln!(f, "time_s,current_A,voltage_V").unwrap();
    for k in 0..sol.time.len() {
        let (i, v) = (sol.current[k] + di.sample(&mut rng), sol.voltage[k] + dv.sample(&mut rng));
        writeln!(f, "{:.6},{i:.5},{v:.6}", sol.time[k]).unwrap();
    }
    let study = dir.join("fit.toml");
    std::fs::write(
        &study,
        format!(
            "name = \"{rows} rows\"\n[model]\nkind = \"spm\"\nsubmodels = {{ contact_resistance = true }}\n\
             [data]\nfile = \"{}\"\n\
             [[parameters]]\npath = \"negative.diffusivity\"\ninitial = 6.6e-14\nlower = 1e-15\nupper = 1e-12\nlog = true\n\
             [[parameters]]\npath = \"cell.contact_resistance\"\ninitial = 0.005\nlower = 1e-4\nupper = 0.1\nlog = true\n\
             [cost]\nkind = \"sse\"\n[optimiser]\nmethod = \"lbfgsb\"\nseed = 1\n[output]\ndir = \"{}\"\n",
            csv.display(),
            dir.join("fit").display()
        ),
    )
    .expect("study");
    study
}

/// Largest resident set (MB) of the terminated children so far.
fn children_peak_mb() -> f64 {
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut usage) };
    usage.ru_maxrss as f64 / 1024.0
}

fn main() {
    let rows: Vec<usize> = std::env::args().skip(1).map(|a| a.parse().expect("ROWS must be integers")).collect();
    let mut rows = if rows.is_empty() { vec![1_000, 10_000, 100_000, 1_000_000] } else { rows };
    // Peak memory is read over all finished children: ascending sizes make it the latest's.
    rows.sort_unstable();
    let exe = std::env::current_exe().expect("exe");
    let binary = exe.parent().and_then(Path::parent).expect("target/release").join("cellstudio");
    assert!(binary.exists(), "build the binary first: cargo build --release ({} missing)", binary.display());
    let root = Path::new("out/bench_big_recording");
    println!("| rows | fit wall (s) | peak memory (MB) | D_n (truth 3.3e-14) | R (mOhm, truth 10) | RMSE (mV, noise 1) |");
    println!("|---|---|---|---|---|---|");
    for n in rows {
        let dir = root.join(format!("rows_{n}"));
        let study = write_case(&dir, n);
        let _ = std::fs::remove_dir_all(dir.join("fit"));
        let start = Instant::now();
        let out = std::process::Command::new(&binary).arg("fit").arg(&study).output().expect("run cellstudio fit");
        let wall = start.elapsed().as_secs_f64();
        assert!(out.status.success(), "fit failed: {}", String::from_utf8_lossy(&out.stderr));
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("fit/fit.json")).expect("fit.json")).expect("json");
        let x = |k: usize| json["x"][k].as_f64().unwrap_or(f64::NAN);
        let rmse = json["rmse"].as_f64().unwrap_or(f64::NAN);
        println!("| {n} | {wall:.1} | {:.0} | {:.3e} | {:.3} | {:.3} |", children_peak_mb(), x(0), x(1) * 1e3, rmse * 1e3);
    }
}
