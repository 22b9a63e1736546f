# Two threads running two cases side by side (the GIL released while they integrate) give the
# numbers of the same runs one after the other, bit for bit: a run shares nothing mutable with
# another (the model is its own; ARPACK and HDF5, which hold global state, are locked in the
# libraries).
import threading

import limber
from results_compare import assert_same_results

RUNS = [("slider_crank.yaml", dict(t_end=0.05)),
        ("slider_crank_seed_setup.yaml", dict(t_end=0.02))]


def test_two_threads_give_the_numbers_of_two_runs_in_turn(cases):
    in_turn = [limber.run(cases / name, **options) for name, options in RUNS]
    side_by_side = [None] * len(RUNS)
    started = threading.Barrier(len(RUNS))

    def run(k):
        name, options = RUNS[k]
        started.wait()
        side_by_side[k] = limber.run(cases / name, **options)

    threads = [threading.Thread(target=run, args=(k,)) for k in range(len(RUNS))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for a, b in zip(side_by_side, in_turn):
        assert_same_results(a, b)


def test_a_progress_callback_sees_every_sample_from_a_thread(cases):
    seen = []
    worker = threading.Thread(target=lambda: seen.append(
        limber.run(cases / "slider_crank.yaml", t_end=0.01, progress=lambda t, t_end: seen.append((t, t_end)))))
    worker.start()
    worker.join()
    results = seen.pop()
    # One call per sample written (t = 0 included), at the samples' times.
    assert [t for t, _ in seen] == list(results.time)
    assert all(t_end == 0.01 for _, t_end in seen)
