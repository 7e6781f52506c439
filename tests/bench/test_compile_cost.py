"""``benchmarks.compile_cost``'s fixed-cost part: what it measures and the floor it prints."""

import math
import re

from benchmarks import compile_cost


def test_fixed_cost_is_measured_per_process_and_per_compile():
    fixed = compile_cost._fixed(repeats=2)  # here: numba is already set up, setup may be ~0
    assert set(fixed) == {"setup", "with_wrappers", "without_wrappers"}
    assert all(math.isfinite(v) for v in fixed.values())
    assert fixed["with_wrappers"] > 0.0  # a compile takes CPU; the rest are differences


def test_floor_is_processes_times_setup_plus_compiles_times_the_cheapest(capsys):
    fixed = {"setup": 0.25, "with_wrappers": 0.06, "without_wrappers": 0.03}
    compile_cost.report_fixed(fixed, processes=3, compiles=100, total=40.0)
    printed = capsys.readouterr().out
    assert "0.25 s to set up" in printed and "60 ms" in printed and "30 ms" in printed
    assert re.search(r"at least 3\.8 s of the 40\.0 s", printed)  # 3 * 0.25 + 100 * 0.03
