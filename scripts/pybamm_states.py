#!/usr/bin/env python3
"""Export PyBaMM SPMe and DFN states (and the voltage's parts) at a few times of a 1C
discharge, for ``cargo run --release --example probe_voltage -- FILE``, which evaluates our
voltage and DFN algebraic residuals on exactly those states: a model difference then shows
without any time integration in between.

Development script (PyBaMM is never a runtime dependency):

    /work/venv-pybamm/bin/python scripts/pybamm_states.py out/pybamm_states.json

Chen2020, PyBaMM's default mesh (20 volumes per x-domain and per particle), IDAKLU at
rtol = atol = 1e-10, 5 A discharge, states at t = 0, 1, 600, 1800, 3000 s.
"""

import json
import sys

import numpy as np
import pybamm

NAMES = [
    "Voltage [V]",
    "X-averaged negative particle concentration [mol.m-3]",
    "X-averaged positive particle concentration [mol.m-3]",
    "Electrolyte concentration [mol.m-3]",
    "Electrolyte potential [V]",
    "Negative electrode potential [V]",
    "Positive electrode potential [V]",
    "Negative particle concentration [mol.m-3]",  # entries (r, x, t)
    "Positive particle concentration [mol.m-3]",
    "Surface open-circuit voltage [V]",
    "X-averaged reaction overpotential [V]",
    "X-averaged concentration overpotential [V]",
    "X-averaged electrolyte ohmic losses [V]",
    "X-averaged solid phase ohmic losses [V]",
]


def main() -> None:
    path = sys.argv[1] if len(sys.argv) > 1 else "out/pybamm_states.json"
    pv = pybamm.ParameterValues("Chen2020")
    out = {}
    for name in ["SPMe", "DFN"]:
        p = pv.copy()
        p["Current function [A]"] = 5.0
        sim = pybamm.Simulation(getattr(pybamm.lithium_ion, name)(), parameter_values=p,
                                solver=pybamm.IDAKLUSolver(rtol=1e-10, atol=1e-10))
        sol = sim.solve([0, 3400], t_interp=np.array([0.0, 1.0, 600.0, 1800.0, 3000.0]))
        d = {n: np.asarray(sol[n].entries).tolist() for n in NAMES}
        d["t"] = np.asarray(sol.t).tolist()
        out[name] = d
    with open(path, "w") as f:
        json.dump(out, f)


if __name__ == "__main__":
    main()
