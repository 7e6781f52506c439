"""Reproductions of the papers' figures and numbers with optbound, side by side with the papers.

One module per paper result group; each has ``main(out_dir) -> dict`` and a command line
(``python -m optbound.papers_repro.<module> --out DIR``). See ``papers_repro/README.md``.
"""
