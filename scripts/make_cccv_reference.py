"""PyBaMM reference for CC-CV protocols (voltage holds ended by a current limit), for
tests/suite/cccv.rs: SPM, SPMe and DFN on Chen 2020, PyBaMM's default mesh (20 volumes per
x-domain and per particle, as ours), IDAKLU at rtol = atol = 1e-8, outputs every 10 s.

    python -m venv .venv && .venv/bin/pip install pybamm==26.10.1.1
    .venv/bin/python scripts/make_cccv_reference.py tests/data/cccv
"""

import os
import sys

import numpy as np
import pybamm

EXPERIMENT = [
    "Discharge at 1C until 3.0 V",
    "Rest for 10 minutes",
    "Charge at 1C until 4.1 V",
    "Hold at 4.1 V until C/20",
    "Rest for 10 minutes",
]


def main(root):
    os.makedirs(root, exist_ok=True)
    for name, model in [("spm", pybamm.lithium_ion.SPM()), ("spme", pybamm.lithium_ion.SPMe()), ("dfn", pybamm.lithium_ion.DFN())]:
        sim = pybamm.Simulation(model, parameter_values=pybamm.ParameterValues("Chen2020"),
                                experiment=pybamm.Experiment(EXPERIMENT, period="10 seconds"),
                                solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
        sol = sim.solve()
        t = sol["Time [s]"].entries
        i = sol["Current [A]"].entries
        v = sol["Voltage [V]"].entries
        # Each step's first index: the step boundaries of the reference.
        # (each experiment string is one cycle of one step)
        step = np.concatenate([np.full(len(c["Time [s]"].entries), k) for k, c in enumerate(sol.cycles)])
        path = os.path.join(root, f"{name}.csv")
        np.savetxt(path, np.column_stack([t, i, v, step]), delimiter=",", header="time_s,current_A,voltage_V,step", comments="", fmt="%.9g")
        print(f"{name}: {len(t)} points, {t[-1]:.1f} s; step ends " + ", ".join(f"{c['Time [s]'].entries[-1]:.2f}" for c in sol.cycles))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/cccv")
