"""The HS96, GLH12 and sonar speed benchmarks as bench families: suites, records, notes."""

import math

import pytest

from optbound.bench import speed_glh12, speed_hs96, speed_sonar
from optbound.bench.registry import families


def test_registered_as_serial_speed_families():
    fams = {f.name: f for f in families()}
    for name in ("speed_hs96", "speed_glh12", "speed_sonar"):
        assert fams[name].kind == "speed" and not fams[name].parallel
    assert fams["speed_sonar"].isolated


def test_hs96_parts_per_suite_and_no_office_run_before_full():
    parts = {s: [t["part"] for t in speed_hs96.tasks(s, 0)] for s in ("tiny", "quick", "full")}
    assert parts["tiny"] == ["linear", "associate"]
    assert parts["quick"] == ["linear", "associate", "tracker"]
    assert parts["full"] == ["linear", "associate", "tracker", "repro"]
    (full_repro,) = [t for t in speed_hs96.tasks("full", 0) if t["part"] == "repro"]
    assert full_repro["kwargs"] == {"full": True}  # the 10-lap run, in the full suite only


@pytest.mark.parametrize("part", ["linear", "associate"])
def test_hs96_tiny_parts_give_ratio_records(part):
    (task,) = [t for t in speed_hs96.tasks("tiny", 0) if t["part"] == part]
    records = speed_hs96.run(task)["records"]
    assert all(r["family"] == "speed_hs96" and r["value"] > 0 for r in records)
    ours = records[-1]
    assert ours["ratio"] > 0 and ours["ratio_label"] and ours["target"]


def test_hs96_tracker_records_pair_reference_and_ours():
    import numpy as np

    records = speed_hs96.bench_tracker(np.random.default_rng(0), n_scans=2, repeat=1)
    assert len(records) == 6
    for ref, ours in zip(records[::2], records[1::2], strict=True):
        assert ref["name"].startswith("bare analytic calls of the " + ours["name"])
        assert ours["overhead"] == pytest.approx(ours["value"] / ref["value"] - 1.0)
    assert "| what |" in speed_hs96.table(records)


def test_glh12_family_runs_its_own_suite():
    (task,) = speed_glh12.FAMILY.tasks("tiny", 0)
    assert task["suite"] == "tiny" and speed_glh12.FAMILY.tasks("full", 0)[0]["suite"] == "full"
    assert speed_glh12.cost(task) < speed_glh12.cost({"suite": "full"})


def test_sonar_has_tasks_in_the_full_suite_only():
    assert speed_sonar.tasks("tiny", 0) == speed_sonar.tasks("quick", 0) == []
    assert [t["kind"] for t in speed_sonar.tasks("full", 0)] == ["kjwm00", "codac"]


class _Paving:
    def __init__(self, empty):
        self.is_empty = empty


@pytest.mark.parametrize(
    ("n_sonars", "first", "expected"), [(16, 1, [0, 1, 2]), (16, 3, [0, 1, 2, 3]), (5, 1, [0, 1])]
)
def test_kjwm00_workload_paves_up_to_auto_and_q2_on_the_belt(n_sonars, first, expected):
    """The pavings of one trial: q = 0 ... q = auto, plus q = 2 on the 16-sonar belt."""
    asked = []

    def pave_q(q):
        asked.append(q)
        return _Paving(q < first)

    assert len(speed_sonar._trial_pavings(pave_q, n_sonars)) == len(expected)
    assert sorted(asked) == expected and len(asked) == len(set(asked))


@pytest.mark.slow
def test_kjwm00_records_time_both_paths_on_the_same_pavings():
    reference, ours = speed_sonar.kjwm00_records(1)
    assert reference["value"] > 0 and ours["ratio"] == reference["value"] / ours["value"]


ROW = {"name": "ljmw97_triangle eps=0.04", "seconds": 0.5, "load_average": 1.0}


def test_sonar_rows_with_codac_give_codac_then_ours():
    row = {**ROW, "codac_seconds": 250.0, "ratio": 500.0, "ratio_label": "x"}
    (codac, ours), notes = speed_sonar.sonar_records([row])
    assert notes == []
    assert (codac["value"], ours["value"], ours["ratio"]) == (250.0, 0.5, 500.0)
    assert codac["name"].startswith("codac sonar localize")


@pytest.mark.parametrize(
    ("extra", "note"),
    [
        ({"note": "codac not installed"}, "codac not installed"),
        ({"codac_seconds": math.inf, "codac_note": "stopped after 1800 s"}, "codac stopped"),
    ],
)
def test_sonar_rows_without_a_codac_time_give_ours_and_a_note(extra, note):
    (ours,), notes = speed_sonar.sonar_records([{**ROW, **extra}])
    assert ours["value"] == 0.5 and "ratio" not in ours
    assert notes[0].startswith(note)
