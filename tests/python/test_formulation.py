# limber.run(..., formulation="nonlinear") against `limber run --formulation nonlinear`: the same
# override (run/case_run.h, io/formulation_override.h) turns the modal rod of the seed set-up into
# the co-rotational one, so the two files are equal bit for bit; a formulation that does not
# exist is a CaseError.
import numpy as np
import pytest

import limber
from results_compare import assert_same_results

# 30 generalized-alpha steps of 0.1 ms of the 100-element rod: a few seconds. (The case's IDA,
# set for the modal rod, takes 9 226 steps over these 3 ms of the nonlinear one, ~30 s.)
T_END = 0.003


def test_nonlinear_formulation_equals_the_command_bit_for_bit(cases, limber_cli, tmp_path):
    case = cases / "slider_crank_seed_setup.yaml"
    record = limber_cli("run", case, "--formulation", "nonlinear", "--integrator", "galpha", "--t-end", T_END,
                        "-o", tmp_path / "cli")
    run = limber.run(case, formulation="nonlinear", integrator="galpha", t_end=T_END)
    assert_same_results(run, limber.read_results(tmp_path / "cli"))
    assert run.status == record["status"] == "ok"
    # Not the modal rod: no modal coordinates, and the deflection differs from the modal run's.
    rod = run.bodies["rod"]
    assert rod.modal_coordinates.shape == (len(run.time), 0)
    modal = limber.run(case, t_end=T_END)
    assert modal.bodies["rod"].modal_coordinates.shape == (len(run.time), 5)
    assert np.abs(rod.deflection - modal.bodies["rod"].deflection).max() > 0.0
    # 'modal' keeps the case's formulation: the modal run again, bit for bit.
    assert_same_results(limber.run(case, formulation="modal", t_end=T_END), modal)


def test_unknown_formulation_is_a_case_error(cases):
    with pytest.raises(limber.CaseError, match="expected modal or nonlinear, got 'exact'"):
        limber.run(cases / "slider_crank_seed_setup.yaml", formulation="exact", t_end=0.0)
