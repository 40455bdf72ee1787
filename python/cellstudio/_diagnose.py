"""``diagnose`` from a DataFrame: written to a temporary CSV in the crate's recording format
(``time_s``, ``current_A`` discharge positive, ``voltage_V``, optional ``temperature_K``)
and diagnosed as ``cellstudio diagnose --data`` diagnoses a file."""

import json
import os
import tempfile

from . import _native
from ._errors import CellstudioError
from ._parameters import ParameterSet
from ._progress import with_progress
from ._results import DiagnosisResult

# Accepted column names per recording column: ours, then PyBaMM's.
_COLUMNS = {
    "time_s": ("time_s", "Time [s]"),
    "current_A": ("current_A", "Current [A]"),
    "voltage_V": ("voltage_V", "Voltage [V]", "Terminal voltage [V]"),
    "temperature_K": ("temperature_K", "Temperature [K]", "X-averaged cell temperature [K]"),
}


def _recording_columns(frame):
    """The frame's columns in the crate's names; a missing required one raises, naming it."""
    out = {}
    for ours, names in _COLUMNS.items():
        found = next((n for n in names if n in frame.columns), None)
        if found is not None:
            out[ours] = frame[found]
        elif ours != "temperature_K":
            raise CellstudioError(f"recording: no `{ours}` column (accepted: {', '.join(names)}); columns: {list(frame.columns)}")
    return out


def diagnose(recording, model="spme", parameters=None, out="out/diagnosis", discharge_positive=True, progress=True, **options):
    """Diagnoses ``recording`` (a DataFrame, or the path of a recording file) with ``model``
    on ``parameters`` (Chen 2020 when None); writes the report into ``out``. ``options``:
    ``contact_resistance``, ``thermal`` (bool), ``fit`` (dotted paths), ``refits``,
    ``start_at_rest``, ``max_rounds``. ``discharge_positive=False`` flips a frame whose
    discharge current is negative. The GIL is released while it runs; ``progress`` draws the
    refits' bar with tqdm when it is installed."""
    p = parameters if parameters is not None else ParameterSet.chen2020()
    if isinstance(recording, (str, os.PathLike)):
        path = os.fspath(recording)
        return DiagnosisResult(json.loads(with_progress(lambda: _native.diagnose(path, p._native, model, os.fspath(out), **options), progress=progress)))
    import pandas as pd

    columns = _recording_columns(recording)
    if not discharge_positive:
        columns["current_A"] = -columns["current_A"]
    with tempfile.TemporaryDirectory(prefix="cellstudio-") as tmp:
        path = os.path.join(tmp, "recording.csv")
        pd.DataFrame(columns).to_csv(path, index=False, float_format="%.10g")
        return DiagnosisResult(json.loads(with_progress(lambda: _native.diagnose(path, p._native, model, os.fspath(out), **options), progress=progress)))
