"""PyBaMM reference for loss of active material (tests/suite/lam.rs): SPM, SPMe and DFN on Chen 2020,
each with PyBaMM's option "loss of active material" set to
- "stress-driven" (PyBaMM then also sets "particle mechanics" = "swelling only" and
  "stress-induced diffusion" = "true"), with the mechanical and LAM parameters of PyBaMM's
  "OKane2022" set (the LG M50 cell of Chen 2020 with degradation parameters) but the
  "LAM constant proportional term [s-1]" of both electrodes 1e-2 / 3600, the largest of the
  notebook's sweep (10x OKane2022's), no SEI;
- "reaction-driven", with SEI "reaction limited" (Chen 2020's SEI parameters) and the
  "Negative electrode reaction-driven LAM factor [m3.mol-1]" = 1e-4 of PyBaMM's LAM notebook
  (docs/source/examples/notebooks/models/loss_of_active_materials.ipynb);
- "stress and reaction-driven", with both of the above and the SEI;
- ("stress-driven", "none") with "stress-induced diffusion" = "false": the negative
  electrode's stress-driven law alone, with plain particle diffusion (the diagnosis's
  progressive-LAM candidate; OKane2022's positive mechanics without stress-induced diffusion
  drive the positive fraction below zero within five cycles, so the positive is left out);
- "current-driven" (throughput-driven), both electrodes, with the "current-driven LAM rate"
  function `-K |i|` of the applied current density `i` (A/m^2), K = CURRENT_RATE m^2/(A s)
  (PyBaMM's sets define no such function; K takes about 1 % of each electrode per cycle);
x-averaged states in the SPM and SPMe, an active material volume fraction per electrode x
volume in the DFN (PyBaMM's defaults); PyBaMM's default mesh (20 volumes per x-domain and per
particle, as ours), IDAKLU at rtol = atol = 1e-8.

Protocol: CYCLES CC-CV cycles of "Discharge at 1C until 3.0 V", "Rest for 10 minutes",
"Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes" from Chen
2020's initial state, outputs every 60 s.

Writes into the folder given (default tests/data/lam):
- `{model}_{option}.csv`: time_s, current_A, voltage_V, eps_n, eps_p (x-averaged active
  material volume fractions), lli_lam_n_mol, lli_lam_p_mol ("Loss of lithium due to loss of
  active material in negative/positive electrode [mol]"), sei_lithium_mol ("Loss of lithium
  to negative SEI [mol]", 0 without SEI), step (0-based over all cycles);
- `{model}_{option}_cycles.csv`: per cycle, the discharge capacity of its discharge step
  (A h), and at the cycle's end the negative and positive electrode capacities (A h, "Negative
  electrode capacity [A.h]") and the lithium lost with the active material in each (mol);
- `meta.json`: versions, options, parameters, protocol, timings.

    python3.11 -m venv /tmp/pyb && /tmp/pyb/bin/pip install -r scripts/requirements.txt
    /tmp/pyb/bin/python scripts/make_lam_reference.py tests/data/lam [spm,spme,dfn] [current_driven,...]

(the optional second and third arguments name the models and the options to (re)make; the
other cases stay in `meta.json`.)
"""

import json
import os
import sys
import time

import numpy as np
import pybamm

from make_cccv_reference import EXPERIMENT as CYCLE

CYCLES = 5
# The mechanical and LAM parameters PyBaMM's OKane2022 set adds to Chen 2020 (constants there).
MECHANICS_KEYS = [
    "Poisson's ratio", "Young's modulus [Pa]", "reference concentration for free of deformation [mol.m-3]",
    "partial molar volume [m3.mol-1]", "LAM constant proportional term [s-1]", "LAM constant exponential term",
    "critical stress [Pa]",
]
OPTIONS = {
    "stress_driven": {"loss of active material": "stress-driven"},
    "reaction_driven": {"loss of active material": "reaction-driven", "SEI": "reaction limited"},
    "stress_and_reaction_driven": {"loss of active material": "stress and reaction-driven", "SEI": "reaction limited"},
    "negative_stress_driven_plain_diffusion": {"loss of active material": ("stress-driven", "none"), "stress-induced diffusion": "false"},
    "current_driven": {"loss of active material": "current-driven"},
}
CURRENT_RATE = 3e-8
REACTION_FACTOR = 1e-4
# The largest "LAM constant proportional term [s-1]" of the notebook's sweep (1e-2 per hour,
# 10x OKane2022's): enough to see in a few cycles.
PROPORTIONAL_TERM = 1e-2 / 3600
MODELS = {"spm": pybamm.lithium_ion.SPM, "spme": pybamm.lithium_ion.SPMe, "dfn": pybamm.lithium_ion.DFN}


def parameters():
    """Chen 2020 with OKane2022's mechanical and LAM constants and the notebook's
    reaction-driven factor."""
    p = pybamm.ParameterValues("Chen2020")
    okane = pybamm.ParameterValues("OKane2022")
    extra = {f"{d} electrode {k}": okane[f"{d} electrode {k}"] for d in ["Negative", "Positive"] for k in MECHANICS_KEYS}
    extra["Negative electrode reaction-driven LAM factor [m3.mol-1]"] = REACTION_FACTOR
    for d in ["Negative", "Positive"]:
        extra[f"{d} electrode LAM constant proportional term [s-1]"] = PROPORTIONAL_TERM
    p.update(extra, check_already_exists=False)
    for d in ["Negative", "Positive"]:
        p.update({f"{d} electrode current-driven LAM rate": lambda i, T: -CURRENT_RATE * abs(i)}, check_already_exists=False)
    extra["current-driven LAM rate"] = f"-{CURRENT_RATE:g} * |i| (both electrodes)"
    return p, extra


def main(root):
    os.makedirs(root, exist_ok=True)
    params, extra = parameters()
    meta = {"made_by": f"PyBaMM {pybamm.__version__}, Chen2020 + OKane2022 mechanics/LAM constants, IDAKLU rtol=atol=1e-8, default mesh",
            "parameters": extra, "cycle": CYCLE, "cycles": CYCLES, "period_s": 60, "cases": {}}
    models = sys.argv[2].split(",") if len(sys.argv) > 2 else list(MODELS)
    if os.path.exists(os.path.join(root, "meta.json")):
        with open(os.path.join(root, "meta.json")) as f:
            meta["cases"] = json.load(f)["cases"]
    for mname, cls in ((m, MODELS[m]) for m in models):
        chosen = sys.argv[3].split(",") if len(sys.argv) > 3 else list(OPTIONS)
        for oname, options in ((o, OPTIONS[o]) for o in chosen):
            model = cls(dict(options))  # PyBaMM writes its defaults into the dict it is given
            sim = pybamm.Simulation(model, parameter_values=params.copy(),
                                    experiment=pybamm.Experiment([tuple(CYCLE)] * CYCLES, period="60 seconds"),
                                    solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
            start = time.perf_counter()
            sol = sim.solve()
            seconds = time.perf_counter() - start
            has_sei = "SEI" in options

            def var(name):
                return sol[name].entries

            sei = var("Loss of lithium to negative SEI [mol]") if has_sei else np.zeros_like(var("Time [s]"))
            cols = [var("Time [s]"), var("Current [A]"), var("Voltage [V]"),
                    var("X-averaged negative electrode active material volume fraction"),
                    var("X-averaged positive electrode active material volume fraction"),
                    var("Loss of lithium due to loss of active material in negative electrode [mol]"),
                    var("Loss of lithium due to loss of active material in positive electrode [mol]"), sei]
            step = np.concatenate([np.full(len(s["Time [s]"].entries), c * len(CYCLE) + k)
                                   for c, cyc in enumerate(sol.cycles) for k, s in enumerate(cyc.steps)])
            name = f"{mname}_{oname}"
            np.savetxt(os.path.join(root, f"{name}.csv"), np.column_stack(cols + [step]), delimiter=",",
                       header="time_s,current_A,voltage_V,eps_n,eps_p,lli_lam_n_mol,lli_lam_p_mol,sei_lithium_mol,step",
                       comments="", fmt="%.10g")
            rows = []
            for c, cyc in enumerate(sol.cycles):
                q = cyc.steps[0]["Discharge capacity [A.h]"].entries
                end = lambda v: cyc[v].entries[-1]
                rows.append([c + 1, q[-1] - q[0], end("Negative electrode capacity [A.h]"), end("Positive electrode capacity [A.h]"),
                             end("Loss of lithium due to loss of active material in negative electrode [mol]"),
                             end("Loss of lithium due to loss of active material in positive electrode [mol]")])
            np.savetxt(os.path.join(root, f"{name}_cycles.csv"), np.array(rows), delimiter=",",
                       header="cycle,discharge_capacity_Ah,negative_capacity_Ah,positive_capacity_Ah,lli_lam_n_mol,lli_lam_p_mol",
                       comments="", fmt="%.12g")
            meta["cases"][name] = {"model": cls.__name__, "options": options, "points": len(step),
                                   "solve_seconds": seconds, "end_time_s": float(cols[0][-1])}
            print(f"{name}: {len(step)} points, {cols[0][-1]:.0f} s, solved in {seconds:.2f} s; capacity "
                  f"{rows[0][1]:.6f} -> {rows[-1][1]:.6f} A h; eps_n {cols[3][0]:.6f} -> {cols[3][-1]:.6f}, "
                  f"eps_p {cols[4][0]:.6f} -> {cols[4][-1]:.6f}; LLI(LAM) {rows[-1][4]:.3e} / {rows[-1][5]:.3e} mol")
    with open(os.path.join(root, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/lam")
