"""``simulate`` and its ``Solution``: NumPy arrays in SI units, ``to_pandas()``, picklable."""

from . import _native
from ._parameters import ParameterSet

# Column names of ``to_pandas``: PyBaMM's variable names and units.
_COLUMNS = {
    "time": "Time [s]",
    "current": "Current [A]",
    "voltage": "Voltage [V]",
    "capacity": "Discharge capacity [A.h]",
    "energy": "Discharge energy [W.h]",
    "temperature": "Temperature [K]",
}


class Solution:
    """A simulation's outputs at every solver step: ``time`` (s), ``current`` (A, discharge
    positive), ``voltage`` (V), ``capacity`` (A h), ``energy`` (W h), ``temperature`` (K), as
    NumPy arrays; ``summary`` holds the final capacity, energy and voltage, build and solve
    times (s), solver steps and the cut-off times (s)."""

    def __init__(self, raw):
        self.time = raw.pop("time")
        self.current = raw.pop("current")
        self.voltage = raw.pop("voltage")
        self.capacity = raw.pop("capacity")
        self.energy = raw.pop("energy")
        self.temperature = raw.pop("temperature")
        self.summary = raw

    def __len__(self):
        return len(self.time)

    def __getitem__(self, name):
        """A series by PyBaMM's name (``sol["Voltage [V]"]``) or ours (``sol["voltage"]``)."""
        for attr, column in _COLUMNS.items():
            if name in (attr, column):
                return getattr(self, attr)
        raise KeyError(name)

    def to_pandas(self):
        """The series as a ``pandas.DataFrame`` with PyBaMM's column names."""
        import pandas as pd

        return pd.DataFrame({column: getattr(self, attr) for attr, column in _COLUMNS.items()})

    def __repr__(self):
        s = self.summary
        return f"Solution({s['model']}, {len(self)} points, {s['capacity_Ah']:.4f} A h, {s['energy_Wh']:.4f} W h)"


def simulate(model="spme", parameters=None, experiment=None, c_rate=1.0, contact_resistance=None, thermal=False, mesh=20):
    """Simulates ``model`` ("spm", "spme" or "dfn") with ``parameters`` (Chen 2020 when None)
    through ``experiment`` (PyBaMM step strings, e.g. ``["Discharge at 1C until 2.5 V",
    "Rest for 10 minutes"]``), or a ``c_rate`` discharge to the lower cut-off without one.
    ``contact_resistance`` (ohm) switches that submodel on with this value (it is on, too,
    when the set's ``cell.contact_resistance`` is above 0); ``thermal`` the lumped thermal
    model; ``mesh`` volumes per domain and particle. The GIL is released while it runs."""
    p = parameters if parameters is not None else ParameterSet.chen2020()
    if isinstance(experiment, str):
        experiment = [experiment]
    if contact_resistance is not None:
        p = p.copy()
        p.set("cell.contact_resistance", contact_resistance)
    raw = _native.simulate(model, p._native, list(experiment) if experiment else None, float(c_rate), contact_resistance is not None, bool(thermal), int(mesh))
    return Solution(raw)
