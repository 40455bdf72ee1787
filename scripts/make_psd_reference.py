"""PyBaMM reference for the particle-size distribution submodel (tests/suite/psd_reference.rs):
PyBaMM's many-particle model (`pybamm.lithium_ion.MPM()`: its SPM with "particle size" =
"distribution" and "surface form" = "algebraic") on Chen 2020 with
`pybamm.get_size_distribution_parameters` (lognormal, area-weighted mean at the set's particle
radius, radii from max(0, 1 - 5 sd) to 1 + 5 sd times it), isothermal, from the set's initial
concentrations. PyBaMM's default mesh: 20 volumes per particle, 30 particle sizes per electrode
(var_pts R_n, R_p). IDAKLU at rtol = atol = 1e-8, outputs every 10 s.

Cases (relative standard deviation negative / positive, ambient = initial temperature):
- `mpm_1c`: 0.3 / 0.3, 25 degC, "Discharge at 1C until 2.5 V";
- `mpm_pulse`: 0.3 / 0.3, 25 degC, 4 x ("Discharge at 2C for 3 minutes", "Rest for 20 minutes");
- `mpm_1c_15degc`: 0.3 / 0.3, 15 degC, "Discharge at 1C until 2.5 V";
- `mpm_2c_mixed`: 0.15 / 0.45, 25 degC, "Discharge at 2C until 2.5 V", "Rest for 30 minutes";
- `mpm_thermal`: 0.3 / 0.3, 25 degC ambient, "thermal" = "lumped" (total heat-transfer
  coefficient 12 W/(m^2 K)), "Discharge at 2C until 2.5 V", "Rest for 30 minutes"; with the
  "X-averaged cell temperature [K]" as a fifth column.

Writes into the folder given (default tests/data/psd):
- `{case}.csv`: time_s, current_A, voltage_V, step (0-based)[, temperature_K];
- `meta.json`: versions, options, parameters, protocols, the size meshes, timings.

    /tmp/pyb/bin/python scripts/make_psd_reference.py tests/data/psd
"""

import json
import os
import sys
import time

import numpy as np
import pybamm

PULSE = ["Discharge at 2C for 3 minutes", "Rest for 20 minutes"]
# name: (relative std negative, positive, ambient (K), experiment steps, lumped thermal)
CASES = {
    "mpm_1c": (0.3, 0.3, 298.15, ["Discharge at 1C until 2.5 V"], False),
    "mpm_pulse": (0.3, 0.3, 298.15, PULSE * 4, False),
    "mpm_1c_15degc": (0.3, 0.3, 288.15, ["Discharge at 1C until 2.5 V"], False),
    "mpm_2c_mixed": (0.15, 0.45, 298.15, ["Discharge at 2C until 2.5 V", "Rest for 30 minutes"], False),
    "mpm_thermal": (0.3, 0.3, 298.15, ["Discharge at 2C until 2.5 V", "Rest for 30 minutes"], True),
}
H = 12.0


def parameters(sd_n, sd_p, ambient):
    p = pybamm.ParameterValues("Chen2020")
    p = pybamm.get_size_distribution_parameters(p, sd_n=sd_n, sd_p=sd_p)
    p.update({"Ambient temperature [K]": ambient, "Initial temperature [K]": ambient,
              "Total heat transfer coefficient [W.m-2.K-1]": H})
    return p


def main(root):
    os.makedirs(root, exist_ok=True)
    meta = {"made_by": f"PyBaMM {pybamm.__version__}, MPM, Chen2020 + get_size_distribution_parameters, IDAKLU rtol=atol=1e-8, default mesh",
            "heat_transfer_coefficient_W_m2K": H,
            "var_pts": {k: v for k, v in pybamm.lithium_ion.MPM().default_var_pts.items() if k in ("r_n", "r_p", "R_n", "R_p")},
            "period_s": 10, "cases": {}}
    for name, (sd_n, sd_p, ambient, steps, thermal) in CASES.items():
        model = pybamm.lithium_ion.MPM({"thermal": "lumped"} if thermal else None)
        sim = pybamm.Simulation(model, parameter_values=parameters(sd_n, sd_p, ambient),
                                experiment=pybamm.Experiment(steps, period="10 seconds"),
                                solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
        start = time.perf_counter()
        sol = sim.solve()
        seconds = time.perf_counter() - start
        cols = [sol[v].entries for v in ("Time [s]", "Current [A]", "Voltage [V]")]
        step = np.concatenate([np.full(len(cyc["Time [s]"].entries), c) for c, cyc in enumerate(sol.cycles)])
        header = "time_s,current_A,voltage_V,step"
        cols.append(step)
        if thermal:
            cols.append(sol["X-averaged cell temperature [K]"].entries)
            header += ",temperature_K"
        np.savetxt(os.path.join(root, f"{name}.csv"), np.column_stack(cols), delimiter=",",
                   header=header, comments="", fmt="%.10g")
        radii = {d: sol[f"{d.capitalize()} particle sizes [m]"].entries[:, 0].tolist() for d in ("negative", "positive")}
        meta["cases"][name] = {"relative_std": [sd_n, sd_p], "ambient_K": ambient, "steps": steps, "thermal": thermal,
                               "options": {k: str(model.options[k]) for k in ("particle size", "surface form")},
                               "radii_first_last_m": {d: [r[0], r[-1]] for d, r in radii.items()},
                               "points": len(step), "solve_seconds": seconds, "end_time_s": float(cols[0][-1])}
        print(f"{name}: {len(step)} points, {cols[0][-1]:.0f} s, solved in {seconds:.2f} s, V {cols[2][0]:.6f} .. {cols[2][-1]:.6f}")
    with open(os.path.join(root, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/psd")
