//! Import: a BPX document (v0.4/v0.5, or v1.x with its `State` section) into a validated
//! [`ParameterSet`], read section by section on top of Chen 2020, each field remembering the
//! BPX key(s) it came from.

use std::collections::BTreeMap;

use serde_json::Value;

use super::super::chen2020::chen2020;
use super::super::function::Function1D;
use super::super::set::{FARADAY, ParameterSet};
use super::keys::{self, HEAT_LAYERS, SOC_KEY, USER_DEFINED_FIELDS, USER_PREFIX, mean_heat_capacity, scalar_paths};
use super::section::{Section, Sections, first_of};
use super::tabulate::{ELECTROLYTE_RANGE, ELECTROLYTE_TOLERANCE, ENTROPIC_TOLERANCE, OCP_TOLERANCE, Tolerance};
use super::value::{Check, describe, missing, number, relabel, type_error};
use crate::error::Error;

/// Result of a BPX import.
#[derive(Clone, Debug)]
pub struct BpxImport {
    /// The validated parameter set.
    pub params: ParameterSet,
    /// BPX keys (as `Section/Sub-section/Key` paths) that map to nothing here, including
    /// `User-defined` keys not written by us and `Validation` data sets.
    pub unknown_fields: Vec<String>,
    /// Our fields (dotted paths) the document does not determine: Chen 2020 values, or the
    /// BPX meaning of an absent optional key (see the module documentation).
    pub defaulted_fields: Vec<String>,
    /// BPX keys converted with a loss of information (expressions sampled into tables,
    /// stoichiometry-dependent values averaged to scalars, a second activation energy).
    pub approximated_fields: Vec<String>,
}

/// Reads a BPX JSON document (v0.4/v0.5, or v1.x) into a validated parameter set.
pub fn from_bpx_json(text: &str) -> Result<BpxImport, Error> {
    let doc: Value = serde_json::from_str(text)
        .map_err(|e| Error::Parse { path: "BPX JSON".into(), message: e.to_string() })?;
    Importer::new().run(&doc)
}

/// A value with the BPX key(s) it came from.
type Sourced = (f64, String);

/// The `User-defined` keys of ours: field values and the initial state of charge.
struct UserDefined {
    values: BTreeMap<&'static str, Sourced>,
    soc: Option<Sourced>,
}

/// The set being read (Chen 2020 until a key says otherwise) and the bookkeeping of the
/// import's three lists.
struct Importer {
    p: ParameterSet,
    /// Our field path -> the BPX key(s) it came from.
    origin: BTreeMap<String, String>,
    unknown: Vec<String>,
    approximated: Vec<String>,
    /// Fields set from BPX data together with an assumption (listed as defaulted as well).
    assumed: Vec<String>,
}

impl Importer {
    fn new() -> Self {
        Importer {
            p: chen2020(),
            origin: BTreeMap::new(),
            unknown: Vec::new(),
            approximated: Vec::new(),
            assumed: Vec::new(),
        }
    }

    /// Sets our field `path` and remembers its BPX `source`.
    fn set(&mut self, path: &str, value: f64, source: impl Into<String>) -> Result<(), Error> {
        self.p.set(path, value)?;
        self.origin.insert(path.into(), source.into());
        Ok(())
    }

    /// Reads a required number into `path`.
    fn copy(&mut self, sec: &mut Section, key: &str, check: Check, path: &str) -> Result<f64, Error> {
        let v = sec.num(key, check)?;
        self.set(path, v, sec.key_path(key))?;
        Ok(v)
    }

    /// Reads an optional non-negative number into `path`; absent, 0 (the BPX meaning, and the
    /// field is listed as defaulted).
    fn copy_or_zero(&mut self, sec: &mut Section, key: &str, path: &str) -> Result<(), Error> {
        match sec.opt_num(key, Check::NonNegative)? {
            Some(v) => self.set(path, v, sec.key_path(key)),
            None => self.p.set(path, 0.0),
        }
    }

    /// The whole import, in the order that decides which error a faulty document reports.
    fn run(mut self, doc: &Value) -> Result<BpxImport, Error> {
        let mut root = Section::new(String::new(), doc)?;
        self.header(&mut root)?;
        let mut s = Sections::open(&mut root)?;
        self.validation(&mut root);
        let user = self.user_defined(s.user.as_ref())?;

        let plate = self.cell(&mut s.cell)?;
        self.temperatures(&mut s)?;
        let lumped = self.lumped_heat_capacity(&mut s.cell)?;
        let ce0 = self.electrolyte(&mut s)?;
        let window_n = self.electrode(&mut s.negative, "negative", ce0)?;
        let window_p = self.electrode(&mut s.positive, "positive", ce0)?;
        self.separator(&mut s.separator)?;

        self.user_fields(&user.values)?;
        self.solid_conductivities()?;
        // Plate: the BPX area, split with the user-defined (else Chen 2020) height.
        let (area, area_source) = plate;
        self.set("cell.electrode_width", area / self.p.cell.electrode_height, area_source)?;
        self.heat_capacities(&user.values, lumped.as_ref())?;
        self.initial_stoichiometries(s.initial.as_mut(), user.soc, window_n, window_p)?;
        // Without a BPX volume, the stack volume with the packaging allowance.
        if !self.origin.contains_key("thermal.cell_volume") {
            self.p.thermal.cell_volume = self.p.budget().volume;
        }

        s.finish(&mut self.unknown);
        root.finish(&mut self.unknown);
        self.finish()
    }

    /// `Header`: a supported version, the title as the set's name, a model name.
    fn header(&mut self, root: &mut Section) -> Result<(), Error> {
        let mut header = root.section(keys::HEADER)?;
        let version_path = header.key_path("BPX");
        let version = header.take("BPX").ok_or_else(|| missing(&version_path))?;
        let major = match version {
            Value::Number(n) => n.as_f64().map(|v| v.floor() as i64),
            Value::String(s) => s.trim().split('.').next().and_then(|m| m.parse().ok()),
            _ => None,
        };
        if !matches!(major, Some(0 | 1)) {
            return Err(Error::InvalidSetting {
                field: version_path,
                reason: format!("unsupported BPX version {} (0.x and 1.x are read)", describe(version)),
            });
        }
        self.p.name = match header.take("Title") {
            Some(Value::String(t)) => t.clone(),
            Some(v) => return Err(type_error(&header.key_path("Title"), "a string", v)),
            None => "BPX import".into(),
        };
        match header.take("Model") {
            Some(Value::String(_)) => {}
            Some(v) => return Err(type_error(&header.key_path("Model"), "a string", v)),
            None => return Err(missing(&header.key_path("Model"))),
        }
        header.finish(&mut self.unknown);
        Ok(())
    }

    /// `Validation` data sets are not read: each is reported unknown.
    fn validation(&mut self, root: &mut Section) {
        if let Some(v) = root.take(keys::VALIDATION) {
            match v.as_object() {
                Some(sets) => self.unknown.extend(sets.keys().map(|k| format!("{}/{k}", keys::VALIDATION))),
                None => self.unknown.push(keys::VALIDATION.into()),
            }
        }
    }

    /// `User-defined`: our own keys; anything else is unknown.
    fn user_defined(&mut self, user: Option<&Section>) -> Result<UserDefined, Error> {
        let mut found = UserDefined { values: BTreeMap::new(), soc: None };
        let Some(user) = user else { return Ok(found) };
        for (k, v) in user.map {
            let path = user.key_path(k);
            if k == SOC_KEY {
                found.soc = Some((number(&path, v, Check::ClosedUnit)?, path));
            } else if let Some(field) =
                k.strip_prefix(USER_PREFIX).and_then(|f| USER_DEFINED_FIELDS.iter().find(|u| **u == f))
            {
                found.values.insert(field, (number(&path, v, Check::Finite)?, path));
            } else {
                self.unknown.push(path);
            }
        }
        Ok(found)
    }

    /// `Cell`: cut-offs, capacity, cooling area and volume; returns the electrode area of
    /// all pairs (m^2) with its source.
    fn cell(&mut self, cell: &mut Section) -> Result<Sourced, Error> {
        let n_pairs_path = cell.key_path(keys::PAIRS);
        let n_pairs = cell.num(keys::PAIRS, Check::Positive)?;
        if n_pairs.fract() != 0.0 {
            return Err(Error::invalid(n_pairs_path, n_pairs, "must be a whole number"));
        }
        let area = cell.num(keys::AREA, Check::Positive)? * n_pairs;
        let area_source = format!("{} x {}", cell.key_path(keys::AREA), n_pairs_path);
        self.copy(cell, keys::LOWER_CUTOFF, Check::Positive, "cell.lower_cutoff")?;
        self.copy(cell, keys::UPPER_CUTOFF, Check::Positive, "cell.upper_cutoff")?;
        self.copy(cell, keys::CAPACITY, Check::Positive, "cell.nominal_capacity")?;
        if let Some(v) = cell.opt_num(keys::EXTERNAL_AREA, Check::NonNegative)? {
            self.set("thermal.cooling_area", v, cell.key_path(keys::EXTERNAL_AREA))?;
        }
        if let Some(v) = cell.opt_num(keys::VOLUME, Check::Positive)? {
            self.set("thermal.cell_volume", v, cell.key_path(keys::VOLUME))?;
        }
        Ok((area, area_source))
    }

    /// Reference, ambient and initial temperatures and the heat-transfer coefficient. v1 keeps
    /// the temperatures in `State`, v0 in `Cell`; `State` wins, an unused `Cell` value is
    /// reported. Absent, the ambient temperature is the reference one, the initial the ambient.
    fn temperatures(&mut self, s: &mut Sections) -> Result<(), Error> {
        let t_ref = match s.cell.opt_num(keys::REFERENCE_T, Check::Positive)? {
            Some(t) => {
                self.set("thermal.reference_temperature", t, s.cell.key_path(keys::REFERENCE_T))?;
                t
            }
            None => self.p.thermal.reference_temperature,
        };
        let ambient =
            first_of(&mut s.environment, keys::AMBIENT_T, &mut s.cell, keys::AMBIENT_T, Check::Positive, &mut self.unknown)?;
        let ambient = match ambient {
            Some((t, src)) => {
                self.set("thermal.ambient_temperature", t, src)?;
                t
            }
            None => {
                self.p.thermal.ambient_temperature = t_ref;
                t_ref
            }
        };
        match first_of(&mut s.initial, keys::INITIAL_T, &mut s.cell, keys::INITIAL_T, Check::Positive, &mut self.unknown)? {
            Some((t, src)) => self.set("thermal.initial_temperature", t, src)?,
            None => self.p.thermal.initial_temperature = ambient,
        }
        if let Some(env) = &mut s.environment
            && let Some(h) = env.opt_num(keys::HEAT_TRANSFER, Check::NonNegative)?
        {
            self.set("thermal.heat_transfer_coefficient", h, env.key_path(keys::HEAT_TRANSFER))?;
        }
        Ok(())
    }

    /// `Cell / Density` x `Specific heat capacity` (J/(m^3 K)), when both are given.
    fn lumped_heat_capacity(&mut self, cell: &mut Section) -> Result<Option<Sourced>, Error> {
        let density = cell.opt_num(keys::DENSITY, Check::Positive)?;
        let heat_capacity = cell.opt_num(keys::HEAT_CAPACITY, Check::Positive)?;
        Ok(match (density, heat_capacity) {
            (Some(rho), Some(cp)) => Some((
                rho * cp,
                format!("{} x {}", cell.key_path(keys::DENSITY), cell.key_path(keys::HEAT_CAPACITY)),
            )),
            // One without the other determines nothing here.
            (Some(_), None) => {
                self.unknown.push(cell.key_path(keys::DENSITY));
                None
            }
            (None, Some(_)) => {
                self.unknown.push(cell.key_path(keys::HEAT_CAPACITY));
                None
            }
            (None, None) => None,
        })
    }

    /// `Electrolyte` (and v1 `State / Initial conditions`); returns the initial electrolyte
    /// concentration (mol/m^3) the reaction rates are scaled with.
    fn electrolyte(&mut self, s: &mut Sections) -> Result<f64, Error> {
        let ce0 = first_of(
            &mut s.initial,
            keys::ELECTROLYTE_C0_V1,
            &mut s.electrolyte,
            keys::ELECTROLYTE_C0,
            Check::Positive,
            &mut self.unknown,
        )?;
        let ce0 = match ce0 {
            Some((c, src)) => {
                self.set("electrolyte.initial_concentration", c, src)?;
                c
            }
            None => self.p.electrolyte.initial_concentration,
        };
        let electrolyte = &mut s.electrolyte;
        self.copy(electrolyte, keys::TRANSFERENCE, Check::OpenUnit, "electrolyte.transference_number")?;
        for (key, field) in [(keys::DIFFUSIVITY, "electrolyte.diffusivity"), (keys::CONDUCTIVITY, "electrolyte.conductivity")] {
            let path = electrolyte.key_path(key);
            let tol = Tolerance::Relative(ELECTROLYTE_TOLERANCE);
            let f = electrolyte.func(key)?.to_function(&path, ELECTROLYTE_RANGE, tol, &mut self.approximated)?;
            if key == keys::DIFFUSIVITY {
                self.p.electrolyte.diffusivity = f;
            } else {
                self.p.electrolyte.conductivity = f;
            }
            self.origin.insert(field.into(), path);
        }
        self.electrolyte_activation_energy(electrolyte)?;
        Ok(ce0)
    }

    /// One activation energy for both transport properties: the conductivity's, which
    /// dominates the voltage; a different diffusivity value is reported as approximated.
    fn electrolyte_activation_energy(&mut self, electrolyte: &mut Section) -> Result<(), Error> {
        let ea_d = electrolyte.opt_num(keys::DIFFUSIVITY_EA, Check::NonNegative)?;
        let ea_k = electrolyte.opt_num(keys::CONDUCTIVITY_EA, Check::NonNegative)?;
        let (ea_d_path, ea_k_path) =
            (electrolyte.key_path(keys::DIFFUSIVITY_EA), electrolyte.key_path(keys::CONDUCTIVITY_EA));
        match (ea_d, ea_k) {
            (Some(d), Some(k)) => {
                if (d - k).abs() > 1e-12 * k.abs().max(1.0) {
                    self.approximated.push(ea_d_path);
                }
                self.set("electrolyte.activation_energy", k, ea_k_path)
            }
            (Some(d), None) => self.set("electrolyte.activation_energy", d, ea_d_path),
            (None, Some(k)) => self.set("electrolyte.activation_energy", k, ea_k_path),
            (None, None) => {
                self.p.electrolyte.activation_energy = 0.0;
                Ok(())
            }
        }
    }

    /// Reads one electrode; returns its stoichiometry window.
    fn electrode(&mut self, sec: &mut Section, side: &str, ce0: f64) -> Result<(f64, f64), Error> {
        if sec.map.contains_key(keys::PARTICLE) {
            return Err(Error::InvalidSetting {
                field: sec.key_path(keys::PARTICLE),
                reason: "blended electrodes (several particle phases) are not supported".into(),
            });
        }
        let f = |name: &str| format!("{side}.{name}");
        self.copy(sec, keys::THICKNESS, Check::Positive, &f("thickness"))?;
        let radius = self.copy(sec, keys::RADIUS, Check::Positive, &f("particle_radius"))?;
        let a = sec.num(keys::SURFACE_AREA, Check::Positive)?;
        self.set(&f("active_fraction"), a * radius / 3.0, sec.key_path(keys::SURFACE_AREA))?;
        let eps = self.copy(sec, keys::POROSITY, Check::OpenUnit, &f("porosity"))?;
        let tau = sec.num(keys::TRANSPORT_EFFICIENCY, Check::HalfOpenUnit)?;
        self.set(&f("bruggeman_electrolyte"), tau.ln() / eps.ln(), sec.key_path(keys::TRANSPORT_EFFICIENCY))?;
        self.copy(sec, keys::CONDUCTIVITY, Check::Positive, &f("conductivity"))?;
        self.set(&f("bruggeman_solid"), 0.0, "BPX convention (effective electrode conductivity)")?;
        self.set(&f("charge_transfer_coefficient"), 0.5, "BPX convention (symmetric Butler-Volmer)")?;
        let c_max = self.copy(sec, keys::MAX_CONCENTRATION, Check::Positive, &f("max_concentration"))?;
        let lo = sec.num(keys::MIN_STO, Check::ClosedUnit)?;
        let hi = sec.num(keys::MAX_STO, Check::ClosedUnit)?;
        if !(hi > lo) {
            return Err(Error::invalid(
                sec.key_path(keys::MAX_STO),
                hi,
                format!("must exceed the minimum stoichiometry {lo}"),
            ));
        }

        let path = sec.key_path(keys::DIFFUSIVITY);
        let d = sec.func(keys::DIFFUSIVITY)?.to_scalar(&path, (lo, hi), true, &mut self.approximated)?;
        self.set(&f("diffusivity"), Check::Positive.apply(&path, d)?, path)?;
        self.copy_or_zero(sec, keys::DIFFUSIVITY_EA, &f("diffusivity_activation_energy"))?;

        let path = sec.key_path(keys::OCP);
        let ocp = sec.func(keys::OCP)?.to_function(
            &path,
            (0.0, 1.0),
            Tolerance::Absolute(OCP_TOLERANCE),
            &mut self.approximated,
        )?;
        if side == "negative" { self.p.negative.ocp = ocp } else { self.p.positive.ocp = ocp }
        self.origin.insert(f("ocp"), path);
        let entropic = match sec.opt_func(keys::ENTROPIC)? {
            Some(e) => {
                let path = sec.key_path(keys::ENTROPIC);
                let function = e.to_function(&path, (0.0, 1.0), Tolerance::Absolute(ENTROPIC_TOLERANCE), &mut self.approximated)?;
                self.origin.insert(f("ocp_entropic_change"), path);
                function
            }
            None => Function1D::Constant { value: 0.0 },
        };
        if side == "negative" { self.p.negative.ocp_entropic_change = entropic } else { self.p.positive.ocp_entropic_change = entropic }

        let k = sec.num(keys::RATE, Check::Positive)?;
        self.set(&f("rate_constant"), FARADAY * k / (c_max * ce0.sqrt()), sec.key_path(keys::RATE))?;
        self.copy_or_zero(sec, keys::RATE_EA, &f("rate_activation_energy"))?;
        Ok((lo, hi))
    }

    /// `Separator`: thickness, porosity, and the Bruggeman exponent of its transport efficiency.
    fn separator(&mut self, separator: &mut Section) -> Result<(), Error> {
        self.copy(separator, keys::THICKNESS, Check::Positive, "separator.thickness")?;
        let eps = self.copy(separator, keys::POROSITY, Check::OpenUnit, "separator.porosity")?;
        let tau = separator.num(keys::TRANSPORT_EFFICIENCY, Check::HalfOpenUnit)?;
        self.set("separator.bruggeman", tau.ln() / eps.ln(), separator.key_path(keys::TRANSPORT_EFFICIENCY))
    }

    /// Our own fields from `User-defined`, unless a standard key (v1 `State`) already set them;
    /// then the user-defined value goes unused and is reported. Heat capacities wait for
    /// [`Self::heat_capacities`].
    fn user_fields(&mut self, values: &BTreeMap<&'static str, Sourced>) -> Result<(), Error> {
        for (field, (v, src)) in values {
            if self.origin.get(*field).is_some_and(|o| !o.starts_with("BPX convention")) {
                self.unknown.push(src.clone());
            } else if !field.ends_with("volumetric_heat_capacity") && !field.ends_with("collector_heat_capacity") {
                self.set(field, *v, src.clone())?;
            }
        }
        Ok(())
    }

    /// BPX's electrode conductivity is effective; ours is scaled by
    /// `(1 - porosity)^bruggeman_solid`, so a user-defined exponent divides it back out.
    fn solid_conductivities(&mut self) -> Result<(), Error> {
        for side in ["negative", "positive"] {
            let b = self.p.get(&format!("{side}.bruggeman_solid"))?;
            if b != 0.0 {
                let e = if side == "negative" { &mut self.p.negative } else { &mut self.p.positive };
                e.conductivity /= (1.0 - e.porosity).powf(b);
            }
        }
        Ok(())
    }

    /// Heat capacities: user-defined per layer, else the lumped value; scaled so that the
    /// stack mean equals the lumped value when there is one.
    fn heat_capacities(&mut self, values: &BTreeMap<&'static str, Sourced>, lumped: Option<&Sourced>) -> Result<(), Error> {
        for (_, field) in HEAT_LAYERS {
            if let Some((v, src)) = values.get(field) {
                self.set(field, *v, src.clone())?;
            } else if let Some((c, src)) = lumped {
                self.set(field, *c, src.clone())?;
            }
        }
        if let Some((c, src)) = lumped {
            let scale = c / mean_heat_capacity(&self.p)?;
            for (_, field) in HEAT_LAYERS {
                let v = self.p.get(field)?;
                let source = match values.get(field) {
                    Some((_, u)) => format!("{u} scaled to {src}"),
                    None => src.clone(),
                };
                self.set(field, v * scale, source)?;
            }
        }
        Ok(())
    }

    /// Initial particle concentrations from the windows and the state of charge: v1
    /// `State / Initial conditions`, else our user-defined key, else 1 (as in PyBaMM).
    fn initial_stoichiometries(
        &mut self,
        initial: Option<&mut Section>,
        user_soc: Option<Sourced>,
        window_n: (f64, f64),
        window_p: (f64, f64),
    ) -> Result<(), Error> {
        let soc = match initial.map(|ic| (ic.opt_num(keys::SOC, Check::ClosedUnit), ic.key_path(keys::SOC))) {
            Some((r, path)) => r?.map(|s| (s, path)),
            None => None,
        };
        let soc = match (soc, user_soc) {
            (Some(s), Some((_, unused))) => {
                self.unknown.push(unused);
                Some(s)
            }
            (s, u) => s.or(u),
        };
        let (soc, soc_source) = match soc {
            Some(s) => s,
            None => {
                self.assumed.push("negative.initial_concentration".into());
                self.assumed.push("positive.initial_concentration".into());
                (1.0, "an initial state of charge of 1 (absent)".into())
            }
        };
        let sto_n = window_n.0 + soc * (window_n.1 - window_n.0);
        let sto_p = window_p.1 - soc * (window_p.1 - window_p.0);
        let c_n = sto_n * self.p.negative.max_concentration;
        let c_p = sto_p * self.p.positive.max_concentration;
        let src = |side: &str| format!("{side} stoichiometry window with {soc_source}");
        self.set("negative.initial_concentration", c_n, src(keys::NEGATIVE))?;
        self.set("positive.initial_concentration", c_p, src(keys::POSITIVE))
    }

    /// Validates the set (errors name the BPX key behind our field) and lists what the
    /// document did not determine.
    fn finish(self) -> Result<BpxImport, Error> {
        self.p.validate().map_err(|e| relabel(e, &self.origin))?;
        let mut defaulted: Vec<String> =
            scalar_paths().into_iter().filter(|f| !self.origin.contains_key(f)).collect();
        for f in self.assumed {
            if !defaulted.contains(&f) {
                defaulted.push(f);
            }
        }
        Ok(BpxImport {
            params: self.p,
            unknown_fields: self.unknown,
            defaulted_fields: defaulted,
            approximated_fields: self.approximated,
        })
    }
}
