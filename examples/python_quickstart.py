"""cellstudio from Python, for a PyBOP user: the seed design optimisation and the
contact-resistance fit, each beside the PyBOP code that does the same (comments only;
PyBOP is not needed).

    pip install ./python pandas
    python examples/python_quickstart.py        # from the repository root

Every value is in SI units; outputs go to out/python_quickstart/.
"""

import cellstudio as cs

# --- 1. Parameters and a simulation ---------------------------------------------------------
# PyBOP / PyBaMM:
#   parameter_set = pybamm.ParameterValues("Chen2020")
#   parameter_set.update({"Positive electrode thickness [m]": 70e-6})
#   model = pybamm.lithium_ion.DFN(parameter_values=parameter_set)
#   experiment = pybamm.Experiment(["Discharge at 1C until 2.5 V", "Rest for 10 minutes"])
#   solution = pybamm.Simulation(model, experiment=experiment).solve()
ps = cs.ParameterSet.from_pybamm({"Positive electrode thickness [m]": 70e-6})
solution = cs.simulate("dfn", ps, ["Discharge at 1C until 2.5 V", "Rest for 10 minutes"])
print(solution, f"in {solution.summary['solve_time_s'] * 1e3:.1f} ms")
print(solution.to_pandas().tail(3))

# --- 2. Design optimisation: maximise W h/kg over positive thickness and active fraction ----
# PyBOP:
#   parameter_set = pybop.ParameterSet.pybamm("Chen2020", formation_concentrations=True)
#   model = pybop.lithium_ion.SPMe(parameter_set=parameter_set)
#   parameters = pybop.Parameters(
#       pybop.Parameter("Positive electrode thickness [m]", initial_value=75.6e-6, bounds=[50e-6, 110e-6]),
#       pybop.Parameter("Positive electrode active material volume fraction", initial_value=0.665, bounds=[0.5, 0.8]),
#   )
#   experiment = pybop.Experiment(["Discharge at 1C until 2.5 V"])
#   problem = pybop.DesignProblem(model, parameters, experiment, update_capacity=True)
#   cost = pybop.GravimetricEnergyDensity(problem)
#   optim = pybop.NelderMead(cost, max_iterations=60)
#   x, final_cost = optim.run()
# Here the same study is a file (designs/gravimetric_chen2020.toml: variables, the porosity
# tie, the objective, the optimiser), run as `cellstudio design` runs it:
study = cs.DesignStudy.from_file("designs/gravimetric_chen2020.toml")
design = study.run(out="out/python_quickstart/design")
print(f"{design.initial_value:.1f} -> {design.value:.1f} W h/kg ({design.improvement:+.1f} %) at {design.x}")
print(design.to_pandas()[["positive.thickness", "positive.active_fraction", "gravimetric_energy_density", "volumetric_energy_density"]])
grid = study.sweep(out="out/python_quickstart/sweep").to_pandas()  # the 13 x 13 grid as a DataFrame
print(f"best of the {len(grid)} grid points: {grid['gravimetric_energy_density'].max():.1f} W h/kg")

# --- 3. Fitting: negative diffusivity and contact resistance from a noisy SPM curve ----------
# PyBOP:
#   model = pybop.lithium_ion.SPM(parameter_set=parameter_set, options={"contact resistance": "true"})
#   parameters = pybop.Parameters(
#       pybop.Parameter("Negative particle diffusivity [m2.s-1]", initial_value=6.6e-14, bounds=[1e-15, 1e-12],
#                       prior=pybop.LogNormal(-30.6, 1.0), transformation=pybop.LogTransformation()),
#       pybop.Parameter("Contact resistance [Ohm]", initial_value=0.005, bounds=[1e-4, 0.1],
#                       transformation=pybop.LogTransformation()),
#   )
#   dataset = pybop.Dataset({"Time [s]": t, "Current function [A]": i, "Voltage [V]": v})
#   problem = pybop.FittingProblem(model, parameters, dataset)
#   cost = pybop.SumSquaredError(problem)
#   optim = pybop.SciPyMinimize(cost, method="L-BFGS-B")
#   x, final_cost = optim.run()
#   sampler = pybop.HaarioBardenetACMC(pybop.LogPosterior(pybop.GaussianLogLikelihood(problem)), chains=4)
fitted = cs.fit("fits/spm_contact_resistance.toml", out="out/python_quickstart/fit")
print(fitted.table)
print(f"R = {fitted.values['cell.contact_resistance'] * 1e3:.2f} mOhm, RMSE {fitted.rmse * 1e3:.3f} mV")
posterior = cs.sample("fits/spm_contact_resistance.toml", out="out/python_quickstart/sample", sampler={"chains": 2, "iterations": 1000, "warmup": 500})
print(posterior.to_pandas()[["mean", "sd", "q2_5", "q97_5", "rhat"]])

# --- 4. What is the model missing? (no PyBOP equivalent) ------------------------------------
import pandas as pd  # noqa: E402

recording = pd.read_csv("tests/data/diagnosis-bench/b2_electrolyte_2C/recording.csv")
diagnosis = cs.diagnose(recording, model="spm", out="out/python_quickstart/diagnosis")
print(diagnosis.verdict)
print("report:", diagnosis.report_path)
