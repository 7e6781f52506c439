"""The flags of ``spin``: what one thread publishes another sees, and polls end."""

import threading

import numpy as np

from optbound.analytic._kernels.spin import handoff, post_slices, publish, wait_for


def test_wait_for_sees_a_published_value_and_gives_up_otherwise():
    flag = np.zeros(8, np.int64)
    assert not wait_for(flag, 7, 100)
    publish(flag, 7)
    assert flag[0] == 7
    assert wait_for(flag, 7, 1)


def test_post_slices_copies_each_rows_next_number():
    posts = np.array([[0, 5, 0, 0, 0, 0, 0, 0], [3, 9, 0, 0, 0, 0, 0, 0]], np.int64)
    post_slices(posts)
    assert posts[:, 0].tolist() == [5, 9]
    post_slices(np.zeros((0, 8), np.int64))  # no workers: nothing to post


def test_handoff_between_threads():
    """A thread publishes its result and then waits for the next post; the main thread sees
    the result and posts: both polls succeed (long budgets: no sleeping involved)."""
    flag, post = np.zeros(8, np.int64), np.zeros(8, np.int64)
    seen = []
    thread = threading.Thread(target=lambda: seen.append(handoff(flag, 1, post, 2, 10**9)))
    thread.start()
    assert wait_for(flag, 1, 10**9)
    publish(post, 2)
    thread.join(timeout=60)
    assert seen == [True]
