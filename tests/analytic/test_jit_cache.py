"""Stale numba caches of the kernels are dropped when any kernel source changes."""

from optbound.analytic import _jit_cache


def test_a_changed_source_drops_the_kernel_caches(tmp_path):
    stale = tmp_path / "_midrad.inflate-1.py311.nbi"
    other = tmp_path / "unrelated.f-1.py311.nbi"
    stale.write_text("x")
    other.write_text("x")
    (tmp_path / _jit_cache.STAMP).write_text("an older digest")
    assert _jit_cache.refresh([tmp_path])
    assert not stale.exists() and other.exists()
    # Same sources: the stamp matches and nothing is dropped.
    stale.write_text("x")
    assert not _jit_cache.refresh([tmp_path])
    assert stale.exists()
