"""Stale numba caches of the kernels are dropped when any kernel source changes."""

import subprocess
import sys

import pytest

from optbound import _jit_cache


def test_kernel_sources_cover_cross_file_kernels():
    names = {p.name for p in _jit_cache.kernel_sources()}
    assert {"midrad.py", "domain.py", "compiled.py", "polygons.py"} <= names


def test_a_changed_source_drops_the_kernel_caches(tmp_path):
    source = tmp_path / "kernel.py"
    source.write_text("from numba import njit\n")
    cached = tmp_path / "kernel.f-1.py311.nbi"
    cached.write_text("x")
    (tmp_path / _jit_cache.STAMP).write_text("an older digest")
    assert _jit_cache.refresh([tmp_path], [source])
    assert not cached.exists()
    # Same sources: the stamp matches and nothing is dropped.
    cached.write_text("x")
    assert not _jit_cache.refresh([tmp_path], [source])
    assert cached.exists()
    # An edit of the source drops the cache again.
    source.write_text("from numba import njit  # edited\n")
    assert _jit_cache.refresh([tmp_path], [source])
    assert not cached.exists()


#: Kernel modules outside the kernel packages that check their own caches: the speed
#: benchmark's reference (``optbound.bench.analytic_reference``) calls ``refresh`` with its own
#: stamp before it compiles anything, so that the command line can import ``optbound.bench``
#: without hashing every kernel source.
SELF_REFRESHING = {"bench/analytic_reference.py"}


def test_every_kernel_source_is_in_a_kernel_package():
    sources = {p.relative_to(_jit_cache.ROOT).as_posix() for p in _jit_cache.kernel_sources()}
    packages = {s.split("/")[0] for s in sources - SELF_REFRESHING}
    assert packages - {"_jit_cache.py"} <= set(_jit_cache.KERNEL_PACKAGES)


@pytest.mark.parametrize("source", sorted(SELF_REFRESHING))
def test_a_self_refreshing_module_checks_its_caches_before_compiling(source):
    text = (_jit_cache.ROOT / source).read_text()
    assert "_jit_cache.refresh(" in text
    assert text.index("_jit_cache.refresh(") < text.index("njit(")


def kernel_modules() -> list[str]:
    """Dotted names of the package's modules that define kernels (``kernel_sources``)."""
    return [
        ".".join(("optbound", *p.relative_to(_jit_cache.ROOT).with_suffix("").parts))
        for p in _jit_cache.kernel_sources()
        if p.name != "_jit_cache.py"  # it names njit in its text and defines no kernel
    ]


@pytest.mark.parametrize("package", _jit_cache.KERNEL_PACKAGES)
def test_the_check_runs_before_any_kernel_of_the_package_is_loaded(package):
    """Importing a kernel subpackage runs ``optbound._fresh`` (which runs ``refresh``) to
    completion before any module that defines kernels, those of other packages included
    (``sys.modules`` is in order of completed imports)."""
    kernels = kernel_modules()
    own = [k for k in kernels if k.startswith(f"optbound.{package}.")]
    code = (
        "import importlib, sys\n"
        f"for name in {own!r}:\n"
        "    importlib.import_module(name)\n"
        "order = list(sys.modules)\n"
        f"loaded = [k for k in {kernels!r} if k in sys.modules]\n"
        "assert all(order.index('optbound._fresh') < order.index(k) for k in loaded)\n"
    )
    assert own
    subprocess.run([sys.executable, "-c", code], check=True)
