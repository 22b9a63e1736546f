# limber.run against `limber run`: the same code writes the same results.h5, so every series is
# equal bit for bit (run/case_run.h is shared; nothing may differ, not even round-off).
import numpy as np

import limber
from results_compare import assert_same_results

T_END = 0.05  # 50 samples of the slider-crank (1 ms), inside its spin-up: a run of ~0.1 s


def test_slider_crank_equals_the_command_bit_for_bit(cases, limber_cli, tmp_path):
    record = limber_cli("run", cases / "slider_crank.yaml", "--t-end", T_END, "-o", tmp_path / "cli")
    from_cli = limber.read_results(tmp_path / "cli")
    in_memory = limber.run(cases / "slider_crank.yaml", t_end=T_END)
    assert_same_results(in_memory, from_cli)
    assert in_memory.path is None
    # What the command reported, read back: the run went to T_END with every sample.
    assert from_cli.status == record["status"] == "ok"
    assert from_cli.time[-1] == record["t_reached"] == T_END
    assert len(from_cli.time) == record["samples"] == 51
    # Not an empty comparison: the rod carries the slider's inertia, R3 loads it in x.
    assert np.abs(in_memory.joints["R3"].force_joint).max() > 1.0
    assert in_memory.bodies["rod"].modal_coordinates.shape == (51, 5)
    assert in_memory.bodies["rod"].deflection.shape == (51, 3)


def test_overrides_and_output_folder_give_the_command_s_file(cases, limber_cli, tmp_path):
    limber_cli("run", cases / "slider_crank.yaml", "--t-end", 0.02, "--integrator", "ida",
               "--rtol", 1e-6, "-o", tmp_path / "cli")
    case = limber.load_case(cases / "slider_crank.yaml")
    kept = limber.run(case, integrator="ida", rtol=1e-6, t_end=0.02, output=tmp_path / "py")
    assert kept.path == str(tmp_path / "py" / "results.h5") and kept.integrator == "ida"
    assert_same_results(kept, limber.read_results(tmp_path / "cli" / "results.h5"))
    assert_same_results(kept, limber.read_results(kept.path))


def test_galpha_step_override(cases, limber_cli, tmp_path):
    limber_cli("run", cases / "slider_crank_rigid.yaml", "--t-end", 0.02, "--integrator", "galpha",
               "--step", 1e-3, "-o", tmp_path / "cli")
    run = limber.run(cases / "slider_crank_rigid.yaml", integrator="galpha", step=1e-3, t_end=0.02)
    assert_same_results(run, limber.read_results(tmp_path / "cli"))


def test_satellite_equals_the_command_bit_for_bit(cases, limber_cli, tmp_path):
    # The deployment's start: static equilibrium on the hold-downs, four shell panels, latches
    # and stops (their angles, torques and switches compared too); 0.05 s of it, a few seconds.
    record = limber_cli("run", cases / "satellite_deployment.yaml", "--t-end", 0.05, "-o", tmp_path / "cli")
    run = limber.run(cases / "satellite_deployment.yaml", t_end=0.05)
    assert_same_results(run, limber.read_results(tmp_path / "cli"))
    assert run.status == record["status"] and len(run.time) == record["samples"]
    assert len(run.hinge_limits) > 0 and len(run.bodies) > 4
