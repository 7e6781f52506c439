"""The user guide's analytic example runs and prints what its text claims."""

from tests.doc_section import run_section


def test_analytic_guide_example_runs(capsys):
    run_section("analytic")
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("partial")
    assert out[1] == "volume saved by clipping: 0.273"  # ~27 % in this 3-D case (HS96 Fig. 1 c)
    assert out[2].startswith("0.4191113192")  # closed-form anchor for C1 = diag(4, 1), C2 = I
    assert out[3].startswith("True")
