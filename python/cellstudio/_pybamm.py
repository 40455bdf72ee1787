"""PyBaMM parameter names, taken from the crate's BPX mapping rather than a table of our own.

PyBaMM names a BPX key by its section (``Negative electrode`` + ``Thickness [m]`` ->
``Negative electrode thickness [m]``; ``Particle radius [m]`` -> ``Negative particle radius
[m]``; ``Maximum concentration [mol.m-3]`` -> ``Maximum concentration in negative electrode
[mol.m-3]``; see PyBaMM's BPX importer). The crate's BPX export lists every key it maps; a key
is accepted here when importing it sets one of our scalars to exactly its value (a one-to-one
field, found once by nudging the key and importing). Keys the BPX import converts (surface
area per volume, transport efficiency, reaction rate, stoichiometry window, electrode area)
and PyBaMM's functions of state are refused by name; our dotted paths are accepted as well.
"""

import json
import math
from functools import lru_cache

from . import _native
from ._errors import CellstudioError

_PREFIX = {
    "Cell": ("", ""),
    "Electrolyte": ("Electrolyte ", ""),
    "Negative electrode": ("Negative electrode ", "Negative "),
    "Positive electrode": ("Positive electrode ", "Positive "),
    "Separator": ("Separator ", ""),
}

# PyBaMM's BPX importer also stores these BPX keys under its own cell names.
_PYBAMM_RENAMES = {"External surface area [m2]": "Cell cooling surface area [m2]", "Volume [m3]": "Cell volume [m3]"}


# PyBaMM's own names (as in `pybamm.ParameterValues("Chen2020")`) for scalars that BPX names
# differently or converts: each is one field here.
_PYBAMM_NAMES = {
    **{f"{side.title()} particle diffusivity [m2.s-1]": f"{side}.diffusivity" for side in ("negative", "positive")},
    **{f"{side.title()} electrode active material volume fraction": f"{side}.active_fraction" for side in ("negative", "positive")},
    **{f"{side.title()} electrode Bruggeman coefficient (electrolyte)": f"{side}.bruggeman_electrolyte" for side in ("negative", "positive")},
    **{f"{side.title()} electrode Bruggeman coefficient (electrode)": f"{side}.bruggeman_solid" for side in ("negative", "positive")},
    **{f"{side.title()} electrode conductivity [S.m-1]": f"{side}.conductivity" for side in ("negative", "positive")},
    **{f"{side.title()} electrode Butler-Volmer transfer coefficient": f"{side}.charge_transfer_coefficient" for side in ("negative", "positive")},
    "Separator Bruggeman coefficient (electrolyte)": "separator.bruggeman",
    "Separator porosity": "separator.porosity",
    "Separator thickness [m]": "separator.thickness",
    "Contact resistance [Ohm]": "cell.contact_resistance",
}


def pybamm_name(section, key):
    """The PyBaMM parameter name of BPX ``key`` in ``section``, by PyBaMM's BPX naming rule."""
    pre, short = _PREFIX[section]
    lower = key[:1].lower() + key[1:]
    for head in ("Initial concentration ", "Maximum concentration "):
        if key.startswith(head):
            return head + "in " + pre.lower() + key[len(head):]
    if key.startswith("Particle radius"):
        return short + lower
    if key.startswith("OCP"):
        return pre + key
    if key.startswith("Entropic change coefficient"):
        return pre + key.replace("Entropic change coefficient", "OCP entropic change")
    if key.startswith("Cation transference number") or not pre:
        return key
    return pre + lower


def _import_scalars(doc):
    native, _ = _native.ParameterSet.from_bpx_json(json.dumps(doc))
    from ._parameters import _scalars

    return _scalars(json.loads(native.to_json()))


def _close(a, b):
    return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-300)


@lru_cache(maxsize=1)
def known_names():
    """``{PyBaMM name: dotted path}`` for the one-to-one BPX keys, and ``{PyBaMM name: why}``
    for the keys the BPX import converts (refused)."""
    doc = json.loads(_native.ParameterSet.chen2020().to_bpx_json())
    reference = _import_scalars(doc)
    direct, converted = {}, {}
    for section in _PREFIX:
        for key, value in doc["Parameterisation"].get(section, {}).items():
            names = [pybamm_name(section, key)] + ([_PYBAMM_RENAMES[key]] if key in _PYBAMM_RENAMES else [])
            if not isinstance(value, (int, float)) or isinstance(value, bool):
                for n in names:
                    converted[n] = "a function of state here (a table or expression); only scalars are converted"
                continue
            nudged = value * 0.99 if value else 1e-3
            doc["Parameterisation"][section][key] = nudged
            try:
                after = _import_scalars(doc)
            except CellstudioError:
                after = reference
            finally:
                doc["Parameterisation"][section][key] = value
            hits = [p for p, v in after.items() if not _close(v, reference[p]) and _close(v, nudged)]
            for n in names:
                if len(hits) == 1:
                    direct[n] = hits[0]
                else:
                    converted[n] = f"BPX `{section}/{key}`, which this crate converts (not one of its scalars); set the field by its dotted path instead"
    direct.update(_PYBAMM_NAMES)
    for name in _PYBAMM_NAMES:
        converted.pop(name, None)
    return direct, converted


def from_pybamm(cls, values, base, ignore_unknown=False):
    """``base`` with the scalars of a PyBaMM ``ParameterValues`` dict applied by dotted path.

    A key that is a function (callable, or PyBaMM's ``(name, (x, y))`` data), or that maps to
    no scalar here, raises ``CellstudioError`` naming every such key, unless
    ``ignore_unknown``, which skips them.
    """
    direct, converted = known_names()
    scalar_paths = set(base.to_dict())
    result = base.copy()
    refused, applied = [], {}
    for name, value in dict(values).items():
        path = direct.get(name, name if name in scalar_paths else None)
        if callable(value) or isinstance(value, (tuple, list, dict, str)):
            refused.append(f"`{name}` is a function or data, not a scalar: it cannot be converted")
        elif path is None:
            why = converted.get(name, "not a PyBaMM name this crate maps (nor a dotted path such as positive.thickness)")
            refused.append(f"`{name}`: {why}")
        else:
            applied[path] = float(value)
    if refused and not ignore_unknown:
        raise CellstudioError("from_pybamm: " + "; ".join(refused))
    data = json.loads(result.to_json())
    for path, value in applied.items():
        group, field = path.split(".", 1)
        data[group][field] = value
    return cls.from_json(json.dumps(data))
