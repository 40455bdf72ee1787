"""Multi-cycle recordings for the diagnosis's ageing candidate (issue 15 item 7), made by
PyBaMM in the diagnosis bench's format (Chen 2020, IDAKLU at rtol = atol = 1e-8, 1 mV
noise): 12 CC-CV cycles of the SPM
- g1: with SEI growth (PyBaMM's "reaction limited", its SEI exchange current x20, so that
  twelve cycles lose about 1 % of the lithium), handed the SPM without SEI: SEI named;
- g2: a control without ageing: nothing named;
- g3: 4 % less cyclable lithium from the start and no ageing: a fixed offset that does not
  drift from cycle to cycle, lithium inventory named, not SEI growth;
- g4: stress-driven loss of active material in the negative electrode (PyBaMM's
  ("stress-driven", "none") with plain particle diffusion, OKane2022's mechanics, LAM
  proportional term 10 x 1e-2 per hour): loss of active material named;
- g5: irreversible lithium plating (OKane2022's plating parameters, its rate constant x0.1)
  under 1.5C charges: plating named (PyBaMM's irreversible plating and reaction-limited SEI
  are both cathodic Tafel side reactions on the same potential difference, so a tie of the
  two is an honest answer);
- g6: reaction-limited SEI growth in the DFN (its SEI exchange current x100, 4 cycles): the
  ageing candidate on the DFN, handed the DFN without SEI: SEI named;
- g7: a DFN control over the same 4 cycles without ageing: nothing named;
- g8: irreversible lithium plating in the DFN (as g5, 4 cycles with 1.5C charges): plating
  named;
- g9: stress-driven loss of negative active material in the DFN (as g4, its proportional term
  x3 over 4 cycles): loss of active material named.

    .venv/bin/python scripts/make_ageing_cases.py tests/data/diagnosis-ageing [g6 g7 ...]
"""

import sys

import pybamm

from make_lam_reference import MECHANICS_KEYS
from make_plating_submodel_reference import PLATING_KEYS
from make_unseen_cases import chen, scaled, write_case

CYCLE = ["Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes"]
CYCLES = 12
PERIOD = 30


DFN_CYCLES = 4


def with_plating(factor):
    """Chen 2020 with OKane2022's plating parameters, its rate constant times `factor`."""
    okane = pybamm.ParameterValues("OKane2022")
    p = chen()
    p.update({k: okane[k] for k in PLATING_KEYS}, check_already_exists=False)
    return scaled(p, "Lithium plating kinetic rate constant [m.s-1]", factor)


def with_negative_lam(term):
    """Chen 2020 with OKane2022's mechanics and the negative LAM proportional term `term` (1/s)."""
    okane = pybamm.ParameterValues("OKane2022")
    p = chen()
    p.update({f"{d} electrode {k}": okane[f"{d} electrode {k}"] for d in ["Negative", "Positive"] for k in MECHANICS_KEYS},
             check_already_exists=False)
    p.update({"Negative electrode LAM constant proportional term [s-1]": term})
    return p
DFN_PERIOD = 60


def dfn_cases(root):
    """g6 and g7: SEI growth and a control on the DFN (fewer cycles: a DFN fit per cycle costs
    about ten SPM fits)."""
    lion = pybamm.lithium_ion
    steps = CYCLE * DFN_CYCLES
    p = scaled(chen(), "SEI reaction exchange current density [A.m-2]", 100.0)
    write_case(root, "g6_sei_growth_4_cycles_dfn", lion.DFN({"SEI": "reaction limited"}), p, steps,
               {"effect": "sei_growth", "candidate_model": "dfn", "accept": ["SEI"],
                "note": "reaction-limited SEI growth with PyBaMM's Chen 2020 SEI parameters, exchange current x100; 4 CC-CV cycles "
                        "(1C to 3.0 V, 10 min rest, 1C to 4.1 V, hold to C/20, 10 min rest) from the set's initial state; DFN data "
                        "and model; 60 s sampling"},
               seed=206, period=DFN_PERIOD, compare=lion.DFN())
    write_case(root, "g7_control_4_cycles_dfn", lion.DFN(), chen(), steps,
               {"effect": "none", "candidate_model": "dfn", "accept": ["no missing physics"],
                "note": "no ageing, the same 4 CC-CV cycles as g6; DFN data and model; 60 s sampling"},
               seed=207, period=DFN_PERIOD, compare=lion.DFN())
    p = with_plating(0.1)
    fast = [s.replace("Charge at 1C", "Charge at 1.5C") for s in CYCLE] * DFN_CYCLES
    write_case(root, "g8_plating_4_cycles_dfn", lion.DFN({"lithium plating": "irreversible"}), p, fast,
               {"effect": "lithium_plating", "candidate_model": "dfn", "accept": ["plating"],
                "note": "irreversible lithium plating (OKane2022's plating parameters, rate constant x0.1 = 1e-10 m/s); 4 cycles of "
                        "1C to 3.0 V, 10 min rest, 1.5C to 4.1 V, hold to C/20, 10 min rest; DFN data and model; 60 s sampling"},
               seed=208, period=DFN_PERIOD, compare=lion.DFN())
    p = with_negative_lam(30 * 1e-2 / 3600)
    lam = lion.DFN({"loss of active material": ("stress-driven", "none"), "stress-induced diffusion": "false"})
    write_case(root, "g9_lam_growth_4_cycles_dfn", lam, p, steps,
               {"effect": "active_material_loss", "candidate_model": "dfn", "accept": ["active material"],
                "note": "stress-driven loss of active material in the negative electrode, plain particle diffusion (OKane2022's "
                        "mechanical constants, LAM proportional term 30 x 1e-2 per hour), the same 4 CC-CV cycles as g6; DFN data "
                        "and model; 60 s sampling"},
               seed=209, period=DFN_PERIOD, compare=lion.DFN())


def main(root):
    lion = pybamm.lithium_ion
    steps = CYCLE * CYCLES
    p = scaled(chen(), "SEI reaction exchange current density [A.m-2]", 20.0)
    write_case(root, "g1_sei_growth_12_cycles_spm", lion.SPM({"SEI": "reaction limited"}), p, steps,
               {"effect": "sei_growth", "candidate_model": "spm", "accept": ["SEI"],
                "note": "reaction-limited SEI growth with PyBaMM's Chen 2020 SEI parameters, exchange current x20; 12 CC-CV cycles "
                        "(1C to 3.0 V, 10 min rest, 1C to 4.1 V, hold to C/20, 10 min rest) from the set's initial state; 30 s sampling"},
               seed=201, period=PERIOD, compare=lion.SPM())
    write_case(root, "g2_control_12_cycles_spm", lion.SPM(), chen(), steps,
               {"effect": "none", "candidate_model": "spm", "accept": ["no missing physics"],
                "note": "no ageing, the same 12 CC-CV cycles; 30 s sampling"},
               seed=202, period=PERIOD, compare=lion.SPM())
    p = scaled(chen(), "Initial concentration in negative electrode [mol.m-3]", 0.96)
    write_case(root, "g3_fixed_inventory_loss_12_cycles_spm", lion.SPM(), p, steps,
               {"effect": "lithium_inventory_loss", "candidate_model": "spm", "accept": ["lithium inventory"],
                "note": "4 % less lithium in the negative electrode from the start, no ageing (a fixed stoichiometry offset); "
                        "the same 12 CC-CV cycles; 30 s sampling"},
               seed=203, period=PERIOD, compare=lion.SPM())
    p = with_negative_lam(10 * 1e-2 / 3600)
    lam = lion.SPM({"loss of active material": ("stress-driven", "none"), "stress-induced diffusion": "false"})
    write_case(root, "g4_lam_growth_12_cycles_spm", lam, p, steps,
               {"effect": "active_material_loss", "candidate_model": "spm", "accept": ["active material"],
                "note": "stress-driven loss of active material in the negative electrode, plain particle diffusion (OKane2022's "
                        "mechanical constants, LAM proportional term 10 x 1e-2 per hour), the same 12 CC-CV cycles; 30 s sampling"},
               seed=204, period=PERIOD, compare=lion.SPM())
    p = with_plating(0.1)
    fast = [s.replace("Charge at 1C", "Charge at 1.5C") for s in CYCLE] * CYCLES
    write_case(root, "g5_plating_12_cycles_spm", lion.SPM({"lithium plating": "irreversible"}), p, fast,
               {"effect": "lithium_plating", "candidate_model": "spm", "accept": ["plating"],
                "note": "irreversible lithium plating (OKane2022's plating parameters, rate constant x0.1 = 1e-10 m/s); 12 cycles of "
                        "1C to 3.0 V, 10 min rest, 1.5C to 4.1 V, hold to C/20, 10 min rest; 30 s sampling"},
               seed=205, period=PERIOD, compare=lion.SPM())


if __name__ == "__main__":
    root = sys.argv[1] if len(sys.argv) > 1 else "tests/data/diagnosis-ageing"
    if "dfn" in sys.argv[2:]:
        dfn_cases(root)
    else:
        main(root)
