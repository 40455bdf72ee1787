//! The candidates' search ranges and plausible sizes: how far each refit may move a parameter
//! of the set, and what size of each effect a real cell can have.

/// Multiplicative range (-) over which a parameter that the model already has is refitted.
pub(super) const MISMATCH_RANGE: f64 = 30.0;

/// The factors (-) on the set's value within which such a refitted parameter is plausible.
pub(super) const MISMATCH_PLAUSIBLE: (f64, f64) = (0.05, 20.0);

/// How far (K) the fitted ambient may lie from a recording's first temperature.
pub(super) const AMBIENT_RANGE_K: f64 = 30.0;

/// Fixed parameters the DFN brings to an SPM: the electrolyte's diffusivity, conductivity,
/// transference number, thermodynamic factor, initial concentration, porosities and
/// tortuosity (7), and the two solid conductivities (2); to an SPMe, the latter two.
pub(super) const SPM_TO_DFN_FIXED: usize = 9;
pub(super) const SPME_TO_DFN_FIXED: usize = 2;

/// The leak candidate's search range, as C-rates (1/h) charging and discharging the cell, and
/// the plausible size of a leak that charges it. One that discharges it (a soft short, or
/// self-discharge) is plausible over its whole search, to C/20: a short of about 15 ohm in a
/// 5 A h cell (blind ao3's 120 mA leak ended on C/50, the bound before). One that charges it
/// can only be a current channel's offset, and a cycler's beyond C/100 would be seen. Both
/// must also fit the rests ([`super::super::at_rest`]): with a symmetric C/50 (tried in the
/// thirty-fourth session) a leak "charging the cell" with lost active material stood in for
/// the real LG M50 files' open-circuit-voltage mismatch (C/10: 84.8 mA, 51.98 -> 12.65 mV,
/// leaving 31 mV RMS at rest against 9 mV under load).
pub(super) const LEAK_SEARCH_C_RATE: (f64, f64) = (0.02, 0.05);
pub(super) const OFFSET_PLAUSIBLE_C_RATE: f64 = 0.01;

/// The unrelaxed-start candidate's search: a load of up to 3C either way (1/h), held for 10 s
/// to 2 h (from 10 min) before the first recorded point.
pub(super) const HISTORY_C_RATE: f64 = 3.0;
pub(super) const HISTORY_START_S: f64 = 600.0;
pub(super) const HISTORY_RANGE_S: (f64, f64) = (10.0, 7200.0);

/// The lithium-inventory candidate searches each electrode's initial stoichiometry within
/// this much of its ends (-); a fit that ends there has run out of the OCP curve.
pub(super) const INVENTORY_EDGE: f64 = 0.01;

/// The salt-concentration candidate's search (a factor either way on the set's initial
/// concentration) and its plausible range (-): from most of the salt consumed to an
/// electrolyte twice as concentrated as the set's.
pub(super) const SALT_SEARCH: f64 = 5.0;
pub(super) const SALT_PLAUSIBLE: (f64, f64) = (0.3, 2.0);

/// The heavier-coating candidate's search: each electrode's thickness from the set's up to this
/// factor (-). Less material than the set's is the active-material loss candidate's.
pub(super) const LOADING_GAIN: f64 = 1.5;

/// The particle-radius candidates' search (a factor either way on the set's radius) and their
/// plausible range (-): a radius off by more than 5x is another material, not another lot.
pub(super) const RADIUS_SEARCH: f64 = 10.0;
pub(super) const RADIUS_PLAUSIBLE: (f64, f64) = (0.2, 5.0);

/// The size-distribution candidate's starting and largest plausible relative standard
/// deviation of the particle radii (-); PyBaMM's default spread is the start.
pub(super) const SIZE_SPREAD_START: f64 = 0.3;
pub(super) const SIZE_SPREAD_PLAUSIBLE: f64 = 0.8;

/// Size classes per electrode of the size-distribution candidate (PyBaMM's 30 by default):
/// at spreads of 0.4, 15 classes lie 0.06 mV RMS from 30 over a 1C discharge and over pulses
/// with rests, at a third of the time (`examples/bench_psd`); 10 lie 0.26 mV away.
pub(super) const SIZE_CLASSES: usize = 15;

/// The entropic-change candidate is offered when the model's temperature lies at least this
/// far (K) from the OCPs' reference temperature (closer, the term is below the noise: 0.1 mV/K
/// of a graphite's dU/dT over 5 K is 0.5 mV), or when the model heats itself.
pub(super) const ENTROPIC_MIN_OFFSET_K: f64 = 5.0;

/// The entropic-change candidate's factors on the chemistry's published dU/dT (-): searched
/// over this range, plausible within [`ENTROPIC_PLAUSIBLE`] (the same chemistry from another
/// maker or batch; the sign of an entropy does not turn).
pub(super) const ENTROPIC_SEARCH: (f64, f64) = (-2.0, 4.0);
pub(super) const ENTROPIC_PLAUSIBLE: (f64, f64) = (0.0, 3.0);

/// The second-material candidates' searches: the share of the electrode's sites (-), where
/// the material fills (V vs Li, per electrode) and how broadly (V); plausible shares. A width
/// of a few mV is a flat two-phase plateau (graphite's stages, LFP, crystalline silicon's
/// first lithiation; blind ar8 fits 2.4 mV): the floor, 1 mV, lies below it, and a fit that
/// runs to either end of the search has not estimated the width (refused).
pub(super) const SECOND_SHARE: (f64, f64, f64) = (0.15, 0.0, 0.5);
pub(super) const SECOND_SHARE_PLAUSIBLE: (f64, f64) = (0.005, 0.4);
pub(super) const SECOND_POTENTIAL_NEGATIVE: (f64, f64, f64) = (0.3, 0.02, 1.2);
pub(super) const SECOND_POTENTIAL_POSITIVE: (f64, f64, f64) = (3.8, 3.0, 4.5);
pub(super) const SECOND_WIDTH: (f64, f64, f64) = (0.1, 0.001, 0.5);

/// The least change of the cyclable lithium (-) a fit that rebalances the electrodes reports
/// beside its own effect: below 1 % it is within a cell-to-cell spread of the balance.
pub(super) const LITHIUM_CHANGE_REPORTED: f64 = 0.01;

/// The voltage-offset candidate's search range and plausible size (V).
pub(super) const VOLTAGE_OFFSET_SEARCH: f64 = 0.05;
pub(super) const VOLTAGE_OFFSET_PLAUSIBLE: f64 = 0.02;

/// The voltage-delay candidate's search range and plausible size (s).
pub(super) const VOLTAGE_DELAY_SEARCH_S: f64 = 10.0;
pub(super) const VOLTAGE_DELAY_PLAUSIBLE_S: f64 = 5.0;

/// The voltage-gain candidate's search range and plausible size (-): 0.5 % reads 21 mV off
/// at 4.2 V, as far as the offset's plausible 20 mV.
pub(super) const VOLTAGE_GAIN_SEARCH: f64 = 0.02;
pub(super) const VOLTAGE_GAIN_PLAUSIBLE: f64 = 0.005;

/// The current-gain candidate's search range and plausible size (-): a battery management
/// system's current sensing is specified to 1-3 %, a cycler's far better; beyond 5 % a
/// capacity check against the rating would show it.
pub(super) const CURRENT_GAIN_SEARCH: f64 = 0.1;
pub(super) const CURRENT_GAIN_PLAUSIBLE: f64 = 0.05;

/// The hysteresis candidate's starting decay rate (-): the state moves `1 - e^-1` of the way
/// to a branch per tenth of the capacity passed.
pub(super) const HYSTERESIS_START_RATE: f64 = 10.0;

/// How far (of the unit hysteresis state's range, -1 to 1) a load must drive the state each
/// way, down and back up or up and back down, for a recording without rests after both
/// directions to show hysteresis: a quarter of the range. A load in one direction only moves
/// the state one way, an offset growing with the charge passed that a stoichiometry shift or
/// an offset also makes.
pub(super) const HYSTERESIS_SWING: f64 = 0.5;
