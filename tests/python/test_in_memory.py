# limber.run(output=None) keeps results.h5 in memory (results::InMemoryFile, an HDF5 file image):
# the writer and the reader of output=DIR, so the same numbers bit for bit, and nothing on disk,
# neither while the run goes (no temporary folder) nor after (no file beside a results.h5).
import os

import numpy as np
import pytest

import limber
from results_compare import assert_same_results


@pytest.fixture
def empty_places(tmp_path, monkeypatch):
    """An empty current folder and an empty TMPDIR (where a temporary folder would go)."""
    places = [tmp_path / "cwd", tmp_path / "tmp"]
    for place in places:
        place.mkdir()
    monkeypatch.chdir(places[0])
    monkeypatch.setenv("TMPDIR", str(places[1]))
    return places


def run_writing_nothing(case, places, **options):
    """limber.run(case, output=None) checked at every sample and at the end: places stay empty."""
    seen = []

    def progress(t, t_end):
        seen.append([entry for place in places for entry in os.listdir(place)])

    results = limber.run(case, progress=progress, **options)
    assert len(seen) == len(results.time) > 1 and not any(seen)
    assert [os.listdir(place) for place in places] == [[], []]
    assert results.path is None
    return results


def test_slider_crank_in_memory_equals_the_output_folder(cases, empty_places, tmp_path):
    in_memory = run_writing_nothing(cases / "slider_crank.yaml", empty_places, t_end=0.05)
    on_disk = limber.run(cases / "slider_crank.yaml", t_end=0.05, output=tmp_path / "out")
    assert on_disk.path == str(tmp_path / "out" / "results.h5")
    assert_same_results(in_memory, on_disk)
    # Not an empty comparison: 51 samples, the flexible rod moving, R3 loaded.
    assert len(in_memory.time) == 51 and np.abs(in_memory.joints["R3"].force_joint).max() > 1.0
    assert np.abs(in_memory.bodies["rod"].modal_coordinates).max() > 0.0


def test_satellite_in_memory_equals_the_output_folder(cases, empty_places, tmp_path):
    # Its acceleration probes make a run write shock spectra beside results.h5 (a CSV file):
    # kept in the file in memory, not written to the current folder.
    in_memory = run_writing_nothing(cases / "satellite_deployment.yaml", empty_places, t_end=0.05)
    on_disk = limber.run(cases / "satellite_deployment.yaml", t_end=0.05, output=tmp_path / "out")
    assert_same_results(in_memory, on_disk)
    assert len(os.listdir(tmp_path / "out")) > 1  # results.h5 and what a folder run adds
    assert len(in_memory.hinge_limits) > 0 and len(in_memory.acceleration_probes) > 0


def test_in_memory_runs_on_threads_keep_their_own_files(cases):
    # Two files in memory at once (HDF5 tells them apart by name): each run reads back its own.
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(max_workers=2) as pool:
        rigid, flexible = pool.map(lambda case: limber.run(cases / case, t_end=0.02),
                                   ["slider_crank_rigid.yaml", "slider_crank.yaml"])
    assert rigid.bodies["rod"].kind == "rigid" and flexible.bodies["rod"].kind == "flexible"
    assert_same_results(flexible, limber.run(cases / "slider_crank.yaml", t_end=0.02))
