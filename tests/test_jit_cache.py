"""Stale numba caches of the kernels are dropped when any kernel source changes."""

from optbound import _jit_cache


def test_kernel_sources_cover_cross_file_kernels():
    names = {p.name for p in _jit_cache.kernel_sources()}
    assert {"midrad.py", "_domain.py", "_compiled.py", "polygons.py"} <= names


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
