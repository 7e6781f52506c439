"""The README's sonar example runs and prints what its text claims."""

import re
from pathlib import Path

README = Path(__file__).resolve().parents[2] / "README.md"


def test_readme_sonar_example_runs(capsys):
    text = README.read_text()
    section = text.split("<!-- BEGIN sonar -->")[1].split("<!-- END sonar -->")[0]
    (code,) = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    exec(compile(code, str(README), "exec"), {})
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "True ((1,), (1,), (2,), (0,))"
    assert out[1] == "True"
