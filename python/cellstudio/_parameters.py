"""``ParameterSet``: the crate's typed parameter set (SI units) by dotted path, e.g.
``positive.thickness`` (m), ``negative.diffusivity`` (m^2/s), ``cell.contact_resistance`` (ohm)."""

import json
import warnings

from . import _native
from ._errors import CellstudioError


def _scalars(tree, prefix=""):
    """The numeric leaves of a parameter set's JSON as ``{dotted path: value}``."""
    out = {}
    for key, value in tree.items():
        path = f"{prefix}{key}"
        if isinstance(value, bool):
            continue
        if isinstance(value, (int, float)):
            out[path] = float(value)
        elif isinstance(value, dict) and prefix == "":
            out.update(_scalars(value, path + "."))
    return out


class ParameterSet:
    """A validated parameter set; every value in SI units (m, mol/m^3, S/m, K, A h, V, ohm).

    Functions of state (open-circuit potentials, electrolyte transport) stay inside; scalars
    are read and written by dotted path: ``get``/``set``, ``ps["positive.thickness"]``.
    """

    __slots__ = ("_native",)

    def __init__(self, native):
        self._native = native

    @classmethod
    def chen2020(cls):
        """The LG M50 set of Chen et al. (2020), PyBaMM's ``"Chen2020"``."""
        return cls(_native.ParameterSet.chen2020())

    @classmethod
    def from_file(cls, path):
        """A parameter file as ``--params`` reads it: TOML, this crate's JSON, or BPX JSON."""
        return cls(_native.ParameterSet.from_file(str(path)))

    @classmethod
    def from_bpx(cls, path):
        """A BPX document (v0.4/v0.5 or v1.x); BPX keys that map to nothing here are warned about."""
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise CellstudioError(f"cannot read {path}: {e}") from e
        native, unknown = _native.ParameterSet.from_bpx_json(text)
        for key in unknown:
            warnings.warn(f"{path}: BPX field `{key}` is not used", stacklevel=2)
        return cls(native)

    @classmethod
    def from_pybamm(cls, values, base=None, ignore_unknown=False):
        """A set from PyBaMM ``ParameterValues`` given as a dict of scalars (see ``_pybamm``)."""
        from ._pybamm import from_pybamm

        return from_pybamm(cls, values, base if base is not None else cls.chen2020(), ignore_unknown)

    @classmethod
    def from_json(cls, text):
        """A set from the JSON text ``to_json`` writes (validated)."""
        return cls(_native.ParameterSet.from_json(text))

    def to_json(self):
        """The whole set, functions included, as JSON text."""
        return self._native.to_json()

    def to_bpx(self):
        """The set as a BPX v0.5 document (a dict)."""
        return json.loads(self._native.to_bpx_json())

    def set(self, path, value):
        """Sets one scalar (SI units) and validates the set, as ``--set PATH=VALUE`` does."""
        self._native.set(path, float(value))

    def get(self, path):
        """One scalar by dotted path (SI units)."""
        return self._native.get(path)

    def to_dict(self):
        """Every scalar as ``{dotted path: value}`` (SI units); functions left out."""
        return _scalars(json.loads(self._native.to_json()))

    def copy(self):
        return ParameterSet(_native.ParameterSet.from_json(self._native.to_json()))

    @property
    def name(self):
        return self._native.name

    @name.setter
    def name(self, value):
        self._native.name = value

    def __getitem__(self, path):
        return self.get(path)

    def __setitem__(self, path, value):
        self.set(path, value)

    def __eq__(self, other):
        return isinstance(other, ParameterSet) and self._native == other._native

    def __repr__(self):
        return f"ParameterSet({self.name!r})"

    def __getstate__(self):
        return self.to_json()

    def __setstate__(self, text):
        self._native = _native.ParameterSet.from_json(text)
