"""run_all writes every discovered script's tables and figures into one folder."""

from optbound.papers_repro import run_all
from optbound.papers_repro._common import scripts


def test_summary_lists_every_script(tmp_path):
    path = run_all.run_all(tmp_path, quick=True)
    text = path.read_text()
    for header in ("## HS96 fusion", "## HS96 on a 3-D pose", "## LJMW97 Appendix A"):
        assert header in text
    pngs = sorted(p.name for p in tmp_path.glob("*.png"))
    assert len(pngs) >= 2 * len(scripts())
    for name in pngs:
        assert f"({name})" in text
