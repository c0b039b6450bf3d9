"""docs/python-api.md is what scripts/python_api_reference.py writes from the package now: a
public name, signature or docstring changed without the reference following fails here. And
every public name of the package is documented there with a docstring of its own."""
import importlib.util
import inspect

import deploydyn
from conftest import SOURCE_DIR


def generator():
    spec = importlib.util.spec_from_file_location("python_api_reference",
                                                  SOURCE_DIR / "scripts" / "python_api_reference.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_reference_is_current():
    written = (SOURCE_DIR / "docs" / "python-api.md").read_text(encoding="utf-8")
    assert written == generator().reference(deploydyn), (
        "docs/python-api.md is out of date: PYTHONPATH=build/release/python /usr/bin/python3 "
        "scripts/python_api_reference.py --out docs/python-api.md")


def test_every_public_name_has_a_docstring_and_a_heading():
    text = (SOURCE_DIR / "docs" / "python-api.md").read_text(encoding="utf-8")
    assert "(no docstring)" not in text
    for name in deploydyn.__all__:
        assert f"### {name}\n" in text, name
        obj = getattr(deploydyn, name)
        if inspect.isclass(obj):
            for member, _, _ in generator().members(obj):
                assert f"`{name}.{member}`" in text, f"{name}.{member}"
    public = {n for n in dir(deploydyn) if not n.startswith("_") and not inspect.ismodule(getattr(deploydyn, n))}
    assert public <= set(deploydyn.__all__), f"public but not in __all__: {public - set(deploydyn.__all__)}"
