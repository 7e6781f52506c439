"""``optbound._core.jit.njit``: numba's ``njit`` without the C-callable wrapper, for all kernels."""

import importlib

import numpy as np
import pytest
from numba.core.registry import CPUDispatcher

from optbound._core.jit import njit
from tests.test_jit_cache import kernel_modules


def test_passes_numba_options_and_drops_the_cfunc_wrapper():
    @njit(error_model="numpy")
    def divide_by_zero(x):
        return x / 0.0

    assert divide_by_zero.targetoptions["no_cfunc_wrapper"] is True
    assert divide_by_zero.targetoptions["error_model"] == "numpy"
    assert divide_by_zero(1.0) == np.inf  # the numpy error model: no ZeroDivisionError


def test_a_kernel_without_the_wrapper_is_still_called_from_python_and_from_kernels():
    @njit()
    def square(x):
        return x * x

    @njit()
    def sum_squares(a):
        total = 0.0
        for v in a:
            total += square(v)
        return total

    assert square(3.0) == 9.0
    assert sum_squares(np.array([1.0, 2.0, 3.0])) == 14.0


def test_no_cfunc_wrapper_is_not_for_callers():
    with pytest.raises(TypeError, match="no_cfunc_wrapper"):
        njit(no_cfunc_wrapper=False)


def test_every_kernel_of_the_package_is_declared_with_it():
    kernels = {}
    for name in kernel_modules():
        module = importlib.import_module(name)
        kernels.update(
            {f"{module.__name__}.{name}": obj for name, obj in vars(module).items()
             if isinstance(obj, CPUDispatcher) and obj.__module__ == module.__name__}
        )  # fmt: skip
    assert len(kernels) > 100  # the scan found the package's kernels
    plain = [name for name, k in kernels.items() if not k.targetoptions.get("no_cfunc_wrapper")]
    assert plain == []
