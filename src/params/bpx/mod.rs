//! BPX (Battery Parameter eXchange, <https://github.com/FaradayInstitution/BPX>) import and
//! export of a [`ParameterSet`](crate::params::ParameterSet).
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
//! | Electrode / Entropic change coefficient (number, table or expression of stoichiometry) | `ocp_entropic_change` |
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
//! a table (adaptively, to 1e-5 V for OCPs, 1e-7 V/K for entropic changes and 1e-4 relative
//! for the electrolyte), and a stoichiometry-dependent particle diffusivity, a scalar here, is
//! averaged over the stoichiometry window (geometric mean). Such lossy conversions are
//! listed in [`BpxImport::approximated_fields`].
//!
//! # Files
//!
//! `import.rs` reads a document on top of Chen 2020, walking it with `section.rs` (sections
//! that remember which keys were read), `value.rs` (checked numbers, errors by BPX key) and
//! `float_function.rs` (numbers, tables or expressions; `expression.rs` parses the last).
//! `export.rs` writes one. Both take the key names from `keys.rs`, tabulate functions with
//! `tabulate.rs` and take the stoichiometry windows from `window.rs`, which are
//! [`params::soc`](crate::params::soc)'s.

mod export;
mod expression;
mod float_function;
mod import;
mod keys;
mod section;
mod tabulate;
mod value;
mod window;

pub use export::to_bpx_json;
pub use import::{BpxImport, from_bpx_json};
pub use keys::{BPX_VERSION, USER_PREFIX};
pub use window::{StoichiometryWindows, stoichiometry_windows};
