"""Run the Python block of one ``<!-- BEGIN name -->`` section of README.md."""

import re
from pathlib import Path

README = Path(__file__).resolve().parents[1] / "README.md"


def run_section(name: str) -> None:
    """Execute the single ```python block between the section's BEGIN and END markers."""
    text = README.read_text()
    section = text.split(f"<!-- BEGIN {name} -->")[1].split(f"<!-- END {name} -->")[0]
    (code,) = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    exec(compile(code, str(README), "exec"), {})
