"""Every docstring example in pulab runs (numpydoc Examples are part of the contract)."""
import doctest
import importlib
import pkgutil
import sys

import pytest

import pulab

MODULES = sorted(m.name for m in pkgutil.walk_packages(pulab.__path__, "pulab.")
                 if not m.name.endswith("__main__"))


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    importlib.import_module(name)
    mod = sys.modules[name]  # pulab.report the module, not the function of the same name
    res = doctest.testmod(mod, optionflags=doctest.ELLIPSIS)
    assert res.failed == 0
