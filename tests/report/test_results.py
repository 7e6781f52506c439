import csv
import json

import pytest

from optbound.report.results import load_results, records_of, save_results, write_csv
from tests.report.sample import sample_results


def test_save_and_load_round_trip(tmp_path):
    results = sample_results()
    save_results(results, tmp_path)
    assert load_results(tmp_path) == results


def test_save_refuses_nan(tmp_path):
    results = sample_results()
    results["families"]["strip"]["records"][0]["ratio"] = float("nan")
    with pytest.raises(ValueError):
        save_results(results, tmp_path)


def test_load_errors_name_the_problem(tmp_path):
    with pytest.raises(ValueError, match="does not exist"):
        load_results(tmp_path / "nowhere")
    with pytest.raises(ValueError, match=r"no results\.json"):
        load_results(tmp_path)
    (tmp_path / "results.json").write_text("{not json")
    with pytest.raises(ValueError, match="not valid JSON"):
        load_results(tmp_path)
    (tmp_path / "results.json").write_text(json.dumps({"schema": 99}))
    with pytest.raises(ValueError, match="schema"):
        load_results(tmp_path)
    (tmp_path / "results.json").write_text(json.dumps({"schema": 1, "meta": {}}))
    with pytest.raises(ValueError, match="families"):
        load_results(tmp_path)


def test_csv_has_one_row_per_record(tmp_path):
    results = sample_results()
    paths = write_csv(results, tmp_path)
    assert [p.name for p in paths] == ["tightness.csv", "speed.csv"]
    with paths[0].open() as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == len(records_of(results, ("tightness", "recursive")))
    assert list(rows[0])[:3] == ["family", "variant", "dim"]
    assert float(rows[2]["ratio"]) == 3.0


def test_attachments_are_written_as_files_and_named_in_the_json(tmp_path):
    import base64

    results = sample_results()
    data = base64.b64encode(b"\x89PNG fake").decode("ascii")
    results["families"]["strip"]["attachments"] = {"strip/x.png": data}
    save_results(results, tmp_path)
    assert (tmp_path / "strip" / "x.png").read_bytes() == b"\x89PNG fake"
    assert load_results(tmp_path)["families"]["strip"]["attachments"] == ["strip/x.png"]
