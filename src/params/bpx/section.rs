//! Walking a BPX document: sections that remember which keys were read, so that the rest can
//! be reported unknown, and hand out numbers, functions and sub-sections by key.

use std::collections::BTreeSet;

use serde_json::{Map, Value};

use super::float_function::Bpx1D;
use super::keys;
use super::value::{Check, missing, number, type_error};
use crate::error::Error;

/// One JSON object of the document, remembering which keys were read.
pub(super) struct Section<'a> {
    path: String,
    pub(super) map: &'a Map<String, Value>,
    used: BTreeSet<&'a str>,
}

impl<'a> Section<'a> {
    pub(super) fn new(path: String, v: &'a Value) -> Result<Self, Error> {
        match v {
            Value::Object(map) => Ok(Section { path, map, used: BTreeSet::new() }),
            _ => Err(type_error(if path.is_empty() { "BPX document" } else { &path }, "an object", v)),
        }
    }

    pub(super) fn key_path(&self, key: &str) -> String {
        if self.path.is_empty() { key.to_string() } else { format!("{}/{key}", self.path) }
    }

    /// The value of `key`, marked as read; `null` counts as absent.
    pub(super) fn take(&mut self, key: &str) -> Option<&'a Value> {
        let (k, v) = self.map.get_key_value(key)?;
        self.used.insert(k.as_str());
        (!v.is_null()).then_some(v)
    }

    pub(super) fn opt_num(&mut self, key: &str, check: Check) -> Result<Option<f64>, Error> {
        let path = self.key_path(key);
        self.take(key).map(|v| number(&path, v, check)).transpose()
    }

    pub(super) fn num(&mut self, key: &str, check: Check) -> Result<f64, Error> {
        self.opt_num(key, check)?.ok_or_else(|| missing(&self.key_path(key)))
    }

    pub(super) fn func(&mut self, key: &str) -> Result<Bpx1D, Error> {
        self.opt_func(key)?.ok_or_else(|| missing(&self.key_path(key)))
    }

    pub(super) fn opt_func(&mut self, key: &str) -> Result<Option<Bpx1D>, Error> {
        let path = self.key_path(key);
        self.take(key).map(|v| Bpx1D::parse(&path, v)).transpose()
    }

    pub(super) fn opt_section(&mut self, key: &str) -> Result<Option<Section<'a>>, Error> {
        let path = self.key_path(key);
        self.take(key).map(|v| Section::new(path, v)).transpose()
    }

    pub(super) fn section(&mut self, key: &str) -> Result<Section<'a>, Error> {
        self.opt_section(key)?.ok_or_else(|| missing(&self.key_path(key)))
    }

    /// Lists the keys never read.
    pub(super) fn finish(self, unknown: &mut Vec<String>) {
        for k in self.map.keys() {
            if !self.used.contains(k.as_str()) {
                unknown.push(self.key_path(k));
            }
        }
    }
}

/// Reads `key` from the preferred (v1 `State`) section, else from the v0 section; a value
/// present in both is taken from the preferred one and the other is reported unknown.
pub(super) fn first_of(
    preferred: &mut Option<Section>,
    preferred_key: &str,
    fallback: &mut Section,
    fallback_key: &str,
    check: Check,
    unknown: &mut Vec<String>,
) -> Result<Option<(f64, String)>, Error> {
    let first = match preferred {
        Some(s) => s.opt_num(preferred_key, check)?.map(|v| (v, s.key_path(preferred_key))),
        None => None,
    };
    let second = fallback.opt_num(fallback_key, check)?.map(|v| (v, fallback.key_path(fallback_key)));
    match (first, second) {
        (Some(a), Some(b)) => {
            unknown.push(b.1);
            Ok(Some(a))
        }
        (a, b) => Ok(a.or(b)),
    }
}

/// The sections of a document under `Parameterisation` and `State`.
pub(super) struct Sections<'a> {
    pub(super) parameterisation: Section<'a>,
    pub(super) cell: Section<'a>,
    pub(super) electrolyte: Section<'a>,
    pub(super) negative: Section<'a>,
    pub(super) positive: Section<'a>,
    pub(super) separator: Section<'a>,
    pub(super) user: Option<Section<'a>>,
    pub(super) state: Option<Section<'a>>,
    /// v1 `State / Initial conditions`.
    pub(super) initial: Option<Section<'a>>,
    /// v1 `State / Thermal environment`.
    pub(super) environment: Option<Section<'a>>,
}

impl<'a> Sections<'a> {
    /// Opens every section the importer reads; the required ones must be there.
    pub(super) fn open(root: &mut Section<'a>) -> Result<Self, Error> {
        let mut parameterisation = root.section(keys::PARAMETERISATION)?;
        let cell = parameterisation.section(keys::CELL)?;
        let electrolyte = parameterisation.section(keys::ELECTROLYTE)?;
        let negative = parameterisation.section(keys::NEGATIVE)?;
        let positive = parameterisation.section(keys::POSITIVE)?;
        let separator = parameterisation.section(keys::SEPARATOR)?;
        let user = parameterisation.opt_section(keys::USER_DEFINED)?;
        let mut state = root.opt_section(keys::STATE)?;
        let initial = match &mut state {
            Some(s) => s.opt_section(keys::INITIAL_CONDITIONS)?,
            None => None,
        };
        let environment = match &mut state {
            Some(s) => s.opt_section(keys::THERMAL_ENVIRONMENT)?,
            None => None,
        };
        Ok(Sections {
            parameterisation,
            cell,
            electrolyte,
            negative,
            positive,
            separator,
            user,
            state,
            initial,
            environment,
        })
    }

    /// Lists the keys never read. `User-defined` is read whole by the importer.
    pub(super) fn finish(self, unknown: &mut Vec<String>) {
        for s in [self.cell, self.electrolyte, self.negative, self.positive, self.separator] {
            s.finish(unknown);
        }
        for s in [self.initial, self.environment, self.state].into_iter().flatten() {
            s.finish(unknown);
        }
        self.parameterisation.finish(unknown);
    }
}
