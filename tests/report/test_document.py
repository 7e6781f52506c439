from optbound.report import write_report
from optbound.report.headline import headline_rows
from tests.report.sample import sample_results


def test_report_has_tables_figures_notes_and_errors(tmp_path):
    path = write_report(sample_results(), tmp_path)
    text = path.read_text()
    assert "## Headline" in text
    # volume: n=3, min 1, median 1.5, max 3 at seed 12, none below 1, 2 points outside
    volume_row = "| `volume` | SDP volume | volume_ratio | 3 | 1.0000000 | 1.5 | 3 | seed 12, "
    assert volume_row in text
    assert "cond 1e+02 | 0 |  | 0 | 2 |" in text
    # trace: one refused SDP reference
    assert "| `trace` | SDP trace | trace_ratio | 2 | 1.1 | 1.15 | 1.2 | seed 13," in text
    assert "cond 1e+02 | 0 |  | 1 | 0 |" in text
    assert "![strip ratio histograms](hist_strip.png)" in text
    assert "![recursive tightness](recursive.png)" in text
    assert "![2-D instances](instances_2d.png)" in text
    assert "> codac is not installed" in text
    assert "**1 task(s) failed**" in text and "SolverError: inaccurate" in text
    assert "Skipped: needs x." in text
    for png in ("hist_strip.png", "recursive.png", "instances_2d.png"):
        assert (tmp_path / png).stat().st_size > 10_000
    assert (tmp_path / "tightness.csv").exists() and (tmp_path / "speed.csv").exists()


def test_recursive_table_lists_each_k_with_dims():
    rows = dict(headline_rows(sample_results()))
    # k = 5: ratios 1 + 0.5 * dim for dim 2, 3 -> median 2.25, max 2.5; lower ratios + 0.1
    assert rows["recursive · analytic filter after k=5 strips / batch SDP"] == (
        "median 2.25, max 2.5 (n=2); vs lower bound on the optimum: median 2.35"
    )


def test_headline_counts_refused_sdp_references():
    rows = dict(headline_rows(sample_results()))
    text = rows["strip · analytic trace / SDP trace"]
    assert text == "median 1.15, max 1.2 (n=2); 1 SDP solves refused"


def test_headline_names_a_reference_measured_like_a_bound():
    results = sample_results()
    recs = results["families"]["strip"]["records"]
    results["families"]["strip"]["records"] = [{**r, "bound": "optimal"} for r in recs]
    rows = dict(headline_rows(results))
    assert "strip · optimal trace / SDP trace" in rows
    assert not any(label.startswith("strip · analytic") for label in rows)


def test_speed_headline_has_the_ratio_and_the_codac_note():
    rows = headline_rows(sample_results())
    assert ("batch", "200 ns; 200× speed-up vs one call") in rows
    assert ("analytic", "codac is not installed") in rows


def test_rebuilding_gives_the_same_report(tmp_path):
    first = write_report(sample_results(), tmp_path).read_text()
    assert write_report(sample_results(), tmp_path).read_text() == first


def test_figures_drawn_over_processes_are_the_same_files(tmp_path):
    one = write_report(sample_results(), tmp_path / "one", jobs=1).parent
    two = write_report(sample_results(), tmp_path / "two", jobs=2).parent
    names = sorted(path.name for path in one.iterdir())
    assert [name for name in names if name.endswith(".png")]
    assert names == sorted(path.name for path in two.iterdir())
    assert all((one / name).read_bytes() == (two / name).read_bytes() for name in names)


def test_a_familys_attachments_are_shown_in_its_section(tmp_path):
    results = sample_results()
    results["families"]["recursive"]["attachments"] = ["own/picture.png"]
    text = write_report(results, tmp_path).read_text()
    section = text.split("## Recursive family")[1].split("\n## ")[0]
    assert "![picture](own/picture.png)" in section


def test_a_family_without_tasks_in_the_suite_says_so(tmp_path):
    results = sample_results()
    results["families"]["speed"].update(records=[], notes=[])
    text = write_report(results, tmp_path).read_text()
    assert "## Speed: analytic\n\nNo task in this suite." in text


def test_header_names_the_command_and_only_the_csv_files_written(tmp_path):
    results = sample_results()
    text = write_report(results, tmp_path).read_text()
    assert text.startswith("# optbound benchmark report\n")
    assert "Re-run with `optbound bench --suite quick --seed 0`" in text  # meta without command
    assert {p.name for p in tmp_path.glob("*.csv")} == {"tightness.csv", "speed.csv"}
    assert "Raw records: `tightness.csv`, `speed.csv`." in text
    speedless = {
        "meta": {**results["meta"], "command": "optbound repro HS96"},
        "families": {k: v for k, v in results["families"].items() if v["kind"] != "speed"},
    }
    text = write_report(speedless, tmp_path / "repro").read_text()
    assert text.startswith("# optbound paper reproductions\n")
    assert "Re-run with `optbound repro HS96`" in text and "speed.csv" not in text


def test_below_one_counts_are_explained_where_they_appear(tmp_path):
    results = sample_results()
    strip = results["families"]["strip"]["records"]
    strip[0] = {**strip[0], "ratio": 1.0 - 1e-5}  # an SDP reference a little off the optimum
    text = write_report(results, tmp_path).read_text()
    section = text.split(f"## {results['families']['strip']['title']}")[1].split("\n## ")[0]
    assert '"below 1" counts ratios under 1 − 1e-06' in section
    assert "the reference's own inaccuracy" in section
    text = write_report(sample_results(), tmp_path / "none").read_text()
    assert '"below 1" counts ratios under 1 − 1e-06' not in text  # said only where it applies
