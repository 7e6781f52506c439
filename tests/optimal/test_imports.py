"""Layering: only optbound.optimal imports cvxpy."""

import subprocess
import sys


def test_core_packages_do_not_import_cvxpy():
    code = (
        "import sys, optbound, optbound.analytic, optbound.compare, optbound.sets;"
        "assert 'cvxpy' not in sys.modules, 'cvxpy imported'"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
