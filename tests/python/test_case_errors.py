# Bad input from Python: a case file's error at its file:line:col, a case dict's at its key path,
# each a limber.CaseError (a ValueError) with the message the case reader gives.
import pytest
import yaml

import limber
from results_compare import assert_same_results


def slider_crank_dict(cases):
    with open(cases / "slider_crank.yaml") as text:
        return yaml.safe_load(text)


def test_a_bad_file_raises_at_its_line_and_column(cases, tmp_path):
    lines = (cases / "slider_crank.yaml").read_text().splitlines()
    row = next(k for k, line in enumerate(lines) if line.startswith("    mass: 0.3"))
    lines[row] = "    mass: -0.3"
    bad = tmp_path / "bad.yaml"
    bad.write_text("\n".join(lines) + "\n")
    with pytest.raises(limber.CaseError) as raised:
        limber.load_case(bad)
    error = raised.value
    assert isinstance(error, ValueError)
    assert (error.file, error.line, error.column) == (str(bad), row + 1, lines[row].index("-") + 1)
    assert str(error).startswith(f"{bad}:{row + 1}:{lines[row].index('-') + 1}: expected a positive number")
    assert error.key_path is None


def test_a_bad_dict_value_raises_at_its_key_path(cases):
    d = slider_crank_dict(cases)
    d["bodies"]["crank"]["mass"] = -0.3
    with pytest.raises(limber.CaseError) as raised:
        limber.case_from_dict(d)
    assert raised.value.key_path == "bodies.crank.mass"
    assert str(raised.value).startswith("bodies.crank.mass: expected a positive number")
    assert raised.value.line is None


def test_a_bad_list_item_and_a_missing_key_name_their_path(cases):
    d = slider_crank_dict(cases)
    d["joints"]["R1"]["position"] = [0, 0, "up"]
    with pytest.raises(limber.CaseError) as raised:
        limber.case_from_dict(d)
    assert raised.value.key_path == "joints.R1.position[2]"
    d = slider_crank_dict(cases)
    del d["drivers"]["D1"]["joint"]
    with pytest.raises(limber.CaseError) as raised:
        limber.case_from_dict(d)
    assert raised.value.key_path == "drivers.D1"
    assert "'joint'" in str(raised.value)


def test_a_value_yaml_cannot_hold_names_its_path(cases):
    d = slider_crank_dict(cases)
    d["bodies"]["slider"]["mass"] = object()
    with pytest.raises(limber.CaseError) as raised:
        limber.case_from_dict(d)
    assert raised.value.key_path == "bodies.slider.mass"


def test_a_good_dict_is_the_file_s_case(cases):
    from_dict = limber.case_from_dict(slider_crank_dict(cases))
    from_file = limber.load_case(cases / "slider_crank.yaml")
    assert from_dict.title == from_file.title and from_dict.file == "<dict>"
    assert from_dict.bodies == from_file.bodies == ["crank", "rod", "slider"]
    assert from_dict.joints == ["R1", "R2", "R3", "T"] and from_dict.flexible_bodies == ["rod"]
    # The same numbers: a dict is read as the file is (20 samples).
    assert_same_results(limber.run(from_dict, t_end=0.02), limber.run(from_file, t_end=0.02))


def test_bad_run_arguments_raise_case_error(cases):
    with pytest.raises(limber.CaseError, match="integrator"):
        limber.run(cases / "slider_crank.yaml", integrator="euler")
    with pytest.raises(limber.CaseError):
        limber.run(cases / "slider_crank.yaml", step=-1.0, integrator="galpha")
