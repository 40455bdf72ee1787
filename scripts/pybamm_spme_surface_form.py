"""Why PyBaMM's SPMe cannot make a case with non-default kinetics (docs/pybamm_equations.md
1.2.1, ak7 in docs/diagnosis-cases.md). PyBaMM's SPM family switches to "surface form" =
"algebraic" for any non-default "intercalation kinetics"; for the SPMe that is another model.
Prints, with PyBaMM at rtol = atol = 1e-8 on Chen 2020:
- a 2C discharge to 2.5 V (outputs every 10 s): the asymmetric SPMe at alpha = 0.5 and the
  algebraic-surface-form SPMe against PyBaMM's SPMe and DFN, and the same for the SPM;
- ak7's protocol (scripts/make_unseen_cases.py, 2 degC, the tow-winch day): the voltage RMS
  of the asymmetry alone (alpha 0.4 against 0.5, both asymmetric SPMe), of the surface form
  alone (asymmetric at 0.5 against the SPMe) and of both (what ak7 recorded, less noise).

    /tmp/pyb/bin/python scripts/pybamm_spme_surface_form.py
"""

import os
import sys

import numpy as np
import pybamm

sys.path.insert(0, os.path.dirname(__file__))
import make_unseen_cases as cases  # noqa: E402

lion = pybamm.lithium_ion
ASYM = {"intercalation kinetics": "asymmetric Butler-Volmer"}


def voltage(model, params, steps, initial_soc=None, period=10.0):
    sim = pybamm.Simulation(model, parameter_values=params, experiment=pybamm.Experiment(steps),
                            solver=pybamm.IDAKLUSolver(rtol=1e-8, atol=1e-8))
    sol = sim.solve(initial_soc=initial_soc)
    t = np.arange(0.0, sol["Time [s]"].entries[-1], period)
    return sol["Voltage [V]"](t)


def with_alpha(p, alpha_n):
    p.update({"Negative electrode Butler-Volmer transfer coefficient": alpha_n,
              "Positive electrode Butler-Volmer transfer coefficient": 0.5}, check_already_exists=False)
    return p


def rms(a, b):
    n = min(len(a), len(b))
    return 1e3 * np.sqrt(np.mean((a[:n] - b[:n]) ** 2))


def main():
    steps = ["Discharge at 2C until 2.5 V"]
    p = lambda: with_alpha(pybamm.ParameterValues("Chen2020"), 0.5)
    dfn = voltage(lion.DFN(), p(), steps)
    for name, cls in (("SPM", lion.SPM), ("SPMe", lion.SPMe)):
        plain = voltage(cls(), p(), steps)
        asym = voltage(cls(ASYM), p(), steps)
        algebraic = voltage(cls({"surface form": "algebraic"}), p(), steps)
        print(f"2C, {name}: asymmetric at 0.5 vs {name} {rms(asym, plain):.2f} mV, algebraic surface form vs {name} "
              f"{rms(algebraic, plain):.2f} mV; vs the DFN: {name} {rms(plain, dfn):.2f}, asymmetric {rms(asym, dfn):.2f} mV")
    steps = ["Rest for 10 minutes"] + cases.paraglider_winch_steps(3607, 12) + ["Rest for 30 minutes"]
    p = lambda a: with_alpha(cases.at_temperature(pybamm.ParameterValues("Chen2020"), 2), a)
    a04, a05 = (voltage(lion.SPMe(ASYM), p(a), steps, 0.9) for a in (0.4, 0.5))
    plain = voltage(lion.SPMe(), p(0.5), steps, 0.9)
    print(f"ak7's protocol, SPMe: asymmetry alone {rms(a04, a05):.2f} mV, surface form alone {rms(a05, plain):.2f} mV, "
          f"both (ak7's recording) {rms(a04, plain):.2f} mV")
    d04, d05 = (voltage(lion.DFN(ASYM), p(a), steps, 0.9) for a in (0.4, 0.5))
    print(f"ak7's protocol, DFN: asymmetry alone {rms(d04, d05):.2f} mV")


if __name__ == "__main__":
    main()
