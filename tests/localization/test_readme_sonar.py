"""The README's sonar example runs and prints what its text claims."""

from tests.readme_section import run_section


def test_readme_sonar_example_runs(capsys):
    run_section("sonar")
    out = capsys.readouterr().out.splitlines()
    assert out == ["True ((1,), (1,), (2,), (0,))", "True"]
