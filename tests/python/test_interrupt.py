# A run stopped from Python (Ctrl-C: SIGINT; or an exception from the progress callback) raises
# that exception and leaves its results.h5 closed, readable, with status "interrupted" and the
# samples written up to the stop.
import os
import signal

import numpy as np
import pytest

import limber

STOP_AT = 0.02  # [s] of the slider-crank's 1 s, sampled every 1 ms


def test_ctrl_c_raises_keyboard_interrupt_and_closes_the_file(cases, tmp_path):
    def progress(t, t_end):
        if t >= STOP_AT:
            os.kill(os.getpid(), signal.SIGINT)  # what Ctrl-C sends

    with pytest.raises(KeyboardInterrupt):
        limber.run(cases / "slider_crank.yaml", output=tmp_path, progress=progress)
    results = limber.read_results(tmp_path)
    assert results.status == "interrupted"
    assert results.message.startswith("interrupted by KeyboardInterrupt after t = ")
    # The run stops at the sample where the signal is seen: the one that sent it, or the next
    # when Python runs its handler only at the run's check (one 1 ms sample later).
    assert STOP_AT <= results.time[-1] <= STOP_AT + 1.5e-3
    assert np.all(np.diff(results.time) > 0)
    assert results.joints["R3"].force_joint.shape == (len(results.time), 3)


def test_an_exception_in_the_progress_callback_stops_the_run(cases, tmp_path):
    class Enough(Exception):
        pass

    def progress(t, t_end):
        if t >= STOP_AT:
            raise Enough()

    with pytest.raises(Enough):
        limber.run(cases / "slider_crank.yaml", output=tmp_path, progress=progress)
    results = limber.read_results(tmp_path / "results.h5")
    assert results.status == "interrupted"
    assert results.message.startswith("interrupted by Enough after t = ")
    # The sample that raised is the last one written.
    assert results.time[-1] == min(t for t in results.time if t >= STOP_AT)
