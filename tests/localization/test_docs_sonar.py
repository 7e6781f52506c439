"""The user guide's sonar example runs and prints what its text claims."""

from tests.doc_section import run_section


def test_sonar_guide_example_runs(capsys):
    run_section("sonar")
    out = capsys.readouterr().out.splitlines()
    assert out == ["True ((1,), (1,), (2,), (0,))", "True"]
