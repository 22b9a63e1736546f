# mypy against the type stubs (limber.pyi beside the built module). A single-module stub is not
# a PEP 561 package: mypy finds it through MYPYPATH, which this test sets to the module's folder
# itself (docs/python.md, "Type stubs"). A study written as docs/python.md writes it checks clean,
# and the same study with a wrong argument type fails naming that argument: what mypy read is the
# stub, not an untyped module (which would pass both).
import os
import pathlib
import shutil
import subprocess

import pytest

import limber

MODULE_DIR = pathlib.Path(limber.__file__).parent

STUDY = """
import limber

case = limber.load_case("cases/slider_crank.yaml")
results = limber.run(case, integrator="galpha", step={step}, t_end=0.1)
peak: float = float(abs(results.joints["R3"].force_ground).max())
status: str = results.status
"""


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    """One mypy cache for the module's checks (the second reads numpy's stubs from it)."""
    return tmp_path_factory.mktemp("mypy-cache")


def mypy(tmp_path, cache, source):
    """mypy's exit code and output on `source`, with MYPYPATH set to the module's folder."""
    if shutil.which("mypy") is None:
        pytest.skip("mypy not installed (Debian mypy: scripts/install-deps.sh --tests)")
    script = tmp_path / "study.py"
    script.write_text(source)
    checked = subprocess.run(
        ["mypy", "--cache-dir", str(cache), str(script)],
        env=dict(os.environ, MYPYPATH=str(MODULE_DIR)), capture_output=True, text=True, check=False)
    return checked.returncode, checked.stdout + checked.stderr


def test_stub_is_found_through_mypypath():
    assert (MODULE_DIR / "limber.pyi").is_file()


def test_a_study_as_the_docs_write_it_checks_clean(tmp_path, cache):
    code, output = mypy(tmp_path, cache, STUDY.format(step="1e-4"))
    assert code == 0, output


def test_a_wrong_argument_type_is_reported(tmp_path, cache):
    code, output = mypy(tmp_path, cache, STUDY.format(step='"fast"'))
    assert code == 1, output
    assert 'Argument "step" to "run" has incompatible type "str"' in output, output
