//! BPX (Battery Parameter eXchange, <https://github.com/FaradayInstitution/BPX>) import and
//! export of a [`ParameterSet`].
//!
//! Export writes the BPX v0.5 layout (`Header`, `Parameterisation` with `Cell`,
//! `Electrolyte`, `Negative electrode`, `Positive electrode`, `Separator`, `User-defined`).
//! Import reads v0.4/v0.5 documents and also the v1.x layout, where the initial and ambient
//! temperatures, the initial electrolyte concentration, the initial state of charge and the
//! heat-transfer coefficient live in a top-level `State` section.
//!
//! # Mapping (BPX key -> our field)
//!
//! | BPX | ParameterSet |
//! |-----|--------------|
//! | Cell / Electrode area x Number of electrode pairs | `cell.electrode_height * cell.electrode_width` |
//! | Cell / Lower, Upper voltage cut-off, Nominal cell capacity | `cell.*` |
//! | Cell / Reference, Ambient, Initial temperature | `thermal.*` |
//! | Cell / External surface area, Volume | `thermal.cooling_area`, `thermal.cell_volume` |
//! | Cell / Density x Specific heat capacity (lumped) | the five volumetric heat capacities (see below) |
//! | Electrolyte / Initial concentration, Cation transference number | `electrolyte.*` |
//! | Electrolyte / Diffusivity, Conductivity (number, table or expression of c) | `electrolyte.diffusivity`, `.conductivity` |
//! | Electrolyte / Diffusivity, Conductivity activation energy | `electrolyte.activation_energy` (one for both) |
//! | Electrode / Thickness, Porosity, Particle radius, Maximum concentration | same |
//! | Electrode / Surface area per unit volume a | `active_fraction = a R / 3` |
//! | Electrode / Transport efficiency tau | `bruggeman_electrolyte = ln tau / ln porosity` |
//! | Electrode / Conductivity (effective) | `conductivity` (with `bruggeman_solid` = 0) |
//! | Electrode / Diffusivity (+ activation energy) | `diffusivity` (+ `diffusivity_activation_energy`) |
//! | Electrode / OCP (number, table or expression of stoichiometry) | `ocp` |
//! | Electrode / Entropic change coefficient | `ocp_entropic_change` |
//! | Electrode / Reaction rate constant k (+ activation energy) | `rate_constant = F k / (c_max sqrt(c_e0))` |
//! | Electrode / Minimum, Maximum stoichiometry + initial state of charge | `initial_concentration` |
//! | Separator / Thickness, Porosity, Transport efficiency | `separator.*` |
//!
//! The reaction rate follows PyBaMM's BPX importer: BPX defines
//! `j0 = F k sqrt((c_e/c_e0) (c_s/c_max) (1 - c_s/c_max))` with `c_e0` the initial
//! electrolyte concentration, our `j0 = m_ref sqrt(c_e c_s (c_max - c_s))`, so
//! `m_ref = F k / (c_max sqrt(c_e0))`. BPX kinetics are symmetric Butler-Volmer and its
//! electrode conductivity is already effective, so `charge_transfer_coefficient` = 0.5 and
//! `bruggeman_solid` = 0 unless the `User-defined` section says otherwise.
//!
//! The initial particle stoichiometries come from the windows and the initial state of charge
//! `s` (BPX v1 `State / Initial conditions / Initial state-of-charge`, or our user-defined
//! `cellstudio.initial_state_of_charge`; 1 when absent, as in PyBaMM):
//! negative `min + s (max - min)`, positive `max - s (max - min)`.
//!
//! Fields of ours BPX lacks (material densities, packaging fractions, collectors, double-layer
//! capacitance, thermodynamic factor, ...) are exported under `User-defined` as
//! `cellstudio.<field path>` and read back from there (a standard key, such as the v1
//! heat-transfer coefficient, wins over a user-defined copy, which is then reported unused);
//! absent, they take the Chen 2020 value and are listed in [`BpxImport::defaulted_fields`].
//! Optional BPX values that are absent take the BPX meaning instead: activation energies and
//! the entropic change 0, the ambient temperature the reference temperature, the initial
//! temperature the ambient one, the cell volume the electrode stack volume with the Chen 2020
//! packaging allowance; these are listed as defaulted too. With a lumped `Density` and
//! `Specific heat capacity`, the per-layer volumetric heat capacities (user-defined, else all
//! equal) are scaled so their thickness-weighted mean, the one our lumped thermal model uses,
//! equals `density * heat capacity`.
//!
//! Expressions (BPX `Function`: Python syntax in `x` with `+ - * / **`, parentheses and
//! `exp`, `tanh`, `cosh`, plus `sinh`, `log`, `sqrt`) are parsed and evaluated here. A
//! constant expression becomes a number; otherwise a function of one variable is sampled into
//! a table (adaptively, to 1e-5 V for OCPs and 1e-4 relative for the electrolyte), and a
//! stoichiometry-dependent particle diffusivity or entropic change, scalars here, is averaged
//! over the stoichiometry window (geometric / arithmetic mean). Such lossy conversions are
//! listed in [`BpxImport::approximated_fields`].

use std::collections::{BTreeMap, BTreeSet};

use serde_json::{Map, Value, json};

use super::chen2020::chen2020;
use super::function::{Function1D, interpolate};
use super::set::{FARADAY, ParameterSet};
use crate::error::Error;

/// Version written in the `Header` of exported documents.
pub const BPX_VERSION: f64 = 0.5;
/// Prefix of our own keys in the `User-defined` section.
pub const USER_PREFIX: &str = "cellstudio.";
/// User-defined key of the initial state of charge (BPX v0.x has none).
const SOC_KEY: &str = "cellstudio.initial_state_of_charge";

/// Concentration range (mol/m^3) over which electrolyte functions are tabulated.
const ELECTROLYTE_RANGE: (f64, f64) = (0.0, 4000.0);
/// Absolute tolerance (V) of a tabulated OCP.
const OCP_TOLERANCE: f64 = 1e-5;
/// Tolerance of a tabulated electrolyte property, relative to its largest value.
const ELECTROLYTE_TOLERANCE: f64 = 1e-4;

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

mod keys {
    pub const HEADER: &str = "Header";
    pub const PARAMETERISATION: &str = "Parameterisation";
    pub const CELL: &str = "Cell";
    pub const ELECTROLYTE: &str = "Electrolyte";
    pub const NEGATIVE: &str = "Negative electrode";
    pub const POSITIVE: &str = "Positive electrode";
    pub const SEPARATOR: &str = "Separator";
    pub const USER_DEFINED: &str = "User-defined";
    pub const STATE: &str = "State";
    pub const INITIAL_CONDITIONS: &str = "Initial conditions";
    pub const THERMAL_ENVIRONMENT: &str = "Thermal environment";
    pub const VALIDATION: &str = "Validation";

    pub const AREA: &str = "Electrode area [m2]";
    pub const PAIRS: &str = "Number of electrode pairs connected in parallel to make a cell";
    pub const EXTERNAL_AREA: &str = "External surface area [m2]";
    pub const VOLUME: &str = "Volume [m3]";
    pub const LOWER_CUTOFF: &str = "Lower voltage cut-off [V]";
    pub const UPPER_CUTOFF: &str = "Upper voltage cut-off [V]";
    pub const CAPACITY: &str = "Nominal cell capacity [A.h]";
    pub const AMBIENT_T: &str = "Ambient temperature [K]";
    pub const INITIAL_T: &str = "Initial temperature [K]";
    pub const REFERENCE_T: &str = "Reference temperature [K]";
    pub const DENSITY: &str = "Density [kg.m-3]";
    pub const HEAT_CAPACITY: &str = "Specific heat capacity [J.K-1.kg-1]";
    pub const HEAT_TRANSFER: &str = "Heat transfer coefficient [W.m-2.K-1]";
    pub const SOC: &str = "Initial state-of-charge";

    pub const ELECTROLYTE_C0: &str = "Initial concentration [mol.m-3]";
    pub const ELECTROLYTE_C0_V1: &str = "Initial electrolyte concentration [mol.m-3]";
    pub const TRANSFERENCE: &str = "Cation transference number";
    pub const DIFFUSIVITY: &str = "Diffusivity [m2.s-1]";
    pub const DIFFUSIVITY_EA: &str = "Diffusivity activation energy [J.mol-1]";
    pub const CONDUCTIVITY: &str = "Conductivity [S.m-1]";
    pub const CONDUCTIVITY_EA: &str = "Conductivity activation energy [J.mol-1]";

    pub const THICKNESS: &str = "Thickness [m]";
    pub const POROSITY: &str = "Porosity";
    pub const TRANSPORT_EFFICIENCY: &str = "Transport efficiency";
    pub const RADIUS: &str = "Particle radius [m]";
    pub const SURFACE_AREA: &str = "Surface area per unit volume [m-1]";
    pub const MAX_CONCENTRATION: &str = "Maximum concentration [mol.m-3]";
    pub const MIN_STO: &str = "Minimum stoichiometry";
    pub const MAX_STO: &str = "Maximum stoichiometry";
    pub const OCP: &str = "OCP [V]";
    pub const ENTROPIC: &str = "Entropic change coefficient [V.K-1]";
    pub const RATE: &str = "Reaction rate constant [mol.m-2.s-1]";
    pub const RATE_EA: &str = "Reaction rate constant activation energy [J.mol-1]";
    pub const PARTICLE: &str = "Particle";
}

/// Our scalar fields with no BPX equivalent, exported as `cellstudio.<path>` user-defined keys.
const USER_DEFINED_FIELDS: &[&str] = &[
    "negative.bruggeman_solid",
    "negative.charge_transfer_coefficient",
    "negative.active_density",
    "negative.inactive_density",
    "negative.volumetric_heat_capacity",
    "negative.double_layer_capacitance",
    "positive.bruggeman_solid",
    "positive.charge_transfer_coefficient",
    "positive.active_density",
    "positive.inactive_density",
    "positive.volumetric_heat_capacity",
    "positive.double_layer_capacitance",
    "separator.solid_density",
    "separator.volumetric_heat_capacity",
    "electrolyte.thermodynamic_factor",
    "electrolyte.density",
    "cell.electrode_height",
    "cell.negative_collector_thickness",
    "cell.positive_collector_thickness",
    "cell.negative_collector_density",
    "cell.positive_collector_density",
    "cell.packaging_mass_fraction",
    "cell.packaging_volume_fraction",
    "cell.contact_resistance",
    "cell.rc_resistance",
    "cell.rc_capacitance",
    "cell.hysteresis_voltage",
    "cell.hysteresis_rate",
    "cell.hysteresis_initial",
    "thermal.heat_transfer_coefficient",
    "thermal.negative_collector_heat_capacity",
    "thermal.positive_collector_heat_capacity",
];

const ELECTRODE_FIELDS: &[&str] = &[
    "thickness",
    "particle_radius",
    "active_fraction",
    "porosity",
    "bruggeman_electrolyte",
    "bruggeman_solid",
    "conductivity",
    "max_concentration",
    "initial_concentration",
    "diffusivity",
    "diffusivity_activation_energy",
    "ocp_entropic_change",
    "rate_constant",
    "rate_activation_energy",
    "charge_transfer_coefficient",
    "active_density",
    "inactive_density",
    "volumetric_heat_capacity",
    "double_layer_capacitance",
];

const OTHER_FIELDS: &[&str] = &[
    "separator.thickness",
    "separator.porosity",
    "separator.bruggeman",
    "separator.solid_density",
    "separator.volumetric_heat_capacity",
    "electrolyte.initial_concentration",
    "electrolyte.transference_number",
    "electrolyte.thermodynamic_factor",
    "electrolyte.activation_energy",
    "electrolyte.density",
    "cell.electrode_height",
    "cell.electrode_width",
    "cell.negative_collector_thickness",
    "cell.positive_collector_thickness",
    "cell.negative_collector_density",
    "cell.positive_collector_density",
    "cell.packaging_mass_fraction",
    "cell.packaging_volume_fraction",
    "cell.nominal_capacity",
    "cell.lower_cutoff",
    "cell.upper_cutoff",
    "cell.contact_resistance",
    "cell.rc_resistance",
    "cell.rc_capacitance",
    "cell.hysteresis_voltage",
    "cell.hysteresis_rate",
    "cell.hysteresis_initial",
    "thermal.reference_temperature",
    "thermal.ambient_temperature",
    "thermal.initial_temperature",
    "thermal.heat_transfer_coefficient",
    "thermal.cooling_area",
    "thermal.cell_volume",
    "thermal.negative_collector_heat_capacity",
    "thermal.positive_collector_heat_capacity",
];

/// Every scalar field of a [`ParameterSet`] as a dotted path.
fn scalar_paths() -> Vec<String> {
    ["negative", "positive"]
        .iter()
        .flat_map(|side| ELECTRODE_FIELDS.iter().map(move |f| format!("{side}.{f}")))
        .chain(OTHER_FIELDS.iter().map(|f| f.to_string()))
        .collect()
}

/// The five layers of the lumped heat capacity: (thickness path, heat-capacity path).
const HEAT_LAYERS: [(&str, &str); 5] = [
    ("negative.thickness", "negative.volumetric_heat_capacity"),
    ("separator.thickness", "separator.volumetric_heat_capacity"),
    ("positive.thickness", "positive.volumetric_heat_capacity"),
    ("cell.negative_collector_thickness", "thermal.negative_collector_heat_capacity"),
    ("cell.positive_collector_thickness", "thermal.positive_collector_heat_capacity"),
];

/// Thickness-weighted mean volumetric heat capacity (J/(m^3 K)) of the stack, as the lumped
/// thermal model uses it.
fn mean_heat_capacity(p: &ParameterSet) -> Result<f64, Error> {
    let mut total = 0.0;
    let mut weighted = 0.0;
    for (t, c) in HEAT_LAYERS {
        let t = p.get(t)?;
        total += t;
        weighted += t * p.get(c)?;
    }
    Ok(weighted / total)
}

// ---------------------------------------------------------------------------------------------
// Import
// ---------------------------------------------------------------------------------------------

/// Reads a BPX JSON document (v0.4/v0.5, or v1.x) into a validated parameter set.
pub fn from_bpx_json(text: &str) -> Result<BpxImport, Error> {
    let doc: Value = serde_json::from_str(text)
        .map_err(|e| Error::Parse { path: "BPX JSON".into(), message: e.to_string() })?;
    Importer::new().run(&doc)
}

/// How a BPX number must lie.
#[derive(Clone, Copy)]
enum Check {
    Finite,
    Positive,
    NonNegative,
    /// (0, 1)
    OpenUnit,
    /// [0, 1]
    ClosedUnit,
    /// (0, 1]
    HalfOpenUnit,
}

impl Check {
    fn apply(self, path: &str, v: f64) -> Result<f64, Error> {
        let (ok, reason) = match self {
            Check::Finite => (true, "must be finite"),
            Check::Positive => (v > 0.0, "must be positive"),
            Check::NonNegative => (v >= 0.0, "must not be negative"),
            Check::OpenUnit => (v > 0.0 && v < 1.0, "must lie strictly between 0 and 1"),
            Check::ClosedUnit => ((0.0..=1.0).contains(&v), "must lie between 0 and 1"),
            Check::HalfOpenUnit => (v > 0.0 && v <= 1.0, "must lie in (0, 1]"),
        };
        if ok && v.is_finite() { Ok(v) } else { Err(Error::invalid(path, v, reason)) }
    }
}

fn describe(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => format!("the boolean {b}"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) => format!("the string {s:?}"),
        Value::Array(_) => "an array".into(),
        Value::Object(_) => "an object".into(),
    }
}

fn type_error(path: &str, expected: &str, v: &Value) -> Error {
    Error::InvalidSetting {
        field: path.into(),
        reason: format!("expected {expected}, found {}", describe(v)),
    }
}

fn missing(path: &str) -> Error {
    Error::InvalidSetting { field: path.into(), reason: "required BPX key is missing".into() }
}

/// A JSON number checked against `check`; strings (expressions) are refused.
fn number(path: &str, v: &Value, check: Check) -> Result<f64, Error> {
    match v.as_f64() {
        Some(x) if v.is_number() => check.apply(path, x),
        _ => Err(type_error(path, "a number", v)),
    }
}

/// A BPX `FloatFunctionTable` value.
enum Bpx1D {
    Number(f64),
    Table { x: Vec<f64>, y: Vec<f64> },
    Expression(Expr),
}

impl Bpx1D {
    fn parse(path: &str, v: &Value) -> Result<Self, Error> {
        match v {
            Value::Number(_) => Ok(Bpx1D::Number(number(path, v, Check::Finite)?)),
            Value::String(s) => {
                Expr::parse(s).map(Bpx1D::Expression).map_err(|reason| Error::InvalidSetting {
                    field: path.into(),
                    reason: format!("cannot parse the expression {s:?}: {reason}"),
                })
            }
            Value::Object(map) => {
                if let Some(k) = map.keys().find(|k| *k != "x" && *k != "y") {
                    return Err(Error::InvalidSetting {
                        field: path.into(),
                        reason: format!("a table has only the keys \"x\" and \"y\", found {k:?}"),
                    });
                }
                let list = |name: &str| -> Result<Vec<f64>, Error> {
                    let p = format!("{path}/{name}");
                    let arr = map.get(name).ok_or_else(|| missing(&p))?;
                    let arr = arr.as_array().ok_or_else(|| type_error(&p, "an array of numbers", arr))?;
                    arr.iter().map(|v| number(&p, v, Check::Finite)).collect()
                };
                let (x, y) = (list("x")?, list("y")?);
                if x.len() != y.len() || x.len() < 2 {
                    return Err(Error::InvalidSetting {
                        field: path.into(),
                        reason: format!(
                            "a table needs at least 2 points and x, y of equal length (x: {}, y: {})",
                            x.len(),
                            y.len()
                        ),
                    });
                }
                // Sorted by x as PyBaMM does; repeated x are an error.
                let mut pts: Vec<(f64, f64)> = x.into_iter().zip(y).collect();
                pts.sort_by(|a, b| a.0.total_cmp(&b.0));
                if let Some(w) = pts.windows(2).find(|w| w[1].0 <= w[0].0) {
                    return Err(Error::invalid(
                        format!("{path}/x"),
                        w[1].0,
                        "table x values must be distinct",
                    ));
                }
                Ok(Bpx1D::Table {
                    x: pts.iter().map(|p| p.0).collect(),
                    y: pts.iter().map(|p| p.1).collect(),
                })
            }
            _ => Err(type_error(path, "a number, an expression string or an {\"x\", \"y\"} table", v)),
        }
    }

    /// The value if it does not depend on x.
    fn constant(&self, path: &str) -> Result<Option<f64>, Error> {
        match self {
            Bpx1D::Number(v) => Ok(Some(*v)),
            Bpx1D::Expression(e) if !e.uses_x() => Check::Finite.apply(path, e.eval(0.0)).map(Some),
            _ => Ok(None),
        }
    }

    fn eval(&self, x: f64) -> f64 {
        match self {
            Bpx1D::Number(v) => *v,
            Bpx1D::Table { x: xs, y: ys } => interpolate(xs, ys, x),
            Bpx1D::Expression(e) => e.eval(x),
        }
    }

    /// A function of one variable; expressions are sampled over `range`.
    fn to_function(
        &self,
        path: &str,
        range: (f64, f64),
        tolerance: Tolerance,
        approximated: &mut Vec<String>,
    ) -> Result<Function1D, Error> {
        if let Some(value) = self.constant(path)? {
            return Ok(Function1D::Constant { value });
        }
        match self {
            Bpx1D::Table { x, y } => Ok(Function1D::Table { x: x.clone(), y: y.clone() }),
            _ => {
                let (x, y) = sample(&|x| self.eval(x), range, tolerance);
                if x.len() < 2 {
                    return Err(Error::InvalidSetting {
                        field: path.into(),
                        reason: format!("the expression is not finite over [{}, {}]", range.0, range.1),
                    });
                }
                approximated.push(path.into());
                Ok(Function1D::Table { x, y })
            }
        }
    }

    /// A scalar: a function of stoichiometry is averaged over the window `[lo, hi]`.
    fn to_scalar(
        &self,
        path: &str,
        window: (f64, f64),
        geometric: bool,
        approximated: &mut Vec<String>,
    ) -> Result<f64, Error> {
        if let Some(v) = self.constant(path)? {
            return Ok(v);
        }
        let n = 101;
        let samples: Vec<f64> =
            (0..n).map(|i| self.eval(window.0 + (window.1 - window.0) * i as f64 / (n - 1) as f64)).collect();
        let mean = if geometric {
            if let Some(v) = samples.iter().find(|v| !(**v > 0.0 && v.is_finite())) {
                return Err(Error::invalid(path, *v, "must be positive over the stoichiometry window"));
            }
            (samples.iter().map(|v| v.ln()).sum::<f64>() / n as f64).exp()
        } else {
            samples.iter().sum::<f64>() / n as f64
        };
        approximated.push(path.into());
        Check::Finite.apply(path, mean)
    }
}

/// One JSON object of the document, remembering which keys were read.
struct Section<'a> {
    path: String,
    map: &'a Map<String, Value>,
    used: BTreeSet<&'a str>,
}

impl<'a> Section<'a> {
    fn new(path: String, v: &'a Value) -> Result<Self, Error> {
        match v {
            Value::Object(map) => Ok(Section { path, map, used: BTreeSet::new() }),
            _ => Err(type_error(if path.is_empty() { "BPX document" } else { &path }, "an object", v)),
        }
    }

    fn key_path(&self, key: &str) -> String {
        if self.path.is_empty() { key.to_string() } else { format!("{}/{key}", self.path) }
    }

    /// The value of `key`, marked as read; `null` counts as absent.
    fn take(&mut self, key: &str) -> Option<&'a Value> {
        let (k, v) = self.map.get_key_value(key)?;
        self.used.insert(k.as_str());
        (!v.is_null()).then_some(v)
    }

    fn opt_num(&mut self, key: &str, check: Check) -> Result<Option<f64>, Error> {
        let path = self.key_path(key);
        self.take(key).map(|v| number(&path, v, check)).transpose()
    }

    fn num(&mut self, key: &str, check: Check) -> Result<f64, Error> {
        self.opt_num(key, check)?.ok_or_else(|| missing(&self.key_path(key)))
    }

    fn func(&mut self, key: &str) -> Result<Bpx1D, Error> {
        self.opt_func(key)?.ok_or_else(|| missing(&self.key_path(key)))
    }

    fn opt_func(&mut self, key: &str) -> Result<Option<Bpx1D>, Error> {
        let path = self.key_path(key);
        self.take(key).map(|v| Bpx1D::parse(&path, v)).transpose()
    }

    fn opt_section(&mut self, key: &str) -> Result<Option<Section<'a>>, Error> {
        let path = self.key_path(key);
        self.take(key).map(|v| Section::new(path, v)).transpose()
    }

    fn section(&mut self, key: &str) -> Result<Section<'a>, Error> {
        self.opt_section(key)?.ok_or_else(|| missing(&self.key_path(key)))
    }

    /// Lists the keys never read.
    fn finish(self, unknown: &mut Vec<String>) {
        for k in self.map.keys() {
            if !self.used.contains(k.as_str()) {
                unknown.push(self.key_path(k));
            }
        }
    }
}

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

    fn run(mut self, doc: &Value) -> Result<BpxImport, Error> {
        let mut root = Section::new(String::new(), doc)?;

        // Header.
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

        let mut par = root.section(keys::PARAMETERISATION)?;
        let mut cell = par.section(keys::CELL)?;
        let mut electrolyte = par.section(keys::ELECTROLYTE)?;
        let mut negative = par.section(keys::NEGATIVE)?;
        let mut positive = par.section(keys::POSITIVE)?;
        let mut separator = par.section(keys::SEPARATOR)?;
        let user = par.opt_section(keys::USER_DEFINED)?;
        let mut state = root.opt_section(keys::STATE)?;
        let mut initial = match &mut state {
            Some(s) => s.opt_section(keys::INITIAL_CONDITIONS)?,
            None => None,
        };
        let mut environment = match &mut state {
            Some(s) => s.opt_section(keys::THERMAL_ENVIRONMENT)?,
            None => None,
        };
        if let Some(v) = root.take(keys::VALIDATION) {
            match v.as_object() {
                Some(sets) => self.unknown.extend(sets.keys().map(|k| format!("{}/{k}", keys::VALIDATION))),
                None => self.unknown.push(keys::VALIDATION.into()),
            }
        }

        // User-defined: our own keys; anything else is unknown.
        let mut user_values: BTreeMap<&str, (f64, String)> = BTreeMap::new();
        let mut user_soc = None;
        if let Some(user) = &user {
            for (k, v) in user.map {
                let path = user.key_path(k);
                if k == SOC_KEY {
                    user_soc = Some((number(&path, v, Check::ClosedUnit)?, path));
                } else if let Some(field) =
                    k.strip_prefix(USER_PREFIX).and_then(|f| USER_DEFINED_FIELDS.iter().find(|u| **u == f))
                {
                    user_values.insert(field, (number(&path, v, Check::Finite)?, path));
                } else {
                    self.unknown.push(path);
                }
            }
        }

        // Cell and thermal environment.
        let n_pairs_path = cell.key_path(keys::PAIRS);
        let n_pairs = cell.num(keys::PAIRS, Check::Positive)?;
        if n_pairs.fract() != 0.0 {
            return Err(Error::invalid(n_pairs_path, n_pairs, "must be a whole number"));
        }
        let area = cell.num(keys::AREA, Check::Positive)? * n_pairs;
        let area_source = format!("{} x {}", cell.key_path(keys::AREA), n_pairs_path);
        self.copy(&mut cell, keys::LOWER_CUTOFF, Check::Positive, "cell.lower_cutoff")?;
        self.copy(&mut cell, keys::UPPER_CUTOFF, Check::Positive, "cell.upper_cutoff")?;
        self.copy(&mut cell, keys::CAPACITY, Check::Positive, "cell.nominal_capacity")?;
        if let Some(v) = cell.opt_num(keys::EXTERNAL_AREA, Check::NonNegative)? {
            self.set("thermal.cooling_area", v, cell.key_path(keys::EXTERNAL_AREA))?;
        }
        if let Some(v) = cell.opt_num(keys::VOLUME, Check::Positive)? {
            self.set("thermal.cell_volume", v, cell.key_path(keys::VOLUME))?;
        }
        let t_ref = match cell.opt_num(keys::REFERENCE_T, Check::Positive)? {
            Some(t) => {
                self.set("thermal.reference_temperature", t, cell.key_path(keys::REFERENCE_T))?;
                t
            }
            None => self.p.thermal.reference_temperature,
        };
        // v1 keeps the temperatures in State, v0 in Cell; State wins, an unused Cell value
        // is reported.
        let ambient = first_of(
            &mut environment,
            keys::AMBIENT_T,
            &mut cell,
            keys::AMBIENT_T,
            Check::Positive,
            &mut self.unknown,
        )?;
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
        match first_of(
            &mut initial,
            keys::INITIAL_T,
            &mut cell,
            keys::INITIAL_T,
            Check::Positive,
            &mut self.unknown,
        )? {
            Some((t, src)) => self.set("thermal.initial_temperature", t, src)?,
            None => self.p.thermal.initial_temperature = ambient,
        }
        if let Some(env) = &mut environment
            && let Some(h) = env.opt_num(keys::HEAT_TRANSFER, Check::NonNegative)?
        {
            self.set("thermal.heat_transfer_coefficient", h, env.key_path(keys::HEAT_TRANSFER))?;
        }
        let density = cell.opt_num(keys::DENSITY, Check::Positive)?;
        let heat_capacity = cell.opt_num(keys::HEAT_CAPACITY, Check::Positive)?;
        let lumped = match (density, heat_capacity) {
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
        };

        // Electrolyte.
        let ce0 = first_of(
            &mut initial,
            keys::ELECTROLYTE_C0_V1,
            &mut electrolyte,
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
        self.copy(&mut electrolyte, keys::TRANSFERENCE, Check::OpenUnit, "electrolyte.transference_number")?;
        for (key, slot) in [(keys::DIFFUSIVITY, 0), (keys::CONDUCTIVITY, 1)] {
            let path = electrolyte.key_path(key);
            let f = electrolyte.func(key)?;
            let tol = Tolerance::Relative(ELECTROLYTE_TOLERANCE);
            let f = f.to_function(&path, ELECTROLYTE_RANGE, tol, &mut self.approximated)?;
            if slot == 0 {
                self.p.electrolyte.diffusivity = f;
                self.origin.insert("electrolyte.diffusivity".into(), path);
            } else {
                self.p.electrolyte.conductivity = f;
                self.origin.insert("electrolyte.conductivity".into(), path);
            }
        }
        let ea_d = electrolyte.opt_num(keys::DIFFUSIVITY_EA, Check::NonNegative)?;
        let ea_k = electrolyte.opt_num(keys::CONDUCTIVITY_EA, Check::NonNegative)?;
        let (ea_d_path, ea_k_path) =
            (electrolyte.key_path(keys::DIFFUSIVITY_EA), electrolyte.key_path(keys::CONDUCTIVITY_EA));
        match (ea_d, ea_k) {
            (Some(d), Some(k)) => {
                // One activation energy for both: the conductivity's, which dominates the
                // voltage; a different diffusivity value is reported as approximated.
                if (d - k).abs() > 1e-12 * k.abs().max(1.0) {
                    self.approximated.push(ea_d_path);
                }
                self.set("electrolyte.activation_energy", k, ea_k_path)?;
            }
            (Some(d), None) => self.set("electrolyte.activation_energy", d, ea_d_path)?,
            (None, Some(k)) => self.set("electrolyte.activation_energy", k, ea_k_path)?,
            (None, None) => self.p.electrolyte.activation_energy = 0.0,
        }

        // Electrodes and separator.
        let window_n = self.electrode(&mut negative, "negative", ce0)?;
        let window_p = self.electrode(&mut positive, "positive", ce0)?;
        self.copy(&mut separator, keys::THICKNESS, Check::Positive, "separator.thickness")?;
        let eps = self.copy(&mut separator, keys::POROSITY, Check::OpenUnit, "separator.porosity")?;
        let tau = separator.num(keys::TRANSPORT_EFFICIENCY, Check::HalfOpenUnit)?;
        self.set("separator.bruggeman", tau.ln() / eps.ln(), separator.key_path(keys::TRANSPORT_EFFICIENCY))?;

        // Our own fields from User-defined, unless a standard key (v1 State) already set them;
        // then the user-defined value goes unused and is reported.
        for (field, (v, src)) in &user_values {
            if self.origin.get(*field).is_some_and(|o| !o.starts_with("BPX convention")) {
                self.unknown.push(src.clone());
            } else if !field.ends_with("volumetric_heat_capacity")
                && !field.ends_with("collector_heat_capacity")
            {
                self.set(field, *v, src.clone())?;
            }
        }
        // Conductivity: BPX's is effective, ours is scaled by (1 - porosity)^bruggeman_solid.
        for side in ["negative", "positive"] {
            let b = self.p.get(&format!("{side}.bruggeman_solid"))?;
            if b != 0.0 {
                let e = if side == "negative" { &mut self.p.negative } else { &mut self.p.positive };
                e.conductivity /= (1.0 - e.porosity).powf(b);
            }
        }
        // Plate: the BPX area, split with the user-defined (else Chen 2020) height.
        let height = self.p.cell.electrode_height;
        self.set("cell.electrode_width", area / height, area_source)?;
        // Heat capacities: user-defined per layer, else the lumped value; scaled so that the
        // stack mean equals the lumped value when there is one.
        for (_, field) in HEAT_LAYERS {
            if let Some((v, src)) = user_values.get(field) {
                self.set(field, *v, src.clone())?;
            } else if let Some((c, src)) = &lumped {
                self.set(field, *c, src.clone())?;
            }
        }
        if let Some((c, src)) = &lumped {
            let scale = c / mean_heat_capacity(&self.p)?;
            for (_, field) in HEAT_LAYERS {
                let v = self.p.get(field)?;
                let source = match user_values.get(field) {
                    Some((_, u)) => format!("{u} scaled to {src}"),
                    None => src.clone(),
                };
                self.set(field, v * scale, source)?;
            }
        }

        // Initial stoichiometries from the windows and the state of charge.
        let soc = match initial
            .as_mut()
            .map(|ic| (ic.opt_num(keys::SOC, Check::ClosedUnit), ic.key_path(keys::SOC)))
        {
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
        self.set("positive.initial_concentration", c_p, src(keys::POSITIVE))?;

        // Without a BPX volume, the stack volume with the packaging allowance.
        if !self.origin.contains_key("thermal.cell_volume") {
            self.p.thermal.cell_volume = self.p.budget().volume;
        }

        for s in [cell, electrolyte, negative, positive, separator] {
            s.finish(&mut self.unknown);
        }
        for s in [initial, environment].into_iter().flatten() {
            s.finish(&mut self.unknown);
        }
        if let Some(s) = state {
            s.finish(&mut self.unknown);
        }
        par.finish(&mut self.unknown);
        root.finish(&mut self.unknown);

        self.p.validate().map_err(|e| self.relabel(e))?;

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
        if let Some(ea) = sec.opt_num(keys::DIFFUSIVITY_EA, Check::NonNegative)? {
            self.set(&f("diffusivity_activation_energy"), ea, sec.key_path(keys::DIFFUSIVITY_EA))?;
        } else {
            self.p.set(&f("diffusivity_activation_energy"), 0.0)?;
        }

        let path = sec.key_path(keys::OCP);
        let ocp = sec.func(keys::OCP)?.to_function(
            &path,
            (0.0, 1.0),
            Tolerance::Absolute(OCP_TOLERANCE),
            &mut self.approximated,
        )?;
        if side == "negative" {
            self.p.negative.ocp = ocp
        } else {
            self.p.positive.ocp = ocp
        }
        self.origin.insert(f("ocp"), path);
        match sec.opt_func(keys::ENTROPIC)? {
            Some(e) => {
                let path = sec.key_path(keys::ENTROPIC);
                let v = e.to_scalar(&path, (lo, hi), false, &mut self.approximated)?;
                self.set(&f("ocp_entropic_change"), v, path)?;
            }
            None => self.p.set(&f("ocp_entropic_change"), 0.0)?,
        }

        let k = sec.num(keys::RATE, Check::Positive)?;
        self.set(&f("rate_constant"), FARADAY * k / (c_max * ce0.sqrt()), sec.key_path(keys::RATE))?;
        if let Some(ea) = sec.opt_num(keys::RATE_EA, Check::NonNegative)? {
            self.set(&f("rate_activation_energy"), ea, sec.key_path(keys::RATE_EA))?;
        } else {
            self.p.set(&f("rate_activation_energy"), 0.0)?;
        }
        Ok((lo, hi))
    }

    /// Names the BPX key behind a failing field of ours.
    fn relabel(&self, e: Error) -> Error {
        let label = |field: String| match self.origin.get(&field) {
            Some(src) => format!("{src}` -> `{field}"),
            None => field,
        };
        match e {
            Error::InvalidParameter { field, value, reason } => {
                Error::InvalidParameter { field: label(field), value, reason }
            }
            Error::InvalidSetting { field, reason } => Error::InvalidSetting { field: label(field), reason },
            other => other,
        }
    }
}

/// Reads `key` from the preferred (v1 `State`) section, else from the v0 section; a value
/// present in both is taken from the preferred one and the other is reported unknown.
fn first_of(
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

// ---------------------------------------------------------------------------------------------
// Export
// ---------------------------------------------------------------------------------------------

/// Writes `p` as a BPX v0.5 JSON document (model "DFN").
///
/// Built-in functions are sampled into `{"x", "y"}` tables (OCPs over stoichiometry [0, 1],
/// electrolyte properties over 0..4000 mol/m^3). The stoichiometry windows are those at which
/// the open-circuit voltage meets the cut-offs with the lithium inventory of the initial state;
/// the initial state of charge and every field without a BPX equivalent go under
/// `User-defined` as `cellstudio.*`, so that [`from_bpx_json`] restores every scalar.
pub fn to_bpx_json(p: &ParameterSet) -> Result<String, Error> {
    p.validate()?;
    for (field, v) in [("electrolyte.diffusivity_factor", p.electrolyte.diffusivity_factor), ("electrolyte.conductivity_factor", p.electrolyte.conductivity_factor)] {
        if v != 1.0 {
            return Err(Error::invalid(field, v, "BPX has no transport factor: export the set with the factor at 1 (scale the function instead)"));
        }
    }
    let ce0 = p.electrolyte.initial_concentration;
    let windows = stoichiometry_windows(p)?;
    let c = &p.cell;
    let t = &p.thermal;
    let budget = p.budget();
    let density = budget.mass / budget.volume;
    let heat_capacity = mean_heat_capacity(p)? / density;

    let cell = json!({
        keys::AREA: num("cell area", c.area())?,
        keys::PAIRS: 1,
        keys::EXTERNAL_AREA: num("thermal.cooling_area", t.cooling_area)?,
        keys::VOLUME: num("thermal.cell_volume", t.cell_volume)?,
        keys::LOWER_CUTOFF: num("cell.lower_cutoff", c.lower_cutoff)?,
        keys::UPPER_CUTOFF: num("cell.upper_cutoff", c.upper_cutoff)?,
        keys::CAPACITY: num("cell.nominal_capacity", c.nominal_capacity)?,
        keys::AMBIENT_T: num("thermal.ambient_temperature", t.ambient_temperature)?,
        keys::INITIAL_T: num("thermal.initial_temperature", t.initial_temperature)?,
        keys::REFERENCE_T: num("thermal.reference_temperature", t.reference_temperature)?,
        keys::DENSITY: num("cell density", density)?,
        keys::HEAT_CAPACITY: num("cell specific heat capacity", heat_capacity)?,
    });
    let e = &p.electrolyte;
    let electrolyte_tol = Tolerance::Relative(ELECTROLYTE_TOLERANCE);
    let electrolyte = json!({
        keys::ELECTROLYTE_C0: num("electrolyte.initial_concentration", ce0)?,
        keys::TRANSFERENCE: num("electrolyte.transference_number", e.transference_number)?,
        keys::DIFFUSIVITY: function_value(&e.diffusivity, ELECTROLYTE_RANGE, electrolyte_tol),
        keys::DIFFUSIVITY_EA: num("electrolyte.activation_energy", e.activation_energy)?,
        keys::CONDUCTIVITY: function_value(&e.conductivity, ELECTROLYTE_RANGE, electrolyte_tol),
        keys::CONDUCTIVITY_EA: num("electrolyte.activation_energy", e.activation_energy)?,
    });
    let electrode = |side: &str, window: (f64, f64)| -> Result<Value, Error> {
        let el = if side == "negative" { &p.negative } else { &p.positive };
        let f = |name: &str| format!("{side}.{name}");
        Ok(json!({
            keys::THICKNESS: num(&f("thickness"), el.thickness)?,
            keys::RADIUS: num(&f("particle_radius"), el.particle_radius)?,
            keys::SURFACE_AREA: num(&f("active_fraction"), el.surface_area_density())?,
            keys::POROSITY: num(&f("porosity"), el.porosity)?,
            keys::TRANSPORT_EFFICIENCY: num(&f("bruggeman_electrolyte"), el.porosity.powf(el.bruggeman_electrolyte))?,
            keys::CONDUCTIVITY: num(&f("conductivity"), el.conductivity * (1.0 - el.porosity).powf(el.bruggeman_solid))?,
            keys::MAX_CONCENTRATION: num(&f("max_concentration"), el.max_concentration)?,
            keys::MIN_STO: num(&f("initial_concentration"), window.0)?,
            keys::MAX_STO: num(&f("initial_concentration"), window.1)?,
            keys::DIFFUSIVITY: num(&f("diffusivity"), el.diffusivity)?,
            keys::DIFFUSIVITY_EA: num(&f("diffusivity_activation_energy"), el.diffusivity_activation_energy)?,
            keys::OCP: function_value(&el.ocp, (0.0, 1.0), Tolerance::Absolute(OCP_TOLERANCE)),
            keys::ENTROPIC: num(&f("ocp_entropic_change"), el.ocp_entropic_change)?,
            keys::RATE: num(&f("rate_constant"), el.rate_constant * el.max_concentration * ce0.sqrt() / FARADAY)?,
            keys::RATE_EA: num(&f("rate_activation_energy"), el.rate_activation_energy)?,
        }))
    };
    let s = &p.separator;
    let separator = json!({
        keys::THICKNESS: num("separator.thickness", s.thickness)?,
        keys::POROSITY: num("separator.porosity", s.porosity)?,
        keys::TRANSPORT_EFFICIENCY: num("separator.bruggeman", s.porosity.powf(s.bruggeman))?,
    });
    let mut user = Map::new();
    for field in USER_DEFINED_FIELDS {
        user.insert(format!("{USER_PREFIX}{field}"), num(field, p.get(field)?)?);
    }
    user.insert(SOC_KEY.into(), num("initial state of charge", windows.soc)?);

    let doc = json!({
        keys::HEADER: {
            "BPX": BPX_VERSION,
            "Title": p.name,
            "Model": "DFN",
        },
        keys::PARAMETERISATION: {
            keys::CELL: cell,
            keys::ELECTROLYTE: electrolyte,
            keys::NEGATIVE: electrode("negative", windows.negative)?,
            keys::POSITIVE: electrode("positive", windows.positive)?,
            keys::SEPARATOR: separator,
            keys::USER_DEFINED: user,
        },
    });
    serde_json::to_string_pretty(&doc)
        .map_err(|e| Error::Parse { path: "BPX JSON".into(), message: e.to_string() })
}

fn num(field: &str, v: f64) -> Result<Value, Error> {
    if v.is_finite() {
        Ok(json!(v))
    } else {
        Err(Error::invalid(field, v, "must be finite to export to BPX"))
    }
}

fn function_value(f: &Function1D, range: (f64, f64), tolerance: Tolerance) -> Value {
    match f {
        Function1D::Constant { value } => json!(value),
        Function1D::Table { x, y } => json!({ "x": x, "y": y }),
        _ => {
            let (x, y) = sample(&|v| f.eval(v), range, tolerance);
            json!({ "x": x, "y": y })
        }
    }
}

/// Stoichiometry windows of a cell and the state of charge of its initial state.
#[derive(Clone, Copy, Debug)]
pub struct StoichiometryWindows {
    /// Negative (min, max) stoichiometry: at the lower and the upper cut-off.
    pub negative: (f64, f64),
    /// Positive (min, max) stoichiometry: at the upper and the lower cut-off.
    pub positive: (f64, f64),
    /// State of charge of the initial particle concentrations within the windows.
    pub soc: f64,
}

/// The particle stoichiometries at which the open-circuit voltage equals the voltage cut-offs
/// with the cyclable lithium of the initial state (clamped to [0, 1] where a cut-off is out of
/// reach), and the initial state of charge between them.
pub fn stoichiometry_windows(p: &ParameterSet) -> Result<StoichiometryWindows, Error> {
    let line = super::soc::LithiumLine::of(p);
    let solve = |v: f64| line.negative_at_ocv(p, v);
    let x_n_min = solve(p.cell.lower_cutoff);
    let x_n_max = solve(p.cell.upper_cutoff);
    if !(x_n_max > x_n_min) {
        return Err(Error::InvalidSetting {
            field: "cell.upper_cutoff".into(),
            reason: format!(
                "no stoichiometry window: the open-circuit voltage does not rise from {} V to {} V over the \
                 cyclable lithium of the initial state",
                p.cell.lower_cutoff, p.cell.upper_cutoff
            ),
        });
    }
    Ok(StoichiometryWindows {
        negative: (x_n_min, x_n_max),
        positive: (line.positive(x_n_max), line.positive(x_n_min)),
        soc: (line.x_n0 - x_n_min) / (x_n_max - x_n_min),
    })
}

// ---------------------------------------------------------------------------------------------
// Tabulation
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy)]
enum Tolerance {
    /// Absolute interpolation error.
    Absolute(f64),
    /// Interpolation error relative to the value, floored at 1e-3 of the largest |value|.
    Relative(f64),
}

/// Samples `f` over `range`: 101 uniform points, each interval bisected (up to 12 times)
/// until linear interpolation is within the tolerance at its quarter and mid points.
/// Non-finite values are left out.
fn sample(f: &dyn Fn(f64) -> f64, range: (f64, f64), tolerance: Tolerance) -> (Vec<f64>, Vec<f64>) {
    let n = 101;
    let (a, b) = range;
    let coarse: Vec<(f64, f64)> = (0..n)
        .map(|i| if i == n - 1 { b } else { a + (b - a) * i as f64 / (n - 1) as f64 })
        .map(|x| (x, f(x)))
        .filter(|(_, y)| y.is_finite())
        .collect();
    // Allowed error: abs + rel |value|.
    let tol = match tolerance {
        Tolerance::Absolute(t) => (t, 0.0),
        Tolerance::Relative(r) => (r * 1e-3 * coarse.iter().map(|p| p.1.abs()).fold(0.0, f64::max), r),
    };
    let mut out: Vec<(f64, f64)> = Vec::new();
    if let Some(first) = coarse.first() {
        out.push(*first);
    }
    for w in coarse.windows(2) {
        refine(f, w[0], w[1], 12, tol, &mut out);
        out.push(w[1]);
    }
    out.into_iter().unzip()
}

fn refine(
    f: &dyn Fn(f64) -> f64,
    p0: (f64, f64),
    p1: (f64, f64),
    depth: u32,
    tol: (f64, f64),
    out: &mut Vec<(f64, f64)>,
) {
    if depth == 0 {
        return;
    }
    let at = |w: f64| {
        let x = p0.0 + w * (p1.0 - p0.0);
        (x, f(x), p0.1 + w * (p1.1 - p0.1))
    };
    let probes = [at(0.25), at(0.5), at(0.75)];
    if probes.iter().any(|p| !p.1.is_finite()) {
        return;
    }
    if probes.iter().all(|p| (p.1 - p.2).abs() <= tol.0 + tol.1 * p.1.abs()) {
        return;
    }
    let mid = (probes[1].0, probes[1].1);
    refine(f, p0, mid, depth - 1, tol, out);
    out.push(mid);
    refine(f, mid, p1, depth - 1, tol, out);
}

// ---------------------------------------------------------------------------------------------
// Expressions
// ---------------------------------------------------------------------------------------------

/// A BPX `Function`: an arithmetic expression in `x` with Python semantics.
#[derive(Clone, Debug)]
enum Expr {
    Num(f64),
    X,
    Neg(Box<Expr>),
    Bin(Op, Box<Expr>, Box<Expr>),
    Call(Func, Box<Expr>),
}

#[derive(Clone, Copy, Debug)]
enum Op {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
}

#[derive(Clone, Copy, Debug)]
enum Func {
    Exp,
    Log,
    Sqrt,
    Tanh,
    Cosh,
    Sinh,
}

impl Expr {
    fn parse(text: &str) -> Result<Expr, String> {
        let mut p = ExprParser { s: text.as_bytes(), i: 0 };
        let e = p.expr()?;
        p.ws();
        if p.i < p.s.len() {
            return Err(format!("unexpected {:?} at character {}", &text[p.i..], p.i + 1));
        }
        Ok(e)
    }

    fn eval(&self, x: f64) -> f64 {
        match self {
            Expr::Num(v) => *v,
            Expr::X => x,
            Expr::Neg(e) => -e.eval(x),
            Expr::Bin(op, a, b) => {
                let (a, b) = (a.eval(x), b.eval(x));
                match op {
                    Op::Add => a + b,
                    Op::Sub => a - b,
                    Op::Mul => a * b,
                    Op::Div => a / b,
                    Op::Pow => a.powf(b),
                }
            }
            Expr::Call(f, e) => {
                let v = e.eval(x);
                match f {
                    Func::Exp => v.exp(),
                    Func::Log => v.ln(),
                    Func::Sqrt => v.sqrt(),
                    Func::Tanh => v.tanh(),
                    Func::Cosh => v.cosh(),
                    Func::Sinh => v.sinh(),
                }
            }
        }
    }

    fn uses_x(&self) -> bool {
        match self {
            Expr::Num(_) => false,
            Expr::X => true,
            Expr::Neg(e) | Expr::Call(_, e) => e.uses_x(),
            Expr::Bin(_, a, b) => a.uses_x() || b.uses_x(),
        }
    }
}

/// Recursive descent over Python's precedence: `+ -` < `* /` < unary `-` < `**` (right
/// associative, with a unary right operand).
struct ExprParser<'a> {
    s: &'a [u8],
    i: usize,
}

impl ExprParser<'_> {
    fn ws(&mut self) {
        while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }

    fn rest(&mut self) -> &[u8] {
        self.ws();
        &self.s[self.i..]
    }

    fn eat(&mut self, tok: &str) -> bool {
        if self.rest().starts_with(tok.as_bytes()) {
            self.i += tok.len();
            true
        } else {
            false
        }
    }

    fn expr(&mut self) -> Result<Expr, String> {
        let mut e = self.term()?;
        loop {
            let op = if self.eat("+") {
                Op::Add
            } else if self.eat("-") {
                Op::Sub
            } else {
                return Ok(e);
            };
            e = Expr::Bin(op, Box::new(e), Box::new(self.term()?));
        }
    }

    fn term(&mut self) -> Result<Expr, String> {
        let mut e = self.unary()?;
        loop {
            let rest = self.rest();
            let op = if rest.starts_with(b"**") || rest.starts_with(b"//") {
                return Err(format!("unsupported operator at character {}", self.i + 1));
            } else if self.eat("*") {
                Op::Mul
            } else if self.eat("/") {
                Op::Div
            } else {
                return Ok(e);
            };
            e = Expr::Bin(op, Box::new(e), Box::new(self.unary()?));
        }
    }

    fn unary(&mut self) -> Result<Expr, String> {
        if self.eat("-") {
            Ok(Expr::Neg(Box::new(self.unary()?)))
        } else if self.eat("+") {
            self.unary()
        } else {
            self.power()
        }
    }

    fn power(&mut self) -> Result<Expr, String> {
        let base = self.atom()?;
        if self.eat("**") {
            Ok(Expr::Bin(Op::Pow, Box::new(base), Box::new(self.unary()?)))
        } else {
            Ok(base)
        }
    }

    fn atom(&mut self) -> Result<Expr, String> {
        self.ws();
        let start = self.i;
        match self.s.get(start) {
            None => Err("unexpected end of expression".into()),
            Some(b'(') => {
                self.i += 1;
                let e = self.expr()?;
                if self.eat(")") { Ok(e) } else { Err(format!("missing ')' at character {}", self.i + 1)) }
            }
            Some(c) if c.is_ascii_digit() || *c == b'.' => {
                let s = self.s;
                let mut j = start;
                while j < s.len() && (s[j].is_ascii_digit() || s[j] == b'.') {
                    j += 1;
                }
                if j < s.len() && (s[j] == b'e' || s[j] == b'E') {
                    let mut k = j + 1;
                    if k < s.len() && (s[k] == b'+' || s[k] == b'-') {
                        k += 1;
                    }
                    if k < s.len() && s[k].is_ascii_digit() {
                        while k < s.len() && s[k].is_ascii_digit() {
                            k += 1;
                        }
                        j = k;
                    }
                }
                let text = std::str::from_utf8(&s[start..j]).unwrap_or_default();
                self.i = j;
                text.parse()
                    .map(Expr::Num)
                    .map_err(|_| format!("bad number {text:?} at character {}", start + 1))
            }
            Some(c) if c.is_ascii_alphabetic() || *c == b'_' => {
                let s = self.s;
                let mut j = start;
                while j < s.len() && (s[j].is_ascii_alphanumeric() || s[j] == b'_') {
                    j += 1;
                }
                let name = std::str::from_utf8(&s[start..j]).unwrap_or_default().to_string();
                self.i = j;
                if name == "x" {
                    return Ok(Expr::X);
                }
                let func = match name.as_str() {
                    "exp" => Func::Exp,
                    "log" => Func::Log,
                    "sqrt" => Func::Sqrt,
                    "tanh" => Func::Tanh,
                    "cosh" => Func::Cosh,
                    "sinh" => Func::Sinh,
                    _ => {
                        return Err(format!(
                            "unknown name {name:?} at character {} (the variable is x)",
                            start + 1
                        ));
                    }
                };
                if !self.eat("(") {
                    return Err(format!("expected '(' after {name}"));
                }
                let arg = self.expr()?;
                if !self.eat(")") {
                    return Err(format!(
                        "{name} takes one argument; expected ')' at character {}",
                        self.i + 1
                    ));
                }
                Ok(Expr::Call(func, Box::new(arg)))
            }
            Some(c) => Err(format!("unexpected {:?} at character {}", char::from(*c), start + 1)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expressions_follow_python() {
        let cases = [
            ("1 + 2 * 3", 0.0, 7.0),
            ("-x**2", 3.0, -9.0),
            ("2 ** -1", 0.0, 0.5),
            ("2 ** 3 ** 2", 0.0, 512.0),
            ("1 / 2", 0.0, 0.5),
            ("(x / 1000) ** 1.5", 4000.0, 8.0),
            ("1.5e-3 * exp(-x) - tanh(0) + cosh(0)", 0.0, 1.0015),
            ("- -x", 2.0, 2.0),
            (".5 + 1.", 0.0, 1.5),
            ("3.3e-14", 0.0, 3.3e-14),
        ];
        for (text, x, want) in cases {
            let got = Expr::parse(text).unwrap().eval(x);
            assert!((got - want).abs() <= 1e-12 * want.abs().max(1.0), "{text}: {got} vs {want}");
        }
        for bad in ["1 +", "foo(x)", "x // 2", "exp(x, 2)", "(x", "x y", "2 * * 3", "y"] {
            assert!(Expr::parse(bad).is_err(), "{bad} should not parse");
        }
        assert!(!Expr::parse("3.3e-14").unwrap().uses_x());
    }
}
