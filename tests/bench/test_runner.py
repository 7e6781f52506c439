"""The runner's per-process set-up of a task."""

import subprocess
import sys


def test_tasks_run_with_single_threaded_blas():
    """After a task has run in a process, every BLAS library it loaded uses one thread (run
    in a child, so the test process keeps its own settings)."""
    code = (
        "import scipy.linalg; from threadpoolctl import threadpool_info; "
        "from optbound.bench import runner; from optbound.bench.registry import families; "
        "fam = next(f for f in families() if f.name == 'minkowski'); "
        "runner._run_task(fam, fam.tasks('tiny', 0)[0]); "
        "blas = [i for i in threadpool_info() if i['user_api'] == 'blas']; "
        "assert blas and all(i['num_threads'] == 1 for i in blas), blas; print(len(blas))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert int(out.stdout) >= 1
