"""Measurement scripts run from a source checkout (``python -m benchmarks.<script>``).

Not installed: the benchmark families that ``optbound bench`` runs live in
:mod:`optbound.bench`. The scripts here measure the compiled analytic kernels against plain
reference kernels (``speed_analytic``, ``analytic_reference``), the cost of the SDP lower
bound (``lower_bound_cost``) and the start-up time of the command (``cli_startup``).
"""
