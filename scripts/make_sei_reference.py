"""PyBaMM reference for SEI growth (tests/suite/sei.rs): SPM, SPMe and DFN on Chen 2020 (its SEI
parameters), each with PyBaMM's SEI options "reaction limited", "solvent-diffusion
limited", "electron-migration limited", "interstitial-diffusion limited" and "ec reaction
limited" (SEI film resistance "distributed", PyBaMM's default with SEI, which in the DFN
makes the total interfacial current density an algebraic state; side reactions x-averaged
in the SPM, per x volume in the SPMe and DFN, PyBaMM's defaults; SEI porosity change
"false", PyBaMM's default), PyBaMM's default mesh (20 volumes per x-domain and
per particle, as ours), IDAKLU at rtol = atol = 1e-8.

Protocol: CYCLES CC-CV cycles of "Discharge at 1C until 3.0 V", "Rest for 10 minutes",
"Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes" from Chen
2020's initial state, outputs every 60 s.

Writes into the folder given (default tests/data/sei):
- `{model}_{option}.csv`: time_s, current_A, voltage_V, sei_thickness_m (x-averaged),
  lithium_lost_mol ("Loss of lithium to negative SEI [mol]"), step (0-based over all cycles);
- `{model}_{option}_cycles.csv`: per cycle, the discharge capacity of its discharge step
  (A h, from "Discharge capacity [A.h]"), and at the cycle's end the lithium lost to the SEI
  (mol) and the SEI thickness (m);
- `meta.json`: versions, options, protocol, timings.

    python -m venv .venv && .venv/bin/pip install pybamm==26.10.1.1
    .venv/bin/python scripts/make_sei_reference.py tests/data/sei [spm,spme,dfn] [reaction_limited,...] [rtol]

(the optional second and third arguments name the models and options to (re)make, the other
cases staying in `meta.json`; the fourth is IDAKLU's rtol = atol, 1e-8 unless given, kept per
case as `rtol`. The SPM and SPMe cases are made at 1e-10: at 1e-8 PyBaMM's own error in the
lithium lost by the two laws that barely grow the layer is about 2e-4 of that growth.)
"""

import json
import os
import sys
import time

import numpy as np
import pybamm

# One cycle: the CC-CV experiment of tests/suite/cccv.rs.
from make_cccv_reference import EXPERIMENT as CYCLE
CYCLES = 10
OPTIONS = {"reaction_limited": "reaction limited", "solvent_diffusion_limited": "solvent-diffusion limited",
           "electron_migration_limited": "electron-migration limited",
           "interstitial_diffusion_limited": "interstitial-diffusion limited", "ec_reaction_limited": "ec reaction limited"}
MODELS = {"spm": pybamm.lithium_ion.SPM, "spme": pybamm.lithium_ion.SPMe, "dfn": pybamm.lithium_ion.DFN}


def simulation(model_cls, option, cycles=CYCLES, period=60, tol=1e-8):
    """A PyBaMM simulation of `cycles` cycles with SEI `option` (Chen2020, IDAKLU at `tol`)."""
    return pybamm.Simulation(model_cls({"SEI": option}), parameter_values=pybamm.ParameterValues("Chen2020"),
                             experiment=pybamm.Experiment([tuple(CYCLE)] * cycles, period=f"{period} seconds"),
                             solver=pybamm.IDAKLUSolver(rtol=tol, atol=tol))


def solve(model_cls, option, **kwargs):
    """PyBaMM's solution and the wall time (s) of `Simulation.solve` (which builds and
    discretises the model on its first call, as a user's run does)."""
    sim = simulation(model_cls, option, **kwargs)
    start = time.perf_counter()
    sol = sim.solve()
    return sol, time.perf_counter() - start


def cycle_rows(sol):
    """Per cycle: [cycle, discharge capacity of its discharge step (A h), lithium lost to the
    SEI at its end (mol), SEI thickness at its end (m)]."""
    rows = []
    for c, cyc in enumerate(sol.cycles):
        q = cyc.steps[0]["Discharge capacity [A.h]"].entries
        rows.append([c + 1, q[-1] - q[0], cyc["Loss of lithium to negative SEI [mol]"].entries[-1],
                     cyc["X-averaged negative SEI thickness [m]"].entries[-1]])
    return rows


def main(root):
    os.makedirs(root, exist_ok=True)
    tol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-8
    meta = {"made_by": f"PyBaMM {pybamm.__version__}, Chen2020, IDAKLU rtol=atol per case (1e-8 unless rtol says), default mesh",
            "cycle": CYCLE, "cycles": CYCLES, "period_s": 60, "cases": {}}
    models = sys.argv[2].split(",") if len(sys.argv) > 2 else list(MODELS)
    if os.path.exists(os.path.join(root, "meta.json")):
        with open(os.path.join(root, "meta.json")) as f:
            meta["cases"] = json.load(f)["cases"]
    options = sys.argv[3].split(",") if len(sys.argv) > 3 else list(OPTIONS)
    for mname, cls in ((m, MODELS[m]) for m in models):
        for oname, option in ((o, OPTIONS[o]) for o in options):
            sol, seconds = solve(cls, option, tol=tol)
            name = f"{mname}_{oname}"
            cols = [sol["Time [s]"].entries, sol["Current [A]"].entries, sol["Voltage [V]"].entries,
                    sol["X-averaged negative SEI thickness [m]"].entries, sol["Loss of lithium to negative SEI [mol]"].entries]
            step = np.concatenate([np.full(len(s["Time [s]"].entries), c * len(CYCLE) + k)
                                   for c, cyc in enumerate(sol.cycles) for k, s in enumerate(cyc.steps)])
            np.savetxt(os.path.join(root, f"{name}.csv"), np.column_stack(cols + [step]), delimiter=",",
                       header="time_s,current_A,voltage_V,sei_thickness_m,lithium_lost_mol,step", comments="", fmt="%.10g")
            rows = cycle_rows(sol)
            np.savetxt(os.path.join(root, f"{name}_cycles.csv"), np.array(rows), delimiter=",",
                       header="cycle,discharge_capacity_Ah,lithium_lost_mol,sei_thickness_m", comments="", fmt="%.12g")
            meta["cases"][name] = {"model": cls.__name__, "options": {"SEI": option}, "rtol": tol, "points": len(step),
                                   "solve_seconds": seconds, "end_time_s": float(cols[0][-1])}
            print(f"{name}: {len(step)} points, {cols[0][-1]:.0f} s, solved in {seconds:.2f} s; "
                  f"capacity {rows[0][1]:.6f} -> {rows[-1][1]:.6f} A h, lost {rows[-1][2]:.4e} mol, L {rows[-1][3]:.4e} m")
    with open(os.path.join(root, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/sei")
