"""Results of the study runs: the outcome as a dict (``.data``) with the useful parts as
attributes and DataFrames. Plain Python objects, so they pickle."""

import json


def _frame(rows):
    import pandas as pd

    return pd.DataFrame(rows)


def _flat(prefix, metrics):
    """Design metrics as columns; nested ones (the fast charge) flattened with ``.``."""
    out = {}
    for key, value in (metrics or {}).items():
        if isinstance(value, dict):
            out.update(_flat(f"{prefix}{key}.", value))
        else:
            out[f"{prefix}{key}"] = value
    return out


class Result:
    """A run's outcome: ``data`` (everything the run returned), ``files`` it wrote,
    ``warnings`` (also in its report)."""

    def __init__(self, data):
        self.data = data

    @property
    def files(self):
        return self.data.get("files", [])

    @property
    def warnings(self):
        return self.data.get("warnings", [])

    def __repr__(self):
        return f"{type(self).__name__}({self.data.get('study', '')!r})"


class DesignResult(Result):
    """``cellstudio design``: ``value`` of the metric at the optimum ``x`` (dict of the
    decision variables, SI units), ``initial_value`` at the baseline, ``improvement`` (%)."""

    @property
    def x(self):
        return dict(zip(self.data["variables"], self.data["x"]))

    @property
    def initial_x(self):
        return dict(zip(self.data["variables"], self.data["initial_x"]))

    @property
    def value(self):
        return self.data["optimised_value"]

    @property
    def initial_value(self):
        return self.data["initial_value"]

    @property
    def improvement(self):
        return self.data["improvement_percent"]

    def to_pandas(self):
        """Baseline and optimum side by side: decision variables, then every metric."""
        rows = []
        for label, x, m in (("initial", self.initial_x, self.data["initial"]), ("optimised", self.x, self.data["optimised"])):
            rows.append({"design": label, **x, **_flat("", m)})
        return _frame(rows).set_index("design")


class SweepResult(Result):
    """``cellstudio sweep``: ``to_pandas()`` has a row per point (variables, status, error,
    metrics); ``best`` the best valid point per energy density."""

    @property
    def best(self):
        return self.data["best"]

    def to_pandas(self):
        names = self.data["variables"]
        rows = [{**dict(zip(names, p["x"])), "status": p["status"], "error": p.get("error"), **_flat("", p.get("metrics"))} for p in self.data["points"]]
        return _frame(rows)


class ParetoResult(Result):
    """``cellstudio pareto``: ``to_pandas()`` has a row per non-dominated design."""

    def to_pandas(self):
        names = self.data["variables"]
        objectives = self.data["objectives"]
        return _frame([{**dict(zip(names, ind["x"])), **dict(zip(objectives, ind["f"]))} for ind in self.data["front"]])


class FitResult(Result):
    """``cellstudio fit``: fitted ``values`` and ``std_errors`` by parameter path, ``rmse`` (V)."""

    @property
    def values(self):
        r = self.data["result"]
        return dict(zip(r["names"], r["x"]))

    @property
    def std_errors(self):
        r = self.data["result"]
        return dict(zip(r["names"], r["std_errors"]))

    @property
    def rmse(self):
        return self.data["result"]["rmse"]

    @property
    def table(self):
        return self.data["table"]

    def to_pandas(self):
        r = self.data["result"]
        errors = r["std_errors"] + [float("nan")] * (len(r["names"]) - len(r["std_errors"]))
        return _frame({"parameter": r["names"], "value": r["x"], "std_error": errors}).set_index("parameter")


class SampleResult(Result):
    """``cellstudio sample``: the posterior summary per parameter (``to_pandas()``)."""

    @property
    def table(self):
        return self.data["table"]

    def to_pandas(self):
        return _frame(self.data["summary"]["parameters"]).set_index("name")


class ParameterisationResult(Result):
    """``cellstudio parameterise``: each stage's results by key (``stages["balancing"]``), the
    one-line ``summary`` per stage, and ``parameters``, the set the stages leave."""

    @property
    def stages(self):
        return self.data["stages"]

    @property
    def summary(self):
        return self.data["summary"]

    @property
    def parameters(self):
        from ._parameters import ParameterSet

        return ParameterSet.from_json(json.dumps(self.data["parameters"]))


class CycleResult(Result):
    """``cellstudio cycle``: ``to_pandas()`` has a row per cycle (capacities in A h,
    retention, lithium lost, SEI thickness); ``fade_fit`` the fitted values when asked."""

    @property
    def cycles(self):
        return self.data["cycles"]

    @property
    def retention(self):
        return self.cycles[-1]["capacity_retention"]

    @property
    def fade_fit(self):
        fit = self.data.get("fade_fit")
        return None if fit is None else {"values": dict(zip(fit["names"], fit["values"])), "std_errors": dict(zip(fit["names"], fit["std_errors"]))}

    def to_pandas(self):
        return _frame(self.cycles).set_index("cycle")


class DiagnosisResult(Result):
    """``cellstudio diagnose``: ``verdict`` (the first round's verdict in words),
    ``conclusion`` over all rounds, ``fitted`` values of each round's named candidate,
    ``report_path`` (``diagnosis.md``), ``markdown`` of each round."""

    @property
    def rounds(self):
        return self.data["rounds"]

    @property
    def verdict(self):
        return self.rounds[0]["summary"]

    @property
    def conclusion(self):
        return self.data["conclusion"]

    @property
    def fitted(self):
        out = []
        for d in self.rounds:
            named = [c for c in d["candidates"] if c["named"] and c.get("fit")]
            out.append({c["name"]: dict(zip(c["fit"]["names"], c["fit"]["values"])) for c in named[:1]})
        return out

    @property
    def markdown(self):
        return self.data["markdown"]

    @property
    def report_path(self):
        return next((f for f in self.files if f.endswith("diagnosis.md")), None)

    def __repr__(self):
        return f"DiagnosisResult({self.conclusion!r})"
