# limber.modes, limber.select and limber.sweep against their commands' --json: the module and
# the command make the same library call and the same library writes both documents, so every
# field is equal except wall times and the folders given; Ctrl-C stops a study.
import os
import signal

import pytest

import limber

# The shipped flexible slider-crank with its rod meshed by 20 beams instead of 100 (the
# select tests' case, tests/select/coarse_slider_crank.h): its five lowest frequencies move by
# less than 0.1 %, and a selection runs in seconds.
COARSE_EDITS = [("elements: 100", "elements: 20"), ("R3: [101]", "R3: [21]"),
                ("{node: 51, chord", "{node: 11, chord"), ("t_end: 1.0 ", "t_end: 0.3 ")]


@pytest.fixture
def coarse_slider_crank(cases, tmp_path):
    text = (cases / "slider_crank.yaml").read_text()
    for old, new in COARSE_EDITS:
        assert old in text
        text = text.replace(old, new, 1)
    path = tmp_path / "coarse_slider_crank.yaml"
    path.write_text(text)
    return path


def without(document, keys):
    """`document` with `keys` removed at every depth (wall times, folders)."""
    if isinstance(document, dict):
        return {k: without(v, keys) for k, v in document.items() if k not in keys}
    if isinstance(document, list):
        return [without(v, keys) for v in document]
    return document


def test_modes_equals_the_command(cases, limber_cli, tmp_path):
    from_cli = limber_cli("modes", cases / "slider_crank.yaml", "-o", tmp_path / "cli", "--no-animation")
    in_process = limber.modes(cases / "slider_crank.yaml", output=tmp_path / "py")
    assert in_process == from_cli
    assert (tmp_path / "py" / "modes.h5").is_file()
    # Not an empty comparison: six rigid modes set aside, then the rod's five normal modes,
    # the lowest at 52.9 Hz (docs/select.md's table for this rod).
    kinds = [m["kind"] for m in in_process["bodies"]["rod"]["modes"]]
    assert kinds == ["rigid"] * 6 + ["normal"] * 5
    assert in_process["bodies"]["rod"]["modes"][6]["frequency_hz"] == pytest.approx(52.85, abs=0.01)


def test_select_equals_the_command(coarse_slider_crank, limber_cli, tmp_path):
    options = dict(t_end=0.15, max_single=2, target=0.05, norm="peak")
    from_cli = limber_cli("select", coarse_slider_crank, "-o", tmp_path / "cli", "--t-end", 0.15,
                          "--max-single", 2, "--target", 0.05, "--norm", "peak")
    seen = []
    in_process = limber.select(coarse_slider_crank, output=tmp_path / "py",
                               progress=lambda t, t_end: seen.append((t, t_end)), **options)
    # Every set's run is the same computation: errors, ranking and choice equal to the bit.
    timing = {"reduction_s", "run_s", "directory"}
    assert without(in_process, timing) == without(from_cli, timing)
    assert in_process["directory"] == str(tmp_path / "py")
    assert in_process["chosen"] is not None and in_process["target_met"]
    assert (tmp_path / "py" / "selected_modes.yaml").read_text() == in_process["fragment"]
    assert seen and all(t_end == 0.15 for _, t_end in seen)


def test_select_nonlinear_reference_equals_the_command(coarse_slider_crank, limber_cli, tmp_path):
    # The nonlinear body takes damping 0 or Rayleigh, not the case's ratio (docs/select.md).
    text = coarse_slider_crank.read_text()
    assert "damping: 0.01 " in text
    undamped = tmp_path / "undamped_rod.yaml"
    undamped.write_text(text.replace("damping: 0.01 ", "damping: 0 ", 1))
    options = dict(t_end=0.05, max_single=1, norm="peak")
    from_cli = limber_cli("select", undamped, "-o", tmp_path / "cli", "--t-end", 0.05, "--max-single", 1,
                          "--norm", "peak", "--reference", "nonlinear")
    in_process = limber.select(undamped, output=tmp_path / "py", reference="nonlinear", **options)
    timing = {"reduction_s", "run_s", "directory"}
    assert without(in_process, timing) == without(from_cli, timing)
    # Against the nonlinear rod: the richest modal set is one of the sets, the reference has no
    # modes (docs/select.md, "The nonlinear reference").
    names = [row["set"] for row in in_process["comparison"]]
    assert "richest" in names and "nonlinear" in names
    assert (tmp_path / "py" / "runs" / "nonlinear" / "results.h5").is_file()
    # The names are the command's: another is a CaseError, before anything runs.
    with pytest.raises(limber.CaseError, match="reference: expected modal or nonlinear, got 'exact'"):
        limber.select(undamped, output=tmp_path / "bad", reference="exact", **options)


def test_select_bad_input_raises_case_error(coarse_slider_crank, cases, tmp_path):
    with pytest.raises(limber.CaseError, match="--keep"):
        limber.select(coarse_slider_crank, output=tmp_path, keep=0.0)
    with pytest.raises(limber.CaseError, match="norm"):
        limber.select(coarse_slider_crank, output=tmp_path, norm="max")
    with pytest.raises(limber.CaseError, match="flexible body"):
        limber.select(cases / "slider_crank_rigid.yaml", output=tmp_path)


def test_sweep_equals_the_command(cases, limber_cli, tmp_path):
    case = cases / "slider_crank_rigid.yaml"
    axes = ["integrator=galpha", "step=1e-3,5e-4"]
    from_cli = limber_cli("sweep", case, "--over", *axes, "--t-end", 0.1, "-o", tmp_path / "cli")
    in_process = limber.sweep(case, over=axes, t_end=0.1, output=tmp_path / "py", jobs=1)
    timing = {"wall_s", "process_s", "peak_rss_mib", "directory", "results", "label"}
    assert without(in_process, timing) == without(from_cli, timing)
    assert [p["point"] for p in in_process["points"]] == ["galpha_step0.001", "galpha_step0.0005"]
    assert all(p["status"] == "ok" for p in in_process["points"])
    # The same call again resumes: every point kept, none rerun.
    again = limber.sweep(case, over=axes, t_end=0.1, output=tmp_path / "py", jobs=1)
    assert all(p["resumed"] for p in again["points"])


def test_sweep_bad_input_raises_case_error(cases, tmp_path):
    with pytest.raises(limber.CaseError, match="mesh"):
        limber.sweep(cases / "slider_crank_rigid.yaml", over=["mesh"], output=tmp_path)


def test_ctrl_c_stops_a_selection_and_closes_its_run(coarse_slider_crank, tmp_path):
    sent = []

    def progress(t, t_end):
        if t >= 0.02 and not sent:  # once: a second Ctrl-C would stop pytest itself
            sent.append(t)
            os.kill(os.getpid(), signal.SIGINT)  # what Ctrl-C sends

    # The selection runs on a thread of its own; Python's main thread sees the signal.
    with pytest.raises(KeyboardInterrupt):
        limber.select(coarse_slider_crank, output=tmp_path, progress=progress)
    normal = limber.read_results(tmp_path / "runs" / "normal")
    assert normal.status == "interrupted"
    # Seen within the main thread's 0.1 s look at its signals: a run of ~0.5 s for its 0.3 s
    # stops well before its end.
    assert 0.02 <= normal.time[-1] < 0.3


def test_ctrl_c_stops_a_sweep(cases, tmp_path):
    sent = []

    def log(line):
        if line.startswith("reference:") and not sent:
            sent.append(line)
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        limber.sweep(cases / "slider_crank_rigid.yaml", over=["integrator=galpha", "step=1e-3"],
                     output=tmp_path, log=log)
    # Nothing after the reference ran: no point, no table.
    assert not (tmp_path / "sweep" / "work_precision.json").exists()
