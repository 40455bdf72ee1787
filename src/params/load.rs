//! Reading a parameter set from a file of any supported format.

use std::path::Path;

use super::ParameterSet;
use super::bpx::from_bpx_json;
use crate::error::Error;

impl ParameterSet {
    /// Reads the parameter set at `path` (see [`from_file`](Self::from_file)), or returns the
    /// embedded Chen 2020 set when no path is given.
    pub fn from_file_or_default(path: Option<&Path>) -> Result<Self, Error> {
        path.map_or_else(|| Ok(super::chen2020()), Self::from_file)
    }

    /// Reads a parameter set: `.toml` (this crate's layout), `.json` holding either this
    /// crate's layout or a BPX document (recognised by its `Parameterisation` section; the
    /// import's unknown fields are printed as warnings to stderr), validated.
    pub fn from_file(path: &Path) -> Result<Self, Error> {
        let name = path.display().to_string();
        match path.extension().and_then(|e| e.to_str()) {
            Some("json") => {
                let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: name.clone(), source })?;
                let value: serde_json::Value =
                    serde_json::from_str(&text).map_err(|e| Error::Parse { path: name.clone(), message: e.to_string() })?;
                if value.get("Parameterisation").is_some() {
                    let import = from_bpx_json(&text)?;
                    for field in &import.unknown_fields {
                        eprintln!("warning: {name}: BPX field `{field}` is not used");
                    }
                    return Ok(import.params);
                }
                let set: ParameterSet =
                    serde_json::from_value(value).map_err(|e| Error::Parse { path: name, message: e.to_string() })?;
                set.validate()?;
                Ok(set)
            }
            _ => Self::from_toml_file(path),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::chen2020;

    #[test]
    fn json_round_trip_and_bpx_detection() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("set.json");
        let mut p = chen2020();
        p.negative.diffusivity = 2.5e-14;
        std::fs::write(&path, serde_json::to_string(&p).unwrap()).unwrap();
        assert_eq!(ParameterSet::from_file(&path).unwrap(), p);
        let bpx = dir.path().join("bpx.json");
        std::fs::copy(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/bpx_example.json"), &bpx).unwrap();
        let direct = from_bpx_json(&std::fs::read_to_string(&bpx).unwrap()).unwrap().params;
        assert_eq!(ParameterSet::from_file(&bpx).unwrap(), direct);
        p.negative.thickness = -1.0;
        std::fs::write(&path, serde_json::to_string(&p).unwrap()).unwrap();
        assert!(ParameterSet::from_file(&path).unwrap_err().to_string().contains("negative.thickness"));
    }
}
