"""Measurement scripts run from a source checkout (``python -m benchmarks.<script>``).

Not installed: the benchmark families that ``optbound bench`` runs live in
:mod:`optbound.bench` (the analytic kernels against their plain reference included:
``python -m optbound.bench.speed_analytic``). The scripts here measure the cost of the SDP
lower bound (``lower_bound_cost``), the start-up time of the command (``cli_startup``), what
``optbound.evaluate`` costs per problem (``audit_cost``), the one-time compilation
(``compile_cost``), the first and second run of the bench (``first_run``), where a warm
bench spends its time (``bench_profile``), the analytic kernels' outputs on seeded
instances, to check that a change leaves them bitwise equal (``kernel_outputs``), and where
the strip update's time goes against a 3-D hand-unrolled kernel (``strip_breakdown``).
"""
