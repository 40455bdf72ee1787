"""PyBaMM reference for the HPPC-style pulse power (tests/suite/pulse_power.rs): the largest
constant discharge current that a Chen 2020 cell at rest at 50 % SOC sustains for 10 s before
its voltage reaches the 2.5 V cut-off, by bisection on the current with PyBaMM's experiment
(its own cut-off event ends a pulse that asks too much), IDAKLU at rtol = atol = 1e-8, the
default mesh (ours too).

    python -m venv .venv && .venv/bin/pip install pybamm==26.10.1.1
    .venv/bin/python scripts/make_pulse_reference.py tests/data/pulse_power_pybamm.json
"""

import json
import sys

import pybamm


def sustains(model, params, current, seconds=10.0, v_min=2.5):
    experiment = pybamm.Experiment([f"Discharge at {current} A for {seconds} seconds"], period="1 second")
    sim = pybamm.Simulation(model, parameter_values=params, experiment=experiment, solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
    try:
        sol = sim.solve(initial_soc=0.5)
    except Exception:
        return False
    return sol["Time [s]"].entries[-1] >= seconds - 1e-6 and sol["Voltage [V]"].entries[-1] > v_min


def main(path):
    params = pybamm.ParameterValues("Chen2020")
    out = {"made_by": f"PyBaMM {pybamm.__version__}, Chen2020, IDAKLU rtol=atol=1e-8", "soc": 0.5, "seconds": 10.0, "voltage_V": 2.5, "current_A": {}}
    # At 2.5 V the SPMe's pulse empties the electrolyte (c_e falls below 1 mol/m^3 within the
    # 10 s); at 3.2 V it does not.
    for name, model, v_min in [("spme", pybamm.lithium_ion.SPMe(), 2.5), ("dfn", pybamm.lithium_ion.DFN(), 2.5), ("spme_3.2V", pybamm.lithium_ion.SPMe(), 3.2)]:
        lo, hi = 1.0, 200.0
        while hi - lo > 1e-6 * hi:
            mid = 0.5 * (lo + hi)
            if sustains(model, params, mid, v_min=v_min):
                lo = mid
            else:
                hi = mid
        out["current_A"][name] = 0.5 * (lo + hi)
        print(name, out["current_A"][name])
    with open(path, "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/pulse_power_pybamm.json")
