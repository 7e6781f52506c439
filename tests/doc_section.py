"""Run the Python block of one ``<!-- BEGIN name -->`` section of the documentation."""

import re

from tests.doc_tables import pages


def run_section(name: str) -> None:
    """Execute the single ```python block between the section's BEGIN and END markers (the
    section is on exactly one page of README.md and ``docs/``)."""
    begin, end = f"<!-- BEGIN {name} -->", f"<!-- END {name} -->"
    (page,) = [p for p in pages() if begin in p.read_text()]
    section = page.read_text().split(begin)[1].split(end)[0]
    (code,) = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    exec(compile(code, str(page), "exec"), {})
