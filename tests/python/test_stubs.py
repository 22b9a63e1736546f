# The type stubs (solver/python/limber.pyi, copied beside the built module) against the module
# itself: every public function, class, attribute and argument of the one is in the other, with
# the same kinds (positional, keyword-only) and the same defaults. The module's signatures are
# those pybind11 writes on the first line of each function's docstring.
import ast
import pathlib

import pytest

import limber

STUB = pathlib.Path(limber.__file__).parent / "limber.pyi"


def stub_tree():
    return ast.parse(STUB.read_text(), filename=str(STUB))


def public(name):
    return not name.startswith("_")


def stub_definitions():
    """name -> its ast node, for the stub's top-level public functions and classes."""
    return {node.name: node for node in stub_tree().body
            if isinstance(node, (ast.FunctionDef, ast.ClassDef)) and public(node.name)}


def parameters(function):
    """[(name, kind, default)] of an ast function; kind 'positional' or 'keyword'; default the
    literal value, or the string '<none given>' when there is none."""
    args = function.args
    positional = args.posonlyargs + args.args
    defaults = [None] * (len(positional) - len(args.defaults)) + list(args.defaults)
    rows = [(a.arg, "positional", d) for a, d in zip(positional, defaults)]
    rows += [(a.arg, "keyword", d) for a, d in zip(args.kwonlyargs, args.kw_defaults)]
    return [(name, kind, "<none given>" if d is None else ast.literal_eval(d)) for name, kind, d in rows]


def module_signature(function):
    """The pybind11 signature of a module function, parsed as a Python definition."""
    first_line = function.__doc__.splitlines()[0]
    assert first_line.startswith(function.__name__ + "("), first_line
    return ast.parse(f"def {first_line}: ...").body[0]


def test_every_public_name_of_the_module_is_in_the_stub_and_back():
    in_module = {name for name in dir(limber) if public(name)}
    assert in_module == set(stub_definitions())
    # Not an empty comparison: the functions and classes the docs name are there.
    assert {"run", "read_results", "load_case", "case_from_dict", "modes", "select", "sweep",
            "Results", "Case", "CaseError"} <= in_module
    version = [node for node in stub_tree().body
               if isinstance(node, ast.AnnAssign) and node.target.id == "__version__"]
    assert len(version) == 1 and isinstance(limber.__version__, str)


@pytest.mark.parametrize("name", sorted(n for n, node in stub_definitions().items()
                                        if isinstance(node, ast.FunctionDef)))
def test_function_arguments_kinds_and_defaults_match(name):
    stub = parameters(stub_definitions()[name])
    real = parameters(module_signature(getattr(limber, name)))
    assert stub == real
    assert stub, name  # every function takes an argument


@pytest.mark.parametrize("name", sorted(n for n, node in stub_definitions().items()
                                        if isinstance(node, ast.ClassDef) and n != "CaseError"))
def test_class_attributes_match(name):
    node = stub_definitions()[name]
    in_stub = {item.name for item in node.body if isinstance(item, ast.FunctionDef) and public(item.name)}
    cls = getattr(limber, name)
    in_module = {attribute for attribute, value in vars(cls).items()
                 if public(attribute) and isinstance(value, property)}
    assert in_stub == in_module and in_module
    # Every attribute is a property in the stub (read-only, as in the module).
    for item in node.body:
        if isinstance(item, ast.FunctionDef):
            assert [d.id for d in item.decorator_list] == ["property"], f"{name}.{item.name}"


def test_case_error_attributes_match(tmp_path):
    node = stub_definitions()["CaseError"]
    in_stub = {item.target.id for item in node.body if isinstance(item, ast.AnnAssign)}
    bad = tmp_path / "bad.yaml"
    bad.write_text("title: [unclosed\n")
    with pytest.raises(limber.CaseError) as raised:
        limber.load_case(bad)
    assert in_stub == {name for name in vars(raised.value) if public(name)}
    assert [base.id for base in node.bases] == ["ValueError"] and issubclass(limber.CaseError, ValueError)
