"""PyBaMM reference for the lithium plating submodel (tests/suite/plating.rs): SPM, SPMe and DFN on
Chen 2020 with the lithium plating parameters of PyBaMM's "OKane2022" set (rate constant 1e-9 m/s,
transfer coefficient 0.65, dead lithium decay constant 1e-6 1/s, its exchange-current and
dead-lithium decay functions), PyBaMM's option "lithium plating" set to
- "irreversible", "reversible", "partially reversible" (PyBaMM then sets "SEI" = "constant":
  the SEI keeps its initial thickness, no film resistance, and the dead-lithium decay rate is
  the decay constant);
- "partially reversible" with "SEI" = "reaction limited" (Chen 2020's SEI parameters, film
  resistance "distributed"): the film's drop and the SEI's thickness enter plating;
plating x-averaged in the SPM, per negative x volume in the SPMe and DFN (PyBaMM's defaults),
"lithium plating porosity change" "false" (PyBaMM's default);
PyBaMM's default mesh (20 volumes per x-domain and per particle, as ours), IDAKLU at
rtol = atol = 1e-8.

Protocol: CYCLES cycles of "Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at
2C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes" from Chen 2020's initial
state, outputs every 60 s. At 2C the negative electrode's `phi_s - phi_e` falls to about
+20 mV (SPM) and -24 mV (SPMe): irreversible plating takes 4 % of the capacity per cycle.

Writes into the folder given (default tests/data/plating-submodel):
- `{model}_{option}.csv`: time_s, current_A, voltage_V, plated_mol and dead_mol (the
  x-averaged "lithium plating concentration" and "dead lithium concentration" times L_n A),
  sei_lithium_mol ("Loss of lithium to negative SEI [mol]", 0 without SEI), step (0-based
  over all cycles);
- `{model}_{option}_cycles.csv`: per cycle, the discharge capacity of its discharge step
  (A h) and at the cycle's end "Loss of lithium to negative lithium plating [mol]" and the
  dead lithium (mol);
- `meta.json`: versions, options, parameters, protocol, timings.

    python3.11 -m venv /tmp/pyb && /tmp/pyb/bin/pip install -r scripts/requirements.txt
    /tmp/pyb/bin/python scripts/make_plating_submodel_reference.py tests/data/plating-submodel [spm,spme,dfn]

(the optional second argument names the models to (re)make; the other cases stay in
`meta.json`.)
"""

import json
import os
import sys
import time

import numpy as np
import pybamm

CYCLE = ["Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at 2C until 4.1 V",
         "Hold at 4.1 V until C/20", "Rest for 10 minutes"]
CYCLES = 3
# The plating parameters PyBaMM's OKane2022 set adds to Chen 2020 (two of them functions).
PLATING_KEYS = [
    "Lithium plating kinetic rate constant [m.s-1]", "Exchange-current density for plating [A.m-2]",
    "Exchange-current density for stripping [A.m-2]", "Initial plated lithium concentration [mol.m-3]",
    "Typical plated lithium concentration [mol.m-3]", "Lithium plating transfer coefficient",
    "Dead lithium decay constant [s-1]", "Dead lithium decay rate [s-1]", "Lithium metal partial molar volume [m3.mol-1]",
]
OPTIONS = {
    "irreversible": {"lithium plating": "irreversible"},
    "reversible": {"lithium plating": "reversible"},
    "partially_reversible": {"lithium plating": "partially reversible"},
    "partially_reversible_sei": {"lithium plating": "partially reversible", "SEI": "reaction limited"},
}
MODELS = {"spm": pybamm.lithium_ion.SPM, "spme": pybamm.lithium_ion.SPMe, "dfn": pybamm.lithium_ion.DFN}


def parameters():
    """Chen 2020 with OKane2022's plating parameters."""
    p = pybamm.ParameterValues("Chen2020")
    okane = pybamm.ParameterValues("OKane2022")
    p.update({k: okane[k] for k in PLATING_KEYS}, check_already_exists=False)
    constants = {k: okane[k] for k in PLATING_KEYS if isinstance(okane[k], (int, float))}
    return p, constants


def main(root):
    os.makedirs(root, exist_ok=True)
    params, constants = parameters()
    meta = {"made_by": f"PyBaMM {pybamm.__version__}, Chen2020 + OKane2022 plating parameters, IDAKLU rtol=atol=1e-8, default mesh",
            "parameters": constants, "cycle": CYCLE, "cycles": CYCLES, "period_s": 60, "cases": {}}
    volume = params["Negative electrode thickness [m]"] * params["Electrode height [m]"] * params["Electrode width [m]"]
    models = sys.argv[2].split(",") if len(sys.argv) > 2 else list(MODELS)
    if os.path.exists(os.path.join(root, "meta.json")):
        with open(os.path.join(root, "meta.json")) as f:
            meta["cases"] = json.load(f)["cases"]
    for mname, cls in ((m, MODELS[m]) for m in models):
        for oname, options in OPTIONS.items():
            # PyBaMM's SPM writes "x-average side reactions" = "true" into the options it is
            # given: each model gets its own copy, so that the SPMe keeps its default "false".
            sim = pybamm.Simulation(cls(dict(options)), parameter_values=params.copy(),
                                    experiment=pybamm.Experiment([tuple(CYCLE)] * CYCLES, period="60 seconds"),
                                    solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
            start = time.perf_counter()
            sol = sim.solve()
            seconds = time.perf_counter() - start

            def var(name):
                return sol[name].entries

            t = var("Time [s]")
            sei = var("Loss of lithium to negative SEI [mol]") if "SEI" in options else np.zeros_like(t)
            cols = [t, var("Current [A]"), var("Voltage [V]"),
                    var("X-averaged negative lithium plating concentration [mol.m-3]") * volume,
                    var("X-averaged negative dead lithium concentration [mol.m-3]") * volume, sei]
            step = np.concatenate([np.full(len(s["Time [s]"].entries), c * len(CYCLE) + k)
                                   for c, cyc in enumerate(sol.cycles) for k, s in enumerate(cyc.steps)])
            name = f"{mname}_{oname}"
            np.savetxt(os.path.join(root, f"{name}.csv"), np.column_stack(cols + [step]), delimiter=",",
                       header="time_s,current_A,voltage_V,plated_mol,dead_mol,sei_lithium_mol,step", comments="", fmt="%.10g")
            rows = []
            for c, cyc in enumerate(sol.cycles):
                q = cyc.steps[0]["Discharge capacity [A.h]"].entries
                rows.append([c + 1, q[-1] - q[0], cyc["Loss of lithium to negative lithium plating [mol]"].entries[-1],
                             cyc["X-averaged negative dead lithium concentration [mol.m-3]"].entries[-1] * volume])
            np.savetxt(os.path.join(root, f"{name}_cycles.csv"), np.array(rows), delimiter=",",
                       header="cycle,discharge_capacity_Ah,lithium_lost_to_plating_mol,dead_lithium_mol", comments="", fmt="%.12g")
            meta["cases"][name] = {"model": cls.__name__, "options": options, "points": len(step),
                                   "solve_seconds": seconds, "end_time_s": float(t[-1])}
            print(f"{name}: {len(step)} points, {t[-1]:.0f} s, solved in {seconds:.2f} s; capacity "
                  f"{rows[0][1]:.6f} -> {rows[-1][1]:.6f} A h; plated {cols[3].max():.3e} mol at most, "
                  f"lost to plating {rows[-1][2]:.3e} mol, dead {rows[-1][3]:.3e} mol")
    with open(os.path.join(root, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/plating-submodel")
