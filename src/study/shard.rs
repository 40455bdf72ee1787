//! Sweeps beyond one machine: `sweep --shard K/N` evaluates the K-th of N contiguous parts of
//! the study's candidates and writes `<output.dir>.shard-K-of-N/shard.json`; `sweep --merge`
//! checks that a set of shards is one whole sweep of this study and writes the ordinary
//! sweep output from them, byte for byte what a single run writes (every point is evaluated
//! alone, and the shard file keeps its numbers exactly: JSON floats round-trip).

use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::time::Instant;

use serde::{Deserialize, Serialize};

use super::Study;
use super::sweep::{SweepOutcome, evaluate_points, sweep_candidates, write_sweep};
use crate::error::Error;
use crate::problem::sweep::SweepPoint;

/// Part `k` (from 1) of `n` of a sweep.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    pub k: usize,
    pub n: usize,
}

impl FromStr for Shard {
    type Err = Error;

    /// `K/N` with `1 <= K <= N`.
    fn from_str(text: &str) -> Result<Self, Error> {
        let bad = |why: &str| Error::InvalidSetting { field: "--shard".into(), reason: format!("`{text}`: {why}") };
        let (k, n) = text.split_once('/').ok_or_else(|| bad("expected K/N, e.g. 2/8"))?;
        let (k, n): (usize, usize) = (k.trim().parse().map_err(|_| bad("K is not a whole number"))?, n.trim().parse().map_err(|_| bad("N is not a whole number"))?);
        if n == 0 || k == 0 || k > n {
            return Err(bad("needs 1 <= K <= N"));
        }
        Ok(Self { k, n })
    }
}

impl Shard {
    /// The candidates (indices into the study's `m`, in order) of this shard.
    pub fn range(&self, m: usize) -> std::ops::Range<usize> {
        (self.k - 1) * m / self.n..self.k * m / self.n
    }

    /// The shard's folder beside the study's output folder `out`.
    pub fn folder(&self, out: &Path) -> PathBuf {
        let name = out.file_name().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "sweep".into());
        out.with_file_name(format!("{name}.shard-{}-of-{}", self.k, self.n))
    }
}

/// What a shard writes.
#[derive(Serialize, Deserialize)]
struct ShardFile {
    study: String,
    /// The study's settings as the shard ran them: shards of one sweep must agree on all.
    settings: serde_json::Value,
    /// Candidates of the whole sweep.
    candidates: usize,
    shard: usize,
    shards: usize,
    /// Index of the first point in the whole sweep.
    first: usize,
    rebuilds: usize,
    seconds: f64,
    points: Vec<SweepPoint>,
}

const SHARD_FILE: &str = "shard.json";

/// Evaluates shard `shard` of the study's sweep and writes its folder; returns the file and
/// the number of points evaluated.
pub fn run_shard(study: &Study, shard: Shard) -> Result<(PathBuf, usize, f64), Error> {
    let candidates = sweep_candidates(study)?;
    let m = candidates.len();
    let range = shard.range(m);
    let out = crate::output::OutputDir::create(&shard.folder(&study.output.dir), &study.inputs())?;
    let problem = study.problem()?;
    let start = Instant::now();
    let baseline = problem.evaluate(&study.baseline()?)?;
    let mine: Vec<Vec<f64>> = candidates[range.clone()].to_vec();
    let points = evaluate_points(study, &problem, &baseline, mine)?;
    let seconds = start.elapsed().as_secs_f64();
    let file = ShardFile { study: study.name.clone(), settings: settings(study)?, candidates: m, shard: shard.k, shards: shard.n, first: range.start, rebuilds: problem.rebuild_count(), seconds, points };
    let path = out.path().join(SHARD_FILE);
    let text = serde_json::to_string(&file).map_err(|e| Error::Io { path: path.display().to_string(), source: e.into() })?;
    crate::error::write_file(&path, text)?;
    let files = out.commit(&[path])?;
    Ok((files.into_iter().next().expect("one file"), range.len(), seconds))
}

/// Merges shard folders (or their `shard.json` files) of the study's sweep into its ordinary
/// output. Errors when a shard belongs to another study or grid, or a part is missing or
/// given twice.
pub fn merge_shards(study: &Study, shards: &[PathBuf]) -> Result<SweepOutcome, Error> {
    let candidates = sweep_candidates(study)?;
    let m = candidates.len();
    let mine = settings(study)?;
    let bad = |path: &Path, why: String| Error::InvalidSetting { field: "--merge".into(), reason: format!("{}: {why}", path.display()) };
    let mut files: Vec<(PathBuf, ShardFile)> = Vec::new();
    for given in shards {
        let path = if given.is_dir() { given.join(SHARD_FILE) } else { given.clone() };
        let text = std::fs::read_to_string(&path).map_err(Error::io(&path))?;
        let file: ShardFile = serde_json::from_str(&text).map_err(|e| Error::Parse { path: path.display().to_string(), message: e.to_string() })?;
        if file.study != study.name || file.candidates != m {
            return Err(bad(&path, format!("a shard of \"{}\" with {} candidates, not of this study's {m}", file.study, file.candidates)));
        }
        if let Some((key, theirs, ours)) = first_difference(&file.settings, &mine, "") {
            return Err(bad(&path, format!("ran with `{key}` = {theirs}, where this study has {ours}: not a shard of this sweep")));
        }
        files.push((path, file));
    }
    let n = files.first().map(|f| f.1.shards).ok_or_else(|| Error::InvalidSetting { field: "--merge".into(), reason: "no shards given".into() })?;
    files.sort_by_key(|f| f.1.shard);
    let given: Vec<usize> = files.iter().map(|f| f.1.shard).collect();
    if files.iter().any(|f| f.1.shards != n) || given != (1..=n).collect::<Vec<_>>() {
        return Err(Error::InvalidSetting { field: "--merge".into(), reason: format!("needs each of the {n} shards once; given {given:?}") });
    }
    let mut points = Vec::with_capacity(m);
    let (mut rebuilds, mut seconds) = (0, 0.0);
    for (path, file) in files {
        let range = Shard { k: file.shard, n }.range(m);
        let expected = &candidates[range.clone()];
        if file.first != range.start || file.points.len() != range.len() || file.points.iter().zip(expected).any(|(p, x)| &p.x != x) {
            return Err(bad(&path, "its points are not this study's candidates (was the study changed after the shards ran?)".into()));
        }
        rebuilds += file.rebuilds;
        seconds += file.seconds;
        points.extend(file.points);
    }
    let out = study.output_dir()?;
    let baseline = study.problem()?.evaluate(&study.baseline()?)?;
    write_sweep(study, out, baseline, points, rebuilds, seconds)
}

/// The study's settings as JSON, without its output section (shards write beside it).
fn settings(study: &Study) -> Result<serde_json::Value, Error> {
    let mut value = serde_json::to_value(study).map_err(|e| Error::InvalidSetting { field: "study".into(), reason: e.to_string() })?;
    if let Some(map) = value.as_object_mut() {
        map.remove("output");
    }
    Ok(value)
}

/// The first key (dotted, `[k]` for list items) whose values differ, with both values.
fn first_difference(a: &serde_json::Value, b: &serde_json::Value, at: &str) -> Option<(String, String, String)> {
    use serde_json::Value;
    let key = |k: &str| if at.is_empty() { k.to_string() } else { format!("{at}.{k}") };
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            let keys: std::collections::BTreeSet<&String> = x.keys().chain(y.keys()).collect();
            keys.into_iter().find_map(|k| first_difference(x.get(k).unwrap_or(&Value::Null), y.get(k).unwrap_or(&Value::Null), &key(k)))
        }
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
            x.iter().zip(y).enumerate().find_map(|(i, (u, v))| first_difference(u, v, &format!("{at}[{i}]")))
        }
        _ if a == b => None,
        _ => Some((if at.is_empty() { "study".into() } else { at.to_string() }, a.to_string(), b.to_string())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_cover_every_candidate_once() {
        for (m, n) in [(169, 4), (10, 10), (7, 3), (3, 5)] {
            let mut covered = Vec::new();
            for k in 1..=n {
                covered.extend(Shard { k, n }.range(m));
            }
            assert_eq!(covered, (0..m).collect::<Vec<_>>(), "{m} over {n}");
        }
        assert_eq!("2/8".parse::<Shard>().unwrap(), Shard { k: 2, n: 8 });
        for bad in ["0/4", "5/4", "2", "a/4", "2/0"] {
            assert!(bad.parse::<Shard>().unwrap_err().to_string().contains("--shard"), "{bad}");
        }
    }

    #[test]
    fn the_first_differing_setting_is_named() {
        let a = serde_json::json!({"operating": {"c_rate": 1.0, "temperature": 298.15}, "variables": [{"lower": 1.0}]});
        assert_eq!(first_difference(&a, &a, ""), None);
        let b = serde_json::json!({"operating": {"c_rate": 1.0, "temperature": 25.0}, "variables": [{"lower": 1.0}]});
        assert_eq!(first_difference(&b, &a, ""), Some(("operating.temperature".into(), "25.0".into(), "298.15".into())));
        let c = serde_json::json!({"operating": {"c_rate": 1.0, "temperature": 298.15}, "variables": [{"lower": 2.0}]});
        assert_eq!(first_difference(&c, &a, "").map(|d| d.0), Some("variables[0].lower".into()));
    }
}
